// FLIP against values that follow from the paper's description alone (CIE
// L*a*b* of the sRGB primaries, the Hunt adjustment, HyAB, the filter radii
// for a given ppd, the 0.7 exponent and the maximum-error normalisation), and
// the temporal error measure of ImageMetrics.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/Flip.h"

namespace {

drr::ImageF Uniform(uint32_t w, uint32_t h, float r, float g, float b) {
  drr::ImageF img{w, h, 4, std::vector<float>(size_t(w) * h * 4, 1.0f)};
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    img.pixels[i * 4 + 0] = r;
    img.pixels[i * 4 + 1] = g;
    img.pixels[i * 4 + 2] = b;
  }
  return img;
}

// Black left of column `edge`, white from it on.
drr::ImageF Step(uint32_t w, uint32_t h, uint32_t edge) {
  drr::ImageF img = Uniform(w, h, 0, 0, 0);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = edge; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.pixels[(size_t(y) * w + x) * 4 + c] = 1.0f;
  return img;
}

TEST(Flip, LabOfTheSrgbPrimariesAndWhite) {
  // The CIE L*a*b* (D65) of sRGB green, blue and white, as tabulated for sRGB.
  const auto green = drr::FlipSrgbToLab({0, 1, 0}), blue = drr::FlipSrgbToLab({0, 0, 1});
  const auto white = drr::FlipSrgbToLab({1, 1, 1});
  EXPECT_NEAR(green[0], 87.735, 0.02);
  EXPECT_NEAR(green[1], -86.183, 0.05);
  EXPECT_NEAR(green[2], 83.179, 0.05);
  EXPECT_NEAR(blue[0], 32.303, 0.02);
  EXPECT_NEAR(blue[1], 79.197, 0.05);
  EXPECT_NEAR(blue[2], -107.864, 0.05);
  EXPECT_NEAR(white[0], 100.0, 0.01);
  EXPECT_NEAR(white[1], 0.0, 0.05);
  EXPECT_NEAR(white[2], 0.0, 0.05);
}

TEST(Flip, HuntAdjustedHyABOfGreenAndBlueIsTheMaximum) {
  // Hunt: a, b scaled by 0.01 L. HyAB = |dL| + |d(a, b)|. From the tabulated
  // Lab values: 55.432 + hypot(-75.612 - 25.583, 72.977 + 34.843) = 203.30.
  const auto g = drr::FlipHunt(drr::FlipSrgbToLab({0, 1, 0}));
  const auto b = drr::FlipHunt(drr::FlipSrgbToLab({0, 0, 1}));
  EXPECT_NEAR(g[1], 0.01 * 87.735 * -86.183, 0.05);
  EXPECT_NEAR(drr::FlipHyAB(g, b), 203.30, 0.1);
  EXPECT_NEAR(drr::FlipMaxColorDistance(), std::pow(203.30, 0.7), 0.02);
  // HyAB of black and white: |dL| = 100, no chroma.
  EXPECT_NEAR(drr::FlipHyAB(drr::FlipHunt(drr::FlipSrgbToLab({0, 0, 0})),
                            drr::FlipHunt(drr::FlipSrgbToLab({1, 1, 1}))), 100.0, 0.05);
}

TEST(Flip, ColourErrorMapping) {
  const double cmax = std::pow(203.30, 0.7);
  EXPECT_EQ(drr::FlipColorError(0.0), 0.0);
  EXPECT_NEAR(drr::FlipColorError(203.30), 1.0, 1e-3);
  // The knee: 0.4 cmax maps to 0.95.
  EXPECT_NEAR(drr::FlipColorError(std::pow(0.4 * cmax, 1 / 0.7)), 0.95, 1e-6);
  // Below the knee the map is linear in HyAB ^ 0.7.
  EXPECT_NEAR(drr::FlipColorError(10.0), std::pow(10.0, 0.7) * 0.95 / (0.4 * cmax), 1e-3);
}

