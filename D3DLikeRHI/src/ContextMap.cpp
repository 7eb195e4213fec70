// Map/Unmap and UpdateSubresource: a switch over the resource's Storage with
// one small function per case. Arguments are checked by ValidateMap /
// ValidateUpdateSubresource first; these functions assume valid calls.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {
namespace {
void SetMapped(MAPPED_SUBRESOURCE* m, void* data, UINT rowPitch, UINT depthPitch) {
  m->pData = data;
  m->RowPitch = rowPitch;
  m->DepthPitch = depthPitch;
}
}  // namespace

bool ContextImpl::WaitForResource(uint64_t lastUse, UINT flags, HRESULT* hr) {
  if (lastUse == 0) return true;
  if (lastUse >= dev_->CurrentSerial()) Flush();  // the GPU work that uses it was not submitted yet
  if (dev_->queue().CompletedSerial() >= lastUse) return true;
  if (flags & MAP_FLAG_DO_NOT_WAIT) {
    *hr = DXGI_ERROR_WAS_STILL_DRAWING;
    return false;
  }
  dev_->queue().WaitForSerial(lastUse);
  return true;
}

// Hot path of Map: a fresh ring slice per WRITE_DISCARD, written by the
// application in place (no shadow copy per draw; see BufferImpl::SyncShadow).
HRESULT ContextImpl::MapDiscardConstants(BufferImpl* b, MAPPED_SUBRESOURCE* mapped) {
  if (!b->NewRingSlice(b->dev()->uboAlign())) {  // b->dev(): one device pointer to load
    *mapped = {};
    return E_OUTOFMEMORY;
  }
  if (!b->shadowStale()) ListDiscarded(b);  // once per buffer and frame
  mapped->pData = b->ring().ptr;
  mapped->RowPitch = mapped->DepthPitch = b->size();
  return S_OK;
}

// Out of line so that MapDiscardConstants stays a leaf without spills.
__attribute__((noinline)) void ContextImpl::ListDiscarded(BufferImpl* b) {
  b->MarkShadowStale();
  if (b->discardListed()) return;
  b->SetDiscardListed(true);
  discardedCBs_.push_back(b);
}

void ContextImpl::SaveDiscardedConstants() {
  for (BufferImpl* b : discardedCBs_) {
    b->SyncShadow();
    b->SetDiscardListed(false);
  }
  discardedCBs_.clear();
}

void ContextImpl::ForgetDiscardedConstants(BufferImpl* b) {
  discardedCBs_.erase(std::remove(discardedCBs_.begin(), discardedCBs_.end(), b), discardedCBs_.end());
}

HRESULT ContextImpl::Map(Resource* resource, UINT sub, MAP type, UINT flags, MAPPED_SUBRESOURCE* mapped) {
  if (type == MAP_WRITE_DISCARD && sub == 0 && mapped) {
    BufferImpl* b = AsBuffer(resource);
    if (b && b->storage() == Storage::DynamicConstants) return MapDiscardConstants(b, mapped);
  }
  const HRESULT valid = ValidateMap(*dev_, DescribeResource(resource), sub, type, mapped);
  if (resource && mapped) *mapped = {};
  if (FAILED(valid)) return valid;
  if (BufferImpl* b = AsBuffer(resource)) return MapBuffer(b, type, flags, mapped);
  return MapTexture(AsTexture(resource), sub, type, flags, mapped);
}

HRESULT ContextImpl::MapBuffer(BufferImpl* b, MAP type, UINT flags, MAPPED_SUBRESOURCE* mapped) {
  switch (b->storage()) {
    case Storage::Constants:
    case Storage::DynamicConstants: return MapConstantShadow(b, mapped);
    case Storage::Ring: return MapRingBuffer(b, type, mapped);
    case Storage::Staging: return MapStagingBuffer(b, type, flags, mapped);
    case Storage::DeviceLocal: break;
  }
  return E_INVALIDARG;
}

HRESULT ContextImpl::MapTexture(TextureCore* t, UINT sub, MAP type, UINT flags, MAPPED_SUBRESOURCE* mapped) {
  switch (t->storage) {
    case Storage::Staging: return MapStagingTexture(t, sub, type, flags, mapped);
    case Storage::Ring: return MapRingTexture(t, sub, mapped);
    default: break;
  }
  return E_INVALIDARG;
}

