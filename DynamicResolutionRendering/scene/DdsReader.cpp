#include "scene/DdsReader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/DdsBlocks.h"
#include "scene/DdsFormat.h"

namespace drr {
using namespace d3dl;

namespace {

uint32_t U32At(const uint8_t* data, size_t offset) {
  uint32_t v;
  std::memcpy(&v, data + offset, 4);
  return v;
}

std::string Hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof(buf), "0x%x", v);
  return buf;
}

std::string FourCCText(uint32_t f) {
  std::string s;
  for (int i = 0; i < 4; ++i) {
    const char c = char((f >> (8 * i)) & 0xff);
    s += (c >= 32 && c < 127) ? c : '?';
  }
  return s;
}

// How the texels of a plain (uncompressed) layout are stored.
enum class Plain { None, Rgba8, Rgbx8, Bgra8, Bgrx8, L8, A8L8 };

struct Layout {
  DXGI_FORMAT bc = DXGI_FORMAT_UNKNOWN;  // a BC format, or UNKNOWN for a plain layout
  Plain plain = Plain::None;
  bool srgb = false;  // a DX10 header naming an _SRGB format
  size_t dataOffset = dds::kDataOffset;
  std::string name;
};

uint32_t PlainBytes(Plain p) {
  switch (p) {
    case Plain::L8: return 1;
    case Plain::A8L8: return 2;
    case Plain::None: return 0;
    default: return 4;
  }
}

// DXT2 and DXT4 (premultiplied alpha) hold the blocks of DXT3 and DXT5; the
// texels are kept as stored, as a D3D11 loader does.
DXGI_FORMAT BcFromFourCC(uint32_t f) {
  using dds::FourCC;
  if (f == FourCC('D', 'X', 'T', '1')) return DXGI_FORMAT_BC1_UNORM;
  if (f == FourCC('D', 'X', 'T', '2') || f == FourCC('D', 'X', 'T', '3')) return DXGI_FORMAT_BC2_UNORM;
  if (f == FourCC('D', 'X', 'T', '4') || f == FourCC('D', 'X', 'T', '5')) return DXGI_FORMAT_BC3_UNORM;
  if (f == FourCC('A', 'T', 'I', '1') || f == FourCC('B', 'C', '4', 'U')) return DXGI_FORMAT_BC4_UNORM;
  if (f == FourCC('B', 'C', '4', 'S')) return DXGI_FORMAT_BC4_SNORM;
  if (f == FourCC('A', 'T', 'I', '2') || f == FourCC('B', 'C', '5', 'U')) return DXGI_FORMAT_BC5_UNORM;
  if (f == FourCC('B', 'C', '5', 'S')) return DXGI_FORMAT_BC5_SNORM;
  return DXGI_FORMAT_UNKNOWN;
}

// A DDS_PIXELFORMAT with RGB or luminance masks.
Plain PlainFromMasks(const uint8_t* pf) {
  const uint32_t flags = U32At(pf, dds::kPfFlags), bits = U32At(pf, dds::kPfBitCount);
  const uint32_t r = U32At(pf, dds::kPfRMask), g = U32At(pf, dds::kPfGMask), b = U32At(pf, dds::kPfBMask);
  const uint32_t a = (flags & dds::kPfAlphaPixels) ? U32At(pf, dds::kPfAMask) : 0;
  if (flags & dds::kPfRgb) {
    if (bits != 32 || g != 0xff00 || (a != 0 && a != 0xff000000u)) return Plain::None;
    if (r == 0xff && b == 0xff0000) return a ? Plain::Rgba8 : Plain::Rgbx8;
    if (r == 0xff0000 && b == 0xff) return a ? Plain::Bgra8 : Plain::Bgrx8;
    return Plain::None;
  }
  if (flags & dds::kPfLuminance) {
    if (bits == 8 && r == 0xff && !a) return Plain::L8;
    if (bits == 16 && r == 0xff && a == 0xff00) return Plain::A8L8;
  }
  return Plain::None;
}

bool Dx10Layout(const uint8_t* data, size_t size, const std::string& name, Layout* l, std::string* error) {
  if (size < dds::kDataOffset + dds::kDx10HeaderSize) {
    *error = name + ": truncated DDS file (" + std::to_string(size) + " bytes; the DX10 header needs " +
             std::to_string(dds::kDataOffset + dds::kDx10HeaderSize) + ")";
    return false;
  }
  const uint8_t* h = data + dds::kDataOffset;
  const uint32_t format = U32At(h, dds::kDx10Format), dim = U32At(h, dds::kDx10Dimension);
  const uint32_t misc = U32At(h, dds::kDx10MiscFlag), arraySize = U32At(h, dds::kDx10ArraySize);
  if (dim != dds::kDimensionTexture2D || (misc & dds::kMiscTextureCube) || arraySize != 1) {
    *error = name + ": DX10 header describes an unsupported resource (dimension " + std::to_string(dim) +
             ", misc flags " + Hex(misc) + ", array size " + std::to_string(arraySize) +
             "); only single 2D textures are supported";
    return false;
  }
  const auto f = DXGI_FORMAT(format);
  l->dataOffset += dds::kDx10HeaderSize;
  l->srgb = FormatIsSrgb(f);
  if (FormatLinearOf(f) == DXGI_FORMAT_R8G8B8A8_UNORM) {
    l->plain = Plain::Rgba8;
  } else if (FormatLinearOf(f) == DXGI_FORMAT_B8G8R8A8_UNORM) {
    l->plain = Plain::Bgra8;
  } else if (BcBlockBytes(f)) {
    l->bc = f;
  } else {
    *error = name + ": DX10 header names DXGI format " + std::to_string(format) + ", which is not supported";
    return false;
  }
  l->name = std::string("DX10 ") + TextureFormatName(f);
  return true;
}

