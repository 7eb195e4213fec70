// BlitExtension::BlitRegion, a Vulkan-backend extension outside D3D11 (a
// scaled, filtered copy with vkCmdBlitImage). It ends the rendering scope and
// records its barriers through UseTexture like the copies in ContextCopy.cpp;
// ValidateBlitRegion checks the arguments first.
#include "Context.h"
#include "Validate.h"

namespace d3dl {

BlitExtension* GetBlitExtension(DeviceContext* context) { return dynamic_cast<BlitExtension*>(context); }

namespace impl {

void ContextImpl::BlitRegion(Texture2D* dstTex, const RECT& dstRect, Texture2D* srcTex,
                             const RECT& srcRect, FILTER filter) {
  if (!ValidateBlitRegion(*dev_, DescribeResource(dstTex), dstRect, DescribeResource(srcTex), srcRect, filter,
                          dstTex && dstTex == srcTex))
    return;
  TextureCore* dst = AsTexture(dstTex);
  TextureCore* src = AsTexture(srcTex);
  EndRendering();
  UseTexture(src, SubresourceRange{}, usage::TransferSrc);
  UseTexture(dst, SubresourceRange{}, usage::TransferDst);
  FlushBarriers();
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[0] = {srcRect.left, srcRect.top, 0};
  blit.srcOffsets[1] = {srcRect.right, srcRect.bottom, 1};
  blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.dstOffsets[0] = {dstRect.left, dstRect.top, 0};
  blit.dstOffsets[1] = {dstRect.right, dstRect.bottom, 1};
  const VkFilter vkFilter = BlitIsLinear(dstRect, srcRect, filter) ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  vkCmdBlitImage(Cmd(), src->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst->Cur().image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, vkFilter);
  const uint64_t serial = dev_->CurrentSerial();
  src->use.Read(serial);
  dst->use.Write(serial);
}

}  // namespace impl
}  // namespace d3dl
