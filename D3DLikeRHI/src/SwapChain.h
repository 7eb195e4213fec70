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

}  // namespace d3dl::impl
