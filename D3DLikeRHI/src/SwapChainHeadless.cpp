// Headless swap chain: N offscreen images behind one back-buffer texture;
// Present submits the frame and rotates to the next image.
#include "Context.h"
#include "SwapChain.h"
#include "Validate.h"

namespace d3dl::impl {

Texture2DImpl* CreateBackBufferProxy(DeviceImpl* dev, uint32_t w, uint32_t h, DXGI_FORMAT format,
                                     uint32_t count, SwapChainImplBase* owner) {
  auto* t = new Texture2DImpl(dev);
  TextureCore& c = t->core;
  c.desc.Width = w;
  c.desc.Height = h;
  c.desc.MipLevels = 1;
  c.desc.ArraySize = 1;
  c.desc.Format = format;
  c.desc.BindFlags = BIND_RENDER_TARGET | BIND_SHADER_RESOURCE;
  c.fmt = GetFormatInfo(format);
  c.format = c.fmt->vk;
  c.swapChain = owner;
  c.images.resize(count);
  for (auto& img : c.images)
    if (!CreateTextureImage(dev, c, &img)) {
      t->Release();
      return nullptr;
    }
  return t;
}

bool BackBufferReleased(DeviceImpl* dev, const Texture2DImpl* proxy) {
  if (ContextImpl* ctx = dev->context()) ctx->CompactPins();
  if (!proxy || proxy->RefCount() <= 1) return true;
  dev->Log(LogLevel::Error, "ResizeBuffers: release every reference to the back buffer (and its views) first");
  return false;
}

class SwapChainHeadless final : public Object<SwapChain>, public SwapChainImplBase {
 public:
  explicit SwapChainHeadless(DeviceImpl* d) : Object(d) {}
  ~SwapChainHeadless() override {
    if (proxy_) proxy_->Release();
  }

  HRESULT Build(const SWAP_CHAIN_DESC& d) {
    const HRESULT valid = ValidateHeadlessSwapChain(*dev_, d);
    if (FAILED(valid)) return valid;
    Texture2DImpl* p = CreateBackBufferProxy(dev_, d.Width, d.Height, d.Format, d.BufferCount, this);
    if (!p) return E_OUTOFMEMORY;
    if (proxy_) proxy_->Release();
    proxy_ = p;
    desc_ = d;
    return S_OK;
  }

  HRESULT Present(UINT, UINT) override {
    if (ContextImpl* ctx = dev_->context()) ctx->SubmitFrame();
    proxy_->core.current = (proxy_->core.current + 1) % static_cast<uint32_t>(proxy_->core.images.size());
    return S_OK;
  }
  HRESULT GetBuffer(UINT index, Texture2D** out) override {
    if (!out) {
      dev_->Log(LogLevel::Error, "GetBuffer: ppSurface is null");
      return E_INVALIDARG;
    }
    if (index != 0) dev_->Log(LogLevel::Warning, "GetBuffer: index %u; the current back buffer is returned", index);
    proxy_->AddRef();
    *out = proxy_;
    return S_OK;
  }
  HRESULT ResizeBuffers(UINT count, UINT w, UINT h, DXGI_FORMAT format, UINT) override {
    if (!BackBufferReleased(dev_, proxy_)) return E_INVALIDARG;
    SWAP_CHAIN_DESC d = desc_;
    if (count) d.BufferCount = count;
    if (w) d.Width = w;
    if (h) d.Height = h;
    if (format != DXGI_FORMAT_UNKNOWN) d.Format = format;
    return Build(d);
  }
  void GetDesc(SWAP_CHAIN_DESC* d) const override {
    if (d) *d = desc_;
  }
  bool IsHeadless() const override { return true; }

 private:
  Texture2DImpl* proxy_ = nullptr;
  SWAP_CHAIN_DESC desc_{};
};

HRESULT DeviceImpl::CreateHeadlessSwapChain(const SWAP_CHAIN_DESC* desc, SwapChain** out) {
  if (out) *out = nullptr;
  if (!ValidatePointers(*this, "CreateHeadlessSwapChain", desc, "pDesc", out, "ppSwapChain")) return E_INVALIDARG;
  auto* s = new SwapChainHeadless(this);
  HRESULT hr = s->Build(*desc);
  if (FAILED(hr)) {
    s->Release();
    return hr;
  }
  *out = s;
  return S_OK;
}

}  // namespace d3dl::impl
