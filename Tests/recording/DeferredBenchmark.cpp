// drr_rhi_bench --deferred: the frame of RhiRecorder (one Map(WRITE_DISCARD)
// of a constant buffer + Draw per draw) recorded on deferred contexts: all
// draws on one context by one recording thread, against half of them on each
// of two contexts by two recording threads at the same time. Timed: from the
// first thread's first call to the last thread's FinishCommandList, read by
// the recording threads themselves (manual time). Not timed: waking the
// threads, which happens before (they spin until the start; how long an OS
// takes to give a sleeping thread a core is the scheduler's cost, not the
// recording's, 0.1 to 0.4 ms on this project's 2-vCPU guest), and
// ExecuteCommandList, submission and the GPU wait after. Both runs record on
// threads other than main, so their heaps behave alike (glibc trims the main
// thread's heap and faults it back in every iteration: 685 page faults per
// 10,000 draws there, 17 on another thread). Every iteration records on 1
// and on 2 threads back to back, in alternating order, so that load from
// other processes hits both alike; K benchmarks ("pairs") of I iterations;
// the ratio of each pair's totals, their median and the ratio of all totals
// are printed.
//
//   drr_rhi_bench --deferred [--draws N] [--pairs K] [--iterations I] [google benchmark flags]
//   drr_rhi_bench --deferred --smoke     the 1- and 2-thread images equal (recycled lists too), validation-clean
#include <benchmark/benchmark.h>
#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "Recorder.h"
#include "RhiDrawSetup.h"

