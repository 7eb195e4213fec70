// DXGI_FORMAT <-> VkFormat table and the layout of texel data in buffers.
#pragma once

#include <vulkan/vulkan.h>

#include "d3dl/Types.h"

namespace d3dl::impl {

struct FormatInfo {
  DXGI_FORMAT dxgi;
  VkFormat vk;
  uint32_t bytes;  // per texel, or per 4x4 block
  bool bc;
  bool depth;
  bool integer;
  const char* name;
  // Views may reinterpret a texture only within its family (D3D11's typeless
  // groups: R8G8B8A8_TYPELESS holds _UNORM, _UNORM_SRGB, _UINT). UNKNOWN: a
  // family of its own. The port also lets UNORM and SRGB members view each
  // other without a TYPELESS texture (the sample's sRGB fix relies on it).
  DXGI_FORMAT family = DXGI_FORMAT_UNKNOWN;
  bool typeless = false;  // a texture format only; views must name a typed member
  VkFormat depthVk = VK_FORMAT_UNDEFINED;  // the image format with BIND_DEPTH_STENCIL
  bool stencil = false;                    // depth-stencil: the stencil aspect too
};
// Whether a view of a `tex` texture may read or write it as `view`.
bool SameFamily(const FormatInfo& tex, const FormatInfo& view);
// The depth image format of a texture of format `f` with BIND_DEPTH_STENCIL
// (VK_FORMAT_UNDEFINED when `f` cannot be a depth-stencil texture).
VkFormat DepthImageFormat(const FormatInfo& f);
const FormatInfo* GetFormatInfo(DXGI_FORMAT f);  // nullptr when not in the table
VkFormat ToVkFormat(DXGI_FORMAT f);
VkCompareOp ToVkCompare(COMPARISON_FUNC f);

// Texels per row/column of a block (4 for BC formats).
inline uint32_t BlockDim(const FormatInfo& f) { return f.bc ? 4 : 1; }

// A w x h region of texels packed in a buffer: bytes per row and rows (rows
// of 4x4 blocks for BC formats).
struct LinearSize {
  uint32_t rowPitch;
  uint32_t rows;
};
inline LinearSize LinearLayout(const FormatInfo& f, uint32_t w, uint32_t h) {
  const uint32_t b = BlockDim(f);
  return {(w + b - 1) / b * f.bytes, (h + b - 1) / b};
}

}  // namespace d3dl::impl
