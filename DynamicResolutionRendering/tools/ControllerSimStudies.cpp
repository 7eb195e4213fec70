// Studies run on the simulator: the robust law's tuning scan over the
// synthetic set (never the held-out traces) and the article law's gain sweep.
// Declared in ControllerSimCore.h.
#include "ControllerSimCore.h"
#include "ControllerSimReplay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace drr::sim {

void ScanTotals::Add(const SimResult& r) {
  overBudget += r.overBudget;
  changes += r.changes;
  stillChanges += r.stillChanges;
  neverSettled += r.settleApplies && r.settleFrames < 0;
  givenUpPct = (givenUpPct * runs + r.givenUpPct) / (runs + 1);
  ++runs;
}

namespace {

// The grid of the scan; the first row is the law as it was before the scan.
std::vector<RobustController::Params> ScanGrid() {
  std::vector<RobustController::Params> grid;
  struct Risk {
    double quantile;
    int frames;
    bool local;
  };
  for (double maxUp : {1.5, 1.2})
    for (int up : {2, 6})
    for (double upQ : {0.5, 1.0})
      for (Risk risk : {Risk{0.0, 60, false}, Risk{0.75, 60, false}, Risk{0.75, 60, true}}) {
        RobustController::Params p = RobustController::PreviousParams();
        p.maxStepUp = maxUp;
        p.minSamplesUp = up;
        p.upQuantile = upQ;
        p.riskQuantile = risk.quantile;
        p.riskFrames = risk.frames;
        p.riskLocal = risk.local;
        grid.push_back(p);
      }
  return grid;
}

}  // namespace

const ScanTotals& ScanRowTotals::Base(ScanSet set, double headroom) const {
  std::size_t best = 0;
  for (std::size_t h = 0; h < std::size(kScanHeadrooms); ++h)
    if (std::abs(kScanHeadrooms[h] - headroom) < std::abs(kScanHeadrooms[best] - headroom)) best = h;
  return at[best][set];
}

double ScanRowTotals::OverBudgetAt(ScanSet set, double givenUp) const {
  std::vector<std::pair<double, double>> curve;  // (given up, over budget), increasing given up
  for (const auto& h : at) curve.push_back({h[set].givenUpPct, static_cast<double>(h[set].overBudget)});
  std::sort(curve.begin(), curve.end());
  if (givenUp <= curve.front().first) return curve.front().second;
  for (std::size_t i = 1; i < curve.size(); ++i)
    if (givenUp <= curve[i].first) {
      const auto& [g0, o0] = curve[i - 1];
      const auto& [g1, o1] = curve[i];
      return g1 > g0 ? o0 + (o1 - o0) * (givenUp - g0) / (g1 - g0) : o1;
    }
  return curve.back().second;
}

namespace {
// Runs one law's parameters over the tuning set at every scan headroom.
template <class Law, class Row>
void RunScanRow(Row* row, const SimConfig& base, const std::vector<TraceCase>& tuningTraces) {
  for (std::size_t h = 0; h < std::size(kScanHeadrooms); ++h) {
    SimConfig config = base;
    config.target.headroom = kScanHeadrooms[h];
    for (const SyntheticCase& c : SyntheticSet(config))
      for (const auto* list : {&AllScenarios(), &SharedMachineScenarios()})
        for (Scenario s : *list) {
          auto p = row->params;
          p.latencyFrames = c.base.plant.latencyFrames;
          Law law(p);
          row->at[h][list == &AllScenarios() ? kSynthetic : kShared].Add(RunScenario(law, ConfigFor(s, c.base)));
        }
    for (const TraceCase& t : tuningTraces) {
      auto p = row->params;
      p.latencyFrames = kSampleTimerLatency;
      Law law(p);
      ReplaySpec spec;
      spec.headroom = kScanHeadrooms[h];
      row->at[h][kTuningTraces].Add(ReplayTraceWith(law, t.trace, t.cost, spec));
    }
  }
}

std::vector<UEStyleController::Params> UEScanGrid() {
  struct History {
    int size;
    double weight;
  };
  std::vector<UEStyleController::Params> grid;
  for (double blend : {0.9, 0.75})
    for (int period : {8, 4})
      for (double threshold : {0.02, 0.05})
        for (History h : {History{16, 0.9}, History{8, 0.8}, History{32, 0.95}}) {
          UEStyleController::Params p;
          p.increaseBlend = blend;
          p.minChangePeriod = period;
          p.changeThreshold = threshold;
          p.historySize = h.size;
          p.frameWeightExponent = h.weight;
          grid.push_back(p);
        }
  return grid;
}
}  // namespace

