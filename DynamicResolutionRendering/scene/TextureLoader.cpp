#include "scene/TextureLoader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <new>

#include "imageio/ImageFile.h"
#include "imageio/Srgb.h"
#include "scene/DdsBlocks.h"
#include "scene/DdsReader.h"

namespace drr {
namespace fs = std::filesystem;

const char* TextureKindName(TextureKind k) {
  switch (k) {
    case TextureKind::Color: return "diffuse";
    case TextureKind::Normal: return "normal";
    case TextureKind::Specular: return "specular";
  }
  return "?";
}

d3dl::DXGI_FORMAT TextureFormatFor(TextureKind k) {
  return k == TextureKind::Color ? d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB : d3dl::DXGI_FORMAT_R8G8B8A8_UNORM;
}

uint64_t TextureData::Bytes() const {
  uint64_t b = 0;
  for (const auto& m : mips) b += m.rgba.size();
  return b;
}

uint64_t TextureData::BytesAsRgba8() const {
  uint64_t b = 0;
  for (const auto& m : mips) b += uint64_t(m.width) * m.height * 4;
  return b;
}

namespace {

const std::array<float, 256>& SrgbToLinearTable() {
  static const std::array<float, 256> t = [] {
    std::array<float, 256> a{};
    for (int i = 0; i < 256; ++i) a[i] = SrgbToLinear(i / 255.f);
    return a;
  }();
  return t;
}

uint8_t LinearToSrgb8(float l) { return static_cast<uint8_t>(std::lround(LinearToSrgb(l) * 255.f)); }

uint8_t ToByte(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); }

TextureMip Downsample(const TextureMip& src, TextureKind kind) {
  TextureMip dst;
  dst.width = std::max(1u, src.width / 2);
  dst.height = std::max(1u, src.height / 2);
  dst.rgba.resize(size_t(dst.width) * dst.height * 4);
  const auto& lin = SrgbToLinearTable();
  for (uint32_t y = 0; y < dst.height; ++y) {
    uint32_t y0 = std::min(src.height - 1, y * 2), y1 = std::min(src.height - 1, y * 2 + 1);
    for (uint32_t x = 0; x < dst.width; ++x) {
      uint32_t x0 = std::min(src.width - 1, x * 2), x1 = std::min(src.width - 1, x * 2 + 1);
      const uint8_t* p[4] = {&src.rgba[(size_t(y0) * src.width + x0) * 4], &src.rgba[(size_t(y0) * src.width + x1) * 4],
                             &src.rgba[(size_t(y1) * src.width + x0) * 4], &src.rgba[(size_t(y1) * src.width + x1) * 4]};
      uint8_t* d = &dst.rgba[(size_t(y) * dst.width + x) * 4];
      if (kind == TextureKind::Color) {
        // Alpha-weighted average in linear light (keeps cut-out edges clean).
        float r = 0, g = 0, b = 0, a = 0;
        for (auto q : p) {
          float w = q[3] / 255.f + 1e-4f;
          r += lin[q[0]] * w; g += lin[q[1]] * w; b += lin[q[2]] * w; a += w;
        }
        d[0] = LinearToSrgb8(r / a); d[1] = LinearToSrgb8(g / a); d[2] = LinearToSrgb8(b / a);
        d[3] = static_cast<uint8_t>((p[0][3] + p[1][3] + p[2][3] + p[3][3] + 2) / 4);
      } else if (kind == TextureKind::Normal) {
        float n[3] = {0, 0, 0};
        for (auto q : p)
          for (int c = 0; c < 3; ++c) n[c] += q[c] / 255.f * 2.f - 1.f;
        float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len < 0.05f) { n[0] = 0; n[1] = 0; n[2] = 1; len = 1; }  // opposing normals cancel: flat
        for (int c = 0; c < 3; ++c) d[c] = ToByte((n[c] / len) * 0.5f + 0.5f);
        d[3] = static_cast<uint8_t>((p[0][3] + p[1][3] + p[2][3] + p[3][3] + 2) / 4);
      } else {
        for (int c = 0; c < 4; ++c) d[c] = static_cast<uint8_t>((p[0][c] + p[1][c] + p[2][c] + p[3][c] + 2) / 4);
      }
    }
  }
  return dst;
}

