// Simulator core: see ControllerSimCore.h.
#include "ControllerSimCore.h"

#include "DynamicResolution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <ostream>
#include <random>

namespace drr::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRampFrames = 200;
constexpr int kCpuBoundFrames = 300;
constexpr int kSpikePeriod = 37;
constexpr int kCorruptPeriod = 5;
constexpr int kTailFrames = 100;

// Deterministic N(0,1) from mt19937 (Box-Muller).
class Gauss {
public:
  explicit Gauss(std::uint32_t seed) : m_Rng(seed) {}
  double Uniform() { return (static_cast<double>(m_Rng()) + 0.5) / 4294967296.0; }
  double Next() {
    if (m_HaveSpare) {
      m_HaveSpare = false;
      return m_Spare;
    }
    const double r = std::sqrt(-2.0 * std::log(Uniform()));
    const double a = 2.0 * kPi * Uniform();
    m_Spare = r * std::sin(a);
    m_HaveSpare = true;
    return r * std::cos(a);
  }

private:
  std::mt19937 m_Rng;
  bool m_HaveSpare = false;
  double m_Spare = 0.0;
};

struct Conditions {
  double load = 1.0;
  double cpuSeconds = 0.0;
  double spike = 1.0;         // multiplier of the real GPU time of this frame
  bool corrupt = false;
  double corruptGpu = 0.0;    // value the controller sees instead
  double corruptFrame = 0.0;
};

double LoadAt(Scenario s, int n, int d) {
  if (n < d) return 1.0;
  switch (s) {
    case Scenario::Step2x:
    case Scenario::VSync60: return 2.0;
    case Scenario::StepHalf: return 0.5;
    case Scenario::Ramp: return 1.0 + std::min(1.0, static_cast<double>(n - d) / kRampFrames);
    case Scenario::Periodic: return 1.0 + 0.5 * std::sin(2.0 * kPi * (n - d) / 120.0);
    default: return 1.0;
  }
}

int SettleFrom(Scenario s, int d) { return s == Scenario::Ramp ? d + kRampFrames : d; }

}  // namespace

const std::vector<Scenario>& AllScenarios() {
  static const std::vector<Scenario> all = {Scenario::Step2x,   Scenario::StepHalf, Scenario::Ramp,
                                            Scenario::Periodic, Scenario::CpuBound, Scenario::Spikes,
                                            Scenario::NaN,      Scenario::VSync60,  Scenario::Still};
  return all;
}

std::string_view ToString(Scenario s) {
  switch (s) {
    case Scenario::Step2x: return "step2x";
    case Scenario::StepHalf: return "step-half";
    case Scenario::Ramp: return "ramp";
    case Scenario::Periodic: return "periodic";
    case Scenario::CpuBound: return "cpu-bound";
    case Scenario::Spikes: return "spikes";
    case Scenario::NaN: return "nan";
    case Scenario::VSync60: return "vsync60";
    case Scenario::Still: return "still";
  }
  return "?";
}

std::string_view Describe(Scenario s) {
  switch (s) {
    case Scenario::Step2x: return "load x2 at the disturbance frame";
    case Scenario::StepHalf: return "load x0.5 at the disturbance frame";
    case Scenario::Ramp: return "load ramps 1 -> 2 over 200 frames (settling counted from the ramp's end)";
    case Scenario::Periodic: return "load 1 + 0.5 sin(2 pi n / 120)";
    case Scenario::CpuBound: return "300 frames with CPU time 20..45 ms (frame time >> GPU time), load still";
    case Scenario::Spikes: return "every 37th frame takes 100x the GPU time, load still";
    case Scenario::NaN: return "every 5th GPU sample is NaN, +Inf, -Inf, 0, 1e-9 or negative, load still";
    case Scenario::VSync60: return "load x2, frame time rounded up to multiples of 1/60 s";
    case Scenario::Still: return "constant load, noise 0.2 %";
  }
  return "";
}

bool ParseScenario(std::string_view name, Scenario* out) {
  for (Scenario s : AllScenarios()) {
    if (ToString(s) == name) {
      if (out) *out = s;
      return true;
    }
  }
  return false;
}

SimConfig ConfigFor(Scenario scenario, const SimConfig& base) {
  SimConfig c = base;
  c.scenario = scenario;
  if (scenario == Scenario::Still) c.plant.noise = std::min(base.plant.noise, 0.002);
  return c;
}

