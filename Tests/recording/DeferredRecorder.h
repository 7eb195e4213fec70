// The recording threads of drr_rhi_bench --deferred (DeferredBenchmark.cpp):
// two persistent threads, each pinned to its own CPU, that record the frame
// of RhiRecorder (one Map(WRITE_DISCARD) of a constant buffer + Draw per
// draw) on deferred contexts: all draws on one context by one thread, or half
// of them on each of two contexts by two threads at the same time; or, for
// --floor, the same Vulkan commands written by hand (RawVulkanRecorder) on one
// device per thread with the RHI's command-pool allocator, sharing nothing.
// Timed: from the first thread's first call to the last thread's
// FinishCommandList (vkEndCommandBuffer for the hand-written commands, whose
// pool reset stays outside), read by the recording threads themselves. Not
// timed: waking the threads, which happens before (they spin until the start;
// how long an OS takes to give a sleeping thread a core is the scheduler's
// cost, not the recording's, 0.1 to 0.4 ms on this project's 2-vCPU guest),
// and ExecuteCommandList, submission and the GPU wait after. Both runs record
// on threads other than main, so their heaps behave alike (glibc trims the
// main thread's heap and faults it back in every iteration: 685 page faults
// per 10,000 draws there, 17 on another thread).
#pragma once

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "CommandMemory.h"  // the RHI's command-pool allocator, for the hand-written floor
#include "Recorder.h"
#include "RhiDrawSetup.h"