bool ValidateSize(uint64_t w, uint64_t h, int channels, const std::string& name, const TextureLoadOptions& opts,
                  std::string* error) {
  if (w == 0 || h == 0) {
    *error = name + ": texture has zero size (" + std::to_string(w) + "x" + std::to_string(h) + ")";
    return false;
  }
  if (w > opts.maxDimension || h > opts.maxDimension) {
    *error = name + ": texture is too large (" + std::to_string(w) + "x" + std::to_string(h) + ", at most " +
             std::to_string(opts.maxDimension) + " per side supported)";
    return false;
  }
  if (channels < 1 || channels > 64) {
    *error = name + ": unsupported texture format (" + std::to_string(channels) + " channels)";
    return false;
  }
  return true;
}

// Converts a decoded image (ImageFile.h: straight alpha, 1..4 channels, 8-bit
// or float) into RGBA8 with the texture kind's conventions.
bool ConvertImage(const ImageFileData& img, const std::string& name, TextureKind kind,
                  const TextureLoadOptions& opts, TextureData* out, std::string* error) {
  if (!ValidateSize(img.width, img.height, int(img.channels), name, opts, error)) return false;
  const uint32_t w = img.width, h = img.height;
  const int nc = int(img.channels);
  const bool isFloat = img.isFloat;
  if ((isFloat ? img.f32.size() : img.u8.size()) < size_t(w) * h * nc) {
    *error = name + ": decoded image is smaller than its size says";
    return false;
  }
  auto sample = [&](size_t i) { return isFloat ? img.f32[i] : img.u8[i] / 255.f; };
  const int alphaIdx = nc == 2 ? 1 : (nc >= 4 ? 3 : -1);
  TextureMip m;
  m.width = w;
  m.height = h;
  m.rgba.resize(size_t(w) * h * 4);
  bool anyAlpha = false;
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    const size_t s = i * nc;
    float rgb[3];
    if (nc <= 2) rgb[0] = rgb[1] = rgb[2] = sample(s);
    else { rgb[0] = sample(s); rgb[1] = sample(s + 1); rgb[2] = sample(s + 2); }
    float a = alphaIdx >= 0 ? sample(s + alphaIdx) : 1.f;
    uint8_t* d = &m.rgba[i * 4];
    for (int c = 0; c < 3; ++c) {
      float v = std::isfinite(rgb[c]) ? rgb[c] : 0.f;
      // Integer files (8- or 16-bit) keep their stored (sRGB) values; float (HDR/EXR) data is linear.
      d[c] = (img.linear && kind == TextureKind::Color) ? LinearToSrgb8(v) : ToByte(v);
    }
    d[3] = ToByte(std::isfinite(a) ? a : 1.f);
    anyAlpha |= d[3] < 255;
  }
  out->source = name;
  out->kind = kind;
  out->format = TextureFormatFor(kind);
  out->hasAlpha = anyAlpha;
  out->mips.clear();
  out->mips.push_back(std::move(m));
  if (opts.generateMips) GenerateMipChain(out);
  return true;
}

// Runs a decoding step; running out of memory (a header that claims more
// texels than fit) becomes an error naming the file instead of an abort.
template <class F>
bool Guarded(const std::string& name, std::string* error, F step) {
  try {
    return step();
  } catch (const std::bad_alloc&) {
    *error = name + ": out of memory while decoding or converting the texture";
    return false;
  }
}

bool HasDdsExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".dds";
}

}  // namespace

void GenerateMipChain(TextureData* tex) {
  if (tex->mips.empty() || tex->mipsFromFile || BcBlockBytes(tex->format)) return;
  tex->mips.resize(1);
  while (tex->mips.back().width > 1 || tex->mips.back().height > 1)
    tex->mips.push_back(Downsample(tex->mips.back(), tex->kind));
}

