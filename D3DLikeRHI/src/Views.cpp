// Shader-resource, render-target and depth-stencil views: VkImageViews (one
// per image of the texture; swap-chain back buffers have several).
#include "Context.h"

namespace d3dl::impl {
namespace {

}  // namespace

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

namespace {

// Common checks; fills v.tex, v.resource (no reference yet) and the format.
HRESULT Prepare(DeviceImpl* dev, const char* fn, Resource* r, DXGI_FORMAT requested, UINT bind,
                const char* bindName, ViewCore& v) {
  if (!r) {
    dev->Log(LogLevel::Error, "%s: pResource is null", fn);
    return E_INVALIDARG;
  }
  TextureCore* t = AsTexture(r);
  if (!t) {
    dev->Log(LogLevel::Error, "%s: the resource is a buffer; only texture views are supported", fn);
    return E_INVALIDARG;
  }
  if (!(t->desc.BindFlags & bind)) {
    dev->Log(LogLevel::Error, "%s: the texture was not created with %s (BindFlags 0x%x)", fn, bindName, t->desc.BindFlags);
    return E_INVALIDARG;
  }
  v.tex = t;
  v.aspect = t->aspect;
  DXGI_FORMAT f = requested == DXGI_FORMAT_UNKNOWN ? t->desc.Format : requested;
  if (t->aspect == VK_IMAGE_ASPECT_DEPTH_BIT) {
    if (f != DXGI_FORMAT_R32_FLOAT && f != DXGI_FORMAT_D32_FLOAT && f != DXGI_FORMAT_R32_TYPELESS) {
      dev->Log(LogLevel::Error, "%s: Format %s cannot view a 32-bit depth texture", fn, FormatName(f));
      return E_INVALIDARG;
    }
    v.format = VK_FORMAT_D32_SFLOAT;
    v.dxgiFormat = f;
    return S_OK;
  }
  const FormatInfo* fi = GetFormatInfo(f);
  if (!fi || (f == DXGI_FORMAT_R32_TYPELESS && requested == DXGI_FORMAT_UNKNOWN)) {
    dev->Log(LogLevel::Error, "%s: Format %u (%s) cannot be used for a view", fn, f, FormatName(f));
    return E_INVALIDARG;
  }
  if (fi->bytes != t->fmt->bytes || fi->bc != t->fmt->bc || fi->depth) {
    dev->Log(LogLevel::Error, "%s: view Format %s is not compatible with texture Format %s", fn, fi->name, t->fmt->name);
    return E_INVALIDARG;
  }
  v.format = fi->vk;
  v.dxgiFormat = f;
  return S_OK;
}

template <class V>
HRESULT Finish(DeviceImpl* dev, const char* fn, Resource* r, V* view, ViewCore& v, auto** out) {
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

// Render-target and depth-stencil views: one mip, one layer.
template <class V>
HRESULT FinishMipSlice(DeviceImpl* dev, const char* fn, Resource* r, V* view, uint32_t mip, auto** out) {
  ViewCore& v = view->v;
  if (mip >= v.tex->desc.MipLevels) {
    dev->Log(LogLevel::Error, "%s: MipSlice %u out of range (texture has %u mips)", fn, mip, v.tex->desc.MipLevels);
    view->Release();
    return E_INVALIDARG;
  }
  v.baseMip = mip;
  v.mipCount = 1;
  v.layerCount = 1;
  return Finish(dev, fn, r, view, v, out);
}

}  // namespace

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

// What every Create*View starts with: the output pointer, a new view object
// and the resource / format / bind-flag checks of Prepare. nullptr (and *hr
// set) when any of them fails; the caller then returns *hr.
template <class Impl, class Iface>
static Impl* BeginView(DeviceImpl* dev, const char* fn, const char* outName, Resource* r,
                       DXGI_FORMAT format, UINT bind, const char* bindName, Iface** out,
                       HRESULT* hr) {
  if (!out) {
    dev->Log(LogLevel::Error, "%s: %s is null", fn, outName);
    *hr = E_INVALIDARG;
    return nullptr;
  }
  *out = nullptr;
  auto* view = new Impl(dev);
  *hr = Prepare(dev, fn, r, format, bind, bindName, view->v);
  if (FAILED(*hr)) {
    view->Release();
    return nullptr;
  }
  return view;
}

HRESULT DeviceImpl::CreateShaderResourceView(Resource* r, const SHADER_RESOURCE_VIEW_DESC* desc,
                                             ShaderResourceView** out) {
  const char* fn = "CreateShaderResourceView";
  HRESULT hr;
  auto* view = BeginView<SRVImpl>(this, fn, "ppSRView", r, desc ? desc->Format : DXGI_FORMAT_UNKNOWN,
                                  BIND_SHADER_RESOURCE, "BIND_SHADER_RESOURCE", out, &hr);
  if (!view) return hr;
  ViewCore& v = view->v;
  const TextureCore* t = v.tex;
  uint32_t most = 0, count = t->desc.MipLevels;
  if (desc) {
    SRV_DIMENSION want = t->dim == RESOURCE_DIMENSION_TEXTURE1D ? SRV_DIMENSION_TEXTURE1D
                                                               : SRV_DIMENSION_TEXTURE2D;
    if (desc->ViewDimension != want && desc->ViewDimension != SRV_DIMENSION_UNKNOWN) {
      Log(LogLevel::Error, "%s: ViewDimension %u does not match the texture", fn, desc->ViewDimension);
      view->Release();
      return E_INVALIDARG;
    }
    most = desc->Texture.MostDetailedMip;
    if (most >= t->desc.MipLevels) {
      Log(LogLevel::Error, "%s: MostDetailedMip %u out of range (texture has %u mips)", fn, most, t->desc.MipLevels);
      view->Release();
      return E_INVALIDARG;
    }
    count = desc->Texture.MipLevels == ~0u ? t->desc.MipLevels - most : desc->Texture.MipLevels;
    if (count == 0 || most + count > t->desc.MipLevels) {
      Log(LogLevel::Error, "%s: MipLevels %u out of range (texture has %u mips)", fn, count, t->desc.MipLevels);
      view->Release();
      return E_INVALIDARG;
    }
  }
  v.baseMip = most;
  v.mipCount = count;
  v.baseLayer = 0;
  v.layerCount = t->desc.ArraySize;
  return Finish(this, fn, r, view, v, out);
}

HRESULT DeviceImpl::CreateRenderTargetView(Resource* r, const RENDER_TARGET_VIEW_DESC* desc,
                                           RenderTargetView** out) {
  const char* fn = "CreateRenderTargetView";
  HRESULT hr;
  auto* view = BeginView<RTVImpl>(this, fn, "ppRTView", r, desc ? desc->Format : DXGI_FORMAT_UNKNOWN,
                                  BIND_RENDER_TARGET, "BIND_RENDER_TARGET", out, &hr);
  if (!view) return hr;
  return FinishMipSlice(this, fn, r, view, desc ? desc->MipSlice : 0, out);
}

HRESULT DeviceImpl::CreateDepthStencilView(Resource* r, const DEPTH_STENCIL_VIEW_DESC* desc,
                                           DepthStencilView** out) {
  const char* fn = "CreateDepthStencilView";
  HRESULT hr;
  auto* view = BeginView<DSVImpl>(this, fn, "ppDepthStencilView", r,
                                  desc ? desc->Format : DXGI_FORMAT_UNKNOWN, BIND_DEPTH_STENCIL,
                                  "BIND_DEPTH_STENCIL", out, &hr);
  if (!view) return hr;
  if (desc && desc->Format != DXGI_FORMAT_UNKNOWN && desc->Format != DXGI_FORMAT_D32_FLOAT) {
    Log(LogLevel::Error, "%s: Format %s is not a depth format", fn, FormatName(desc->Format));
    view->Release();
    return E_INVALIDARG;
  }
  return FinishMipSlice(this, fn, r, view, desc ? desc->MipSlice : 0, out);
}

}  // namespace d3dl::impl
