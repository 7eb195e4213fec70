// The immediate context: the common context (Context.h) recording into one
// command buffer per frame slot of the queue, submitted at Flush, Present or
// when a Map must wait for the GPU; it lives as long as the device and
// shares the device's reference count.
#pragma once

#include "Context.h"

namespace d3dl::impl {

class ImmediateContext final : public ContextImpl {
 public:
  explicit ImmediateContext(DeviceImpl* dev);
  UINT AddRef() override { return dev_->AddRef(); }
  UINT Release() override { return dev_->Release(); }
  DEVICE_CONTEXT_TYPE GetType() override { return DEVICE_CONTEXT_IMMEDIATE; }

  // Only a deferred context records command lists (logged).
  HRESULT FinishCommandList(BOOL restoreDeferredContextState, CommandList** commandList) override;
  // ContextImmediate.cpp: brings each resource into the list's entry state,
  // executes its secondary buffer and makes its exit state current.
  void ExecuteCommandList(CommandList* commandList, BOOL restoreContextState) override;

 protected:
  // Barriers.cpp: against the resources' global state.
  void UseTexture(TextureCore* t, const SubresourceRange& range, const Usage& u) override;
  void UseBuffer(VkBuffer buf, SyncState& s, const Usage& u) override;
  void NoteUse(GpuUse& u, bool write) override {
    write ? u.Write(dev_->CurrentSerial()) : u.Read(dev_->CurrentSerial());
  }
  void Hold(Unknown*) override {}
  DescriptorPools SetPools() override {
    CommandFrame& f = frames_[dev_->queue().Slot()];
    return {f.descPools, f.descPoolCurrent, true};
  }
  VkPipelineLayout BindingLayout(const ProgramLayout& p) override { return p.layout; }
  VkDescriptorSetLayout SetLayout(const ProgramLayout& p) override { return p.setLayout; }
  const RingAlloc& CbRing(BufferImpl* b) override {
    b->EnsureUploaded();
    return b->ring();
  }
  const RingAlloc& DynRing(const BufferImpl* b) override;

 private:
  void CopyImports(CommandListImpl& list);
  void ExportConstants(ListRecording& rec);
};

}  // namespace d3dl::impl
