// Shader-resource, render-target and depth-stencil views: VkImageViews (one
// per image of the texture; swap-chain back buffers have several). The
// arguments are checked by ValidateViewResource & co. first.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {

bool RebuildViews(DeviceImpl* dev, ViewCore& v) {
  for (VkImageView view : v.views) dev->Defer(VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<uint64_t>(view));
  v.views.clear();
  const bool is1D = v.tex->dim == RESOURCE_DIMENSION_TEXTURE1D;
  const bool array = v.tex->desc.ArraySize > 1 && v.layerCount > 1;
  VkImageViewType type = is1D ? (array ? VK_IMAGE_VIEW_TYPE_1D_ARRAY : VK_IMAGE_VIEW_TYPE_1D)
                              : (array ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D);
  for (auto& img : v.tex->images) {
    VkImageViewCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    ci.image = img.image;
    ci.viewType = type;
    ci.format = v.format;
    ci.subresourceRange = {v.aspect, v.baseMip, v.mipCount, v.baseLayer, v.layerCount};
    VkImageView view;
    if (vkCreateImageView(dev->vk(), &ci, nullptr, &view) != VK_SUCCESS) return false;
    v.views.push_back(view);
  }
  return true;
}

template <class Iface, ViewKind Kind>
ViewImpl<Iface, Kind>::~ViewImpl() {
  for (VkImageView view : v.views)
    this->dev_->Defer(VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<uint64_t>(view));
  if (v.tex) {
    auto& reg = v.tex->registeredViews;
    reg.erase(std::remove(reg.begin(), reg.end(), &v), reg.end());
  }
  if (v.resource) v.resource->Release();
}

template <class Iface, ViewKind Kind>
void ViewImpl<Iface, Kind>::OnDebugName() {
  for (VkImageView view : v.views)
    this->dev_->SetName(VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<uint64_t>(view), this->name_);
}

template class ViewImpl<ShaderResourceView, ViewKind::SRV>;
template class ViewImpl<RenderTargetView, ViewKind::RTV>;
template class ViewImpl<DepthStencilView, ViewKind::DSV>;
template class ViewImpl<UnorderedAccessView, ViewKind::UAV>;

namespace {

// A view of `r` (validated) in `format` over the given mips and all layers
// (one layer for render-target and depth-stencil views).
template <class Impl, class Iface>
HRESULT MakeView(DeviceImpl* dev, const char* fn, Resource* r, const ViewFormat& format, uint32_t baseMip,
                 uint32_t mipCount, bool oneLayer, Iface** out) {
  auto* view = new Impl(dev);
  ViewCore& v = view->v;
  v.tex = AsTexture(r);
  v.aspect = v.tex->aspect;
  v.format = format.vk;
  v.dxgiFormat = format.dxgi;
  v.baseMip = baseMip;
  v.mipCount = mipCount;
  v.layerCount = oneLayer ? 1 : v.tex->desc.ArraySize;
  if (!RebuildViews(dev, v)) {
    dev->Log(LogLevel::Error, "%s: vkCreateImageView failed", fn);
    view->Release();
    return E_INVALIDARG;
  }
  v.resource = r;
  r->AddRef();
  if (v.tex->swapChain) v.tex->registeredViews.push_back(&v);
  *out = view;
  return S_OK;
}

template <class Iface>
DXGI_FORMAT RequestedFormat(const Iface* desc) {
  return desc ? desc->Format : DXGI_FORMAT_UNKNOWN;
}

// Render-target and depth-stencil views: one mip, one layer.
template <class Impl, class Desc, class Iface>
HRESULT CreateMipSliceView(DeviceImpl* dev, const ViewKindInfo& kind, Resource* r, const Desc* desc, Iface** out) {
  if (out) *out = nullptr;
  ViewFormat format;
  const UINT mip = desc ? desc->MipSlice : 0;
  HRESULT hr = ValidateViewResource(*dev, kind, r, out, RequestedFormat(desc), &format);
  if constexpr (std::is_same_v<Desc, DEPTH_STENCIL_VIEW_DESC>) {
    if (SUCCEEDED(hr)) hr = ValidateDsvFormat(*dev, desc);
  }
  if (SUCCEEDED(hr)) hr = ValidateMipSlice(*dev, kind.fn, *AsTexture(r), mip);
  if (FAILED(hr)) return hr;
  return MakeView<Impl>(dev, kind.fn, r, format, mip, 1, true, out);
}

}  // namespace

HRESULT DeviceImpl::CreateShaderResourceView(Resource* r, const SHADER_RESOURCE_VIEW_DESC* desc,
                                             ShaderResourceView** out) {
  if (out) *out = nullptr;
  if (AsBuffer(r)) return CreateBufferSRV(this, r, desc, out);
  ViewFormat format;
  uint32_t baseMip, mipCount;
  HRESULT hr = ValidateViewResource(*this, kSrvKind, r, out, RequestedFormat(desc), &format);
  if (SUCCEEDED(hr)) hr = ValidateSrvMips(*this, *AsTexture(r), desc, &baseMip, &mipCount);
  if (FAILED(hr)) return hr;
  return MakeView<SRVImpl>(this, kSrvKind.fn, r, format, baseMip, mipCount, false, out);
}

HRESULT DeviceImpl::CreateRenderTargetView(Resource* r, const RENDER_TARGET_VIEW_DESC* desc,
                                           RenderTargetView** out) {
  return CreateMipSliceView<RTVImpl>(this, kRtvKind, r, desc, out);
}

HRESULT DeviceImpl::CreateDepthStencilView(Resource* r, const DEPTH_STENCIL_VIEW_DESC* desc,
                                           DepthStencilView** out) {
  return CreateMipSliceView<DSVImpl>(this, kDsvKind, r, desc, out);
}

}  // namespace d3dl::impl
