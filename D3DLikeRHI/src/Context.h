// What the immediate and deferred contexts share (as DXVK's common context):
// D3D11-style state, its commit at draws and dispatches, clears, Map of
// constant buffers, barriers. ImmediateContext (ContextImmediate.h) records
// into one Vulkan command buffer per frame, which it submits through the
// device queue and executes command lists; DeferredContext (ContextDeferred.h)
// records command lists and rejects the calls D3D11 forbids on it. Where the
// two differ, the common part calls a virtual hook (UseTexture, CbRing...)
// and never tests which kind it is. The common part is split over
// ContextState.cpp (setters), ContextDraw.cpp (commit, rendering scopes),
// ContextClear.cpp, ContextMap.cpp (map/update), ContextCopy.cpp,
// ContextBlit.cpp, ContextQuery.cpp, ContextFrame.cpp (command buffers,
// submission) and Barriers.cpp.
#pragma once

#include "CommandList.h"
#include "ContextState.h"
#include "Device.h"
#include "d3dl/BlitExtension.h"

namespace d3dl::impl {

struct DrawInputs;  // Validate.h

class QueryImpl final : public Child<Query> {
 public:
  using Child::Child;
  void GetDesc(QUERY_DESC* d) const override {
    if (d) *d = desc;
  }
  UINT GetDataSize() const override;
  QUERY_DESC desc{};
  uint64_t serial = 0;  // frame of the last End (0 = never ended)
  uint32_t index = 0;   // timestamp: index in the frame's query pool
  VkQueryPool pool = VK_NULL_HANDLE;
  bool resolved = false;
  uint64_t value = 0;
  bool begun = false;
  // Pipeline statistics (QueryStatistics.cpp): its own one-query pool, the
  // counters it holds, whether a frame end cut it short.
  ~QueryImpl() override;
  VkQueryPool statsPool = VK_NULL_HANDLE;
  VkQueryPipelineStatisticFlags statsFlags = 0;
  bool statsCut = false;
  QUERY_DATA_PIPELINE_STATISTICS stats{};
};

// What a context records with in one frame slot of the queue: its command
// buffer, the pools its descriptor sets come from and its timestamps.
struct CommandFrame {
  // The pool's host memory (CommandMemory.h): the immediate context's
  // commands, thousands a frame on lavapipe, come from blocks this slot
  // already owns rather than from a malloc and a free each (Docs/Threads.md).
  std::unique_ptr<CommandMemory> memory;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  uint64_t serial = 0;  // frame recorded in this slot
  std::vector<VkDescriptorPool> descPools;
  size_t descPoolCurrent = 0;
  VkQueryPool queryPool = VK_NULL_HANDLE;
  uint32_t queriesUsed = 0;
  std::vector<QueryImpl*> queries;  // referenced until resolved
};

// The descriptor set of the last commit, and what the constants-only path
// needs to rebind it with new dynamic offsets.
struct BoundDescriptors {
  static constexpr uint32_t kMaxCbs = kGraphicsStageCount * kMaxConstantBufferSlots;
  VkDescriptorSet set = VK_NULL_HANDLE;
  VkBuffer cbBuffers[kMaxCbs] = {};  // written into `set`
  uint32_t cbRanges[kMaxCbs] = {};
  uint32_t dynOffsets[kMaxCbs] = {};
  // The program's CBs in binding order (null: dummy) and its layout (null:
  // no descriptor set), as BindDescriptors last bound them.
  BufferImpl* hotCbs[kMaxCbs] = {};
  uint32_t nHotCbs = 0;
  VkPipelineLayout hotLayout = VK_NULL_HANDLE;
};

class ContextImpl : public DeviceContext, public BlitExtension {
 public:
  ~ContextImpl() override;

