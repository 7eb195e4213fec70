// drr_rhi_bench: CPU cost of recording N draws with changing constants,
// D3DLikeRHI against hand-written Vulkan, in one process, side by side.
// Only recording is timed; submission and the wait are excluded for both.
// The dispatch case (compute and unordered access) runs K rounds of
// raw / RHI alternately, so a machine shared with other work slows both alike.
//
//   drr_rhi_bench [--draws N] [--dispatches N] [--rounds K] [google benchmark flags]
//   drr_rhi_bench --benchmark_filter=Dispatch              the dispatch case only
//   drr_rhi_bench --smoke                                  correctness only
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "Recorder.h"

namespace drrbench {

std::string BenchShaderDir() {
  const char* env = std::getenv("DRR_BENCH_SHADER_DIR");
  return env && *env ? env : DRR_BENCH_SHADER_DIR;
}

DrawConstants ConstantsForDraw(uint32_t i, uint32_t n) {
  // A grid of triangles over the target, colours from the index.
  const uint32_t side = static_cast<uint32_t>(std::ceil(std::sqrt(double(n))));
  const float fx = (float(i % side) + 0.5f) / float(side);
  const float fy = (float(i / side) + 0.5f) / float(side);
  DrawConstants c{};
  c.offset[0] = fx * 2.0f - 1.0f;
  c.offset[1] = 1.0f - fy * 2.0f;
  c.color[0] = float(i % 7) / 6.0f;
  c.color[1] = float(i % 5) / 4.0f;
  c.color[2] = float(i % 3) / 2.0f;
  c.color[3] = 1.0f;
  return c;
}

DispatchConstants ConstantsForDispatch(uint32_t i) {
  return DispatchConstants{i, (i * 2654435761u) ^ 0x9e3779b9u, {0, 0}};
}

namespace {

// The benchmarks' recorders, kept across repetitions. They must be destroyed
// before main returns: a static destructor would run after the Vulkan driver
// (loaded after this array's registration) has torn itself down at exit.
std::unique_ptr<Recorder> g_recorders[2];

void DestroyRecorders() {
  for (auto& r : g_recorders) r.reset();
}

std::unique_ptr<Recorder> Make(bool rhi) {
  std::unique_ptr<Recorder> r(rhi ? CreateRhiRecorder() : CreateRawVulkanRecorder());
  std::string error;
  if (!r->Init(&error)) {
    std::fprintf(stderr, "%s recorder: %s\n", rhi ? "rhi" : "raw", error.c_str());
    r.reset();
    DestroyRecorders();  // std::exit runs static destructors, not these
    std::exit(1);
  }
  return r;
}

void RecordDraws(benchmark::State& state, bool rhi) {
  auto& rec = g_recorders[rhi ? 1 : 0];
  if (!rec) rec = Make(rhi);
  const auto n = static_cast<uint32_t>(state.range(0));
  for (auto _ : state) {
    rec->Record(n);
    state.PauseTiming();
    rec->SubmitAndWait();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
}

void BM_RawVulkan(benchmark::State& s) { RecordDraws(s, false); }
void BM_D3DLikeRHI(benchmark::State& s) { RecordDraws(s, true); }

// Compute and unordered access: n dispatches per frame.
void RecordDispatchFrame(benchmark::State& state, bool rhi) {
  auto& rec = g_recorders[rhi ? 1 : 0];
  if (!rec) rec = Make(rhi);
  const auto n = static_cast<uint32_t>(state.range(0));
  for (auto _ : state) {
    rec->RecordDispatches(n);
    state.PauseTiming();
    rec->SubmitAndWait();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
}
void BM_RawVulkanDispatch(benchmark::State& s) { RecordDispatchFrame(s, false); }
void BM_D3DLikeRHIDispatch(benchmark::State& s) { RecordDispatchFrame(s, true); }

// Keeps the mean real time of each benchmark to print the ratio at the end.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    // Single runs land under "", repetitions' aggregates under "mean"/"median".
    for (const Run& run : runs) {
      const std::string kind = run.run_type == Run::RT_Aggregate ? run.aggregate_name : "";
      if (kind == "" || kind == "mean" || kind == "median")
        times[kind][run.run_name.function_name] = run.GetAdjustedRealTime();
      if (kind == "") {
        rounds[run.run_name.function_name].push_back(run.GetAdjustedRealTime());
        cpuRounds[run.run_name.function_name].push_back(run.GetAdjustedCPUTime());
      }
    }
  }
  std::map<std::string, std::map<std::string, double>> times;
  // Every single run, in order: wall time, and CPU time of the recording thread
  // (less disturbed by other work on a shared machine).
  std::map<std::string, std::vector<double>> rounds, cpuRounds;
};

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// The dispatch case: per-round ratios of the interleaved runs and their
// medians, in wall time and in the recording thread's CPU time.
void PrintDispatchRatios(const RatioReporter& r, int64_t dispatches) {
  const char* kRaw = "BM_RawVulkanDispatch";
  const char* kRhi = "BM_D3DLikeRHIDispatch";
  if (!r.rounds.count(kRaw) || !r.rounds.count(kRhi)) return;
  const auto& raw = r.rounds.at(kRaw);
  const auto& rhi = r.rounds.at(kRhi);
  const auto& rawCpu = r.cpuRounds.at(kRaw);
  const auto& rhiCpu = r.cpuRounds.at(kRhi);
  std::vector<double> wall, cpu;
  for (size_t k = 0; k < raw.size() && k < rhi.size(); ++k) {
    wall.push_back(rhi[k] / raw[k]);
    cpu.push_back(rhiCpu[k] / rawCpu[k]);
    std::printf("dispatch round %zu: wall raw %.3f ms, rhi %.3f ms, ratio %.3f; cpu raw %.3f ms, rhi %.3f ms, ratio %.3f\n",
                k, raw[k], rhi[k], wall.back(), rawCpu[k], rhiCpu[k], cpu.back());
  }
  if (wall.empty()) return;
  const double perRaw = 1e6 * Median(rawCpu) / double(dispatches), perRhi = 1e6 * Median(rhiCpu) / double(dispatches);
  std::printf("ratio D3DLikeRHI / raw Vulkan dispatch recording (%lld dispatches, median of %zu interleaved rounds): "
              "wall %.3f, cpu %.3f (cpu per dispatch: %.1f ns vs %.1f ns)\n",
              static_cast<long long>(dispatches), wall.size(), Median(wall), Median(cpu), perRhi, perRaw);
}

// Compute and unordered access: both recorders give the UAV words of a CPU
// model of the dispatch shader (w = w * 3 + value + thread).
bool SmokeDispatches(Recorder& raw, Recorder& rhi) {
  constexpr uint32_t kDispatches = 300;
  std::vector<uint32_t> want(kDispatchWords, 0);
  for (uint32_t i = 0; i < kDispatches; ++i)
    for (uint32_t j = 0; j < kDispatchWords; ++j) want[j] = want[j] * 3u + ConstantsForDispatch(i).value + j;
  raw.RecordDispatches(kDispatches);
  raw.SubmitAndWait();
  rhi.RecordDispatches(kDispatches);
  rhi.SubmitAndWait();
  const bool ok = raw.ReadBackWords() == want && rhi.ReadBackWords() == want;
  std::printf("smoke: %u dispatches, UAV words %s the CPU model\n", kDispatches, ok ? "match" : "DIFFER from");
  return ok;
}

int Smoke() {
  constexpr uint32_t kDraws = 200;
  auto raw = Make(false);
  auto rhi = Make(true);
  raw->Record(kDraws);
  raw->SubmitAndWait();
  rhi->Record(kDraws);
  rhi->SubmitAndWait();
  const auto a = raw->ReadBack();
  const auto b = rhi->ReadBack();
  size_t differing = 0, lit = 0;
  for (size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4) {
    if (std::memcmp(&a[i], &b[i], 4) != 0) ++differing;
    if (a[i + 3] != 0) ++lit;
  }
  const bool dispatchesOk = SmokeDispatches(*raw, *rhi);
  const uint64_t messages = raw->ValidationMessages() + rhi->ValidationMessages();
  std::printf("smoke: %u draws, %zu lit pixels, %zu differing pixels, %llu validation messages\n",
              kDraws, lit, differing, static_cast<unsigned long long>(messages));
  const bool ok = a.size() == b.size() && !a.empty() && differing == 0 && lit > 0 && messages == 0 && dispatchesOk;
  std::printf("%d passed, %d failed\n", ok ? 1 : 0, ok ? 0 : 1);
  return ok ? 0 : 1;
}

}  // namespace
}  // namespace drrbench

