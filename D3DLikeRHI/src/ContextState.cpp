// Context state setters: they only store state (holding references) and set
// dirty bits; Commit() in ContextDraw.cpp turns them into Vulkan commands.
#include "Context.h"

namespace d3dl::impl {

ContextImpl::ContextImpl(DeviceImpl* dev) : dev_(dev) {
  imageBarriers_.reserve(32);
  bufferBarriers_.reserve(16);
  RasterizerState* r = nullptr;
  BlendState* b = nullptr;
  DepthStencilState* d = nullptr;
  RASTERIZER_DESC rd;
  BLEND_DESC bd;
  DEPTH_STENCIL_DESC dd;
  dev_->CreateRasterizerState(&rd, &r);
  dev_->CreateBlendState(&bd, &b);
  dev_->CreateDepthStencilState(&dd, &d);
  defRaster_ = static_cast<RasterizerImpl*>(r);
  defBlend_ = static_cast<BlendImpl*>(b);
  defDepth_ = static_cast<DepthStencilImpl*>(d);
}

ContextImpl::~ContextImpl() {
  SaveDiscardedConstants();
  ClearState();
  if (defRaster_) defRaster_->Release();
  if (defBlend_) defBlend_->Release();
  if (defDepth_) defDepth_->Release();
}

void ContextImpl::MarkDirtyAll() {
  dirty_ = kAll;
  pipeline_ = VK_NULL_HANDLE;
  set_ = VK_NULL_HANDLE;
  std::fill(std::begin(setCbBuffers_), std::end(setCbBuffers_), VK_NULL_HANDLE);
}

void ContextImpl::OnFrameBegin() {
  rendering_ = false;
  MarkDirtyAll();
  labelDepth_ = 0;
}

void ContextImpl::IASetInputLayout(InputLayout* layout) {
  auto* il = static_cast<InputLayoutImpl*>(layout);
  if (il == il_) return;
  SetRef(il_, il);
  dirty_ |= kPipeline | kVertexBuffers;
}

void ContextImpl::IASetVertexBuffers(UINT start, UINT num, Buffer* const* buffers, const UINT* strides,
                                     const UINT* offsets) {
  if (start >= IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT || num > IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT - start) {
    dev_->Log(LogLevel::Error, "IASetVertexBuffers: slots %u..%u out of range (0..15)", start, start + num);
    return;
  }
  for (UINT i = 0; i < num; ++i) {
    BufferImpl* b = buffers ? static_cast<BufferImpl*>(buffers[i]) : nullptr;
    if (b && !(b->desc_.BindFlags & BIND_VERTEX_BUFFER)) {
      dev_->Log(LogLevel::Error, "IASetVertexBuffers: buffer in slot %u lacks BIND_VERTEX_BUFFER; unbound", start + i);
      b = nullptr;
    }
    VB& v = vbs_[start + i];
    SetRef(v.buffer, b);
    v.stride = strides ? strides[i] : 0;
    v.offset = offsets ? offsets[i] : 0;
  }
  dirty_ |= kVertexBuffers;
}

void ContextImpl::IASetIndexBuffer(Buffer* buffer, DXGI_FORMAT format, UINT offset) {
  auto* b = static_cast<BufferImpl*>(buffer);
  if (b && !(b->desc_.BindFlags & BIND_INDEX_BUFFER)) {
    dev_->Log(LogLevel::Error, "IASetIndexBuffer: buffer lacks BIND_INDEX_BUFFER; unbound");
    b = nullptr;
  }
  if (b && format != DXGI_FORMAT_R16_UINT && format != DXGI_FORMAT_R32_UINT) {
    dev_->Log(LogLevel::Error, "IASetIndexBuffer: Format %s is not R16_UINT or R32_UINT; unbound", FormatName(format));
    b = nullptr;
  }
  SetRef(ib_, b);
  ibType_ = format == DXGI_FORMAT_R32_UINT ? VK_INDEX_TYPE_UINT32 : VK_INDEX_TYPE_UINT16;
  ibOffset_ = offset;
  dirty_ |= kIndexBuffer;
}

void ContextImpl::IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY t) {
  if (t == topology_) return;
  auto cls = [](PRIMITIVE_TOPOLOGY p) {
    return p == PRIMITIVE_TOPOLOGY_POINTLIST ? 0u
           : (p == PRIMITIVE_TOPOLOGY_LINELIST || p == PRIMITIVE_TOPOLOGY_LINESTRIP) ? 1u : 2u;
  };
  if (cls(t) != cls(topology_) || topology_ == PRIMITIVE_TOPOLOGY_UNDEFINED) dirty_ |= kPipeline;
  topology_ = t;
  dirty_ |= kTopology;
}

void ContextImpl::VSSetShader(VertexShader* shader) {
  auto* s = static_cast<VertexShaderImpl*>(shader);
  if (s == vs_) return;
  SetRef(vs_, s);
  dirty_ |= kProgram | kPipeline;
}

