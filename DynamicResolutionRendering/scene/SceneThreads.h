// Multithreaded scene recording (Docs/Threads.md): persistent worker threads,
// one deferred context each, and the split of the frame's draw list into
// contiguous chunks. Thread 0 is the caller's: it records the first chunk on
// the immediate context, then executes the workers' lists there in order;
// threads 1.. are workers created once and woken each frame.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "d3dl/D3DLike.h"
#include "scene/RecordingThreads.h"

namespace drr {

// [first, last) of chunk `chunk` when `draws` draws are split into `chunks`
// contiguous chunks whose draw counts differ by at most one.
struct ChunkRange {
  uint32_t first = 0, last = 0;
};
ChunkRange SplitEvenly(uint32_t draws, uint32_t chunks, uint32_t chunk);

// The split that gives every thread the same expected recording time. A
// draw's cost differs between threads: the caller's immediate context records
// straight into its frame, a worker's deferred context also tracks what its
// list uses and ends with FinishCommandList. Each thread's time per draw is
// learnt from the frames recorded so far (a running average), and chunk t
// gets draws in proportion to thread t's speed. Before anything is known, or
// for a thread count not seen yet, the split is even. Only where a chunk
// starts moves: the chunks stay contiguous and in draw-list order, so the
// image is the same whatever the split.
class ChunkBalance {
 public:
  // [first, last) of chunk `chunk` of `draws` split over `chunks` threads.
  ChunkRange Split(uint32_t draws, uint32_t chunks, uint32_t chunk) const;
  // After a frame: thread `thread` of `chunks` recorded `draws` draws in `ms`
  // milliseconds. Chunks of fewer than kMinDraws draws teach nothing (their
  // time is mostly fixed costs), nor do non-positive or non-finite times.
  void Observe(uint32_t chunks, uint32_t thread, uint32_t draws, double ms);
  // Thread t's learnt time per draw, 0 while unknown.
  double MsPerDraw(uint32_t thread) const { return thread < msPerDraw_.size() ? msPerDraw_[thread] : 0.0; }

  static constexpr uint32_t kMinDraws = 32;
  // Weight of a new frame in the running average.
  static constexpr double kLearningRate = 0.25;
  // No thread gets more than this many times another's share per draw, so
  // one frame of a descheduled worker cannot starve it of draws for long.
  static constexpr double kMaxSpeedRatio = 3.0;

 private:
  std::vector<double> msPerDraw_;  // per thread of the last thread count seen
};

class RecordingPool {
 public:
  // threads - 1 worker threads (threads >= 2), each with its deferred
  // context; null with *error when a deferred context cannot be created.
  static std::unique_ptr<RecordingPool> Create(d3dl::Device* device, int threads, std::string* error);
  ~RecordingPool();  // stops and joins the workers
  RecordingPool(const RecordingPool&) = delete;
  RecordingPool& operator=(const RecordingPool&) = delete;

  int Threads() const { return int(contexts_.size()) + 1; }  // the caller's included
  d3dl::DeviceContext* Context(int thread) const { return contexts_[size_t(thread - 1)].Get(); }  // 1..

  // Wakes the workers to run job(1) .. job(Threads() - 1); the caller runs
  // job(0) itself between Start and Wait. Wait returns when every worker's
  // job has returned (their writes are then visible to the caller).
  void Start(const std::function<void(int)>* job);
  void Wait();

 private:
  RecordingPool() = default;
  void WorkerLoop(int thread);

  std::vector<d3dl::ComPtr<d3dl::DeviceContext>> contexts_;  // of threads 1..
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  uint64_t generation_ = 0;  // bumped by Start; a worker runs once per generation
  int running_ = 0;          // workers still inside this generation's job
  bool stop_ = false;
  const std::function<void(int)>* job_ = nullptr;
};

}  // namespace drr
