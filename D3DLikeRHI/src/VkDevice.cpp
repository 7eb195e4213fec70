// The device's lifetime (CreateDevice, Release, Shutdown), logging, memory,
// deferred destruction and format support. Setup is in DeviceSetup.cpp.
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

#include "ContextImmediate.h"

namespace d3dl {
namespace impl {
namespace {

void DefaultLog(LogLevel level, const char* message, void*) {
  if (level == LogLevel::Info) return;
  const char* tag = level == LogLevel::Warning   ? "warning"
                    : level == LogLevel::Error   ? "error"
                                                 : "validation";
  std::fprintf(stderr, "[d3dl %s] %s\n", tag, message);
}

ValidationMode ResolveValidation(ValidationMode m) {
  if (m != ValidationMode::FromEnvironment) return m;
  const char* env = std::getenv("D3DL_VALIDATION");
  if (!env || !*env || std::strcmp(env, "0") == 0) return ValidationMode::Off;
  if (std::strcmp(env, "sync") == 0) return ValidationMode::CoreAndSync;
  return ValidationMode::Core;
}

}  // namespace

ObjectRoot::ObjectRoot(DeviceImpl* dev) : dev_(dev), uid_(dev->NextUid()) { dev_->ChildCreated(); }
ObjectRoot::~ObjectRoot() { dev_->ChildDestroyed(); }

namespace {
std::atomic<UINT> g_liveDevices{0};
}  // namespace

DeviceImpl::DeviceImpl() { ++g_liveDevices; }
DeviceImpl::~DeviceImpl() { --g_liveDevices; }

void ValidationDevice::Log(LogLevel level, const char* fmt, ...) const {
  char buf[2048];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof(buf), fmt, ap);
  va_end(ap);
  (log_ ? log_ : DefaultLog)(level, buf, logUser_);
}

void DeviceImpl::OnValidationMessage(const char* msg) {
  ++stats.ValidationMessages;
  (log_ ? log_ : DefaultLog)(LogLevel::Validation, msg, logUser_);
}

bool DeviceImpl::AllocateMemory(const VkMemoryRequirements& req, VkMemoryPropertyFlags want,
                                VkMemoryPropertyFlags fallback, VkDeviceMemory* out) {
  for (VkMemoryPropertyFlags flags : {want, fallback}) {
    for (uint32_t i = 0; i < memProps_.memoryTypeCount; ++i) {
      if (!(req.memoryTypeBits & (1u << i))) continue;
      if ((memProps_.memoryTypes[i].propertyFlags & flags) != flags) continue;
      VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
      ai.allocationSize = req.size;
      ai.memoryTypeIndex = i;
      if (vkAllocateMemory(device_, &ai, nullptr, out) == VK_SUCCESS) return true;
    }
  }
  Log(LogLevel::Error, "out of device memory (%llu bytes)", static_cast<unsigned long long>(req.size));
  return false;
}

bool DeviceImpl::CreateBufferRaw(VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible, VkBuffer* buf,
                                 VkDeviceMemory* mem, uint8_t** mapped) {
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = std::max<VkDeviceSize>(size, 4);
  bci.usage = usage;
  if (vkCreateBuffer(device_, &bci, nullptr, buf) != VK_SUCCESS) return false;
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, *buf, &req);
  const VkMemoryPropertyFlags hostCoherent = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  const VkMemoryPropertyFlags want =
      hostVisible ? hostCoherent | VK_MEMORY_PROPERTY_HOST_CACHED_BIT : VkMemoryPropertyFlags(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!AllocateMemory(req, want, hostVisible ? hostCoherent : 0, mem)) {
    vkDestroyBuffer(device_, *buf, nullptr);
    *buf = VK_NULL_HANDLE;
    return false;
  }
  vkBindBufferMemory(device_, *buf, *mem, 0);
  if (hostVisible && mapped) {
    void* p = nullptr;
    vkMapMemory(device_, *mem, 0, VK_WHOLE_SIZE, 0, &p);
    *mapped = static_cast<uint8_t*>(p);
  }
  return true;
}

