// The fair comparison of the laws (Docs/Controller.md "Fair comparison"):
// one aim for every law, resolution given up, UE-style pairing each GPU time
// with its frame's scale and keeping its minimum change period, correlated
// noise, and the replay of the held-out traces.
#include "ControllerSimCore.h"
#include "ControllerSimReplay.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace {

using namespace drr;
using namespace drr::sim;

constexpr double kT = 1.0 / 60.0;
ControlTarget Target() { return ControlTarget{kT, 0.1, 0.3, 1.0}; }

TEST(FairComparison, EveryLawAimsAtTheSameTime) {
  const ControlTarget tg = Target();
  for (ControlLaw law : AllLaws()) {
    auto c = MakeController(law, 1);
    EXPECT_DOUBLE_EQ(c->AimSeconds(LawTarget(*c, tg, true)), kT * 0.9) << ControlLawOption(law);
  }
  // The matrix reports the aim each law was run at: all equal.
  for (const SimResult& r : RunMatrix(AllLaws(), {Scenario::Step2x, Scenario::Still}, SimConfig{}))
    EXPECT_DOUBLE_EQ(r.aimSeconds, kT * 0.9) << r.controller;
  // Without the common aim the article law keeps the original's: T itself.
  ArticleController article;
  EXPECT_DOUBLE_EQ(article.AimSeconds(LawTarget(article, tg, false)), kT);
  // and it really steers there: the step settles at T (1 - headroom).
  SimConfig c = ConfigFor(Scenario::Step2x, SimConfig{});
  c.plant.noise = 0.0;
  ArticleController settled;
  EXPECT_LT(std::abs(RunScenario(settled, c).steadyErrorPct), 0.5);
}

TEST(FairComparison, GivenUpOnAHandMadeTrace) {
  // Scales 0.5, 0.5, 0.8 against budget scales 0.5, 1.0, 0.8: 1 - 1.8 / 2.3.
  EXPECT_NEAR(GivenUpPercent({0.5, 0.5, 0.8}, {0.5, 1.0, 0.8}), 100.0 * (1.0 - 1.8 / 2.3), 1e-12);
  EXPECT_DOUBLE_EQ(GivenUpPercent({0.9}, {0.6}), -50.0);  // above the budget scale: negative
  EXPECT_DOUBLE_EQ(GivenUpPercent({}, {}), 0.0);
  // Budget scale of the model: t = 2 ms + 30 ms s^2 load = T at s = sqrt((T - 2 ms) / (30 ms load)).
  const PlantModel plant;
  EXPECT_NEAR(BudgetScale(plant, 2.0, Target()), std::sqrt((kT - 0.002) / 0.060), 1e-12);
  EXPECT_DOUBLE_EQ(BudgetScale(plant, 100.0, Target()), 0.3);  // out of reach: the range's end
  EXPECT_DOUBLE_EQ(BudgetScale(plant, 0.01, Target()), 1.0);
}

TEST(FairComparison, GivenUpMatchesTheTracedScales) {
  // Recompute the figure from the per-frame trace of a run, independently.
  SimConfig c = ConfigFor(Scenario::Step2x, SimConfig{});
  auto law = MakeController(ControlLaw::UEStyle, c.plant.latencyFrames);
  const SimResult r = RunScenario(*law, c, true);
  double sum = 0.0, budget = 0.0;
  for (const FrameRecord& f : r.trace) {
    if (f.frame < c.disturbanceFrame) continue;
    sum += f.scale;
    budget += std::sqrt((kT - 0.002) / (0.030 * f.load));
  }
  EXPECT_NEAR(r.givenUpPct, 100.0 * (1.0 - sum / budget), 1e-9);
  EXPECT_GT(r.givenUpPct, 0.0);  // the aim is 10 % under the budget
}

TEST(UEStyle, PairsEachTimeWithItsFramesScale) {
  const ControlTarget tg = Target();
  const double aim = 0.9 * kT;
  // A time exactly at the aim, measured at scale 1 while the scale is now 0.5:
  // scale 1 was right, so the law moves up. Read as the cost of 0.5 it would hold.
  UEStyleController paired;
  EXPECT_GT(paired.Update(0.5, {aim, aim, 1.0}, tg), 0.5);
  UEStyleController unpaired;
  EXPECT_EQ(unpaired.Update(0.5, {aim, aim, 0.0}, tg), 0.5);
  // Without gpuScale, latencyFrames names the call whose scale the time measured.
  UEStyleController::Params p;
  p.latencyFrames = 2;
  UEStyleController delayed(p);
  const double over = 1.05 * kT;  // over budget but one frame only: no panic
  EXPECT_EQ(delayed.Update(1.0, {0.0, aim}, tg), 1.0);  // no result yet
  EXPECT_EQ(delayed.Update(1.0, {0.0, aim}, tg), 1.0);
  // The scale dropped to 0.5; this time is frame 1.0's (2 calls ago): it
  // suggests 1.0 sqrt(aim / over) = 0.926, i.e. up from 0.5.
  EXPECT_GT(delayed.Update(0.5, {over, over}, tg), 0.5);
}

