// DeviceContext::BlitRegion: a Vulkan-backend extension outside D3D11 (a
// scaled, filtered copy with vkCmdBlitImage). It ends the rendering scope and
// records its barriers through UseTexture like the copies in ContextCopy.cpp.
#include <cstdlib>
#include <cstring>

#include "Context.h"

namespace d3dl::impl {
namespace {
bool InBounds(const RECT& r, uint32_t w, uint32_t h) {
  auto in = [](int32_t v, uint32_t hi) { return v >= 0 && uint32_t(v) <= hi; };
  return in(r.left, w) && in(r.right, w) && in(r.top, h) && in(r.bottom, h) && r.left != r.right &&
         r.top != r.bottom;
}
}  // namespace

void ContextImpl::BlitRegion(Texture2D* dstTex, const RECT& dstRect, Texture2D* srcTex,
                             const RECT& srcRect, FILTER filter) {
  if (!dstTex || !srcTex) {
    dev_->Log(LogLevel::Error, "BlitRegion: %s is null", dstTex ? "pSrc" : "pDst");
    return;
  }
  TextureCore* dst = AsTexture(dstTex);
  TextureCore* src = AsTexture(srcTex);
  if (!dst || !src || dst == src) {
    dev_->Log(LogLevel::Error, "BlitRegion: source and destination must be two different textures");
    return;
  }
  if (dst->staging || src->staging || dst->aspect != VK_IMAGE_ASPECT_COLOR_BIT ||
      src->aspect != VK_IMAGE_ASPECT_COLOR_BIT) {
    dev_->Log(LogLevel::Error, "BlitRegion: only non-staging colour textures can be blitted");
    return;
  }
  if (dst->desc.Usage == USAGE_IMMUTABLE) {
    dev_->Log(LogLevel::Error, "BlitRegion: the destination is IMMUTABLE");
    return;
  }
  const uint32_t sw = src->MipWidth(0), sh = src->MipHeight(0);
  const uint32_t dw = dst->MipWidth(0), dh = dst->MipHeight(0);
  if (!InBounds(srcRect, sw, sh) || !InBounds(dstRect, dw, dh)) {
    dev_->Log(LogLevel::Error,
              "BlitRegion: rectangle out of bounds or empty (src (%d,%d)-(%d,%d) of %ux%u, dst (%d,%d)-(%d,%d) of %ux%u)",
              srcRect.left, srcRect.top, srcRect.right, srcRect.bottom, sw, sh, dstRect.left, dstRect.top,
              dstRect.right, dstRect.bottom, dw, dh);
    return;
  }
  // Point or linear, as a sampler with this filter would magnify or minify.
  const bool magnifies = std::abs(dstRect.right - dstRect.left) >= std::abs(srcRect.right - srcRect.left) &&
                         std::abs(dstRect.bottom - dstRect.top) >= std::abs(srcRect.bottom - srcRect.top);
  const uint32_t f = uint32_t(filter);
  const bool anisotropic = (f & 0x40u) != 0;
  const bool linear = anisotropic || (magnifies ? (f & 0x04u) != 0 : (f & 0x10u) != 0);

  VkFormatProperties sp, dp;
  vkGetPhysicalDeviceFormatProperties(dev_->phys(), src->format, &sp);
  vkGetPhysicalDeviceFormatProperties(dev_->phys(), dst->format, &dp);
  if (!(sp.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT) ||
      !(dp.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT)) {
    dev_->Log(LogLevel::Error, "BlitRegion: %s -> %s is not blittable on this device", src->fmt->name,
              dst->fmt->name);
    return;
  }
  if (linear && !(sp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)) {
    dev_->Log(LogLevel::Error, "BlitRegion: format %s cannot be blitted with linear filtering", src->fmt->name);
    return;
  }
  // Integer formats blit only into the same kind of integer format, with
  // point filtering (vkCmdBlitImage VUIDs 00229/00230, 00235 ... ).
  auto isSigned = [](const TextureCore* t) { return std::strstr(t->fmt->name, "SINT") != nullptr; };
  if (src->fmt->integer != dst->fmt->integer || (src->fmt->integer && (linear || isSigned(src) != isSigned(dst)))) {
    dev_->Log(LogLevel::Error, "BlitRegion: %s -> %s: integer formats blit only to the same kind of integer format, with point filtering",
              src->fmt->name, dst->fmt->name);
    return;
  }

  EndRendering();
  UseTexture(src, 0, 1, 0, 1, usage::TransferSrc);
  UseTexture(dst, 0, 1, 0, 1, usage::TransferDst);
  FlushBarriers();
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[0] = {srcRect.left, srcRect.top, 0};
  blit.srcOffsets[1] = {srcRect.right, srcRect.bottom, 1};
  blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.dstOffsets[0] = {dstRect.left, dstRect.top, 0};
  blit.dstOffsets[1] = {dstRect.right, dstRect.bottom, 1};
  vkCmdBlitImage(dev_->Cmd(), src->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst->Cur().image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST);
  const uint64_t serial = dev_->CurrentSerial();
  src->lastUseSerial = serial;
  dst->lastUseSerial = dst->lastWriteSerial = serial;
}

}  // namespace d3dl::impl
