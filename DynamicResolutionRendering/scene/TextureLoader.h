// Texture files through ImageFile.h (OpenImageIO: PNG, JPG, TGA, DDS, EXR, HDR, BMP, TIFF...;
// into RGBA8 with a full, CPU box-filtered mip chain. Colour data (diffuse) is
// R8G8B8A8_UNORM_SRGB and filtered in linear light; normal and specular maps
// are R8G8B8A8_UNORM (normals are renormalised per mip).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "d3dl/Types.h"

namespace drr {

enum class TextureKind { Color, Normal, Specular };
const char* TextureKindName(TextureKind k);

struct TextureMip {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4, rows top to bottom
};

struct TextureData {
  std::string source;  // file (or "<fallback ...>", "<embedded ...>")
  TextureKind kind = TextureKind::Color;
  d3dl::DXGI_FORMAT format = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
  std::vector<TextureMip> mips;  // mips[0] is the full size
  bool hasAlpha = false;         // some texel has alpha < 255
  uint64_t Bytes() const;
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

// Replaces mips[1..] by a box-filtered chain down to 1x1 from mips[0].
void GenerateMipChain(TextureData* tex);

}  // namespace drr
