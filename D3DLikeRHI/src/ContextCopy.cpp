// Map/Unmap, UpdateSubresource, copies and GenerateMips. Copies end the
// rendering scope and record their own barriers.
#include "Context.h"

namespace d3dl::impl {
namespace {
struct SubIndex {
  uint32_t mip, layer;
};
bool DecodeSub(const TextureCore* t, UINT sub, SubIndex* out) {
  if (sub >= t->SubCount()) return false;
  out->mip = sub % t->desc.MipLevels;
  out->layer = sub / t->desc.MipLevels;
  return true;
}
uint32_t BlockDim(const TextureCore* t) { return t->fmt->bc ? 4 : 1; }
}  // namespace

bool ContextImpl::WaitForResource(uint64_t lastUse, UINT flags, HRESULT* hr) {
  if (lastUse == 0) return true;
  if (lastUse >= dev_->CurrentSerial()) Flush();  // the GPU work that uses it was not submitted yet
  if (dev_->CompletedSerial() >= lastUse) return true;
  if (flags & MAP_FLAG_DO_NOT_WAIT) {
    *hr = DXGI_ERROR_WAS_STILL_DRAWING;
    return false;
  }
  dev_->WaitForSerial(lastUse);
  return true;
}

// Hot path of Map: a fresh ring slice per WRITE_DISCARD, written by the
// application in place (no shadow copy per draw; see BufferImpl::SyncShadow).
HRESULT ContextImpl::MapDiscardConstants(BufferImpl* b, MAPPED_SUBRESOURCE* mapped) {
  if (!dev_->AllocateRing(b->desc_.ByteWidth, dev_->uboAlign(), &b->ring)) {  // writes only on success
    *mapped = {};
    return E_OUTOFMEMORY;
  }
  b->ringSerial = dev_->CurrentSerial();
  if (!b->shadowStale) ListDiscarded(b);  // once per buffer and frame
  mapped->pData = b->ring.ptr;
  mapped->RowPitch = mapped->DepthPitch = b->desc_.ByteWidth;
  return S_OK;
}

// Out of line so that MapDiscardConstants stays a leaf without spills.
__attribute__((noinline)) void ContextImpl::ListDiscarded(BufferImpl* b) {
  b->shadowStale = true;
  discardedCBs_.push_back(b);
}

void ContextImpl::SaveDiscardedConstants() {
  for (BufferImpl* b : discardedCBs_) b->SyncShadow();
  discardedCBs_.clear();
}

void ContextImpl::ForgetDiscardedConstants(BufferImpl* b) {
  discardedCBs_.erase(std::remove(discardedCBs_.begin(), discardedCBs_.end(), b), discardedCBs_.end());
}

HRESULT ContextImpl::Map(Resource* resource, UINT sub, MAP type, UINT flags, MAPPED_SUBRESOURCE* mapped) {
  if (type == MAP_WRITE_DISCARD && sub == 0 && mapped) {
    BufferImpl* b = AsBuffer(resource);
    if (b && b->isDynamicConstant) return MapDiscardConstants(b, mapped);
  }
  if (!resource || !mapped) {
    dev_->Log(LogLevel::Error, "Map: %s is null", resource ? "pMappedResource" : "pResource");
    return E_INVALIDARG;
  }
  *mapped = {};
  if (type < MAP_READ || type > MAP_WRITE_NO_OVERWRITE) {
    dev_->Log(LogLevel::Error, "Map: invalid MapType %u", type);
    return E_INVALIDARG;
  }
  HRESULT hr = S_OK;
  if (BufferImpl* b = AsBuffer(resource)) {
    if (sub != 0) {
      dev_->Log(LogLevel::Error, "Map: buffers have one subresource (got %u)", sub);
      return E_INVALIDARG;
    }
    if (b->isConstant) {
      if (type == MAP_READ || type == MAP_READ_WRITE || b->desc_.Usage != USAGE_DYNAMIC) {
        dev_->Log(LogLevel::Error, "Map: a constant buffer can be mapped only with WRITE_DISCARD and USAGE_DYNAMIC");
        return E_INVALIDARG;
      }
      b->SyncShadow();  // WRITE_NO_OVERWRITE keeps what the last WRITE_DISCARD wrote
      mapped->pData = b->shadow.data();  // copied into the ring at the next draw that uses it
      mapped->RowPitch = mapped->DepthPitch = b->desc_.ByteWidth;
      return S_OK;
    }
    if (b->isRing) {
      if (type != MAP_WRITE_DISCARD && type != MAP_WRITE_NO_OVERWRITE) {
        dev_->Log(LogLevel::Error, "Map: USAGE_DYNAMIC buffers accept WRITE_DISCARD or WRITE_NO_OVERWRITE only (got %u)", type);
        return E_INVALIDARG;
      }
      if (type == MAP_WRITE_DISCARD || b->ringSerial != dev_->CurrentSerial() || !b->ring.buffer) {
        if (!dev_->AllocateRing(b->desc_.ByteWidth, 256, &b->ring)) return E_OUTOFMEMORY;
        b->ringSerial = dev_->CurrentSerial();
      }
      mapped->pData = b->ring.ptr;
      mapped->RowPitch = mapped->DepthPitch = b->desc_.ByteWidth;
      return S_OK;
    }
    if (b->desc_.Usage != USAGE_STAGING) {
      dev_->Log(LogLevel::Error, "Map: only DYNAMIC or STAGING buffers can be mapped");
      return E_INVALIDARG;
    }
    if (((type == MAP_READ || type == MAP_READ_WRITE) && !(b->desc_.CPUAccessFlags & CPU_ACCESS_READ)) ||
        (type != MAP_READ && !(b->desc_.CPUAccessFlags & CPU_ACCESS_WRITE))) {
      dev_->Log(LogLevel::Error, "Map: MapType %u does not match CPUAccessFlags 0x%x", type, b->desc_.CPUAccessFlags);
      return E_INVALIDARG;
    }
    if (!WaitForResource(type == MAP_READ ? b->lastWriteSerial : b->lastUseSerial, flags, &hr)) return hr;
    mapped->pData = b->mapped;
    mapped->RowPitch = mapped->DepthPitch = b->desc_.ByteWidth;
    return S_OK;
  }
  TextureCore* t = AsTexture(resource);
  SubIndex si;
  if (!t || !DecodeSub(t, sub, &si)) {
    dev_->Log(LogLevel::Error, "Map: subresource %u out of range", sub);
    return E_INVALIDARG;
  }
  if (t->staging) {
    if (((type == MAP_READ || type == MAP_READ_WRITE) && !(t->desc.CPUAccessFlags & CPU_ACCESS_READ)) ||
        (type != MAP_READ && !(t->desc.CPUAccessFlags & CPU_ACCESS_WRITE))) {
      dev_->Log(LogLevel::Error, "Map: MapType %u does not match CPUAccessFlags 0x%x", type, t->desc.CPUAccessFlags);
      return E_INVALIDARG;
    }
    if (!WaitForResource(type == MAP_READ ? t->lastWriteSerial : t->lastUseSerial, flags, &hr)) return hr;
    const auto& s = t->subs[sub];
    mapped->pData = t->mapped + s.offset;
    mapped->RowPitch = s.rowPitch;
    mapped->DepthPitch = s.rowPitch * s.rows;
    return S_OK;
  }
  if (t->desc.Usage == USAGE_DYNAMIC) {
    if (type != MAP_WRITE_DISCARD) {
      dev_->Log(LogLevel::Error, "Map: DYNAMIC textures accept WRITE_DISCARD only (got %u)", type);
      return E_INVALIDARG;
    }
    uint32_t w = t->MipWidth(si.mip), h = t->MipHeight(si.mip);
    uint32_t pitch = t->fmt->bc ? ((w + 3) / 4) * t->fmt->bytes : w * t->fmt->bytes;
    uint32_t rows = t->fmt->bc ? (h + 3) / 4 : h;
    if (!dev_->AllocateRing(VkDeviceSize(pitch) * rows, 16, &t->mapRing)) return E_OUTOFMEMORY;
    mapped->pData = t->mapRing.ptr;
    mapped->RowPitch = pitch;
    mapped->DepthPitch = pitch * rows;
    return S_OK;
  }
  dev_->Log(LogLevel::Error, "Map: only DYNAMIC or STAGING textures can be mapped");
  return E_INVALIDARG;
}

void ContextImpl::Unmap(Resource* resource, UINT sub) {
  if (BufferImpl* b = AsBuffer(resource)) {
    if (b->isConstant) {
      // After WRITE_DISCARD the data is already in this frame's ring slice;
      // after another map type it is in the shadow: re-upload at the next draw.
      if (!b->shadowStale) b->ringSerial = 0;
      dirty_ |= kConstants;
    } else if (b->isRing) {
      dirty_ |= kVertexBuffers | kIndexBuffer;
    }
    return;
  }
  TextureCore* t = AsTexture(resource);
  SubIndex si;
  if (!t || !DecodeSub(t, sub, &si) || t->staging || !t->mapRing.buffer) return;
  EndRendering();
  UseTexture(t, si.mip, 1, si.layer, 1, usage::TransferDst);
  FlushBarriers();
  VkBufferImageCopy region{};
  region.bufferOffset = t->mapRing.offset;
  region.imageSubresource = {t->aspect, si.mip, si.layer, 1};
  region.imageExtent = {t->MipWidth(si.mip), t->MipHeight(si.mip), 1};
  vkCmdCopyBufferToImage(dev_->Cmd(), t->mapRing.buffer, t->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  t->mapRing = {};
}

void ContextImpl::UpdateTexture(TextureCore* t, UINT sub, const BOX* box, const void* data, UINT rowPitch) {
  SubIndex si;
  if (!DecodeSub(t, sub, &si)) {
    dev_->Log(LogLevel::Error, "UpdateSubresource: subresource %u out of range", sub);
    return;
  }
  uint32_t mw = t->MipWidth(si.mip), mh = t->MipHeight(si.mip);
  BOX b = box ? *box : BOX{0, 0, 0, mw, mh, 1};
  if (b.right > mw || b.bottom > mh || b.left >= b.right || b.top >= b.bottom) {
    if (box && (b.left >= b.right || b.top >= b.bottom)) return;  // empty box: no-op, as D3D
    dev_->Log(LogLevel::Error, "UpdateSubresource: box (%u,%u)-(%u,%u) outside mip %u (%ux%u)", b.left, b.top, b.right, b.bottom, si.mip, mw, mh);
    return;
  }
  const uint32_t bd = BlockDim(t);
  if (bd > 1 && ((b.left % 4) || (b.top % 4))) {
    dev_->Log(LogLevel::Error, "UpdateSubresource: box of a block-compressed texture must be 4-aligned");
    return;
  }
  uint32_t w = b.right - b.left, h = b.bottom - b.top;
  uint32_t pitch = ((w + bd - 1) / bd) * t->fmt->bytes, rows = (h + bd - 1) / bd;
  if (rowPitch == 0) rowPitch = pitch;
  if (rowPitch < pitch) {
    dev_->Log(LogLevel::Error, "UpdateSubresource: SrcRowPitch %u is smaller than a row (%u bytes)", rowPitch, pitch);
    return;
  }
  if (t->staging) {
    HRESULT hr;
    WaitForResource(t->lastUseSerial, 0, &hr);
    const auto& s = t->subs[sub];
    for (uint32_t r = 0; r < rows; ++r)
      std::memcpy(t->mapped + s.offset + VkDeviceSize(b.top / bd + r) * s.rowPitch + (b.left / bd) * t->fmt->bytes,
                  static_cast<const uint8_t*>(data) + size_t(r) * rowPitch, pitch);
    return;
  }
  RingAlloc a;
  if (!dev_->AllocateRing(VkDeviceSize(pitch) * rows, 16, &a)) return;
  for (uint32_t r = 0; r < rows; ++r)
    std::memcpy(a.ptr + size_t(r) * pitch, static_cast<const uint8_t*>(data) + size_t(r) * rowPitch, pitch);
  EndRendering();
  UseTexture(t, si.mip, 1, si.layer, 1, usage::TransferDst);
  FlushBarriers();
  VkBufferImageCopy region{};
  region.bufferOffset = a.offset;
  region.imageSubresource = {t->aspect, si.mip, si.layer, 1};
  region.imageOffset = {int32_t(b.left), int32_t(b.top), 0};
  region.imageExtent = {std::min(w, mw - b.left), std::min(h, mh - b.top), 1};
  vkCmdCopyBufferToImage(dev_->Cmd(), a.buffer, t->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  t->lastUseSerial = t->lastWriteSerial = dev_->CurrentSerial();
}

void ContextImpl::UpdateSubresource(Resource* dst, UINT sub, const BOX* box, const void* data, UINT rowPitch, UINT) {
  if (!dst || !data) {
    dev_->Log(LogLevel::Error, "UpdateSubresource: %s is null", dst ? "pSrcData" : "pDstResource");
    return;
  }
  if (BufferImpl* b = AsBuffer(dst)) {
    UINT lo = box ? box->left : 0, hi = box ? box->right : b->desc_.ByteWidth;
    if (sub != 0 || hi > b->desc_.ByteWidth || lo > hi) {
      dev_->Log(LogLevel::Error, "UpdateSubresource: range [%u, %u) outside the buffer (%u bytes)", lo, hi, b->desc_.ByteWidth);
      return;
    }
    if (lo == hi) return;
    if (b->desc_.Usage == USAGE_IMMUTABLE || b->desc_.Usage == USAGE_DYNAMIC) {
      dev_->Log(LogLevel::Error, "UpdateSubresource: buffer Usage %u cannot be updated (use Map for DYNAMIC)", b->desc_.Usage);
      return;
    }
    if (b->isConstant) {
      b->SyncShadow();
      std::memcpy(b->shadow.data() + lo, data, hi - lo);
      b->ringSerial = 0;
      dirty_ |= kConstants;
      return;
    }
    if (b->desc_.Usage == USAGE_STAGING) {
      HRESULT hr;
      WaitForResource(b->lastUseSerial, 0, &hr);
      std::memcpy(b->mapped + lo, data, hi - lo);
      return;
    }
    RingAlloc a;
    if (!dev_->AllocateRing(hi - lo, 16, &a)) return;
    std::memcpy(a.ptr, data, hi - lo);
    EndRendering();
    UseBuffer(b->buffer, b->sync, usage::BufferCopyDst);
    FlushBarriers();
    VkBufferCopy region{a.offset, lo, hi - lo};
    vkCmdCopyBuffer(dev_->Cmd(), a.buffer, b->buffer, 1, &region);
    b->lastUseSerial = b->lastWriteSerial = dev_->CurrentSerial();
    return;
  }
  TextureCore* t = AsTexture(dst);
  if (!t) return;
  if (t->desc.Usage == USAGE_IMMUTABLE || t->desc.Usage == USAGE_DYNAMIC) {
    dev_->Log(LogLevel::Error, "UpdateSubresource: texture Usage %u cannot be updated", t->desc.Usage);
    return;
  }
  UpdateTexture(t, sub, box, data, rowPitch);
}

void ContextImpl::CopyBufferRegion(BufferImpl* dst, UINT dstX, BufferImpl* src, const BOX* box) {
  UINT lo = box ? box->left : 0, hi = box ? box->right : src->desc_.ByteWidth;
  if (lo >= hi || hi > src->desc_.ByteWidth || dstX + (hi - lo) > dst->desc_.ByteWidth) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: buffer range [%u, %u) -> %u out of bounds", lo, hi, dstX);
    return;
  }
  if (dst->isConstant || dst->isRing || dst->desc_.Usage == USAGE_IMMUTABLE) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: the destination buffer must be DEFAULT or STAGING (not a constant, dynamic or immutable buffer)");
    return;
  }
  VkBuffer srcBuf;
  VkDeviceSize srcOff = lo;
  if (src->isConstant) {
    src->EnsureUploaded();
    srcBuf = src->ring.buffer;
    srcOff += src->ring.offset;
  } else if (src->isRing) {
    if (!src->ring.buffer) return;
    srcBuf = src->ring.buffer;
    srcOff += src->ring.offset;
  } else {
    srcBuf = src->buffer;
    UseBuffer(src->buffer, src->sync, usage::BufferCopySrc);
  }
  EndRendering();
  UseBuffer(dst->buffer, dst->sync, usage::BufferCopyDst);
  FlushBarriers();
  VkBufferCopy region{srcOff, dstX, hi - lo};
  vkCmdCopyBuffer(dev_->Cmd(), srcBuf, dst->buffer, 1, &region);
  const uint64_t s = dev_->CurrentSerial();
  src->lastUseSerial = s;
  dst->lastUseSerial = dst->lastWriteSerial = s;
}

void ContextImpl::CopyTextureRegion(TextureCore* dst, UINT dstSub, UINT x, UINT y, TextureCore* src, UINT srcSub,
                                    const BOX* box) {
  SubIndex ds, ss;
  if (!DecodeSub(dst, dstSub, &ds) || !DecodeSub(src, srcSub, &ss)) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: subresource out of range (dst %u, src %u)", dstSub, srcSub);
    return;
  }
  if (dst->fmt->bytes != src->fmt->bytes || dst->fmt->bc != src->fmt->bc ||
      (!dst->staging && !src->staging && dst->aspect != src->aspect)) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: formats %s and %s are not copy-compatible", dst->fmt->name, src->fmt->name);
    return;
  }
  uint32_t sw = src->MipWidth(ss.mip), sh = src->MipHeight(ss.mip);
  BOX b = box ? *box : BOX{0, 0, 0, sw, sh, 1};
  uint32_t dw = dst->MipWidth(ds.mip), dh = dst->MipHeight(ds.mip);
  if (b.left >= b.right || b.top >= b.bottom || b.right > sw || b.bottom > sh || x + (b.right - b.left) > dw ||
      y + (b.bottom - b.top) > dh) {
    if (box && (b.left >= b.right || b.top >= b.bottom)) return;
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: box (%u,%u)-(%u,%u) at (%u,%u) out of bounds (src %ux%u, dst %ux%u)",
              b.left, b.top, b.right, b.bottom, x, y, sw, sh, dw, dh);
    return;
  }
  if (dst->staging && src->staging) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: staging-to-staging copies are not supported");
    return;
  }
  const uint32_t w = b.right - b.left, h = b.bottom - b.top;
  VkCommandBuffer cmd = dev_->Cmd();
  EndRendering();
  const uint64_t serial = dev_->CurrentSerial();
  if (!dst->staging && !src->staging) {
    UseTexture(src, ss.mip, 1, ss.layer, 1, usage::TransferSrc);
    UseTexture(dst, ds.mip, 1, ds.layer, 1, usage::TransferDst);
    FlushBarriers();
    VkImageCopy region{};
    region.srcSubresource = {src->aspect, ss.mip, ss.layer, 1};
    region.srcOffset = {int32_t(b.left), int32_t(b.top), 0};
    region.dstSubresource = {dst->aspect, ds.mip, ds.layer, 1};
    region.dstOffset = {int32_t(x), int32_t(y), 0};
    region.extent = {w, h, 1};
    vkCmdCopyImage(cmd, src->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst->Cur().image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  } else if (dst->staging) {
    UseTexture(src, ss.mip, 1, ss.layer, 1, usage::TransferSrc);
    UseBuffer(dst->stagingBuffer, dst->stagingSync, usage::BufferCopyDst);
    FlushBarriers();
    const auto& sl = dst->subs[dstSub];
    const uint32_t bd = BlockDim(dst);
    VkBufferImageCopy region{};
    region.bufferOffset = sl.offset + VkDeviceSize(y / bd) * sl.rowPitch + (x / bd) * dst->fmt->bytes;
    region.bufferRowLength = sl.rowPitch / dst->fmt->bytes * bd;
    region.imageSubresource = {src->aspect, ss.mip, ss.layer, 1};
    region.imageOffset = {int32_t(b.left), int32_t(b.top), 0};
    region.imageExtent = {w, h, 1};
    vkCmdCopyImageToBuffer(cmd, src->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst->stagingBuffer, 1, &region);
  } else {
    UseBuffer(src->stagingBuffer, src->stagingSync, usage::BufferCopySrc);
    UseTexture(dst, ds.mip, 1, ds.layer, 1, usage::TransferDst);
    FlushBarriers();
    const auto& sl = src->subs[srcSub];
    const uint32_t bd = BlockDim(src);
    VkBufferImageCopy region{};
    region.bufferOffset = sl.offset + VkDeviceSize(b.top / bd) * sl.rowPitch + (b.left / bd) * src->fmt->bytes;
    region.bufferRowLength = sl.rowPitch / src->fmt->bytes * bd;
    region.imageSubresource = {dst->aspect, ds.mip, ds.layer, 1};
    region.imageOffset = {int32_t(x), int32_t(y), 0};
    region.imageExtent = {w, h, 1};
    vkCmdCopyBufferToImage(cmd, src->stagingBuffer, dst->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  }
  src->lastUseSerial = serial;
  dst->lastUseSerial = dst->lastWriteSerial = serial;
}

void ContextImpl::CopySubresourceRegion(Resource* dst, UINT dstSub, UINT x, UINT y, UINT, Resource* src,
                                        UINT srcSub, const BOX* box) {
  if (!dst || !src) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: %s is null", dst ? "pSrcResource" : "pDstResource");
    return;
  }
  if (dst == src && dstSub == srcSub) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: source and destination are the same subresource");
    return;
  }
  BufferImpl *bd = AsBuffer(dst), *bs = AsBuffer(src);
  if (bd && bs) {
    if (dstSub || srcSub) {
      dev_->Log(LogLevel::Error, "CopySubresourceRegion: buffers have one subresource");
      return;
    }
    CopyBufferRegion(bd, x, bs, box);
    return;
  }
  TextureCore *td = AsTexture(dst), *ts = AsTexture(src);
  if (!td || !ts) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: cannot copy between a buffer and a texture");
    return;
  }
  if (td->desc.Usage == USAGE_IMMUTABLE) {
    dev_->Log(LogLevel::Error, "CopySubresourceRegion: the destination is IMMUTABLE");
    return;
  }
  CopyTextureRegion(td, dstSub, x, y, ts, srcSub, box);
}

