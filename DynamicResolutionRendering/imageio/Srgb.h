// The sRGB transfer function (IEC 61966-2-1), one definition for textures,
// screenshots and the image metrics.
#pragma once

#include <algorithm>
#include <cmath>

namespace drr {

inline float SrgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

inline float LinearToSrgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

}  // namespace drr
