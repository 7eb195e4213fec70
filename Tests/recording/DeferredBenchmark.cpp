// drr_rhi_bench --deferred: the frame of RhiRecorder (one Map(WRITE_DISCARD)
// of a constant buffer + Draw per draw) recorded on deferred contexts, all
// draws on one worker thread against half of them on each of two worker
// threads at the same time. Timed (wall clock): waking the (persistent)
// workers, their recording up to FinishCommandList, and the wait for both;
// not timed: ExecuteCommandList, submission and the GPU wait. The two benchmarks run in alternating pairs so
// that load from other processes hits both alike; the ratio of each pair and
// their median are printed.
//
//   drr_rhi_bench --deferred [--draws N] [--pairs K] [google benchmark flags]
//   drr_rhi_bench --deferred --smoke     the 1- and 2-thread images equal (recycled lists too), validation-clean
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
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

// Two persistent worker threads, woken per iteration (no thread start-up in
// the timed part); worker t always records on deferred context t.
class DeferredRecorder {
 public:
  ~DeferredRecorder() { StopWorkers(); }

  bool Init(std::string* error) {
    if (!r_.Init("rhi-deferred-benchmark", error)) return false;
    bool ok = true;
    for (auto& c : deferred_) ok = ok && d3dl::SUCCEEDED(r_.device->CreateDeferredContext(0, c.GetAddressOf()));
    if (!ok) *error = "CreateDeferredContext failed";
    for (uint32_t t = 0; ok && t < kMaxThreads; ++t) workers_[t] = std::thread([this, t] { WorkerLoop(t); });
    return ok;
  }

  // Timed part: draws [0, n) split into `threads` contiguous ranges, each
  // recorded into its own list by its own worker thread. Returns the CPU
  // seconds the workers spent (all together) and the longest worker's wall
  // time from its wake-up to its FinishCommandList.
  struct Cost {
    double cpu, wall;
  };
  Cost Record(uint32_t n, uint32_t threads) {
    // Only the workers that record are woken; job_ is read by them alone,
    // and written again only after they are all done.
    job_ = {n, threads};
    done_.store(0);
    for (uint32_t t = 0; t < threads; ++t) {
      go_[t].fetch_add(1, std::memory_order_release);
      go_[t].notify_one();
    }
    for (uint32_t d; (d = done_.load(std::memory_order_acquire)) < threads;) done_.wait(d);
    listCount_ = threads;
    Cost c{0, 0};
    for (uint32_t t = 0; t < threads; ++t) {
      c.cpu += cpu_[t];
      c.wall = std::max(c.wall, wall_[t]);
    }
    return c;
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
  }

  std::vector<uint8_t> ReadBack() { return r_.ReadStaging(); }
  uint64_t Messages() const { return r_.Messages(); }

 private:
  struct Job {
    uint32_t n, threads;
  };

  void WorkerLoop(uint32_t t) {
    uint32_t seen = 0;
    for (;;) {
      go_[t].wait(seen, std::memory_order_acquire);
      seen = go_[t].load(std::memory_order_acquire);
      if (stop_) return;
      const Job job = job_;
      const double start = Seconds(CLOCK_MONOTONIC), cpuStart = Seconds(CLOCK_THREAD_CPUTIME_ID);
      RecordRange(t, job.n * t / job.threads, job.n * (t + 1) / job.threads, job.n);
      wall_[t] = Seconds(CLOCK_MONOTONIC) - start;
      cpu_[t] = Seconds(CLOCK_THREAD_CPUTIME_ID) - cpuStart;
      done_.fetch_add(1, std::memory_order_release);
      done_.notify_one();
    }
  }

  void StopWorkers() {
    stop_ = true;
    for (auto& go : go_) {
      go.fetch_add(1, std::memory_order_release);
      go.notify_one();
    }
    for (auto& w : workers_)
      if (w.joinable()) w.join();
  }

  void RecordRange(uint32_t t, uint32_t first, uint32_t last, uint32_t n) {
    d3dl::DeviceContext* ctx = deferred_[t].Get();
    r_.BindDrawState(ctx);
    r_.RecordDraws(ctx, first, last, n);
    ctx->FinishCommandList(0, lists_[t].ReleaseAndGetAddressOf());
  }

