// Context state setters: they only store state (pinning objects) and set
// dirty bits; Commit() in ContextDraw.cpp turns them into Vulkan commands.
// Arguments are checked by Validate*.cpp first.
#include <algorithm>

#include "Context.h"
#include "Topology.h"
#include "Validate.h"

namespace d3dl::impl {
void ContextImpl::CreateDefaultStates() {
  RASTERIZER_DESC rd;
  BLEND_DESC bd;
  DEPTH_STENCIL_DESC dd;
  RasterizerState* r = nullptr;
  BlendState* b = nullptr;
  DepthStencilState* d = nullptr;
  dev_->CreateRasterizerState(&rd, &r);
  dev_->CreateBlendState(&bd, &b);
  dev_->CreateDepthStencilState(&dd, &d);
  defaults_.raster = ComPtr<RasterizerImpl>(static_cast<RasterizerImpl*>(r), false);
  defaults_.blend = ComPtr<BlendImpl>(static_cast<BlendImpl*>(b), false);
  defaults_.depth = ComPtr<DepthStencilImpl>(static_cast<DepthStencilImpl*>(d), false);
}

void ContextImpl::MarkDirtyAll() {
  dirty_ = kAll;
  pipeline_ = VK_NULL_HANDLE;
  desc_.set = VK_NULL_HANDLE;
  std::fill(std::begin(desc_.cbBuffers), std::end(desc_.cbBuffers), VK_NULL_HANDLE);
  computePipeline_ = VK_NULL_HANDLE;
  computeDesc_ = BoundDescriptors{};
}

void ContextImpl::IASetInputLayout(InputLayout* layout) {
  auto* il = static_cast<InputLayoutImpl*>(layout);
  if (il == state_.ia.layout.Get()) return;
  Bind(state_.ia.layout, il);
  dirty_ |= kPipeline | kVertexBuffers;
}

void ContextImpl::IASetVertexBuffers(UINT start, UINT num, Buffer* const* buffers, const UINT* strides,
                                     const UINT* offsets) {
  if (!ValidateSlots(*dev_, "IA", "SetVertexBuffers", start, num, IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT)) return;
  bool changed = false;  // re-binding the bound buffers leaves the draw on its fast path
  for (UINT i = 0; i < num; ++i) {
    auto& v = state_.ia.vertexBuffers[start + i];
    auto* b = static_cast<BufferImpl*>(buffers ? buffers[i] : nullptr);
    if (!ValidateVertexBuffer(*dev_, b ? &b->desc() : nullptr, start + i)) b = nullptr;
    const UINT stride = strides ? strides[i] : 0, offset = offsets ? offsets[i] : 0;
    if (v.buffer.Get() == b && v.stride == stride && v.offset == offset) continue;
    Bind(v.buffer, b);
    v.stride = stride;
    v.offset = offset;
    changed = true;
  }
  if (changed) dirty_ |= kVertexBuffers;
}

void ContextImpl::IASetIndexBuffer(Buffer* buffer, DXGI_FORMAT format, UINT offset) {
  auto* b = static_cast<BufferImpl*>(buffer);
  if (!ValidateIndexBuffer(*dev_, b ? &b->desc() : nullptr, format)) b = nullptr;
  const VkIndexType type = format == DXGI_FORMAT_R32_UINT ? VK_INDEX_TYPE_UINT32 : VK_INDEX_TYPE_UINT16;
  InputAssemblerState& ia = state_.ia;
  if (ia.indexBuffer.Get() == b && ia.indexType == type && ia.indexOffset == offset) return;
  Bind(ia.indexBuffer, b);
  ia.indexType = type;
  ia.indexOffset = offset;
  dirty_ |= kIndexBuffer;
}

// Pipelines are built per point / line / triangle / patch class (and patch
// size); the exact topology is dynamic state.
void ContextImpl::IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY t) {
  if (!ValidateTopology(*dev_, t)) return;
  PRIMITIVE_TOPOLOGY& current = state_.ia.topology;
  if (t == current) return;
  if (TopologyClass(t) != TopologyClass(current) || PatchControlPoints(t) != PatchControlPoints(current) ||
      current == PRIMITIVE_TOPOLOGY_UNDEFINED)
    dirty_ |= kPipeline;
  current = t;
  dirty_ |= kTopology;
}