TextureData FallbackTexture(TextureKind kind) {
  TextureData t;
  t.kind = kind;
  t.format = TextureFormatFor(kind);
  TextureMip m;
  m.width = m.height = 1;
  switch (kind) {
    case TextureKind::Color: m.rgba = {255, 255, 255, 255}; t.source = "<fallback white>"; break;
    case TextureKind::Normal: m.rgba = {128, 128, 255, 255}; t.source = "<fallback flat normal>"; break;
    case TextureKind::Specular: m.rgba = {0, 0, 0, 255}; t.source = "<fallback black>"; break;
  }
  t.mips.push_back(std::move(m));
  return t;
}

bool LoadTextureFile(const std::string& path, TextureKind kind, const TextureLoadOptions& opts, TextureData* out,
                     std::string* error) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    *error = path + ": texture file not found";
    return false;
  }
  if (fs::file_size(path, ec) == 0) {
    *error = path + ": texture has zero size (empty file)";
    return false;
  }
  return Guarded(path, error, [&] {
    if (HasDdsExtension(path)) {
      DdsImage dds;
      if (!ReadDdsFile(path, opts.maxDimension, &dds, error)) return false;
      TextureFromDds(std::move(dds), path, kind, opts, out);
      return true;
    }
    ImageFileData img;
    std::string reason;
    if (!ReadImageFile(path, &img, &reason, opts.maxDimension)) {
      *error = path + ": unsupported texture format or unreadable image (" + reason + ")";
      return false;
    }
    return ConvertImage(img, path, kind, opts, out, error);
  });
}

bool LoadTextureMemory(const void* data, size_t size, const std::string& formatHint, const std::string& name,
                       TextureKind kind, const TextureLoadOptions& opts, TextureData* out, std::string* error) {
  if (!data || size == 0) {
    *error = name + ": embedded texture has zero size";
    return false;
  }
  std::string hint = formatHint.empty() ? "png" : formatHint;
  for (auto& c : hint) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (hint == "jpeg") hint = "jpg";
  return Guarded(name, error, [&] {
    if (hint == "dds" || IsDdsData(static_cast<const uint8_t*>(data), size)) {
      // Embedded textures leave the import worker as RGBA8 (mip 0): expand here.
      DdsImage dds;
      if (!ReadDds(static_cast<const uint8_t*>(data), size, name, opts.maxDimension, &dds, error)) return false;
      TextureData t;
      TextureFromDds(std::move(dds), name, kind, opts, &t);
      return ExpandToRgba8(t, out, error);
    }
    ImageFileData img;
    std::string reason;
    if (!ReadImageMemory(data, size, "embedded." + hint, &img, &reason, opts.maxDimension)) {
      *error = name + ": unsupported embedded texture format '" + hint + "' (" + reason + ")";
      return false;
    }
    return ConvertImage(img, name, kind, opts, out, error);
  });
}

bool MakeTextureRGBA8(const uint8_t* rgba, uint32_t width, uint32_t height, const std::string& name, TextureKind kind,
                      const TextureLoadOptions& opts, TextureData* out, std::string* error) {
  if (!ValidateSize(width, height, 4, name, opts, error)) return false;
  if (!rgba) {
    *error = name + ": texture has no data";
    return false;
  }
  TextureMip m;
  m.width = width;
  m.height = height;
  m.rgba.assign(rgba, rgba + size_t(width) * height * 4);
  out->source = name;
  out->kind = kind;
  out->format = TextureFormatFor(kind);
  out->hasAlpha = false;
  for (size_t i = 3; i < m.rgba.size(); i += 4) out->hasAlpha |= m.rgba[i] < 255;
  out->mips.clear();
  out->mips.push_back(std::move(m));
  if (opts.generateMips) GenerateMipChain(out);
  return true;
}

}  // namespace drr
