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
void ScoreResponse(const SimConfig& c, const std::vector<double>& err, int d, SimResult* r) {
  const int frames = static_cast<int>(err.size());
  // Settling: first frame from which the model time stays in the band to the end.
  const int from = SettleFrom(c.scenario, d);
  int lastOut = -1;
  for (int n = from; n < frames; ++n)
    if (std::abs(err[n]) > c.settleBand) lastOut = n;
  r->settleFrames = lastOut < 0 ? 0 : (lastOut + 1 < frames - kTailFrames / 2 ? lastOut + 1 - from : -1);

  const double e0 = err[from];
  const bool stepLike = std::abs(e0) > c.settleBand && r->settleApplies;
  double over = 0.0;
  for (int n = from; n < frames; ++n) over = std::max(over, stepLike ? -(e0 > 0 ? 1.0 : -1.0) * err[n] : std::abs(err[n]));
  r->overshootPct = 100.0 * over;
  double tail = 0.0;
  for (int n = frames - kTailFrames; n < frames; ++n) tail += err[n];
  r->steadyErrorPct = 100.0 * tail / kTailFrames;
}

}  // namespace

SimResult RunScenario(ResolutionController& controller, const SimConfig& config, bool keepTrace) {
  const SimConfig& c = config;
  const ControlTarget target = SanitizeTarget(c.target);
  const int frames = std::max(c.frames, kMinFrames);
  const int d = std::clamp(c.disturbanceFrame, 1, frames - kTailFrames);
  const double budget = target.budgetSeconds;
  const double aim = controller.AimSeconds(target);

  DynamicResolution dr;
  dr.InitializeResolutionParameters(c.backBufferWidth, c.backBufferHeight, 8192, 8192,
                                    static_cast<float>(std::max(1.0, target.maxScale)));
  dr.SetScale(1.0f, 1.0f);

  Gauss gauss(c.seed ^ (static_cast<std::uint32_t>(c.scenario) * 0x9E3779B9u));
  std::deque<double> inFlight;  // GPU times on their way to the controller (latency)
  const Feed feed = c.feed.value_or(dynamic_cast<ArticleController*>(&controller) ? Feed::Original : Feed::PerResult);
  BlockAverage average(10);  // the original's AveragedGPUTimer(10)
  DxutFpsCounter fps;
  double clock = 0.0;        // simulated time at the start of the next frame
  fps.Tick(clock);

  SimResult r;
  r.controller = std::string(controller.Name());
  r.scenario = std::string(ToString(c.scenario));
  r.aimSeconds = aim;
  r.settleApplies = c.scenario != Scenario::Periodic;

  std::vector<double> err(frames, 0.0);
  int lastLoadChange = 0;
  double previousLoad = LoadAt(c.scenario, 0, d);
  for (int n = 0; n < frames; ++n) {
    const double u = gauss.Uniform();  // drawn every frame so all scenarios share the noise sequence
    const Conditions cond = ConditionsAt(c, n, d, u);
    if (cond.load != previousLoad) lastLoadChange = n;
    previousLoad = cond.load;

    const double sx = dr.GetScaleX();
    const double sy = dr.GetScaleY();
    const double model = c.plant.GpuSeconds(sx * sy, cond.load);
    const double actual = std::max(0.0, model * (1.0 + c.plant.noise * gauss.Next())) * cond.spike;
    double frame = std::max(cond.cpuSeconds, actual);
    if (c.scenario == Scenario::VSync60) frame = std::ceil(frame * 60.0 - 1e-9) / 60.0;

    inFlight.push_back(actual);
    double seen = inFlight.front();
    if (static_cast<int>(inFlight.size()) > c.plant.latencyFrames) inFlight.pop_front();
    FrameTiming timing{seen, frame};
    if (feed == Feed::Original) {
      average.Add(seen);
      clock += frame;
      fps.Tick(clock);  // DXUT counts the frame at the start of the next one
      timing = {average.Value(), c.variant.lastFramePeriod ? frame : fps.FrameSeconds()};
    }
    if (cond.corrupt) {
      timing.gpuInnerSeconds = cond.corruptGpu;
      if (cond.corruptFrame >= 0.0 || std::isnan(cond.corruptFrame)) timing.frameSeconds = cond.corruptFrame;
    }

    const unsigned int w0 = dr.GetViewportWidth(), h0 = dr.GetViewportHeight();
    const double next = controller.Update(sx, timing, target);
    dr.SetScale(static_cast<float>(next), static_cast<float>(next));
    const bool changed = dr.GetViewportWidth() != w0 || dr.GetViewportHeight() != h0;

    err[n] = model / aim - 1.0;
    if (n >= d) {
      if (actual > budget && cond.spike == 1.0) ++r.overBudget;
      if (changed) ++r.changes;
      if (IsStill(c, n, d, lastLoadChange) && changed) ++r.stillChanges;
    }
    if (keepTrace) r.trace.push_back({n, cond.load, sx, model, timing.gpuInnerSeconds, timing.frameSeconds, changed});
  }
  ScoreResponse(c, err, d, &r);
  r.finalScale = dr.GetScaleX();
  return r;
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
      t.push_back({r.controller, 0, 0});
      it = t.end() - 1;
    }
    it->overBudget += r.overBudget;
    it->stillChanges += r.stillChanges;
  }
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
  char line[256];
  std::snprintf(line, sizeof line, "| %-9s | %-9s | %6s | %10s | %11s | %13s | %11s | %7s | %11s |\n", "law", "scenario",
                "settle", "overshoot%", "steady err%", "still changes", "over budget", "changes", "final scale");
  out << line;
  out << "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const SimResult& r : results) {
    std::snprintf(line, sizeof line, "| %-9s | %-9s | %6s | %10.1f | %11.2f | %13d | %11d | %7d | %11.3f |\n",
                  r.controller.c_str(), r.scenario.c_str(), SettleText(r).c_str(), r.overshootPct, r.steadyErrorPct,
                  r.stillChanges, r.overBudget, r.changes, r.finalScale);
    out << line;
  }
  out << "\nTotals over the scenarios above:\n\n| law | over budget | still changes |\n| --- | ---: | ---: |\n";
  for (const Totals& t : Summarise(results)) {
    std::snprintf(line, sizeof line, "| %-9s | %11d | %13d |\n", t.controller.c_str(), t.overBudget, t.stillChanges);
    out << line;
  }
}

void WriteCsv(std::ostream& out, const std::vector<SimResult>& results) {
  out << "controller,scenario,aim_ms,settle_frames,overshoot_pct,steady_error_pct,still_changes,over_budget,changes,"
         "final_scale\n";
  char line[256];
  for (const SimResult& r : results) {
    std::snprintf(line, sizeof line, "%s,%s,%.4f,%s,%.3f,%.3f,%d,%d,%d,%.5f\n", r.controller.c_str(),
                  r.scenario.c_str(), r.aimSeconds * 1000.0, SettleText(r).c_str(), r.overshootPct,
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
