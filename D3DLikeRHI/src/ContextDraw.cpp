// Draw-time commit of the recorded state, lazy dynamic-rendering scopes and
// clears. The hot path (only constants changed) touches the dirty bits, the
// ring and vkCmdBindDescriptorSets with new dynamic offsets, nothing else.
#include "Context.h"

namespace d3dl::impl {
namespace {
VkPrimitiveTopology ToVkTopology(PRIMITIVE_TOPOLOGY t) {
  switch (t) {
    case PRIMITIVE_TOPOLOGY_POINTLIST: return VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    case PRIMITIVE_TOPOLOGY_LINELIST: return VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
    case PRIMITIVE_TOPOLOGY_LINESTRIP: return VK_PRIMITIVE_TOPOLOGY_LINE_STRIP;
    case PRIMITIVE_TOPOLOGY_TRIANGLESTRIP: return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    default: return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  }
}
uint32_t TopologyClass(PRIMITIVE_TOPOLOGY t) {
  switch (t) {
    case PRIMITIVE_TOPOLOGY_POINTLIST: return 0;
    case PRIMITIVE_TOPOLOGY_LINELIST:
    case PRIMITIVE_TOPOLOGY_LINESTRIP: return 1;
    default: return 2;
  }
}
VkClearColorValue ToClearColor(const ViewCore& v, const float c[4]) {
  VkClearColorValue r{};
  const FormatInfo* f = GetFormatInfo(v.dxgiFormat);
  if (f && f->integer) {
    for (int i = 0; i < 4; ++i) r.uint32[i] = static_cast<uint32_t>(std::max(0.0f, c[i]));
  } else {
    for (int i = 0; i < 4; ++i) r.float32[i] = c[i];
  }
  return r;
}
}  // namespace

void ContextImpl::ErrorOnce(uint32_t bit, const char* msg) {
  if (errorsLogged_ & bit) return;
  errorsLogged_ |= bit;
  dev_->Log(LogLevel::Error, "%s", msg);
}

bool ContextImpl::TargetSize(uint32_t* w, uint32_t* h) const {
  uint32_t W = ~0u, H = ~0u;
  for (uint32_t i = 0; i < numRT_; ++i)
    if (rtvs_[i]) {
      W = std::min(W, rtvs_[i]->v.tex->MipWidth(rtvs_[i]->v.baseMip));
      H = std::min(H, rtvs_[i]->v.tex->MipHeight(rtvs_[i]->v.baseMip));
    }
  if (dsv_) {
    W = std::min(W, dsv_->v.tex->MipWidth(dsv_->v.baseMip));
    H = std::min(H, dsv_->v.tex->MipHeight(dsv_->v.baseMip));
  }
  if (W == ~0u) return false;
  *w = W;
  *h = H;
  return true;
}

void ContextImpl::EndRendering() {
  if (!rendering_) return;
  vkCmdEndRendering(dev_->Cmd());
  rendering_ = false;
}

bool ContextImpl::BeginRendering() {
  uint32_t w, h;
  if (!TargetSize(&w, &h)) return false;
  for (uint32_t i = 0; i < numRT_; ++i)
    if (rtvs_[i]) UseTexture(rtvs_[i]->v.tex, rtvs_[i]->v.baseMip, 1, rtvs_[i]->v.baseLayer, 1, usage::ColorAttachment);
  if (dsv_) UseTexture(dsv_->v.tex, dsv_->v.baseMip, 1, dsv_->v.baseLayer, 1, usage::DepthAttachment);
  FlushBarriers();
  VkRenderingAttachmentInfo color[SIMULTANEOUS_RENDER_TARGET_COUNT]{};
  const uint64_t serial = dev_->CurrentSerial();
  for (uint32_t i = 0; i < numRT_; ++i) {
    color[i].sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    color[i].imageView = rtvs_[i] ? rtvs_[i]->v.Current() : VK_NULL_HANDLE;
    color[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color[i].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    color[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    if (rtvs_[i]) rtvs_[i]->v.tex->lastUseSerial = rtvs_[i]->v.tex->lastWriteSerial = serial;
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  if (dsv_) {
    depth.imageView = dsv_->v.Current();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    dsv_->v.tex->lastUseSerial = dsv_->v.tex->lastWriteSerial = serial;
  }
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, {w, h}};
  ri.layerCount = 1;
  ri.colorAttachmentCount = numRT_;
  ri.pColorAttachments = color;
  ri.pDepthAttachment = dsv_ ? &depth : nullptr;
  vkCmdBeginRendering(dev_->Cmd(), &ri);
  rendering_ = true;
  if (w != renderW_ || h != renderH_) dirty_ |= kViewport | kScissor;
  renderW_ = w;
  renderH_ = h;
  return true;
}

bool ContextImpl::CommitSlow(bool indexed) {
  if (!vs_) return ErrorOnce(1u << 0, "draw skipped: no vertex shader is bound"), false;
  if (numRT_ == 0 && !dsv_) return ErrorOnce(1u << 1, "draw skipped: no render target or depth-stencil view is bound"), false;
  if (indexed && !ib_) return ErrorOnce(1u << 2, "DrawIndexed skipped: no index buffer is bound"), false;
  if (topology_ == PRIMITIVE_TOPOLOGY_UNDEFINED)
    return ErrorOnce(1u << 3, "draw skipped: no primitive topology is set"), false;
  if (numViewports_ && (viewport_.Width <= 0.0f || viewport_.Height <= 0.0f)) return false;  // nothing to draw
  VkCommandBuffer cmd = dev_->Cmd();

  if (dirty_ & kProgram) {
    program_ = dev_->pipelines().GetProgram(vs_, ps_);
    if (!program_) return ErrorOnce(1u << 4, "draw skipped: could not create the pipeline layout"), false;
    dirty_ |= kDescriptors | kConstants;
  }
  // Barriers first: they must be outside a rendering scope.
  if (dirty_ & (kDescriptors | kSrvLayouts)) {
    for (const auto& s : program_->srvs)
      if (SRVImpl* v = srvs_[s.stage][s.slot])
        UseTexture(v->v.tex, v->v.baseMip, v->v.mipCount, v->v.baseLayer, v->v.layerCount, usage::ShaderRead);
  }
  if ((dirty_ & kVertexBuffers) && il_) {
    for (uint32_t m = il_->slotMask; m; m &= m - 1) {
      BufferImpl* b = vbs_[__builtin_ctz(m)].buffer;
      if (b && b->buffer) UseBuffer(b->buffer, b->sync, usage::VertexRead);
    }
  }
  if (indexed && (dirty_ & kIndexBuffer) && ib_->buffer) UseBuffer(ib_->buffer, ib_->sync, usage::VertexRead);
  if (HasPendingBarriers()) FlushBarriers();
  if (!rendering_ && !BeginRendering()) return false;

  if (dirty_ & kPipeline) {
    PipelineKey k;
    std::memset(&k, 0, sizeof(k));
    BlendImpl* blend = blend_ ? blend_ : defBlend_;
    DepthStencilImpl* depth = depth_ ? depth_ : defDepth_;
    RasterizerImpl* raster = raster_ ? raster_ : defRaster_;
    k.vs = vs_->uid();
    k.ps = ps_ ? ps_->uid() : 0;
    k.il = il_ ? il_->uid() : 0;
    k.blend = blend->uid();
    k.depth = depth->uid();
    k.raster = raster->uid();
    k.topologyClass = TopologyClass(topology_);
    k.numRT = numRT_;
    for (uint32_t i = 0; i < numRT_; ++i) k.rt[i] = rtvs_[i] ? rtvs_[i]->v.format : VK_FORMAT_UNDEFINED;
    k.ds = dsv_ ? dsv_->v.format : VK_FORMAT_UNDEFINED;
    if (!pipeline_ || !(k == key_)) {
      PipelineInputs in{vs_, ps_, il_, blend, depth, raster, topology_};
      VkPipeline p = dev_->pipelines().GetPipeline(k, in, program_);
      if (!p) return ErrorOnce(1u << 5, "draw skipped: pipeline creation failed (see the previous message)"), false;
      key_ = k;
      if (p != pipeline_) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p);
        pipeline_ = p;
      }
    }
  }
  if (dirty_ & kViewport) {
    VkViewport vp;
    if (numViewports_) {
      // D3D: +Y up in clip space, y down in the window. A negative height flips Y.
      vp = {viewport_.TopLeftX, viewport_.TopLeftY + viewport_.Height, viewport_.Width,
            -viewport_.Height, viewport_.MinDepth, viewport_.MaxDepth};
    } else {
      vp = {0, float(renderH_), float(renderW_), -float(renderH_), 0, 1};
    }
    vkCmdSetViewport(cmd, 0, 1, &vp);
  }
  if (dirty_ & kScissor) {
    RasterizerImpl* raster = raster_ ? raster_ : defRaster_;
    VkRect2D r{{0, 0}, {renderW_, renderH_}};
    if (raster->desc.ScissorEnable) {
      if (numScissors_) {
        int32_t l = std::max(0, scissor_.left), t = std::max(0, scissor_.top);
        int32_t rr = std::max(l, scissor_.right), b = std::max(t, scissor_.bottom);
        r = {{l, t}, {uint32_t(rr - l), uint32_t(b - t)}};
      } else {
        r = {{0, 0}, {0, 0}};  // D3D: scissor enabled without rects culls everything
      }
    }
    vkCmdSetScissor(cmd, 0, 1, &r);
  }
  if (dirty_ & kBlendConst) vkCmdSetBlendConstants(cmd, blendFactor_);
  if (dirty_ & kStencilRef) vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, stencilRef_);
  if (dirty_ & kTopology) vkCmdSetPrimitiveTopology(cmd, ToVkTopology(topology_));

