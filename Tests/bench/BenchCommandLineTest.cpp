// The --bench command line: defaults of the full and quick presets, and bad
// values rejected with their allowed range (exit code 2).
#include <gtest/gtest.h>

#include <algorithm>

#include "bench/Bench.h"

namespace {
using drr::BenchPlan;

int Parse(std::vector<std::string> args, BenchPlan* plan, std::string* message) {
  args.insert(args.begin(), "--bench");
  return drr::ParseBenchCommandLine(args, plan, message);
}
}  // namespace

TEST(BenchCommandLine, FullAndQuickDefaults) {
  BenchPlan full, quick;
  std::string m;
  ASSERT_EQ(Parse({}, &full, &m), 0) << m;
  EXPECT_EQ(full.warmupFrames, 8);
  EXPECT_EQ(full.warmupMs, 500);  // GPU clocks need time, not frames, to come back
  EXPECT_EQ(full.measuredFrames, 24);
  ASSERT_EQ(Parse({"--quick"}, &quick, &m), 0) << m;
  EXPECT_EQ(quick.warmupFrames, 4);
  EXPECT_EQ(quick.warmupMs, 0);
  EXPECT_EQ(quick.base.width, 320u);
  EXPECT_EQ(quick.base.height, 180u);
}

TEST(BenchCommandLine, WarmUpValues) {
  BenchPlan plan;
  std::string m;
  ASSERT_EQ(Parse({"--bench-warmup", "0", "--bench-warmup-ms", "0", "--bench-frames", "3"}, &plan, &m), 0) << m;
  EXPECT_EQ(plan.warmupFrames, 0);
  EXPECT_EQ(plan.warmupMs, 0);
  EXPECT_EQ(plan.measuredFrames, 3);
  ASSERT_EQ(Parse({"--quick", "--bench-warmup-ms", "250"}, &plan, &m), 0) << m;
  EXPECT_EQ(plan.warmupMs, 250);
}

TEST(BenchCommandLine, BadValuesNameTheirRange) {
  struct Case {
    std::vector<std::string> args;
    const char* range;
  } cases[] = {
      {{"--bench-warmup-ms", "-1"}, "[0, 60000]"},
      {{"--bench-warmup-ms", "60001"}, "[0, 60000]"},
      {{"--bench-warmup-ms", "fast"}, "[0, 60000]"},
      {{"--bench-warmup-ms"}, "missing value"},
      {{"--bench-warmup", "-2"}, "[0, 10000]"},
      {{"--bench-frames", "0"}, "[1, 10000]"},
      {{"--ghost-frames", "1"}, "[2, 300]"},
  };
  for (const Case& c : cases) {
    BenchPlan plan;
    std::string m;
    EXPECT_EQ(Parse(c.args, &plan, &m), 2) << c.args[0];
    EXPECT_NE(m.find(c.range), std::string::npos) << c.args[0] << ": " << m;
  }
}

TEST(BenchCommandLine, MovingSequencesAndInterleavedTiming) {
  BenchPlan full, quick, narrow;
  std::string m;
  ASSERT_EQ(Parse({}, &full, &m), 0) << m;
  EXPECT_TRUE(full.moving);
  EXPECT_EQ(full.movingSpeeds, (std::vector<double>{0.5, 1.0, 2.0}));
  EXPECT_EQ(full.movingFrames, 60);
  EXPECT_EQ(full.movingWarmup, 8);
  EXPECT_EQ(full.movingFilters.size(), full.filters.size());
  for (float s : full.movingScales) EXPECT_LE(s, 1.0f);  // sequences never allow 2x targets
  EXPECT_EQ(full.timingRounds, 4);
  EXPECT_FALSE(full.sweepMotionBlur);
  ASSERT_EQ(Parse({"--quick"}, &quick, &m), 0) << m;
  EXPECT_EQ(quick.movingSpeeds, (std::vector<double>{1.0}));
  EXPECT_EQ(quick.movingFrames, 4);
  EXPECT_EQ(quick.timingRounds, 1);
  ASSERT_EQ(Parse({"--moving-speed", "200", "--moving-frames", "90", "--scale", "0.5", "--no-ablations",
                   "--timing-rounds", "0", "--sweep-motion-blur"}, &narrow, &m), 0) << m;
  EXPECT_EQ(narrow.movingSpeeds, (std::vector<double>{2.0}));
  EXPECT_EQ(narrow.movingFrames, 90);
  EXPECT_EQ(narrow.movingScales, (std::vector<float>{0.5f}));
  EXPECT_FALSE(narrow.ablations);
  EXPECT_EQ(narrow.timingRounds, 0);
  EXPECT_TRUE(narrow.sweepMotionBlur);
}

