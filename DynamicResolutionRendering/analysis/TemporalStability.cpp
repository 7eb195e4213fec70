#include "analysis/TemporalStability.h"

#include <algorithm>
#include <cmath>

namespace drr {
namespace {

bool SameSize(const ImageF& a, const ImageF& b) {
  return a.width == b.width && a.height == b.height && a.channels >= 3 && b.channels >= 3;
}

// Bilinear sample of channel c at continuous pixel coordinates (pixel
// centres at integer + 0.5 are at integers here: x, y index pixels).
float Bilinear(const ImageF& img, float x, float y, uint32_t c) {
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  const auto clampX = [&](float v) { return uint32_t(std::clamp(v, 0.0f, float(img.width - 1))); };
  const auto clampY = [&](float v) { return uint32_t(std::clamp(v, 0.0f, float(img.height - 1))); };
  const uint32_t x0 = clampX(fx), x1 = clampX(fx + 1), y0 = clampY(fy), y1 = clampY(fy + 1);
  const float top = img.At(x0, y0, c) * (1 - tx) + img.At(x1, y0, c) * tx;
  const float bottom = img.At(x0, y1, c) * (1 - tx) + img.At(x1, y1, c) * tx;
  return top * (1 - ty) + bottom * ty;
}

}  // namespace

MotionField MotionFromUvVelocity(const std::vector<float>& uv, uint32_t width, uint32_t height) {
  MotionField m;
  if (uv.size() != size_t(width) * height * 2 || width == 0 || height == 0) return m;
  m.width = width;
  m.height = height;
  m.dx.resize(size_t(width) * height);
  m.dy.resize(m.dx.size());
  for (size_t i = 0; i < m.dx.size(); ++i) {
    m.dx[i] = uv[2 * i] * float(width);
    m.dy[i] = uv[2 * i + 1] * float(height);
  }
  return m;
}

ImageF Reproject(const ImageF& previous, const MotionField& motion, std::vector<uint8_t>* valid) {
  ImageF out = previous;
  if (valid) valid->assign(size_t(previous.width) * previous.height, 1);
  if (motion.Empty()) return out;
  for (uint32_t y = 0; y < previous.height; ++y)
    for (uint32_t x = 0; x < previous.width; ++x) {
      const size_t i = size_t(y) * previous.width + x;
      const float sx = float(x) - motion.dx[i], sy = float(y) - motion.dy[i];
      const bool inside = sx >= -0.5f && sy >= -0.5f && sx <= float(previous.width) - 0.5f &&
                          sy <= float(previous.height) - 0.5f && std::isfinite(sx) && std::isfinite(sy);
      if (valid) (*valid)[i] = inside;
      for (uint32_t c = 0; c < previous.channels; ++c)
        out.pixels[i * previous.channels + c] = inside ? Bilinear(previous, sx, sy, c) : 0.0f;
    }
  return out;
}

double ReprojectedInstability(const ImageF& testPrev, const ImageF& test, const ImageF& referencePrev,
                              const ImageF& reference, const MotionField& motion) {
  if (!SameSize(test, testPrev) || !SameSize(test, reference) || !SameSize(test, referencePrev) || test.width == 0 ||
      (!motion.Empty() && (motion.width != test.width || motion.height != test.height)))
    return std::nan("");
  std::vector<uint8_t> valid;
  const ImageF testMoved = Reproject(testPrev, motion, &valid);
  const ImageF referenceMoved = Reproject(referencePrev, motion);
  double sum = 0;
  uint64_t n = 0;
  for (uint32_t y = 0; y < test.height; ++y)
    for (uint32_t x = 0; x < test.width; ++x) {
      if (!valid[size_t(y) * test.width + x]) continue;
      for (uint32_t c = 0; c < 3; ++c) {
        const double d = (double(test.At(x, y, c)) - testMoved.At(x, y, c)) -
                         (double(reference.At(x, y, c)) - referenceMoved.At(x, y, c));
        sum += d * d;
      }
      n += 3;
    }
  if (n == 0 || !std::isfinite(sum)) return std::nan("");
  return std::sqrt(sum / double(n));
}

}  // namespace drr