void ContextImpl::SetShader(ShaderStage stage, ShaderBase* shader) {
  Bound<ShaderBase>& slot = Stage(stage).shader;
  if (shader == slot.Get()) return;
  Bind(slot, shader);
  MarkDirty(stage, kProgram | kPipeline);
}
void ContextImpl::VSSetShader(VertexShader* s) { SetShader(ShaderStage::Vertex, static_cast<VertexShaderImpl*>(s)); }
void ContextImpl::PSSetShader(PixelShader* s) { SetShader(ShaderStage::Pixel, static_cast<PixelShaderImpl*>(s)); }

void ContextImpl::SetCBs(ShaderStage stage, UINT start, UINT num, Buffer* const* buffers) {
  if (!ValidateSlots(*dev_, StagePrefix(stage), "SetConstantBuffers", start, num, kMaxConstantBufferSlots))
    return;
  auto& slots = Stage(stage).constantBuffers;
  bool changed = false;
  for (UINT i = 0; i < num; ++i) {
    auto* b = static_cast<BufferImpl*>(buffers ? buffers[i] : nullptr);
    if (!ValidateConstantBuffer(*dev_, stage, b ? &b->desc() : nullptr, start + i)) b = nullptr;
    changed = changed || slots[start + i].Get() != b;
    Bind(slots[start + i], b);
  }
  MarkDirty(stage, changed ? uint32_t(kConstants | kCbSlots) : uint32_t(kConstants));
}
void ContextImpl::VSSetConstantBuffers(UINT s, UINT n, Buffer* const* b) { SetCBs(ShaderStage::Vertex, s, n, b); }
void ContextImpl::PSSetConstantBuffers(UINT s, UINT n, Buffer* const* b) { SetCBs(ShaderStage::Pixel, s, n, b); }

void ContextImpl::SetSRVs(ShaderStage stage, UINT start, UINT num, ShaderResourceView* const* views) {
  if (!ValidateSlots(*dev_, StagePrefix(stage), "SetShaderResources", start, num, kMaxTextureSlots)) return;
  auto& slots = Stage(stage).shaderResources;
  bool changed = false;  // the same views again keep the descriptor set
  for (UINT i = 0; i < num; ++i) {
    auto* v = views ? static_cast<SRVImpl*>(views[i]) : nullptr;
    if (v && BoundForOutput(v->v)) {
      // D3D11 hazard rule: a resource bound for output cannot be bound as input.
      dev_->Log(LogLevel::Warning, "%sSetShaderResources: slot %u: the %s is bound as a render target or UAV; bound as null",
                StagePrefix(stage), start + i, v->v.tex ? "texture" : "buffer");
      v = nullptr;
    }
    changed = changed || slots[start + i].Get() != v;
    Bind(slots[start + i], v);
  }
  if (changed) MarkDirty(stage, kDescriptors);
}
void ContextImpl::VSSetShaderResources(UINT s, UINT n, ShaderResourceView* const* v) { SetSRVs(ShaderStage::Vertex, s, n, v); }
void ContextImpl::PSSetShaderResources(UINT s, UINT n, ShaderResourceView* const* v) { SetSRVs(ShaderStage::Pixel, s, n, v); }

