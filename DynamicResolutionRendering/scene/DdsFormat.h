// The DDS file layout (public format facts): the "DDS " magic, the 124-byte
// DDS_HEADER with its DDS_PIXELFORMAT, and the optional 20-byte DX10
// extension header. Shared by the reader (DdsReader.h) and the Arena
// generator's writer (tools/ArenaGenDds.cpp), so both use one set of offsets.
#pragma once

#include <cstdint>

namespace drr::dds {

inline constexpr uint32_t kMagic = 0x20534444;  // "DDS "
inline constexpr uint32_t kHeaderSize = 124;    // DDS_HEADER.dwSize
inline constexpr uint32_t kPixelFormatSize = 32;
inline constexpr uint32_t kDx10HeaderSize = 20;
inline constexpr uint32_t kDataOffset = 4 + kHeaderSize;  // first byte after the DX9 header

// Byte offsets of the DDS_HEADER fields, counted from the start of the file.
inline constexpr uint32_t kOffSize = 4, kOffFlags = 8, kOffHeight = 12, kOffWidth = 16, kOffPitch = 20,
                          kOffDepth = 24, kOffMipCount = 28, kOffPixelFormat = 76, kOffCaps = 108,
                          kOffCaps2 = 112;
// Offsets inside DDS_PIXELFORMAT.
inline constexpr uint32_t kPfSize = 0, kPfFlags = 4, kPfFourCC = 8, kPfBitCount = 12, kPfRMask = 16,
                          kPfGMask = 20, kPfBMask = 24, kPfAMask = 28;
// Offsets inside the DX10 header (DDS_HEADER_DXT10).
inline constexpr uint32_t kDx10Format = 0, kDx10Dimension = 4, kDx10MiscFlag = 8, kDx10ArraySize = 12;

// DDS_HEADER.dwFlags
inline constexpr uint32_t kFlagCaps = 0x1, kFlagHeight = 0x2, kFlagWidth = 0x4, kFlagPitch = 0x8,
                          kFlagPixelFormat = 0x1000, kFlagMipCount = 0x20000, kFlagLinearSize = 0x80000,
                          kFlagDepth = 0x800000;
// DDS_PIXELFORMAT.dwFlags
inline constexpr uint32_t kPfAlphaPixels = 0x1, kPfFourCCFlag = 0x4, kPfRgb = 0x40, kPfLuminance = 0x20000;
// dwCaps / dwCaps2
inline constexpr uint32_t kCapsComplex = 0x8, kCapsTexture = 0x1000, kCapsMipmap = 0x400000;
inline constexpr uint32_t kCaps2Cubemap = 0x200, kCaps2Volume = 0x200000;
// DX10 header: resource dimension and misc flag
inline constexpr uint32_t kDimensionTexture2D = 3, kMiscTextureCube = 0x4;

constexpr uint32_t FourCC(char a, char b, char c, char d) {
  return uint32_t(uint8_t(a)) | uint32_t(uint8_t(b)) << 8 | uint32_t(uint8_t(c)) << 16 | uint32_t(uint8_t(d)) << 24;
}

}  // namespace drr::dds
