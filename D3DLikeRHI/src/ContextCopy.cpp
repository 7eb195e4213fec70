// Copies between resources, GenerateMips and ResolveSubresource. They end the
// rendering scope and record their own barriers; arguments are checked by
// ValidateCopy* / ValidateResolveSubresource.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {

void ContextImpl::CopyBufferRegion(BufferImpl* dst, UINT dstX, BufferImpl* src, const BOX* box) {
  const UINT lo = box ? box->left : 0, hi = box ? box->right : src->size();
  VkBuffer srcBuf;
  VkDeviceSize srcOff = lo;
  switch (src->storage()) {
    case Storage::Constants:
    case Storage::DynamicConstants:
      src->EnsureUploaded();
      srcBuf = src->ring().buffer;
      srcOff += src->ring().offset;
      break;
    case Storage::Ring:
      if (!src->ring().buffer) return;  // never mapped
      srcBuf = src->ring().buffer;
      srcOff += src->ring().offset;
      break;
    default:
      srcBuf = src->vkBuffer();
      UseBuffer(srcBuf, src->sync(), usage::BufferCopySrc);
  }
  EndRendering();
  UseBuffer(dst->vkBuffer(), dst->sync(), usage::BufferCopyDst);
  FlushBarriers();
  VkBufferCopy region{srcOff, dstX, hi - lo};
  vkCmdCopyBuffer(Cmd(), srcBuf, dst->vkBuffer(), 1, &region);
  const uint64_t s = dev_->CurrentSerial();
  src->use.Read(s);
  dst->use.Write(s);
}

// `box` is the source region (null: the whole source mip), checked by
// ValidateCopyTextureRegion.
void ContextImpl::CopyTextureRegion(TextureCore* dst, UINT dstSub, UINT x, UINT y, TextureCore* src,
                                    UINT srcSub, const BOX* box) {
  SubIndex ds, ss;
  dst->DecodeSub(dstSub, &ds);
  src->DecodeSub(srcSub, &ss);
  const BOX b = box ? *box : BOX{0, 0, 0, src->MipWidth(ss.mip), src->MipHeight(ss.mip), 1};
  EndRendering();
  if (dst->IsStaging())
    CopyImageToStaging(dst, dstSub, x, y, src, ss, b);
  else if (src->IsStaging())
    CopyStagingToImage(dst, ds, x, y, src, srcSub, b);
  else
    CopyImageToImage(dst, ds, x, y, src, ss, b);
  const uint64_t serial = dev_->CurrentSerial();
  src->use.Read(serial);
  dst->use.Write(serial);
}

