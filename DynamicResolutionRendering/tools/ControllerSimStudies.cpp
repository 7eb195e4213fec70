// Studies run on the simulator: the robust law's tuning scan over the
// synthetic set (never the held-out traces) and the article law's gain sweep.
// Declared in ControllerSimCore.h.
#include "ControllerSimCore.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace drr::sim {

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
