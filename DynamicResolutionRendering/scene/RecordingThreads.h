// How many threads record the scene (Docs/Threads.md): the --threads range
// and its automatic value. Header-only: the options and the scene read it.
#pragma once

#include <algorithm>
#include <thread>

namespace drr {

constexpr int kAutoRecordingThreads = 4;  // automatic: one per hardware thread, at most this
constexpr int kMaxRecordingThreads = 8;   // --threads range 0..this

// 0 = automatic; otherwise as asked (at most kMaxRecordingThreads). 1 records
// on the immediate context, as the original.
inline int RecordingThreadsFor(int requested) {
  if (requested > 0) return std::min(requested, kMaxRecordingThreads);
  const int cores = int(std::thread::hardware_concurrency());  // 0 when unknown
  return std::clamp(cores, 1, kAutoRecordingThreads);
}

}  // namespace drr