namespace {

// The disturbance of frame n (d: the disturbance frame); u: this frame's
// uniform draw, for the CPU-bound frame times.
Conditions ConditionsAt(const SimConfig& c, int n, int d, double u) {
  static const double kCorrupt[] = {std::numeric_limits<double>::quiet_NaN(),
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    0.0,
                                    1e-9,
                                    -0.004};
  Conditions cond;
  cond.load = LoadAt(c.scenario, n, d);
  cond.cpuSeconds = c.plant.cpuSeconds;
  if (n < d) return cond;
  if (c.scenario == Scenario::CpuBound && n < d + kCpuBoundFrames) cond.cpuSeconds = 0.020 + 0.025 * u;
  if (c.scenario == Scenario::Spikes && (n - d) % kSpikePeriod == 0) cond.spike = 100.0;
  if (c.scenario == Scenario::NaN && (n - d) % kCorruptPeriod == 0) {
    const int i = ((n - d) / kCorruptPeriod) % 6;
    cond.corrupt = true;
    cond.corruptGpu = kCorrupt[i];
    // Some corrupt samples also carry a corrupt frame time.
    cond.corruptFrame = (i % 2 == 0) ? kCorrupt[(i + 1) % 6] : -1.0;
  }
  return cond;
}

// Whether frame n counts as still (load settled) for the still-changes count.
bool IsStill(const SimConfig& c, int n, int d, int lastLoadChange) {
  return c.scenario != Scenario::Periodic && c.scenario != Scenario::Ramp
             ? n - lastLoadChange >= c.stillAfterFrames
             : (c.scenario == Scenario::Ramp && n - (d + kRampFrames) >= c.stillAfterFrames);
}

// Settling time, overshoot and steady-state error from the per-frame
// relative error of the model time against the aim.
void ScoreResponse(const LoopSpec& c, const std::vector<double>& err, SimResult* r) {
  const int frames = static_cast<int>(err.size());
  // Settling: first frame from which the model time stays in the band to the end.
  const int from = c.settleFrom;
  int lastOut = -1;
  for (int n = from; n < frames; ++n)
    if (std::abs(err[n]) > c.settleBand) lastOut = n;
  r->settleFrames = lastOut < 0 ? 0 : (lastOut + 1 < frames - kTailFrames / 2 ? lastOut + 1 - from : -1);
  if (c.settleIsFirstReach) {
    r->settleFrames = -1;
    for (int n = from; n < frames && r->settleFrames < 0; ++n)
      if (std::abs(err[n]) <= c.settleBand) r->settleFrames = n - from;
  }

  const double e0 = err[from];
  const bool stepLike = std::abs(e0) > c.settleBand && r->settleApplies;
  double over = 0.0;
  for (int n = from; n < frames; ++n) over = std::max(over, stepLike ? -(e0 > 0 ? 1.0 : -1.0) * err[n] : std::abs(err[n]));
  r->overshootPct = 100.0 * over;
  double tail = 0.0;
  for (int n = frames - kTailFrames; n < frames; ++n) tail += err[n];
  r->steadyErrorPct = 100.0 * tail / kTailFrames;
}

// The synthetic plant: the model of ControllerSimCore.h with the scenario's
// disturbances, white or AR(1)-correlated noise.
class SyntheticPlant final : public Plant {
public:
  SyntheticPlant(const SimConfig& c, int d)
      : m_C(c), m_D(d), m_Gauss(c.seed ^ (static_cast<std::uint32_t>(c.scenario) * 0x9E3779B9u)),
        m_PreviousLoad(LoadAt(c.scenario, 0, d)) {}
  PlantFrame Frame(int n, double pixelFraction) override {
    const double u = m_Gauss.Uniform();  // drawn every frame so all scenarios share the noise sequence
    const Conditions cond = ConditionsAt(m_C, n, m_D, u);
    if (cond.load != m_PreviousLoad) m_LastLoadChange = n;
    m_PreviousLoad = cond.load;
    const double rho = std::clamp(m_C.plant.noiseCorrelation, 0.0, 0.999);
    m_Noise = rho * m_Noise + std::sqrt(1.0 - rho * rho) * m_Gauss.Next();
    PlantFrame f;
    f.model = m_C.plant.GpuSeconds(pixelFraction, cond.load);
    f.actual = std::max(0.0, f.model * (1.0 + m_C.plant.noise * m_Noise)) * cond.spike;
    f.frameSeconds = std::max(cond.cpuSeconds, f.actual);
    if (m_C.scenario == Scenario::VSync60) f.frameSeconds = std::ceil(f.frameSeconds * 60.0 - 1e-9) / 60.0;
    f.load = cond.load;
    f.budgetScale = BudgetScale(m_C.plant, cond.load, SanitizeTarget(m_C.target));
    f.countsOverBudget = cond.spike == 1.0;
    f.still = IsStill(m_C, n, m_D, m_LastLoadChange);
    f.corrupt = cond.corrupt;
    f.corruptGpu = cond.corruptGpu;
    f.corruptFrame = cond.corruptFrame;
    return f;
  }

private:
  const SimConfig& m_C;
  int m_D;
  Gauss m_Gauss;
  double m_PreviousLoad;
  int m_LastLoadChange = 0;
  double m_Noise = 0.0;  // AR(1) state, unit variance
};

}  // namespace

