// Draw-time commit of the recorded state, lazy dynamic-rendering scopes, and
// the draws (direct and indirect).
// The hot path (only constants changed) touches the dirty bits, the ring and
// vkCmdBindDescriptorSets with new dynamic offsets, nothing else.
#include "Context.h"
#include "Topology.h"
#include "Validate.h"

namespace d3dl::impl {
const char* OnceErrorMessage(OnceError e) {
  switch (e) {
    case OnceError::NoVertexShader: return "draw skipped: no vertex shader is bound";
    case OnceError::NoRenderTarget: return "draw skipped: no render target or depth-stencil view is bound";
    case OnceError::NoIndexBuffer: return "DrawIndexed skipped: no index buffer is bound";
    case OnceError::NoTopology: return "draw skipped: no primitive topology is set";
    case OnceError::ProgramLayoutFailed: return "draw skipped: could not create the pipeline layout";
    case OnceError::PipelineFailed: return "draw skipped: pipeline creation failed (see the previous message)";
    case OnceError::StaleDynamicBuffer:
      return "a DYNAMIC vertex/index buffer is drawn in a later frame than its last Map(WRITE_DISCARD); its contents are undefined";
    case OnceError::IndexBufferNeverMapped: return "DrawIndexed skipped: the DYNAMIC index buffer was never mapped";
    case OnceError::DescriptorSetFailed: return "draw skipped: descriptor set allocation failed";
    case OnceError::TooManyTimestamps: return "End: more than 1024 timestamps in one frame; extra timestamps read as 0";
    case OnceError::HullWithoutDomain: return "draw skipped: a hull shader is bound without a domain shader";
    case OnceError::DomainWithoutHull: return "draw skipped: a domain shader is bound without a hull shader";
    case OnceError::PatchListWithoutHull:
      return "draw skipped: a patch-list topology needs a hull and a domain shader";
    case OnceError::HullWithoutPatchList:
      return "draw skipped: hull and domain shaders need a PRIMITIVE_TOPOLOGY_<n>_CONTROL_POINT_PATCHLIST topology";
    case OnceError::GeometryInputMismatch:
      return "draw skipped: the geometry shader's input primitive (point/line/triangle) differs from the topology's (or the tessellator's output)";
    case OnceError::NoComputeShader: return "Dispatch skipped: no compute shader is bound";
    case OnceError::UnboundUav:
      return "dispatch/draw skipped: the shader writes a UAV slot that has no view of the kind it declares (RWTexture2D or RW buffer) bound";
    case OnceError::NoFragmentStores: return "draw skipped: pixel-shader UAVs need fragmentStoresAndAtomics, which this adapter lacks";
  }
  return "?";
}

void ContextImpl::ErrorOnce(OnceError e) {
  const uint32_t bit = 1u << static_cast<uint32_t>(e);
  if (errorsLogged_ & bit) return;
  errorsLogged_ |= bit;
  dev_->Log(LogLevel::Error, "%s", OnceErrorMessage(e));
}

bool ContextImpl::TargetSize(uint32_t* w, uint32_t* h) const {
  const OutputMergerState& om = state_.om;
  uint32_t W = ~0u, H = ~0u;
  for (uint32_t i = 0; i < om.numRenderTargets; ++i)
    if (const RTVImpl* r = om.renderTargets[i].Get()) {
      W = std::min(W, r->v.Width());
      H = std::min(H, r->v.Height());
    }
  if (const DSVImpl* d = om.depthStencilView.Get()) {
    W = std::min(W, d->v.Width());
    H = std::min(H, d->v.Height());
  }
  if (W == ~0u) return false;
  *w = W;
  *h = H;
  return true;
}

// D3D11 renders into as many array slices as the bound view with the fewest.
uint32_t ContextImpl::TargetLayers() const {
  const OutputMergerState& om = state_.om;
  uint32_t n = ~0u;
  for (uint32_t i = 0; i < om.numRenderTargets; ++i)
    if (const RTVImpl* r = om.renderTargets[i].Get()) n = std::min(n, r->v.layerCount);
  if (const DSVImpl* d = om.depthStencilView.Get()) n = std::min(n, d->v.layerCount);
  return n == ~0u ? 1 : n;
}

// The bound targets' sample count (OMSetRenderTargets checked that they agree).
uint32_t ContextImpl::TargetSamples() const {
  const OutputMergerState& om = state_.om;
  for (uint32_t i = 0; i < om.numRenderTargets; ++i)
    if (const RTVImpl* r = om.renderTargets[i].Get()) return r->v.Samples();
  return om.depthStencilView ? om.depthStencilView->v.Samples() : 1;
}

void ContextImpl::EndRendering() {
  if (!rendering_) return;
  vkCmdEndRendering(Cmd());
  rendering_ = false;
}

bool ContextImpl::BeginRendering() {
  const OutputMergerState& om = state_.om;
  uint32_t w, h;
  if (!TargetSize(&w, &h)) return false;
  const uint32_t layers = TargetLayers();
  for (uint32_t i = 0; i < om.numRenderTargets; ++i)
    if (const RTVImpl* r = om.renderTargets[i].Get()) UseTexture(r->v.tex, r->v.range(), usage::ColorAttachment);
  if (const DSVImpl* d = om.depthStencilView.Get()) UseTexture(d->v.tex, d->v.range(), usage::DepthAttachment);
  FlushBarriers();
  VkRenderingAttachmentInfo color[SIMULTANEOUS_RENDER_TARGET_COUNT]{};
  for (uint32_t i = 0; i < om.numRenderTargets; ++i) {
    const RTVImpl* r = om.renderTargets[i].Get();
    color[i] = LoadStoreAttachment(r ? r->v.Current() : VK_NULL_HANDLE, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    if (r) NoteUse(r->v.tex->use, true);
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  if (const DSVImpl* d = om.depthStencilView.Get()) {
    depth = LoadStoreAttachment(d->v.Current(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    NoteUse(d->v.tex->use, true);
  }
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, {w, h}};
  ri.layerCount = layers;
  ri.colorAttachmentCount = om.numRenderTargets;
  ri.pColorAttachments = om.numRenderTargets ? color : nullptr;
  ri.pDepthAttachment = om.depthStencilView ? &depth : nullptr;
  const bool stencil = om.depthStencilView && (om.depthStencilView->v.aspect & VK_IMAGE_ASPECT_STENCIL_BIT);
  ri.pStencilAttachment = stencil ? &depth : nullptr;
  vkCmdBeginRendering(Cmd(), &ri);
  rendering_ = true;
  renderLayers_ = layers;
  if (w != renderW_ || h != renderH_) dirty_ |= kViewport | kScissor;
  renderW_ = w;
  renderH_ = h;
  return true;
}

// Missing or mismatched state skips the draw with one error per kind and
// context (ValidateDraw decides).
bool ContextImpl::CheckDrawState(bool indexed) {
  OnceError error;
  const DrawVerdict verdict = ValidateDraw(DrawInputsOf(indexed), &error);
  if (verdict == DrawVerdict::SkipWithError) ErrorOnce(error);
  return verdict == DrawVerdict::Draw;
}

PerStage<ShaderBase*> ContextImpl::BoundShaders() const {
  PerStage<ShaderBase*> shaders;
  for (ShaderStage s : kGraphicsStages) shaders[s] = state_.stages[s].shader.Get();
  return shaders;
}

// Barriers of what the draw reads; they must be outside a rendering scope.
void ContextImpl::UseDrawResources(bool indexed) {
  if (dirty_ & (kDescriptors | kSrvLayouts)) {
    for (const auto& s : program_->srvs)
      if (SRVImpl* v = state_.stages[s.stage].shaderResources[s.slot].Get(); v && v->v.tex)
        UseTexture(v->v.tex, v->v.range(), usage::ShaderRead);
  }
  // Buffer SRVs and pixel-shader UAVs; a buffer
  // written since the last draw raises kVertexBuffers.
  if ((dirty_ & (kDescriptors | kSrvLayouts | kVertexBuffers | kUavs)) || program_->HasUavs())
    UseShaderViews(*program_, ShaderStage::Pixel);
  const InputAssemblerState& ia = state_.ia;
  if ((dirty_ & kVertexBuffers) && ia.layout) {
    for (uint32_t m = ia.layout->slotMask; m; m &= m - 1) {
      BufferImpl* b = ia.vertexBuffers[__builtin_ctz(m)].buffer.Get();
      if (b && b->vkBuffer()) UseBuffer(b->vkBuffer(), b->sync(), usage::VertexRead);
    }
  }
  BufferImpl* ib = ia.indexBuffer.Get();
  if (indexed && (dirty_ & kIndexBuffer) && ib->vkBuffer()) UseBuffer(ib->vkBuffer(), ib->sync(), usage::VertexRead);
}

bool ContextImpl::CommitSlow(bool indexed) {
  if (!CheckDrawState(indexed)) return false;
  if (dirty_ & kProgram) {
    program_ = pipelineFront_.GetProgram(dev_->pipelines(), BoundShaders());
    if (!program_) return ErrorOnce(OnceError::ProgramLayoutFailed), false;
    dirty_ |= kDescriptors | kConstants;
  }
  if (program_->HasUavs() && !CheckUavs(*program_, ShaderStage::Pixel)) return false;
  UseDrawResources(indexed);
  if (HasPendingBarriers()) FlushBarriers();
  if (!rendering_ && !BeginRendering()) return false;
  VkCommandBuffer cmd = Cmd();
  if ((dirty_ & kPipeline) && !BindPipeline(cmd)) return false;
  SetDynamicState(cmd);
  if (dirty_ & kVertexBuffers) BindVertexBuffers(cmd);
  if (indexed && (dirty_ & kIndexBuffer) && !BindIndexBuffer(cmd)) return false;
  if ((dirty_ & (kDescriptors | kConstants)) && !BindDescriptors(cmd)) return false;
  dirty_ &= indexed ? uint32_t(kComputeDirty) : uint32_t(kComputeDirty | kIndexBuffer);
  if (program_->HasUavs()) dirty_ |= kUavs;  // D3D11 orders UAV writes of consecutive draws
  return true;
}

bool ContextImpl::BindPipeline(VkCommandBuffer cmd) {
  const OutputMergerState& om = state_.om;
  PipelineInputs in{BoundShaders(), state_.ia.layout.Get(), om.blend ? om.blend.Get() : defaults_.blend.Get(),
                    om.depthStencil ? om.depthStencil.Get() : defaults_.depth.Get(), Rasterizer()};
  // Every field is written (rt[] up to its end), so the key held from the
  // last build needs no clearing; it has no padding (PipelineCache.h), so the
  // byte comparison and hash see only these values.
  PipelineKey& k = nextKey_;
  for (ShaderStage s : kGraphicsStages) k.shaders.ids[StageIndex(s)] = in.shaders[s] ? in.shaders[s]->cacheId : 0;
  k.il = in.il ? in.il->uid() : 0;
  // 0 stands for the context's own default state object: every context's
  // has the default description, so all contexts share those pipelines.
  k.blend = om.blend ? in.blend->uid() : 0;
  k.depth = om.depthStencil ? in.depth->uid() : 0;
  k.raster = state_.rs.state ? in.raster->uid() : 0;
  k.topologyClass = TopologyClass(state_.ia.topology);
  k.patchControlPoints = PatchControlPoints(state_.ia.topology);
  k.numRT = om.numRenderTargets;
  for (uint32_t i = 0; i < SIMULTANEOUS_RENDER_TARGET_COUNT; ++i)
    k.rt[i] = i < om.numRenderTargets && om.renderTargets[i] ? om.renderTargets[i]->v.format : VK_FORMAT_UNDEFINED;
  k.ds = om.depthStencilView ? om.depthStencilView->v.format : VK_FORMAT_UNDEFINED;
  k.samples = TargetSamples();
  k.sampleMask = k.samples >= 32 ? om.sampleMask : om.sampleMask & ((1u << k.samples) - 1);
  if (pipeline_ && k == key_) return true;
  VkPipeline p = pipelineFront_.GetPipeline(dev_->pipelines(), k, in, program_);
  if (!p) return ErrorOnce(OnceError::PipelineFailed), false;
  key_ = k;
  if (p != pipeline_) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p);
    pipeline_ = p;
  }
  return true;
}

void ContextImpl::SetDynamicState(VkCommandBuffer cmd) {
  const RasterizerStageState& rs = state_.rs;
  if (dirty_ & kViewport) {
    VkViewport vp;
    if (rs.numViewports) {
      // D3D: +Y up in clip space, y down in the window. A negative height flips Y.
      const VIEWPORT& v = rs.viewport;
      vp = {v.TopLeftX, v.TopLeftY + v.Height, v.Width, -v.Height, v.MinDepth, v.MaxDepth};
    } else {
      vp = {0, float(renderH_), float(renderW_), -float(renderH_), 0, 1};
    }
    vkCmdSetViewport(cmd, 0, 1, &vp);
  }
  if (dirty_ & kScissor) {
    VkRect2D r{{0, 0}, {renderW_, renderH_}};
    if (Rasterizer()->desc.ScissorEnable) {
      if (rs.numScissors) {
        int32_t l = std::max(0, rs.scissor.left), t = std::max(0, rs.scissor.top);
        int32_t rr = std::max(l, rs.scissor.right), b = std::max(t, rs.scissor.bottom);
        r = {{l, t}, {uint32_t(rr - l), uint32_t(b - t)}};
      } else {
        r = {{0, 0}, {0, 0}};  // D3D: scissor enabled without rects culls everything
      }
    }
    vkCmdSetScissor(cmd, 0, 1, &r);
  }
  if (dirty_ & kBlendConst) vkCmdSetBlendConstants(cmd, state_.om.blendFactor);
  if (dirty_ & kStencilRef) vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, state_.om.stencilRef);
  if (dirty_ & kTopology) vkCmdSetPrimitiveTopology(cmd, ToVkTopology(state_.ia.topology));
}

void ContextImpl::BindVertexBuffers(VkCommandBuffer cmd) {
  const InputAssemblerState& ia = state_.ia;
  for (uint32_t mask = ia.layout ? ia.layout->slotMask : 0; mask; mask &= mask - 1) {
    const uint32_t slot = __builtin_ctz(mask);
    const auto& v = ia.vertexBuffers[slot];
    const BufferImpl* b = v.buffer.Get();
    VkBuffer buf = dev_->dummies().uniform;
    VkDeviceSize off = 0, stride = v.stride;
    if (b && b->storage() == Storage::Ring) {
      const RingAlloc& ring = DynRing(b);
      if (ring.buffer) {
        buf = ring.buffer;
        off = ring.offset + v.offset;
      } else {
        stride = 0;
      }
    } else if (b) {
      buf = b->vkBuffer();
      off = v.offset;
    } else {
      stride = 0;
    }
    vkCmdBindVertexBuffers2(cmd, slot, 1, &buf, &off, nullptr, &stride);
  }
}

bool ContextImpl::BindIndexBuffer(VkCommandBuffer cmd) {
  const InputAssemblerState& ia = state_.ia;
  const BufferImpl* ib = ia.indexBuffer.Get();
  VkBuffer buf = ib->vkBuffer();
  VkDeviceSize off = ia.indexOffset;
  if (ib->storage() == Storage::Ring) {
    const RingAlloc& ring = DynRing(ib);
    buf = ring.buffer;
    off += ring.offset;
  }
  if (!buf) return ErrorOnce(OnceError::IndexBufferNeverMapped), false;
  vkCmdBindIndexBuffer(cmd, buf, off, ia.indexType);
  return true;
}

// Binds the program's descriptor set with this draw's dynamic offsets (one per
// constant buffer the program uses). A new set is written only when a bound
// SRV/sampler/CB changed identity or a CB's ring slice moved to another chunk.
bool ContextImpl::BindDescriptors(VkCommandBuffer cmd) {
  return BindSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, *program_, desc_, (dirty_ & kDescriptors) != 0);
}

