// Validation of BlitExtension::BlitRegion: the two textures, the rectangles
// inside their first mip, and formats the device can blit (see Validate.h).
#include "Validate.h"

namespace d3dl::impl {

namespace {
bool InBounds(const RECT& r, uint32_t w, uint32_t h) {
  auto in = [](int32_t v, uint32_t hi) { return v >= 0 && uint32_t(v) <= hi; };
  return in(r.left, w) && in(r.right, w) && in(r.top, h) && in(r.bottom, h) && r.left != r.right &&
         r.top != r.bottom;
}

bool ValidateBlitTextures(DeviceImpl& dev, const TextureCore* dst, const TextureCore* src) {
  if (!dst || !src || dst == src) {
    dev.Log(LogLevel::Error, "BlitRegion: source and destination must be two different textures");
    return false;
  }
  if (dst->IsStaging() || src->IsStaging() || dst->aspect != VK_IMAGE_ASPECT_COLOR_BIT ||
      src->aspect != VK_IMAGE_ASPECT_COLOR_BIT) {
    dev.Log(LogLevel::Error, "BlitRegion: only non-staging colour textures can be blitted");
    return false;
  }
  if (dst->desc.Usage == USAGE_IMMUTABLE) {
    dev.Log(LogLevel::Error, "BlitRegion: the destination is IMMUTABLE");
    return false;
  }
  return true;
}

bool ValidateBlitRects(DeviceImpl& dev, const TextureCore* dst, const RECT& dstRect, const TextureCore* src,
                       const RECT& srcRect) {
  const uint32_t sw = src->MipWidth(0), sh = src->MipHeight(0);
  const uint32_t dw = dst->MipWidth(0), dh = dst->MipHeight(0);
  if (InBounds(srcRect, sw, sh) && InBounds(dstRect, dw, dh)) return true;
  dev.Log(LogLevel::Error,
          "BlitRegion: rectangle out of bounds or empty (src (%d,%d)-(%d,%d) of %ux%u, dst (%d,%d)-(%d,%d) of %ux%u)",
          srcRect.left, srcRect.top, srcRect.right, srcRect.bottom, sw, sh, dstRect.left, dstRect.top,
          dstRect.right, dstRect.bottom, dw, dh);
  return false;
}

bool ValidateBlitFormats(DeviceImpl& dev, const TextureCore* dst, const TextureCore* src, bool linear) {
  VkFormatProperties sp, dp;
  vkGetPhysicalDeviceFormatProperties(dev.phys(), src->format, &sp);
  vkGetPhysicalDeviceFormatProperties(dev.phys(), dst->format, &dp);
  if (!(sp.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT) ||
      !(dp.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT)) {
    dev.Log(LogLevel::Error, "BlitRegion: %s -> %s is not blittable on this device", src->fmt->name, dst->fmt->name);
    return false;
  }
  if (linear && !(sp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)) {
    dev.Log(LogLevel::Error, "BlitRegion: format %s cannot be blitted with linear filtering", src->fmt->name);
    return false;
  }
  // Integer formats blit only into the same kind of integer format, with
  // point filtering (vkCmdBlitImage VUIDs 00229/00230, 00235 ... ).
  auto isSigned = [](const TextureCore* t) { return std::strstr(t->fmt->name, "SINT") != nullptr; };
  if (src->fmt->integer != dst->fmt->integer || (src->fmt->integer && (linear || isSigned(src) != isSigned(dst)))) {
    dev.Log(LogLevel::Error, "BlitRegion: %s -> %s: integer formats blit only to the same kind of integer format, with point filtering",
            src->fmt->name, dst->fmt->name);
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

bool ValidateBlitRegion(DeviceImpl& dev, Texture2D* dstTex, const RECT& dstRect, Texture2D* srcTex,
                        const RECT& srcRect, FILTER filter) {
  if (!dstTex || !srcTex) {
    dev.Log(LogLevel::Error, "BlitRegion: %s is null", dstTex ? "pSrc" : "pDst");
    return false;
  }
  const TextureCore* dst = AsTexture(dstTex);
  const TextureCore* src = AsTexture(srcTex);
  return ValidateBlitTextures(dev, dst, src) && ValidateBlitRects(dev, dst, dstRect, src, srcRect) &&
         ValidateBlitFormats(dev, dst, src, BlitIsLinear(dstRect, srcRect, filter));
}

}  // namespace d3dl::impl