namespace drrbench {
namespace {

using d3dl::ComPtr;
constexpr uint32_t kMaxThreads = 2;

double Seconds(clockid_t clock) {
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
void PinTo(unsigned cpu) {
  if (std::thread::hardware_concurrency() <= cpu) return;
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  pthread_setaffinity_np(pthread_self(), sizeof(set), &set);
}

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
  Cost Record(uint32_t n) {
    job_ = {n, armed_};
    Release();
    listCount_ = job_.threads;
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
    job_ = {0, 0};
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
    // lavapipe's queue thread goes on after the fence (0.4 ms seen: releasing
    // what the submission held); left running it takes a core from the next
    // timed recording, which only the 2-thread run needs (medians 0.776-0.796
    // without this pause, 0.736 with 1 ms, 0.724 with 3 ms).
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
  }

  std::vector<uint8_t> ReadBack() { return r_.ReadStaging(); }
  uint64_t Messages() const { return r_.Messages(); }

 private:
  struct Job {
    uint32_t n, threads;
  };

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
    d3dl::DeviceContext* ctx = deferred_[job.threads == 1 ? kMaxThreads : t].Get();
    r_.BindDrawState(ctx);
    r_.RecordDraws(ctx, job.n * t / job.threads, job.n * (t + 1) / job.threads, job.n);
    ctx->FinishCommandList(0, lists_[t].ReleaseAndGetAddressOf());
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
  ComPtr<d3dl::DeviceContext> deferred_[kMaxThreads + 1];
  ComPtr<d3dl::CommandList> lists_[kMaxThreads];
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
};

std::unique_ptr<DeferredRecorder> g_recorder;  // reset before returning (see RecordBenchmark.cpp)

DeferredRecorder& Recorder() {
  if (!g_recorder) {
    g_recorder = std::make_unique<DeferredRecorder>();
    std::string error;
    if (!g_recorder->Init(&error)) {
      std::fprintf(stderr, "deferred recorder: %s\n", error.c_str());
      g_recorder.reset();
      std::exit(1);
    }
  }
  return *g_recorder;
}

double Sum(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return sum;
}

// Per pair: every iteration's 1- and 2-thread spans and CPU times.
struct PairSamples {
  std::vector<double> one, two, cpuOne, cpuTwo;
};
std::vector<PairSamples> g_pairs;

// Each iteration records the same draws on 1 and on 2 threads back to back,
// in alternating order, so that both meet the same machine (on this guest
// the 1-thread time alone drifts by up to 2x within a second). The
// manual time is the 2-thread span; the 1-thread span is a counter.
void RecordPair(benchmark::State& state, uint32_t n, size_t pair) {
  DeferredRecorder& rec = Recorder();
  PairSamples& s = g_pairs[pair];
  s = {};
  double skew = 0;
  for (auto _ : state) {
    DeferredRecorder::Cost cost[2];  // [0]: 1 thread, [1]: 2 threads
    const size_t first = s.one.size() % 2;
    for (size_t k = 0; k < 2; ++k) {
      const size_t t = (first + k) % 2;
      rec.Arm(uint32_t(t + 1));
      cost[t] = rec.Record(n);
      rec.ExecuteAndWait();
    }
    state.SetIterationTime(cost[1].span);
    s.one.push_back(cost[0].span);
    s.two.push_back(cost[1].span);
    s.cpuOne.push_back(cost[0].cpu);
    s.cpuTwo.push_back(cost[1].cpu);
    skew += cost[1].skew;
  }
  const double iters = double(state.iterations());
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.counters["one_thread_ms"] = 1e3 * Sum(s.one) / iters;
  // CPU time of the recording threads per iteration: equal for 1 and 2
  // threads when the contexts do not contend (whatever the wall clock says).
  state.counters["cpu_one_ms"] = 1e3 * Sum(s.cpuOne) / iters;
  state.counters["cpu_two_ms"] = 1e3 * Sum(s.cpuTwo) / iters;
  state.counters["start_skew_us"] = 1e6 * skew / iters;
}

struct RatioSummary {
  double median, min, max;
};
RatioSummary Summarise(std::vector<double> r) {
  std::sort(r.begin(), r.end());
  const size_t m = r.size();
  return {m % 2 ? r[m / 2] : 0.5 * (r[m / 2 - 1] + r[m / 2]), r.front(), r.back()};
}

// The 1- and 2-thread images, alternately and several times (so that later
// rounds record into recycled command pools, descriptor pools and ring
// chunks), all equal to the first, lit, and validation-clean.
int Smoke(uint32_t draws) {
  DeferredRecorder& rec = Recorder();
  constexpr int kRounds = 6;
  std::vector<uint8_t> first;
  size_t differing = 0, lit = 0;
  bool sizesMatch = true;
  for (int round = 0; round < kRounds; ++round) {
    rec.Arm(1 + round % 2);
    rec.Record(draws);
    rec.ExecuteAndWait();
    const auto image = rec.ReadBack();
    if (round == 0) {
      first = image;
      for (size_t i = 3; i < first.size(); i += 4) lit += first[i] != 0;
      continue;
    }
    sizesMatch = sizesMatch && image.size() == first.size();
    for (size_t i = 0; i + 3 < image.size() && sizesMatch; i += 4) differing += std::memcmp(&first[i], &image[i], 4) != 0;
  }
  const uint64_t messages = rec.Messages();
  std::printf("deferred smoke: %u draws, %d rounds on 1 and 2 threads, %zu lit pixels, %zu differing pixels, "
              "%llu messages\n", draws, kRounds, lit, differing, static_cast<unsigned long long>(messages));
  const bool ok = !first.empty() && sizesMatch && differing == 0 && lit > 0 && messages == 0;
  std::printf("%d passed, %d failed\n", ok ? 1 : 0, ok ? 0 : 1);
  return ok ? 0 : 1;
}

void PrintPairs(int64_t draws) {
  std::vector<double> ratios, cpuRatios, iterationRatios;
  double sum1 = 0, sum2 = 0;
  size_t samples = 0;
  for (size_t k = 0; k < g_pairs.size(); ++k) {
    const PairSamples& p = g_pairs[k];
    if (p.one.empty()) continue;
    const double t1 = Sum(p.one), t2 = Sum(p.two), n = double(p.one.size());
    ratios.push_back(t2 / t1);
    cpuRatios.push_back(Sum(p.cpuTwo) / Sum(p.cpuOne));
    sum1 += t1;
    sum2 += t2;
    samples += p.one.size();
    for (size_t i = 0; i < p.one.size(); ++i) iterationRatios.push_back(p.two[i] / p.one[i]);
    std::printf("pair %zu: 1 thread %.3f ms, 2 threads %.3f ms, ratio %.3f\n", k, 1e3 * t1 / n, 1e3 * t2 / n,
                t2 / t1);
  }
  if (ratios.empty()) return;
  const RatioSummary all = Summarise(ratios);
  std::printf("ratio 2-thread / 1-thread deferred recording (%lld draws, %zu pairs of %zu iterations in all, "
              "hardware threads %u): median %.3f, min %.3f, max %.3f, of the totals %.3f\n",
              static_cast<long long>(draws), ratios.size(), samples, std::thread::hardware_concurrency(),
              all.median, all.min, all.max, sum2 / sum1);
  // Each iteration's own ratio: robust to a pair that other processes hit.
  std::sort(iterationRatios.begin(), iterationRatios.end());
  const auto quantile = [&](double q) { return iterationRatios[size_t(q * double(iterationRatios.size() - 1))]; };
  std::printf("ratio per iteration: median %.3f, quartiles %.3f and %.3f\n", quantile(0.5), quantile(0.25),
              quantile(0.75));
  // Near 1 when two contexts do not slow each other down (locks, shared
  // cache lines, allocator); less sensitive to other processes than wall time.
  const RatioSummary cpu = Summarise(cpuRatios);
  std::printf("ratio of the recording CPU time, both threads together / one thread: median %.3f, min %.3f, "
              "max %.3f\n", cpu.median, cpu.min, cpu.max);
}

}  // namespace

int DeferredMain(int argc, char** argv) {
  int64_t draws = 10000;
  int pairs = 10;
  int64_t iterations = 100;
  bool smoke = false;
  std::vector<char*> args{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--deferred") == 0) continue;
    if (std::strcmp(argv[i], "--smoke") == 0) {
      smoke = true;
    } else if (std::strcmp(argv[i], "--draws") == 0 && i + 1 < argc) {
      draws = std::strtoll(argv[++i], nullptr, 10);
    } else if (std::strcmp(argv[i], "--pairs") == 0 && i + 1 < argc) {
      pairs = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--iterations") == 0 && i + 1 < argc) {
      iterations = std::strtoll(argv[++i], nullptr, 10);
    } else {
      args.push_back(argv[i]);
    }
  }
  if (draws < 2 || draws > 1000000 || pairs < 1 || pairs > 1000 || iterations < 1 || iterations > 100000) {
    std::fprintf(stderr, "--draws expects [2, 1000000], --pairs [1, 1000], --iterations [1, 100000]\n");
    return 2;
  }
  if (smoke) {
    const int rc = Smoke(400);
    g_recorder.reset();
    return rc;
  }
  // A fixed number of iterations: the untimed part of one (executing the
  // draws on lavapipe, the pause) is ten times the timed part, so Google
  // Benchmark's own choice, made from the timed part, would take minutes.
  const auto count = static_cast<uint32_t>(draws);
  g_pairs.assign(size_t(pairs), {});
  for (size_t k = 0; k < size_t(pairs); ++k) {
    benchmark::RegisterBenchmark(("BM_DeferredPair/pair:" + std::to_string(k)).c_str(),
                                 [count, k](benchmark::State& s) { RecordPair(s, count, k); })
        ->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(iterations);
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  benchmark::RunSpecifiedBenchmarks();
  g_recorder.reset();
  PrintPairs(draws);
  benchmark::Shutdown();
  return 0;
}

}  // namespace drrbench
