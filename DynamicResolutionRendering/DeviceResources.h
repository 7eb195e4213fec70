// The device, its immediate context, the swap chain (window or headless) and
// the back buffer: what the original got from DXUT's device callbacks.
#pragma once

#include <cstdint>
#include <string>

#include "AppWindow.h"
#include "d3dl/D3DLike.h"

namespace drr {

// The back buffer of this frame.
struct BackBuffer {
  d3dl::Texture2D* texture = nullptr;
  d3dl::RenderTargetView* rtv = nullptr;
  uint32_t width = 0, height = 0;
};

class DeviceResources {
 public:
  // A window swap chain when the window is not headless (the window is
  // created here at width x height), else a headless one of that size.
  // headlessFormat: the headless back buffer's (a window's follows its surface).
  bool Create(bool validation, AppWindow& window, uint32_t width, uint32_t height, d3dl::DXGI_FORMAT headlessFormat,
              std::string* error);
  // Clears the context state and re-creates the back buffer at w x h.
  bool Resize(uint32_t w, uint32_t h);
  // Releases everything; false (with a message on stderr) when the device
  // outlived its last reference or destroying it raised validation messages.
  bool Release();

  d3dl::Device* Device() const { return m_Device.Get(); }
  d3dl::DeviceContext* Context() const { return m_Context.Get(); }
  d3dl::SwapChain* SwapChain() const { return m_SwapChain.Get(); }
  BackBuffer Back() const { return {m_BackBuffer.Get(), m_BackBufferRTV.Get(), m_Width, m_Height}; }
  uint32_t Width() const { return m_Width; }
  uint32_t Height() const { return m_Height; }
  d3dl::DXGI_FORMAT Format() const { return m_Format; }  // the back buffer's
  const d3dl::ADAPTER_DESC& Adapter() const { return m_Adapter; }
  uint64_t ValidationMessages() const;
  // Validation was asked for (--validation or D3DL_VALIDATION), but the
  // layer is not installed: the device runs without it.
  bool ValidationLayerMissing() const;

 private:
  bool CreateBackBufferViews();

  d3dl::ComPtr<d3dl::Device> m_Device;
  d3dl::ComPtr<d3dl::DeviceContext> m_Context;
  d3dl::ComPtr<d3dl::SwapChain> m_SwapChain;
  d3dl::ComPtr<d3dl::Texture2D> m_BackBuffer;
  d3dl::ComPtr<d3dl::RenderTargetView> m_BackBufferRTV;
  uint32_t m_Width = 0, m_Height = 0;
  d3dl::DXGI_FORMAT m_Format = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
  d3dl::ADAPTER_DESC m_Adapter{};
};

}  // namespace drr
