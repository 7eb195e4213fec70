// Closed-loop simulator of the resolution controllers: the plant model, the
// scenarios and the metrics. Shared by the drr_controller_sim tool and the
// tests (Tests/controller), so both drive one model.
//
// Plant (per frame n, s = applied scale per axis after the viewport
// quantisation of DynamicResolution, so the pixel fraction is sx * sy ~ s^2):
//   gpu(n)   = (fixed + pixel * sx * sy * load(n)) * (1 + noise * N(0,1))
//   frame(n) = max(cpu(n), gpu(n)), rounded up to a multiple of 1/60 s in vsync60
// Each GPU time becomes a timer result (optionally delayed by latencyFrames).
// What the controller is fed depends on its feed (Feed, ResolutionController.h):
//   Original  (the article law): the mean of the last complete block of 10
//             results (0 before the first) and 1 / DXUT-style FPS over the
//             simulated clock (+Inf during the first second), every frame;
//   PerResult (the port's laws): the newest result and that frame's period.
// In the nan scenario a corrupt value replaces what the controller is fed.
// Noise comes from
// std::mt19937 (fully specified) through our own Box-Muller transform, so a
// seed gives the same run with any standard library.
#pragma once

#include "ResolutionController.h"

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drr::sim {

// The sample's timer latency in the simulator's terms: on lavapipe every
// inner-frame result is polled 2 frames after its frame (FrameRecord's
// gpu_delay_frames, the traces' headers), i.e. one frame later than the
// simulator's latency 0 (time of frame n fed after frame n).
constexpr int kSampleTimerLatency = 1;

struct PlantModel {
  double fixedSeconds = 0.002;   // resolution-independent GPU work (c)
  double pixelSeconds = 0.030;   // GPU work at scale 1, load 1 (p)
  double noise = 0.01;           // relative standard deviation of the GPU time
  double noiseCorrelation = 0.0; // AR(1) coefficient of that noise from frame to frame (0: white)
  double cpuSeconds = 0.005;     // CPU time per frame when not CPU-bound
  int latencyFrames = kSampleTimerLatency;  // frames before a GPU time reaches the controller
  double GpuSeconds(double pixelFraction, double load) const { return fixedSeconds + pixelSeconds * pixelFraction * load; }
};

enum class Scenario { Step2x, StepHalf, Ramp, Periodic, CpuBound, Spikes, NaN, VSync60, Still, Bursts, Drift };

// The nine scenarios of the fair table and the synthetic set ("all").
const std::vector<Scenario>& AllScenarios();
// Loads of a shared machine (the tuning set only, ScanRobust): Bursts, a
// Markov-modulated load (bursts of 1.5-4x, 15 frames on average, every 55 on
// average) and Drift, a wandering load (log-load AR(1), 0.98, sd 0.4, and
// white log noise of 0.1 on each frame's time), modelled on a lavapipe
// tuning trace.
const std::vector<Scenario>& SharedMachineScenarios();
std::string_view ToString(Scenario scenario);
bool ParseScenario(std::string_view name, Scenario* scenario);
std::string_view Describe(Scenario scenario);

// Variants of the Original feed, for comparing the fix options with it.
struct FeedVariant {
  bool lastFramePeriod = false;  // frame time = this frame's period instead of 1 / DXUT FPS
};

struct SimConfig {
  Scenario scenario = Scenario::Step2x;
  std::optional<Feed> feed;    // empty: the law's own (FeedFor; the article law: Original)
  FeedVariant variant;
  int frames = 900;            // >= kMinFrames
  int disturbanceFrame = 300;  // also the end of the warm-up (metrics start here)
  PlantModel plant;
  ControlTarget target;        // budget 1/60 s, headroom 10 %, scale [0.3, 1]
  // Every law steers to T (1 - headroom): the article law (which aims at its
  // budget) is handed the budget T (1 - headroom). false: each law its own aim
  // (the article law at T, as the original), for the article-law studies.
  bool commonAim = true;
  std::uint32_t seed = 20110228u;
  unsigned int backBufferWidth = 1280;
  unsigned int backBufferHeight = 720;
  double settleBand = 0.05;    // +-5 % of the controller's aim
  int stillAfterFrames = 150;  // a load is "still" once unchanged for this many frames
};
constexpr int kMinFrames = 600;

// Per-scenario adjustments of a base configuration (noise of `still`, ...).
SimConfig ConfigFor(Scenario scenario, const SimConfig& base);

struct FrameRecord {
  int frame = 0;
  double load = 1.0;
  double scale = 1.0;        // applied scale X at the start of the frame
  double modelGpu = 0.0;     // noise-free GPU time at that scale and load
  double measuredGpu = 0.0;  // what the controller was given
  double frameSeconds = 0.0;
  bool changed = false;      // viewport changed after this frame
  double actualGpu = 0.0;    // what the timer measured for this frame (noise, spikes, recorded load)
  double budgetScale = 1.0;  // scale whose noise-free time equals the budget at this frame's load
  bool overBudget = false;   // counted in SimResult::overBudget
};

struct SimResult {
  std::string controller;
  std::string scenario;
  double aimSeconds = 0.0;
  double budgetSeconds = 0.0;   // T, against which over budget is counted
  int settleFrames = -1;        // frames after the disturbance until the model GPU time stays within the band; -1 never
  bool settleApplies = true;    // false for periodic (never still)
  double overshootPct = 0.0;    // largest excursion past the aim, opposite to the initial error (or the largest deviation)
  double steadyErrorPct = 0.0;  // mean (model / aim - 1) over the last 100 frames
  int stillChanges = 0;         // viewport changes while the load was still
  int overBudget = 0;           // frames after warm-up whose GPU time exceeded the budget (injected spikes excluded)
  int changes = 0;              // viewport changes after warm-up
  double finalScale = 0.0;
  // Resolution given up: 100 (1 - sum of applied scales / sum of budget
  // scales) after warm-up, the budget scale being the scale whose noise-free
  // time equals the budget T at that frame's load (clamped to the range).
  // Negative: above the budget scale.
  double givenUpPct = 0.0;
  std::vector<FrameRecord> trace;  // filled when asked
};

// One frame of a plant at the applied scale.
struct PlantFrame {
  double model = 0.0;         // noise-free GPU time
  double actual = 0.0;        // what the timer measures
  double frameSeconds = 0.0;  // frame period
  double load = 1.0;          // for the trace
  double budgetScale = 1.0;   // scale whose noise-free time equals the budget (clamped)
  bool countsOverBudget = true;  // false for injected spikes
  bool still = false;            // the load has been still (for still changes)
  bool corrupt = false;          // the controller is fed corruptGpu / corruptFrame instead
  double corruptGpu = 0.0, corruptFrame = 0.0;
};
class Plant {
public:
  virtual ~Plant() = default;
  // Frame n rendered with pixel fraction sx * sy (called once per frame, in order).
  virtual PlantFrame Frame(int n, double pixelFraction) = 0;
};

// How a closed loop runs and is scored (RunScenario fills it from a SimConfig,
// the trace replay from a trace).
struct LoopSpec {
  std::string scenario;
  int frames = 900;
  int metricsFrom = 300;   // end of the warm-up
  int settleFrom = 300;    // settling counted from here
  bool settleIsFirstReach = false;  // settle = first frame in the band (not: in it to the end)
  bool settleApplies = true;
  ControlTarget target;
  bool commonAim = true;
  std::optional<Feed> feed;
  FeedVariant variant;
  int latencyFrames = 0;
  unsigned int backBufferWidth = 1280, backBufferHeight = 720;
  double settleBand = 0.05;
};
SimResult RunLoop(ResolutionController& controller, Plant& plant, const LoopSpec& spec, bool keepTrace = false);

// The target a law is handed (LawTarget) so that its AimSeconds is
// T (1 - headroom) when commonAim; the over-budget count uses T itself.
ControlTarget LawTarget(const ResolutionController& controller, const ControlTarget& target, bool commonAim);
// Scale whose noise-free time equals the budget: sqrt((T - c) / (p load)), clamped.
double BudgetScale(const PlantModel& plant, double load, const ControlTarget& sanitizedTarget);
// 100 (1 - sum(scales) / sum(budgetScales)); 0 for empty input.
double GivenUpPercent(const std::vector<double>& scales, const std::vector<double>& budgetScales);

// The article law integrating the applied, quantised scale instead of its own
// continuous one: what the port did before it followed the original (the floor
// of the integral viewport then ratchets the scale down). For comparison only.
class AppliedScaleArticle final : public ResolutionController {
public:
  std::string_view Name() const override { return "article-applied"; }
  double AimSeconds(const ControlTarget& target) const override { return SanitizeTarget(target).budgetSeconds; }
  double Update(double currentScale, const FrameTiming& timing, const ControlTarget& target) override {
    return ArticleController::Step(static_cast<float>(currentScale), timing, target, ArticleController::kDefaultGain);
  }
};

// Article-law variants compared in Docs/Controller.md: the original, the
// fix options (ctrl-frame-period), and the port's former applied-scale feedback.
enum class ArticleVariant { Original, FramePeriod, AppliedScale };
bool ParseArticleVariant(std::string_view name, ArticleVariant* variant);
std::string_view ToString(ArticleVariant variant);
// The article law of that variant on every scenario (the name column says which).
std::vector<SimResult> RunArticleVariant(ArticleVariant variant, const std::vector<Scenario>& scenarios,
                                         const SimConfig& base);

// The laws in the order of the simulator's tables (article, ue-style, robust).
const std::vector<ControlLaw>& AllLaws();

SimResult RunScenario(ResolutionController& controller, const SimConfig& config, bool keepTrace = false);
// A fresh controller of each law for each scenario, made by MakeController: the
// robust law is told the plant's measurement latency (the application knows its
// timer pipeline depth); the others have no such setting.
std::vector<SimResult> RunMatrix(const std::vector<ControlLaw>& laws, const std::vector<Scenario>& scenarios,
                                 const SimConfig& base);

// The synthetic set, the only cases any tuning of a law may look at: every
// scenario under latency 0..3 frames, each with white 1 % noise and with
// AR(1) noise of 3 % and correlation 0.9 (a slowly wandering timer).
struct SyntheticCase {
  std::string label;  // "latency 1, white 1 %"
  SimConfig base;
};
std::vector<SyntheticCase> SyntheticSet(const SimConfig& base);

// The robust law's tuning scan over the tuning set, and nothing else (the
// held-out traces never enter it): the synthetic set (every scenario of
// AllScenarios under its eight cases), the shared-machine scenarios under the
// same cases, and the tuning traces (ControllerSimRecord.sh ... tuning), each
// replayed at the sample's latency. Rows: increases of at most 1.5x or 1.2x
// per correction, after 2 or 6 samples, decided on the window's median or
// largest sample; the risk-aware set point off or at quantile 0.75 over 60
// samples, of the samples' level or of their jumps above the recent level. The first row is the law before the scan
// (RobustController::PreviousParams). Each row runs at the headrooms
// kScanHeadrooms, so that a law is judged by its frames over budget at a
// given resolution given up (a law can always trade one for the other by
// sitting lower).
struct TraceCase;
struct ScanTotals {
  int overBudget = 0, changes = 0, stillChanges = 0, neverSettled = 0, runs = 0;
  double givenUpPct = 0.0;  // mean over the runs
  void Add(const SimResult& r);
};
inline constexpr double kScanHeadrooms[] = {0.05, 0.1, 0.2, 0.3};
enum ScanSet { kSynthetic, kShared, kTuningTraces, kScanSets };
struct ScanRowTotals {
  ScanTotals at[std::size(kScanHeadrooms)][kScanSets];  // per headroom, per set
  const ScanTotals& Base(ScanSet set, double headroom) const;  // at the base headroom
  // Frames over budget at `givenUp`, interpolated linearly along the row's
  // (given up, over budget) points over the headrooms (clamped to the ends).
  double OverBudgetAt(ScanSet set, double givenUp) const;
};
struct RobustScanRow : ScanRowTotals {
  RobustController::Params params;
};
std::vector<RobustScanRow> ScanRobust(const SimConfig& base, const std::vector<TraceCase>& tuningTraces);
// The UE-style law's scan on the same tuning set with the same budget as the
// robust law's tuning-set scan (24 rows, the same headrooms and pick rule):
// increases blended 0.9 or 0.75 of the way, changes at most every 8 or 4
// calls, a change threshold of 2 % or 5 %, and a history of 16 samples
// weighted 0.9^age, 8 weighted 0.8^age or 32 weighted 0.95^age. The first row
// is the law as it is (UEStyleController::Params{}).
struct UEScanRow : ScanRowTotals {
  UEStyleController::Params params;
};
std::vector<UEScanRow> ScanUEStyle(const SimConfig& base, const std::vector<TraceCase>& tuningTraces);
int PickUEStyleRow(const std::vector<UEScanRow>& rows, double baseHeadroom);
void PrintUEStyleScan(std::ostream& out, const std::vector<UEScanRow>& rows, double baseHeadroom);
// The row the rule of Docs/Controller.md picks: among the rows that keep the
// synthetic set's changes within +10 %, its still changes, never-settled runs
// and given up (+0.5 point) not above the baseline's (row 0) at the base
// headroom, the lowest sum over the three sets of
// OverBudgetAt(set, baseline's given up) / baseline's over budget. -1 if none.
int PickRobustRow(const std::vector<RobustScanRow>& rows, double baseHeadroom);
void PrintRobustScan(std::ostream& out, const std::vector<RobustScanRow>& rows, double baseHeadroom);

// Totals per controller over a matrix.
struct Totals {
  std::string controller;
  int overBudget = 0;
  int stillChanges = 0;
  int changes = 0;
  int runs = 0;
  int neverSettled = 0;      // runs where settling applies and never happened
  double givenUpPct = 0.0;   // mean over the runs
};
std::vector<Totals> Summarise(const std::vector<SimResult>& results);

void PrintTable(std::ostream& out, const std::vector<SimResult>& results);
void WriteCsv(std::ostream& out, const std::vector<SimResult>& results);
// Every frame of every run that kept its trace (law, scenario, frame, load,
// scale, budget scale, times in ms, over budget, changed), for diagnosis.
void WritePerFrameCsv(std::ostream& out, const std::vector<SimResult>& results);

// --sweep-k: the article law on step2x (quantised viewport, noise as configured)
// for gains 0.001..10 in log steps.
struct SweepRow {
  double gain = 0.0;
  double multiplier = 0.0;      // analytic error multiplier 1 - 2 k alpha at the post-step fixed point
  int settleFrames = -1;
  double amplitudePct = 0.0;    // (max - min) / mean of the scale over the last 200 frames
  double alternation = 0.0;     // fraction of frame-to-frame scale changes that reverse direction
  bool hitsClamp = false;       // the scale touched a limit in the last 200 frames
  std::string verdict;          // "monotone", "oscillating, converges", "unstable: bounded by clamp", ...
};
// alpha = fraction of the GPU time that scales with pixels at the article law's
// post-step fixed point (t = T): alpha = 1 - fixed / T.
double ArticleAlpha(const PlantModel& plant, const ControlTarget& target);
std::vector<SweepRow> SweepArticleGain(const SimConfig& base, int stepsPerDecade = 4);
void PrintSweep(std::ostream& out, const std::vector<SweepRow>& rows, const SimConfig& base);
void WriteSweepCsv(std::ostream& out, const std::vector<SweepRow>& rows);

}  // namespace drr::sim
