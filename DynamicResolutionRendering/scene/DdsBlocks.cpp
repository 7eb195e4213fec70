#include "scene/DdsBlocks.h"

#include <algorithm>
#include <array>

namespace drr {
using namespace d3dl;

uint32_t BcBlockBytes(DXGI_FORMAT format) {
  switch (format) {
    case DXGI_FORMAT_BC1_UNORM: case DXGI_FORMAT_BC1_UNORM_SRGB:
    case DXGI_FORMAT_BC4_UNORM: case DXGI_FORMAT_BC4_SNORM:
      return 8;
    case DXGI_FORMAT_BC2_UNORM: case DXGI_FORMAT_BC2_UNORM_SRGB:
    case DXGI_FORMAT_BC3_UNORM: case DXGI_FORMAT_BC3_UNORM_SRGB:
    case DXGI_FORMAT_BC5_UNORM: case DXGI_FORMAT_BC5_SNORM:
      return 16;
    default: return 0;
  }
}

bool IsTextureDataFormat(DXGI_FORMAT format) {
  return BcBlockBytes(format) != 0 || format == DXGI_FORMAT_R8G8B8A8_UNORM ||
         format == DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
}

const char* TextureFormatName(DXGI_FORMAT format) {
  switch (format) {
    case DXGI_FORMAT_R8G8B8A8_UNORM: return "R8G8B8A8_UNORM";
    case DXGI_FORMAT_R8G8B8A8_UNORM_SRGB: return "R8G8B8A8_UNORM_SRGB";
    case DXGI_FORMAT_B8G8R8A8_UNORM: return "B8G8R8A8_UNORM";
    case DXGI_FORMAT_B8G8R8A8_UNORM_SRGB: return "B8G8R8A8_UNORM_SRGB";
    case DXGI_FORMAT_BC1_UNORM: return "BC1_UNORM";
    case DXGI_FORMAT_BC1_UNORM_SRGB: return "BC1_UNORM_SRGB";
    case DXGI_FORMAT_BC2_UNORM: return "BC2_UNORM";
    case DXGI_FORMAT_BC2_UNORM_SRGB: return "BC2_UNORM_SRGB";
    case DXGI_FORMAT_BC3_UNORM: return "BC3_UNORM";
    case DXGI_FORMAT_BC3_UNORM_SRGB: return "BC3_UNORM_SRGB";
    case DXGI_FORMAT_BC4_UNORM: return "BC4_UNORM";
    case DXGI_FORMAT_BC4_SNORM: return "BC4_SNORM";
    case DXGI_FORMAT_BC5_UNORM: return "BC5_UNORM";
    case DXGI_FORMAT_BC5_SNORM: return "BC5_SNORM";
    default: return "?";
  }
}

uint64_t TextureRowPitch(DXGI_FORMAT format, uint32_t width) {
  if (const uint32_t b = BcBlockBytes(format)) return uint64_t(std::max(1u, (width + 3) / 4)) * b;
  return IsTextureDataFormat(format) ? uint64_t(width) * 4 : 0;
}

uint64_t TextureMipBytes(DXGI_FORMAT format, uint32_t width, uint32_t height) {
  const uint64_t rows = BcBlockBytes(format) ? std::max(1u, (height + 3) / 4) : height;
  return TextureRowPitch(format, width) * rows;
}

namespace {

using Texels = std::array<std::array<uint8_t, 4>, 16>;  // one block, row by row

uint16_t Read16(const uint8_t* p) { return uint16_t(p[0] | p[1] << 8); }

std::array<uint8_t, 3> Expand565(uint16_t c) {
  const uint32_t r = c >> 11, g = (c >> 5) & 63, b = c & 31;
  return {uint8_t(r << 3 | r >> 2), uint8_t(g << 2 | g >> 4), uint8_t(b << 3 | b >> 2)};
}

// (a * wa + b * wb) / (wa + wb), rounded to nearest.
uint8_t Mix(uint32_t a, uint32_t wa, uint32_t b, uint32_t wb) {
  return uint8_t((a * wa + b * wb + (wa + wb) / 2) / (wa + wb));
}

// The colour half of a block (BC1, and BC2/BC3 where it always has four colours).
void DecodeColour(const uint8_t* p, bool bc1, Texels* out) {
  const uint16_t c0 = Read16(p), c1 = Read16(p + 2);
  const auto e0 = Expand565(c0), e1 = Expand565(c1);
  std::array<std::array<uint8_t, 4>, 4> pal{};
  const bool four = !bc1 || c0 > c1;
  for (int c = 0; c < 3; ++c) {
    pal[0][c] = e0[c];
    pal[1][c] = e1[c];
    pal[2][c] = four ? Mix(e0[c], 2, e1[c], 1) : Mix(e0[c], 1, e1[c], 1);
    pal[3][c] = four ? Mix(e0[c], 1, e1[c], 2) : 0;
  }
  pal[0][3] = pal[1][3] = pal[2][3] = 255;
  pal[3][3] = four ? 255 : 0;
  const uint32_t bits = uint32_t(p[4]) | uint32_t(p[5]) << 8 | uint32_t(p[6]) << 16 | uint32_t(p[7]) << 24;
  for (int i = 0; i < 16; ++i) (*out)[i] = pal[(bits >> (2 * i)) & 3];
}

// An 8-byte interpolated channel (BC3 alpha, BC4/BC5 channels): two
// endpoints and sixteen 3-bit indices.
std::array<uint8_t, 16> DecodeChannel(const uint8_t* p) {
  const uint32_t a0 = p[0], a1 = p[1];
  std::array<uint8_t, 8> pal{uint8_t(a0), uint8_t(a1)};
  if (a0 > a1) {
    for (uint32_t i = 1; i <= 6; ++i) pal[i + 1] = Mix(a0, 7 - i, a1, i);
  } else {
    for (uint32_t i = 1; i <= 4; ++i) pal[i + 1] = Mix(a0, 5 - i, a1, i);
    pal[6] = 0;
    pal[7] = 255;
  }
  uint64_t bits = 0;
  for (int i = 0; i < 6; ++i) bits |= uint64_t(p[2 + i]) << (8 * i);
  std::array<uint8_t, 16> out{};
  for (int i = 0; i < 16; ++i) out[i] = pal[(bits >> (3 * i)) & 7];
  return out;
}

bool DecodeBlock(DXGI_FORMAT format, const uint8_t* p, Texels* t) {
  switch (d3dl::FormatLinearOf(format)) {
    case DXGI_FORMAT_BC1_UNORM: DecodeColour(p, true, t); return true;
    case DXGI_FORMAT_BC2_UNORM:
      DecodeColour(p + 8, false, t);
      for (int i = 0; i < 16; ++i) (*t)[i][3] = uint8_t(((p[i / 2] >> (4 * (i % 2))) & 15) * 17);
      return true;
    case DXGI_FORMAT_BC3_UNORM: {
      DecodeColour(p + 8, false, t);
      const auto a = DecodeChannel(p);
      for (int i = 0; i < 16; ++i) (*t)[i][3] = a[i];
      return true;
    }
    case DXGI_FORMAT_BC4_UNORM: {
      const auto r = DecodeChannel(p);
      for (int i = 0; i < 16; ++i) (*t)[i] = {r[i], 0, 0, 255};
      return true;
    }
    case DXGI_FORMAT_BC5_UNORM: {
      const auto r = DecodeChannel(p), g = DecodeChannel(p + 8);
      for (int i = 0; i < 16; ++i) (*t)[i] = {r[i], g[i], 0, 255};
      return true;
    }
    default: return false;
  }
}

}  // namespace

bool DecodeBcMip(DXGI_FORMAT format, const uint8_t* blocks, uint32_t width, uint32_t height,
                 std::vector<uint8_t>* rgba) {
  const uint32_t blockBytes = BcBlockBytes(format);
  if (!blockBytes || width == 0 || height == 0) return false;
  const uint32_t bw = (width + 3) / 4, bh = (height + 3) / 4;
  rgba->assign(size_t(width) * height * 4, 0);
  Texels t{};
  for (uint32_t by = 0; by < bh; ++by)
    for (uint32_t bx = 0; bx < bw; ++bx) {
      if (!DecodeBlock(format, blocks + (size_t(by) * bw + bx) * blockBytes, &t)) return false;
      for (uint32_t i = 0; i < 16; ++i) {
        const uint32_t x = bx * 4 + i % 4, y = by * 4 + i / 4;
        if (x < width && y < height) std::copy(t[i].begin(), t[i].end(), &(*rgba)[(size_t(y) * width + x) * 4]);
      }
    }
  return true;
}

}  // namespace drr