  if (dirty_ & kVertexBuffers) {
    uint32_t mask = il_ ? il_->slotMask : 0;
    for (; mask; mask &= mask - 1) {
      uint32_t slot = __builtin_ctz(mask);
      const VB& v = vbs_[slot];
      VkBuffer buf = dev_->dummyVertex;
      VkDeviceSize off = 0, stride = v.stride;
      if (v.buffer && v.buffer->isRing) {
        if (v.buffer->ringSerial != dev_->CurrentSerial() && v.buffer->ring.buffer)
          ErrorOnce(1u << 6, "a DYNAMIC vertex/index buffer is drawn in a later frame than its last Map(WRITE_DISCARD); its contents are undefined");
        if (v.buffer->ring.buffer) {
          buf = v.buffer->ring.buffer;
          off = v.buffer->ring.offset + v.offset;
        } else {
          stride = 0;
        }
      } else if (v.buffer) {
        buf = v.buffer->buffer;
        off = v.offset;
      } else {
        stride = 0;
      }
      vkCmdBindVertexBuffers2(cmd, slot, 1, &buf, &off, nullptr, &stride);
    }
  }
  if (indexed && (dirty_ & kIndexBuffer)) {
    VkBuffer buf = ib_->isRing ? ib_->ring.buffer : ib_->buffer;
    VkDeviceSize off = (ib_->isRing ? ib_->ring.offset : 0) + ibOffset_;
    if (!buf) return ErrorOnce(1u << 7, "DrawIndexed skipped: the DYNAMIC index buffer was never mapped"), false;
    vkCmdBindIndexBuffer(cmd, buf, off, ibType_);
  }