bool PixelLayout(const uint8_t* data, size_t size, const std::string& name, Layout* l, std::string* error) {
  const uint8_t* pf = data + dds::kOffPixelFormat;
  const uint32_t flags = U32At(pf, dds::kPfFlags), fourCC = U32At(pf, dds::kPfFourCC);
  if (flags & dds::kPfFourCCFlag) {
    if (fourCC == dds::FourCC('D', 'X', '1', '0')) return Dx10Layout(data, size, name, l, error);
    l->bc = BcFromFourCC(fourCC);
    l->name = FourCCText(fourCC);
  } else {
    l->plain = PlainFromMasks(pf);
    static const char* names[] = {"", "RGBA8", "RGBX8", "BGRA8", "BGRX8", "L8", "A8L8"};
    l->name = names[int(l->plain)];
  }
  if (l->bc == DXGI_FORMAT_UNKNOWN && l->plain == Plain::None) {
    *error = name + ": unsupported DDS pixel format (flags " + Hex(flags) + ", FourCC '" + FourCCText(fourCC) +
             "', " + std::to_string(U32At(pf, dds::kPfBitCount)) + " bits, masks " +
             Hex(U32At(pf, dds::kPfRMask)) + "/" + Hex(U32At(pf, dds::kPfGMask)) + "/" +
             Hex(U32At(pf, dds::kPfBMask)) + "/" + Hex(U32At(pf, dds::kPfAMask)) + ")";
    return false;
  }
  return true;
}

uint32_t FullChainLength(uint32_t w, uint32_t h) {
  uint32_t n = 1;
  for (uint32_t s = std::max(w, h); s > 1; s >>= 1) ++n;
  return n;
}

// The header's sizes and mip count, checked.
bool HeaderSizes(const uint8_t* data, const std::string& name, uint32_t maxDimension, uint32_t* w, uint32_t* h,
                 uint32_t* mips, std::string* error) {
  *w = U32At(data, dds::kOffWidth), *h = U32At(data, dds::kOffHeight);
  const uint32_t caps2 = U32At(data, dds::kOffCaps2), flags = U32At(data, dds::kOffFlags);
  const bool volume = (flags & dds::kFlagDepth) && U32At(data, dds::kOffDepth) > 1;
  if ((caps2 & (dds::kCaps2Cubemap | dds::kCaps2Volume)) || volume) {
    *error = name + ": cube maps and volume textures are not supported (caps2 " + Hex(caps2) + ")";
    return false;
  }
  if (*w == 0 || *h == 0 || *w > maxDimension || *h > maxDimension) {
    *error = name + ": DDS size " + std::to_string(*w) + "x" + std::to_string(*h) + " is out of range (1.." +
             std::to_string(maxDimension) + " per side)";
    return false;
  }
  const uint32_t count = U32At(data, dds::kOffMipCount), full = FullChainLength(*w, *h);
  *mips = std::max(1u, count);
  if (*mips > full) {
    *error = name + ": DDS mip count " + std::to_string(count) + " exceeds the " + std::to_string(full) +
             " levels of a " + std::to_string(*w) + "x" + std::to_string(*h) + " texture";
    return false;
  }
  return true;
}

// One plain-layout mip expanded to RGBA8.
void ExpandPlain(Plain p, const uint8_t* src, size_t texels, std::vector<uint8_t>* rgba) {
  rgba->resize(texels * 4);
  uint8_t* d = rgba->data();
  for (size_t i = 0; i < texels; ++i, d += 4) {
    switch (p) {
      case Plain::Rgba8: std::memcpy(d, src + i * 4, 4); break;
      case Plain::Rgbx8: std::memcpy(d, src + i * 4, 3), d[3] = 255; break;
      case Plain::Bgra8: case Plain::Bgrx8:
        d[0] = src[i * 4 + 2], d[1] = src[i * 4 + 1], d[2] = src[i * 4];
        d[3] = p == Plain::Bgra8 ? src[i * 4 + 3] : 255;
        break;
      case Plain::L8: d[0] = d[1] = d[2] = src[i], d[3] = 255; break;
      case Plain::A8L8: d[0] = d[1] = d[2] = src[i * 2], d[3] = src[i * 2 + 1]; break;
      case Plain::None: break;
    }
  }
}