TEST(UEStyle, KeepsTheMinimumChangePeriod) {
  const ControlTarget tg = Target();
  UEStyleController::Params p;
  p.minChangePeriod = 8;
  UEStyleController law(p);
  // Times alternating far under and just under the budget (never two over it:
  // no panic) ask for a change at every call.
  double s = 0.7;
  int lastChange = -1000, changes = 0;
  for (int i = 0; i < 400; ++i) {
    const double t = (i / 3) % 2 ? 0.5 * kT : 0.99 * kT;
    const double next = law.Update(s, {t, t, s}, tg);
    if (next != s) {
      EXPECT_GE(i - lastChange, 8) << i;
      lastChange = i;
      ++changes;
    }
    s = next;
  }
  EXPECT_GT(changes, 10);  // it did change, at most every 8 calls
  // A panic does not wait: two frames far over the budget drop at once after a change.
  UEStyleController fast(p);
  double t = 0.5 * kT;
  const double up = fast.Update(0.5, {t, t, 0.5}, tg);
  ASSERT_GT(up, 0.5);
  t = 2.0 * kT;
  fast.Update(up, {t, t, up}, tg);
  EXPECT_LT(fast.Update(up, {t, t, up}, tg), up);
}

TEST(UEStyle, StableUnderTheSamplesLatency) {
  // With each time paired with its frame's scale, the x2 step settles at
  // latency 0..3 with a handful of changes.
  for (int latency = 0; latency <= 3; ++latency) {
    SimConfig c = ConfigFor(Scenario::Step2x, SimConfig{});
    c.plant.latencyFrames = latency;
    auto law = MakeController(ControlLaw::UEStyle, latency);
    const SimResult r = RunScenario(*law, c);
    EXPECT_GE(r.settleFrames, 0) << latency;
    EXPECT_LE(r.changes, 10) << latency;
  }
}

// Lag-1 autocorrelation of the relative noise of the measured times.
double NoiseAutocorrelation(double rho) {
  SimConfig c = ConfigFor(Scenario::Still, SimConfig{});
  c.plant.latencyFrames = 0;
  c.plant.noise = 0.002;
  c.plant.noiseCorrelation = rho;
  RobustController law;  // holds the scale under a still load, so model is constant
  const SimResult r = RunScenario(law, c, true);
  std::vector<double> e;
  for (const FrameRecord& f : r.trace)
    if (f.frame > 50) e.push_back(f.measuredGpu / f.modelGpu - 1.0);
  double mean = 0.0;
  for (double x : e) mean += x / e.size();
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    den += (e[i] - mean) * (e[i] - mean);
    if (i > 0) num += (e[i] - mean) * (e[i - 1] - mean);
  }
  return num / den;
}

TEST(Simulator, CorrelatedNoiseHasTheAskedCorrelation) {
  EXPECT_NEAR(NoiseAutocorrelation(0.0), 0.0, 0.1);
  EXPECT_NEAR(NoiseAutocorrelation(0.9), 0.9, 0.06);
}

TEST(Simulator, SyntheticSetCoversLatencyAndCorrelatedNoise) {
  const auto set = SyntheticSet(SimConfig{});
  ASSERT_EQ(set.size(), 8u);
  int correlated = 0;
  for (const SyntheticCase& c : set) correlated += c.base.plant.noiseCorrelation > 0.0;
  EXPECT_EQ(correlated, 4);
  EXPECT_EQ(set.back().base.plant.latencyFrames, 3);
}

// --------------------------------------------------------------- traces

Trace Parse(const std::string& text, bool* ok, std::string* error) {
  std::istringstream in(text);
  Trace t;
  *ok = ReadTrace(in, "t", &t, error);
  return t;
}

