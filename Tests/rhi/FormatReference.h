// CPU reference encodings of render-target formats (FormatTests.cpp): what a
// float written by a pixel shader becomes in each format, computed here
// independently of the GPU. Where the Vulkan specification leaves the rounding
// to the implementation, the reference gives the range of allowed codes:
// float to UNORM may return either integer next to f * (2^b - 1) (exactly
// that integer when it is one), and a float that falls between two values of a
// smaller float format may become either of them.
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

// Codes lo..hi of an encoding that any conformant implementation may produce.
struct CodeRange {
  uint32_t lo, hi;
  bool Holds(uint32_t code) const { return code >= lo && code <= hi; }
};

// The UNORM codes the specification allows for v: the integers next to
// saturate(v) * (2^bits - 1), one code when that product is an integer. The
// product is exact in double for the tests' values (k / 256 times < 2^16).
inline CodeRange UnormAllowed(float v, int bits) {
  const double r = std::clamp(double(v), 0.0, 1.0) * double((1u << bits) - 1);
  return {uint32_t(std::floor(r)), uint32_t(std::ceil(r))};
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
enum class Rounding { Nearest, Down, Up };  // Down and Up in magnitude
inline uint32_t SmallFloat(float v, int mantBits, bool isSigned, Rounding rounding = Rounding::Nearest) {
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
  const double rounded = rounding == Rounding::Down ? std::floor(scaled)
                         : rounding == Rounding::Up ? std::ceil(scaled)
                                                    : std::nearbyint(scaled);
  uint32_t mant = uint32_t(rounded);
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
// The unsigned 11- and 10-bit floats of R11G11B10_FLOAT: the two values next
// to v are allowed (the bits of same-signed floats are ordered as the values).
inline CodeRange Float11Allowed(float v) {
  return {SmallFloat(v, 6, false, Rounding::Down), SmallFloat(v, 6, false, Rounding::Up)};
}
inline CodeRange Float10Allowed(float v) {
  return {SmallFloat(v, 5, false, Rounding::Down), SmallFloat(v, 5, false, Rounding::Up)};
}

// Whether GPU encoding `got` is `want` or one step away (an integer-ordered
// encoding: UNORM codes, or the bits of a same-signed small float).
inline bool WithinOneStep(uint32_t got, uint32_t want) { return got + 1 >= want && got <= want + 1; }

}  // namespace rhitest::fmtref