bool ReadMips(const uint8_t* data, size_t size, const std::string& name, const Layout& l, uint32_t w, uint32_t h,
              uint32_t count, DdsImage* out, std::string* error) {
  uint64_t offset = l.dataOffset;
  for (uint32_t i = 0; i < count; ++i) {
    TextureMip m;
    m.width = std::max(1u, w >> i), m.height = std::max(1u, h >> i);
    const uint64_t bytes = l.bc ? TextureMipBytes(l.bc, m.width, m.height)
                                : uint64_t(m.width) * m.height * PlainBytes(l.plain);
    if (offset > size || bytes > size - offset) {
      *error = name + ": truncated DDS file: mip " + std::to_string(i) + " (" + std::to_string(m.width) + "x" +
               std::to_string(m.height) + ", " + std::to_string(bytes) + " bytes at offset " +
               std::to_string(offset) + ") runs past the end of the file (" + std::to_string(size) + " bytes)";
      return false;
    }
    if (l.bc) m.rgba.assign(data + offset, data + offset + bytes);
    else ExpandPlain(l.plain, data + offset, size_t(m.width) * m.height, &m.rgba);
    offset += bytes;
    out->mips.push_back(std::move(m));
  }
  return true;
}

// The bytes from the file's start to the end of its last mip, as its headers
// describe them; 0 when the headers are invalid (ReadDds then says why).
uint64_t BytesDescribed(const uint8_t* data, size_t size, uint32_t maxDimension) {
  Layout l;
  uint32_t w, h, mips;
  std::string ignored;
  if (size < dds::kDataOffset || !PixelLayout(data, size, "", &l, &ignored) ||
      !HeaderSizes(data, "", maxDimension, &w, &h, &mips, &ignored))
    return 0;
  uint64_t end = l.dataOffset;
  for (uint32_t i = 0; i < mips; ++i) {
    const uint32_t mw = std::max(1u, w >> i), mh = std::max(1u, h >> i);
    end += l.bc ? TextureMipBytes(l.bc, mw, mh) : uint64_t(mw) * mh * PlainBytes(l.plain);
  }
  return end;
}

}  // namespace

bool IsDdsData(const uint8_t* data, size_t size) { return data && size >= 4 && U32At(data, 0) == dds::kMagic; }

bool ReadDds(const uint8_t* data, size_t size, const std::string& name, uint32_t maxDimension, DdsImage* out,
             std::string* error) {
  if (!data || size < dds::kDataOffset) {
    *error = name + ": truncated DDS file (" + std::to_string(size) + " bytes; the header needs " +
             std::to_string(dds::kDataOffset) + ")";
    return false;
  }
  if (!IsDdsData(data, size) || U32At(data, dds::kOffSize) != dds::kHeaderSize ||
      U32At(data, dds::kOffPixelFormat + dds::kPfSize) != dds::kPixelFormatSize) {
    *error = name + ": not a DDS file (magic " + Hex(U32At(data, 0)) + ", header size " +
             std::to_string(U32At(data, dds::kOffSize)) + ", pixel format size " +
             std::to_string(U32At(data, dds::kOffPixelFormat)) + ")";
    return false;
  }
  Layout l;
  uint32_t w, h, mips;
  if (!PixelLayout(data, size, name, &l, error) || !HeaderSizes(data, name, maxDimension, &w, &h, &mips, error))
    return false;
  if (l.bc && ((w % 4) || (h % 4)) && (w >= 4 || h >= 4)) {
    *error = name + ": block-compressed DDS size " + std::to_string(w) + "x" + std::to_string(h) +
             " is not a multiple of 4 (D3D11 cannot create such a texture)";
    return false;
  }
  DdsImage img;
  img.pixelFormat = l.name;
  img.format = l.bc ? l.bc : (l.srgb ? DXGI_FORMAT_R8G8B8A8_UNORM_SRGB : DXGI_FORMAT_R8G8B8A8_UNORM);
  if (!ReadMips(data, size, name, l, w, h, mips, &img, error)) return false;
  *out = std::move(img);
  return true;
}

bool ReadDdsFile(const std::string& path, uint32_t maxDimension, DdsImage* out, std::string* error) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *error = path + ": cannot open the DDS file";
    return false;
  }
  // The headers first; then no more than the mips they describe, so that a
  // file with gigabytes of trailing bytes is neither read nor held.
  std::vector<uint8_t> bytes(dds::kDataOffset + dds::kDx10HeaderSize);
  f.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  bytes.resize(size_t(f.gcount()));
  std::error_code ec;
  const uint64_t fileSize = std::filesystem::file_size(path, ec);
  const uint64_t needed = std::min<uint64_t>(BytesDescribed(bytes.data(), bytes.size(), maxDimension),
                                             ec ? 0 : fileSize);
  if (needed > bytes.size()) {
    const size_t have = bytes.size();
    bytes.resize(size_t(needed));
    f.read(reinterpret_cast<char*>(bytes.data() + have), std::streamsize(needed - have));
    bytes.resize(have + size_t(f.gcount()));
  }
  return ReadDds(bytes.data(), bytes.size(), path, maxDimension, out, error);
}

}  // namespace drr