namespace drrbench {

constexpr uint32_t kMaxThreads = 2;

inline double Seconds(clockid_t clock) {
  timespec ts;
  clock_gettime(clock, &ts);
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

// A spin-wait hint: lets the sibling hardware thread run, costs no syscall.
inline void CpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// Keeps the calling thread on CPU `cpu` (when the machine has it). Without
// it Linux places a woken thread on its waker's CPU: two recording threads
// then share one core for up to a scheduler slice while the other idles
// (measured before pinning: the second thread started 0.32 to 0.44 ms after
// the first, a quarter of a 10,000-draw recording).
inline void PinTo(unsigned cpu) {
  if (std::thread::hardware_concurrency() <= cpu) return;
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  pthread_setaffinity_np(pthread_self(), sizeof(set), &set);
}

// What the recording threads run: the RHI's deferred contexts, or the
// hand-written commands of --floor.
enum class Work { kRhi, kRawVulkan };

// Recording thread t (pinned to CPU t) records on deferred context t. The
// threads a run uses are armed (woken, spinning) before the timed part.
class DeferredRecorder {
 public:
  ~DeferredRecorder() { StopThreads(); }

  bool Init(std::string* error) {
    if (!r_.Init("rhi-deferred-benchmark", error)) return false;
    bool ok = true;
    for (auto& c : deferred_) ok = ok && d3dl::SUCCEEDED(r_.device->CreateDeferredContext(0, c.GetAddressOf()));
    if (!ok) {
      *error = "CreateDeferredContext failed";
      return false;
    }
    for (uint32_t t = 0; t < kMaxThreads; ++t)
      threads_[t] = std::thread([this, t] {
        PinTo(t);
        ThreadLoop(t);
      });
    return true;
  }

  // Not timed: wakes recording threads 0 .. threads-1 and returns once they
  // all spin, ready for the next Record.
  void Arm(uint32_t threads) {
    const uint32_t g = ++generation_;
    armed_ = threads;
    for (uint32_t t = 0; t < threads; ++t) {
      go_[t].store(g, std::memory_order_release);
      go_[t].notify_one();
    }
    for (uint32_t t = 0; t < threads; ++t)
      while (ready_[t].load(std::memory_order_acquire) != g) std::this_thread::yield();
  }

  // Timed part: draws [0, n) split into the armed threads' contiguous ranges,
  // range t recorded into list t (on context t, or on the 1-thread run's own
  // context when one thread is armed). Returns the CPU seconds the
  // threads spent together and the span from the first start to the last end.
  struct Cost {
    double cpu, span;
    double skew;  // from the first thread's start to the last one's
  };
  Cost Record(uint32_t n, Work work = Work::kRhi) {
    job_ = {n, armed_, work};
    Release();
    if (work == Work::kRhi) listCount_ = job_.threads;
    Cost c{0, 0, 0};
    double first = begin_[0], lastBegin = begin_[0], last = end_[0];
    for (uint32_t t = 0; t < job_.threads; ++t) {
      c.cpu += cpu_[t];
      first = std::min(first, begin_[t]);
      lastBegin = std::max(lastBegin, begin_[t]);
      last = std::max(last, end_[t]);
    }
    c.span = last - first;
    c.skew = lastBegin - first;
    return c;
  }

  // Not timed: releases the armed threads without work (after the last Record).
  void Disarm() {
    job_ = {0, 0, Work::kRhi};
    Release();
  }

  // Not timed: the lists in draw order after a clear, then the copy for ReadBack.
  void ExecuteAndWait() {
    const float black[4] = {0, 0, 0, 0};
    r_.context->ClearRenderTargetView(r_.rtv.Get(), black);
    for (uint32_t t = 0; t < listCount_; ++t) r_.context->ExecuteCommandList(lists_[t].Get(), 0);
    r_.context->CopyResource(r_.staging.Get(), r_.target.Get());
    r_.context->Flush();
    r_.device->WaitIdle();
    for (auto& l : lists_) l = {};
    Pause();
  }

  // Not timed: what follows a run: the lists executed, or the hand-written
  // command buffers submitted, waited for and begun again; then a pause.
  void Settle(Work work) {
    if (work == Work::kRhi) return ExecuteAndWait();
    for (uint32_t t = 0; t < job_.threads; ++t) raw_[Slot(t, job_.threads)]->SubmitAndWait();
    Pause();
  }

  // The hand-written recorders of --floor, one device each.
  bool InitFloor(std::string* error) {
    for (uint32_t k = 0; k <= kMaxThreads; ++k) {
      raw_[k].reset(CreateRawVulkanRecorder(rawMemory_[k].callbacks()));
      if (!raw_[k]->Init(error)) return false;
    }
    return true;
  }
  // The hand-written recorders' messages (one counter for all of them).
  uint64_t RawMessages() const { return raw_[0] ? raw_[0]->ValidationMessages() : 0; }

  std::vector<uint8_t> ReadBack() { return r_.ReadStaging(); }
  uint64_t Messages() const { return r_.Messages(); }

 private:
  struct Job {
    uint32_t n, threads;
    Work work;
  };

  // The context (or hand-written recorder) thread t uses in a run of
  // `threads`: its own in the 2-thread run, the 1-thread run's own otherwise.
  static uint32_t Slot(uint32_t t, uint32_t threads) { return threads == 1 ? kMaxThreads : t; }

  // lavapipe's queue thread goes on after the fence (0.4 ms seen: releasing
  // what the submission held); left running it takes a core from the next
  // timed recording, which only the 2-thread run needs (medians 0.776-0.796
  // without this pause, 0.736 with 1 ms, 0.724 with 3 ms).
  static void Pause() { std::this_thread::sleep_for(std::chrono::milliseconds(3)); }

  // Starts the armed threads on job_ and sleeps until they are done. The
  // wait is a condition variable, not a spinning atomic wait: a waiting
  // thread that yields would share a core with a recording one.
  void Release() {
    startAt_ = Seconds(CLOCK_MONOTONIC) + kStartDelay;
    start_.store(generation_, std::memory_order_release);
    std::unique_lock<std::mutex> lock(doneMutex_);
    doneCv_.wait(lock, [this] { return doneCount_ == armed_; });
    doneCount_ = 0;
    armed_ = 0;
  }

  // Context t's range of the current job, with its times.
  void Measure(uint32_t t) {
    const Job job = job_;
    const double cpuStart = Seconds(CLOCK_THREAD_CPUTIME_ID);
    begin_[t] = Seconds(CLOCK_MONOTONIC);
    const uint32_t slot = Slot(t, job.threads);
    const uint32_t first = job.n * t / job.threads, last = job.n * (t + 1) / job.threads;
    if (job.work == Work::kRawVulkan) {
      raw_[slot]->Record(last - first);
    } else {
      d3dl::DeviceContext* ctx = deferred_[slot].Get();
      r_.BindDrawState(ctx);
      r_.RecordDraws(ctx, first, last, job.n);
      ctx->FinishCommandList(0, lists_[t].ReleaseAndGetAddressOf());
    }
    end_[t] = Seconds(CLOCK_MONOTONIC);
    cpu_[t] = Seconds(CLOCK_THREAD_CPUTIME_ID) - cpuStart;
  }

  void ThreadLoop(uint32_t t) {
    uint32_t seen = 0;
    for (;;) {
      go_[t].wait(seen, std::memory_order_acquire);
      seen = go_[t].load(std::memory_order_acquire);
      if (stop_) return;
      ready_[t].store(seen, std::memory_order_release);
      // Yielding: the main thread, which gives the start, may be queued on
      // this core. Then all begin at startAt_, when it sleeps.
      while (start_.load(std::memory_order_acquire) != seen) sched_yield();
      while (Seconds(CLOCK_MONOTONIC) < startAt_) CpuRelax();
      if (job_.threads > 0) Measure(t);
      std::lock_guard<std::mutex> lock(doneMutex_);
      ++doneCount_;
      doneCv_.notify_one();
    }
  }

  void StopThreads() {
    if (armed_) Disarm();  // an armed thread spins until released
    stop_ = true;
    for (auto& go : go_) {
      go.fetch_add(1, std::memory_order_release);
      go.notify_one();
    }
    for (auto& t : threads_)
      if (t.joinable()) t.join();
  }

  RhiDrawSetup r_;
  // [t]: thread t of the 2-thread run; [kMaxThreads]: the 1-thread run's.
  // Each context always records the same share of the draws, so the list it
  // recycles (whose commands the driver frees inside FinishCommandList, in
  // the timed part) is always as long as the one it records.
  d3dl::ComPtr<d3dl::DeviceContext> deferred_[kMaxThreads + 1];
  d3dl::ComPtr<d3dl::CommandList> lists_[kMaxThreads];
  uint32_t listCount_ = 0;
  // job_ and stop_ are written before go_ or start_ is raised.
  std::thread threads_[kMaxThreads];
  Job job_{};
  bool stop_ = false;
  uint32_t armed_ = 0, generation_ = 0, doneCount_ = 0;
  std::atomic<uint32_t> go_[kMaxThreads] = {}, ready_[kMaxThreads] = {}, start_{0};
  std::mutex doneMutex_;
  std::condition_variable doneCv_;
  double cpu_[kMaxThreads] = {}, begin_[kMaxThreads] = {}, end_[kMaxThreads] = {};
  // The threads start recording this long after the main thread gives the
  // start, time enough for it to fall asleep: with three runnable threads on
  // two cores, one recording thread would otherwise wait for the main one.
  static constexpr double kStartDelay = 200e-6;
  double startAt_ = 0;  // written before start_ is raised
  // Hand-written Vulkan with the RHI's per-pool allocator (not malloc's per
  // command, which the RHI's deferred lists do not use either).
  d3dl::impl::CommandMemory rawMemory_[kMaxThreads + 1];
  std::unique_ptr<Recorder> raw_[kMaxThreads + 1];
};

}  // namespace drrbench
