// Window swap chain (GLFW surface): the back-buffer texture wraps the
// acquired VkSwapchainKHR image; an extra offscreen image stands in while
// nothing is acquired (minimised window), so recorded draws stay valid.
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "Context.h"
#include "SwapChain.h"

namespace d3dl::impl {

class SwapChainWindow final : public Object<SwapChain>, public SwapChainImplBase {
 public:
  explicit SwapChainWindow(DeviceImpl* d) : Object(d) {}
  ~SwapChainWindow() override {
    vkDeviceWaitIdle(dev_->vk());
    if (proxy_) proxy_->Release();
    for (auto s : renderDone_) dev_->Defer(VK_OBJECT_TYPE_SEMAPHORE, reinterpret_cast<uint64_t>(s));
    if (swapchain_) vkDestroySwapchainKHR(dev_->vk(), swapchain_, nullptr);
    if (surface_) vkDestroySurfaceKHR(dev_->instance(), surface_, nullptr);
  }

  HRESULT Init(GLFWwindow* window, const SWAP_CHAIN_DESC& d) {
    window_ = window;
    desc_ = d;
    if (desc_.BufferCount == 0) desc_.BufferCount = 2;
    if (!dev_->features().swapchain) {
      dev_->Log(LogLevel::Error, "CreateSwapChainForWindow: the adapter has no VK_KHR_swapchain");
      return DXGI_ERROR_UNSUPPORTED;
    }
    VkResult r = glfwCreateWindowSurface(dev_->instance(), window, nullptr, &surface_);
    if (r != VK_SUCCESS) {
      dev_->Log(LogLevel::Error, "CreateSwapChainForWindow: glfwCreateWindowSurface failed (VkResult %d); was the device created with EnableWindowSurfaces?", r);
      return DXGI_ERROR_UNSUPPORTED;
    }
    VkBool32 supported = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(dev_->phys(), dev_->queueFamily(), surface_, &supported);
    if (!supported) {
      dev_->Log(LogLevel::Error, "CreateSwapChainForWindow: the graphics queue cannot present to this window");
      return DXGI_ERROR_UNSUPPORTED;
    }
    if (!ChooseFormat()) return E_INVALIDARG;
    HRESULT hr = Build();
    if (FAILED(hr)) return hr;
    Acquire();
    return S_OK;
  }

  HRESULT Present(UINT syncInterval, UINT) override {
    if (syncInterval != syncInterval_) {
      syncInterval_ = syncInterval;
      needRebuild_ = true;
    }
    ContextImpl* ctx = dev_->context();
    if (!acquired_) {
      ctx->SubmitFrame();
      RebuildIfNeeded();
      Acquire();
      return DXGI_STATUS_OCCLUDED;
    }
    VkSemaphore done = renderDone_[imageIndex_];
    ctx->SubmitFrame(&proxy_->core, done);
    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = &done;
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain_;
    pi.pImageIndices = &imageIndex_;
    VkResult r = vkQueuePresentKHR(dev_->queue().vk(), &pi);
    acquired_ = false;
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) needRebuild_ = true;
    else if (r != VK_SUCCESS) dev_->Log(LogLevel::Error, "vkQueuePresentKHR failed (VkResult %d)", r);
    RebuildIfNeeded();
    Acquire();
    return S_OK;
  }

  HRESULT GetBuffer(UINT index, Texture2D** out) override {
    if (!out) return E_INVALIDARG;
    if (index != 0) dev_->Log(LogLevel::Warning, "GetBuffer: index %u; the current back buffer is returned", index);
    proxy_->AddRef();
    *out = proxy_;
    return S_OK;
  }

  HRESULT ResizeBuffers(UINT count, UINT w, UINT h, DXGI_FORMAT format, UINT) override {
    if (!BackBufferReleased(dev_, proxy_)) return E_INVALIDARG;
    if (count) desc_.BufferCount = count;
    desc_.Width = w;
    desc_.Height = h;
    if (format != DXGI_FORMAT_UNKNOWN) {
      desc_.Format = format;
      if (!ChooseFormat()) return E_INVALIDARG;
    }
    dev_->context()->SubmitFrame();  // the acquire wait (if any) is consumed
    vkDeviceWaitIdle(dev_->vk());
    acquired_ = false;
    HRESULT hr = Build();
    Acquire();
    return hr;
  }

  void GetDesc(SWAP_CHAIN_DESC* d) const override {
    if (!d) return;
    *d = desc_;
    d->Format = actualFormat_;
    d->Width = proxy_ ? proxy_->core.desc.Width : 0;
    d->Height = proxy_ ? proxy_->core.desc.Height : 0;
  }
  bool IsHeadless() const override { return false; }