bool ContextImpl::BindSet(VkCommandBuffer cmd, VkPipelineBindPoint point, const ProgramLayout& p,
                          BoundDescriptors& d, bool changed) {
  const uint32_t nCB = static_cast<uint32_t>(p.cbs.size());
  d.hotLayout = VK_NULL_HANDLE;
  d.nHotCbs = 0;
  if (p.Empty()) return true;
  bool newSet = changed || !d.set;
  for (uint32_t i = 0; i < nCB; ++i) {
    const auto& s = p.cbs[i];
    BufferImpl* b = Stage(s.stage).constantBuffers[s.slot].Get();
    VkBuffer buf = dev_->dummies().uniform;
    uint32_t off = 0, range = static_cast<uint32_t>(dev_->dummies().uniformSize);
    if (b) {
      const RingAlloc& r = CbRing(b);
      buf = r.buffer;
      off = static_cast<uint32_t>(r.offset);
      range = b->size();
    }
    if (buf != d.cbBuffers[i] || range != d.cbRanges[i]) newSet = true;
    d.dynOffsets[i] = off;
    d.hotCbs[i] = b;
  }
  if (newSet && !WriteSet(p, d)) return false;
  d.hotLayout = BindingLayout(p);
  d.nHotCbs = nCB;
  vkCmdBindDescriptorSets(cmd, point, d.hotLayout, 0, 1, &d.set, nCB, d.dynOffsets);
  return true;
}

