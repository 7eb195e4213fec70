// A deferred context (CreateDeferredContext): the common context (Context.h)
// recording into command lists (ContextDeferred.cpp). Map and
// UpdateSubresource write the list's own constant and dynamic slices; the calls
// D3D11 forbids on a deferred context (Flush, queries) and those this port
// runs only on the immediate context (copies, GenerateMips, blits) log an
// error and do nothing. It is counted on its own and keeps the device alive.
#pragma once

#include <atomic>

#include "Context.h"

namespace d3dl::impl {

class DeferredContext final : public ContextImpl {
 public:
  explicit DeferredContext(DeviceImpl* dev);
  UINT AddRef() override { return ++refs_; }
  UINT Release() override;
  DEVICE_CONTEXT_TYPE GetType() override { return DEVICE_CONTEXT_DEFERRED; }

  HRESULT Map(Resource* resource, UINT subresource, MAP mapType, UINT mapFlags,
              MAPPED_SUBRESOURCE* mapped) override;
  void Unmap(Resource* resource, UINT subresource) override;
  void UpdateSubresource(Resource* dst, UINT dstSubresource, const BOX* dstBox, const void* srcData,
                         UINT srcRowPitch, UINT srcDepthPitch) override;

  // Forbidden by D3D11 on a deferred context.
  void Flush() override { Reject("Flush", false); }
  void Begin(Query*) override { Reject("Begin", false); }
  void End(Query*) override { Reject("End", false); }
  HRESULT GetData(Query*, void*, UINT, UINT) override {
    Reject("GetData", false);
    return DXGI_ERROR_INVALID_CALL;
  }
  // Run only on the immediate context by this port.
  void CopyResource(Resource*, Resource*) override { Reject("CopyResource", true); }
  void CopySubresourceRegion(Resource*, UINT, UINT, UINT, UINT, Resource*, UINT, const BOX*) override {
    Reject("CopySubresourceRegion", true);
  }
  void GenerateMips(ShaderResourceView*) override { Reject("GenerateMips", true); }
  void BlitRegion(Texture2D*, const RECT&, Texture2D*, const RECT&, FILTER) override {
    Reject("BlitRegion", true);
  }

 protected:
  // Into the list (ContextDeferred.cpp).
  void UseTexture(TextureCore* t, const SubresourceRange& range, const Usage& u) override {
    UseTextureInList(t, range, u);
  }
  void UseBuffer(VkBuffer buf, SyncState& s, const Usage& u) override { UseBufferInList(buf, s, u); }
  void NoteUse(GpuUse& u, bool write) override { NoteUseInList(u, write); }
  void Hold(Unknown* object) override { RetainInList(object); }
  void HoldDrawState(bool indexed) override { RetainDrawState(indexed); }
  void HoldComputeState() override { RetainComputeState(); }
  DescriptorPools SetPools() override { return {rec_->descPools, rec_->descPoolCurrent, false}; }
  VkPipelineLayout BindingLayout(const ProgramLayout& p) override {
    return dev_->pipelines().ListLayout(p, listLayoutIndex_);
  }

 private:
  // Logs that `fn` is forbidden here (as in D3D11), or not supported here by
  // this port (`portLimit`).
  void Reject(const char* fn, bool portLimit);
  std::atomic<UINT> refs_{1};
};

}  // namespace d3dl::impl