void ContextImpl::SetSamplers(ShaderStage stage, UINT start, UINT num, SamplerState* const* samplers) {
  if (!ValidateSlots(*dev_, StagePrefix(stage), "SetSamplers", start, num, kMaxSamplerSlots)) return;
  auto& slots = Stage(stage).samplers;
  bool changed = false;
  for (UINT i = 0; i < num; ++i) {
    auto* smp = samplers ? static_cast<SamplerImpl*>(samplers[i]) : nullptr;
    changed = changed || slots[start + i].Get() != smp;
    Bind(slots[start + i], smp);
  }
  if (changed) MarkDirty(stage, kDescriptors);
}
void ContextImpl::VSSetSamplers(UINT s, UINT n, SamplerState* const* v) { SetSamplers(ShaderStage::Vertex, s, n, v); }
void ContextImpl::PSSetSamplers(UINT s, UINT n, SamplerState* const* v) { SetSamplers(ShaderStage::Pixel, s, n, v); }

void ContextImpl::RSSetViewports(UINT num, const VIEWPORT* viewports) {
  if (!ValidateViewports(*dev_, num, viewports)) return;
  state_.rs.numViewports = num ? 1 : 0;
  if (num) state_.rs.viewport = viewports[0];
  dirty_ |= kViewport;
}

void ContextImpl::RSSetScissorRects(UINT num, const RECT* rects) {
  if (!ValidateScissorRects(*dev_, num, rects)) return;
  state_.rs.numScissors = num ? 1 : 0;
  if (num) state_.rs.scissor = rects[0];
  dirty_ |= kScissor;
}

void ContextImpl::RSSetState(RasterizerState* state) {
  auto* s = static_cast<RasterizerImpl*>(state);
  if (s == state_.rs.state.Get()) return;
  Bind(state_.rs.state, s);
  dirty_ |= kPipeline | kScissor;
}

void ContextImpl::OMSetBlendState(BlendState* state, const float factor[4], UINT sampleMask) {
  OutputMergerState& om = state_.om;
  auto* s = static_cast<BlendImpl*>(state);
  if (s != om.blend.Get()) {
    Bind(om.blend, s);
    dirty_ |= kPipeline;
  }
  if (sampleMask != om.sampleMask) {  // part of the pipeline (VkPipelineMultisampleStateCreateInfo)
    om.sampleMask = sampleMask;
    dirty_ |= kPipeline;
  }
  const float one[4] = {1, 1, 1, 1};
  std::memcpy(om.blendFactor, factor ? factor : one, sizeof(om.blendFactor));
  dirty_ |= kBlendConst;
}

void ContextImpl::OMSetDepthStencilState(DepthStencilState* state, UINT stencilRef) {
  OutputMergerState& om = state_.om;
  auto* s = static_cast<DepthStencilImpl*>(state);
  if (s != om.depthStencil.Get()) {
    Bind(om.depthStencil, s);
    dirty_ |= kPipeline;
  }
  if (stencilRef != om.stencilRef) {
    om.stencilRef = stencilRef;
    dirty_ |= kStencilRef;
  }
}

void ContextImpl::OMSetRenderTargets(UINT num, RenderTargetView* const* rtvs, DepthStencilView* dsv) {
  if (!ValidateRenderTargets(*dev_, num, rtvs)) return;
  UINT rtvSamples[SIMULTANEOUS_RENDER_TARGET_COUNT] = {};
  for (UINT i = 0; i < num; ++i)
    if (rtvs[i]) rtvSamples[i] = static_cast<RTVImpl*>(rtvs[i])->v.Samples();
  if (!ValidateTargetSamples(*dev_, num, rtvSamples, dsv ? static_cast<DSVImpl*>(dsv)->v.Samples() : 0)) return;
  OutputMergerState& om = state_.om;
  RTVImpl* newRt[SIMULTANEOUS_RENDER_TARGET_COUNT] = {};
  for (UINT i = 0; i < num; ++i) newRt[i] = static_cast<RTVImpl*>(rtvs[i]);
  auto* newDs = static_cast<DSVImpl*>(dsv);
  bool same = newDs == om.depthStencilView.Get();
  for (UINT i = 0; i < SIMULTANEOUS_RENDER_TARGET_COUNT; ++i) same = same && newRt[i] == om.renderTargets[i].Get();
  if (same) return;
  EndRendering();
  om.numRenderTargets = 0;
  for (UINT i = 0; i < SIMULTANEOUS_RENDER_TARGET_COUNT; ++i) {
    Bind(om.renderTargets[i], newRt[i]);
    if (newRt[i]) om.numRenderTargets = i + 1;
  }
  Bind(om.depthStencilView, newDs);
  UnbindAliasedSRVs();
  dirty_ |= kPipeline | kScissor | kViewport;
}

