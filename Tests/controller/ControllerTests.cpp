// Control laws: the article law's exact arithmetic, bounded outputs for any
// input, stiff gains, and the robust law's headline properties, driving the
// simulator's plant model (tools/ControllerSimCore.h) so tests and the simulator
// share one model.
#include "ControllerSimCore.h"
#include "ResolutionController.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace {

using namespace drr;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kT = 1.0 / 60.0;

ControlTarget Target() { return ControlTarget{kT, 0.1, 0.3, 1.0}; }

TEST(TargetFrameSeconds, VSyncAndHalf) {
  EXPECT_DOUBLE_EQ(TargetFrameSeconds(60.0, ControlMode::VSync), 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(TargetFrameSeconds(60.0, ControlMode::HalfVSync), 2.0 / 60.0);
  EXPECT_DOUBLE_EQ(TargetFrameSeconds(144.0, ControlMode::VSync), 1.0 / 144.0);
  EXPECT_DOUBLE_EQ(TargetFrameSeconds(0.0, ControlMode::VSync), 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(TargetFrameSeconds(kNaN, ControlMode::HalfVSync), 2.0 / 60.0);
  EXPECT_DOUBLE_EQ(TargetFrameSeconds(75.0, ControlMode::Manual), 1.0 / 75.0);
}

// The original's ControlResolution in float, written out for comparison.
float OriginalStep(float controlled, float gpu, float frame, float budget) {
  float t = (gpu + frame) / 2.0f;
  if (frame > 2.0f * gpu) t = gpu;
  const float next = (0.01f * (1.0f - t / budget) + 1.0f) * controlled;
  return std::clamp(next, 0.3f, 1.0f);
}

TEST(ArticleController, ExactLaw) {
  const ControlTarget tg = Target();
  const float T = static_cast<float>(kT);
  // frame <= 2 gpu: t = (gpu + frame) / 2.
  EXPECT_EQ(ArticleController::Step(0.8f, {0.015, 0.016}, tg, 0.01), OriginalStep(0.8f, 0.015f, 0.016f, T));
  EXPECT_NEAR(ArticleController::Step(0.8f, {0.015, 0.016}, tg, 0.01), 0.8 * (1.0 + 0.01 * (1.0 - 0.0155 / kT)), 1e-6);
  // frame > 2 gpu (CPU spike): t = gpu.
  EXPECT_DOUBLE_EQ(ArticleController::MeasuredSeconds({0.010, 0.030}), 0.010);
  EXPECT_EQ(ArticleController::Step(0.8f, {0.010, 0.030}, tg, 0.01), OriginalStep(0.8f, 0.010f, 0.030f, T));
  // exactly 2x: still the average (strict >).
  EXPECT_DOUBLE_EQ(ArticleController::MeasuredSeconds({0.010, 0.020}), 0.015);
  // no FPS figure yet (1 / 0 = +Inf): the original's comparison picks the GPU time.
  EXPECT_EQ(ArticleController::Step(0.8f, {0.010, kInf}, tg, 0.01), OriginalStep(0.8f, 0.010f, INFINITY, T));
  // VSync/2 target.
  ControlTarget half = tg;
  half.budgetSeconds = TargetFrameSeconds(60.0, ControlMode::HalfVSync);
  EXPECT_NEAR(ArticleController::Step(0.5f, {0.02, 0.03}, half, 0.01), 0.5 * (1.0 + 0.01 * (1.0 - 0.025 * 30.0)), 1e-6);
  // clamps [0.3, max]; a GPU time of 0 (the averaged timer before its first
  // block) raises the scale by 1 % a frame, up to the maximum.
  EXPECT_EQ(ArticleController::Step(0.3f, {1.0, 1.0}, tg, 0.01), 0.3f);
  EXPECT_EQ(ArticleController::Step(1.0f, {0.0, 0.001}, tg, 0.01), 1.0f);
  ControlTarget ss = tg;
  ss.maxScale = 2.0;
  EXPECT_EQ(ArticleController::Step(1.0f, {0.0, 0.001}, ss, 0.01), 1.01f);
  // the default object is the article's k = 0.01, starting at the original's 1.0
  ArticleController law;
  EXPECT_DOUBLE_EQ(law.Gain(), 0.01);
  EXPECT_EQ(law.ControlledScale(), 1.0f);
  EXPECT_EQ(law.Update(0.8, {0.015, 0.016}, tg), ArticleController::Step(1.0f, {0.015, 0.016}, tg, 0.01));
  EXPECT_DOUBLE_EQ(law.AimSeconds(tg), kT);
}

TEST(ArticleController, IntegratesItsOwnScaleNotTheAppliedOne) {
  // The original's g_ControlledScale: the applied (quantised) scale passed in
  // is not read, and Reset (resize, mode switch) keeps the integrator.
  const ControlTarget tg = Target();
  ArticleController a, b;
  float expected = 1.0f;
  for (int i = 0; i < 50; ++i) {
    const FrameTiming over{0.020, 0.020};
    expected = OriginalStep(expected, 0.020f, 0.020f, static_cast<float>(kT));
    EXPECT_EQ(a.Update(0.3 + 0.01 * i, over, tg), expected);
    EXPECT_EQ(b.Update(kNaN, over, tg), expected);
    if (i == 25) a.Reset();
  }
  // Steps far below one pixel still accumulate: 200 steps of +0.01 % each.
  ArticleController slow;
  for (int i = 0; i < 100; ++i) slow.Update(1.0, {0.030, 0.030}, tg);  // down to ~0.7
  const float before = slow.ControlledScale();
  for (int i = 0; i < 200; ++i) slow.Update(1.0, {kT * 0.99, kT * 0.99}, tg);
  EXPECT_NEAR(slow.ControlledScale() / before, std::pow(1.0 + 0.0001, 200), 1e-4);
}

TEST(BlockAverage, ZeroUntilTheFirstBlockThenTheBlockMean) {
  BlockAverage avg(10);
  for (int i = 1; i <= 9; ++i) {
    EXPECT_FALSE(avg.Add(i));
    EXPECT_EQ(avg.Value(), 0.0);  // the original feeds this 0 to the law
  }
  EXPECT_TRUE(avg.Add(10));
  EXPECT_DOUBLE_EQ(avg.Value(), 5.5);
  for (int i = 0; i < 9; ++i) EXPECT_FALSE(avg.Add(100.0));
  EXPECT_DOUBLE_EQ(avg.Value(), 5.5);  // held until the next block completes
  EXPECT_TRUE(avg.Add(100.0));
  EXPECT_DOUBLE_EQ(avg.Value(), 100.0);
}

TEST(DxutFpsCounter, OnceASecondFramesOverElapsed) {
  DxutFpsCounter fps;
  fps.Tick(100.0);  // first frame: no figure (DXUT's is ~0)
  EXPECT_EQ(fps.Fps(), 0.0);
  EXPECT_EQ(fps.FrameSeconds(), kInf);
  double now = 100.0;
  int frame = 0;
  for (; now - 100.0 <= 1.0; ++frame) {  // 20 ms frames
    now += 0.020;
    fps.Tick(now);
    if (now - 100.0 <= 1.0) {
      EXPECT_EQ(fps.Fps(), 0.0) << frame;
    }
  }
  // the tick that passed 1 s: every frame since the first over the elapsed time
  EXPECT_NEAR(fps.Fps(), frame / (now - 100.0), 1e-4);
  EXPECT_NEAR(fps.Fps(), 50.0, 1.0);
  const double first = fps.Fps();
  for (int i = 0; i < 10; ++i) fps.Tick(now += 0.040);  // slower frames: the figure waits
  EXPECT_EQ(fps.Fps(), first);
  for (int i = 0; i < 30; ++i) fps.Tick(now += 0.040);
  EXPECT_NEAR(fps.Fps(), 25.0, 0.01);
  EXPECT_NEAR(fps.FrameSeconds(), 0.040, 1e-5);
}

const double kTimes[] = {0.0, 1e-9, 1e-300, 0.001, kT, 100.0 * kT, 1e300, kNaN, kInf, -kInf, -1.0, -0.0};
const double kScales[] = {0.3, 0.7, 1.0, 0.0, -1.0, 1e-9, 5.0, kNaN, kInf, -kInf};

void ExpectBoundedForAnyInput(ResolutionController& c, const ControlTarget& tg) {
  for (double s : kScales)
    for (double gpu : kTimes)
      for (double frame : kTimes) {
        const double out = c.Update(s, {gpu, frame}, tg);
        ASSERT_TRUE(std::isfinite(out)) << c.Name() << " s " << s << " gpu " << gpu << " frame " << frame;
        ASSERT_GE(out, tg.minScale) << c.Name();
        ASSERT_LE(out, tg.maxScale) << c.Name();
      }
}

TEST(AllControllers, BoundedForAnyInput) {
  const double gains[] = {0.001, 0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 0.0, -5.0, 1e6, kNaN, kInf};
  for (double k : gains) {
    ArticleController law(k);
    ExpectBoundedForAnyInput(law, Target());
  }
  for (ControlLaw law : {ControlLaw::UEStyle, ControlLaw::Robust}) {
    auto c = MakeController(law);
    ExpectBoundedForAnyInput(*c, Target());
    ControlTarget ss{kT / 2, 0.2, 0.5, 2.0};
    ExpectBoundedForAnyInput(*c, ss);
  }
}

TEST(AllControllers, BadTargetIsSanitised) {
  const ControlTarget bad[] = {{kNaN, kNaN, kNaN, kNaN}, {-1.0, 2.0, 0.0, -1.0}, {kInf, -1.0, 0.9, 0.2}};
  for (const ControlTarget& tg : bad) {
    const ControlTarget s = SanitizeTarget(tg);
    EXPECT_TRUE(std::isfinite(s.budgetSeconds) && s.budgetSeconds > 0.0);
    EXPECT_TRUE(s.minScale > 0.0 && s.maxScale >= s.minScale);
    for (ControlLaw law : {ControlLaw::Article, ControlLaw::UEStyle, ControlLaw::Robust}) {
      auto c = MakeController(law);
      for (double gpu : kTimes) {
        const double out = c->Update(0.7, {gpu, kT}, tg);
        ASSERT_TRUE(std::isfinite(out));
        ASSERT_GE(out, s.minScale);
        ASSERT_LE(out, s.maxScale);
      }
    }
  }
}

// Closed loop on the simulator's plant, with the quantised viewport, checking
// every frame for range and finiteness.
std::vector<double> ClosedLoop(ResolutionController& c, sim::Scenario scenario, int frames = 900,
                               std::optional<Feed> feed = {}) {
  sim::SimConfig cfg = sim::ConfigFor(scenario, sim::SimConfig{});
  cfg.frames = frames;
  cfg.feed = feed;
  const sim::SimResult r = sim::RunScenario(c, cfg, true);
  std::vector<double> scales;
  for (const auto& f : r.trace) scales.push_back(f.scale);
  return scales;
}

TEST(ArticleController, StiffGainsStayBoundedByTheClamp) {
  for (double k : {0.5, 1.0, 2.0, 5.0, 10.0}) {
    ArticleController law(k);
    for (sim::Scenario s : sim::AllScenarios()) {
      for (double scale : ClosedLoop(law, s)) {
        ASSERT_TRUE(std::isfinite(scale)) << k;
        ASSERT_GE(scale, 0.3 - 1e-3) << k;  // quantised viewport of the clamp value
        ASSERT_LE(scale, 1.0) << k;
      }
    }
  }
}

TEST(ArticleController, GainBelowHalfConvergesAboveOneOverAlphaOscillates) {
  // alpha = (T - c) / T with the simulator's plant: linear analysis says
  // alternation above 1/(2 alpha), growth (held by the clamp) above 1/alpha.
  // The analysis assumes the time of the last frame (per-result feed); the
  // original's block average adds delay (see the sweep in Controller.md).
  const sim::SimConfig base;
  const double alpha = sim::ArticleAlpha(base.plant, base.target);
  ASSERT_NEAR(alpha, 1.0 - 0.002 * 60.0, 1e-12);
  for (double k : {0.2, 0.4}) {
    ArticleController law(k);
    const auto s = ClosedLoop(law, sim::Scenario::Step2x, 900, Feed::PerResult);
    double lo = 1, hi = 0;
    for (std::size_t i = s.size() - 100; i < s.size(); ++i) lo = std::min(lo, s[i]), hi = std::max(hi, s[i]);
    EXPECT_LT(hi - lo, 0.03) << k;
  }
  for (double k : {2.0 / alpha, 10.0}) {
    ArticleController law(k);
    const auto s = ClosedLoop(law, sim::Scenario::Step2x, 900, Feed::PerResult);
    double lo = 1, hi = 0;
    for (std::size_t i = s.size() - 100; i < s.size(); ++i) lo = std::min(lo, s[i]), hi = std::max(hi, s[i]);
    EXPECT_GT(hi - lo, 0.1) << k;  // sustained 2-cycle ...
    EXPECT_GE(lo, 0.3 - 1e-3);     // ... that the clamp holds
    EXPECT_LE(hi, 1.0);
  }
}

TEST(IsCpuBoundFrame, Cases) {
  const ControlTarget tg = Target();
  EXPECT_TRUE(IsCpuBoundFrame({0.010, 0.030}, tg));    // late frame, GPU fitted
  EXPECT_FALSE(IsCpuBoundFrame({0.020, 0.0333}, tg));  // GPU over budget: GPU-bound
  EXPECT_FALSE(IsCpuBoundFrame({0.010, kT}, tg));      // vsync-quantised, on time
  EXPECT_FALSE(IsCpuBoundFrame({kNaN, 0.030}, tg));
  EXPECT_FALSE(IsCpuBoundFrame({0.010, kNaN}, tg));
}

// Drive a controller with a fixed plant at a fixed load, with the same
// viewport quantisation as the simulator, and return the applied scales.
TEST(RobustController, ZeroChangesUnderASteadyLoad) {
  for (double noise : {0.0, 0.002, 0.01}) {
    RobustController c;
    sim::SimConfig cfg = sim::ConfigFor(sim::Scenario::Still, sim::SimConfig{});
    cfg.plant.noise = noise;
    const sim::SimResult r = sim::RunScenario(c, cfg, true);
    EXPECT_EQ(r.changes, 0) << noise;  // no change at all after the warm-up
    EXPECT_EQ(r.stillChanges, 0) << noise;
    EXPECT_EQ(r.settleFrames, 0) << noise;
  }
}

TEST(RobustController, HoldsExactlyWhenTheTimeIsOnTarget) {
  RobustController c;
  const ControlTarget tg = Target();
  double s = 0.7;
  for (int i = 0; i < 1000; ++i) {
    const double next = c.Update(s, {0.015 * (1.0 + 0.005 * ((i % 3) - 1)), 0.016}, tg);
    ASSERT_EQ(next, s) << i;
  }
}

TEST(RobustController, SettlesA2xStepWithin20Frames) {
  for (std::uint32_t seed : {1u, 2u, 3u, 20110228u}) {
    RobustController c;
    sim::SimConfig cfg = sim::ConfigFor(sim::Scenario::Step2x, sim::SimConfig{});
    cfg.seed = seed;
    const sim::SimResult r = sim::RunScenario(c, cfg);
    EXPECT_GE(r.settleFrames, 0) << seed;
    EXPECT_LE(r.settleFrames, 20) << seed;
    EXPECT_EQ(r.stillChanges, 0) << seed;
  }
}

TEST(RobustController, SettlesWithMeasurementLatencyWhenTold) {
  RobustController::Params p;
  p.latencyFrames = 2;
  RobustController c(p);
  sim::SimConfig cfg = sim::ConfigFor(sim::Scenario::Step2x, sim::SimConfig{});
  cfg.plant.latencyFrames = 2;
  const sim::SimResult r = sim::RunScenario(c, cfg);
  EXPECT_GE(r.settleFrames, 0);
  EXPECT_LE(r.settleFrames, 20);
}

TEST(RobustController, IgnoresIsolatedSpikesAndBadSamples) {
  RobustController c;
  const ControlTarget tg = Target();
  const double s = 0.7;
  for (int i = 0; i < 20; ++i) ASSERT_EQ(c.Update(s, {0.015, 0.016}, tg), s);
  for (double bad : {1.5, kNaN, kInf, -kInf, 0.0, -0.01, 1e-9}) {
    EXPECT_EQ(c.Update(s, {bad, 0.016}, tg), s) << bad;
    EXPECT_EQ(c.Update(s, {0.015, 0.016}, tg), s);
  }
}

TEST(RobustController, ReactsToPersistentOverload) {
  RobustController c;
  const ControlTarget tg = Target();
  double s = 0.7;
  for (int i = 0; i < 10; ++i) s = c.Update(s, {0.015, 0.016}, tg);
  // 100x for good: after outlierPersistFrames it is the new load; the scale
  // keeps dropping (halving per correction at most) down to the minimum.
  for (int i = 0; i < 60; ++i) s = c.Update(s, {1.5 * (s * s) / 0.49, 1.5}, tg);
  EXPECT_DOUBLE_EQ(s, tg.minScale);
}

TEST(RobustController, IgnoresCpuBoundFrames) {
  RobustController c;
  const ControlTarget tg = Target();
  const double s = 0.7;
  for (int i = 0; i < 200; ++i) ASSERT_EQ(c.Update(s, {0.012, 0.020 + 0.0001 * (i % 50)}, tg), s);
}

TEST(UEStyleController, PanicsAfterConsecutiveOverBudgetFrames) {
  UEStyleController c;
  const ControlTarget tg = Target();
  double s = 0.7;
  for (int i = 0; i < 20; ++i) s = c.Update(s, {0.015, 0.016}, tg);
  const double before = s;
  s = c.Update(s, {0.030, 0.030}, tg);
  s = c.Update(s, {0.030, 0.030}, tg);
  EXPECT_LT(s, before * 0.8);
}

TEST(Factory, Names) {
  ControlLaw law = ControlLaw::Count;
  EXPECT_TRUE(ParseControlLaw("article", &law));
  EXPECT_EQ(law, ControlLaw::Article);
  EXPECT_TRUE(ParseControlLaw("ue", &law));
  EXPECT_EQ(law, ControlLaw::UEStyle);
  EXPECT_TRUE(ParseControlLaw("ue-style", &law));
  EXPECT_EQ(law, ControlLaw::UEStyle);
  EXPECT_TRUE(ParseControlLaw("robust", &law));
  EXPECT_EQ(law, ControlLaw::Robust);
  EXPECT_FALSE(ParseControlLaw("pid", &law));
  EXPECT_FALSE(ParseControlLaw("", &law));
  EXPECT_EQ(law, ControlLaw::Robust);  // untouched by a failed parse
  // One name table: every law parses back from its option, and the controller
  // made for it reports that option as its name.
  for (int i = 0; i < static_cast<int>(ControlLaw::Count); ++i) {
    const auto l = static_cast<ControlLaw>(i);
    EXPECT_TRUE(ParseControlLaw(ControlLawOption(l), &law));
    EXPECT_EQ(law, l);
    EXPECT_EQ(MakeController(l)->Name(), ControlLawOption(l));
    EXPECT_EQ(MakeController(l, 3)->Name(), ControlLawOption(l));
  }
  EXPECT_STREQ(ControlLawName(ControlLaw::Article), "Article (original)");
  EXPECT_STREQ(ControlLawOption(ControlLaw::UEStyle), "ue-style");
  EXPECT_STREQ(ControlModeName(ControlMode::HalfVSync), "VSync/2");
  EXPECT_STREQ(ControlModeOption(ControlMode::HalfVSync), "half-vsync");
  EXPECT_STREQ(ControlModeOption(ControlMode::Manual), "manual");
  EXPECT_STREQ(ControlModeOption(ControlMode::VSync), "vsync");
}

// MakeController(Robust, n) is the law the sample and the simulator run with a
// measurement latency of n frames: it behaves as a RobustController whose
// Params say latencyFrames = n, not as the default one.
TEST(Factory, RobustLatency) {
  RobustController::Params p;
  p.latencyFrames = 2;
  RobustController expected(p);
  RobustController zero;
  auto made = MakeController(ControlLaw::Robust, 2);
  const ControlTarget tg = Target();
  double se = 0.7, sm = 0.7, sz = 0.7;
  bool differsFromZero = false;
  for (int i = 0; i < 60; ++i) {
    const FrameTiming t{i < 20 ? 0.015 : 0.030, 0.016};
    se = expected.Update(se, t, tg);
    sm = made->Update(sm, t, tg);
    sz = zero.Update(sz, t, tg);
    EXPECT_EQ(sm, se) << i;
    differsFromZero |= sm != sz;
  }
  EXPECT_TRUE(differsFromZero);
}

}  // namespace