// WRITE / WRITE_NO_OVERWRITE of a DYNAMIC constant buffer: the shadow, with
// what the last WRITE_DISCARD wrote; copied into the ring at the next draw.
HRESULT ContextImpl::MapConstantShadow(BufferImpl* b, MAPPED_SUBRESOURCE* mapped) {
  b->SyncShadow();
  SetMapped(mapped, b->shadow(), b->size(), b->size());
  return S_OK;
}

// DYNAMIC vertex/index buffers: WRITE_DISCARD takes a new slice, NO_OVERWRITE
// returns the current one (a new one in a new frame).
HRESULT ContextImpl::MapRingBuffer(BufferImpl* b, MAP type, MAPPED_SUBRESOURCE* mapped) {
  if (type == MAP_WRITE_DISCARD || !b->RingFromFrame(dev_->CurrentSerial()) || !b->ring().buffer) {
    if (!b->NewRingSlice(256)) return E_OUTOFMEMORY;
  }
  SetMapped(mapped, b->ring().ptr, b->size(), b->size());
  return S_OK;
}

HRESULT ContextImpl::MapStagingBuffer(BufferImpl* b, MAP type, UINT flags, MAPPED_SUBRESOURCE* mapped) {
  HRESULT hr = S_OK;
  if (!WaitForResource(type == MAP_READ ? b->use.lastWrite : b->use.lastUse, flags, &hr)) return hr;
  SetMapped(mapped, b->mapped(), b->size(), b->size());
  return S_OK;
}

HRESULT ContextImpl::MapStagingTexture(TextureCore* t, UINT sub, MAP type, UINT flags,
                                       MAPPED_SUBRESOURCE* mapped) {
  HRESULT hr = S_OK;
  if (!WaitForResource(type == MAP_READ ? t->use.lastWrite : t->use.lastUse, flags, &hr)) return hr;
  const SubresourceLayout& s = t->staging.subs[sub];
  SetMapped(mapped, t->staging.mapped + s.offset, s.rowPitch, s.rowPitch * s.rows);
  return S_OK;
}

// DYNAMIC textures: the application writes a ring slice; Unmap copies it.
HRESULT ContextImpl::MapRingTexture(TextureCore* t, UINT sub, MAPPED_SUBRESOURCE* mapped) {
  SubIndex si;
  t->DecodeSub(sub, &si);
  const LinearSize ls = LinearLayout(*t->fmt, t->MipWidth(si.mip), t->MipHeight(si.mip));
  if (!dev_->AllocateRing(VkDeviceSize(ls.rowPitch) * ls.rows, 16, &t->mapRing)) return E_OUTOFMEMORY;
  SetMapped(mapped, t->mapRing.ptr, ls.rowPitch, ls.rowPitch * ls.rows);
  return S_OK;
}

void ContextImpl::Unmap(Resource* resource, UINT sub) {
  if (BufferImpl* b = AsBuffer(resource)) {
    if (b->IsConstantBuffer()) {
      // After WRITE_DISCARD the data is already in this frame's ring slice;
      // after another map type it is in the shadow: re-upload at the next draw.
      if (!b->shadowStale()) b->ShadowChanged();
      dirty_ |= kConstants;
    } else if (b->storage() == Storage::Ring) {
      dirty_ |= kVertexBuffers | kIndexBuffer;
    }
    return;
  }
  TextureCore* t = AsTexture(resource);
  if (t && t->storage == Storage::Ring) UnmapRingTexture(t, sub);
}

void ContextImpl::UnmapRingTexture(TextureCore* t, UINT sub) {
  SubIndex si;
  if (!t->DecodeSub(sub, &si) || !t->mapRing.buffer) return;
  CopyFromRing(t, si, t->mapRing, BOX{0, 0, 0, t->MipWidth(si.mip), t->MipHeight(si.mip), 1});
  t->mapRing = {};
}