  void IASetInputLayout(InputLayout* layout) override;
  void IASetVertexBuffers(UINT startSlot, UINT numBuffers, Buffer* const* buffers,
                          const UINT* strides, const UINT* offsets) override;
  void IASetIndexBuffer(Buffer* buffer, DXGI_FORMAT format, UINT offset) override;
  void IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY topology) override;
  void VSSetShader(VertexShader* shader) override;
  void VSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) override;
  void VSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) override;
  void VSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) override;
  void PSSetShader(PixelShader* shader) override;
  void PSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) override;
  void PSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) override;
  void PSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) override;
  // Hull, domain and geometry stages (ContextStages.cpp)
  void HSSetShader(HullShader* shader) override;
  void HSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) override;
  void HSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) override;
  void HSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) override;
  void DSSetShader(DomainShader* shader) override;
  void DSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) override;
  void DSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) override;
  void DSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) override;
  void GSSetShader(GeometryShader* shader) override;
  void GSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) override;
  void GSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) override;
  void GSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) override;
  void RSSetViewports(UINT num, const VIEWPORT* viewports) override;
  void RSSetScissorRects(UINT num, const RECT* rects) override;
  void RSSetState(RasterizerState* state) override;
  void OMSetRenderTargets(UINT num, RenderTargetView* const* rtvs, DepthStencilView* dsv) override;
  void OMSetBlendState(BlendState* state, const float blendFactor[4], UINT sampleMask) override;
  void OMSetDepthStencilState(DepthStencilState* state, UINT stencilRef) override;
  void OMGetRenderTargets(UINT num, RenderTargetView** rtvs, DepthStencilView** dsv) override;
  void ClearRenderTargetView(RenderTargetView* rtv, const float color[4]) override;
  void ClearDepthStencilView(DepthStencilView* dsv, UINT clearFlags, float depth,
                             uint8_t stencil) override;
  void ClearView(View* view, const float color[4], const RECT* rects, UINT numRects) override;
  void Draw(UINT vertexCount, UINT startVertex) override;
  void DrawIndexed(UINT indexCount, UINT startIndex, int32_t baseVertex) override;
  void DrawInstanced(UINT vertexCountPerInstance, UINT instanceCount, UINT startVertex,
                     UINT startInstance) override;
  void DrawIndexedInstanced(UINT indexCountPerInstance, UINT instanceCount, UINT startIndex,
                            int32_t baseVertex, UINT startInstance) override;
  void DrawInstancedIndirect(Buffer* args, UINT alignedByteOffset) override;
  void DrawIndexedInstancedIndirect(Buffer* args, UINT alignedByteOffset) override;
  HRESULT Map(Resource* resource, UINT subresource, MAP mapType, UINT mapFlags,
              MAPPED_SUBRESOURCE* mapped) override;
  void Unmap(Resource* resource, UINT subresource) override;
  void UpdateSubresource(Resource* dst, UINT dstSubresource, const BOX* dstBox,
                         const void* srcData, UINT srcRowPitch, UINT srcDepthPitch) override;
  void CopyResource(Resource* dst, Resource* src) override;
  void CopySubresourceRegion(Resource* dst, UINT dstSubresource, UINT dstX, UINT dstY, UINT dstZ,
                             Resource* src, UINT srcSubresource, const BOX* srcBox) override;
  void GenerateMips(ShaderResourceView* srv) override;
  void Begin(Query* query) override;
  void End(Query* query) override;
  HRESULT GetData(Query* query, void* data, UINT dataSize, UINT flags) override;
  void BeginEvent(const char* name) override;
  void EndEvent() override;
  void ClearState() override;
  void Flush() override;

  // Multisample resolve (ContextCopy.cpp)
  void ResolveSubresource(Resource* dst, UINT dstSubresource, Resource* src, UINT srcSubresource,
                          DXGI_FORMAT format) override;
  // FinishCommandList and ExecuteCommandList: ContextDeferred.h, ContextImmediate.h.
  // Compute shaders and UAVs (ContextCompute.cpp)
  void CSSetShader(ComputeShader* shader) override;
  void CSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) override;
  void CSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) override;
  void CSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) override;
  void CSSetUnorderedAccessViews(UINT startSlot, UINT num, UnorderedAccessView* const* views,
                                 const UINT* initialCounts) override;
  void Dispatch(UINT groupsX, UINT groupsY, UINT groupsZ) override;
  void DispatchIndirect(Buffer* args, UINT offset) override;
  void ClearUnorderedAccessViewUint(UnorderedAccessView* uav, const UINT values[4]) override;
  void ClearUnorderedAccessViewFloat(UnorderedAccessView* uav, const float values[4]) override;
  void OMSetRenderTargetsAndUnorderedAccessViews(UINT numRTVs, RenderTargetView* const* rtvs,
                                                 DepthStencilView* dsv, UINT uavStartSlot, UINT numUAVs,
                                                 UnorderedAccessView* const* uavs,
                                                 const UINT* initialCounts) override;

  // BlitExtension (ContextBlit.cpp)
  void BlitRegion(Texture2D* dst, const RECT& dstRect, Texture2D* src, const RECT& srcRect,
                  FILTER filter) override;

  // ---- backend internals
  // Ends the frame's commands (the rendering scope, pending barriers; `present`
  // is left in PRESENT_SRC), submits them through the device queue with
  // `signal`, and begins the next frame.
  void SubmitFrame(TextureCore* present = nullptr, VkSemaphore signal = VK_NULL_HANDLE);
  // Releases the pins of objects no slot holds any more (Pins.h): what D3D11
  // releases at the unbind. ResizeBuffers calls it before it counts the back
  // buffer's references.
  void CompactPins();
  void ForgetDiscardedConstants(BufferImpl* b);  // `b` is being destroyed

 protected:
  explicit ContextImpl(DeviceImpl* dev);

  // ContextFrame.cpp
  void CreateCommandFrames();
  void DestroyCommandFrames();
  void BeginCommandFrame();  // a fresh command buffer: everything is re-bound lazily
  void EndCommandFrame(TextureCore* present);
  void RecycleCommandFrame(CommandFrame& f);
  VkDescriptorSet AllocateSet(VkDescriptorSetLayout layout);

  // ---- What differs between recording into the frame (ImmediateContext)
  // and into a command list (DeferredContext); none is called while the
  // context is being constructed or destroyed.
  // Records the barriers a use needs (queued until FlushBarriers); a list
  // records them against its own view of the resource's state.
  virtual void UseTexture(TextureCore* t, const SubresourceRange& range, const Usage& u) = 0;
  virtual void UseBuffer(VkBuffer buf, SyncState& s, const Usage& u) = 0;
  // A CPU-visible use of a resource (GpuUse): recorded at the call on the
  // immediate context, at ExecuteCommandList for a list (its frame is known
  // only then).
  virtual void NoteUse(GpuUse& u, bool write) = 0;
  // A list holds a reference to each object its commands use; the frame
  // needs none (the application's bindings hold them until it is submitted).
  virtual void Hold(Unknown* object) = 0;
  // A pin dropped (Pins.h): the immediate context releases it, a deferred
  // context hands it to its list, which then holds every object bound while it
  // was recorded; so draws and dispatches need no reference of their own.
  virtual void Unpinned(const PinTable::Entry& e) { e.release(e.object); }
  // The descriptor pools sets come from: the frame slot's, or the list's
  // (freed with it); `countStats`: DEVICE_STATS counts them (the immediate
  // context's thread only).
  struct DescriptorPools {
    std::vector<VkDescriptorPool>& pools;
    size_t& current;
    bool countStats;
  };
  virtual DescriptorPools SetPools() = 0;
  // The pipeline layout sets are bound with (a list binds with its context's
  // twin of it, ProgramLayout::listLayouts).
  virtual VkPipelineLayout BindingLayout(const ProgramLayout& p) = 0;
  // The set layout its descriptor sets are allocated with (BindingLayout's).
  virtual VkDescriptorSetLayout SetLayout(const ProgramLayout& p) = 0;
  // The ring slice with a constant buffer's data for this context's commands:
  // the buffer's own (uploaded from its shadow first) or the list's.
  virtual const RingAlloc& CbRing(BufferImpl* b) = 0;
  // The slice of a DYNAMIC vertex/index buffer's last Map(WRITE_DISCARD): the
  // buffer's own (the immediate context reports one from an earlier frame)
  // or the list's.
  virtual const RingAlloc& DynRing(const BufferImpl* b) = 0;
  bool AllocateTimestamp(QueryImpl* q, uint32_t* index);

  // Barriers.cpp
  void FlushBarriers();
  bool HasPendingBarriers() const { return !barriers_.Empty(); }

  // ContextState.cpp
  // Stores `value` in a slot, pinning it first (Pins.h); nothing happens when
  // it is there already.
  template <class T>
  void Bind(Bound<T>& slot, T* value) {
    if (slot.Get() == value) return;
    if (value && cmd_ == VK_NULL_HANDLE) OpenList();  // a new list starts with its first bind
    slot.Set(value);
    if (value && pins_.Pin(value) && pins_.size() > kPinsBeforeCompaction) CompactPins();
  }
  static constexpr size_t kPinsBeforeCompaction = 4096;
  void PinBoundState();  // pins what the slots hold (a list's end that keeps the state)
  void SetShader(ShaderStage stage, ShaderBase* shader);
  void SetCBs(ShaderStage stage, UINT start, UINT num, Buffer* const* buffers);
  void SetSRVs(ShaderStage stage, UINT start, UINT num, ShaderResourceView* const* views);
  void SetSamplers(ShaderStage stage, UINT start, UINT num, SamplerState* const* samplers);
  void UnbindAliasedSRVs();
  bool BoundForOutput(const ViewCore& v) const;
  void CreateDefaultStates();
  ShaderStageState& Stage(ShaderStage s) { return state_.stages[s]; }
  const ShaderStageState& Stage(ShaderStage s) const { return state_.stages[s]; }
  // Sets the dirty bits of a change to `s`'s state (graphics bits, or their
  // compute counterparts for the compute stage).
  void MarkDirty(ShaderStage s, uint32_t graphicsBits) { dirty_ |= DirtyBits(s, graphicsBits); }

  // ContextCompute.cpp
  void SetUavs(Bound<UAVImpl>* slots, const char* fn, UINT start, UINT num, UnorderedAccessView* const* views);
  bool CommitCompute();
  bool CheckUavs(const ProgramLayout& p, ShaderStage stage);
  void UseShaderViews(const ProgramLayout& p, ShaderStage stage);
  UAVImpl* UavAt(ShaderStage s, uint32_t slot) const { return Stage(s).uavs[slot].Get(); }
  void ClearUav(UAVImpl* v, const VkClearColorValue& value, uint32_t fill);

  // ContextStages.cpp: the bound state a draw's checks look at.
  DrawInputs DrawInputsOf(bool indexed) const;
  // QueryStatistics.cpp: one pipeline statistics query is active at a time;
  // a frame end ends it (a Vulkan query cannot span command buffers).
  void BeginStatistics(QueryImpl* q);
  void EndStatistics(QueryImpl* q);
  void CutStatisticsAtFrameEnd();
  QueryImpl* activeStatistics_ = nullptr;  // referenced while active

  // ContextDraw.cpp
  inline bool Commit(bool indexed);
  bool CommitSlow(bool indexed);
  // The argument buffer of an indirect draw or dispatch (`argBytes` read at
  // `offset`), checked (null: the call is dropped), held by a list and queued
  // for its DRAW_INDIRECT barrier, which the commit then records outside any
  // rendering scope.
  BufferImpl* UseIndirectArgs(const char* fn, Buffer* args, UINT offset, UINT argBytes);
  bool CheckDrawState(bool indexed);
  void UseDrawResources(bool indexed);
  bool BindPipeline(VkCommandBuffer cmd);
  void SetDynamicState(VkCommandBuffer cmd);
  void BindVertexBuffers(VkCommandBuffer cmd);
  bool BindIndexBuffer(VkCommandBuffer cmd);
  bool BindDescriptors(VkCommandBuffer cmd);
  inline bool BindConstantsHot(VkCommandBuffer cmd);
  inline bool RebindWithNewOffsets(VkCommandBuffer cmd, VkPipelineBindPoint point, BoundDescriptors& d);
  // The program's descriptor set (new when `changed` or a CB moved), bound
  // with this call's dynamic offsets at `point` (graphics or compute).
  bool BindSet(VkCommandBuffer cmd, VkPipelineBindPoint point, const ProgramLayout& p, BoundDescriptors& d,
               bool changed);
  bool WriteSet(const ProgramLayout& p, BoundDescriptors& d);
  PerStage<ShaderBase*> BoundShaders() const;
  RasterizerImpl* Rasterizer() const { return state_.rs.state ? state_.rs.state.Get() : defaults_.raster.Get(); }
  bool BeginRendering();
  void EndRendering();
  bool TargetSize(uint32_t* w, uint32_t* h) const;
  uint32_t TargetLayers() const;
  uint32_t TargetSamples() const;
  void ErrorOnce(OnceError e);
  void MarkDirtyAll();

  // ContextClear.cpp
  void ClearRectsInScope(uint32_t attachment, VkImageAspectFlags aspect, const VkClearValue& v,
                         const RECT* rects, UINT numRects, uint32_t w, uint32_t h);
  void ClearUnboundView(RTVImpl* v, const VkClearValue& cv, const RECT* rects, UINT numRects);
  int BoundRenderTargetSlot(const RTVImpl* v) const;
  // Whether `list` was recorded on this context's device (false when null).
  bool OwnList(const CommandList* list) const {
    return list && static_cast<const CommandListImpl*>(list)->dev() == dev_;
  }

  // ContextMap.cpp
  HRESULT MapDiscardConstants(BufferImpl* b, MAPPED_SUBRESOURCE* mapped);
  void ListDiscarded(BufferImpl* b);
  void SaveDiscardedConstants();
  HRESULT MapBuffer(BufferImpl* b, MAP type, UINT flags, MAPPED_SUBRESOURCE* mapped);
  HRESULT MapTexture(TextureCore* t, UINT sub, MAP type, UINT flags, MAPPED_SUBRESOURCE* mapped);
  HRESULT MapConstantShadow(BufferImpl* b, MAPPED_SUBRESOURCE* mapped);
  HRESULT MapRingBuffer(BufferImpl* b, MAP type, MAPPED_SUBRESOURCE* mapped);
  HRESULT MapStagingBuffer(BufferImpl* b, MAP type, UINT flags, MAPPED_SUBRESOURCE* mapped);
  HRESULT MapStagingTexture(TextureCore* t, UINT sub, MAP type, UINT flags,
                            MAPPED_SUBRESOURCE* mapped);
  HRESULT MapRingTexture(TextureCore* t, UINT sub, MAPPED_SUBRESOURCE* mapped);
  void UnmapRingTexture(TextureCore* t, UINT sub);
  bool WaitForResource(uint64_t lastUse, UINT flags, HRESULT* hr);
  void UpdateBuffer(BufferImpl* b, UINT lo, UINT hi, const void* data);
  void UpdateTexture(TextureCore* t, UINT sub, const BOX& box, const void* data, UINT rowPitch);
  void CopyFromRing(TextureCore* t, const SubIndex& si, const RingAlloc& a, const BOX& box);

  // ContextCopy.cpp
  void CopyBufferRegion(BufferImpl* dst, UINT dstX, BufferImpl* src, const BOX* box);
  void CopyTextureRegion(TextureCore* dst, UINT dstSub, UINT x, UINT y, TextureCore* src,
                         UINT srcSub, const BOX* box);
  void CopyImageToImage(TextureCore* dst, SubIndex ds, UINT x, UINT y, TextureCore* src,
                        SubIndex ss, const BOX& b);
  void CopyImageToStaging(TextureCore* dst, UINT dstSub, UINT x, UINT y, TextureCore* src,
                          SubIndex ss, const BOX& b);
  void CopyStagingToImage(TextureCore* dst, SubIndex ds, UINT x, UINT y, TextureCore* src,
                          UINT srcSub, const BOX& b);

  // The command buffer being recorded: this frame's, or the deferred list's.
  // Null on a deferred context between FinishCommandList and the next list's
  // first bind or command, which take its recording (OpenList): the recycled
  // recording's reset then runs while the application sets the next list's
  // state, not in FinishCommandList.
  VkCommandBuffer Cmd() {
    if (cmd_ == VK_NULL_HANDLE) [[unlikely]]
      OpenList();
    return cmd_;
  }
  virtual void OpenList() {}

  DeviceImpl* dev_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;  // read through Cmd() where a command is recorded

  // Committed state of the current command buffer (the hot path first).
  uint32_t dirty_ = kAll;
  bool rendering_ = false;
  BoundDescriptors desc_;
  BarrierBatch barriers_;
  uint32_t renderW_ = 0, renderH_ = 0;
  uint32_t renderLayers_ = 1;  // array slices of the rendering scope (the bound views' fewest)
  ProgramLayout* program_ = nullptr;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  PipelineKey key_{};      // the bound pipeline's
  PipelineKey nextKey_{};  // built by BindPipeline, compared with key_
  PipelineCacheFront pipelineFront_;  // this context's memo of the shared cache
  int labelDepth_ = 0;
  uint32_t errorsLogged_ = 0;  // bits of OnceError

  // The compute bind point's committed state (its dirty bits are in dirty_).
  ProgramLayout* computeProgram_ = nullptr;
  VkPipeline computePipeline_ = VK_NULL_HANDLE;
  BoundDescriptors computeDesc_;

  ContextState state_;
  PinTable pins_;  // one reference to each object state_ holds, or held since the last compaction
  // Default states (D3D11 defaults), used when nullptr is bound.
  struct {
    ComPtr<RasterizerImpl> raster;
    ComPtr<BlendImpl> blend;
    ComPtr<DepthStencilImpl> depth;
  } defaults_;

  std::vector<CommandFrame> frames_;  // one per frame slot of the queue
  // Constant buffers Map(WRITE_DISCARD)ed this frame keep their latest data
  // only in the ring: copied back to their shadows before the frame ends
  // (no references held; see ForgetDiscardedConstants).
  std::vector<BufferImpl*> discardedCBs_;

  // DEVICE_STATS::DrawCalls: a list's draws are counted when it is executed.
  void CountDraw() { ++*drawCount_; }
  // The device's counter (immediate) or the list's (deferred, set when a
  // list begins), so that counting a draw needs no test.
  uint64_t* drawCount_ = &dev_->stats.DrawCalls;
};

