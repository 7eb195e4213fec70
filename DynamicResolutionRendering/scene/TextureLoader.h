// Texture files through ImageFile.h (OpenImageIO: PNG, JPG, TGA, EXR, HDR, BMP, TIFF...)
// into RGBA8 with a full, CPU box-filtered mip chain. Colour data (diffuse) is
// R8G8B8A8_UNORM_SRGB and filtered in linear light; normal and specular maps
// are R8G8B8A8_UNORM (normals are renormalised per mip). DDS files go through
// DdsReader.h instead: block-compressed data (BC1..BC5) stays compressed with
// the file's own mips, in the sRGB form for diffuse maps as the original's
// DXUT loader gives it (Docs/Port-Notes.md, "Texture colour spaces").
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "d3dl/Types.h"

namespace drr {

enum class TextureKind { Color, Normal, Specular };
const char* TextureKindName(TextureKind k);

struct TextureMip {
  uint32_t width = 0, height = 0;
  // The texels in the texture's format, rows top to bottom: width * height * 4
  // bytes of RGBA8, or whole 4x4 blocks for BC formats (DdsBlocks.h).
  std::vector<uint8_t> rgba;
};

struct TextureData {
  std::string source;  // file (or "<fallback ...>", "<embedded ...>")
  TextureKind kind = TextureKind::Color;
  d3dl::DXGI_FORMAT format = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
  std::vector<TextureMip> mips;  // mips[0] is the full size
  bool hasAlpha = false;         // some texel has alpha < 255
  bool mipsFromFile = false;     // the file's own mip chain (DDS): kept as it is
  uint64_t Bytes() const;
  uint64_t BytesAsRgba8() const;  // the same mips expanded to RGBA8
  uint32_t Width() const { return mips.empty() ? 0 : mips[0].width; }
  uint32_t Height() const { return mips.empty() ? 0 : mips[0].height; }
};

struct TextureLoadOptions {
  uint32_t maxDimension = 16384;  // larger images are rejected
  bool generateMips = true;
};

d3dl::DXGI_FORMAT TextureFormatFor(TextureKind k);

// Loads a file. On failure returns false and error names the file and why
// (missing, zero size, unsupported format, too large, decode error).
bool LoadTextureFile(const std::string& path, TextureKind kind, const TextureLoadOptions& opts,
                     TextureData* out, std::string* error);
// Decodes an image held in memory (an embedded texture); formatHint is an
// extension such as "png" or "jpg".
bool LoadTextureMemory(const void* data, size_t size, const std::string& formatHint, const std::string& name,
                       TextureKind kind, const TextureLoadOptions& opts, TextureData* out, std::string* error);
// From RGBA8 texels already in memory (top row first).
bool MakeTextureRGBA8(const uint8_t* rgba, uint32_t width, uint32_t height, const std::string& name,
                      TextureKind kind, const TextureLoadOptions& opts, TextureData* out, std::string* error);

// 1x1 fallbacks: white (colour), flat normal (0.5,0.5,1), black (specular).
TextureData FallbackTexture(TextureKind kind);

// Replaces mips[1..] by a box-filtered chain down to 1x1 from mips[0]
// (RGBA8 textures whose mips did not come from their file; others unchanged).
void GenerateMipChain(TextureData* tex);

// Block-compressed texture data expanded to RGBA8 by the CPU decoder, in the
// same colour space (BC1_UNORM_SRGB becomes R8G8B8A8_UNORM_SRGB); an RGBA8
// texture is copied as it is. False (error names the texture) for formats the
// decoder does not handle (BC4/BC5 SNORM).
bool ExpandToRgba8(const TextureData& texture, TextureData* out, std::string* error);
// Whether DRR_BC_DECODE=cpu asks for the CPU decoder even where the device
// samples BC formats (to exercise the fallback on any device).
bool CpuBcDecodeForced();
// The texture as the device will sample it: `texture` itself, or its RGBA8
// expansion where it is block-compressed and the device cannot sample its
// format (deviceSamplesFormat false) or CpuBcDecodeForced(). nullptr with
// *error set when it cannot be expanded.
std::shared_ptr<const TextureData> TextureForDevice(const std::shared_ptr<const TextureData>& texture,
                                                    bool deviceSamplesFormat, std::string* error);

}  // namespace drr