 private:
  bool ChooseFormat() {
    uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(dev_->phys(), surface_, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(dev_->phys(), surface_, &n, formats.data());
    auto has = [&](VkFormat f) {
      for (auto& sf : formats)
        if (sf.format == f) return true;
      return false;
    };
    DXGI_FORMAT want = desc_.Format;
    DXGI_FORMAT alt = want == DXGI_FORMAT_R8G8B8A8_UNORM        ? DXGI_FORMAT_B8G8R8A8_UNORM
                      : want == DXGI_FORMAT_R8G8B8A8_UNORM_SRGB ? DXGI_FORMAT_B8G8R8A8_UNORM_SRGB
                      : want == DXGI_FORMAT_B8G8R8A8_UNORM      ? DXGI_FORMAT_R8G8B8A8_UNORM
                                                                : want;
    if (has(ToVkFormat(want))) {
      actualFormat_ = want;
    } else if (has(ToVkFormat(alt))) {
      actualFormat_ = alt;
      dev_->Log(LogLevel::Info, "swap chain: %s is not offered by the surface; using %s", FormatName(want), FormatName(alt));
    } else {
      dev_->Log(LogLevel::Error, "swap chain: the surface offers neither %s nor %s", FormatName(want), FormatName(alt));
      return false;
    }
    return true;
  }

  HRESULT Build() {
    VkSurfaceCapabilitiesKHR caps;
    vkGetPhysicalDeviceSurfaceCapabilitiesKHR(dev_->phys(), surface_, &caps);
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    uint32_t w = desc_.Width ? desc_.Width : uint32_t(fw), h = desc_.Height ? desc_.Height : uint32_t(fh);
    if (caps.currentExtent.width != 0xFFFFFFFFu) {
      w = caps.currentExtent.width;
      h = caps.currentExtent.height;
    }
    occluded_ = w == 0 || h == 0;
    if (occluded_) return BuildStandInOnly();
    w = std::clamp(w, caps.minImageExtent.width, caps.maxImageExtent.width);
    h = std::clamp(h, caps.minImageExtent.height, caps.maxImageExtent.height);
    HRESULT hr = CreateSwapchain(caps, w, h);
    if (FAILED(hr)) return hr;
    uint32_t n = 0;
    vkGetSwapchainImagesKHR(dev_->vk(), swapchain_, &n, nullptr);
    std::vector<VkImage> images(n);
    vkGetSwapchainImagesKHR(dev_->vk(), swapchain_, &n, images.data());
    hr = WrapImages(images, w, h);
    if (FAILED(hr)) return hr;
    for (auto s : renderDone_) dev_->Defer(VK_OBJECT_TYPE_SEMAPHORE, reinterpret_cast<uint64_t>(s));
    renderDone_.assign(n, VK_NULL_HANDLE);
    VkSemaphoreCreateInfo sci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (auto& s : renderDone_) vkCreateSemaphore(dev_->vk(), &sci, nullptr, &s);
    needRebuild_ = false;
    return S_OK;
  }

  // Minimised: keep (or make) only the stand-in image; no 0-size swap chain.
  HRESULT BuildStandInOnly() {
    if (!proxy_) {
      proxy_ = CreateBackBufferProxy(dev_, std::max(1u, desc_.Width ? desc_.Width : 1),
                                     std::max(1u, desc_.Height ? desc_.Height : 1), actualFormat_, 1, this);
      if (!proxy_) return E_OUTOFMEMORY;
    }
    proxy_->core.current = static_cast<uint32_t>(proxy_->core.images.size() - 1);
    needRebuild_ = true;
    return S_OK;
  }

  // FIFO for vsync; MAILBOX, else IMMEDIATE, else FIFO without.
  VkPresentModeKHR ChoosePresentMode() const {
    uint32_t pn = 0;
    vkGetPhysicalDeviceSurfacePresentModesKHR(dev_->phys(), surface_, &pn, nullptr);
    std::vector<VkPresentModeKHR> modes(pn);
    vkGetPhysicalDeviceSurfacePresentModesKHR(dev_->phys(), surface_, &pn, modes.data());
    if (syncInterval_ != 0) return VK_PRESENT_MODE_FIFO_KHR;
    for (auto m : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
      if (std::find(modes.begin(), modes.end(), m) != modes.end()) return m;
    return VK_PRESENT_MODE_FIFO_KHR;
  }

  // Replaces swapchain_ (the old one is retired once the device is idle).
  HRESULT CreateSwapchain(const VkSurfaceCapabilitiesKHR& caps, uint32_t w, uint32_t h) {
    uint32_t count = std::max(caps.minImageCount, desc_.BufferCount);
    if (caps.maxImageCount) count = std::min(count, caps.maxImageCount);
    VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    ci.surface = surface_;
    ci.minImageCount = count;
    ci.imageFormat = ToVkFormat(actualFormat_);
    ci.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    ci.imageExtent = {w, h};
    ci.imageArrayLayers = 1;
    ci.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                    (caps.supportedUsageFlags &
                     (VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT));
    ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.preTransform = caps.currentTransform;
    ci.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
    ci.presentMode = ChoosePresentMode();
    ci.clipped = VK_TRUE;
    ci.oldSwapchain = swapchain_;
    VkSwapchainKHR sc;
    VkResult r = vkCreateSwapchainKHR(dev_->vk(), &ci, nullptr, &sc);
    if (r != VK_SUCCESS) {
      dev_->Log(LogLevel::Error, "vkCreateSwapchainKHR failed (VkResult %d)", r);
      return E_FAIL;
    }
    vkDeviceWaitIdle(dev_->vk());
    if (swapchain_) vkDestroySwapchainKHR(dev_->vk(), swapchain_, nullptr);
    swapchain_ = sc;
    return S_OK;
  }

  // The back-buffer texture keeps its identity (the application's views stay
  // valid); its images are replaced: the swap-chain images + one stand-in.
  HRESULT WrapImages(const std::vector<VkImage>& images, uint32_t w, uint32_t h) {
    if (!proxy_) {
      proxy_ = CreateBackBufferProxy(dev_, w, h, actualFormat_, 1, this);
      if (!proxy_) return E_OUTOFMEMORY;
    }
    TextureCore& c = proxy_->core;
    TextureImage standIn = c.images.back();
    if (c.desc.Width != w || c.desc.Height != h || c.desc.Format != actualFormat_) {
      dev_->Defer(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(standIn.image));
      dev_->Defer(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(standIn.memory));
      c.desc.Width = w;
      c.desc.Height = h;
      c.desc.Format = actualFormat_;
      c.fmt = GetFormatInfo(actualFormat_);
      c.format = c.fmt->vk;
      CreateTextureImage(dev_, c, &standIn);
    }
    c.images.clear();
    for (VkImage img : images) {
      TextureImage ti;
      ti.image = img;
      ti.owned = false;
      ti.sync.assign(1, SyncState{});
      c.images.push_back(ti);
    }
    c.images.push_back(standIn);
    c.current = static_cast<uint32_t>(images.size());
    for (ViewCore* v : c.registeredViews) RebuildViews(dev_, *v);
    return S_OK;
  }

  void RebuildIfNeeded() {
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    if (fw == 0 || fh == 0) {
      occluded_ = true;
      return;
    }
    if (needRebuild_ || occluded_ || !swapchain_) {
      vkDeviceWaitIdle(dev_->vk());
      Build();
    }
  }

  void Acquire() {
    TextureCore& c = proxy_->core;
    c.current = static_cast<uint32_t>(c.images.size() - 1);  // stand-in
    if (occluded_ || !swapchain_ || acquired_) return;
    VkSemaphore sem = dev_->queue().AcquireSemaphore();
    uint32_t idx = 0;
    VkResult r = vkAcquireNextImageKHR(dev_->vk(), swapchain_, UINT64_MAX, sem, VK_NULL_HANDLE, &idx);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
      needRebuild_ = true;
      return;  // rendered into the stand-in this frame; rebuilt at Present
    }
    if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR) {
      dev_->Log(LogLevel::Error, "vkAcquireNextImageKHR failed (VkResult %d)", r);
      return;
    }
    if (r == VK_SUBOPTIMAL_KHR) needRebuild_ = true;
    dev_->queue().AddPendingWait(sem);
    imageIndex_ = idx;
    acquired_ = true;
    c.current = idx;
    SyncState& s = c.images[idx].sync[0];
    s = SyncState{};
    s.pending = true;  // the acquire semaphore's wait (ALL_COMMANDS) orders the first use
    s.writeStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  }

  GLFWwindow* window_ = nullptr;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  SWAP_CHAIN_DESC desc_{};
  DXGI_FORMAT actualFormat_ = DXGI_FORMAT_R8G8B8A8_UNORM;
  Texture2DImpl* proxy_ = nullptr;
  std::vector<VkSemaphore> renderDone_;
  uint32_t imageIndex_ = 0;
  bool acquired_ = false;
  bool occluded_ = false;
  bool needRebuild_ = false;
  UINT syncInterval_ = 1;
};

HRESULT DeviceImpl::CreateSwapChainForWindow(GLFWwindow* window, const SWAP_CHAIN_DESC* desc, SwapChain** out) {
  if (out) *out = nullptr;
  if (!window || !desc || !out) {
    Log(LogLevel::Error, "CreateSwapChainForWindow: %s is null", !window ? "window" : !desc ? "pDesc" : "ppSwapChain");
    return E_INVALIDARG;
  }
  auto* s = new SwapChainWindow(this);
  HRESULT hr = s->Init(window, *desc);
  if (FAILED(hr)) {
    s->Release();
    return hr;
  }
  *out = s;
  return S_OK;
}

}  // namespace d3dl::impl