TEST(Flip, FilterRadiiAndPixelsPerDegree) {
  // 0.7 m from a 0.7 m wide 3840-pixel display: 67.02 ppd.
  EXPECT_NEAR(drr::FlipPixelsPerDegree(0.7, 0.7, 3840), 67.02, 0.01);
  // CSF: 3 sqrt(0.04 / (2 pi^2)) 67 = 9.05 -> 10. Features: sigma = 0.5 * 0.082 * 67 = 2.747, 3 sigma = 8.24 -> 9.
  EXPECT_EQ(drr::FlipCsfRadius(67.0), 10);
  EXPECT_EQ(drr::FlipFeatureRadius(67.0), 9);
  EXPECT_EQ(drr::FlipCsfRadius(30.0), 5);   // 4.05
  EXPECT_EQ(drr::FlipFeatureRadius(30.0), 4);  // 3.69
}

TEST(Flip, FullScreenOnTheReferenceDisplay) {
  // The frame stretched over FLIP's 0.7 m, 3840-pixel display seen from 0.7 m:
  // ppd = 0.7 m x (w / 0.7 m) x pi / 180 = w pi / 180.
  EXPECT_NEAR(drr::FlipFullScreenPpd(3840), 67.02, 0.01);
  EXPECT_NEAR(drr::FlipFullScreenPpd(320), 320 * 3.14159265358979 / 180, 1e-9);  // 5.585
  EXPECT_NEAR(drr::FlipFullScreenPpd(1920), 33.51, 0.01);
  // At 5.585 ppd both filters reach one pixel: CSF 3 x 0.04502 x 5.585 = 0.754,
  // features 3 x 0.041 x 5.585 = 0.687.
  EXPECT_EQ(drr::FlipCsfRadius(drr::FlipFullScreenPpd(320)), 1);
  EXPECT_EQ(drr::FlipFeatureRadius(drr::FlipFullScreenPpd(320)), 1);
}

TEST(Flip, AtTheBenchPpdUniformErrorIsUnchangedAndEdgesStayLocal) {
  const double ppd = drr::FlipFullScreenPpd(320);
  // Normalised filters keep a uniform image: the same mapped colour error as at 67 ppd.
  const auto grey = Uniform(24, 16, 0.5f, 0.5f, 0.5f), grey2 = Uniform(24, 16, 0.52f, 0.5f, 0.5f);
  const double expected = drr::FlipColorError(drr::FlipHyAB(drr::FlipHunt(drr::FlipSrgbToLab({0.5, 0.5, 0.5})),
                                                            drr::FlipHunt(drr::FlipSrgbToLab({0.52, 0.5, 0.5}))));
  EXPECT_NEAR(drr::ComputeFlip(grey, grey2, ppd).mean, expected, 1e-4);
  // An edge moved by a pixel (columns 30 -> 31): with 1-pixel filters only
  // columns 28..32 can differ (the changed column 30, one filter tap, one
  // feature tap); at 67 ppd the error reaches 19 columns on either side.
  const uint32_t w = 64, h = 8;
  const auto a = Step(w, h, 30), b = Step(w, h, 31);
  const auto low = drr::ComputeFlip(a, b, ppd, true), high = drr::ComputeFlip(a, b, 67.0, true);
  ASSERT_TRUE(low.valid && high.valid);
  for (uint32_t x = 0; x < w; ++x) {
    if (x < 28 || x > 32) {
      EXPECT_EQ(low.map.pixels[4 * w + x], 0.0f) << x;
    }
  }
  EXPECT_GT(low.map.pixels[4 * w + 30], 0.5f);
  EXPECT_GT(high.map.pixels[4 * w + 25], 0.0f);
  EXPECT_LT(low.mean, high.mean);
}

TEST(Flip, IdenticalImagesGiveZero) {
  const auto a = Step(40, 30, 17);
  const auto r = drr::ComputeFlip(a, a);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.mean, 0.0);
}