void ContextImpl::PSSetShader(PixelShader* shader) {
  auto* s = static_cast<PixelShaderImpl*>(shader);
  if (s == ps_) return;
  SetRef(ps_, s);
  dirty_ |= kProgram | kPipeline;
}

void ContextImpl::SetCBs(uint32_t stage, UINT start, UINT num, Buffer* const* buffers) {
  if (start >= kMaxConstantBufferSlots || num > kMaxConstantBufferSlots - start) {
    dev_->Log(LogLevel::Error, "%sSetConstantBuffers: slots %u..%u out of range (0..13)", stage ? "PS" : "VS", start, start + num);
    return;
  }
  for (UINT i = 0; i < num; ++i) {
    auto* b = buffers ? static_cast<BufferImpl*>(buffers[i]) : nullptr;
    if (b && !b->isConstant) {
      dev_->Log(LogLevel::Error, "%sSetConstantBuffers: buffer in slot %u lacks BIND_CONSTANT_BUFFER; unbound", stage ? "PS" : "VS", start + i);
      b = nullptr;
    }
    SetRef(cbs_[stage][start + i], b);
  }
  dirty_ |= kConstants | kCbSlots;
}
void ContextImpl::VSSetConstantBuffers(UINT s, UINT n, Buffer* const* b) { SetCBs(0, s, n, b); }
void ContextImpl::PSSetConstantBuffers(UINT s, UINT n, Buffer* const* b) { SetCBs(1, s, n, b); }

void ContextImpl::SetSRVs(uint32_t stage, UINT start, UINT num, ShaderResourceView* const* views) {
  if (start >= kMaxTextureSlots || num > kMaxTextureSlots - start) {
    dev_->Log(LogLevel::Error, "%sSetShaderResources: slots %u..%u out of range (0..31)", stage ? "PS" : "VS", start, start + num);
    return;
  }
  for (UINT i = 0; i < num; ++i) {
    auto* v = views ? static_cast<SRVImpl*>(views[i]) : nullptr;
    if (v && v->v.tex->boundAsTarget > 0) {
      // D3D11 hazard rule: a resource bound for output cannot be bound as input.
      dev_->Log(LogLevel::Warning, "%sSetShaderResources: slot %u: the texture is bound as a render target; bound as null",
                stage ? "PS" : "VS", start + i);
      v = nullptr;
    }
    SetRef(srvs_[stage][start + i], v);
  }
  dirty_ |= kDescriptors;
}
void ContextImpl::VSSetShaderResources(UINT s, UINT n, ShaderResourceView* const* v) { SetSRVs(0, s, n, v); }
void ContextImpl::PSSetShaderResources(UINT s, UINT n, ShaderResourceView* const* v) { SetSRVs(1, s, n, v); }

void ContextImpl::SetSamplers(uint32_t stage, UINT start, UINT num, SamplerState* const* samplers) {
  if (start >= kMaxSamplerSlots || num > kMaxSamplerSlots - start) {
    dev_->Log(LogLevel::Error, "%sSetSamplers: slots %u..%u out of range (0..15)", stage ? "PS" : "VS", start, start + num);
    return;
  }
  for (UINT i = 0; i < num; ++i) SetRef(samplers_[stage][start + i], samplers ? static_cast<SamplerImpl*>(samplers[i]) : nullptr);
  dirty_ |= kDescriptors;
}
void ContextImpl::VSSetSamplers(UINT s, UINT n, SamplerState* const* v) { SetSamplers(0, s, n, v); }
void ContextImpl::PSSetSamplers(UINT s, UINT n, SamplerState* const* v) { SetSamplers(1, s, n, v); }

void ContextImpl::RSSetViewports(UINT num, const VIEWPORT* viewports) {
  if (num && !viewports) {
    dev_->Log(LogLevel::Error, "RSSetViewports: pViewports is null");
    return;
  }
  if (num > 1) dev_->Log(LogLevel::Warning, "RSSetViewports: %u viewports; only the first is used", num);
  numViewports_ = num ? 1 : 0;
  if (num) viewport_ = viewports[0];
  dirty_ |= kViewport;
}

void ContextImpl::RSSetScissorRects(UINT num, const RECT* rects) {
  if (num && !rects) {
    dev_->Log(LogLevel::Error, "RSSetScissorRects: pRects is null");
    return;
  }
  numScissors_ = num ? 1 : 0;
  if (num) scissor_ = rects[0];
  dirty_ |= kScissor;
}

void ContextImpl::RSSetState(RasterizerState* state) {
  auto* s = static_cast<RasterizerImpl*>(state);
  if (s == raster_) return;
  SetRef(raster_, s);
  dirty_ |= kPipeline | kScissor;
}