double BudgetScale(const PlantModel& plant, double load, const ControlTarget& sanitized) {
  const double pixelPart = sanitized.budgetSeconds - plant.fixedSeconds;
  const double s = pixelPart > 0.0 ? std::sqrt(pixelPart / (plant.pixelSeconds * load)) : 0.0;
  return std::clamp(s, sanitized.minScale, sanitized.maxScale);
}

double GivenUpPercent(const std::vector<double>& scales, const std::vector<double>& budgetScales) {
  double sum = 0.0, budgetSum = 0.0;
  for (std::size_t i = 0; i < std::min(scales.size(), budgetScales.size()); ++i) {
    sum += scales[i];
    budgetSum += budgetScales[i];
  }
  return budgetSum > 0.0 ? 100.0 * (1.0 - sum / budgetSum) : 0.0;
}

ControlTarget LawTarget(const ResolutionController& controller, const ControlTarget& target, bool commonAim) {
  ControlTarget t = SanitizeTarget(target);
  if (!commonAim) return t;
  // A law whose own aim ignores the headroom (the article law steers to its
  // budget) is handed the budget that puts its aim on T (1 - headroom).
  const double common = t.budgetSeconds * (1.0 - t.headroom);
  t.budgetSeconds *= common / controller.AimSeconds(t);
  return t;
}

SimResult RunLoop(ResolutionController& controller, Plant& plant, const LoopSpec& c, bool keepTrace) {
  const ControlTarget target = SanitizeTarget(c.target);
  const ControlTarget lawTarget = LawTarget(controller, target, c.commonAim);
  const int frames = c.frames;
  const double budget = target.budgetSeconds;
  const double aim = controller.AimSeconds(lawTarget);

  DynamicResolution dr;
  dr.InitializeResolutionParameters(c.backBufferWidth, c.backBufferHeight, 8192, 8192,
                                    static_cast<float>(std::max(1.0, target.maxScale)));
  dr.SetScale(1.0f, 1.0f);

  struct InFlight {
    double gpu, scale;
  };
  std::deque<InFlight> inFlight;  // GPU times (and their frames' scales) on their way to the controller
  const Feed feed = c.feed.value_or(dynamic_cast<ArticleController*>(&controller) ? Feed::Original : Feed::PerResult);
  BlockAverage average(10);  // the original's AveragedGPUTimer(10)
  DxutFpsCounter fps;
  double clock = 0.0;        // simulated time at the start of the next frame
  fps.Tick(clock);

  SimResult r;
  r.controller = std::string(controller.Name());
  r.scenario = c.scenario;
  r.aimSeconds = aim;
  r.settleApplies = c.settleApplies;

  std::vector<double> err(frames, 0.0), scales, budgetScales;
  for (int n = 0; n < frames; ++n) {
    const double sx = dr.GetScaleX();
    const double sy = dr.GetScaleY();
    const PlantFrame f = plant.Frame(n, sx * sy);

    inFlight.push_back({f.actual, sx});
    const InFlight seen = inFlight.front();
    if (static_cast<int>(inFlight.size()) > c.latencyFrames) inFlight.pop_front();
    FrameTiming timing{seen.gpu, f.frameSeconds, seen.scale};
    if (feed == Feed::Original) {
      average.Add(seen.gpu);
      clock += f.frameSeconds;
      fps.Tick(clock);  // DXUT counts the frame at the start of the next one
      timing = {average.Value(), c.variant.lastFramePeriod ? f.frameSeconds : fps.FrameSeconds()};
    }
    if (f.corrupt) {
      timing.gpuInnerSeconds = f.corruptGpu;
      if (f.corruptFrame >= 0.0 || std::isnan(f.corruptFrame)) timing.frameSeconds = f.corruptFrame;
    }

    const unsigned int w0 = dr.GetViewportWidth(), h0 = dr.GetViewportHeight();
    const double next = controller.Update(sx, timing, lawTarget);
    dr.SetScale(static_cast<float>(next), static_cast<float>(next));
    const bool changed = dr.GetViewportWidth() != w0 || dr.GetViewportHeight() != h0;

    err[n] = f.model / aim - 1.0;
    if (n >= c.metricsFrom) {
      if (f.actual > budget && f.countsOverBudget) ++r.overBudget;
      if (changed) ++r.changes;
      if (f.still && changed) ++r.stillChanges;
      scales.push_back(sx);
      budgetScales.push_back(f.budgetScale);
    }
    if (keepTrace) r.trace.push_back({n, f.load, sx, f.model, timing.gpuInnerSeconds, timing.frameSeconds, changed});
  }
  ScoreResponse(c, err, &r);
  r.finalScale = dr.GetScaleX();
  r.givenUpPct = GivenUpPercent(scales, budgetScales);
  return r;
}

