// drr_rhi_bench --deferred: 10,000 draws recorded on deferred contexts by
// one thread against two threads at the same time (DeferredRecorder.h says
// what is timed). Every iteration records on 1 and on 2 threads back to
// back, in alternating order, so that load from other processes hits both
// alike; K benchmarks ("pairs") of I iterations; the ratio of each pair's
// totals, their median and the ratio of all totals are printed. --floor adds,
// in every iteration, the same 1- and 2-thread runs of the RHI's Vulkan
// commands written by hand, one device per thread so that nothing is shared:
// what lavapipe and this machine give any recorder, beside the RHI's ratio.
//
//   drr_rhi_bench --deferred [--draws N] [--pairs K] [--iterations I] [--floor] [google benchmark flags]
//   drr_rhi_bench --deferred --smoke     the 1- and 2-thread images equal (recycled lists too), the
//                                        floor's recorders too, all validation-clean
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "DeferredRecorder.h"

namespace drrbench {
namespace {

bool g_floor = false;  // --floor
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

bool InitFloor() {
  std::string error;
  if (Recorder().InitFloor(&error)) return true;
  std::fprintf(stderr, "deferred benchmark --floor: %s\n", error.c_str());
  return false;
}

double Sum(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return sum;
}

// Per pair: every iteration's 1- and 2-thread spans and CPU times.
struct PairSamples {
  std::vector<double> one, two, cpuOne, cpuTwo;
  std::vector<double> floorOne, floorTwo;  // --floor: the hand-written recording's spans
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
    if (g_floor) {
      DeferredRecorder::Cost floor[2];
      for (size_t k = 0; k < 2; ++k) {
        const size_t t = (first + k) % 2;
        rec.Arm(uint32_t(t + 1));
        floor[t] = rec.Record(n, Work::kRawVulkan);
        rec.Settle(Work::kRawVulkan);
      }
      s.floorOne.push_back(floor[0].span);
      s.floorTwo.push_back(floor[1].span);
    }
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
  // The --floor recorders, once on 1 and 2 threads: validation-clean too.
  std::string error;
  const bool floorReady = rec.InitFloor(&error);
  if (!floorReady) std::printf("deferred smoke: --floor: %s\n", error.c_str());
  for (uint32_t threads = 1; floorReady && threads <= 2; ++threads) {
    rec.Arm(threads);
    rec.Record(draws, Work::kRawVulkan);
    rec.Settle(Work::kRawVulkan);
  }
  const uint64_t messages = rec.Messages() + rec.RawMessages();
  std::printf("deferred smoke: %u draws, %d rounds on 1 and 2 threads (and the floor's), %zu lit pixels, "
              "%zu differing pixels, %llu messages\n", draws, kRounds, lit, differing,
              static_cast<unsigned long long>(messages));
  const bool ok = !first.empty() && sizesMatch && differing == 0 && lit > 0 && messages == 0 && floorReady;
  std::printf("%d passed, %d failed\n", ok ? 1 : 0, ok ? 0 : 1);
  return ok ? 0 : 1;
}

// The hand-written recording's ratio in the same pairs and iterations.
void PrintFloor(double rhiTotals) {
  std::vector<double> ratios;
  double sum1 = 0, sum2 = 0;
  size_t samples = 0;
  for (const PairSamples& p : g_pairs) {
    if (p.floorOne.empty()) continue;
    ratios.push_back(Sum(p.floorTwo) / Sum(p.floorOne));
    sum1 += Sum(p.floorOne);
    sum2 += Sum(p.floorTwo);
    samples += p.floorOne.size();
  }
  if (ratios.empty()) return;
  const RatioSummary r = Summarise(ratios);
  std::printf("floor, hand-written Vulkan (the same commands, one device per thread, nothing shared): 1 thread "
              "%.3f ms; ratio 2-thread / 1-thread: median %.3f, min %.3f, max %.3f, of the totals %.3f; the "
              "RHI's ratio of the totals minus this: %+.3f\n", 1e3 * sum1 / double(samples), r.median, r.min,
              r.max, sum2 / sum1, rhiTotals - sum2 / sum1);
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
  PrintFloor(sum2 / sum1);
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
    } else if (std::strcmp(argv[i], "--floor") == 0) {
      g_floor = true;
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
  if (g_floor && !InitFloor()) {
    g_recorder.reset();
    return 1;
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
