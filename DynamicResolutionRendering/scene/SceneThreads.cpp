// The worker pool of the multithreaded scene recording (SceneThreads.h).
#include "scene/SceneThreads.h"

#include <pthread.h>

#include <algorithm>
#include <string>

namespace drr {

ChunkRange SplitEvenly(uint32_t draws, uint32_t chunks, uint32_t chunk) {
  if (chunks == 0) return {};
  const uint64_t n = draws;
  return {uint32_t(n * chunk / chunks), uint32_t(n * (chunk + 1) / chunks)};
}

std::unique_ptr<RecordingPool> RecordingPool::Create(d3dl::Device* device, int threads, std::string* error) {
  std::unique_ptr<RecordingPool> pool(new RecordingPool());
  pool->contexts_.resize(size_t(std::max(threads - 1, 0)));
  for (auto& c : pool->contexts_) {
    if (d3dl::FAILED(device->CreateDeferredContext(0, c.GetAddressOf()))) {
      *error = "CreateDeferredContext failed: the scene records on the immediate context";
      return nullptr;
    }
  }
  for (int t = 1; t < threads; ++t) pool->workers_.emplace_back([p = pool.get(), t] { p->WorkerLoop(t); });
  return pool;
}

RecordingPool::~RecordingPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& w : workers_) w.join();
}

void RecordingPool::Start(const std::function<void(int)>* job) {
  {
    std::lock_guard lock(mutex_);
    job_ = job;
    running_ = int(workers_.size());
    ++generation_;
  }
  wake_.notify_all();
}

void RecordingPool::Wait() {
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return running_ == 0; });
  job_ = nullptr;
}

void RecordingPool::WorkerLoop(int thread) {
  // Named for profilers and debuggers (at most 15 characters).
  pthread_setname_np(pthread_self(), ("drr-record-" + std::to_string(thread)).c_str());
  uint64_t seen = 0;
  for (;;) {
    const std::function<void(int)>* job = nullptr;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    (*job)(thread);
    bool last = false;
    {
      std::lock_guard lock(mutex_);
      last = --running_ == 0;
    }
    if (last) done_.notify_one();
  }
}

}  // namespace drr