namespace {
VkWriteDescriptorSet WriteOf(VkDescriptorSet set, uint32_t binding, VkDescriptorType type) {
  VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  w.dstSet = set;
  w.dstBinding = binding;
  w.descriptorCount = 1;
  w.descriptorType = type;
  return w;
}
// At most every binding of every graphics stage in one set.
constexpr uint32_t kMaxWrites = kGraphicsStageCount * kStageBindingStride;
}  // namespace

bool ContextImpl::WriteSet(const ProgramLayout& p, BoundDescriptors& d) {
  VkDescriptorSet set = AllocateSet(SetLayout(p));
  if (!set) return ErrorOnce(OnceError::DescriptorSetFailed), false;
  const DummyResources& dummy = dev_->dummies();
  VkDescriptorBufferInfo bufInfo[kMaxWrites];
  VkDescriptorImageInfo imgInfo[kMaxWrites];
  VkWriteDescriptorSet writes[kMaxWrites];
  uint32_t nw = 0, ni = 0, nb = 0;
  for (const auto& s : p.cbs) {
    BufferImpl* b = Stage(s.stage).constantBuffers[s.slot].Get();
    bufInfo[nb] = {b ? CbRing(b).buffer : dummy.uniform, 0, b ? b->size() : dummy.uniformSize};
    d.cbBuffers[nb] = bufInfo[nb].buffer;
    d.cbRanges[nb] = static_cast<uint32_t>(bufInfo[nb].range);
    writes[nw] = WriteOf(set, s.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC);
    writes[nw++].pBufferInfo = &bufInfo[nb++];
  }
  for (const auto& s : p.srvs) {
    const SRVImpl* v = Stage(s.stage).shaderResources[s.slot].Get();
    const bool image = v && v->v.tex;
    VkImageView unbound = dummy.views[s.dummy] ? dummy.views[s.dummy] : (s.image1D ? dummy.view1D : dummy.view2D);
    imgInfo[ni] = {VK_NULL_HANDLE, image ? v->v.Current() : unbound,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    writes[nw] = WriteOf(set, s.binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
    writes[nw++].pImageInfo = &imgInfo[ni++];
  }
  for (const auto& s : p.samplers) {
    const SamplerImpl* smp = Stage(s.stage).samplers[s.slot].Get();
    imgInfo[ni] = {smp ? smp->sampler : dummy.sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
    writes[nw] = WriteOf(set, s.binding, VK_DESCRIPTOR_TYPE_SAMPLER);
    writes[nw++].pImageInfo = &imgInfo[ni++];
  }
  // Buffer SRVs (dummy when unbound) and UAVs
  // (bound with the right kind: CheckUavs checked it).
  for (const auto& s : p.bufferSrvs) {
    const SRVImpl* v = Stage(s.stage).shaderResources[s.slot].Get();
    const bool buffer = v && v->v.buf;
    bufInfo[nb] = buffer ? VkDescriptorBufferInfo{v->v.buf->vkBuffer(), v->v.bufOffset, v->v.bufRange}
                         : VkDescriptorBufferInfo{dummy.uniform, 0, VK_WHOLE_SIZE};
    writes[nw] = WriteOf(set, s.binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    writes[nw++].pBufferInfo = &bufInfo[nb++];
  }
  for (const auto& s : p.uavBuffers) {
    const UAVImpl* v = UavAt(s.stage, s.slot);
    bufInfo[nb] = {v->v.buf->vkBuffer(), v->v.bufOffset, v->v.bufRange};
    writes[nw] = WriteOf(set, s.binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    writes[nw++].pBufferInfo = &bufInfo[nb++];
  }
  for (const auto& s : p.uavImages) {
    imgInfo[ni] = {VK_NULL_HANDLE, UavAt(s.stage, s.slot)->v.Current(), VK_IMAGE_LAYOUT_GENERAL};
    writes[nw] = WriteOf(set, s.binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    writes[nw++].pImageInfo = &imgInfo[ni++];
  }
  vkUpdateDescriptorSets(dev_->vk(), nw, writes, 0, nullptr);
  d.set = set;
  return true;
}

void ContextImpl::Draw(UINT count, UINT start) {
  if (!Commit(false)) return;
  vkCmdDraw(Cmd(), count, 1, start, 0);
  CountDraw();
}
void ContextImpl::DrawInstanced(UINT count, UINT instances, UINT start, UINT startInstance) {
  if (!Commit(false)) return;
  vkCmdDraw(Cmd(), count, instances, start, startInstance);
  CountDraw();
}
void ContextImpl::DrawIndexed(UINT count, UINT start, int32_t base) {
  if (!Commit(true)) return;
  vkCmdDrawIndexed(Cmd(), count, 1, start, base, 0);
  CountDraw();
}
void ContextImpl::DrawIndexedInstanced(UINT count, UINT instances, UINT start, int32_t base, UINT startInstance) {
  if (!Commit(true)) return;
  vkCmdDrawIndexed(Cmd(), count, instances, start, base, startInstance);
  CountDraw();
}

// Indirect draws and dispatches: the arguments' barrier is queued before the
// commit, so a pending one ends the rendering scope there (FlushBarriers) and
// the draw runs in a new scope.
BufferImpl* ContextImpl::UseIndirectArgs(const char* fn, Buffer* args, UINT offset, UINT argBytes) {
  if (!ValidateIndirectArgs(*dev_, fn, DescribeResource(args), offset, argBytes)) return nullptr;
  BufferImpl* b = static_cast<BufferImpl*>(args);
  UseBuffer(b->vkBuffer(), b->sync(), usage::IndirectRead);
  Hold(b);
  NoteUse(b->use, false);
  return b;
}

// D3D11's argument records are Vulkan's indirect commands, field for field.
static_assert(sizeof(VkDrawIndirectCommand) == kDrawArgsBytes);
static_assert(sizeof(VkDrawIndexedIndirectCommand) == kDrawIndexedArgsBytes);

void ContextImpl::DrawInstancedIndirect(Buffer* args, UINT offset) {
  BufferImpl* b = UseIndirectArgs("DrawInstancedIndirect", args, offset, kDrawArgsBytes);
  if (!b || !Commit(false)) return;
  vkCmdDrawIndirect(Cmd(), b->vkBuffer(), offset, 1, kDrawArgsBytes);
  CountDraw();
}
void ContextImpl::DrawIndexedInstancedIndirect(Buffer* args, UINT offset) {
  BufferImpl* b = UseIndirectArgs("DrawIndexedInstancedIndirect", args, offset, kDrawIndexedArgsBytes);
  if (!b || !Commit(true)) return;
  vkCmdDrawIndexedIndirect(Cmd(), b->vkBuffer(), offset, 1, kDrawIndexedArgsBytes);
  CountDraw();
}

}  // namespace d3dl::impl
