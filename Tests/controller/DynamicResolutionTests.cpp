// DynamicResolution: the original's results on valid inputs (expected values
// computed by hand from the formulas of the original's DynamicResolution.cpp),
// and the fixed defects (D1..D8 in DynamicResolution.h) on extreme inputs.
#include "DynamicResolution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

struct ValidCase {
  const char* name;
  unsigned bbW, bbH, maxW, maxH;
  float maxScaling;
  float scale;  // applied with SetScale(scale, scale) after initialisation
  // expected
  unsigned dynW, dynH;
  float maxScalingX, maxScalingY;
  unsigned vpW, vpH;
  float scaleX, scaleY;      // recomputed from the integral viewport
  float rtScaleX, rtScaleY;  // scale / maxScaling
};

// k = maxW / bbW (integer); dyn = min(k, maxScaling) * bb if k > 1 else bb;
// vp = floor(dyn * s / maxScaling); s' = vp * maxScaling / dyn; rt = s' / maxScaling.
const ValidCase kValid[] = {
    // 8192/1280 = 6, 8192/720 = 11 -> min(.,1) = 1: dyn = bb.
    {"720p_x1_s1", 1280, 720, 8192, 8192, 1.0f, 1.0f, 1280, 720, 1.0f, 1.0f, 1280, 720, 1.0f, 1.0f, 1.0f, 1.0f},
    // floor(1280 * 0.71) = floor(908.8) = 908, floor(720 * 0.71) = floor(511.2) = 511.
    {"720p_x1_s071", 1280, 720, 8192, 8192, 1.0f, 0.71f, 1280, 720, 1.0f, 1.0f, 908, 511, 908.0f / 1280.0f,
     511.0f / 720.0f, 908.0f / 1280.0f, 511.0f / 720.0f},
    {"720p_x1_s05", 1280, 720, 8192, 8192, 1.0f, 0.5f, 1280, 720, 1.0f, 1.0f, 640, 360, 0.5f, 0.5f, 0.5f, 0.5f},
    // above the maximum: clamped to 1.
    {"720p_x1_s15", 1280, 720, 8192, 8192, 1.0f, 1.5f, 1280, 720, 1.0f, 1.0f, 1280, 720, 1.0f, 1.0f, 1.0f, 1.0f},
    // super sampling: dyn = 2 * bb; vp = floor(2560 * s / 2).
    {"720p_x2_s1", 1280, 720, 8192, 8192, 2.0f, 1.0f, 2560, 1440, 2.0f, 2.0f, 1280, 720, 1.0f, 1.0f, 0.5f, 0.5f},
    {"720p_x2_s2", 1280, 720, 8192, 8192, 2.0f, 2.0f, 2560, 1440, 2.0f, 2.0f, 2560, 1440, 2.0f, 2.0f, 1.0f, 1.0f},
    // floor(2560 * 0.71 / 2) = floor(908.8) = 908 -> s = 908 * 2 / 2560.
    {"720p_x2_s071", 1280, 720, 8192, 8192, 2.0f, 0.71f, 2560, 1440, 2.0f, 2.0f, 908, 511, 908.0f * 2.0f / 2560.0f,
     511.0f * 2.0f / 1440.0f, 908.0f / 2560.0f, 511.0f / 1440.0f},
    // 8192/1920 = 4, 8192/1080 = 7.
    {"1080p_x1_s075", 1920, 1080, 8192, 8192, 1.0f, 0.75f, 1920, 1080, 1.0f, 1.0f, 1440, 810, 0.75f, 0.75f, 0.75f,
     0.75f},
    {"1080p_x2_s075", 1920, 1080, 8192, 8192, 2.0f, 0.75f, 3840, 2160, 2.0f, 2.0f, 1440, 810, 0.75f, 0.75f, 0.375f,
     0.375f},
    // 7x3: floor(7 * 0.5) = 3 -> 3/7; floor(3 * 0.5) = 1 -> 1/3.
    {"7x3_x1_s05", 7, 3, 8192, 8192, 1.0f, 0.5f, 7, 3, 1.0f, 1.0f, 3, 1, 3.0f / 7.0f, 1.0f / 3.0f, 3.0f / 7.0f,
     1.0f / 3.0f},
    // dyn 14x6; floor(14 * 0.5 / 2) = 3 -> 3 * 2 / 14; floor(6 * 0.5 / 2) = 1 -> 1 * 2 / 6.
    {"7x3_x2_s05", 7, 3, 8192, 8192, 2.0f, 0.5f, 14, 6, 2.0f, 2.0f, 3, 1, 3.0f * 2.0f / 14.0f, 1.0f * 2.0f / 6.0f,
     3.0f / 14.0f, 1.0f / 6.0f},
    {"7x3_x2_s2", 7, 3, 8192, 8192, 2.0f, 2.0f, 14, 6, 2.0f, 2.0f, 14, 6, 2.0f, 2.0f, 1.0f, 1.0f},
    {"1x1_x1_s1", 1, 1, 8192, 8192, 1.0f, 1.0f, 1, 1, 1.0f, 1.0f, 1, 1, 1.0f, 1.0f, 1.0f, 1.0f},
    {"1x1_x2_s2", 1, 1, 8192, 8192, 2.0f, 2.0f, 2, 2, 2.0f, 2.0f, 2, 2, 2.0f, 2.0f, 1.0f, 1.0f},
    {"1x1_x2_s1", 1, 1, 8192, 8192, 2.0f, 1.0f, 2, 2, 2.0f, 2.0f, 1, 1, 1.0f, 1.0f, 0.5f, 0.5f},
    // max RT between 1x and 2x the back buffer: k = 1, no super sampling possible.
    {"maxRT_1.5x", 1280, 720, 2000, 1000, 2.0f, 1.0f, 1280, 720, 1.0f, 1.0f, 1280, 720, 1.0f, 1.0f, 1.0f, 1.0f},
    // per axis: 8192/5000 = 1 -> X without super sampling; 8192/720 = 11 -> Y doubled.
    {"wide_5000", 5000, 720, 8192, 8192, 2.0f, 1.0f, 5000, 1440, 1.0f, 2.0f, 5000, 720, 1.0f, 1.0f, 1.0f, 0.5f},
};

