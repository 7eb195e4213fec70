#include "ArenaGenDds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "scene/DdsFormat.h"

namespace arena {
namespace {
namespace fs = std::filesystem;
namespace dds = drr::dds;

constexpr uint32_t kDxgiBc1Unorm = 71;  // DXGI_FORMAT_BC1_UNORM (the DX10 header's format field)

struct Rgba8Image {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> texels;  // RGBA8, rows top to bottom
  const uint8_t* At(uint32_t x, uint32_t y) const {
    return &texels[(size_t(std::min(y, height - 1)) * width + std::min(x, width - 1)) * 4];
  }
};

// A colourful pattern with an alpha ramp, different at every mip so that a
// wrong mip is visible.
Rgba8Image Pattern(uint32_t w, uint32_t h, uint32_t variant) {
  Rgba8Image img{w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      uint8_t* p = &img.texels[(size_t(y) * w + x) * 4];
      const float u = (x + 0.5f) / w, v = (y + 0.5f) / h;
      p[0] = uint8_t(255 * u);
      p[1] = uint8_t(255 * (0.5f + 0.5f * std::sin(6.2832f * (v + 0.17f * variant))));
      p[2] = uint8_t(((x / 2 + y / 2 + variant) % 2) ? 230 : 40);
      p[3] = uint8_t(255 * std::min(1.f, 0.2f + v));
    }
  return img;
}

uint16_t To565(const uint8_t* c) { return uint16_t((c[0] >> 3) << 11 | (c[1] >> 2) << 5 | (c[2] >> 3)); }

std::array<int, 3> From565(uint16_t c) {
  const int r = c >> 11, g = (c >> 5) & 63, b = c & 31;
  return {r << 3 | r >> 2, g << 2 | g >> 4, b << 3 | b >> 2};
}

void Put16(std::vector<uint8_t>* out, uint16_t v) { out->push_back(uint8_t(v)), out->push_back(uint8_t(v >> 8)); }

// Four-colour BC1 block: endpoints the block's per-channel max and min,
// each texel the nearest of the four palette colours.
void EncodeColourBlock(const Rgba8Image& img, uint32_t bx, uint32_t by, std::vector<uint8_t>* out) {
  uint8_t lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
  for (uint32_t i = 0; i < 16; ++i) {
    const uint8_t* p = img.At(bx * 4 + i % 4, by * 4 + i / 4);
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
  }
  uint16_t c0 = To565(hi), c1 = To565(lo);
  if (c0 < c1) std::swap(c0, c1);
  uint32_t indices = 0;
  if (c0 != c1) {
    const auto e0 = From565(c0), e1 = From565(c1);
    std::array<std::array<int, 3>, 4> pal;
    for (int c = 0; c < 3; ++c)
      pal[0][c] = e0[c], pal[1][c] = e1[c], pal[2][c] = (2 * e0[c] + e1[c]) / 3, pal[3][c] = (e0[c] + 2 * e1[c]) / 3;
    for (uint32_t i = 0; i < 16; ++i) {
      const uint8_t* p = img.At(bx * 4 + i % 4, by * 4 + i / 4);
      int best = 0, bestDist = 1 << 30;
      for (int k = 0; k < 4; ++k) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d += (p[c] - pal[k][c]) * (p[c] - pal[k][c]);
        if (d < bestDist) best = k, bestDist = d;
      }
      indices |= uint32_t(best) << (2 * i);
    }
  }
  Put16(out, c0), Put16(out, c1);
  for (int i = 0; i < 4; ++i) out->push_back(uint8_t(indices >> (8 * i)));
}

// BC3 alpha block: endpoints max and min (eight-value mode), nearest index.
void EncodeAlphaBlock(const Rgba8Image& img, uint32_t bx, uint32_t by, std::vector<uint8_t>* out) {
  int lo = 255, hi = 0;
  for (uint32_t i = 0; i < 16; ++i) {
    const int a = img.At(bx * 4 + i % 4, by * 4 + i / 4)[3];
    lo = std::min(lo, a), hi = std::max(hi, a);
  }
  std::array<int, 8> pal{hi, lo};
  for (int i = 1; i <= 6; ++i) pal[i + 1] = ((7 - i) * hi + i * lo) / 7;
  uint64_t indices = 0;
  for (uint32_t i = 0; i < 16 && hi != lo; ++i) {
    const int a = img.At(bx * 4 + i % 4, by * 4 + i / 4)[3];
    int best = 0;
    for (int k = 1; k < 8; ++k)
      if (std::abs(a - pal[k]) < std::abs(a - pal[best])) best = k;
    indices |= uint64_t(best) << (3 * i);
  }
  out->push_back(uint8_t(hi)), out->push_back(uint8_t(lo));
  for (int i = 0; i < 6; ++i) out->push_back(uint8_t(indices >> (8 * i)));
}

std::vector<uint8_t> EncodeMip(const Rgba8Image& img, bool withAlpha) {
  std::vector<uint8_t> out;
  for (uint32_t by = 0; by < (img.height + 3) / 4; ++by)
    for (uint32_t bx = 0; bx < (img.width + 3) / 4; ++bx) {
      if (withAlpha) EncodeAlphaBlock(img, bx, by, &out);
      EncodeColourBlock(img, bx, by, &out);
    }
  return out;
}

void Put32(std::vector<uint8_t>* f, uint32_t offset, uint32_t v) { std::memcpy(f->data() + offset, &v, 4); }

struct DdsSpec {
  const char* file;
  uint32_t width, height, mips;
  enum { Bc1, Bc3, Rgba8, Bc1Dx10 } kind;
};

// Header (and DX10 header) of a 2D texture.
std::vector<uint8_t> Header(const DdsSpec& s) {
  std::vector<uint8_t> f(dds::kDataOffset + (s.kind == DdsSpec::Bc1Dx10 ? dds::kDx10HeaderSize : 0));
  const bool bc = s.kind != DdsSpec::Rgba8;
  Put32(&f, 0, dds::kMagic);
  Put32(&f, dds::kOffSize, dds::kHeaderSize);
  Put32(&f, dds::kOffFlags, dds::kFlagCaps | dds::kFlagHeight | dds::kFlagWidth | dds::kFlagPixelFormat |
                                (s.mips > 1 ? dds::kFlagMipCount : 0) | (bc ? dds::kFlagLinearSize : dds::kFlagPitch));
  Put32(&f, dds::kOffHeight, s.height), Put32(&f, dds::kOffWidth, s.width);
  const uint32_t blockBytes = s.kind == DdsSpec::Bc3 ? 16 : 8;  // the top mip's size (BC) or row pitch
  Put32(&f, dds::kOffPitch, bc ? std::max(1u, (s.width + 3) / 4) * std::max(1u, (s.height + 3) / 4) * blockBytes
                               : s.width * 4);
  Put32(&f, dds::kOffMipCount, s.mips);
  const uint32_t pf = dds::kOffPixelFormat;
  Put32(&f, pf + dds::kPfSize, dds::kPixelFormatSize);
  if (s.kind == DdsSpec::Rgba8) {
    Put32(&f, pf + dds::kPfFlags, dds::kPfRgb | dds::kPfAlphaPixels);
    Put32(&f, pf + dds::kPfBitCount, 32);
    Put32(&f, pf + dds::kPfRMask, 0xff), Put32(&f, pf + dds::kPfGMask, 0xff00);
    Put32(&f, pf + dds::kPfBMask, 0xff0000), Put32(&f, pf + dds::kPfAMask, 0xff000000u);
  } else {
    Put32(&f, pf + dds::kPfFlags, dds::kPfFourCCFlag);
    Put32(&f, pf + dds::kPfFourCC, s.kind == DdsSpec::Bc1   ? dds::FourCC('D', 'X', 'T', '1')
                                   : s.kind == DdsSpec::Bc3 ? dds::FourCC('D', 'X', 'T', '5')
                                                            : dds::FourCC('D', 'X', '1', '0'));
  }
  Put32(&f, dds::kOffCaps, dds::kCapsTexture | (s.mips > 1 ? dds::kCapsComplex | dds::kCapsMipmap : 0));
  if (s.kind == DdsSpec::Bc1Dx10) {
    Put32(&f, dds::kDataOffset + dds::kDx10Format, kDxgiBc1Unorm);
    Put32(&f, dds::kDataOffset + dds::kDx10Dimension, dds::kDimensionTexture2D);
    Put32(&f, dds::kDataOffset + dds::kDx10ArraySize, 1);
  }
  return f;
}

std::vector<uint8_t> BuildDds(const DdsSpec& s) {
  std::vector<uint8_t> f = Header(s);
  for (uint32_t m = 0; m < s.mips; ++m) {
    const Rgba8Image img = Pattern(std::max(1u, s.width >> m), std::max(1u, s.height >> m), m);
    const std::vector<uint8_t> data = s.kind == DdsSpec::Rgba8 ? img.texels : EncodeMip(img, s.kind == DdsSpec::Bc3);
    f.insert(f.end(), data.begin(), data.end());
  }
  return f;
}

}  // namespace

int WriteArenaDdsSet(const std::string& outDir) {
  static const DdsSpec specs[] = {{"bc1_mips.dds", 64, 32, 7, DdsSpec::Bc1},
                                  {"bc3_mips.dds", 32, 32, 6, DdsSpec::Bc3},
                                  {"rgba8.dds", 16, 8, 1, DdsSpec::Rgba8},
                                  {"bc1_dx10.dds", 16, 16, 5, DdsSpec::Bc1Dx10}};
  const fs::path dir = fs::path(outDir) / "dds";
  std::error_code ec;
  fs::create_directories(dir, ec);
  for (const DdsSpec& s : specs) {
    const std::vector<uint8_t> bytes = BuildDds(s);
    const fs::path path = dir / s.file;
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    f.close();
    if (ec || !f) {
      fprintf(stderr, "drr_arenagen: cannot write %s\n", path.string().c_str());
      return 1;
    }
  }
  return 0;
}

}  // namespace arena