  RhiDrawSetup r_;
  ComPtr<d3dl::DeviceContext> deferred_[kMaxThreads];
  ComPtr<d3dl::CommandList> lists_[kMaxThreads];
  uint32_t listCount_ = 0;
  // Worker threads: job_ and stop_ are written before a worker's go_ is raised.
  std::thread workers_[kMaxThreads];
  Job job_{};
  bool stop_ = false;
  std::atomic<uint32_t> go_[kMaxThreads] = {}, done_{0};
  double cpu_[kMaxThreads] = {}, wall_[kMaxThreads] = {};
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

void RecordOnThreads(benchmark::State& state, uint32_t n, uint32_t threads) {
  DeferredRecorder& rec = Recorder();
  double workerCpu = 0, workerWall = 0;
  for (auto _ : state) {
    const DeferredRecorder::Cost cost = rec.Record(n, threads);
    workerCpu += cost.cpu;
    workerWall += cost.wall;
    state.PauseTiming();
    rec.ExecuteAndWait();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  // CPU time of the recording threads per iteration: equal for 1 and 2
  // threads when the contexts do not contend (whatever the wall clock says).
  state.counters["worker_cpu_ms"] = 1e3 * workerCpu / double(state.iterations());
  state.counters["worker_wall_ms"] = 1e3 * workerWall / double(state.iterations());
}

// Per registered run: real time per iteration (waking the workers, recording,
// waiting for them) and the workers' own recording time (worker_wall_ms).
class PairReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration) continue;
      times[run.run_name.function_name] = run.GetAdjustedRealTime();
      const auto w = run.counters.find("worker_wall_ms");
      if (w != run.counters.end()) recording[run.run_name.function_name] = w->second.value;
      const auto c = run.counters.find("worker_cpu_ms");
      if (c != run.counters.end()) cpu[run.run_name.function_name] = c->second.value;
    }
  }
  std::map<std::string, double> times, recording, cpu;
};

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
    rec.Record(draws, 1 + round % 2);
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

void PrintPairs(const PairReporter& reporter, int pairs, int64_t draws) {
  std::vector<double> ratios, recordingRatios, cpuRatios;
  double sum1 = 0, sum2 = 0;
  for (int k = 0; k < pairs; ++k) {
    const std::string one = "BM_Deferred1Thread/pair:" + std::to_string(k);
    const std::string two = "BM_Deferred2Threads/pair:" + std::to_string(k);
    if (!reporter.times.count(one) || !reporter.times.count(two) || reporter.times.at(one) <= 0) continue;
    const double t1 = reporter.times.at(one), t2 = reporter.times.at(two);
    const double r1 = reporter.recording.count(one) ? reporter.recording.at(one) : 0;
    const double r2 = reporter.recording.count(two) ? reporter.recording.at(two) : 0;
    ratios.push_back(t2 / t1);
    if (r1 > 0) recordingRatios.push_back(r2 / r1);
    if (reporter.cpu.count(one) && reporter.cpu.count(two) && reporter.cpu.at(one) > 0)
      cpuRatios.push_back(reporter.cpu.at(two) / reporter.cpu.at(one));
    sum1 += t1;
    sum2 += t2;
    std::printf("pair %d: 1 thread %.3f ms, 2 threads %.3f ms, ratio %.3f; recording alone %.3f / %.3f ms, ratio %.3f\n",
                k, t1, t2, t2 / t1, r1, r2, r1 > 0 ? r2 / r1 : 0.0);
  }
  if (ratios.empty()) return;
  const RatioSummary all = Summarise(ratios);
  std::printf("ratio 2-thread / 1-thread deferred recording (%lld draws, %zu pairs, hardware threads %u): "
              "median %.3f, min %.3f, max %.3f, of the totals %.3f\n",
              static_cast<long long>(draws), ratios.size(), std::thread::hardware_concurrency(), all.median,
              all.min, all.max, sum2 / sum1);
  if (recordingRatios.empty()) return;
  const RatioSummary rec = Summarise(recordingRatios);
  std::printf("ratio of the workers' recording alone (from wake-up to FinishCommandList): median %.3f, "
              "min %.3f, max %.3f\n", rec.median, rec.min, rec.max);
  if (cpuRatios.empty()) return;
  // Near 1 when two contexts do not slow each other down (locks, shared
  // cache lines, allocator); less sensitive to other processes than wall time.
  const RatioSummary cpu = Summarise(cpuRatios);
  std::printf("ratio of the workers' CPU time, both threads together / one thread: median %.3f, min %.3f, "
              "max %.3f\n", cpu.median, cpu.min, cpu.max);
}

}  // namespace

int DeferredMain(int argc, char** argv) {
  int64_t draws = 10000;
  int pairs = 10;
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
    } else {
      args.push_back(argv[i]);
    }
  }
  if (draws < 2 || draws > 1000000 || pairs < 1 || pairs > 1000) {
    std::fprintf(stderr, "--draws expects [2, 1000000], --pairs [1, 1000]\n");
    return 2;
  }
  if (smoke) {
    const int rc = Smoke(400);
    g_recorder.reset();
    return rc;
  }
  // Alternating pairs; wall-clock time, as the work runs on worker threads.
  const auto count = static_cast<uint32_t>(draws);
  for (int k = 0; k < pairs; ++k) {
    const std::string suffix = "/pair:" + std::to_string(k);
    benchmark::RegisterBenchmark(("BM_Deferred1Thread" + suffix).c_str(),
                                 [count](benchmark::State& s) { RecordOnThreads(s, count, 1); })
        ->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark(("BM_Deferred2Threads" + suffix).c_str(),
                                 [count](benchmark::State& s) { RecordOnThreads(s, count, 2); })
        ->Unit(benchmark::kMillisecond)->UseRealTime();
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  PairReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  g_recorder.reset();
  PrintPairs(reporter, pairs, draws);
  benchmark::Shutdown();
  return 0;
}

}  // namespace drrbench