TEST(BenchCommandLine, BadMovingValuesNameTheirRange) {
  const std::vector<std::pair<std::vector<std::string>, const char*>> cases = {
      {{"--moving-frames", "1"}, "[2, 10000]"},
      {{"--moving-speed", "0"}, "[1, 1000]"},
      {{"--moving-warmup", "-1"}, "[0, 10000]"},
      {{"--timing-rounds", "x"}, "[0, 1000]"},
      {{"--report-from"}, "missing value"},
  };
  for (const auto& [args, range] : cases) {
    BenchPlan plan;
    std::string m;
    EXPECT_EQ(Parse(args, &plan, &m), 2) << args[0];
    EXPECT_NE(m.find(range), std::string::npos) << args[0] << ": " << m;
  }
}

// The renderer is the sample's option: the bench renders every row (and the
// reference) with it, and a bad name is the sample's error.
TEST(BenchCommandLine, RendererChoice) {
  BenchPlan plan;
  std::string m;
  ASSERT_EQ(Parse({"--quick"}, &plan, &m), 0) << m;
  EXPECT_EQ(plan.base.renderer, drr::Renderer::Forward);
  ASSERT_EQ(Parse({"--quick", "--renderer", "deferred", "--no-ssao"}, &plan, &m), 0) << m;
  EXPECT_EQ(plan.base.renderer, drr::Renderer::Deferred);
  EXPECT_FALSE(plan.base.ssao);
  EXPECT_EQ(Parse({"--renderer", "tiled"}, &plan, &m), 2);
  EXPECT_EQ(m, "option --renderer: unknown renderer 'tiled' (allowed: forward, deferred)");
}

// --filters and --scales set the still and the moving sweep (moving: only
// the scales at or below 1.0); the quick preset carries TAAU on both; a bad
// item is named with what was expected.
TEST(BenchCommandLine, FilterAndScaleLists) {
  BenchPlan plan;
  std::string m;
  ASSERT_EQ(Parse({"--filters", "point,taau,upscale-lanczos3", "--scales", "0.5,0.71,1.5"}, &plan, &m), 0) << m;
  const std::vector<drr::Filter> filters = {drr::Filter::Point, drr::Filter::TAAU, drr::Filter::UpscaleLanczos3};
  EXPECT_EQ(plan.filters, filters);
  EXPECT_EQ(plan.movingFilters, filters);
  EXPECT_EQ(plan.scales, (std::vector<float>{0.5f, 0.71f, 1.5f}));
  EXPECT_EQ(plan.movingScales, (std::vector<float>{0.5f, 0.71f}));
  BenchPlan quick;
  ASSERT_EQ(Parse({"--quick"}, &quick, &m), 0) << m;
  for (const auto* list : {&quick.filters, &quick.movingFilters})
    EXPECT_NE(std::find(list->begin(), list->end(), drr::Filter::TAAU), list->end());
  struct Case {
    std::vector<std::string> args;
    const char* expected;
  } cases[] = {
      {{"--filters", "point,bogus"}, "'bogus' in 'point,bogus' is not a --filter name"},
      {{"--filters", "point,"}, "'' in 'point,' is not a --filter name"},
      {{"--scales", "0.5,3"}, "'3' in '0.5,3' is not a scale from 0.1 to 2"},
      {{"--scales"}, "missing value"},
  };
  for (const Case& c : cases) {
    BenchPlan bad;
    EXPECT_EQ(Parse(c.args, &bad, &m), 2) << c.args[0];
    EXPECT_NE(m.find(c.expected), std::string::npos) << m;
  }
}

TEST(BenchCommandLine, FlipPpdFromTheDisplayOrGiven) {
  BenchPlan plan;
  std::string m;
  ASSERT_EQ(Parse({"--quick"}, &plan, &m), 0) << m;
  // 320 pixels full-screen on FLIP's 0.7 m, 3840-pixel display at 0.7 m: 320 pi / 180.
  EXPECT_NEAR(drr::FlipPpd(plan), 5.585, 0.001);
  BenchPlan given;
  ASSERT_EQ(Parse({"--flip-ppd", "33.5"}, &given, &m), 0) << m;
  EXPECT_DOUBLE_EQ(drr::FlipPpd(given), 33.5);
  for (const char* bad : {"0", "-3", "abc", "1001"}) {
    BenchPlan p;
    EXPECT_EQ(Parse({"--flip-ppd", bad}, &p, &m), 2) << bad;
    EXPECT_NE(m.find("1 to 1000"), std::string::npos) << m;
  }
}

TEST(BenchCommandLine, TimingWarmUpByTime) {
  BenchPlan full, quick, given;
  std::string m;
  ASSERT_EQ(Parse({}, &full, &m), 0) << m;
  EXPECT_EQ(full.timingWarmupMs, 200);
  ASSERT_EQ(Parse({"--quick"}, &quick, &m), 0) << m;
  EXPECT_EQ(quick.timingWarmupMs, 0);
  ASSERT_EQ(Parse({"--quick", "--timing-warmup-ms", "50"}, &given, &m), 0) << m;
  EXPECT_EQ(given.timingWarmupMs, 50);
}
