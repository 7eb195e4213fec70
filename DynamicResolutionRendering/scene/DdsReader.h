// DDS files (DirectDraw Surface): the DX9 header with its pixel format
// (FourCC DXT1..DXT5, ATI1/ATI2, BC4U/BC4S/BC5U/BC5S; RGBA, BGRA and BGRX
// masks; luminance L8 and A8L8) and the DX10 extension header (DXGI format,
// resource dimension, array size). 2D textures with all their mips; cube
// maps, volumes and arrays are rejected (the original's media has none).
// Every size, count and mip offset is checked against the file's size before
// use; errors name the file and the offending value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/TextureLoader.h"

namespace drr {

struct DdsImage {
  // BC1..BC5 (UNORM, SNORM or SRGB as the file says): the file's blocks as
  // they are; every plain format is expanded to R8G8B8A8_UNORM (_SRGB when a
  // DX10 header says so).
  d3dl::DXGI_FORMAT format = d3dl::DXGI_FORMAT_UNKNOWN;
  std::vector<TextureMip> mips;  // mips[0] full size; bytes in `format`
  std::string pixelFormat;       // what the header named, for messages ("DXT1", "BGRA8", "DX10 BC3_UNORM")
};

// Whether the bytes start with the DDS magic ("DDS ").
bool IsDdsData(const uint8_t* data, size_t size);

// Parses a DDS file held in memory; `name` (the file) starts every error.
// Sides above maxDimension are rejected before anything is allocated.
bool ReadDds(const uint8_t* data, size_t size, const std::string& name, uint32_t maxDimension, DdsImage* out,
             std::string* error);

// Reads and parses a DDS file.
bool ReadDdsFile(const std::string& path, uint32_t maxDimension, DdsImage* out, std::string* error);

// The image as texture data of `kind` (DdsTexture.cpp). Diffuse maps take the
// sRGB form of the file's format, normal and specular maps the format as it
// is, as the original's DXUT loader does; the file's mips are kept, except
// that a single-mip RGBA8 image gets the box-filtered chain when
// opts.generateMips (as the original's D3DX loader builds one).
void TextureFromDds(DdsImage image, const std::string& name, TextureKind kind, const TextureLoadOptions& opts,
                    TextureData* out);

}  // namespace drr
