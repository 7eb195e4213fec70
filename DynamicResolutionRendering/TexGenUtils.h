// Generated textures of the sample, as the original's TexGenUtils.cpp makes
// them: the lookup table of the Bicubic filter and the noise texture (from
// the C library's rand() of the original's platform, emulated by MsvcRand).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "d3dl/D3DLike.h"

namespace drr {

class CubicFilterLookupTable {
 public:
  static constexpr uint32_t kDefaultSize = 128;
  // (h0, h1, g0, g1) for the fraction a: B-spline weights w0..w3 (times
  // 1/6 as a product, as the original), g0 = w0 + w1, g1 = w2 + w3,
  // h0 = 1 - w1 / g0 + a, h1 = 1 + w3 / g1 - a.
  static std::array<float, 4> Entry(float a);
  // size entries; entry i is for the fraction i / size. RGBA floats.
  static std::vector<float> Generate(uint32_t size = kDefaultSize);

  d3dl::HRESULT Create(d3dl::Device* device, uint32_t size = kDefaultSize);
  void Release();
  d3dl::ShaderResourceView* GetSRV() const { return m_SRV.Get(); }
  uint64_t Bytes() const { return m_Bytes; }

 private:
  d3dl::ComPtr<d3dl::Texture1D> m_Texture;
  d3dl::ComPtr<d3dl::ShaderResourceView> m_SRV;
  uint64_t m_Bytes = 0;
};

// The rand() of the original's C library (Microsoft's): a 32-bit linear
// congruential generator whose bits 16..30 are the result, 0..kMax.
class MsvcRand {
 public:
  static constexpr int kMax = 0x7fff;  // RAND_MAX
  explicit MsvcRand(uint32_t seed = 1) : m_State(seed) {}
  int Next() {
    m_State = m_State * 214013u + 2531011u;
    return int((m_State >> 16) & 0x7fffu);
  }

 private:
  uint32_t m_State;
};

class NoiseTexture {
 public:
  static constexpr uint32_t kDefaultSize = 128;
  static constexpr uint32_t kDefaultSeed = 42;  // the original's srand(42)
  // size x size RGBA8 texels, one rand() each: byte(256 * r / RAND_MAX),
  // where r = RAND_MAX gives 256 and the conversion keeps its low byte (0).
  // *rng (optional) continues the sequence afterwards.
  static std::vector<uint8_t> Generate(uint32_t size = kDefaultSize, uint32_t seed = kDefaultSeed,
                                       MsvcRand* rng = nullptr);
  // The Noise filter's per-frame offset, two further rand() / (RAND_MAX + 1).
  std::array<float, 2> NextOffset();

  d3dl::HRESULT Create(d3dl::Device* device, uint32_t size = kDefaultSize,
                       uint32_t seed = kDefaultSeed);
  void Release();
  d3dl::ShaderResourceView* GetSRV() const { return m_SRV.Get(); }
  uint32_t Size() const { return m_Size; }
  uint64_t Bytes() const { return m_Bytes; }

 private:
  d3dl::ComPtr<d3dl::Texture2D> m_Texture;
  d3dl::ComPtr<d3dl::ShaderResourceView> m_SRV;
  uint32_t m_Size = 0;
  uint64_t m_Bytes = 0;
  MsvcRand m_Rand;
};

}  // namespace drr