// D3D11 hazard rule: shader inputs that alias an output are unbound.
void ContextImpl::UnbindAliasedSRVs() {
  for (ShaderStage s : kAllStages)
    for (auto& srv : Stage(s).shaderResources)
      if (srv && BoundForOutput(srv->v)) {
        srv = nullptr;
        MarkDirty(s, kDescriptors);
      }
}

// Whether this context writes the viewed resource: a render target, the depth
// buffer or a UAV (compute or pixel stage). Hazards are per context: another
// thread's deferred context may write the resource meanwhile.
bool ContextImpl::BoundForOutput(const ViewCore& v) const {
  const OutputMergerState& om = state_.om;
  if (v.tex) {
    for (uint32_t i = 0; i < om.numRenderTargets; ++i)
      if (om.renderTargets[i] && om.renderTargets[i]->v.tex == v.tex) return true;
    if (om.depthStencilView && om.depthStencilView->v.tex == v.tex) return true;
  }
  for (const Bound<UAVImpl>* slots : {Stage(ShaderStage::Compute).uavs, Stage(ShaderStage::Pixel).uavs})
    for (uint32_t i = 0; i < kMaxUnorderedAccessSlots; ++i)
      if (slots[i] && (v.tex ? slots[i]->v.tex == v.tex : slots[i]->v.buf == v.buf)) return true;
  return false;
}

void ContextImpl::OMGetRenderTargets(UINT num, RenderTargetView** rtvs, DepthStencilView** dsv) {
  const OutputMergerState& om = state_.om;
  for (UINT i = 0; rtvs && i < num; ++i) {
    rtvs[i] = i < SIMULTANEOUS_RENDER_TARGET_COUNT ? om.renderTargets[i].Get() : nullptr;
    if (rtvs[i]) rtvs[i]->AddRef();
  }
  if (dsv) {
    *dsv = om.depthStencilView.Get();
    if (*dsv) (*dsv)->AddRef();
  }
}

void ContextImpl::ClearState() {
  EndRendering();
  OMSetRenderTargets(0, nullptr, nullptr);  // ends the rendering scope
  CSSetUnorderedAccessViews(0, kMaxUnorderedAccessSlots, nullptr, nullptr);  // and the UAV counts
  OMSetRenderTargetsAndUnorderedAccessViews(KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL, nullptr, nullptr, 0,
                                            kMaxUnorderedAccessSlots, nullptr, nullptr);
  state_ = ContextState{};
  pins_.DropAll([this](const PinTable::Entry& e) { Unpinned(e); });
  dirty_ = kAll;
}

void ContextImpl::CompactPins() {
  std::vector<const void*> bound;  // as the pointer each slot's type gives
  ForEachBound(state_, [&bound](const auto& slot) { bound.push_back(static_cast<const void*>(slot.Get())); });
  std::sort(bound.begin(), bound.end());
  pins_.DropUnless([&bound](const void* p) { return std::binary_search(bound.begin(), bound.end(), p); },
                   [this](const PinTable::Entry& e) { Unpinned(e); });
}

void ContextImpl::PinBoundState() {
  ForEachBound(state_, [this](const auto& slot) { pins_.Pin(slot.Get()); });
}

}  // namespace d3dl::impl
