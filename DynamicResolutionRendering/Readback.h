// The one image type of the GPU side: the pixels of one texture subresource,
// tightly packed in the texture's DXGI format, and the read-back path that
// fills it (a STAGING copy recorded in the frame, mapped once the GPU is done).
// Used by the sample's captures, the bench and the rendering tests.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "d3dl/D3DLike.h"

namespace drr {

struct Image {
  uint32_t width = 0, height = 0;
  d3dl::DXGI_FORMAT format = d3dl::DXGI_FORMAT_UNKNOWN;
  std::vector<uint8_t> pixels;  // rows of width * BytesPerPixel(), no padding

  bool Empty() const { return pixels.empty(); }
  uint32_t BytesPerPixel() const { return d3dl::FormatBytesPerElement(format); }
  const uint8_t* At(uint32_t x, uint32_t y) const {
    return pixels.data() + (size_t(y) * width + x) * BytesPerPixel();
  }
  // R, G, B, A of an 8-bit RGBA or BGRA pixel (BGRA is swizzled to RGBA).
  std::array<uint8_t, 4> RGBA8(uint32_t x, uint32_t y) const;
  // Channel c of a 16/32-bit float pixel, or of an 8-bit pixel as 0..1.
  float Float(uint32_t x, uint32_t y, uint32_t c = 0) const;
  // An 8-bit BGRA image turned into RGBA in place (other formats unchanged).
  void SwizzleToRGBA();
};

float HalfToFloat(uint16_t h);

// Records a copy of `mip` of `texture` into a new STAGING texture (null on failure).
d3dl::ComPtr<d3dl::Texture2D> CopyToStaging(d3dl::Device* device, d3dl::DeviceContext* ctx,
                                            d3dl::Texture2D* texture, uint32_t mip = 0);
// Maps a STAGING texture written by CopyToStaging (waits for its copy).
bool MapStaging(d3dl::DeviceContext* ctx, d3dl::Texture2D* staging, Image* image, std::string* error);
// Both at once.
bool ReadBack(d3dl::Device* device, d3dl::DeviceContext* ctx, d3dl::Texture2D* texture, uint32_t mip,
              Image* image, std::string* error);

}  // namespace drr
