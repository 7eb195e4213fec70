// D3DLikeRHI public types: DXGI_FORMAT (Direct3D's numbering, the subset the
// sample and its loaders need) and what the RHI can say about a format.
#pragma once

#include "d3dl/Base.h"

namespace d3dl {

enum DXGI_FORMAT : uint32_t {
  DXGI_FORMAT_UNKNOWN = 0,
  DXGI_FORMAT_R32G32B32A32_FLOAT = 2,
  DXGI_FORMAT_R32G32B32_FLOAT = 6,
  DXGI_FORMAT_R16G16B16A16_TYPELESS = 9,  // typeless families (views name a typed member)
  DXGI_FORMAT_R16G16B16A16_FLOAT = 10,
  DXGI_FORMAT_R16G16B16A16_UNORM = 11,
  DXGI_FORMAT_R32G32_FLOAT = 16,
  DXGI_FORMAT_R10G10B10A2_TYPELESS = 23,
  DXGI_FORMAT_R10G10B10A2_UNORM = 24,
  DXGI_FORMAT_R11G11B10_FLOAT = 26,
  DXGI_FORMAT_R8G8B8A8_TYPELESS = 27,
  DXGI_FORMAT_R8G8B8A8_UNORM = 28,
  DXGI_FORMAT_R8G8B8A8_UNORM_SRGB = 29,
  DXGI_FORMAT_R8G8B8A8_UINT = 30,
  DXGI_FORMAT_R16G16_FLOAT = 34,
  DXGI_FORMAT_R32_TYPELESS = 39,  // depth texture that is also sampled
  DXGI_FORMAT_D32_FLOAT = 40,
  DXGI_FORMAT_R32_FLOAT = 41,
  DXGI_FORMAT_R32_UINT = 42,
  DXGI_FORMAT_R24G8_TYPELESS = 44,         // depth-stencil texture that is also sampled
  DXGI_FORMAT_D24_UNORM_S8_UINT = 45,      // Vulkan D24_UNORM_S8_UINT, where the adapter has it
  DXGI_FORMAT_R24_UNORM_X8_TYPELESS = 46,  // SRV of the depth half of R24G8_TYPELESS
  DXGI_FORMAT_R8G8_UNORM = 49,
  DXGI_FORMAT_R16_FLOAT = 54,
  DXGI_FORMAT_R16_UINT = 57,
  DXGI_FORMAT_R8_UNORM = 61,
  DXGI_FORMAT_BC1_UNORM = 71,
  DXGI_FORMAT_BC1_UNORM_SRGB = 72,
  DXGI_FORMAT_BC2_UNORM = 74,
  DXGI_FORMAT_BC2_UNORM_SRGB = 75,
  DXGI_FORMAT_BC3_UNORM = 77,
  DXGI_FORMAT_BC3_UNORM_SRGB = 78,
  DXGI_FORMAT_BC4_UNORM = 80,
  DXGI_FORMAT_BC4_SNORM = 81,
  DXGI_FORMAT_BC5_UNORM = 83,
  DXGI_FORMAT_BC5_SNORM = 84,
  DXGI_FORMAT_B8G8R8A8_UNORM = 87,
  DXGI_FORMAT_B8G8R8A8_UNORM_SRGB = 91,
};

// The sRGB formats and the UNORM formats with the same bits: views of one may
// read or write the other, a copy keeps the bits. Header-only, so that code
// without the RHI's library (the scene's CPU side) can use it.
struct FormatSrgbPair {
  DXGI_FORMAT srgb;
  DXGI_FORMAT linear;
};
inline constexpr FormatSrgbPair kFormatSrgbPairs[] = {
    {DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, DXGI_FORMAT_R8G8B8A8_UNORM},
    {DXGI_FORMAT_B8G8R8A8_UNORM_SRGB, DXGI_FORMAT_B8G8R8A8_UNORM},
    {DXGI_FORMAT_BC1_UNORM_SRGB, DXGI_FORMAT_BC1_UNORM},
    {DXGI_FORMAT_BC2_UNORM_SRGB, DXGI_FORMAT_BC2_UNORM},
    {DXGI_FORMAT_BC3_UNORM_SRGB, DXGI_FORMAT_BC3_UNORM},
};
// The UNORM format with an sRGB format's bits (BC1_UNORM_SRGB: BC1_UNORM);
// any other format itself.
constexpr DXGI_FORMAT FormatLinearOf(DXGI_FORMAT format) {
  for (const FormatSrgbPair& p : kFormatSrgbPairs)
    if (p.srgb == format) return p.linear;
  return format;
}
// The sRGB format with a UNORM format's bits, where there is one; any other
// format itself.
constexpr DXGI_FORMAT FormatSrgbOf(DXGI_FORMAT format) {
  for (const FormatSrgbPair& p : kFormatSrgbPairs)
    if (p.linear == format) return p.srgb;
  return format;
}
constexpr bool FormatIsSrgb(DXGI_FORMAT format) { return FormatLinearOf(format) != format; }

// Bytes per texel (or per 4x4 block for BC formats); 0 for unknown formats.
UINT FormatBytesPerElement(DXGI_FORMAT format);
bool FormatIsBlockCompressed(DXGI_FORMAT format);
const char* FormatName(DXGI_FORMAT format);

}  // namespace d3dl
