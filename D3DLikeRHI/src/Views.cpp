// Shader-resource, render-target and depth-stencil views: VkImageViews (one
// per image of the texture; swap-chain back buffers have several). The
// arguments are checked by ValidateViewResource & co. first.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {

bool RebuildViews(DeviceImpl* dev, ViewCore& v) {
  for (VkImageView view : v.views) dev->Defer(VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<uint64_t>(view));
  v.views.clear();
  for (auto& img : v.tex->images) {
    VkImageViewCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    ci.image = img.image;
    ci.viewType = v.type;
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

namespace {

// A view of `r` (validated) in `format` over the mips and slices of `shape`.
template <class Impl, class Iface>
HRESULT MakeView(DeviceImpl* dev, const char* fn, Resource* r, const ViewFormat& format, const ViewShape& shape,
                 Iface** out) {
  auto* view = new Impl(dev);
  ViewCore& v = view->v;
  v.tex = AsTexture(r);
  v.aspect = format.aspect;
  v.format = format.vk;
  v.dxgiFormat = format.dxgi;
  v.baseMip = shape.baseMip;
  v.mipCount = shape.mipCount;
  v.baseLayer = shape.baseLayer;
  v.layerCount = shape.layerCount;
  v.type = shape.type;
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

// Render-target and depth-stencil views: one mip, a slice or a slice range.
template <class Impl, class Desc, class Iface>
HRESULT CreateTargetView(DeviceImpl* dev, const ViewKindInfo& kind, Resource* r, const Desc* desc, ViewDim dim,
                         Iface** out) {
  if (out) *out = nullptr;
  ViewFormat format;
  ViewShape shape;
  HRESULT hr = ValidateViewResource(*dev, kind, r, out, RequestedFormat(desc), &format);
  if (SUCCEEDED(hr) && dim == ViewDim::Invalid) {
    dev->Log(LogLevel::Error, "%s: ViewDimension %u is invalid", kind.fn, static_cast<UINT>(desc->ViewDimension));
    hr = E_INVALIDARG;
  }
  if (SUCCEEDED(hr))
    hr = ValidateTargetShape(*dev, kind, *AsTexture(r), dim, desc ? desc->MipSlice : 0,
                             desc ? desc->Array : TEX_ARRAY_RANGE{}, &shape);
  if (FAILED(hr)) return hr;
  return MakeView<Impl>(dev, kind.fn, r, format, shape, out);
}

}  // namespace

HRESULT DeviceImpl::CreateShaderResourceView(Resource* r, const SHADER_RESOURCE_VIEW_DESC* desc,
                                             ShaderResourceView** out) {
  if (out) *out = nullptr;
  ViewFormat format;
  ViewShape shape;
  HRESULT hr = ValidateViewResource(*this, kSrvKind, r, out, RequestedFormat(desc), &format);
  if (SUCCEEDED(hr) && desc && FromSrvDimension(desc->ViewDimension) == ViewDim::Invalid) {
    Log(LogLevel::Error, "%s: ViewDimension %u is invalid", kSrvKind.fn, static_cast<UINT>(desc->ViewDimension));
    hr = E_INVALIDARG;
  }
  if (SUCCEEDED(hr)) hr = ValidateSrvShape(*this, *AsTexture(r), desc, &shape);
  if (FAILED(hr)) return hr;
  return MakeView<SRVImpl>(this, kSrvKind.fn, r, format, shape, out);
}

HRESULT DeviceImpl::CreateRenderTargetView(Resource* r, const RENDER_TARGET_VIEW_DESC* desc,
                                           RenderTargetView** out) {
  const ViewDim dim = desc ? FromRtvDimension(desc->ViewDimension) : ViewDim::Unknown;
  return CreateTargetView<RTVImpl>(this, kRtvKind, r, desc, dim, out);
}

HRESULT DeviceImpl::CreateDepthStencilView(Resource* r, const DEPTH_STENCIL_VIEW_DESC* desc,
                                           DepthStencilView** out) {
  const ViewDim dim = desc ? FromDsvDimension(desc->ViewDimension) : ViewDim::Unknown;
  return CreateTargetView<DSVImpl>(this, kDsvKind, r, desc, dim, out);
}

}  // namespace d3dl::impl
