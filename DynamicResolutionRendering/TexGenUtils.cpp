#include "TexGenUtils.h"

namespace drr {

std::array<float, 4> CubicFilterLookupTable::Entry(float a) {
  const float a2 = a * a, a3 = a2 * a;
  const float sixth = 1.f / 6.f;
  const float w0 = (-a3 + 3.f * a2 - 3.f * a + 1.f) * sixth;
  const float w1 = (3.f * a3 - 6.f * a2 + 4.f) * sixth;
  const float w2 = (-3.f * a3 + 3.f * a2 + 3.f * a + 1.f) * sixth;
  const float w3 = a3 * sixth;
  const float g0 = w0 + w1;
  const float g1 = w2 + w3;
  const float h0 = 1.f - w1 / g0 + a;
  const float h1 = 1.f + w3 / g1 - a;
  return {h0, h1, g0, g1};
}

std::vector<float> CubicFilterLookupTable::Generate(uint32_t size) {
  std::vector<float> data(size * 4u);
  for (uint32_t i = 0; i < size; ++i) {
    const auto e = Entry(static_cast<float>(i) / static_cast<float>(size));
    for (int c = 0; c < 4; ++c) data[i * 4u + c] = e[c];
  }
  return data;
}

d3dl::HRESULT CubicFilterLookupTable::Create(d3dl::Device* device, uint32_t size) {
  Release();
  const std::vector<float> data = Generate(size);
  d3dl::TEXTURE1D_DESC desc;
  desc.Width = size;
  desc.MipLevels = 1;
  desc.Format = d3dl::DXGI_FORMAT_R32G32B32A32_FLOAT;
  desc.Usage = d3dl::USAGE_IMMUTABLE;
  desc.BindFlags = d3dl::BIND_SHADER_RESOURCE;
  d3dl::SUBRESOURCE_DATA init;
  init.pSysMem = data.data();
  init.SysMemPitch = size * 16u;
  d3dl::HRESULT hr = device->CreateTexture1D(&desc, &init, m_Texture.ReleaseAndGetAddressOf());
  if (d3dl::FAILED(hr)) return hr;
  m_Texture->SetDebugName("CubicFilterLookupTable");
  hr = device->CreateShaderResourceView(m_Texture.Get(), nullptr, m_SRV.ReleaseAndGetAddressOf());
  m_Bytes = uint64_t(size) * 16u;
  return hr;
}

void CubicFilterLookupTable::Release() {
  m_SRV = nullptr;
  m_Texture = nullptr;
  m_Bytes = 0;
}

std::vector<uint8_t> NoiseTexture::Generate(uint32_t size, uint32_t seed, MsvcRand* rng) {
  std::vector<uint8_t> data(size_t(size) * size * 4u);
  MsvcRand local(seed);
  if (rng) *rng = MsvcRand(seed);  // the caller's generator continues after the texels
  MsvcRand& r = rng ? *rng : local;
  for (uint8_t& byte : data) {
    const float v = 256.0f * static_cast<float>(r.Next()) / static_cast<float>(MsvcRand::kMax);
    byte = static_cast<uint8_t>(static_cast<int>(v) & 0xff);
  }
  return data;
}

std::array<float, 2> NoiseTexture::NextOffset() {
  const float x = static_cast<float>(m_Rand.Next()) / (MsvcRand::kMax + 1.0f);
  const float y = static_cast<float>(m_Rand.Next()) / (MsvcRand::kMax + 1.0f);
  return {x, y};
}

d3dl::HRESULT NoiseTexture::Create(d3dl::Device* device, uint32_t size, uint32_t seed) {
  Release();
  const std::vector<uint8_t> data = Generate(size, seed, &m_Rand);
  d3dl::TEXTURE2D_DESC desc;
  desc.Width = size;
  desc.Height = size;
  desc.MipLevels = 1;
  desc.Format = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM;
  desc.Usage = d3dl::USAGE_IMMUTABLE;
  desc.BindFlags = d3dl::BIND_SHADER_RESOURCE;
  d3dl::SUBRESOURCE_DATA init;
  init.pSysMem = data.data();
  init.SysMemPitch = size * 4u;
  d3dl::HRESULT hr = device->CreateTexture2D(&desc, &init, m_Texture.ReleaseAndGetAddressOf());
  if (d3dl::FAILED(hr)) return hr;
  m_Texture->SetDebugName("NoiseTexture");
  hr = device->CreateShaderResourceView(m_Texture.Get(), nullptr, m_SRV.ReleaseAndGetAddressOf());
  m_Size = size;
  m_Bytes = uint64_t(size) * size * 4u;
  return hr;
}

void NoiseTexture::Release() {
  m_SRV = nullptr;
  m_Texture = nullptr;
  m_Size = 0;
  m_Bytes = 0;
}

}  // namespace drr
