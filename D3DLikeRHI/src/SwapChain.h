// What the swap chains share (SwapChainHeadless.cpp, SwapChainWindow.cpp).
#pragma once

#include "Resources.h"

namespace d3dl::impl {

class SwapChainImplBase {
 public:
  virtual ~SwapChainImplBase() = default;
};

// Creates a back-buffer proxy texture (RTV + SRV + copy source) with `count`
// owned images; swap chains replace/extend its images.
TextureImpl<Texture2D, RESOURCE_DIMENSION_TEXTURE2D>* CreateBackBufferProxy(
    DeviceImpl* dev, uint32_t w, uint32_t h, DXGI_FORMAT format, uint32_t count,
    SwapChainImplBase* owner);

// ResizeBuffers' precondition, for both swap chains: no reference to the
// back buffer but the swap chain's own (`proxy` may be null: none made yet).
// The immediate context first releases its pins of views no longer bound,
// which D3D11 would have released at the unbind. Logs the error when not.
bool BackBufferReleased(DeviceImpl* dev, const Texture2DImpl* proxy);

}  // namespace d3dl::impl
