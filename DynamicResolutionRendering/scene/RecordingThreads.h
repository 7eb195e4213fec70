// How many threads record the scene (Docs/Threads.md): the --threads range
// and the automatic mode. Header-only: the options and the scene read it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <thread>

namespace drr {

constexpr int kAutoRecordingThreads = 4;  // automatic: at most one per hardware thread and at most this
constexpr int kMaxRecordingThreads = 8;   // --threads range 0..this
// Automatic mode: a thread is added only when each thread gets at least this
// many draws. Below it, waking a worker, its list's Finish and Execute cost
// more than its share of the recording saves. Measured on the project's
// 2-vCPU development guest with lavapipe, quiet (Docs/Threads.md, "commands
// at consecutive addresses, chunks by measured speed"): 2 threads against 1
// cost 1.54 on the Arena's 59 draws, cannot be told from 1 thread with 102
// draws per thread (0.97) and pay 0.90 with 175, the fewest measured that
// paid (as in the section before it); 170 gives the 349 draws of that row
// two threads.
constexpr uint32_t kMinDrawsPerRecordingThread = 170;

// The count SceneRenderParams::recordingThreads gets for the --threads value:
// 0 stays 0 (automatic: the scene picks per frame, AutoRecordingThreads);
// otherwise as asked, at most kMaxRecordingThreads. 1 records on the
// immediate context, as the original.
inline int RecordingThreadsFor(int requested) { return std::clamp(requested, 0, kMaxRecordingThreads); }

// The automatic count for a frame of `draws` draws on `cores` hardware
// threads (0 when unknown): as many threads as get kMinDrawsPerRecordingThread
// draws each, at most one per core and at most kAutoRecordingThreads.
inline int AutoRecordingThreads(uint32_t draws, unsigned cores) {
  const uint32_t paying = draws / kMinDrawsPerRecordingThread;
  const uint32_t cap = std::min<uint32_t>(std::max(cores, 1u), kAutoRecordingThreads);
  return int(std::clamp<uint32_t>(paying, 1, cap));
}
// On this machine's hardware threads, read once: the query is a system call,
// a measurable part of a 59-draw frame's recording.
inline int AutoRecordingThreads(uint32_t draws) {
  static const unsigned cores = std::thread::hardware_concurrency();
  return AutoRecordingThreads(draws, cores);
}

}  // namespace drr
