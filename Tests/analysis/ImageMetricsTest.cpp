#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "analysis/ImageMetrics.h"

namespace {

drr::ImageF Gradient(uint32_t w, uint32_t h) {
  drr::ImageF img{w, h, 4, std::vector<float>(size_t(w) * h * 4)};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (uint32_t c = 0; c < 4; ++c)
        img.pixels[(size_t(y) * w + x) * 4 + c] = float((x * 7 + y * 3 + c * 11) % 64) / 63.0f;
  return img;
}

TEST(ImageMetrics, IdenticalImagesHaveInfinitePsnrAndUnitSsim) {
  const auto a = Gradient(32, 24);
  const auto e = drr::CompareImages(a, a);
  ASSERT_TRUE(e.valid);
  EXPECT_EQ(e.mse, 0.0);
  EXPECT_TRUE(std::isinf(e.psnr));
  EXPECT_NEAR(e.ssim, 1.0, 1e-12);
  EXPECT_EQ(e.maxAbsError, 0.0);
  EXPECT_EQ(e.pixelsDiffering, 0u);
}

TEST(ImageMetrics, KnownUniformErrorGivesKnownPsnr) {
  auto a = Gradient(16, 16);
  auto b = a;
  for (size_t i = 0; i < b.pixels.size(); ++i)
    if (i % 4 != 3) b.pixels[i] += 0.1f;  // MSE = 0.01 -> 20 dB
  const auto e = drr::CompareImages(a, b);
  ASSERT_TRUE(e.valid);
  EXPECT_NEAR(e.mse, 0.01, 1e-6);
  EXPECT_NEAR(e.psnr, 20.0, 1e-3);
  EXPECT_NEAR(e.maxAbsError, 0.1, 1e-6);
  EXPECT_EQ(e.pixelsDiffering, 256u);
}

TEST(ImageMetrics, SsimDropsWithStructuralNoiseMoreThanWithABrightnessShift) {
  const auto a = Gradient(64, 64);
  auto shifted = a, noisy = a;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    shifted.pixels[i] += 0.02f;
    noisy.pixels[i] += ((i * 2654435761u) >> 7) % 2 ? 0.02f : -0.02f;
  }
  const auto es = drr::CompareImages(a, shifted), en = drr::CompareImages(a, noisy);
  EXPECT_NEAR(es.mse, en.mse, 1e-6);  // same error energy...
  EXPECT_GT(es.ssim, en.ssim);        // ...but noise destroys structure
  EXPECT_LT(en.ssim, 1.0);
}

TEST(ImageMetrics, NonFiniteOrMismatchedInputIsInvalid) {
  auto a = Gradient(8, 8), b = a;
  b.pixels[5] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(drr::CompareImages(a, b).valid);
  EXPECT_FALSE(drr::CompareImages(a, Gradient(8, 9)).valid);
  EXPECT_FALSE(drr::CompareImages(drr::ImageF{}, drr::ImageF{}).valid);
}

TEST(ImageMetrics, DownsampleAveragesInLinearLight) {
  drr::ImageF img{2, 2, 4, {0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 0, 1, 1, 1, 1, 1}};
  const auto d = drr::Downsample(img, 2);
  ASSERT_EQ(d.width, 1u);
  // Half black, half white in linear light is sRGB ~0.7354, not 0.5.
  EXPECT_NEAR(d.At(0, 0, 0), drr::LinearToSrgb(0.5f), 1e-5);
  EXPECT_NEAR(d.At(0, 0, 0), 0.7354, 1e-3);
  EXPECT_NEAR(d.At(0, 0, 3), 1.0, 1e-6);
  EXPECT_EQ(drr::Downsample(img, 3).width, 0u);  // not divisible
}

TEST(ImageMetrics, Rgba8ConversionRespectsRowPitch) {
  const uint8_t data[2 * 12] = {255, 0, 0, 255, 0, 255, 0, 255, 9, 9, 9, 9,
                                0, 0, 255, 255, 51, 51, 51, 255, 9, 9, 9, 9};
  const auto img = drr::ImageFromRGBA8(data, 2, 2, 12);
  EXPECT_EQ(img.At(0, 0, 0), 1.0f);
  EXPECT_EQ(img.At(1, 0, 1), 1.0f);
  EXPECT_EQ(img.At(0, 1, 2), 1.0f);
  EXPECT_NEAR(img.At(1, 1, 0), 0.2f, 1e-6);
}

}  // namespace