SimResult RunScenario(ResolutionController& controller, const SimConfig& config, bool keepTrace) {
  const SimConfig& c = config;
  LoopSpec spec;
  spec.scenario = std::string(ToString(c.scenario));
  spec.frames = std::max(c.frames, kMinFrames);
  spec.metricsFrom = std::clamp(c.disturbanceFrame, 1, spec.frames - kTailFrames);
  spec.settleFrom = SettleFrom(c.scenario, spec.metricsFrom);
  spec.settleApplies = c.scenario != Scenario::Periodic;
  spec.target = c.target;
  spec.commonAim = c.commonAim;
  spec.feed = c.feed;
  spec.variant = c.variant;
  spec.latencyFrames = c.plant.latencyFrames;
  spec.backBufferWidth = c.backBufferWidth;
  spec.backBufferHeight = c.backBufferHeight;
  spec.settleBand = c.settleBand;
  SyntheticPlant plant(c, spec.metricsFrom);
  return RunLoop(controller, plant, spec, keepTrace);
}

const std::vector<ControlLaw>& AllLaws() {
  static const std::vector<ControlLaw> laws = {ControlLaw::Article, ControlLaw::UEStyle, ControlLaw::Robust};
  return laws;
}

std::vector<SimResult> RunMatrix(const std::vector<ControlLaw>& laws, const std::vector<Scenario>& scenarios,
                                 const SimConfig& base) {
  std::vector<SimResult> out;
  for (ControlLaw law : laws) {
    for (Scenario s : scenarios) {
      const SimConfig c = ConfigFor(s, base);
      auto controller = MakeController(law, c.plant.latencyFrames);
      out.push_back(RunScenario(*controller, c));
    }
  }
  return out;
}

std::vector<SyntheticCase> SyntheticSet(const SimConfig& base) {
  std::vector<SyntheticCase> set;
  for (int latency = 0; latency <= 3; ++latency) {
    for (const bool correlated : {false, true}) {
      SyntheticCase c{"latency " + std::to_string(latency) + (correlated ? ", AR(0.9) 3 %" : ", white 1 %"), base};
      c.base.plant.latencyFrames = latency;
      c.base.plant.noise = correlated ? 0.03 : 0.01;
      c.base.plant.noiseCorrelation = correlated ? 0.9 : 0.0;
      set.push_back(c);
    }
  }
  return set;
}