void DeviceImpl::SetName(VkObjectType type, uint64_t handle, const std::string& name) {
  if (!debugUtils_.setObjectName || !handle) return;
  VkDebugUtilsObjectNameInfoEXT ni{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  ni.objectType = type;
  ni.objectHandle = handle;
  ni.pObjectName = name.c_str();
  debugUtils_.setObjectName(device_, &ni);
}

void DeviceImpl::CreateCommandBuffer(VkCommandPool* pool, VkCommandBuffer* cmd, const VkAllocationCallbacks* memory) {
  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pci.queueFamilyIndex = queueFamily_;
  vkCreateCommandPool(device_, &pci, memory, pool);
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = *pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  vkAllocateCommandBuffers(device_, &ai, cmd);
}

// ---------------------------------------------------------------------------
void DeviceImpl::Defer(VkObjectType type, uint64_t handle, CommandMemory* memory) {
  if (!handle) {
    delete memory;
    return;
  }
  if (orphaned_ || shuttingDown_ || !queue_.Ready()) {
    ++stats.ObjectsDestroyed;
    DestroyNow({type, handle, memory});
    return;
  }
  queue_.Defer({type, handle, memory});
}

void DeviceImpl::DestroyNow(const Garbage& g) {
  switch (g.type) {
    case VK_OBJECT_TYPE_BUFFER: vkDestroyBuffer(device_, reinterpret_cast<VkBuffer>(g.handle), nullptr); break;
    case VK_OBJECT_TYPE_IMAGE: vkDestroyImage(device_, reinterpret_cast<VkImage>(g.handle), nullptr); break;
    case VK_OBJECT_TYPE_IMAGE_VIEW: vkDestroyImageView(device_, reinterpret_cast<VkImageView>(g.handle), nullptr); break;
    case VK_OBJECT_TYPE_DEVICE_MEMORY: vkFreeMemory(device_, reinterpret_cast<VkDeviceMemory>(g.handle), nullptr); break;
    case VK_OBJECT_TYPE_SAMPLER: vkDestroySampler(device_, reinterpret_cast<VkSampler>(g.handle), nullptr); break;
    case VK_OBJECT_TYPE_SHADER_MODULE:
      vkDestroyShaderModule(device_, reinterpret_cast<VkShaderModule>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_COMMAND_POOL:  // a command list's (with its buffer), then its allocator
      vkDestroyCommandPool(device_, reinterpret_cast<VkCommandPool>(g.handle), g.memory ? g.memory->callbacks() : nullptr);
      delete g.memory;
      break;
    case VK_OBJECT_TYPE_DESCRIPTOR_POOL:
      vkDestroyDescriptorPool(device_, reinterpret_cast<VkDescriptorPool>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_PIPELINE: vkDestroyPipeline(device_, reinterpret_cast<VkPipeline>(g.handle), nullptr); break;
    case VK_OBJECT_TYPE_PIPELINE_LAYOUT:
      vkDestroyPipelineLayout(device_, reinterpret_cast<VkPipelineLayout>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT:
      vkDestroyDescriptorSetLayout(device_, reinterpret_cast<VkDescriptorSetLayout>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_QUERY_POOL: vkDestroyQueryPool(device_, reinterpret_cast<VkQueryPool>(g.handle), nullptr); break;
    case VK_OBJECT_TYPE_SEMAPHORE: vkDestroySemaphore(device_, reinterpret_cast<VkSemaphore>(g.handle), nullptr); break;
    case VK_OBJECT_TYPE_SWAPCHAIN_KHR:
      vkDestroySwapchainKHR(device_, reinterpret_cast<VkSwapchainKHR>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_SURFACE_KHR:
      vkDestroySurfaceKHR(instance_, reinterpret_cast<VkSurfaceKHR>(g.handle), nullptr);
      break;
    default: Log(LogLevel::Error, "internal: cannot destroy object type %d", g.type);
  }
}

// ---------------------------------------------------------------------------
HRESULT DeviceImpl::Init(const DEVICE_CREATE_DESC& desc) {
  log_ = desc.Log;
  logUser_ = desc.LogUser;
  const ValidationMode mode = ResolveValidation(desc.Validation);
  if (!CreateInstance(desc, mode)) return E_FAIL;
  if (!PickAdapter(desc)) return DXGI_ERROR_UNSUPPORTED;
  if (!CreateLogicalDevice()) return DXGI_ERROR_UNSUPPORTED;
  uint32_t fif = desc.FramesInFlight ? desc.FramesInFlight : 2;
  if (fif > 8) {
    Log(LogLevel::Warning, "FramesInFlight %u clamped to 8", fif);
    fif = 8;
  }
  VkQueue queue;
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue);
  pipelines_.Init(this);
  queue_.Init(this, queue, fif);
  if (!CreateDummies()) return E_OUTOFMEMORY;
  context_ = std::make_unique<ImmediateContext>(this);
  Log(LogLevel::Info, "D3DLikeRHI on %s (%s)", adapter_.Description, adapter_.Driver);
  return S_OK;
}

UINT DeviceImpl::Release() {
  UINT r = --externalRefs_;
  if (r == 0) {
    // The context drops its references; then wait for the GPU. Objects the
    // application still holds keep the Vulkan device alive until released.
    if (context_) context_->ClearState();
    if (device_) vkDeviceWaitIdle(device_);
    context_.reset();  // its default states are children too
    orphaned_ = true;
    if (internalRefs_ == 0) Shutdown();
  }
  return r;
}

void DeviceImpl::ChildDestroyed() {
  UINT r = --internalRefs_;
  if (r == 0 && orphaned_ && !shuttingDown_) Shutdown();
}

void DeviceImpl::Shutdown() {
  shuttingDown_ = true;
  if (device_) vkDeviceWaitIdle(device_);
  context_.reset();  // releases the default states (children)
  queue_.Destroy();
  pipelines_.Destroy();
  for (auto& g : dummyGarbage_) DestroyNow(g);
  dummyGarbage_.clear();
  if (device_) vkDestroyDevice(device_, nullptr);
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
  delete this;
}

void DeviceImpl::GetImmediateContext(DeviceContext** context) {
  if (!context) return;
  *context = context_.get();
  AddRef();
}

void DeviceImpl::GetStats(DEVICE_STATS* s) const {
  if (!s) return;
  *s = stats;
  s->DeferredDestructionsPending = queue_.PendingGarbage();
  s->LiveObjects = internalRefs_.load();
  s->CommandPoolResets = commandPoolResets_.load();
  s->CommandPoolRewinds = commandPoolRewinds_.load();
}

uint32_t DeviceImpl::FormatFeatures(DXGI_FORMAT format) const {
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(phys_, ToVkFormat(format), &fp);
  const VkFormatFeatureFlags f = fp.optimalTilingFeatures;
  uint32_t out = 0;
  if (f & VK_FORMAT_FEATURE_BLIT_SRC_BIT) out |= FORMAT_FEATURE_BLIT_SRC;
  if (f & VK_FORMAT_FEATURE_BLIT_DST_BIT) out |= FORMAT_FEATURE_BLIT_DST;
  if (f & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) out |= FORMAT_FEATURE_FILTER_LINEAR;
  return out;
}

bool DeviceImpl::CheckFormatSupport(DXGI_FORMAT format, UINT bindFlags) const {
  const FormatInfo* f = GetFormatInfo(format);
  if (!f || (f->bc && !features_.bc)) return false;
  VkFormat vf = f->vk;
  if ((bindFlags & BIND_DEPTH_STENCIL) && f->depthVk) vf = f->depthVk;  // typeless depth families
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(phys_, vf, &fp);
  VkFormatFeatureFlags need = 0;
  if (bindFlags & BIND_SHADER_RESOURCE) need |= VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
  if (bindFlags & BIND_UNORDERED_ACCESS) need |= VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT;
  if (bindFlags & BIND_RENDER_TARGET)
    need |= VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT;
  if (bindFlags & BIND_DEPTH_STENCIL) need |= VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
  // Integer render targets do not blend.
  if ((bindFlags & BIND_RENDER_TARGET) && f->integer && (fp.optimalTilingFeatures & need) != need)
    need &= ~VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT;
  if ((fp.optimalTilingFeatures & need) != need) return false;
  if ((bindFlags & BIND_VERTEX_BUFFER) && !(fp.bufferFeatures & VK_FORMAT_FEATURE_VERTEX_BUFFER_BIT)) return false;
  if (bindFlags & BIND_INDEX_BUFFER) return format == DXGI_FORMAT_R16_UINT || format == DXGI_FORMAT_R32_UINT;
  return true;
}

void DeviceImpl::WaitIdle() {
  if (!device_) return;
  vkDeviceWaitIdle(device_);
  queue_.CompletedSerial();
}

}  // namespace impl

UINT LiveDeviceCount() { return impl::g_liveDevices.load(); }

HRESULT CreateDevice(const DEVICE_CREATE_DESC* desc, Device** device, DeviceContext** context) {
  if (device) *device = nullptr;
  if (context) *context = nullptr;
  DEVICE_CREATE_DESC d = desc ? *desc : DEVICE_CREATE_DESC{};
  if (!device) {
    (d.Log ? d.Log : impl::DefaultLog)(LogLevel::Error, "CreateDevice: device pointer is null", d.LogUser);
    return E_INVALIDARG;
  }
  auto* dev = new impl::DeviceImpl();
  HRESULT hr = dev->Init(d);
  if (FAILED(hr)) {
    dev->Release();
    return hr;
  }
  *device = dev;
  if (context) dev->GetImmediateContext(context);
  return S_OK;
}

}  // namespace d3dl