void ContextImpl::CopyImageToImage(TextureCore* dst, SubIndex ds, UINT x, UINT y, TextureCore* src,
                                   SubIndex ss, const BOX& b) {
  UseTexture(src, OneSubresource(ss.mip, ss.layer), usage::TransferSrc);
  UseTexture(dst, OneSubresource(ds.mip, ds.layer), usage::TransferDst);
  FlushBarriers();
  VkImageCopy region{};
  region.srcSubresource = {src->aspect, ss.mip, ss.layer, 1};
  region.srcOffset = {int32_t(b.left), int32_t(b.top), 0};
  region.dstSubresource = {dst->aspect, ds.mip, ds.layer, 1};
  region.dstOffset = {int32_t(x), int32_t(y), 0};
  region.extent = {b.right - b.left, b.bottom - b.top, 1};
  vkCmdCopyImage(Cmd(), src->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst->Cur().image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

namespace {
// Where texel (x, y) of a staging subresource lies in its buffer, and the
// buffer's row length in texels.
VkBufferImageCopy StagingRegion(const TextureCore* staging, UINT sub, UINT x, UINT y) {
  const SubresourceLayout& sl = staging->staging.subs[sub];
  const uint32_t bd = BlockDim(*staging->fmt);
  VkBufferImageCopy region{};
  region.bufferOffset = sl.offset + VkDeviceSize(y / bd) * sl.rowPitch + (x / bd) * staging->fmt->bytes;
  region.bufferRowLength = sl.rowPitch / staging->fmt->bytes * bd;
  return region;
}
}  // namespace

void ContextImpl::CopyImageToStaging(TextureCore* dst, UINT dstSub, UINT x, UINT y, TextureCore* src,
                                     SubIndex ss, const BOX& b) {
  UseTexture(src, OneSubresource(ss.mip, ss.layer), usage::TransferSrc);
  UseBuffer(dst->staging.buffer, dst->staging.sync, usage::BufferCopyDst);
  FlushBarriers();
  VkBufferImageCopy region = StagingRegion(dst, dstSub, x, y);
  region.imageSubresource = {src->aspect, ss.mip, ss.layer, 1};
  region.imageOffset = {int32_t(b.left), int32_t(b.top), 0};
  region.imageExtent = {b.right - b.left, b.bottom - b.top, 1};
  vkCmdCopyImageToBuffer(Cmd(), src->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst->staging.buffer, 1,
                         &region);
}

void ContextImpl::CopyStagingToImage(TextureCore* dst, SubIndex ds, UINT x, UINT y, TextureCore* src,
                                     UINT srcSub, const BOX& b) {
  UseBuffer(src->staging.buffer, src->staging.sync, usage::BufferCopySrc);
  UseTexture(dst, OneSubresource(ds.mip, ds.layer), usage::TransferDst);
  FlushBarriers();
  VkBufferImageCopy region = StagingRegion(src, srcSub, b.left, b.top);
  region.imageSubresource = {dst->aspect, ds.mip, ds.layer, 1};
  region.imageOffset = {int32_t(x), int32_t(y), 0};
  region.imageExtent = {b.right - b.left, b.bottom - b.top, 1};
  vkCmdCopyBufferToImage(Cmd(), src->staging.buffer, dst->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &region);
}

void ContextImpl::CopySubresourceRegion(Resource* dst, UINT dstSub, UINT x, UINT y, UINT, Resource* src,
                                        UINT srcSub, const BOX* box) {
  if (!ValidateCopySubresourceRegion(*dev_, DescribeResource(dst), dstSub, x, y, DescribeResource(src), srcSub, box,
                                     dst && dst == src))
    return;
  BufferImpl *bd = AsBuffer(dst), *bs = AsBuffer(src);
  if (bd && bs) return CopyBufferRegion(bd, x, bs, box);
  CopyTextureRegion(AsTexture(dst), dstSub, x, y, AsTexture(src), srcSub, box);
}

void ContextImpl::CopyResource(Resource* dst, Resource* src) {
  const ResourceInfo di = DescribeResource(dst), si = DescribeResource(src);
  if (!ValidateCopyResource(*dev_, di, si, dst && dst == src)) return;
  BufferImpl *bd = AsBuffer(dst), *bs = AsBuffer(src);
  if (bd && bs) return CopyBufferRegion(bd, 0, bs, nullptr);
  TextureCore *td = AsTexture(dst), *ts = AsTexture(src);
  for (uint32_t s = 0; s < td->SubCount(); ++s)
    if (ValidateCopyTextureRegion(*dev_, di, s, 0, 0, si, s, nullptr)) CopyTextureRegion(td, s, 0, 0, ts, s, nullptr);
}

void ContextImpl::GenerateMips(ShaderResourceView* srv) {
  const ViewInfo info = srv ? DescribeView(static_cast<SRVImpl*>(srv)->v) : ViewInfo{};
  if (!ValidateGenerateMips(*dev_, srv ? &info : nullptr)) return;
  const ViewCore& v = static_cast<SRVImpl*>(srv)->v;
  TextureCore* t = v.tex;
  EndRendering();
  for (uint32_t l = v.baseLayer; l < v.baseLayer + v.layerCount; ++l)
    for (uint32_t m = v.baseMip + 1; m < v.baseMip + v.mipCount; ++m) {
      UseTexture(t, OneSubresource(m - 1, l), usage::TransferSrc);
      UseTexture(t, OneSubresource(m, l), usage::TransferDst);
      FlushBarriers();
      VkImageBlit blit{};
      blit.srcSubresource = {t->aspect, m - 1, l, 1};
      blit.srcOffsets[1] = {int32_t(t->MipWidth(m - 1)), int32_t(t->MipHeight(m - 1)), 1};
      blit.dstSubresource = {t->aspect, m, l, 1};
      blit.dstOffsets[1] = {int32_t(t->MipWidth(m)), int32_t(t->MipHeight(m)), 1};
      vkCmdBlitImage(Cmd(), t->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, t->Cur().image,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
    }
  t->use.Write(dev_->CurrentSerial());
}

// vkCmdResolveImage averages the samples (float and UNORM formats; the
// validation rejects the integer and depth formats D3D11 cannot resolve).
void ContextImpl::ResolveSubresource(Resource* dst, UINT dstSub, Resource* src, UINT srcSub, DXGI_FORMAT format) {
  if (!ValidateResolveSubresource(*dev_, DescribeResource(dst), dstSub, DescribeResource(src), srcSub, format)) return;
  TextureCore *td = AsTexture(dst), *ts = AsTexture(src);
  SubIndex ds, ss;
  td->DecodeSub(dstSub, &ds);
  ts->DecodeSub(srcSub, &ss);
  EndRendering();
  UseTexture(ts, OneSubresource(ss.mip, ss.layer), usage::ResolveSrc);
  UseTexture(td, OneSubresource(ds.mip, ds.layer), usage::ResolveDst);
  FlushBarriers();
  VkImageResolve region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, ss.mip, ss.layer, 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, ds.mip, ds.layer, 1};
  region.extent = {ts->MipWidth(ss.mip), ts->MipHeight(ss.mip), 1};
  vkCmdResolveImage(Cmd(), ts->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, td->Cur().image,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  const uint64_t serial = dev_->CurrentSerial();
  ts->use.Read(serial);
  td->use.Write(serial);
}

}  // namespace d3dl::impl