namespace {
// One row per parameter set of the grid, each run over the tuning set.
template <class Law, class Row, class Params>
std::vector<Row> ScanRows(const std::vector<Params>& grid, const SimConfig& base,
                          const std::vector<TraceCase>& tuningTraces) {
  std::vector<Row> rows;
  for (const Params& params : grid) {
    Row row;
    row.params = params;
    RunScanRow<Law>(&row, base, tuningTraces);
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

std::vector<RobustScanRow> ScanRobust(const SimConfig& base, const std::vector<TraceCase>& tuningTraces) {
  return ScanRows<RobustController, RobustScanRow>(ScanGrid(), base, tuningTraces);
}

std::vector<UEScanRow> ScanUEStyle(const SimConfig& base, const std::vector<TraceCase>& tuningTraces) {
  return ScanRows<UEStyleController, UEScanRow>(UEScanGrid(), base, tuningTraces);
}

namespace {
// Sum over the sets of the row's over budget at the baseline's given up,
// relative to the baseline's over budget (3 = as the baseline).
double Efficiency(const ScanRowTotals& row, const ScanRowTotals& baseline, double headroom) {
  double sum = 0.0;
  for (ScanSet set : {kSynthetic, kShared, kTuningTraces}) {
    const ScanTotals& b = baseline.Base(set, headroom);
    if (b.runs == 0) {
      sum += 1.0;
      continue;
    }
    sum += row.OverBudgetAt(set, b.givenUpPct) / std::max(1, b.overBudget);
  }
  return sum;
}

// The pick rule of Docs/Controller.md over any law's scan rows.
template <class Row>
int PickRow(const std::vector<Row>& rows, double headroom) {
  if (rows.empty()) return -1;
  const ScanTotals& b = rows.front().Base(kSynthetic, headroom);
  int best = -1;
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    const ScanTotals& s = rows[i].Base(kSynthetic, headroom);
    if (s.givenUpPct > b.givenUpPct + 0.5 || s.changes > 1.1 * b.changes || s.neverSettled > b.neverSettled ||
        s.stillChanges > b.stillChanges)
      continue;
    if (best < 0 || Efficiency(rows[i], rows[0], headroom) < Efficiency(rows[best], rows[0], headroom)) best = i;
  }
  return best;
}

// The columns of a scan row after its parameters: per set over budget / given
// up % / changes at the base headroom, synthetic's still changes and never
// settled, each set's over budget at the baseline's given up, and the score.
std::string ScanColumns(const ScanRowTotals& r, const ScanRowTotals& b, double headroom) {
  const ScanTotals& sy = r.Base(kSynthetic, headroom);
  const ScanTotals& sh = r.Base(kShared, headroom);
  const ScanTotals& tr = r.Base(kTuningTraces, headroom);
  char line[400];
  std::snprintf(line, sizeof line,
                "%d / %.2f / %d | %d / %d | %.0f | %d / %.2f / %d | %.0f | %d / %.2f / %d | %.0f | %.2f |",
                sy.overBudget, sy.givenUpPct, sy.changes, sy.stillChanges, sy.neverSettled,
                r.OverBudgetAt(kSynthetic, b.Base(kSynthetic, headroom).givenUpPct), sh.overBudget, sh.givenUpPct,
                sh.changes, r.OverBudgetAt(kShared, b.Base(kShared, headroom).givenUpPct), tr.overBudget,
                tr.givenUpPct, tr.changes, r.OverBudgetAt(kTuningTraces, b.Base(kTuningTraces, headroom).givenUpPct),
                Efficiency(r, b, headroom));
  return line;
}

const char* kScanHead =
    "At headroom %.2f: over budget / given up %% / changes per set (synthetic also still changes and "
    "never settled); \"at base\": over budget at the baseline's given up, interpolated over headrooms "
    "0.05, 0.1, 0.2, 0.3; score: their sum relative to the baseline (3.00 = as the baseline)\n\n";
const char* kScanColumnsHead = "synthetic | still / never | at base | shared | at base | tuning traces | at base | score |\n";
const char* kScanColumnsRule = " ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
}  // namespace

int PickRobustRow(const std::vector<RobustScanRow>& rows, double headroom) { return PickRow(rows, headroom); }
int PickUEStyleRow(const std::vector<UEScanRow>& rows, double headroom) { return PickRow(rows, headroom); }

void PrintUEStyleScan(std::ostream& out, const std::vector<UEScanRow>& rows, double headroom) {
  char line[512];
  std::snprintf(line, sizeof line, kScanHead, headroom);
  out << line << "| increase blend | change period | threshold | history | " << kScanColumnsHead
      << "| ---: | ---: | ---: | ---: |" << kScanColumnsRule;
  const int picked = PickUEStyleRow(rows, headroom);
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    const auto& p = rows[i].params;
    std::snprintf(line, sizeof line, "| %.2f | %d | %.2f | %d x %.2f^age | ", p.increaseBlend, p.minChangePeriod,
                  p.changeThreshold, p.historySize, p.frameWeightExponent);
    out << line << ScanColumns(rows[i], rows.front(), headroom)
        << (i == 0 ? " baseline" : (i == picked ? " **picked**" : "")) << "\n";
  }
}

void PrintRobustScan(std::ostream& out, const std::vector<RobustScanRow>& rows, double headroom) {
  char line[512];
  std::snprintf(line, sizeof line, kScanHead, headroom);
  out << line << "| max up | up after | up on | risk | " << kScanColumnsHead << "| ---: | ---: | ---: | ---: |"
      << kScanColumnsRule;
  const int picked = PickRobustRow(rows, headroom);
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    const auto& p = rows[i].params;
    char risk[32] = "off";
    if (p.riskQuantile > 0.0)
      std::snprintf(risk, sizeof risk, "%.2f/%d%s", p.riskQuantile, p.riskFrames, p.riskLocal ? " local" : "");
    std::snprintf(line, sizeof line, "| %.1f | %d | %.2f | %s | ", p.maxStepUp, p.minSamplesUp, p.upQuantile, risk);
    out << line << ScanColumns(rows[i], rows.front(), headroom)
        << (i == 0 ? " baseline" : (i == picked ? " **picked**" : "")) << "\n";
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