  if ((dirty_ & (kDescriptors | kConstants)) && !BindDescriptors(cmd)) return false;
  dirty_ = indexed ? 0u : (dirty_ & kIndexBuffer);
  return true;
}

// Binds the program's descriptor set with this draw's dynamic offsets (one per
// constant buffer the program uses). A new set is written only when a bound
// SRV/sampler/CB changed identity or a CB's ring slice moved to another chunk.
bool ContextImpl::BindDescriptors(VkCommandBuffer cmd) {
  const ProgramLayout& p = *program_;
  const uint32_t nCB = static_cast<uint32_t>(p.cbs.size());
  hotLayout_ = VK_NULL_HANDLE;
  nHotCbs_ = 0;
  if (nCB == 0 && p.srvs.empty() && p.samplers.empty()) return true;
  bool newSet = (dirty_ & kDescriptors) || !set_;
  for (uint32_t i = 0; i < nCB; ++i) {
    const auto& s = p.cbs[i];
    BufferImpl* b = cbs_[s.stage][s.slot];
    VkBuffer buf = dev_->dummyUniform;
    uint32_t off = 0, range = static_cast<uint32_t>(dev_->dummyUniformSize);
    if (b) {
      b->EnsureUploaded();
      buf = b->ring.buffer;
      off = static_cast<uint32_t>(b->ring.offset);
      range = b->desc_.ByteWidth;
    }
    if (buf != setCbBuffers_[i] || range != setCbRanges_[i]) newSet = true;
    dynOffsets_[i] = off;
    hotCbs_[i] = b;
  }
  if (newSet && !WriteNewSet()) return false;
  hotLayout_ = p.layout;
  nHotCbs_ = nCB;
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout, 0, 1, &set_, nCB, dynOffsets_);
  return true;
}