std::vector<RobustScanRow> ScanRobustOnSyntheticSet(const SimConfig& base) {
  std::vector<RobustScanRow> rows;
  for (int window : {9, 15})
    for (double deadband : {0.03, 0.05})
      for (double z : {3.5, 5.0})
        for (bool spread : {false, true}) {
          RobustScanRow row;
          row.params.medianWindow = window;
          row.params.deadband = deadband;
          row.params.noiseZ = z;
          row.params.spreadNoise = spread;
          int runs = 0;
          for (const SyntheticCase& c : SyntheticSet(base)) {
            for (Scenario s : AllScenarios()) {
              RobustController::Params p = row.params;
              p.latencyFrames = c.base.plant.latencyFrames;
              RobustController law(p);
              const SimResult r = RunScenario(law, ConfigFor(s, c.base));
              row.overBudget += r.overBudget;
              row.changes += r.changes;
              row.stillChanges += r.stillChanges;
              row.neverSettled += r.settleApplies && r.settleFrames < 0;
              row.givenUpPct += r.givenUpPct;
              ++runs;
            }
          }
          row.givenUpPct /= std::max(1, runs);
          rows.push_back(row);
        }
  return rows;
}

void PrintRobustScan(std::ostream& out, const std::vector<RobustScanRow>& rows) {
  out << "| window | deadband | noiseZ | spread | over budget | given up % | changes | still changes | never settled |\n"
         "| ---: | ---: | ---: | :---: | ---: | ---: | ---: | ---: | ---: |\n";
  char line[200];
  for (const RobustScanRow& r : rows) {
    std::snprintf(line, sizeof line, "| %d | %.2f | %.1f | %s | %d | %.2f | %d | %d | %d |\n", r.params.medianWindow,
                  r.params.deadband, r.params.noiseZ, r.params.spreadNoise ? "yes" : "no", r.overBudget,
                  r.givenUpPct, r.changes, r.stillChanges, r.neverSettled);
    out << line;
  }
}

bool ParseArticleVariant(std::string_view name, ArticleVariant* variant) {
  for (ArticleVariant v : {ArticleVariant::Original, ArticleVariant::FramePeriod, ArticleVariant::AppliedScale})
    if (ToString(v) == name) {
      if (variant) *variant = v;
      return true;
    }
  return false;
}

std::string_view ToString(ArticleVariant v) {
  switch (v) {
    case ArticleVariant::Original: return "original";
    case ArticleVariant::FramePeriod: return "frame-period";
    case ArticleVariant::AppliedScale: return "applied-scale";
  }
  return "?";
}

std::vector<SimResult> RunArticleVariant(ArticleVariant variant, const std::vector<Scenario>& scenarios,
                                         const SimConfig& base) {
  std::vector<SimResult> out;
  for (Scenario s : scenarios) {
    SimConfig c = ConfigFor(s, base);
    c.commonAim = false;  // the original's own aim, T
    c.feed = Feed::Original;
    c.variant.lastFramePeriod = variant == ArticleVariant::FramePeriod;
    ArticleController article;
    AppliedScaleArticle applied;
    ResolutionController& law =
        variant == ArticleVariant::AppliedScale ? static_cast<ResolutionController&>(applied) : article;
    SimResult r = RunScenario(law, c);
    r.controller = "article/" + std::string(ToString(variant));
    out.push_back(r);
  }
  return out;
}

std::vector<Totals> Summarise(const std::vector<SimResult>& results) {
  std::vector<Totals> t;
  for (const SimResult& r : results) {
    auto it = std::find_if(t.begin(), t.end(), [&](const Totals& x) { return x.controller == r.controller; });
    if (it == t.end()) {
      t.push_back(Totals{});
      it = t.end() - 1;
      it->controller = r.controller;
    }
    it->overBudget += r.overBudget;
    it->stillChanges += r.stillChanges;
    it->changes += r.changes;
    it->neverSettled += r.settleApplies && r.settleFrames < 0;
    it->givenUpPct += r.givenUpPct;  // a sum until the end
    ++it->runs;
  }
  for (Totals& x : t) x.givenUpPct /= std::max(1, x.runs);
  return t;
}

namespace {
std::string SettleText(const SimResult& r) {
  if (!r.settleApplies) return "n/a";
  if (r.settleFrames < 0) return "never";
  return std::to_string(r.settleFrames);
}
}  // namespace