void ContextImpl::CopyResource(Resource* dst, Resource* src) {
  if (!dst || !src || dst == src) {
    dev_->Log(LogLevel::Error, "CopyResource: %s", dst == src && dst ? "source and destination are the same" : "null resource");
    return;
  }
  BufferImpl *bd = AsBuffer(dst), *bs = AsBuffer(src);
  if (bd || bs) {
    if (!bd || !bs || bd->desc_.ByteWidth != bs->desc_.ByteWidth) {
      dev_->Log(LogLevel::Error, "CopyResource: buffers must have the same size");
      return;
    }
    CopyBufferRegion(bd, 0, bs, nullptr);
    return;
  }
  TextureCore *td = AsTexture(dst), *ts = AsTexture(src);
  if (td->dim != ts->dim || td->desc.Width != ts->desc.Width || td->desc.Height != ts->desc.Height ||
      td->desc.MipLevels != ts->desc.MipLevels || td->desc.ArraySize != ts->desc.ArraySize) {
    dev_->Log(LogLevel::Error, "CopyResource: textures differ in size, mips or array size (%ux%u/%u vs %ux%u/%u)",
              td->desc.Width, td->desc.Height, td->desc.MipLevels, ts->desc.Width, ts->desc.Height, ts->desc.MipLevels);
    return;
  }
  if (td->desc.Usage == USAGE_IMMUTABLE) {
    dev_->Log(LogLevel::Error, "CopyResource: the destination is IMMUTABLE");
    return;
  }
  for (uint32_t s = 0; s < td->SubCount(); ++s) CopyTextureRegion(td, s, 0, 0, ts, s, nullptr);
}

