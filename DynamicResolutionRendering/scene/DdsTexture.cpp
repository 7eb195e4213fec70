// DDS images as texture data, and the CPU fallback that expands
// block-compressed textures to RGBA8 where the device cannot sample them.
#include <cstdlib>
#include <cstring>

#include "scene/DdsBlocks.h"
#include "scene/DdsReader.h"

namespace drr {
using namespace d3dl;

namespace {

bool AnyAlphaBelowOpaque(const TextureData& t) {
  if (t.mips.empty()) return false;
  const TextureMip& m = t.mips[0];
  std::vector<uint8_t> decoded;
  const std::vector<uint8_t>* rgba = &m.rgba;
  if (BcBlockBytes(t.format)) {
    if (!DecodeBcMip(t.format, m.rgba.data(), m.width, m.height, &decoded)) return false;
    rgba = &decoded;
  }
  for (size_t i = 3; i < rgba->size(); i += 4)
    if ((*rgba)[i] < 255) return true;
  return false;
}

}  // namespace

void TextureFromDds(DdsImage image, const std::string& name, TextureKind kind, const TextureLoadOptions& opts,
                    TextureData* out) {
  TextureData t;
  t.source = name;
  t.kind = kind;
  t.format = kind == TextureKind::Color ? FormatSrgbOf(image.format) : image.format;
  t.mipsFromFile = BcBlockBytes(image.format) != 0 || image.mips.size() > 1;
  t.mips = std::move(image.mips);
  t.hasAlpha = AnyAlphaBelowOpaque(t);
  if (opts.generateMips) GenerateMipChain(&t);
  *out = std::move(t);
}

bool ExpandToRgba8(const TextureData& texture, TextureData* out, std::string* error) {
  if (!BcBlockBytes(texture.format)) {
    *out = texture;
    return true;
  }
  TextureData t;
  t.source = texture.source;
  t.kind = texture.kind;
  t.hasAlpha = texture.hasAlpha;
  t.mipsFromFile = texture.mipsFromFile;
  t.format = FormatIsSrgb(texture.format) ? DXGI_FORMAT_R8G8B8A8_UNORM_SRGB : DXGI_FORMAT_R8G8B8A8_UNORM;
  for (const TextureMip& m : texture.mips) {
    TextureMip e;
    e.width = m.width, e.height = m.height;
    if (m.rgba.size() != TextureMipBytes(texture.format, m.width, m.height) ||
        !DecodeBcMip(texture.format, m.rgba.data(), m.width, m.height, &e.rgba)) {
      *error = texture.source + ": the CPU decoder cannot expand " + TextureFormatName(texture.format) + " data (" +
               std::to_string(m.width) + "x" + std::to_string(m.height) + ")";
      return false;
    }
    t.mips.push_back(std::move(e));
  }
  *out = std::move(t);
  return true;
}

bool CpuBcDecodeForced() {
  const char* v = std::getenv("DRR_BC_DECODE");
  return v && std::strcmp(v, "cpu") == 0;
}

std::shared_ptr<const TextureData> TextureForDevice(const std::shared_ptr<const TextureData>& texture,
                                                    bool deviceSamplesFormat, std::string* error) {
  if (!BcBlockBytes(texture->format) || (deviceSamplesFormat && !CpuBcDecodeForced())) return texture;
  auto expanded = std::make_shared<TextureData>();
  if (!ExpandToRgba8(*texture, expanded.get(), error)) return nullptr;
  return expanded;
}

}  // namespace drr
