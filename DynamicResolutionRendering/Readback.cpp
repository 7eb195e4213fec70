#include "Readback.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace drr {

float HalfToFloat(uint16_t h) {
  const uint32_t sign = (h >> 15) & 1, exp = (h >> 10) & 0x1f, man = h & 0x3ff;
  float v;
  if (exp == 0) v = std::ldexp(float(man), -24);
  else if (exp == 31) v = man ? NAN : INFINITY;
  else v = std::ldexp(float(man | 0x400), int(exp) - 25);
  return sign ? -v : v;
}

static bool IsBGRA8(d3dl::DXGI_FORMAT f) {
  return f == d3dl::DXGI_FORMAT_B8G8R8A8_UNORM || f == d3dl::DXGI_FORMAT_B8G8R8A8_UNORM_SRGB;
}

std::array<uint8_t, 4> Image::RGBA8(uint32_t x, uint32_t y) const {
  const uint8_t* p = At(x, y);
  if (IsBGRA8(format)) return {p[2], p[1], p[0], p[3]};
  return {p[0], p[1], p[2], p[3]};
}

float Image::Float(uint32_t x, uint32_t y, uint32_t c) const {
  const uint8_t* p = At(x, y);
  switch (format) {
    case d3dl::DXGI_FORMAT_R32_FLOAT:
    case d3dl::DXGI_FORMAT_R32G32_FLOAT:
    case d3dl::DXGI_FORMAT_R32G32B32A32_FLOAT:
    case d3dl::DXGI_FORMAT_D32_FLOAT:
    case d3dl::DXGI_FORMAT_R32_TYPELESS: {
      float f;
      std::memcpy(&f, p + 4 * c, 4);
      return f;
    }
    case d3dl::DXGI_FORMAT_R16_FLOAT:
    case d3dl::DXGI_FORMAT_R16G16_FLOAT:
    case d3dl::DXGI_FORMAT_R16G16B16A16_FLOAT: {
      uint16_t h;
      std::memcpy(&h, p + 2 * c, 2);
      return HalfToFloat(h);
    }
    default:
      return RGBA8(x, y)[c] / 255.0f;
  }
}

void Image::SwizzleToRGBA() {
  if (!IsBGRA8(format)) return;
  for (size_t i = 0; i + 3 < pixels.size(); i += 4) std::swap(pixels[i], pixels[i + 2]);
  format = format == d3dl::DXGI_FORMAT_B8G8R8A8_UNORM_SRGB ? d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB
                                                         : d3dl::DXGI_FORMAT_R8G8B8A8_UNORM;
}

d3dl::ComPtr<d3dl::Texture2D> CopyToStaging(d3dl::Device* device, d3dl::DeviceContext* ctx,
                                            d3dl::Texture2D* texture, uint32_t mip) {
  d3dl::ComPtr<d3dl::Texture2D> staging;
  if (!texture) return staging;
  d3dl::TEXTURE2D_DESC d;
  texture->GetDesc(&d);
  if (mip >= d.MipLevels) return staging;
  d3dl::TEXTURE2D_DESC s;
  s.Width = std::max(1u, d.Width >> mip);
  s.Height = std::max(1u, d.Height >> mip);
  s.Format = d.Format;
  s.Usage = d3dl::USAGE_STAGING;
  s.CPUAccessFlags = d3dl::CPU_ACCESS_READ;
  s.BindFlags = 0;
  if (d3dl::FAILED(device->CreateTexture2D(&s, nullptr, staging.GetAddressOf()))) return {};
  ctx->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, texture, d3dl::CalcSubresource(mip, 0, d.MipLevels),
                             nullptr);
  return staging;
}

bool MapStaging(d3dl::DeviceContext* ctx, d3dl::Texture2D* staging, Image* image, std::string* error) {
  if (!staging) {
    if (error) *error = "no staging texture (the copy could not be made)";
    return false;
  }
  d3dl::TEXTURE2D_DESC d;
  staging->GetDesc(&d);
  d3dl::MAPPED_SUBRESOURCE m;
  const d3dl::HRESULT hr = ctx->Map(staging, 0, d3dl::MAP_READ, 0, &m);
  if (d3dl::FAILED(hr)) {
    if (error) *error = std::string("Map(MAP_READ) failed: ") + d3dl::HResultName(hr);
    return false;
  }
  image->width = d.Width;
  image->height = d.Height;
  image->format = d.Format == d3dl::DXGI_FORMAT_R32_TYPELESS ? d3dl::DXGI_FORMAT_R32_FLOAT : d.Format;
  const size_t row = size_t(d.Width) * image->BytesPerPixel();
  image->pixels.resize(row * d.Height);
  for (uint32_t y = 0; y < d.Height; ++y)
    std::memcpy(image->pixels.data() + y * row, static_cast<const uint8_t*>(m.pData) + size_t(y) * m.RowPitch, row);
  ctx->Unmap(staging, 0);
  return true;
}

bool ReadBack(d3dl::Device* device, d3dl::DeviceContext* ctx, d3dl::Texture2D* texture, uint32_t mip,
              Image* image, std::string* error) {
  const d3dl::ComPtr<d3dl::Texture2D> staging = CopyToStaging(device, ctx, texture, mip);
  return MapStaging(ctx, staging.Get(), image, error);
}

}  // namespace drr