// Records the copy of a ring slice (tightly packed rows) into box of a mip.
void ContextImpl::CopyFromRing(TextureCore* t, const SubIndex& si, const RingAlloc& a, const BOX& box) {
  EndRendering();
  UseTexture(t, OneSubresource(si.mip, si.layer), usage::TransferDst);
  FlushBarriers();
  VkBufferImageCopy region{};
  region.bufferOffset = a.offset;
  region.imageSubresource = {t->aspect, si.mip, si.layer, 1};
  region.imageOffset = {int32_t(box.left), int32_t(box.top), 0};
  region.imageExtent = {box.right - box.left, box.bottom - box.top, 1};
  vkCmdCopyBufferToImage(Cmd(), a.buffer, t->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

// ---------------------------------------------------------------------------
void ContextImpl::UpdateSubresource(Resource* dst, UINT sub, const BOX* box, const void* data, UINT rowPitch, UINT) {
  BOX region;
  if (!ValidateUpdateSubresource(*dev_, DescribeResource(dst), sub, box, data, rowPitch, &region)) return;
  if (BufferImpl* b = AsBuffer(dst)) return UpdateBuffer(b, region.left, region.right, data);
  UpdateTexture(AsTexture(dst), sub, region, data, rowPitch);
}

void ContextImpl::UpdateBuffer(BufferImpl* b, UINT lo, UINT hi, const void* data) {
  switch (b->storage()) {
    case Storage::Constants:
    case Storage::DynamicConstants:
      b->SyncShadow();
      std::memcpy(b->shadow() + lo, data, hi - lo);
      b->ShadowChanged();
      dirty_ |= kConstants;
      return;
    case Storage::Staging: {
      HRESULT hr;
      WaitForResource(b->use.lastUse, 0, &hr);
      std::memcpy(b->mapped() + lo, data, hi - lo);
      return;
    }
    case Storage::DeviceLocal: break;
    case Storage::Ring: return;  // rejected by validation (use Map)
  }
  RingAlloc a;
  if (!dev_->AllocateRing(hi - lo, 16, &a)) return;
  std::memcpy(a.ptr, data, hi - lo);
  EndRendering();
  UseBuffer(b->vkBuffer(), b->sync(), usage::BufferCopyDst);
  FlushBarriers();
  VkBufferCopy copy{a.offset, lo, hi - lo};
  vkCmdCopyBuffer(Cmd(), a.buffer, b->vkBuffer(), 1, &copy);
  b->use.Write(dev_->CurrentSerial());
}

// `box` lies inside the mip (ValidateUpdateSubresource); rows of `rowPitch`
// bytes (0: tightly packed).
void ContextImpl::UpdateTexture(TextureCore* t, UINT sub, const BOX& box, const void* data, UINT rowPitch) {
  SubIndex si;
  t->DecodeSub(sub, &si);
  const uint32_t bd = BlockDim(*t->fmt);
  const LinearSize ls = LinearLayout(*t->fmt, box.right - box.left, box.bottom - box.top);
  if (rowPitch == 0) rowPitch = ls.rowPitch;
  const auto* src = static_cast<const uint8_t*>(data);
  if (t->IsStaging()) {
    HRESULT hr;
    WaitForResource(t->use.lastUse, 0, &hr);
    const SubresourceLayout& s = t->staging.subs[sub];
    uint8_t* dst = t->staging.mapped + s.offset + VkDeviceSize(box.top / bd) * s.rowPitch + (box.left / bd) * t->fmt->bytes;
    for (uint32_t r = 0; r < ls.rows; ++r) std::memcpy(dst + VkDeviceSize(r) * s.rowPitch, src + size_t(r) * rowPitch, ls.rowPitch);
    return;
  }
  RingAlloc a;
  if (!dev_->AllocateRing(VkDeviceSize(ls.rowPitch) * ls.rows, 16, &a)) return;
  for (uint32_t r = 0; r < ls.rows; ++r) std::memcpy(a.ptr + size_t(r) * ls.rowPitch, src + size_t(r) * rowPitch, ls.rowPitch);
  CopyFromRing(t, si, a, box);
  t->use.Write(dev_->CurrentSerial());
}

}  // namespace d3dl::impl
