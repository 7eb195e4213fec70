// The worker pool of the multithreaded scene recording (SceneThreads.h).
#include "scene/SceneThreads.h"

#include <pthread.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace drr {

ChunkRange SplitEvenly(uint32_t draws, uint32_t chunks, uint32_t chunk) {
  if (chunks == 0) return {};
  const uint64_t n = draws;
  return {uint32_t(n * chunk / chunks), uint32_t(n * (chunk + 1) / chunks)};
}

ChunkRange ChunkBalance::Split(uint32_t draws, uint32_t chunks, uint32_t chunk) const {
  if (chunks == 0 || chunk >= chunks) return {};
  bool known = msPerDraw_.size() == chunks;
  for (uint32_t t = 0; known && t < chunks; ++t) known = msPerDraw_[t] > 0.0;
  if (!known) return SplitEvenly(draws, chunks, chunk);
  // Speeds (draws per ms), each at least the fastest's / kMaxSpeedRatio;
  // chunk boundaries where the running sum of speeds crosses draws' shares.
  const double fastest = 1.0 / *std::min_element(msPerDraw_.begin(), msPerDraw_.end());
  std::vector<double> upTo(chunks + 1, 0.0);  // sum of the speeds of threads [0, k)
  for (uint32_t t = 0; t < chunks; ++t) upTo[t + 1] = upTo[t] + std::max(1.0 / msPerDraw_[t], fastest / kMaxSpeedRatio);
  const auto boundary = [&](uint32_t k) {
    if (k == chunks) return draws;
    return std::min(draws, uint32_t(std::lround(double(draws) * upTo[k] / upTo[chunks])));
  };
  return {boundary(chunk), boundary(chunk + 1)};
}

void ChunkBalance::Observe(uint32_t chunks, uint32_t thread, uint32_t draws, double ms) {
  if (msPerDraw_.size() != chunks) msPerDraw_.assign(chunks, 0.0);
  if (thread >= chunks || draws < kMinDraws || !(ms > 0.0) || !std::isfinite(ms)) return;
  const double sample = ms / double(draws);
  double& estimate = msPerDraw_[thread];
  estimate = estimate > 0.0 ? estimate + kLearningRate * (sample - estimate) : sample;
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