void ContextImpl::GenerateMips(ShaderResourceView* srv) {
  if (!srv) {
    dev_->Log(LogLevel::Error, "GenerateMips: pShaderResourceView is null");
    return;
  }
  auto* v = static_cast<SRVImpl*>(srv);
  TextureCore* t = v->v.tex;
  if (!(t->desc.MiscFlags & RESOURCE_MISC_GENERATE_MIPS)) {
    dev_->Log(LogLevel::Error, "GenerateMips: the texture was not created with RESOURCE_MISC_GENERATE_MIPS");
    return;
  }
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(dev_->phys(), t->format, &fp);
  const VkFormatFeatureFlags need = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                    VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((fp.optimalTilingFeatures & need) != need) {
    dev_->Log(LogLevel::Error, "GenerateMips: format %s cannot be blitted with linear filtering", t->fmt->name);
    return;
  }
  EndRendering();
  VkCommandBuffer cmd = dev_->Cmd();
  for (uint32_t l = v->v.baseLayer; l < v->v.baseLayer + v->v.layerCount; ++l)
    for (uint32_t m = v->v.baseMip + 1; m < v->v.baseMip + v->v.mipCount; ++m) {
      UseTexture(t, m - 1, 1, l, 1, usage::TransferSrc);
      UseTexture(t, m, 1, l, 1, usage::TransferDst);
      FlushBarriers();
      VkImageBlit blit{};
      blit.srcSubresource = {t->aspect, m - 1, l, 1};
      blit.srcOffsets[1] = {int32_t(t->MipWidth(m - 1)), int32_t(t->MipHeight(m - 1)), 1};
      blit.dstSubresource = {t->aspect, m, l, 1};
      blit.dstOffsets[1] = {int32_t(t->MipWidth(m)), int32_t(t->MipHeight(m)), 1};
      vkCmdBlitImage(cmd, t->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, t->Cur().image,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
    }
  t->lastUseSerial = t->lastWriteSerial = dev_->CurrentSerial();
}

}  // namespace d3dl::impl
