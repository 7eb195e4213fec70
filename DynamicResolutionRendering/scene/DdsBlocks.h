// Sizes of texture data by DXGI format (RGBA8 texels or 4x4 blocks) and the
// CPU decoder of the block-compressed formats BC1..BC5, used where the device
// cannot sample them (the loader then expands them to RGBA8) and by the tests
// as the reference for what the GPU samples.
#pragma once

#include <cstdint>
#include <vector>

#include "d3dl/Types.h"

namespace drr {

// Bytes of one 4x4 block of a BC format (8 for BC1/BC4, 16 for BC2/BC3/BC5);
// 0 when `format` is not one of them.
uint32_t BcBlockBytes(d3dl::DXGI_FORMAT format);
// Whether textures of `format` can hold loaded texture data (RGBA8 or BC1..BC5).
bool IsTextureDataFormat(d3dl::DXGI_FORMAT format);
// The DXGI name without its prefix ("BC1_UNORM_SRGB") of a texture data format
// or of B8G8R8A8_UNORM(_SRGB); "?" for others. (The scene's CPU side does
// not link the RHI, whose FormatName covers every format.)
const char* TextureFormatName(d3dl::DXGI_FORMAT format);
// Bytes per row of texels (RGBA8) or of 4x4 blocks (BC) of a mip `width` wide.
uint64_t TextureRowPitch(d3dl::DXGI_FORMAT format, uint32_t width);
// Bytes of a width x height mip (whole blocks for BC); 0 for other formats.
uint64_t TextureMipBytes(d3dl::DXGI_FORMAT format, uint32_t width, uint32_t height);

// Decodes a width x height mip of BC1..BC5 (UNORM or SRGB: the stored values,
// no colour-space conversion) into RGBA8, rows top to bottom, as a D3D11
// device samples it: BC4 gives (r, 0, 0, 255), BC5 (r, g, 0, 255). `blocks`
// holds TextureMipBytes(format, width, height) bytes. Returns false for a
// format it does not decode (SNORM BC4/BC5, non-BC formats).
bool DecodeBcMip(d3dl::DXGI_FORMAT format, const uint8_t* blocks, uint32_t width, uint32_t height,
                 std::vector<uint8_t>* rgba);

}  // namespace drr