class ValidTable : public ::testing::TestWithParam<ValidCase> {};

TEST_P(ValidTable, MatchesTheOriginal) {
  const ValidCase& c = GetParam();
  DynamicResolution dr;
  const ScaleStatus init = dr.InitializeResolutionParameters(c.bbW, c.bbH, c.maxW, c.maxH, c.maxScaling);
  EXPECT_FALSE(Has(init, ScaleStatus::InvalidBackBuffer));
  EXPECT_TRUE(dr.IsValid());
  dr.SetScale(c.scale, c.scale);
  EXPECT_EQ(dr.GetDynamicBufferWidth(), c.dynW);
  EXPECT_EQ(dr.GetDynamicBufferHeight(), c.dynH);
  EXPECT_FLOAT_EQ(dr.GetMaxScalingX(), c.maxScalingX);
  EXPECT_FLOAT_EQ(dr.GetMaxScalingY(), c.maxScalingY);
  EXPECT_EQ(dr.GetViewportWidth(), c.vpW);
  EXPECT_EQ(dr.GetViewportHeight(), c.vpH);
  EXPECT_FLOAT_EQ(dr.GetScaleX(), c.scaleX);
  EXPECT_FLOAT_EQ(dr.GetScaleY(), c.scaleY);
  EXPECT_FLOAT_EQ(dr.GetRTScaleX(), c.rtScaleX);
  EXPECT_FLOAT_EQ(dr.GetRTScaleY(), c.rtScaleY);
  const DynamicViewport vp = dr.GetViewport();
  EXPECT_EQ(vp.TopLeftX, 0.0f);
  EXPECT_EQ(vp.TopLeftY, 0.0f);
  EXPECT_EQ(vp.Width, static_cast<float>(c.vpW));
  EXPECT_EQ(vp.Height, static_cast<float>(c.vpH));
  EXPECT_EQ(vp.MinDepth, 0.0f);
  EXPECT_EQ(vp.MaxDepth, 1.0f);
  DynamicViewport out;
  dr.GetViewport(&out);
  EXPECT_EQ(out.Width, vp.Width);
  EXPECT_EQ(out.Height, vp.Height);
}