TEST(Traces, ReadsAndRejectsWithTheLine) {
  bool ok;
  std::string error;
  const Trace t = Parse("# held-out trace\nframe,scale,gpu_ms\n0,1.0,40\n1,0.5,10.5\n", &ok, &error);
  ASSERT_TRUE(ok) << error;
  EXPECT_TRUE(t.HeldOut());
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(t.rows[1].gpuSeconds, 0.0105);
  for (const char* bad : {"frame,scale,ms\n0,1,1\n1,1,1\n", "frame,scale,gpu_ms\n0,1,1\n1,1,x\n",
                          "frame,scale,gpu_ms\n0,1,1\n1,3,1\n", "frame,scale,gpu_ms\n0,1,1\n1,1,-2\n",
                          "frame,scale,gpu_ms\n5,1,1\n5,1,1\n", "frame,scale,gpu_ms\n0,1,1\n",
                          "frame,scale,gpu_ms\n0,1,1\n1,1,nan\n"}) {
    Parse(bad, &ok, &error);
    EXPECT_FALSE(ok) << bad;
    EXPECT_NE(error.find("t:"), std::string::npos) << error;
  }
}

TEST(Traces, CostCurveInterpolatesInPixelsAndInverts) {
  bool ok;
  std::string error;
  // Medians 40 ms at scale 1 and 10 ms at 0.5 (one noisy 99 ms sample).
  const Trace sweep = Parse("frame,scale,gpu_ms\n0,1,40\n1,1,41\n2,1,39\n3,0.5,10\n4,0.5,99\n5,0.5,10\n", &ok, &error);
  ASSERT_TRUE(ok) << error;
  CostCurve cost;
  ASSERT_TRUE(cost.FromSweep(sweep, &error)) << error;
  EXPECT_NEAR(cost.Seconds(1.0), 0.040, 1e-12);
  EXPECT_NEAR(cost.Seconds(0.5), 0.010, 1e-12);
  EXPECT_NEAR(cost.Seconds(0.7), 0.010 + 0.030 * (0.49 - 0.25) / 0.75, 1e-12);  // linear in s^2
  EXPECT_NEAR(cost.Seconds(0.25), 0.010 / 4.0, 1e-12);                           // proportional below
  EXPECT_NEAR(cost.ScaleFor(cost.Seconds(0.7), 0.3, 1.0), 0.7, 1e-9);
  EXPECT_DOUBLE_EQ(cost.ScaleFor(1.0, 0.3, 1.0), 1.0);
}

TEST(Traces, ReplayOfAConstantTraceGivesUpAgainstItsBudgetScale) {
  bool ok;
  std::string error;
  const Trace sweep = Parse("frame,scale,gpu_ms\n0,1,40\n1,0.5,10\n", &ok, &error);
  CostCurve cost;
  ASSERT_TRUE(ok && cost.FromSweep(sweep, &error)) << error;
  std::string rows = "# held-out\nframe,scale,gpu_ms\n";
  for (int i = 0; i < 400; ++i) rows += std::to_string(i) + ",1,40\n";  // load 1 at scale 1
  const Trace trace = Parse(rows, &ok, &error);
  ASSERT_TRUE(ok) << error;
  ReplaySpec spec;
  spec.headroom = 0.0;
  EXPECT_NEAR(ReplayBudget(trace, cost, spec), cost.Seconds(0.7), 1e-12);
  for (const SimResult& r : ReplayTrace(AllLaws(), trace, cost, spec)) {
    // The budget scale is 0.7 at every frame: given up = 1 - mean scale / 0.7,
    // near 0 once settled (aim = budget here), and the final scale near 0.7.
    EXPECT_NEAR(r.finalScale, 0.7, 0.03) << r.controller;
    EXPECT_NEAR(r.givenUpPct, 0.0, 5.0) << r.controller;
  }
}

TEST(Traces, CommittedTracesAreHeldOutAndLoad) {
  std::vector<TraceCase> cases;
  std::string error;
  ASSERT_TRUE(LoadTraceDir(DRR_CONTROLLER_TRACE_DIR, &cases, &error)) << error;
  EXPECT_GE(cases.size(), 4u);
  for (const TraceCase& c : cases) {
    EXPECT_TRUE(c.trace.HeldOut()) << c.trace.name;
    EXPECT_GE(c.trace.rows.size(), 300u) << c.trace.name;
    for (std::size_t i = 1; i < c.cost.Points().size(); ++i)
      EXPECT_GE(c.cost.Points()[i].second, c.cost.Points()[i - 1].second) << c.trace.name;
    // Every law replays it and stays in range.
    for (const SimResult& r : ReplayTrace(AllLaws(), c.trace, c.cost, ReplaySpec{})) {
      EXPECT_GE(r.finalScale, 0.3) << r.controller;
      EXPECT_LE(r.finalScale, 1.0) << r.controller;
      EXPECT_TRUE(std::isfinite(r.givenUpPct)) << r.controller;
    }
  }
}

}  // namespace