void ContextImpl::OMSetBlendState(BlendState* state, const float factor[4], UINT) {
  auto* s = static_cast<BlendImpl*>(state);
  if (s != blend_) {
    SetRef(blend_, s);
    dirty_ |= kPipeline;
  }
  const float one[4] = {1, 1, 1, 1};
  std::memcpy(blendFactor_, factor ? factor : one, sizeof(blendFactor_));
  dirty_ |= kBlendConst;
}

void ContextImpl::OMSetDepthStencilState(DepthStencilState* state, UINT stencilRef) {
  auto* s = static_cast<DepthStencilImpl*>(state);
  if (s != depth_) {
    SetRef(depth_, s);
    dirty_ |= kPipeline;
  }
  if (stencilRef != stencilRef_) {
    stencilRef_ = stencilRef;
    dirty_ |= kStencilRef;
  }
}

void ContextImpl::OMSetRenderTargets(UINT num, RenderTargetView* const* rtvs, DepthStencilView* dsv) {
  if (num > SIMULTANEOUS_RENDER_TARGET_COUNT || (num && !rtvs)) {
    dev_->Log(LogLevel::Error, "OMSetRenderTargets: %u views (at most 8, array required)", num);
    return;
  }
  RTVImpl* newRt[SIMULTANEOUS_RENDER_TARGET_COUNT] = {};
  for (UINT i = 0; i < num; ++i) newRt[i] = static_cast<RTVImpl*>(rtvs[i]);
  auto* newDs = static_cast<DSVImpl*>(dsv);
  bool same = newDs == dsv_;
  for (UINT i = 0; i < SIMULTANEOUS_RENDER_TARGET_COUNT; ++i) same = same && newRt[i] == rtvs_[i];
  if (same) return;
  EndRendering();
  for (auto* r : rtvs_)
    if (r) --r->v.tex->boundAsTarget;
  if (dsv_) --dsv_->v.tex->boundAsTarget;
  numRT_ = 0;
  for (UINT i = 0; i < SIMULTANEOUS_RENDER_TARGET_COUNT; ++i) {
    SetRef(rtvs_[i], newRt[i]);
    if (newRt[i]) {
      ++newRt[i]->v.tex->boundAsTarget;
      numRT_ = i + 1;
    }
  }
  SetRef(dsv_, newDs);
  if (newDs) ++newDs->v.tex->boundAsTarget;
  // D3D11 hazard rule: shader inputs that alias an output are unbound.
  for (auto& stage : srvs_)
    for (auto*& srv : stage)
      if (srv && srv->v.tex->boundAsTarget > 0) {
        SetRef(srv, static_cast<SRVImpl*>(nullptr));
        dirty_ |= kDescriptors;
      }
  dirty_ |= kPipeline | kScissor | kViewport;
}

void ContextImpl::OMGetRenderTargets(UINT num, RenderTargetView** rtvs, DepthStencilView** dsv) {
  for (UINT i = 0; rtvs && i < num; ++i) {
    rtvs[i] = i < SIMULTANEOUS_RENDER_TARGET_COUNT ? rtvs_[i] : nullptr;
    if (rtvs[i]) rtvs[i]->AddRef();
  }
  if (dsv) {
    *dsv = dsv_;
    if (dsv_) dsv_->AddRef();
  }
}

void ContextImpl::ClearState() {
  EndRendering();
  IASetInputLayout(nullptr);
  for (auto& v : vbs_) SetRef(v.buffer, static_cast<BufferImpl*>(nullptr));
  SetRef(ib_, static_cast<BufferImpl*>(nullptr));
  topology_ = PRIMITIVE_TOPOLOGY_UNDEFINED;
  SetRef(vs_, static_cast<VertexShaderImpl*>(nullptr));
  SetRef(ps_, static_cast<PixelShaderImpl*>(nullptr));
  for (int s = 0; s < 2; ++s) {
    for (auto*& c : cbs_[s]) SetRef(c, static_cast<BufferImpl*>(nullptr));
    for (auto*& v : srvs_[s]) SetRef(v, static_cast<SRVImpl*>(nullptr));
    for (auto*& v : samplers_[s]) SetRef(v, static_cast<SamplerImpl*>(nullptr));
  }
  numViewports_ = numScissors_ = 0;
  SetRef(raster_, static_cast<RasterizerImpl*>(nullptr));
  SetRef(blend_, static_cast<BlendImpl*>(nullptr));
  SetRef(depth_, static_cast<DepthStencilImpl*>(nullptr));
  std::fill(std::begin(blendFactor_), std::end(blendFactor_), 1.0f);
  stencilRef_ = 0;
  OMSetRenderTargets(0, nullptr, nullptr);
  dirty_ = kAll;
}

void ContextImpl::Flush() { dev_->SubmitFrame(); }

}  // namespace d3dl::impl