INSTANTIATE_TEST_SUITE_P(Original, ValidTable, ::testing::ValuesIn(kValid),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

TEST(DynamicResolution, ScalesStartAtOne) {  // D1
  DynamicResolution dr;
  EXPECT_EQ(dr.GetScaleX(), 1.0f);
  EXPECT_EQ(dr.GetScaleY(), 1.0f);
  EXPECT_FALSE(dr.IsValid());  // nothing initialised yet: the defined 1x1 state
  EXPECT_EQ(dr.GetViewport().Width, 1.0f);
  dr.InitializeResolutionParameters(1280, 720, 8192, 8192, 1.0f);
  EXPECT_EQ(dr.GetViewportWidth(), 1280u);
  EXPECT_EQ(dr.GetViewportHeight(), 720u);
}

TEST(DynamicResolution, ReinitialisationReappliesTheScale) {  // as the original
  DynamicResolution dr;
  dr.InitializeResolutionParameters(1280, 720, 8192, 8192, 1.0f);
  dr.SetScale(0.5f, 0.5f);
  dr.InitializeResolutionParameters(1920, 1080, 8192, 8192, 2.0f);
  EXPECT_EQ(dr.GetDynamicBufferWidth(), 3840u);
  EXPECT_EQ(dr.GetViewportWidth(), 960u);  // floor(3840 * 0.5 / 2)
  EXPECT_EQ(dr.GetViewportHeight(), 540u);
  EXPECT_FLOAT_EQ(dr.GetRTScaleX(), 0.25f);
}

TEST(DynamicResolution, ClampedHighIsReported) {
  DynamicResolution dr;
  dr.InitializeResolutionParameters(1280, 720, 8192, 8192, 1.0f);
  EXPECT_TRUE(Has(dr.SetScale(1.5f, 1.0f), ScaleStatus::ClampedHigh));
  EXPECT_EQ(dr.SetScale(0.5f, 0.5f), ScaleStatus::Ok);
}

TEST(DynamicResolution, LowerBoundIsOnePixel) {  // D2
  DynamicResolution dr;
  dr.InitializeResolutionParameters(1280, 720, 8192, 8192, 1.0f);
  for (float s : {0.0f, -1.0f, 1e-7f, 1.0f / 1280.0f * 0.5f, -1e30f}) {
    const ScaleStatus st = dr.SetScale(s, s);
    EXPECT_TRUE(Has(st, ScaleStatus::ClampedLow)) << s;
    EXPECT_EQ(dr.GetViewportWidth(), 1u) << s;
    EXPECT_EQ(dr.GetViewportHeight(), 1u) << s;
    EXPECT_FLOAT_EQ(dr.GetScaleX(), 1.0f / 1280.0f);
    EXPECT_FLOAT_EQ(dr.GetScaleY(), 1.0f / 720.0f);
  }
}

TEST(DynamicResolution, NonFiniteIsRejectedPerAxisAndLogged) {  // D3
  DynamicResolution dr;
  std::vector<std::string> log;
  dr.SetLogHook([&](std::string_view m) { log.emplace_back(m); });
  dr.InitializeResolutionParameters(1280, 720, 8192, 8192, 1.0f);
  dr.SetScale(0.5f, 0.5f);
  const ScaleStatus st = dr.SetScale(kNaN, 0.75f);
  EXPECT_TRUE(Has(st, ScaleStatus::RejectedNonFinite));
  EXPECT_EQ(dr.GetViewportWidth(), 640u);   // kept
  EXPECT_EQ(dr.GetViewportHeight(), 540u);  // applied
  EXPECT_FALSE(log.empty());
  for (float bad : {kInf, -kInf, kNaN}) {
    EXPECT_TRUE(Has(dr.SetScale(bad, bad), ScaleStatus::RejectedNonFinite));
    EXPECT_EQ(dr.GetViewportWidth(), 640u);
    EXPECT_EQ(dr.GetViewportHeight(), 540u);
    EXPECT_EQ(dr.GetScaleX(), 0.5f);
    EXPECT_EQ(dr.GetScaleY(), 0.75f);
  }
}

TEST(DynamicResolution, BackBufferLargerThanMaxRT) {  // D4
  DynamicResolution dr;
  const ScaleStatus st = dr.InitializeResolutionParameters(16384, 1080, 8192, 8192, 2.0f);
  EXPECT_TRUE(Has(st, ScaleStatus::RenderTargetClamped));
  EXPECT_EQ(dr.GetDynamicBufferWidth(), 8192u);  // never above the max RT
  EXPECT_FLOAT_EQ(dr.GetMaxScalingX(), 0.5f);
  EXPECT_EQ(dr.GetDynamicBufferHeight(), 2160u);  // Y: 8192/1080 = 7 -> 2x
  EXPECT_LE(dr.GetScaleX(), 0.5f);                // scale <= max / bb
  EXPECT_EQ(dr.GetViewportWidth(), 8192u);
  EXPECT_FLOAT_EQ(dr.GetRTScaleX(), 1.0f);
  dr.SetScale(0.25f, 0.5f);
  EXPECT_EQ(dr.GetViewportWidth(), 4096u);  // floor(8192 * 0.25 / 0.5)
  EXPECT_FLOAT_EQ(dr.GetRTScaleX(), 0.5f);
}

TEST(DynamicResolution, ZeroBackBufferIsADefinedInvalidState) {  // D5
  DynamicResolution dr;
  dr.InitializeResolutionParameters(1280, 720, 8192, 8192, 1.0f);
  dr.SetScale(0.5f, 0.5f);
  for (auto [w, h] : {std::pair{0u, 720u}, std::pair{1280u, 0u}, std::pair{0u, 0u}}) {
    const ScaleStatus st = dr.InitializeResolutionParameters(w, h, 8192, 8192, 1.0f);
    EXPECT_TRUE(Has(st, ScaleStatus::InvalidBackBuffer));
    EXPECT_FALSE(dr.IsValid());
    EXPECT_EQ(dr.GetDynamicBufferWidth(), 1u);
    EXPECT_EQ(dr.GetDynamicBufferHeight(), 1u);
    EXPECT_EQ(dr.GetViewport().Width, 1.0f);
    EXPECT_EQ(dr.GetViewport().Height, 1.0f);
    EXPECT_EQ(dr.GetRTScaleX(), 1.0f);
    EXPECT_EQ(dr.GetScaleX(), 0.5f);  // remembered
  }
  EXPECT_TRUE(Has(dr.SetScale(0.25f, kNaN), ScaleStatus::InvalidBackBuffer));
  EXPECT_TRUE(Has(dr.SetScale(-3.0f, 0.25f), ScaleStatus::ClampedLow));
  dr.SetScale(0.25f, 0.25f);
  EXPECT_EQ(dr.GetViewport().Width, 1.0f);
  // Restored window: the remembered scale applies.
  dr.InitializeResolutionParameters(1280, 720, 8192, 8192, 1.0f);
  EXPECT_TRUE(dr.IsValid());
  EXPECT_EQ(dr.GetViewportWidth(), 320u);
  EXPECT_EQ(dr.GetViewportHeight(), 180u);
  // Zero-size max RT is invalid too.
  EXPECT_TRUE(Has(dr.InitializeResolutionParameters(1280, 720, 0, 8192, 1.0f), ScaleStatus::InvalidBackBuffer));
}

TEST(DynamicResolution, BadMaxScalingIsTreatedAsOne) {  // D6
  for (float m : {0.0f, 0.5f, -2.0f, kNaN, kInf}) {
    DynamicResolution dr;
    EXPECT_TRUE(Has(dr.InitializeResolutionParameters(1280, 720, 8192, 8192, m), ScaleStatus::BadMaxScaling)) << m;
    EXPECT_EQ(dr.GetDynamicBufferWidth(), 1280u);
    EXPECT_EQ(dr.GetMaxScalingX(), 1.0f);
  }
}

TEST(DynamicResolution, HugeScaleDoesNotOverflow) {  // D7
  DynamicResolution dr;
  dr.InitializeResolutionParameters(16384, 16384, 32768, 32768, 2.0f);
  EXPECT_TRUE(Has(dr.SetScale(1e9f, 3.4e38f), ScaleStatus::ClampedHigh));
  EXPECT_EQ(dr.GetViewportWidth(), 32768u);
  EXPECT_EQ(dr.GetViewportHeight(), 32768u);
  EXPECT_EQ(dr.GetRTScaleX(), 1.0f);
}

TEST(DynamicResolution, ResubmittingTheCurrentScaleKeepsTheViewport) {  // D8
  // dyn 22, w 13: in float floor(22 * (13 / 22)) is 12.
  DynamicResolution dr;
  dr.InitializeResolutionParameters(22, 22, 22, 22, 1.0f);
  dr.SetScale(13.5f / 22.0f, 13.5f / 22.0f);
  ASSERT_EQ(dr.GetViewportWidth(), 13u);
  for (int i = 0; i < 10; ++i) dr.SetScale(dr.GetScaleX(), dr.GetScaleY());
  EXPECT_EQ(dr.GetViewportWidth(), 13u);
  EXPECT_EQ(dr.GetViewportHeight(), 13u);
}

// Extreme table: never a zero/negative/non-finite viewport, never a ratio
// outside (0, 1], and re-submitting the scale is stable.
TEST(DynamicResolution, ExtremeTable) {
  const unsigned sizes[] = {1, 2, 3, 7, 22, 720, 1080, 1280, 4096, 8191, 16384};
  const unsigned maxRTs[] = {1, 5, 8192, 16384, 32768};
  const float maxScalings[] = {1.0f, 2.0f};
  std::vector<float> scales = {0.0f, 1e-7f, -1.0f, 1e9f, kNaN, kInf, -kInf, 0.3f, 0.5f, 0.71f, 1.0f, 2.0f,
                               std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max()};
  int checked = 0;
  for (unsigned w : sizes)
    for (unsigned h : {1u, 720u, 16384u})
      for (unsigned maxRT : maxRTs)
        for (float m : maxScalings) {
          DynamicResolution dr;
          dr.InitializeResolutionParameters(w, h, maxRT, maxRT, m);
          ASSERT_LE(dr.GetDynamicBufferWidth(), std::max(maxRT, 1u));
          ASSERT_LE(dr.GetDynamicBufferHeight(), std::max(maxRT, 1u));
          std::vector<float> all = scales;
          all.push_back(1.0f / static_cast<float>(w));
          all.push_back(1.0f / static_cast<float>(h));
          for (float sx : all)
            for (float sy : all) {
              dr.SetScale(sx, sy);
              const DynamicViewport vp = dr.GetViewport();
              ASSERT_TRUE(std::isfinite(vp.Width) && std::isfinite(vp.Height));
              ASSERT_GE(vp.Width, 1.0f);
              ASSERT_GE(vp.Height, 1.0f);
              ASSERT_LE(vp.Width, static_cast<float>(dr.GetDynamicBufferWidth()));
              ASSERT_LE(vp.Height, static_cast<float>(dr.GetDynamicBufferHeight()));
              const float rx = dr.GetRTScaleX(), ry = dr.GetRTScaleY();
              ASSERT_TRUE(rx > 0.0f && rx <= 1.0f) << w << "x" << h << " max " << maxRT << " s " << sx << " rx " << rx;
              ASSERT_TRUE(ry > 0.0f && ry <= 1.0f) << w << "x" << h << " max " << maxRT << " s " << sy << " ry " << ry;
              ASSERT_TRUE(std::isfinite(dr.GetScaleX()) && dr.GetScaleX() > 0.0f);
              ASSERT_TRUE(std::isfinite(dr.GetScaleY()) && dr.GetScaleY() > 0.0f);
              const unsigned vw = dr.GetViewportWidth(), vh = dr.GetViewportHeight();
              dr.SetScale(dr.GetScaleX(), dr.GetScaleY());
              ASSERT_EQ(dr.GetViewportWidth(), vw);
              ASSERT_EQ(dr.GetViewportHeight(), vh);
              ++checked;
            }
        }
  EXPECT_GT(checked, 10000);
}

}  // namespace