bool ContextImpl::WriteNewSet() {
  VkDescriptorSet set = dev_->AllocateSet(program_->setLayout);
  if (!set) return ErrorOnce(1u << 8, "draw skipped: descriptor set allocation failed"), false;
  VkDescriptorBufferInfo bufInfo[2 * kMaxConstantBufferSlots];
  VkDescriptorImageInfo imgInfo[2 * (kMaxTextureSlots + kMaxSamplerSlots)];
  VkWriteDescriptorSet writes[2 * (kMaxConstantBufferSlots + kMaxTextureSlots + kMaxSamplerSlots)];
  uint32_t nw = 0, ni = 0;
  const uint32_t nCB = static_cast<uint32_t>(program_->cbs.size());
  for (uint32_t i = 0; i < nCB; ++i) {
    const auto& s = program_->cbs[i];
    BufferImpl* b = cbs_[s.stage][s.slot];
    bufInfo[i] = {b ? b->ring.buffer : dev_->dummyUniform, 0,
                  b ? b->desc_.ByteWidth : dev_->dummyUniformSize};
    setCbBuffers_[i] = bufInfo[i].buffer;
    setCbRanges_[i] = static_cast<uint32_t>(bufInfo[i].range);
    writes[nw] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[nw].dstSet = set;
    writes[nw].dstBinding = s.binding;
    writes[nw].descriptorCount = 1;
    writes[nw].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
    writes[nw++].pBufferInfo = &bufInfo[i];
  }
  for (const auto& s : program_->srvs) {
    SRVImpl* v = srvs_[s.stage][s.slot];
    imgInfo[ni] = {VK_NULL_HANDLE,
                   v ? v->v.Current() : (s.image1D ? dev_->dummyImageView1D : dev_->dummyImageView2D),
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    writes[nw] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[nw].dstSet = set;
    writes[nw].dstBinding = s.binding;
    writes[nw].descriptorCount = 1;
    writes[nw].descriptorType = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    writes[nw++].pImageInfo = &imgInfo[ni++];
  }
  for (const auto& s : program_->samplers) {
    SamplerImpl* smp = samplers_[s.stage][s.slot];
    imgInfo[ni] = {smp ? smp->sampler : dev_->dummySampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
    writes[nw] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[nw].dstSet = set;
    writes[nw].dstBinding = s.binding;
    writes[nw].descriptorCount = 1;
    writes[nw].descriptorType = VK_DESCRIPTOR_TYPE_SAMPLER;
    writes[nw++].pImageInfo = &imgInfo[ni++];
  }
  vkUpdateDescriptorSets(dev_->vk(), nw, writes, 0, nullptr);
  set_ = set;
  return true;
}

void ContextImpl::Draw(UINT count, UINT start) {
  if (!Commit(false)) return;
  vkCmdDraw(dev_->Cmd(), count, 1, start, 0);
  ++dev_->stats.DrawCalls;
}
void ContextImpl::DrawInstanced(UINT count, UINT instances, UINT start, UINT startInstance) {
  if (!Commit(false)) return;
  vkCmdDraw(dev_->Cmd(), count, instances, start, startInstance);
  ++dev_->stats.DrawCalls;
}
void ContextImpl::DrawIndexed(UINT count, UINT start, int32_t base) {
  if (!Commit(true)) return;
  vkCmdDrawIndexed(dev_->Cmd(), count, 1, start, base, 0);
  ++dev_->stats.DrawCalls;
}
void ContextImpl::DrawIndexedInstanced(UINT count, UINT instances, UINT start, int32_t base, UINT startInstance) {
  if (!Commit(true)) return;
  vkCmdDrawIndexed(dev_->Cmd(), count, instances, start, base, startInstance);
  ++dev_->stats.DrawCalls;
}

// ---------------------------------------------------------------------------
void ContextImpl::ClearRectsInScope(uint32_t attachment, VkImageAspectFlags aspect, const VkClearValue& v,
                                    const RECT* rects, UINT n, uint32_t w, uint32_t h) {
  VkClearAttachment ca{aspect, attachment, v};
  std::vector<VkClearRect> cr;
  if (n == 0) {
    cr.push_back({{{0, 0}, {w, h}}, 0, 1});
  } else {
    for (UINT i = 0; i < n; ++i) {
      int32_t l = std::clamp<int32_t>(rects[i].left, 0, int32_t(w)), t = std::clamp<int32_t>(rects[i].top, 0, int32_t(h));
      int32_t r = std::clamp<int32_t>(rects[i].right, 0, int32_t(w)), b = std::clamp<int32_t>(rects[i].bottom, 0, int32_t(h));
      if (r > l && b > t) cr.push_back({{{l, t}, {uint32_t(r - l), uint32_t(b - t)}}, 0, 1});
    }
  }
  if (!cr.empty()) vkCmdClearAttachments(dev_->Cmd(), 1, &ca, static_cast<uint32_t>(cr.size()), cr.data());
}

void ContextImpl::ClearRenderTargetView(RenderTargetView* rtv, const float color[4]) {
  if (!rtv || !color) {
    dev_->Log(LogLevel::Error, "ClearRenderTargetView: %s is null", rtv ? "ColorRGBA" : "pRenderTargetView");
    return;
  }
  auto* v = static_cast<RTVImpl*>(rtv);
  VkClearValue cv;
  cv.color = ToClearColor(v->v, color);
  for (uint32_t i = 0; i < numRT_; ++i)
    if (rtvs_[i] == v && (rendering_ || BeginRendering())) {
      ClearRectsInScope(i, VK_IMAGE_ASPECT_COLOR_BIT, cv, nullptr, 0, renderW_, renderH_);
      // Only the render area was cleared; clear the rest if the view is larger.
      if (v->v.tex->MipWidth(v->v.baseMip) == renderW_ && v->v.tex->MipHeight(v->v.baseMip) == renderH_) return;
      break;
    }
  EndRendering();
  UseTexture(v->v.tex, v->v.baseMip, 1, v->v.baseLayer, 1, usage::TransferDst);
  FlushBarriers();
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, v->v.baseMip, 1, v->v.baseLayer, 1};
  vkCmdClearColorImage(dev_->Cmd(), v->v.tex->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &cv.color, 1, &range);
  v->v.tex->lastUseSerial = v->v.tex->lastWriteSerial = dev_->CurrentSerial();
}

void ContextImpl::ClearDepthStencilView(DepthStencilView* dsv, UINT flags, float depth, uint8_t) {
  if (!dsv) {
    dev_->Log(LogLevel::Error, "ClearDepthStencilView: pDepthStencilView is null");
    return;
  }
  if (!(flags & CLEAR_DEPTH)) return;  // no stencil formats
  auto* v = static_cast<DSVImpl*>(dsv);
  VkClearValue cv;
  cv.depthStencil = {std::clamp(depth, 0.0f, 1.0f), 0};
  if (dsv_ == v && (rendering_ || BeginRendering())) {
    ClearRectsInScope(0, VK_IMAGE_ASPECT_DEPTH_BIT, cv, nullptr, 0, renderW_, renderH_);
    if (v->v.tex->MipWidth(v->v.baseMip) == renderW_ && v->v.tex->MipHeight(v->v.baseMip) == renderH_) return;
  }
  EndRendering();
  UseTexture(v->v.tex, v->v.baseMip, 1, v->v.baseLayer, 1, usage::TransferDst);
  FlushBarriers();
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, v->v.baseMip, 1, v->v.baseLayer, 1};
  vkCmdClearDepthStencilImage(dev_->Cmd(), v->v.tex->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              &cv.depthStencil, 1, &range);
}

