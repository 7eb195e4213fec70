// The motion-compensated temporal instability: a renderer whose image moves
// exactly with the camera scores 0 whatever its error (perfect, or blurred),
// while the unreprojected frame-to-frame error change does not; a jittering
// renderer scores above 0 on a still and on a moving camera.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "analysis/ImageMetrics.h"
#include "analysis/TemporalStability.h"

namespace {

using drr::ImageF;
using drr::MotionField;

// A scene with detail at several frequencies, per channel, at any point.
float Scene(double x, double y, int c) {
  return float(0.5 + 0.25 * std::sin(0.9 * x + c) * std::cos(0.55 * y) + 0.2 * std::sin(0.13 * (x + 2 * y) + c));
}

// A w x h frame whose pixel (x, y) shows `pixel(x, y, c)`.
ImageF Frame(uint32_t w, uint32_t h, const std::function<float(double, double, int)>& pixel) {
  ImageF img{w, h, 4, std::vector<float>(size_t(w) * h * 4, 1.0f)};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.pixels[(size_t(y) * w + x) * 4 + c] = pixel(x, y, c);
  return img;
}

// The camera pans by (mx, my) pixels a frame: frame k shows the scene at p + k m,
// so the content at p was at p + m in frame k - 1 (screen motion -m).
ImageF Panned(uint32_t w, uint32_t h, int k, double mx, double my, double jitter = 0, double blur = 0) {
  return Frame(w, h, [=](double x, double y, int c) {
    const double sx = x + k * mx + jitter, sy = y + k * my;
    if (blur == 0) return Scene(sx, sy, c);
    float sum = 0;  // a 3x3 box at `blur` pixel spacing
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) sum += Scene(sx + i * blur, sy + j * blur, c);
    return sum / 9.0f;
  });
}

MotionField Constant(uint32_t w, uint32_t h, float dx, float dy) {
  return MotionField{w, h, std::vector<float>(size_t(w) * h, dx), std::vector<float>(size_t(w) * h, dy)};
}

constexpr uint32_t kW = 64, kH = 40;

TEST(TemporalStability, PerfectRendererOnAMovingCameraScoresZero) {
  const MotionField motion = Constant(kW, kH, -1.5f, -0.75f);
  for (int k = 1; k < 4; ++k) {
    const ImageF prev = Panned(kW, kH, k - 1, 1.5, 0.75), cur = Panned(kW, kH, k, 1.5, 0.75);
    EXPECT_EQ(drr::ReprojectedInstability(prev, cur, prev, cur, motion), 0.0) << k;
  }
}

TEST(TemporalStability, StableBlurScoresZeroWhereTheUncompensatedChangeDoesNot) {
  // Whole-pixel motion: the reprojection is exact, so the blurred renderer's
  // error moves with the scene and its instability is 0 (to float rounding).
  const MotionField motion = Constant(kW, kH, -2.0f, -1.0f);
  const ImageF refPrev = Panned(kW, kH, 0, 2, 1), ref = Panned(kW, kH, 1, 2, 1);
  const ImageF testPrev = Panned(kW, kH, 0, 2, 1, 0, 1.0), test = Panned(kW, kH, 1, 2, 1, 0, 1.0);
  EXPECT_LT(drr::ReprojectedInstability(testPrev, test, refPrev, ref, motion), 1e-6);
  // The former flicker measure (error change without motion compensation)
  // reports the moving blur error as instability.
  EXPECT_GT(drr::TemporalErrorRms(testPrev, test, refPrev, ref), 0.01);
}

TEST(TemporalStability, JitterOnAStillCameraScoresAboveZero) {
  const ImageF ref = Panned(kW, kH, 0, 0, 0);
  const ImageF a = Panned(kW, kH, 0, 0, 0, -0.25), b = Panned(kW, kH, 0, 0, 0, 0.25);
  const double jitter = drr::ReprojectedInstability(a, b, ref, ref, MotionField{});
  EXPECT_GT(jitter, 0.01);
  // A still, unjittered but wrong image is stable.
  const ImageF wrong = Panned(kW, kH, 0, 0, 0, 0.25);
  EXPECT_EQ(drr::ReprojectedInstability(wrong, wrong, ref, ref, MotionField{}), 0.0);
  // Half the jitter amplitude, less instability.
  const ImageF c = Panned(kW, kH, 0, 0, 0, -0.125), d = Panned(kW, kH, 0, 0, 0, 0.125);
  EXPECT_LT(drr::ReprojectedInstability(c, d, ref, ref, MotionField{}), jitter);
}

TEST(TemporalStability, JitterOnAMovingCameraScoresAboveZero) {
  const MotionField motion = Constant(kW, kH, -2.0f, -1.0f);
  const ImageF refPrev = Panned(kW, kH, 0, 2, 1), ref = Panned(kW, kH, 1, 2, 1);
  const ImageF testPrev = Panned(kW, kH, 0, 2, 1, -0.25), test = Panned(kW, kH, 1, 2, 1, 0.25);
  EXPECT_GT(drr::ReprojectedInstability(testPrev, test, refPrev, ref, motion), 0.01);
}

TEST(TemporalStability, MotionFromUvVelocityScalesByTheImageSize) {
  const MotionField m = drr::MotionFromUvVelocity({0.25f, -0.5f, 0.0f, 0.125f}, 2, 1);
  ASSERT_EQ(m.width, 2u);
  EXPECT_FLOAT_EQ(m.dx[0], 0.5f);
  EXPECT_FLOAT_EQ(m.dy[0], -0.5f);
  EXPECT_FLOAT_EQ(m.dy[1], 0.125f);
  EXPECT_TRUE(drr::MotionFromUvVelocity({0.0f}, 2, 1).Empty());
}

TEST(TemporalStability, PixelsMovedInFromOutsideAreLeftOut) {
  // Content moving 3 pixels right: the first 3 columns come from outside.
  const ImageF prev = Panned(8, 4, 0, -3, 0), cur = Panned(8, 4, 1, -3, 0);
  std::vector<uint8_t> valid;
  drr::Reproject(prev, Constant(8, 4, 3.0f, 0.0f), &valid);
  for (uint32_t x = 0; x < 8; ++x) EXPECT_EQ(valid[x], x >= 3 ? 1 : 0) << x;
}

TEST(TemporalStability, BadInputIsNaN) {
  const ImageF a = Panned(8, 4, 0, 0, 0), b = Panned(9, 4, 0, 0, 0);
  EXPECT_TRUE(std::isnan(drr::ReprojectedInstability(a, b, a, a, MotionField{})));
  EXPECT_TRUE(std::isnan(drr::ReprojectedInstability(a, a, a, a, Constant(4, 4, 0, 0))));
  ImageF bad = a;
  bad.pixels[0] = NAN;
  EXPECT_TRUE(std::isnan(drr::ReprojectedInstability(bad, a, a, a, MotionField{})));
  EXPECT_TRUE(std::isnan(drr::ReprojectedInstability(a, a, a, a, Constant(8, 4, 100, 0))));
}

}  // namespace
