// Shader-resource, render-target and depth-stencil views (Views.cpp).
#pragma once

#include <vector>

#include "Resources.h"
#include "ValidationDevice.h"

namespace d3dl::impl {

struct ViewCore {
  Resource* resource = nullptr;  // holds a reference
  TextureCore* tex = nullptr;    // null for a buffer view
  // Buffer views (structured or raw SRVs/UAVs): the bytes they see.
  BufferImpl* buf = nullptr;
  VkDeviceSize bufOffset = 0, bufRange = 0;
  VkFormat format = VK_FORMAT_UNDEFINED;
  DXGI_FORMAT dxgiFormat = DXGI_FORMAT_UNKNOWN;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  uint32_t baseMip = 0, mipCount = 1, baseLayer = 0, layerCount = 1;
  VkImageViewType type = VK_IMAGE_VIEW_TYPE_2D;  // from the view dimension
  std::vector<VkImageView> views;  // one per image of the texture
  VkImageView Current() const { return views[tex->current]; }
  SubresourceRange range() const { return {baseMip, mipCount, baseLayer, layerCount}; }
  uint32_t Width() const { return tex->MipWidth(baseMip); }
  uint32_t Height() const { return tex->MipHeight(baseMip); }
  uint32_t Samples() const { return tex->desc.SampleDesc.Count; }
};

enum class ViewKind { SRV, RTV, DSV, UAV };
// (Re)creates the VkImageViews of a view, one per image of its texture.
bool RebuildViews(DeviceImpl* dev, ViewCore& v);
struct ViewFormat;  // Validate.h
// The Vulkan format and aspect of a texture view (`v.tex` set) from the DXGI
// format and aspect its validation settled on (Views.cpp).
void SetViewFormat(ViewCore& v, const ViewFormat& format);
// What the validation layer sees of a view (ValidationDevice.h).
ViewInfo DescribeView(const ViewCore& v);

template <class Iface, ViewKind Kind>
class ViewImpl final : public Child<Iface> {
 public:
  explicit ViewImpl(DeviceImpl* d) : Child<Iface>(d) {}
  ~ViewImpl() override;
  void GetResource(Resource** r) const override {
    if (!r) return;
    *r = v.resource;
    if (*r) (*r)->AddRef();
  }
  void OnDebugName() override;
  ViewCore v;
};
using SRVImpl = ViewImpl<ShaderResourceView, ViewKind::SRV>;
using RTVImpl = ViewImpl<RenderTargetView, ViewKind::RTV>;
using DSVImpl = ViewImpl<DepthStencilView, ViewKind::DSV>;
using UAVImpl = ViewImpl<UnorderedAccessView, ViewKind::UAV>;

// Buffer views (ComputeViews.cpp): an SRV of a structured or
// raw buffer (CreateShaderResourceView hands buffers to it).
HRESULT CreateBufferSRV(DeviceImpl* dev, Resource* r, const SHADER_RESOURCE_VIEW_DESC* desc,
                        ShaderResourceView** out);

}  // namespace d3dl::impl