TEST(Flip, UniformImagesGiveTheMappedColourError) {
  // No features in uniform images and the CSF filters keep a constant: the
  // error is the colour mapping of the two colours' HyAB.
  const auto green = Uniform(24, 16, 0, 1, 0), blue = Uniform(24, 16, 0, 0, 1);
  EXPECT_NEAR(drr::ComputeFlip(green, blue).mean, 1.0, 1e-4);
  // White against black: HyAB 100, 100^0.7 = 25.12 above the knee (16.56):
  // 0.95 + (25.12 - 16.56) / (41.40 - 16.56) * 0.05 = 0.967, not 1 (only the
  // green/blue pair reaches the maximum).
  const auto white = Uniform(24, 16, 1, 1, 1), black = Uniform(24, 16, 0, 0, 0);
  EXPECT_NEAR(drr::ComputeFlip(white, black).mean, 0.967, 0.001);
  const auto grey = Uniform(24, 16, 0.5f, 0.5f, 0.5f), grey2 = Uniform(24, 16, 0.52f, 0.5f, 0.5f);
  const double expected = drr::FlipColorError(drr::FlipHyAB(drr::FlipHunt(drr::FlipSrgbToLab({0.5, 0.5, 0.5})),
                                                            drr::FlipHunt(drr::FlipSrgbToLab({0.52, 0.5, 0.5}))));
  EXPECT_NEAR(drr::ComputeFlip(grey, grey2).mean, expected, 1e-4);
}

TEST(Flip, MovedEdgeErrsNearTheEdgeOnly) {
  const uint32_t w = 64, h = 8;
  const auto a = Step(w, h, 30), b = Step(w, h, 31);
  const auto r = drr::ComputeFlip(a, b, 67.0, true);
  ASSERT_TRUE(r.valid);
  ASSERT_EQ(r.map.pixels.size(), size_t(w) * h);
  const float atEdge = r.map.pixels[4 * w + 30];
  EXPECT_GT(atEdge, 0.5f);
  // Beyond the CSF and feature radii (10 and 9 pixels) nothing differs.
  EXPECT_EQ(r.map.pixels[4 * w + 5], 0.0f);
  EXPECT_EQ(r.map.pixels[4 * w + 58], 0.0f);
  EXPECT_GT(r.mean, 0.0);
  EXPECT_LT(r.mean, atEdge);
}

TEST(Flip, BadInputIsInvalid) {
  EXPECT_FALSE(drr::ComputeFlip(Uniform(4, 4, 0, 0, 0), Uniform(5, 4, 0, 0, 0)).valid);
  EXPECT_FALSE(drr::ComputeFlip(drr::ImageF{}, drr::ImageF{}).valid);
  EXPECT_FALSE(drr::ComputeFlip(Uniform(4, 4, 0, 0, 0), Uniform(4, 4, 0, 0, 0), 0.0).valid);
}

TEST(TemporalError, FlickerBeyondTheReferenceMotion) {
  const auto dark = Uniform(8, 8, 0.4f, 0.4f, 0.4f), light = Uniform(8, 8, 0.5f, 0.5f, 0.5f);
  // Still reference, test alternating by 0.1: the whole change is flicker.
  EXPECT_NEAR(drr::TemporalErrorRms(dark, light, dark, dark), 0.1, 1e-6);
  // The test changes exactly as the reference does: no flicker, though both move.
  EXPECT_NEAR(drr::TemporalErrorRms(dark, light, dark, light), 0.0, 1e-7);
  // A constant error (test always 0.1 darker) is not temporal.
  EXPECT_NEAR(drr::TemporalErrorRms(dark, dark, light, light), 0.0, 1e-7);
  EXPECT_TRUE(std::isnan(drr::TemporalErrorRms(dark, Uniform(4, 8, 0, 0, 0), dark, dark)));
}

}  // namespace