void PrintTable(std::ostream& out, const std::vector<SimResult>& results) {
  char line[320];
  std::snprintf(line, sizeof line, "| %-9s | %-9s | %7s | %11s | %6s | %10s | %11s | %13s | %7s | %11s |\n", "law",
                "scenario", "aim ms", "given up %", "settle", "overshoot%", "steady err%", "still changes",
                "changes", "over budget");
  out << line;
  out << "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const SimResult& r : results) {
    std::snprintf(line, sizeof line, "| %-9s | %-9s | %7.2f | %11.1f | %6s | %10.1f | %11.2f | %13d | %7d | %11d |\n",
                  r.controller.c_str(), r.scenario.c_str(), r.aimSeconds * 1000.0, r.givenUpPct,
                  SettleText(r).c_str(), r.overshootPct, r.steadyErrorPct, r.stillChanges, r.changes, r.overBudget);
    out << line;
  }
  out << "\nTotals over the runs above (given up: mean over the runs):\n\n"
         "| law | over budget | given up % | changes | still changes | never settled |\n"
         "| --- | ---: | ---: | ---: | ---: | ---: |\n";
  for (const Totals& t : Summarise(results)) {
    std::snprintf(line, sizeof line, "| %-9s | %11d | %10.1f | %7d | %13d | %13d |\n", t.controller.c_str(),
                  t.overBudget, t.givenUpPct, t.changes, t.stillChanges, t.neverSettled);
    out << line;
  }
}

void WriteCsv(std::ostream& out, const std::vector<SimResult>& results) {
  out << "controller,scenario,aim_ms,given_up_pct,settle_frames,overshoot_pct,steady_error_pct,still_changes,"
         "over_budget,changes,final_scale\n";
  char line[320];
  for (const SimResult& r : results) {
    std::snprintf(line, sizeof line, "%s,%s,%.4f,%.3f,%s,%.3f,%.3f,%d,%d,%d,%.5f\n", r.controller.c_str(),
                  r.scenario.c_str(), r.aimSeconds * 1000.0, r.givenUpPct, SettleText(r).c_str(), r.overshootPct,
                  r.steadyErrorPct, r.stillChanges, r.overBudget, r.changes, r.finalScale);
    out << line;
  }
}

// ----------------------------------------------------------------- k sweep
//
// Stability of the article law. With the plant t(S) = c + p L S^2 and the law
// S' = S (1 + k (1 - t(S)/T)), the fixed point S* has t(S*) = T. Linearising,
// with S = S* (1 + e):
//   d S'/d S at S* = 1 + k (1 - t/T) - k S* t'(S*) / T = 1 - 2 k p L S*^2 / T
//                  = 1 - 2 k alpha,   alpha = (T - c) / T  (pixel-bound share of T)
// so e' = (1 - 2 k alpha) e:
//   k < 1 / (2 alpha)              monotone convergence (rate 1 - 2 k alpha per frame)
//   1 / (2 alpha) < k < 1 / alpha  alternating, still converging
//   k > 1 / alpha                  |multiplier| > 1: the alternation grows (period-2
//                                  flip); the linear law would diverge, the clamp
//                                  [minScale, maxScale] holds it in a bounded
//                                  2-cycle, and for k (t/T - 1) > 1 the raw S'
//                                  is negative, which only the clamp rescues.
// For a purely pixel-bound GPU (c = 0): alpha = 1, alternation above k = 0.5,
// instability above k = 1. Two effects the linear model leaves out show up in
// the sweep: the floor() of the integral viewport makes tiny steps (k (1 - t/T)
// S W < 1 px) round down only, so small gains ratchet downwards; and with vsync
// t = (t_gpu + T)/2 for GPU-bound frames under T, which halves the effective gain
// from below.
double ArticleAlpha(const PlantModel& plant, const ControlTarget& target) {
  const ControlTarget t = SanitizeTarget(target);
  return std::clamp((t.budgetSeconds - plant.fixedSeconds) / t.budgetSeconds, 0.0, 1.0);
}

