// Image error against a reference, for the error-versus-run-time reports:
// PSNR, SSIM and the largest per-pixel difference, on 8-bit RGBA or float
// images. CPU only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "imageio/Srgb.h"

namespace drr {

// An RGB(A) image with float channels in [0, 1] (display-encoded, i.e. the
// sRGB values a viewer sees, which is what the article's screenshots compare).
struct ImageF {
  uint32_t width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // row-major, tightly packed
  float At(uint32_t x, uint32_t y, uint32_t c) const {
    return pixels[(size_t(y) * width + x) * channels + c];
  }
};

ImageF ImageFromRGBA8(const uint8_t* rgba, uint32_t width, uint32_t height, uint32_t rowPitch);

struct ImageError {
  double mse = 0.0;          // mean squared error over RGB, values in [0, 1]
  double psnr = 0.0;         // dB; +infinity when the images are identical
  double ssim = 1.0;         // mean SSIM of Rec. 709 luma, 11-tap Gaussian window
  double maxAbsError = 0.0;  // largest |a - b| of any RGB channel, in [0, 1]
  uint64_t pixelsDiffering = 0;
  bool valid = false;        // false when sizes differ or an input has NaN/Inf
};

// Compares the RGB channels of a and b (alpha ignored). Non-finite values
// make the result invalid rather than poisoning the statistics.
ImageError CompareImages(const ImageF& a, const ImageF& b);

// Box-filters an image down by an integer factor per axis (the 4x4 super-
// sampled reference of the reports). Width and height must be divisible.
ImageF Downsample(const ImageF& image, uint32_t factor);

// Temporal instability beyond the reference's own motion: the RMS over RGB of
// (test - testPrev) - (reference - referencePrev), i.e. the frame-to-frame
// change of the error image. 0 when the test changes exactly as the reference
// does (a still scene with a stable filter, or a perfect moving one); flicker
// and crawling raise it. NaN when sizes differ or a value is not finite.
double TemporalErrorRms(const ImageF& testPrev, const ImageF& test, const ImageF& referencePrev,
                        const ImageF& reference);


}  // namespace drr
