// The Arena's small DDS set, for the DDS reader and BC sampling tests (none of
// the scene's materials use it): under <out>/dds/
//   bc1_mips.dds   64x32 BC1 (FourCC DXT1), full mip chain down to 1x1
//   bc3_mips.dds   32x32 BC3 (FourCC DXT5) with an alpha gradient, full chain
//   rgba8.dds      16x8 RGBA8 through DX9 RGB masks, one mip
//   bc1_dx10.dds   16x16 BC1_UNORM through the DX10 extension header, full chain
// The blocks come from a simple encoder of its own (per-channel bounding box
// endpoints, nearest-palette indices).
#pragma once

#include <string>

namespace arena {

// 0 on success; otherwise prints what failed to stderr and returns 1.
int WriteArenaDdsSet(const std::string& outDir);

}  // namespace arena
