// Views for compute and pixel-shader stores: UAVs of 2-D textures (a VkImageView
// used as a storage image) and of structured/raw buffers, and SRVs of
// structured/raw buffers (storage-buffer descriptors over a byte range).
// The arguments are checked by ValidateBufferView / ValidateTextureUav first.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {
namespace {

template <class Impl, class Iface>
HRESULT MakeBufferView(DeviceImpl* dev, Resource* r, VkDeviceSize offset, VkDeviceSize range, Iface** out) {
  auto* view = new Impl(dev);
  ViewCore& v = view->v;
  v.buf = AsBuffer(r);
  v.bufOffset = offset;
  v.bufRange = range;
  v.resource = r;
  r->AddRef();
  *out = view;
  return S_OK;
}

HRESULT MakeTextureUav(DeviceImpl* dev, Resource* r, const ViewFormat& format, uint32_t mip,
                       UnorderedAccessView** out) {
  auto* view = new UAVImpl(dev);
  ViewCore& v = view->v;
  v.tex = AsTexture(r);
  v.aspect = v.tex->aspect;
  v.format = format.vk;
  v.dxgiFormat = format.dxgi;
  v.baseMip = mip;
  if (!RebuildViews(dev, v)) {
    dev->Log(LogLevel::Error, "%s: vkCreateImageView failed", kUavKind.fn);
    view->Release();
    return E_INVALIDARG;
  }
  v.resource = r;
  r->AddRef();
  *out = view;
  return S_OK;
}

}  // namespace

HRESULT CreateBufferSRV(DeviceImpl* dev, Resource* r, const SHADER_RESOURCE_VIEW_DESC* desc,
                        ShaderResourceView** out) {
  if (desc && desc->ViewDimension != SRV_DIMENSION_BUFFEREX && desc->ViewDimension != SRV_DIMENSION_BUFFER) {
    dev->Log(LogLevel::Error, "%s: ViewDimension %u does not match a buffer (SRV_DIMENSION_BUFFEREX)", kSrvKind.fn,
             desc->ViewDimension);
    return E_INVALIDARG;
  }
  BufferViewRequest req{};
  if (desc)
    req = {desc->Format, desc->BufferEx.FirstElement, desc->BufferEx.NumElements,
           desc->BufferEx.Flags & ~UINT(BUFFEREX_SRV_FLAG_RAW), (desc->BufferEx.Flags & BUFFEREX_SRV_FLAG_RAW) != 0};
  VkDeviceSize offset = 0, range = 0;
  const HRESULT hr = ValidateBufferView(*dev, kSrvKind, r, out, desc ? &req : nullptr, &offset, &range);
  if (FAILED(hr)) return hr;
  return MakeBufferView<SRVImpl>(dev, r, offset, range, out);
}

HRESULT DeviceImpl::CreateUnorderedAccessView(Resource* r, const UNORDERED_ACCESS_VIEW_DESC* desc,
                                              UnorderedAccessView** out) {
  if (out) *out = nullptr;
  if (!AsBuffer(r)) {
    ViewFormat format;
    uint32_t mip = 0;
    const HRESULT hr = ValidateTextureUav(*this, r, desc, out, &format, &mip);
    if (FAILED(hr)) return hr;
    return MakeTextureUav(this, r, format, mip, out);
  }
  if (desc && desc->ViewDimension != UAV_DIMENSION_BUFFER) {
    Log(LogLevel::Error, "%s: ViewDimension %u does not match a buffer (UAV_DIMENSION_BUFFER)", kUavKind.fn,
        desc->ViewDimension);
    return E_INVALIDARG;
  }
  BufferViewRequest req{};
  if (desc)
    req = {desc->Format, desc->Buffer.FirstElement, desc->Buffer.NumElements,
           desc->Buffer.Flags & ~UINT(BUFFER_UAV_FLAG_RAW), (desc->Buffer.Flags & BUFFER_UAV_FLAG_RAW) != 0};
  VkDeviceSize offset = 0, range = 0;
  const HRESULT hr = ValidateBufferView(*this, kUavKind, r, out, desc ? &req : nullptr, &offset, &range);
  if (FAILED(hr)) return hr;
  return MakeBufferView<UAVImpl>(this, r, offset, range, out);
}

}  // namespace d3dl::impl
