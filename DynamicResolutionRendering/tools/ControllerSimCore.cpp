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
// Shared-machine loads (Bursts, Drift).
constexpr double kBurstStartChance = 1.0 / 40.0;  // per frame outside a burst
constexpr double kBurstEndChance = 1.0 / 15.0;    // per frame inside one
constexpr double kBurstMin = 1.5, kBurstMax = 4.0;  // burst factor, log-uniform
// Drift: modelled on the first lavapipe tuning trace (arena-cinematic-fixed08:
// sd of log load 0.49, lag-1 / 5 / 20 autocorrelations 0.93 / 0.84 / 0.60):
// a slow log-load AR(1) plus white frame-to-frame noise of the GPU time.
constexpr double kDriftCorrelation = 0.98;        // slow log-load AR(1) coefficient
constexpr double kDriftSd = 0.4;                  // its stationary standard deviation
constexpr double kDriftFrameSd = 0.1;             // white log noise of each frame's time

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

const std::vector<Scenario>& SharedMachineScenarios() {
  static const std::vector<Scenario> shared = {Scenario::Bursts, Scenario::Drift};
  return shared;
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
    case Scenario::Bursts: return "bursts";
    case Scenario::Drift: return "drift";
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
    case Scenario::Bursts: return "load x1.5..4 in bursts of 15 frames on average, one every 55 (tuning set)";
    case Scenario::Drift: return "load wanders: log-load AR(1) 0.98, sd 0.4, frame noise 0.1 (tuning set)";
  }
  return "";
}

