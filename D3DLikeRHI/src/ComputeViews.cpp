// Views for compute and pixel-shader stores: UAVs of 2-D textures (a VkImageView
// used as a storage image) and of structured/raw buffers, and SRVs of
// structured/raw buffers (storage-buffer descriptors over a byte range).
// The arguments are checked by ValidateBufferView / ValidateTextureUav first.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {
namespace {

template <class Impl, class Iface>
HRESULT MakeBufferView(DeviceImpl* dev, Resource* r, UINT64 offset, UINT64 range, Iface** out) {
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
  SetViewFormat(v, format);
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
  BufferViewRequest req{};
  UINT64 offset = 0, range = 0;
  HRESULT hr = BufferSrvRequest(*dev, desc, &req);
  if (SUCCEEDED(hr)) hr = ValidateBufferView(*dev, kSrvKind, DescribeResource(r), out, desc ? &req : nullptr, &offset, &range);
  if (FAILED(hr)) return hr;
  return MakeBufferView<SRVImpl>(dev, r, offset, range, out);
}

HRESULT DeviceImpl::CreateUnorderedAccessView(Resource* r, const UNORDERED_ACCESS_VIEW_DESC* desc,
                                              UnorderedAccessView** out) {
  if (out) *out = nullptr;
  if (!AsBuffer(r)) {
    ViewFormat format;
    uint32_t mip = 0;
    const HRESULT hr = ValidateTextureUav(*this, DescribeResource(r), desc, out, &format, &mip);
    if (FAILED(hr)) return hr;
    return MakeTextureUav(this, r, format, mip, out);
  }
  BufferViewRequest req{};
  UINT64 offset = 0, range = 0;
  HRESULT hr = BufferUavRequest(*this, desc, &req);
  if (SUCCEEDED(hr)) hr = ValidateBufferView(*this, kUavKind, DescribeResource(r), out, desc ? &req : nullptr, &offset, &range);
  if (FAILED(hr)) return hr;
  return MakeBufferView<UAVImpl>(this, r, offset, range, out);
}

}  // namespace d3dl::impl