std::vector<SweepRow> SweepArticleGain(const SimConfig& base, int stepsPerDecade) {
  stepsPerDecade = std::max(1, stepsPerDecade);
  const ControlTarget target = SanitizeTarget(base.target);
  const double alpha = ArticleAlpha(base.plant, target);
  std::vector<SweepRow> rows;
  const int steps = 4 * stepsPerDecade;  // 1e-3 .. 1e1
  for (int i = 0; i <= steps; ++i) {
    const double k = std::pow(10.0, -3.0 + static_cast<double>(i) / stepsPerDecade);
    ArticleController law(k);
    SimConfig c = ConfigFor(Scenario::Step2x, base);
    c.commonAim = false;  // the analysis is about the original's fixed point t = T
    const SimResult r = RunScenario(law, c, /*keepTrace=*/true);
    SweepRow row;
    row.gain = k;
    row.multiplier = 1.0 - 2.0 * k * alpha;
    row.settleFrames = r.settleFrames;
    const int n = static_cast<int>(r.trace.size());
    double lo = 1e9, hi = -1e9, sum = 0.0;
    int moves = 0, reversals = 0, lastDir = 0;
    for (int j = n - 200; j < n; ++j) {
      const double s = r.trace[j].scale;
      lo = std::min(lo, s);
      hi = std::max(hi, s);
      sum += s;
      if (j > n - 200) {
        const double ds = s - r.trace[j - 1].scale;
        const int dir = ds > 0 ? 1 : (ds < 0 ? -1 : 0);
        if (dir != 0) {
          ++moves;
          if (lastDir != 0 && dir != lastDir) ++reversals;
          lastDir = dir;
        }
      }
    }
    row.amplitudePct = 100.0 * (hi - lo) / (sum / 200.0);
    row.alternation = moves > 0 ? static_cast<double>(reversals) / moves : 0.0;
    const double minS = target.minScale, maxS = target.maxScale;
    row.hitsClamp = lo <= minS * 1.0001 || hi >= maxS * 0.9999;
    if (row.amplitudePct > 10.0 && row.alternation > 0.8)
      row.verdict = row.hitsClamp ? "unstable: 2-cycle held by the clamp" : "unstable: sustained alternation";
    else if (row.settleFrames < 0)
      row.verdict = "does not settle (too slow / ratchets)";
    else if (row.multiplier < 0.0)
      row.verdict = "alternating, converges";
    else
      row.verdict = "monotone, converges";
    rows.push_back(row);
  }
  return rows;
}

void PrintSweep(std::ostream& out, const std::vector<SweepRow>& rows, const SimConfig& base) {
  const double alpha = ArticleAlpha(base.plant, base.target);
  char line[256];
  std::snprintf(line, sizeof line,
                "Article law gain sweep on step2x (alpha = (T - c)/T = %.3f): alternation above k = 1/(2 alpha) = "
                "%.3f, linear instability above k = 1/alpha = %.3f\n\n",
                alpha, 0.5 / alpha, 1.0 / alpha);
  out << line;
  out << "| k | 1 - 2 k alpha | settle | amplitude% (last 200) | reversals | at clamp | verdict |\n"
         "| ---: | ---: | ---: | ---: | ---: | :---: | --- |\n";
  for (const SweepRow& r : rows) {
    std::snprintf(line, sizeof line, "| %.4g | %+.3f | %s | %.1f | %.2f | %s | %s |\n", r.gain, r.multiplier,
                  r.settleFrames < 0 ? "never" : std::to_string(r.settleFrames).c_str(), r.amplitudePct,
                  r.alternation, r.hitsClamp ? "yes" : "no", r.verdict.c_str());
    out << line;
  }
  const SweepRow* first = nullptr;
  for (const SweepRow& r : rows)
    if (r.verdict.rfind("unstable", 0) == 0) {
      first = &r;
      break;
    }
  if (first) {
    std::snprintf(line, sizeof line, "\nFirst unstable gain in the sweep: k = %.4g (analytic bound 1/alpha = %.3f)\n",
                  first->gain, 1.0 / alpha);
    out << line;
  } else {
    out << "\nNo unstable gain in the sweep.\n";
  }
}

void WriteSweepCsv(std::ostream& out, const std::vector<SweepRow>& rows) {
  out << "gain,multiplier,settle_frames,amplitude_pct,alternation,hits_clamp,verdict\n";
  char line[256];
  for (const SweepRow& r : rows) {
    std::snprintf(line, sizeof line, "%.6g,%.4f,%d,%.3f,%.3f,%d,\"%s\"\n", r.gain, r.multiplier, r.settleFrames,
                  r.amplitudePct, r.alternation, r.hitsClamp ? 1 : 0, r.verdict.c_str());
    out << line;
  }
}

}  // namespace drr::sim