bool ParseScenario(std::string_view name, Scenario* out) {
  for (const auto* list : {&AllScenarios(), &SharedMachineScenarios()})
    for (Scenario s : *list)
      if (ToString(s) == name) {
        if (out) *out = s;
        return true;
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
// The load of a shared machine from the disturbance frame on (Bursts,
// Drift; 1 for the other scenarios), from its own generator so that the
// other scenarios keep their noise sequence. Called once per frame, in order.
class SharedLoad {
public:
  SharedLoad(Scenario s, std::uint32_t seed) : m_Scenario(s), m_Gauss(seed ^ 0x5bd1e995u) {}
  // Multiplier of this frame's measured time beyond the load (Drift's frame noise).
  double FrameNoise() const { return m_FrameNoise; }
  double Next(int n, int d) {
    if (n < d) return 1.0;
    if (m_Scenario == Scenario::Bursts) {
      const double u = m_Gauss.Uniform();
      if (m_Burst == 1.0 && u < kBurstStartChance)
        m_Burst = kBurstMin * std::pow(kBurstMax / kBurstMin, m_Gauss.Uniform());
      else if (m_Burst != 1.0 && u < kBurstEndChance)
        m_Burst = 1.0;
      return m_Burst;
    }
    if (m_Scenario == Scenario::Drift) {
      const double r = kDriftCorrelation;
      m_LogLoad = r * m_LogLoad + kDriftSd * std::sqrt(1.0 - r * r) * m_Gauss.Next();
      m_FrameNoise = std::exp(kDriftFrameSd * m_Gauss.Next());
      return std::exp(m_LogLoad);
    }
    return 1.0;
  }

private:
  Scenario m_Scenario;
  Gauss m_Gauss;
  double m_Burst = 1.0;
  double m_LogLoad = 0.0;
  double m_FrameNoise = 1.0;
};

class SyntheticPlant final : public Plant {
public:
  SyntheticPlant(const SimConfig& c, int d)
      : m_C(c), m_D(d), m_Gauss(c.seed ^ (static_cast<std::uint32_t>(c.scenario) * 0x9E3779B9u)),
        m_Shared(c.scenario, c.seed), m_PreviousLoad(LoadAt(c.scenario, 0, d)) {}
  PlantFrame Frame(int n, double pixelFraction) override {
    const double u = m_Gauss.Uniform();  // drawn every frame so all scenarios share the noise sequence
    Conditions cond = ConditionsAt(m_C, n, m_D, u);
    cond.load *= m_Shared.Next(n, m_D);
    if (cond.load != m_PreviousLoad) m_LastLoadChange = n;
    m_PreviousLoad = cond.load;
    const double rho = std::clamp(m_C.plant.noiseCorrelation, 0.0, 0.999);
    m_Noise = rho * m_Noise + std::sqrt(1.0 - rho * rho) * m_Gauss.Next();
    PlantFrame f;
    f.model = m_C.plant.GpuSeconds(pixelFraction, cond.load);
    f.actual = std::max(0.0, f.model * (1.0 + m_C.plant.noise * m_Noise)) * cond.spike * m_Shared.FrameNoise();
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
  SharedLoad m_Shared;
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

namespace {
// What the law is shown of each frame: the GPU time of the frame latencyFrames
// back, with that frame's scale; fed as the original, the 10-result average of
// those times and DXUT's frame period (or the last frame's period with the
// lastFramePeriod variant) instead; a corrupt frame's injected values over either.
class LawView {
public:
  LawView(Feed feed, int latencyFrames, bool lastFramePeriod)
      : m_Feed(feed), m_LatencyFrames(latencyFrames), m_LastFramePeriod(lastFramePeriod) {
    m_Fps.Tick(m_Clock);
  }

  // Frame f, rendered at scale, has ended: what the law is given now.
  FrameTiming Next(const PlantFrame& f, double scale) {
    m_InFlight.push_back({f.actual, scale});
    const InFlight seen = m_InFlight.front();
    if (static_cast<int>(m_InFlight.size()) > m_LatencyFrames) m_InFlight.pop_front();
    FrameTiming timing{seen.gpu, f.frameSeconds, seen.scale};
    if (m_Feed == Feed::Original) {
      m_Average.Add(seen.gpu);
      m_Clock += f.frameSeconds;
      m_Fps.Tick(m_Clock);  // DXUT counts the frame at the start of the next one
      timing = {m_Average.Value(), m_LastFramePeriod ? f.frameSeconds : m_Fps.FrameSeconds()};
    }
    if (f.corrupt) {
      timing.gpuInnerSeconds = f.corruptGpu;
      if (f.corruptFrame >= 0.0 || std::isnan(f.corruptFrame)) timing.frameSeconds = f.corruptFrame;
    }
    return timing;
  }

private:
  struct InFlight {
    double gpu, scale;
  };
  Feed m_Feed;
  int m_LatencyFrames;
  bool m_LastFramePeriod;
  std::deque<InFlight> m_InFlight;  // GPU times (and their frames' scales) on their way to the controller
  BlockAverage m_Average{10};       // the original's AveragedGPUTimer(10)
  DxutFpsCounter m_Fps;
  double m_Clock = 0.0;  // simulated time at the start of the next frame
};

// The counts after warm-up (SimResult's over budget, changes and still
// changes) and the scales GivenUpPercent compares.
struct LoopMetrics {
  int from = 0;         // LoopSpec::metricsFrom
  double budget = 0.0;  // T
  std::vector<double> scales, budgetScales;

  // Frame n, applied at scale, changed the viewport or not; returns whether
  // it counts as over budget.
  bool Count(int n, const PlantFrame& f, double scale, bool changed, SimResult* r) {
    const bool over = n >= from && f.actual > budget && f.countsOverBudget;
    if (n < from) return over;
    if (over) ++r->overBudget;
    if (changed) ++r->changes;
    if (f.still && changed) ++r->stillChanges;
    scales.push_back(scale);
    budgetScales.push_back(f.budgetScale);
    return over;
  }
};
}  // namespace

SimResult RunLoop(ResolutionController& controller, Plant& plant, const LoopSpec& c, bool keepTrace) {
  const ControlTarget target = SanitizeTarget(c.target);
  const ControlTarget lawTarget = LawTarget(controller, target, c.commonAim);
  const double aim = controller.AimSeconds(lawTarget);

  DynamicResolution dr;
  dr.InitializeResolutionParameters(c.backBufferWidth, c.backBufferHeight, 8192, 8192,
                                    static_cast<float>(std::max(1.0, target.maxScale)));
  dr.SetScale(1.0f, 1.0f);
  const Feed feed = c.feed.value_or(dynamic_cast<ArticleController*>(&controller) ? Feed::Original : Feed::PerResult);
  LawView shown(feed, c.latencyFrames, c.variant.lastFramePeriod);

  SimResult r;
  r.controller = std::string(controller.Name());
  r.scenario = c.scenario;
  r.aimSeconds = aim;
  r.budgetSeconds = target.budgetSeconds;
  r.settleApplies = c.settleApplies;

  LoopMetrics metrics{c.metricsFrom, target.budgetSeconds, {}, {}};
  std::vector<double> err(c.frames, 0.0);
  for (int n = 0; n < c.frames; ++n) {
    const double sx = dr.GetScaleX();
    const double sy = dr.GetScaleY();
    const PlantFrame f = plant.Frame(n, sx * sy);
    const FrameTiming timing = shown.Next(f, sx);

    const unsigned int w0 = dr.GetViewportWidth(), h0 = dr.GetViewportHeight();
    const double next = controller.Update(sx, timing, lawTarget);
    dr.SetScale(static_cast<float>(next), static_cast<float>(next));
    const bool changed = dr.GetViewportWidth() != w0 || dr.GetViewportHeight() != h0;

    err[n] = f.model / aim - 1.0;
    const bool over = metrics.Count(n, f, sx, changed, &r);
    if (keepTrace)
      r.trace.push_back({n, f.load, sx, f.model, timing.gpuInnerSeconds, timing.frameSeconds, changed, f.actual,
                         f.budgetScale, over});
  }
  ScoreResponse(c, err, &r);
  r.finalScale = dr.GetScaleX();
  r.givenUpPct = GivenUpPercent(metrics.scales, metrics.budgetScales);
  return r;
}

SimResult RunScenario(ResolutionController& controller, const SimConfig& config, bool keepTrace) {
  const SimConfig& c = config;
  LoopSpec spec;
  spec.scenario = std::string(ToString(c.scenario));
  spec.frames = std::max(c.frames, kMinFrames);
  spec.metricsFrom = std::clamp(c.disturbanceFrame, 1, spec.frames - kTailFrames);
  spec.settleFrom = SettleFrom(c.scenario, spec.metricsFrom);
  spec.settleApplies = c.scenario != Scenario::Periodic && c.scenario != Scenario::Bursts &&
                       c.scenario != Scenario::Drift;  // loads that never keep still
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

void WritePerFrameCsv(std::ostream& out, const std::vector<SimResult>& results) {
  out << "controller,scenario,frame,load,scale,budget_scale,model_ms,actual_ms,fed_ms,budget_ms,over_budget,changed\n";
  char line[400];
  for (const SimResult& r : results)
    for (const FrameRecord& f : r.trace) {
      std::snprintf(line, sizeof line, "%s,%s,%d,%.5f,%.5f,%.5f,%.4f,%.4f,%.4f,%.4f,%d,%d\n", r.controller.c_str(),
                    r.scenario.c_str(), f.frame, f.load, f.scale, f.budgetScale, f.modelGpu * 1e3, f.actualGpu * 1e3,
                    f.measuredGpu * 1e3, r.budgetSeconds * 1e3, f.overBudget ? 1 : 0, f.changed ? 1 : 0);
      out << line;
    }
}

}  // namespace drr::sim
