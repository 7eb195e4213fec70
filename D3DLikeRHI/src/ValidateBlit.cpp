// Validation of BlitExtension::BlitRegion: the two textures, the rectangles
// inside their first mip, and formats the device can blit (see Validate.h).
#include <cstring>

#include "Validate.h"

namespace d3dl::impl {

namespace {
bool InBounds(const RECT& r, uint32_t w, uint32_t h) {
  auto in = [](int32_t v, uint32_t hi) { return v >= 0 && uint32_t(v) <= hi; };
  return in(r.left, w) && in(r.right, w) && in(r.top, h) && in(r.bottom, h) && r.left != r.right &&
         r.top != r.bottom;
}

bool ValidateBlitTextures(ValidationDevice& dev, const ResourceInfo& dst, const ResourceInfo& src, bool same) {
  if (!dst.IsTexture() || !src.IsTexture() || same) {
    dev.Log(LogLevel::Error, "BlitRegion: source and destination must be two different textures");
    return false;
  }
  if (dst.usage == USAGE_STAGING || src.usage == USAGE_STAGING || dst.depth || src.depth) {
    dev.Log(LogLevel::Error, "BlitRegion: only non-staging colour textures can be blitted");
    return false;
  }
  if (dst.usage == USAGE_IMMUTABLE) {
    dev.Log(LogLevel::Error, "BlitRegion: the destination is IMMUTABLE");
    return false;
  }
  return true;
}

bool ValidateBlitRects(ValidationDevice& dev, const ResourceInfo& dst, const RECT& dstRect, const ResourceInfo& src,
                       const RECT& srcRect) {
  const uint32_t sw = src.MipWidth(0), sh = src.MipHeight(0);
  const uint32_t dw = dst.MipWidth(0), dh = dst.MipHeight(0);
  if (InBounds(srcRect, sw, sh) && InBounds(dstRect, dw, dh)) return true;
  dev.Log(LogLevel::Error,
          "BlitRegion: rectangle out of bounds or empty (src (%d,%d)-(%d,%d) of %ux%u, dst (%d,%d)-(%d,%d) of %ux%u)",
          srcRect.left, srcRect.top, srcRect.right, srcRect.bottom, sw, sh, dstRect.left, dstRect.top,
          dstRect.right, dstRect.bottom, dw, dh);
  return false;
}

bool ValidateBlitFormats(ValidationDevice& dev, const ResourceInfo& dst, const ResourceInfo& src, bool linear) {
  const uint32_t sf = dev.FormatFeatures(src.format), df = dev.FormatFeatures(dst.format);
  const char *srcName = FormatName(src.format), *dstName = FormatName(dst.format);
  if (!(sf & FORMAT_FEATURE_BLIT_SRC) || !(df & FORMAT_FEATURE_BLIT_DST)) {
    dev.Log(LogLevel::Error, "BlitRegion: %s -> %s is not blittable on this device", srcName, dstName);
    return false;
  }
  if (linear && !(sf & FORMAT_FEATURE_FILTER_LINEAR)) {
    dev.Log(LogLevel::Error, "BlitRegion: format %s cannot be blitted with linear filtering", srcName);
    return false;
  }
  // Integer formats blit only into the same kind of integer format, with
  // point filtering (vkCmdBlitImage VUIDs 00229/00230, 00235 ... ).
  const bool srcInteger = GetFormatInfo(src.format)->integer, dstInteger = GetFormatInfo(dst.format)->integer;
  auto isSigned = [](const char* name) { return std::strstr(name, "SINT") != nullptr; };
  if (srcInteger != dstInteger || (srcInteger && (linear || isSigned(srcName) != isSigned(dstName)))) {
    dev.Log(LogLevel::Error, "BlitRegion: %s -> %s: integer formats blit only to the same kind of integer format, with point filtering",
            srcName, dstName);
    return false;
  }
  return true;
}
}  // namespace

bool BlitIsLinear(const RECT& dstRect, const RECT& srcRect, FILTER filter) {
  const bool magnifies = std::abs(dstRect.right - dstRect.left) >= std::abs(srcRect.right - srcRect.left) &&
                         std::abs(dstRect.bottom - dstRect.top) >= std::abs(srcRect.bottom - srcRect.top);
  const uint32_t f = uint32_t(filter);
  const bool anisotropic = (f & 0x40u) != 0;
  return anisotropic || (magnifies ? (f & 0x04u) != 0 : (f & 0x10u) != 0);
}

bool ValidateBlitRegion(ValidationDevice& dev, const ResourceInfo& dst, const RECT& dstRect, const ResourceInfo& src,
                        const RECT& srcRect, FILTER filter, bool same) {
  if (dst.dimension == RESOURCE_DIMENSION_UNKNOWN || src.dimension == RESOURCE_DIMENSION_UNKNOWN) {
    dev.Log(LogLevel::Error, "BlitRegion: %s is null", dst.dimension != RESOURCE_DIMENSION_UNKNOWN ? "pSrc" : "pDst");
    return false;
  }
  return ValidateBlitTextures(dev, dst, src, same) && ValidateBlitRects(dev, dst, dstRect, src, srcRect) &&
         ValidateBlitFormats(dev, dst, src, BlitIsLinear(dstRect, srcRect, filter));
}

}  // namespace d3dl::impl
