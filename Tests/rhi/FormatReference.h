// CPU reference encodings of render-target formats (FormatTests.cpp): what a
// float written by a pixel shader becomes in each format, computed here
// independently of the GPU. Rounding is to nearest, ties to even; the small
// unsigned floats of R11G11B10_FLOAT may also round toward zero, which the
// Vulkan specification allows (lavapipe does).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace rhitest::fmtref {

// The pixel shader's value for pixel p, target t, channel c (fmt_gbuffer_ps.hlsl).
inline float Value(uint32_t x, uint32_t y, uint32_t target, uint32_t channel) {
  const uint32_t h = x * 37u + y * 101u + target * 53u + channel * 17u;
  return float(h & 255u) / 256.0f;
}

// UNORM with `bits` bits: round(saturate(v) * (2^bits - 1)).
inline uint32_t Unorm(float v, int bits) {
  const double max = double((1u << bits) - 1);
  return uint32_t(std::nearbyint(std::clamp(double(v), 0.0, 1.0) * max));
}

// The sRGB transfer function applied before 8-bit quantisation.
inline uint32_t Srgb8(float v) {
  const double l = std::clamp(double(v), 0.0, 1.0);
  const double s = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
  return uint32_t(std::nearbyint(s * 255.0));
}

// A float with `mantBits` mantissa and 5 exponent bits (bias 15), optionally
// signed: half (10 bits, signed), the 11-bit (6) and 10-bit (5) unsigned
// floats of R11G11B10_FLOAT. Unsigned ones clamp negatives to 0. Finite
// inputs in range only (the tests stay far below the maximum).
inline uint32_t SmallFloat(float v, int mantBits, bool isSigned, bool towardZero = false) {
  uint32_t sign = 0;
  if (v < 0) {
    if (!isSigned) return 0;
    sign = 1u << (mantBits + 5);
    v = -v;
  }
  if (v == 0) return sign;
  int e;
  const double m = std::frexp(double(v), &e);  // v = m * 2^e, m in [0.5, 1)
  int exp = e - 1 + 15;                          // biased exponent of 1.xxx * 2^(e-1)
  double scaled;
  if (exp <= 0) {  // denormal: v / 2^-14 * 2^mantBits
    scaled = std::ldexp(double(v), 14 + mantBits);
    exp = 0;
  } else {
    scaled = (m * 2.0 - 1.0) * double(1u << mantBits);
  }
  uint32_t mant = uint32_t(towardZero ? std::floor(scaled) : std::nearbyint(scaled));
  if (exp > 0 && mant == (1u << mantBits)) {  // rounded up into the next exponent
    mant = 0;
    ++exp;
  } else if (exp == 0 && mant == (1u << mantBits)) {
    mant = 0;
    exp = 1;
  }
  return sign | (uint32_t(exp) << mantBits) | mant;
}
inline uint32_t Half(float v) { return SmallFloat(v, 10, true); }
inline uint32_t Float11(float v, bool towardZero = false) { return SmallFloat(v, 6, false, towardZero); }
inline uint32_t Float10(float v, bool towardZero = false) { return SmallFloat(v, 5, false, towardZero); }

// Whether GPU encoding `got` is `want` or one step away (an integer-ordered
// encoding: UNORM codes, or the bits of a same-signed small float).
inline bool WithinOneStep(uint32_t got, uint32_t want) { return got + 1 >= want && got <= want + 1; }

}  // namespace rhitest::fmtref
