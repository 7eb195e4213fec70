// The immediate context: D3D11-style state recording over one Vulkan command
// buffer per frame. Split over ContextState.cpp (setters), ContextDraw.cpp
// (commit, rendering scopes, clears), ContextCopy.cpp (map/update/copy) and
// ContextQuery.cpp (queries, debug labels).
#pragma once

#include "Internal.h"

namespace d3dl::impl {

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
};

class ContextImpl final : public DeviceContext {
 public:
  explicit ContextImpl(DeviceImpl* dev);
  ~ContextImpl();
  UINT AddRef() override { return dev_->AddRef(); }
  UINT Release() override { return dev_->Release(); }

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
  void BlitRegion(Texture2D* dst, const RECT& dstRect, Texture2D* src, const RECT& srcRect,
                  FILTER filter) override;  // ContextBlit.cpp

  // ---- backend internals
  void OnFrameBegin();  // a fresh command buffer: everything is re-bound lazily
  void EndRendering();
  // Records the barrier `u` needs on a texture range (queued until FlushBarriers).
  void UseTexture(TextureCore* t, uint32_t baseMip, uint32_t mips, uint32_t baseLayer,
                  uint32_t layers, const Usage& u);
  void UseBuffer(VkBuffer buf, SyncState& s, const Usage& u);
  void FlushBarriers();
  bool HasPendingBarriers() const { return !imageBarriers_.empty() || !bufferBarriers_.empty(); }
  void MarkDirtyAll();
  void InvalidateTexture(TextureCore* t);  // a texture's layout changed behind our back
  bool IsRendering() const { return rendering_; }
  // Constant buffers Map(WRITE_DISCARD)ed this frame keep their latest data
  // only in the ring: copied back to their shadows before the frame ends.
  void SaveDiscardedConstants();
  void ForgetDiscardedConstants(BufferImpl* b);  // `b` is being destroyed

 private:
  enum Dirty : uint32_t {
    kPipeline = 1u << 0,
    kVertexBuffers = 1u << 1,
    kIndexBuffer = 1u << 2,
    kViewport = 1u << 3,
    kScissor = 1u << 4,
    kBlendConst = 1u << 5,
    kStencilRef = 1u << 6,
    kDescriptors = 1u << 7,  // SRV/sampler/CB identity
    kConstants = 1u << 8,    // only constant data changed
    kSrvLayouts = 1u << 9,   // some texture changed layout: re-check SRVs
    kProgram = 1u << 10,
    kTopology = 1u << 11,
    kCbSlots = 1u << 12,     // a CB slot was (re)bound: hotCbs_ is out of date
    kAll = 0xffffffffu,
  };

  inline bool Commit(bool indexed);
  bool CommitSlow(bool indexed);
  bool BindDescriptors(VkCommandBuffer cmd);
  inline bool BindConstantsHot(VkCommandBuffer cmd);
  void ListDiscarded(BufferImpl* b);
  bool WriteNewSet();
  HRESULT MapDiscardConstants(BufferImpl* b, MAPPED_SUBRESOURCE* mapped);
  bool BeginRendering();
  void ErrorOnce(uint32_t bit, const char* msg);
  void SetCBs(uint32_t stage, UINT start, UINT num, Buffer* const* buffers);
  void SetSRVs(uint32_t stage, UINT start, UINT num, ShaderResourceView* const* views);
  void SetSamplers(uint32_t stage, UINT start, UINT num, SamplerState* const* samplers);
  void ClearRectsInScope(uint32_t attachment, VkImageAspectFlags aspect, const VkClearValue& v,
                         const RECT* rects, UINT numRects, uint32_t w, uint32_t h);
  bool TargetSize(uint32_t* w, uint32_t* h) const;
  bool WaitForResource(uint64_t lastUse, UINT flags, HRESULT* hr);
  void CopyTextureRegion(TextureCore* dst, UINT dstSub, UINT x, UINT y, TextureCore* src,
                         UINT srcSub, const BOX* box);
  void CopyBufferRegion(BufferImpl* dst, UINT dstX, BufferImpl* src, const BOX* box);
  void UpdateTexture(TextureCore* t, UINT sub, const BOX* box, const void* data, UINT rowPitch);

  DeviceImpl* dev_;

