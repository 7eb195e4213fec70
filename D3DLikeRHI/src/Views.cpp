// Shader-resource, render-target and depth-stencil views: VkImageViews (one
// per image of the texture; swap-chain back buffers have several). The
// arguments are checked by ValidateViewResource & co. first; what they return
// (a DXGI format, an aspect, a D3D11 view dimension) becomes Vulkan's here.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {

ViewInfo DescribeView(const ViewCore& v) {
  ViewInfo info;
  if (v.tex || v.buf) info.resource = DescribeResource(v.resource);
  info.format = v.dxgiFormat;
  return info;
}

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
template class ViewImpl<UnorderedAccessView, ViewKind::UAV>;

void SetViewFormat(ViewCore& v, const ViewFormat& format) {
  v.dxgiFormat = format.format;
  switch (format.aspect) {
    case ViewAspect::Color:
      v.format = ToVkFormat(format.format);
      v.aspect = VK_IMAGE_ASPECT_COLOR_BIT;
      break;
    case ViewAspect::Depth:  // the depth image's own format, its depth aspect
      v.format = v.tex->format;
      v.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
      break;
    case ViewAspect::Attachment:
      v.format = v.tex->format;
      v.aspect = v.tex->aspect;
      break;
  }
}

namespace {
VkImageViewType VkViewType(ViewDim d) {
  switch (d) {
    case ViewDim::Tex1D: return VK_IMAGE_VIEW_TYPE_1D;
    case ViewDim::Tex1DArray: return VK_IMAGE_VIEW_TYPE_1D_ARRAY;
    case ViewDim::Tex2DArray:
    case ViewDim::Tex2DMSArray: return VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    case ViewDim::Cube: return VK_IMAGE_VIEW_TYPE_CUBE;
    case ViewDim::CubeArray: return VK_IMAGE_VIEW_TYPE_CUBE_ARRAY;
    default: return VK_IMAGE_VIEW_TYPE_2D;
  }
}

// A view of `r` (validated) in `format` over the mips and slices of `shape`.
template <class Impl, class Iface>
HRESULT MakeView(DeviceImpl* dev, const char* fn, Resource* r, const ViewFormat& format, const ViewShape& shape,
                 Iface** out) {
  auto* view = new Impl(dev);
  ViewCore& v = view->v;
  v.tex = AsTexture(r);
  SetViewFormat(v, format);
  v.baseMip = shape.baseMip;
  v.mipCount = shape.mipCount;
  v.baseLayer = shape.baseLayer;
  v.layerCount = shape.layerCount;
  v.type = VkViewType(shape.dim);
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
  const ResourceInfo info = DescribeResource(r);
  HRESULT hr = ValidateViewResource(*dev, kind, info, out, RequestedFormat(desc), &format);
  if (SUCCEEDED(hr))
    hr = ValidateTargetShape(*dev, kind, info, dim, desc ? UINT(desc->ViewDimension) : 0, desc ? desc->MipSlice : 0,
                             desc ? desc->Array : TEX_ARRAY_RANGE{}, &shape);
  if (FAILED(hr)) return hr;
  return MakeView<Impl>(dev, kind.fn, r, format, shape, out);
}

}  // namespace

HRESULT DeviceImpl::CreateShaderResourceView(Resource* r, const SHADER_RESOURCE_VIEW_DESC* desc,
                                             ShaderResourceView** out) {
  if (out) *out = nullptr;
  if (AsBuffer(r)) return CreateBufferSRV(this, r, desc, out);
  ViewFormat format;
  ViewShape shape;
  const ResourceInfo info = DescribeResource(r);
  HRESULT hr = ValidateViewResource(*this, kSrvKind, info, out, RequestedFormat(desc), &format);
  if (SUCCEEDED(hr)) hr = ValidateSrvShape(*this, info, desc, &shape);
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

// ---------------------------------------------------------------------------
// Zero views for unbound SRV slots of every declared image shape, so an
// unbound Texture2DArray / TextureCube / Texture2DMS reads zeros as in D3D11
// instead of a view of the wrong type.
bool DeviceImpl::CreateDummyLayers(uint32_t layers, VkSampleCountFlagBits samples, VkImageCreateFlags flags,
                                   VkImage* image) {
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.flags = flags;
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = VK_FORMAT_R8G8B8A8_UNORM;
  ici.extent = {1, 1, 1};
  ici.mipLevels = 1;
  ici.arrayLayers = layers;
  ici.samples = samples;
  ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (vkCreateImage(device_, &ici, nullptr, image) != VK_SUCCESS) return false;
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device_, *image, &req);
  VkDeviceMemory mem;
  dummyGarbage_.push_back({VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(*image)});
  if (!AllocateMemory(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, &mem)) return false;
  dummyGarbage_.push_back({VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(mem)});
  vkBindImageMemory(device_, *image, mem, 0);
  // Zeroed by the first upload batch, then shader-readable.
  const TransferInit t = TransferInitBarriers(VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_MEMORY_READ_BIT,
                                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
  VkCommandBuffer cb = UploadCmd();
  VkImageMemoryBarrier2 b = ImageBarrier(*image, range, t.before);
  RecordImageBarriers(cb, &b, 1);
  const VkClearColorValue zero{};
  vkCmdClearColorImage(cb, *image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
  b = ImageBarrier(*image, range, t.after);
  RecordImageBarriers(cb, &b, 1);
  return true;
}

bool DeviceImpl::CreateViewDummies(VkImage image1D) {
  VkImageView* views = dummies_.views;
  views[DummyViewIndex(VK_IMAGE_VIEW_TYPE_1D, false)] = dummies_.view1D;
  views[DummyViewIndex(VK_IMAGE_VIEW_TYPE_2D, false)] = dummies_.view2D;
  auto view = [&](VkImage image, VkImageViewType type, uint32_t layers, bool ms) {
    VkImageViewCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    ci.image = image;
    ci.viewType = type;
    ci.format = VK_FORMAT_R8G8B8A8_UNORM;
    ci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
    VkImageView& v = views[DummyViewIndex(type, ms)];
    if (vkCreateImageView(device_, &ci, nullptr, &v) != VK_SUCCESS) return false;
    dummyGarbage_.push_back({VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<uint64_t>(v)});
    return true;
  };
  VkImage cube, ms;
  if (!view(image1D, VK_IMAGE_VIEW_TYPE_1D_ARRAY, 1, false) ||
      !CreateDummyLayers(6, VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT, &cube) ||
      !view(cube, VK_IMAGE_VIEW_TYPE_2D_ARRAY, 1, false) || !view(cube, VK_IMAGE_VIEW_TYPE_CUBE, 6, false) ||
      (features_.cubeArray && !view(cube, VK_IMAGE_VIEW_TYPE_CUBE_ARRAY, 6, false)))
    return false;
  // The smallest multisampled count the adapter can sample (none: no MSAA SRVs).
  const VkSampleCountFlags counts = props_.limits.sampledImageColorSampleCounts & ~VkSampleCountFlags(1);
  if (!counts) return true;
  const auto samples = static_cast<VkSampleCountFlagBits>(counts & (~counts + 1));
  return CreateDummyLayers(1, samples, 0, &ms) && view(ms, VK_IMAGE_VIEW_TYPE_2D, 1, true) &&
         view(ms, VK_IMAGE_VIEW_TYPE_2D_ARRAY, 1, true);
}

}  // namespace d3dl::impl
