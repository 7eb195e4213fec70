#include "DeviceResources.h"

#include <algorithm>
#include <atomic>
#include <cstdio>

namespace drr {

namespace {
// Validation messages logged so far; those of vkDestroyDevice (undestroyed
// objects) arrive when no device is left to ask for its statistics.
std::atomic<uint64_t> g_validationLogged{0};

void LogToStderr(d3dl::LogLevel level, const char* message, void*) {
  if (level == d3dl::LogLevel::Validation) ++g_validationLogged;
  const char* tag = level == d3dl::LogLevel::Validation ? "validation"
                    : level == d3dl::LogLevel::Error    ? "error"
                    : level == d3dl::LogLevel::Warning  ? "warning"
                                                        : "info";
  if (level != d3dl::LogLevel::Info) std::fprintf(stderr, "[d3dl %s] %s\n", tag, message);
}
}  // namespace

bool DeviceResources::Create(bool validation, AppWindow& window, uint32_t width, uint32_t height,
                             d3dl::DXGI_FORMAT headlessFormat, std::string* error) {
  d3dl::DEVICE_CREATE_DESC dd;
  dd.Validation = validation ? d3dl::ValidationMode::CoreAndSync : d3dl::ValidationMode::FromEnvironment;
  dd.Log = LogToStderr;
  dd.EnableWindowSurfaces = !window.Headless();
  dd.ApplicationName = "DynamicResolutionRendering";
  if (d3dl::FAILED(d3dl::CreateDevice(&dd, m_Device.GetAddressOf(), m_Context.GetAddressOf()))) {
    *error = "cannot create the Vulkan device (see the messages above)";
    return false;
  }
  if (validation && ValidationLayerMissing()) {
    *error = "--validation: VK_LAYER_KHRONOS_validation is not installed (Debian package vulkan-validationlayers)";
    return false;
  }
  m_Device->GetAdapterDesc(&m_Adapter);
  d3dl::SWAP_CHAIN_DESC sd;
  sd.Format = window.Headless() ? headlessFormat : m_Format;
  sd.BufferCount = 2;
  sd.Width = width;
  sd.Height = height;
  if (!window.Headless()) {
    if (!window.Create(width, height, error)) return false;
    window.FramebufferSize(&sd.Width, &sd.Height);
    sd.Width = std::max(sd.Width, 1u);
    sd.Height = std::max(sd.Height, 1u);
    if (d3dl::FAILED(m_Device->CreateSwapChainForWindow(window.Handle(), &sd, m_SwapChain.GetAddressOf()))) {
      *error = "cannot create the window swap chain";
      return false;
    }
  } else if (d3dl::FAILED(m_Device->CreateHeadlessSwapChain(&sd, m_SwapChain.GetAddressOf()))) {
    *error = "cannot create the headless swap chain";
    return false;
  }
  if (!CreateBackBufferViews()) {
    *error = "cannot create the back-buffer views";
    return false;
  }
  return true;
}

bool DeviceResources::CreateBackBufferViews() {
  if (d3dl::FAILED(m_SwapChain->GetBuffer(0, m_BackBuffer.ReleaseAndGetAddressOf()))) return false;
  if (d3dl::FAILED(m_Device->CreateRenderTargetView(m_BackBuffer.Get(), nullptr, m_BackBufferRTV.ReleaseAndGetAddressOf())))
    return false;
  d3dl::TEXTURE2D_DESC d;
  m_BackBuffer->GetDesc(&d);
  m_Width = d.Width;
  m_Height = d.Height;
  m_Format = d.Format;
  return true;
}

bool DeviceResources::Resize(uint32_t w, uint32_t h) {
  m_Context->ClearState();
  m_BackBufferRTV = nullptr;
  m_BackBuffer = nullptr;
  if (d3dl::FAILED(m_SwapChain->ResizeBuffers(0, w, h, m_Format, 0))) return false;
  return CreateBackBufferViews();
}

bool DeviceResources::Release() {
  if (!m_Device) return true;
  const uint64_t before = g_validationLogged.load();
  const unsigned devicesBefore = d3dl::LiveDeviceCount();
  m_BackBufferRTV = nullptr;
  m_BackBuffer = nullptr;
  m_SwapChain = nullptr;
  m_Context = nullptr;
  m_Device = nullptr;
  const uint64_t messages = g_validationLogged.load() - before;
  const bool destroyed = d3dl::LiveDeviceCount() < devicesBefore;
  if (!destroyed)
    std::fprintf(stderr, "error: shutdown: the Vulkan device was not destroyed (an object still holds it)\n");
  if (messages != 0)
    std::fprintf(stderr, "error: shutdown: %llu validation messages while destroying the device\n",
                 (unsigned long long)messages);
  return destroyed && messages == 0;
}

uint64_t DeviceResources::ValidationMessages() const {
  if (!m_Device) return 0;
  d3dl::DEVICE_STATS st;
  m_Device->GetStats(&st);
  return st.ValidationMessages;
}

bool DeviceResources::ValidationLayerMissing() const {
  if (!m_Device) return false;
  d3dl::DEVICE_STATS st;
  m_Device->GetStats(&st);
  return st.Validation != st.ValidationRequested;
}

}  // namespace drr