// "--flag N" with N in [1, max]; false (and a message) for a bad value.
bool ParseCount(const char* flag, const char* text, int64_t max, int64_t* out) {
  char* end = nullptr;
  *out = std::strtoll(text, &end, 10);
  if (end && !*end && *out >= 1 && *out <= max) return true;
  std::fprintf(stderr, "%s: expected an integer in [1, %lld], got '%s'\n", flag, static_cast<long long>(max), text);
  return false;
}

int main(int argc, char** argv) {
  int64_t draws = 10000, dispatches = 10000, rounds = 5;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--deferred") == 0) return drrbench::DeferredMain(argc, argv);
    if (std::strcmp(argv[i], "--smoke") == 0) return drrbench::Smoke();
    if (std::strcmp(argv[i], "--draws") == 0 && i + 1 < argc) {
      char* end = nullptr;
      draws = std::strtoll(argv[++i], &end, 10);
      if (!end || *end || draws < 1 || draws > 1000000) {
        std::fprintf(stderr, "--draws: expected an integer in [1, 1000000], got '%s'\n", argv[i]);
        return 2;
      }
      continue;
    }
    if (std::strcmp(argv[i], "--dispatches") == 0 && i + 1 < argc) {
      if (!ParseCount("--dispatches", argv[++i], 1000000, &dispatches)) return 2;
      continue;
    }
    if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc) {
      if (!ParseCount("--rounds", argv[++i], 100, &rounds)) return 2;
      continue;
    }
    args.push_back(argv[i]);
  }
  benchmark::RegisterBenchmark("BM_RawVulkan", drrbench::BM_RawVulkan)->Arg(draws)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_D3DLikeRHI", drrbench::BM_D3DLikeRHI)->Arg(draws)->Unit(benchmark::kMillisecond);
  for (int64_t k = 0; k < rounds; ++k) {  // interleaved: raw, rhi, raw, rhi, ...
    benchmark::RegisterBenchmark("BM_RawVulkanDispatch", drrbench::BM_RawVulkanDispatch)->Arg(dispatches)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_D3DLikeRHIDispatch", drrbench::BM_D3DLikeRHIDispatch)->Arg(dispatches)->Unit(benchmark::kMillisecond);
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  drrbench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  drrbench::DestroyRecorders();
  for (const auto& [kind, t] : reporter.times) {
    const auto raw = t.find("BM_RawVulkan"), rhi = t.find("BM_D3DLikeRHI");
    if (raw == t.end() || rhi == t.end() || raw->second <= 0) continue;
    std::printf("ratio D3DLikeRHI / raw Vulkan recording (%lld draws%s%s): %.3f\n",
                static_cast<long long>(draws), kind.empty() ? "" : ", ", kind.c_str(),
                rhi->second / raw->second);
  }
  drrbench::PrintDispatchRatios(reporter, dispatches);
  benchmark::Shutdown();
  return 0;
}