  // Bound state (references held, as D3D11 does).
  struct VB {
    BufferImpl* buffer = nullptr;
    UINT stride = 0;
    UINT offset = 0;
  };
  InputLayoutImpl* il_ = nullptr;
  VB vbs_[IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT];
  BufferImpl* ib_ = nullptr;
  VkIndexType ibType_ = VK_INDEX_TYPE_UINT16;
  UINT ibOffset_ = 0;
  PRIMITIVE_TOPOLOGY topology_ = PRIMITIVE_TOPOLOGY_UNDEFINED;
  VertexShaderImpl* vs_ = nullptr;
  PixelShaderImpl* ps_ = nullptr;
  BufferImpl* cbs_[2][kMaxConstantBufferSlots] = {};
  SRVImpl* srvs_[2][kMaxTextureSlots] = {};
  SamplerImpl* samplers_[2][kMaxSamplerSlots] = {};
  VIEWPORT viewport_{};
  UINT numViewports_ = 0;
  RECT scissor_{};
  UINT numScissors_ = 0;
  RasterizerImpl* raster_ = nullptr;
  BlendImpl* blend_ = nullptr;
  float blendFactor_[4] = {1, 1, 1, 1};
  DepthStencilImpl* depth_ = nullptr;
  UINT stencilRef_ = 0;
  RTVImpl* rtvs_[SIMULTANEOUS_RENDER_TARGET_COUNT] = {};
  UINT numRT_ = 0;
  DSVImpl* dsv_ = nullptr;

  // Default states (D3D11 defaults), used when nullptr is bound.
  RasterizerImpl* defRaster_ = nullptr;
  BlendImpl* defBlend_ = nullptr;
  DepthStencilImpl* defDepth_ = nullptr;

  // Committed state of the current command buffer.
  uint32_t dirty_ = kAll;
  uint32_t errorsLogged_ = 0;
  bool rendering_ = false;
  uint32_t renderW_ = 0, renderH_ = 0;
  ProgramLayout* program_ = nullptr;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  PipelineKey key_{};
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkBuffer setCbBuffers_[2 * kMaxConstantBufferSlots] = {};
  uint32_t setCbRanges_[2 * kMaxConstantBufferSlots] = {};
  uint32_t dynOffsets_[2 * kMaxConstantBufferSlots] = {};
  // What BindDescriptors last bound, for BindConstantsHot: the program's CBs
  // in binding order (null: dummy) and its layout (null: no descriptor set).
  BufferImpl* hotCbs_[2 * kMaxConstantBufferSlots] = {};
  uint32_t nHotCbs_ = 0;
  VkPipelineLayout hotLayout_ = VK_NULL_HANDLE;
  int labelDepth_ = 0;

  std::vector<VkImageMemoryBarrier2> imageBarriers_;
  std::vector<VkBufferMemoryBarrier2> bufferBarriers_;
  std::vector<BufferImpl*> discardedCBs_;  // see SaveDiscardedConstants (no references held)
};

// Draw-time commit. Hot path: nothing but constant data changed since the last
// successful commit, inside the same rendering scope. Every setter that could
// change the outcome of CommitSlow's checks, barriers or bindings sets another
// dirty bit (kIndexBuffer matters only to indexed draws).
inline bool ContextImpl::Commit(bool indexed) {
  const uint32_t ignored = indexed ? uint32_t(kConstants) : uint32_t(kConstants | kIndexBuffer);
  if ((dirty_ & ~ignored) != 0 || !rendering_ || HasPendingBarriers()) return CommitSlow(indexed);
  if ((dirty_ & kConstants) && !BindConstantsHot(dev_->Cmd())) return false;
  dirty_ &= indexed ? 0u : uint32_t(kIndexBuffer);
  return true;
}

// Same descriptor set and CB bindings as the last BindDescriptors: only the
// dynamic offsets change (unless a CB's ring slice moved to another chunk).
inline bool ContextImpl::BindConstantsHot(VkCommandBuffer cmd) {
  if (!hotLayout_) return true;
  for (uint32_t i = 0; i < nHotCbs_; ++i) {
    BufferImpl* b = hotCbs_[i];
    if (!b) continue;  // the dummy buffer: offset 0
    b->EnsureUploaded();
    if (b->ring.buffer != setCbBuffers_[i]) return BindDescriptors(cmd);
    dynOffsets_[i] = static_cast<uint32_t>(b->ring.offset);
  }
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, hotLayout_, 0, 1, &set_, nHotCbs_, dynOffsets_);
  return true;
}

template <class T>
inline void SetRef(T*& slot, T* value) {
  if (slot == value) return;
  if (value) value->AddRef();
  if (slot) slot->Release();
  slot = value;
}

}  // namespace d3dl::impl
