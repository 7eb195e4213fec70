// Clears: inside the rendering scope (vkCmdClearAttachments) when the view is
// bound, else with the transfer clears or a short scope of its own.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {
namespace {
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

// Clears every slice of the rendering scope (D3D11 clears all slices of a view).
void ContextImpl::ClearRectsInScope(uint32_t attachment, VkImageAspectFlags aspect, const VkClearValue& v,
                                    const RECT* rects, UINT n, uint32_t w, uint32_t h) {
  VkClearAttachment ca{aspect, attachment, v};
  std::vector<VkClearRect> cr;
  const uint32_t layers = rendering_ ? renderLayers_ : 1;
  if (n == 0) {
    cr.push_back({{{0, 0}, {w, h}}, 0, layers});
  } else {
    for (UINT i = 0; i < n; ++i) {
      int32_t l = std::clamp<int32_t>(rects[i].left, 0, int32_t(w)), t = std::clamp<int32_t>(rects[i].top, 0, int32_t(h));
      int32_t r = std::clamp<int32_t>(rects[i].right, 0, int32_t(w)), b = std::clamp<int32_t>(rects[i].bottom, 0, int32_t(h));
      if (r > l && b > t) cr.push_back({{{l, t}, {uint32_t(r - l), uint32_t(b - t)}}, 0, layers});
    }
  }
  if (!cr.empty()) vkCmdClearAttachments(Cmd(), 1, &ca, static_cast<uint32_t>(cr.size()), cr.data());
}

// Slot of `v` among the bound render targets, or -1.
int ContextImpl::BoundRenderTargetSlot(const RTVImpl* v) const {
  for (uint32_t i = 0; i < state_.om.numRenderTargets; ++i)
    if (state_.om.renderTargets[i].Get() == v) return static_cast<int>(i);
  return -1;
}

void ContextImpl::ClearRenderTargetView(RenderTargetView* rtv, const float color[4]) {
  if (!ValidateClearRenderTargetView(*dev_, rtv, color)) return;
  auto* v = static_cast<RTVImpl*>(rtv);
  Hold(v);
  VkClearValue cv;
  cv.color = ToClearColor(v->v, color);
  const int slot = BoundRenderTargetSlot(v);
  if (slot >= 0 && (rendering_ || BeginRendering())) {
    ClearRectsInScope(uint32_t(slot), VK_IMAGE_ASPECT_COLOR_BIT, cv, nullptr, 0, renderW_, renderH_);
    // Only the render area and slices were cleared; clear the rest if the view is larger.
    if (v->v.Width() == renderW_ && v->v.Height() == renderH_ && v->v.layerCount == renderLayers_) return;
  }
  EndRendering();
  UseTexture(v->v.tex, v->v.range(), usage::TransferDst);
  FlushBarriers();
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, v->v.baseMip, 1, v->v.baseLayer, v->v.layerCount};
  vkCmdClearColorImage(Cmd(), v->v.tex->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &cv.color, 1, &range);
  NoteUse(v->v.tex->use, true);
}

void ContextImpl::ClearDepthStencilView(DepthStencilView* dsv, UINT flags, float depth, uint8_t stencil) {
  if (!ValidateClearDepthStencilView(*dev_, dsv)) return;
  auto* v = static_cast<DSVImpl*>(dsv);
  VkImageAspectFlags aspect = (flags & CLEAR_DEPTH) ? VK_IMAGE_ASPECT_DEPTH_BIT : 0;
  if (flags & CLEAR_STENCIL) aspect |= v->v.aspect & VK_IMAGE_ASPECT_STENCIL_BIT;
  if (!aspect) return;
  Hold(v);
  VkClearValue cv;
  cv.depthStencil = {std::clamp(depth, 0.0f, 1.0f), stencil};
  if (state_.om.depthStencilView.Get() == v && (rendering_ || BeginRendering())) {
    ClearRectsInScope(0, aspect, cv, nullptr, 0, renderW_, renderH_);
    if (v->v.Width() == renderW_ && v->v.Height() == renderH_ && v->v.layerCount == renderLayers_) return;
  }
  EndRendering();
  UseTexture(v->v.tex, v->v.range(), usage::TransferDst);
  FlushBarriers();
  VkImageSubresourceRange range{aspect, v->v.baseMip, 1, v->v.baseLayer, v->v.layerCount};
  vkCmdClearDepthStencilImage(Cmd(), v->v.tex->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              &cv.depthStencil, 1, &range);
}

void ContextImpl::ClearView(View* view, const float color[4], const RECT* rects, UINT numRects) {
  auto* v = dynamic_cast<RTVImpl*>(view);
  if (!ValidateClearView(*dev_, view, v != nullptr, color, rects, numRects)) return;
  Hold(v);
  if (numRects == 0) {
    ClearRenderTargetView(v, color);
    return;
  }
  VkClearValue cv;
  cv.color = ToClearColor(v->v, color);
  const int slot = BoundRenderTargetSlot(v);
  if (slot < 0) return ClearUnboundView(v, cv, rects, numRects);
  if (!rendering_ && !BeginRendering()) return;
  ClearRectsInScope(uint32_t(slot), VK_IMAGE_ASPECT_COLOR_BIT, cv, rects, numRects, renderW_, renderH_);
}

// A short rendering scope with only this view.
void ContextImpl::ClearUnboundView(RTVImpl* v, const VkClearValue& cv, const RECT* rects, UINT numRects) {
  EndRendering();
  UseTexture(v->v.tex, v->v.range(), usage::ColorAttachment);
  FlushBarriers();
  const uint32_t w = v->v.Width(), h = v->v.Height();
  VkRenderingAttachmentInfo att = LoadStoreAttachment(v->v.Current(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, {w, h}};
  ri.layerCount = v->v.layerCount;
  ri.colorAttachmentCount = 1;
  ri.pColorAttachments = &att;
  vkCmdBeginRendering(Cmd(), &ri);
  rendering_ = true;  // for ClearRectsInScope's slice count
  renderLayers_ = v->v.layerCount;
  ClearRectsInScope(0, VK_IMAGE_ASPECT_COLOR_BIT, cv, rects, numRects, w, h);
  vkCmdEndRendering(Cmd());
  rendering_ = false;
  NoteUse(v->v.tex->use, true);
}

}  // namespace d3dl::impl
