#include "analysis/ImageMetrics.h"

#include <algorithm>
#include <cmath>

namespace drr {

ImageF ImageFromRGBA8(const uint8_t* rgba, uint32_t width, uint32_t height, uint32_t rowPitch) {
  ImageF img;
  img.width = width;
  img.height = height;
  img.channels = 4;
  img.pixels.resize(size_t(width) * height * 4);
  for (uint32_t y = 0; y < height; ++y) {
    const uint8_t* row = rgba + size_t(y) * rowPitch;
    for (uint32_t i = 0; i < width * 4; ++i) {
      img.pixels[size_t(y) * width * 4 + i] = row[i] / 255.0f;
    }
  }
  return img;
}

ImageF Downsample(const ImageF& image, uint32_t factor) {
  ImageF out;
  if (factor == 0 || image.width % factor || image.height % factor) return out;
  out.width = image.width / factor;
  out.height = image.height / factor;
  out.channels = image.channels;
  out.pixels.assign(size_t(out.width) * out.height * out.channels, 0.0f);
  const float norm = 1.0f / float(factor * factor);
  for (uint32_t y = 0; y < out.height; ++y) {
    for (uint32_t x = 0; x < out.width; ++x) {
      for (uint32_t c = 0; c < out.channels; ++c) {
        // Colour channels are averaged in linear light, alpha as it is.
        const bool colour = c < 3;
        float sum = 0.0f;
        for (uint32_t j = 0; j < factor; ++j) {
          for (uint32_t i = 0; i < factor; ++i) {
            const float v = image.At(x * factor + i, y * factor + j, c);
            sum += colour ? SrgbToLinear(v) : v;
          }
        }
        const float mean = sum * norm;
        out.pixels[(size_t(y) * out.width + x) * out.channels + c] =
            colour ? LinearToSrgb(mean) : mean;
      }
    }
  }
  return out;
}

namespace {

// Rec. 709 luma of the display values: SSIM is computed on it.
std::vector<double> Luma(const ImageF& img) {
  std::vector<double> y(size_t(img.width) * img.height);
  for (uint32_t j = 0; j < img.height; ++j) {
    for (uint32_t i = 0; i < img.width; ++i) {
      y[size_t(j) * img.width + i] =
          0.2126 * img.At(i, j, 0) + 0.7152 * img.At(i, j, 1) + 0.0722 * img.At(i, j, 2);
    }
  }
  return y;
}

// Separable Gaussian blur (sigma 1.5, 11 taps, as in Wang et al. 2004),
// clamped at the borders.
std::vector<double> Blur(const std::vector<double>& src, uint32_t w, uint32_t h) {
  constexpr int kRadius = 5;
  double kernel[2 * kRadius + 1];
  double sum = 0.0;
  for (int k = -kRadius; k <= kRadius; ++k) {
    kernel[k + kRadius] = std::exp(-(k * k) / (2.0 * 1.5 * 1.5));
    sum += kernel[k + kRadius];
  }
  for (double& k : kernel) k /= sum;
  std::vector<double> tmp(src.size()), dst(src.size());
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      double acc = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) {
        const int xx = std::clamp(int(x) + k, 0, int(w) - 1);
        acc += kernel[k + kRadius] * src[size_t(y) * w + xx];
      }
      tmp[size_t(y) * w + x] = acc;
    }
  }
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      double acc = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) {
        const int yy = std::clamp(int(y) + k, 0, int(h) - 1);
        acc += kernel[k + kRadius] * tmp[size_t(yy) * w + x];
      }
      dst[size_t(y) * w + x] = acc;
    }
  }
  return dst;
}

double Ssim(const ImageF& a, const ImageF& b) {
  const uint32_t w = a.width, h = a.height;
  const std::vector<double> x = Luma(a), y = Luma(b);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const auto mx = Blur(x, w, h), my = Blur(y, w, h);
  const auto sxx = Blur(xx, w, h), syy = Blur(yy, w, h), sxy = Blur(xy, w, h);
  constexpr double kC1 = (0.01 * 1.0) * (0.01 * 1.0);  // dynamic range L = 1
  constexpr double kC2 = (0.03 * 1.0) * (0.03 * 1.0);
  double total = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double vx = sxx[i] - mx[i] * mx[i];
    const double vy = syy[i] - my[i] * my[i];
    const double cxy = sxy[i] - mx[i] * my[i];
    total += ((2 * mx[i] * my[i] + kC1) * (2 * cxy + kC2)) /
             ((mx[i] * mx[i] + my[i] * my[i] + kC1) * (vx + vy + kC2));
  }
  return total / double(x.size());
}

}  // namespace

ImageError CompareImages(const ImageF& a, const ImageF& b) {
  ImageError e;
  if (a.width != b.width || a.height != b.height || a.channels < 3 || b.channels < 3 ||
      a.width == 0 || a.height == 0) {
    return e;
  }
  double sumSq = 0.0;
  for (uint32_t y = 0; y < a.height; ++y) {
    for (uint32_t x = 0; x < a.width; ++x) {
      bool differs = false;
      for (uint32_t c = 0; c < 3; ++c) {
        const double va = a.At(x, y, c), vb = b.At(x, y, c);
        if (!std::isfinite(va) || !std::isfinite(vb)) return e;
        const double d = va - vb;
        sumSq += d * d;
        e.maxAbsError = std::max(e.maxAbsError, std::abs(d));
        differs |= d != 0.0;
      }
      e.pixelsDiffering += differs ? 1 : 0;
    }
  }
  e.mse = sumSq / (double(a.width) * a.height * 3.0);
  e.psnr = e.mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(1.0 / e.mse);
  e.ssim = Ssim(a, b);
  e.valid = true;
  return e;
}

double TemporalErrorRms(const ImageF& testPrev, const ImageF& test, const ImageF& referencePrev,
                        const ImageF& reference) {
  const ImageF* all[] = {&testPrev, &test, &referencePrev, &reference};
  for (const ImageF* i : all)
    if (i->width != test.width || i->height != test.height || i->channels < 3 || test.width == 0 || test.height == 0)
      return std::nan("");
  double sumSq = 0.0;
  for (uint32_t y = 0; y < test.height; ++y)
    for (uint32_t x = 0; x < test.width; ++x)
      for (uint32_t c = 0; c < 3; ++c) {
        const double d = (double(test.At(x, y, c)) - testPrev.At(x, y, c)) -
                         (double(reference.At(x, y, c)) - referencePrev.At(x, y, c));
        if (!std::isfinite(d)) return std::nan("");
        sumSq += d * d;
      }
  return std::sqrt(sumSq / (double(test.width) * test.height * 3.0));
}

}  // namespace drr
