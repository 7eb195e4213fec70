// Generated textures of the sample: the cubic B-spline lookup table for the
// fast bicubic filter (Sigg & Hadwiger, GPU Gems 2 ch. 20) and the noise texture.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "d3dl/D3DLike.h"

namespace drr {

class CubicFilterLookupTable {
 public:
  static constexpr uint32_t kDefaultSize = 128;
  // (h0, h1, g0, g1) for the fraction a: B-spline weights w0..w3,
  // g0 = w0 + w1, g1 = w2 + w3, h0 = 1 - w1 / g0 + a, h1 = 1 + w3 / g1 - a.
  static std::array<float, 4> Entry(float a);
  // size entries; entry i is for the fraction (i + 0.5) / size. RGBA floats.
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

class NoiseTexture {
 public:
  static constexpr uint32_t kDefaultSize = 128;
  static constexpr uint32_t kDefaultSeed = 0x1B0D2011u;
  // size x size RGBA8 texels of uniform random bytes from a fixed seed.
  static std::vector<uint8_t> Generate(uint32_t size = kDefaultSize, uint32_t seed = kDefaultSeed);

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
};

}  // namespace drr
