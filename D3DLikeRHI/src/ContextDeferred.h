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
  ~DeferredContext() override;
  UINT AddRef() override { return ++refs_; }
  UINT Release() override;
  DEVICE_CONTEXT_TYPE GetType() override { return DEVICE_CONTEXT_DEFERRED; }

  HRESULT Map(Resource* resource, UINT subresource, MAP mapType, UINT mapFlags,
              MAPPED_SUBRESOURCE* mapped) override;
  void Unmap(Resource* resource, UINT subresource) override;
  void UpdateSubresource(Resource* dst, UINT dstSubresource, const BOX* dstBox, const void* srcData,
                         UINT srcRowPitch, UINT srcDepthPitch) override;
  // Ends the list being recorded and begins the next one.
  HRESULT FinishCommandList(BOOL restoreDeferredContextState, CommandList** commandList) override;
  // Run only on the immediate context by this port (logged).
  void ExecuteCommandList(CommandList* commandList, BOOL restoreContextState) override;

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
  void UseTexture(TextureCore* t, const SubresourceRange& range, const Usage& u) override;
  void UseBuffer(VkBuffer buf, SyncState& s, const Usage& u) override;
  void NoteUse(GpuUse& u, bool write) override;
  void Hold(Unknown* object) override;
  void Unpinned(const PinTable::Entry& e) override;
  DescriptorPools SetPools() override {
    ListRecording& r = Rec();
    return {r.descPools, r.descPoolCurrent, false};
  }
  VkPipelineLayout BindingLayout(const ProgramLayout& p) override {
    return dev_->pipelines().ListLayout(p, listLayoutIndex_);
  }
  VkDescriptorSetLayout SetLayout(const ProgramLayout& p) override {
    return dev_->pipelines().ListSetLayout(p, listLayoutIndex_);
  }
  const RingAlloc& CbRing(BufferImpl* b) override;
  const RingAlloc& DynRing(const BufferImpl* b) override;

 private:
  // Logs that `fn` is forbidden here (as in D3D11), or not supported here by
  // this port (`portLimit`).
  void Reject(const char* fn, bool portLimit);
  void OpenList() override;
  void EndList();
  // The list being recorded, taken first when none is (OpenList).
  ListRecording& Rec() {
    if (!rec_) OpenList();
    return *rec_;
  }
  // The list's synchronisation entries (its own view of resource states).
  ListSyncEntry& ListEntry(SyncState* global, const Usage& u, bool* first);
  uint32_t ListImageEntries(TextureCore* t, TextureImage& img);
  // Buffer contents written or read by the list, in its own ring.
  ListRecording::Slice* NewListSlice(BufferImpl* b, bool discarded, bool written);
  ListRecording::Slice* FindListSlice(const BufferImpl* b);
  void UpdateConstantsInList(BufferImpl* b, const BOX* box, const void* data);
  template <class T>
  void Retain(T* object);

  std::atomic<UINT> refs_{1};
  // Binds descriptor sets with twin pipeline layout number this
  // (ProgramLayout::listLayouts), so that contexts recording at once do not
  // share one reference count in the driver.
  const uint32_t listLayoutIndex_;
  std::shared_ptr<ListRecycler> recycler_;  // this context's recordings for reuse (ListRecycler.cpp)
  std::unique_ptr<ListRecording> rec_;      // the list being recorded (cmd_ is its secondary buffer); null: none yet
  uint64_t closedDraws_ = 0;                // drawCount_'s target while no list is open (never counted: draws open one)
};

}  // namespace d3dl::impl