void ContextImpl::ClearView(View* view, const float color[4], const RECT* rects, UINT numRects) {
  if (!view || !color || (numRects && !rects)) {
    dev_->Log(LogLevel::Error, "ClearView: %s is null", !view ? "pView" : !color ? "Color" : "pRect");
    return;
  }
  auto* v = dynamic_cast<RTVImpl*>(view);
  if (!v) {
    dev_->Log(LogLevel::Error, "ClearView: only render-target views are supported");
    return;
  }
  if (numRects == 0) {
    ClearRenderTargetView(v, color);
    return;
  }
  VkClearValue cv;
  cv.color = ToClearColor(v->v, color);
  for (uint32_t i = 0; i < numRT_; ++i)
    if (rtvs_[i] == v) {
      if (!rendering_ && !BeginRendering()) return;
      ClearRectsInScope(i, VK_IMAGE_ASPECT_COLOR_BIT, cv, rects, numRects, renderW_, renderH_);
      return;
    }
  // Not bound: a short rendering scope with only this view.
  EndRendering();
  UseTexture(v->v.tex, v->v.baseMip, 1, v->v.baseLayer, 1, usage::ColorAttachment);
  FlushBarriers();
  uint32_t w = v->v.tex->MipWidth(v->v.baseMip), h = v->v.tex->MipHeight(v->v.baseMip);
  VkRenderingAttachmentInfo att{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  att.imageView = v->v.Current();
  att.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  att.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, {w, h}};
  ri.layerCount = 1;
  ri.colorAttachmentCount = 1;
  ri.pColorAttachments = &att;
  vkCmdBeginRendering(dev_->Cmd(), &ri);
  ClearRectsInScope(0, VK_IMAGE_ASPECT_COLOR_BIT, cv, rects, numRects, w, h);
  vkCmdEndRendering(dev_->Cmd());
  v->v.tex->lastUseSerial = v->v.tex->lastWriteSerial = dev_->CurrentSerial();
}

}  // namespace d3dl::impl
