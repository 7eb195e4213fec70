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
};
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