// Pipeline statistics queries (QueryStatistics.cpp): the query's pool, and
// its counters once the frame that ended it has completed (S_FALSE before).
bool CreateStatisticsPool(DeviceImpl* dev, QueryImpl* q);
HRESULT ReadStatistics(DeviceImpl& dev, QueryImpl* q, void* data);

// An attachment of a rendering scope that keeps its contents (D3D11 targets
// are never discarded).
inline VkRenderingAttachmentInfo LoadStoreAttachment(VkImageView view, VkImageLayout layout) {
  VkRenderingAttachmentInfo att{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  att.imageView = view;
  att.imageLayout = layout;
  att.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  return att;
}

// Draw-time commit. Hot path: nothing but constant data changed since the last
// successful commit, inside the same rendering scope. Every setter that could
// change the outcome of CommitSlow's checks, barriers or bindings sets another
// dirty bit (kIndexBuffer matters only to indexed draws).
inline bool ContextImpl::Commit(bool indexed) {
  const uint32_t ignored = indexed ? uint32_t(kConstants) : uint32_t(kConstants | kIndexBuffer);
  if ((dirty_ & kGraphicsDirty & ~ignored) != 0 || !rendering_ || HasPendingBarriers()) return CommitSlow(indexed);
  if ((dirty_ & kConstants) && !BindConstantsHot(Cmd())) return false;
  dirty_ &= indexed ? uint32_t(kComputeDirty) : uint32_t(kComputeDirty | kIndexBuffer);
  return true;
}

// Same descriptor set and CB bindings as the last BindDescriptors: only the
// dynamic offsets change (unless a CB's ring slice moved to another chunk).
inline bool ContextImpl::BindConstantsHot(VkCommandBuffer cmd) {
  if (!desc_.hotLayout) return true;
  return RebindWithNewOffsets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, desc_) || BindDescriptors(cmd);
}

// The set `d` last bound, rebound with the CBs' current ring offsets; false
// (nothing recorded) when a CB's slice moved to another ring chunk.
inline bool ContextImpl::RebindWithNewOffsets(VkCommandBuffer cmd, VkPipelineBindPoint point, BoundDescriptors& d) {
  for (uint32_t i = 0; i < d.nHotCbs; ++i) {
    BufferImpl* b = d.hotCbs[i];
    if (!b) continue;  // the dummy buffer: offset 0
    const RingAlloc& r = CbRing(b);
    if (r.buffer != d.cbBuffers[i]) return false;
    d.dynOffsets[i] = static_cast<uint32_t>(r.offset);
  }
  vkCmdBindDescriptorSets(cmd, point, d.hotLayout, 0, 1, &d.set, d.nHotCbs, d.dynOffsets);
  return true;
}

}  // namespace d3dl::impl
