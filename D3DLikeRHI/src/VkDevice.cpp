// Instance, adapter choice, logical device, validation messages, memory and
// the device's lifetime (CreateDevice, Release).
#include <cstdio>
#include <cstdlib>

#include "Context.h"

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

VKAPI_ATTR VkBool32 VKAPI_CALL DebugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* user) {
  if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
  static_cast<DeviceImpl*>(user)->OnValidationMessage(data && data->pMessage ? data->pMessage : "?");
  return VK_FALSE;
}

bool HasLayer(const char* name) {
  uint32_t n = 0;
  vkEnumerateInstanceLayerProperties(&n, nullptr);
  std::vector<VkLayerProperties> layers(n);
  vkEnumerateInstanceLayerProperties(&n, layers.data());
  for (auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

std::vector<std::string> InstanceExtensions() {
  uint32_t n = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> ext(n);
  vkEnumerateInstanceExtensionProperties(nullptr, &n, ext.data());
  std::vector<std::string> r;
  for (auto& e : ext) r.emplace_back(e.extensionName);
  return r;
}

ValidationMode ResolveValidation(ValidationMode m) {
  if (m != ValidationMode::FromEnvironment) return m;
  const char* env = std::getenv("D3DL_VALIDATION");
  if (!env || !*env || std::strcmp(env, "0") == 0) return ValidationMode::Off;
  if (std::strcmp(env, "sync") == 0) return ValidationMode::CoreAndSync;
  return ValidationMode::Core;
}

}  // namespace

// ---------------------------------------------------------------------------
ObjectRoot::ObjectRoot(DeviceImpl* dev) : dev_(dev), uid_(dev->NextUid()) { dev_->ChildCreated(); }
ObjectRoot::~ObjectRoot() { dev_->ChildDestroyed(); }

DeviceImpl::DeviceImpl() = default;
DeviceImpl::~DeviceImpl() = default;

void DeviceImpl::Log(LogLevel level, const char* fmt, ...) {
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

bool DeviceImpl::CreateInstance(const DEVICE_CREATE_DESC& desc, ValidationMode mode) {
  std::vector<const char*> layers, exts;
  auto available = InstanceExtensions();
  auto has = [&](const char* e) {
    for (auto& a : available)
      if (a == e) return true;
    return false;
  };
  if (has(VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
    exts.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    debugUtils_ = true;
  }
  if (desc.EnableWindowSurfaces) {
    // What glfwGetRequiredInstanceExtensions would return, without needing a
    // display at device creation: every window-system surface the loader offers.
    for (const char* e : {"VK_KHR_surface", "VK_KHR_xcb_surface", "VK_KHR_xlib_surface",
                          "VK_KHR_wayland_surface", "VK_KHR_win32_surface",
                          "VK_EXT_metal_surface"})
      if (has(e)) exts.push_back(e);
    surfaceExt_ = has("VK_KHR_surface");
  }
  bool validation = mode != ValidationMode::Off;
  if (validation && !HasLayer("VK_LAYER_KHRONOS_validation")) {
    Log(LogLevel::Warning, "VK_LAYER_KHRONOS_validation is not installed; validation is off");
    validation = false;
  }
  if (validation) layers.push_back("VK_LAYER_KHRONOS_validation");

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = desc.ApplicationName ? desc.ApplicationName : "D3DLikeRHI";
  app.pEngineName = "D3DLikeRHI";
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ci.pApplicationInfo = &app;
  ci.enabledLayerCount = static_cast<uint32_t>(layers.size());
  ci.ppEnabledLayerNames = layers.data();
  ci.enabledExtensionCount = static_cast<uint32_t>(exts.size());
  ci.ppEnabledExtensionNames = exts.data();

  VkValidationFeatureEnableEXT syncFeature = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &syncFeature;
  VkDebugUtilsMessengerCreateInfoEXT mci{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  mci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                        VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                    VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                    VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  mci.pfnUserCallback = DebugCallback;
  mci.pUserData = this;
  const void* chain = nullptr;
  if (debugUtils_ && validation) {
    mci.pNext = nullptr;
    chain = &mci;
  }
  if (validation && mode == ValidationMode::CoreAndSync) {
    features.pNext = chain;
    chain = &features;
  }
  ci.pNext = chain;
  VkResult r = vkCreateInstance(&ci, nullptr, &instance_);
  if (r != VK_SUCCESS) {
    Log(LogLevel::Error, "vkCreateInstance failed (VkResult %d)", r);
    return false;
  }
  if (debugUtils_) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (validation && create) create(instance_, &mci, nullptr, &messenger_);
    cmdBeginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance_, "vkCmdBeginDebugUtilsLabelEXT"));
    cmdEndLabel = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance_, "vkCmdEndDebugUtilsLabelEXT"));
    setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
  }
  if (validation)
    Log(LogLevel::Info, "Vulkan validation on%s",
        mode == ValidationMode::CoreAndSync ? " (with synchronization validation)" : "");
  return true;
}

bool DeviceImpl::PickAdapter(const DEVICE_CREATE_DESC& desc) {
  uint32_t n = 0;
  vkEnumeratePhysicalDevices(instance_, &n, nullptr);
  std::vector<VkPhysicalDevice> devs(n);
  vkEnumeratePhysicalDevices(instance_, &n, devs.data());
  const char* filter = desc.AdapterNameFilter;
  if (!filter || !*filter) filter = std::getenv("D3DL_ADAPTER");
  int best = -1;
  int bestScore = -1;
  for (uint32_t i = 0; i < n; ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(devs[i], &p);
    if (p.apiVersion < VK_API_VERSION_1_3) continue;
    if (filter && *filter && !std::strstr(p.deviceName, filter)) continue;
    int score = p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU     ? 4
                : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? 3
                : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU    ? 2
                                                                         : 1;
    if (score > bestScore) {
      bestScore = score;
      best = static_cast<int>(i);
    }
  }
  if (best < 0) {
    Log(LogLevel::Error, "no Vulkan 1.3 adapter found%s%s", filter ? " matching filter " : "",
        filter ? filter : "");
    return false;
  }
  phys_ = devs[best];
  vkGetPhysicalDeviceProperties(phys_, &props_);
  vkGetPhysicalDeviceMemoryProperties(phys_, &memProps_);
  uboAlign_ = std::max<VkDeviceSize>(16, props_.limits.minUniformBufferOffsetAlignment);
  return true;
}

bool DeviceImpl::CreateLogicalDevice() {
  uint32_t qn = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(phys_, &qn, nullptr);
  std::vector<VkQueueFamilyProperties> qf(qn);
  vkGetPhysicalDeviceQueueFamilyProperties(phys_, &qn, qf.data());
  bool found = false;
  for (uint32_t i = 0; i < qn; ++i)
    if (qf[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      queueFamily_ = i;
      found = true;
      break;
    }
  if (!found) {
    Log(LogLevel::Error, "adapter %s has no graphics queue", props_.deviceName);
    return false;
  }
  uint32_t tsBits = qf[queueFamily_].timestampValidBits;

  VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  f12.pNext = &f13;
  VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  f2.pNext = &f12;
  vkGetPhysicalDeviceFeatures2(phys_, &f2);
  if (!f13.dynamicRendering || !f13.synchronization2) {
    Log(LogLevel::Error, "adapter %s lacks dynamicRendering/synchronization2", props_.deviceName);
    return false;
  }
  VkPhysicalDeviceVulkan12Features e12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features e13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  e12.pNext = &e13;
  e13.dynamicRendering = VK_TRUE;
  e13.synchronization2 = VK_TRUE;
  e13.maintenance4 = f13.maintenance4;  // relaxed VS/PS interface matching, as in D3D
  e12.hostQueryReset = f12.hostQueryReset;
  e12.samplerFilterMinmax = f12.samplerFilterMinmax;
  e12.samplerMirrorClampToEdge = f12.samplerMirrorClampToEdge;
  mirrorOnce_ = f12.samplerMirrorClampToEdge;
  VkPhysicalDeviceFeatures2 e2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  e2.pNext = &e12;
  e2.features.samplerAnisotropy = f2.features.samplerAnisotropy;
  e2.features.textureCompressionBC = f2.features.textureCompressionBC;
  e2.features.fillModeNonSolid = f2.features.fillModeNonSolid;
  e2.features.depthClamp = f2.features.depthClamp;
  e2.features.independentBlend = f2.features.independentBlend;
  e2.features.depthBiasClamp = f2.features.depthBiasClamp;
  minmax_ = f12.samplerFilterMinmax;
  anisotropy_ = f2.features.samplerAnisotropy;
  bc_ = f2.features.textureCompressionBC;
  fillNonSolid_ = f2.features.fillModeNonSolid;
  depthClamp_ = f2.features.depthClamp;
  if (!f12.hostQueryReset) {
    Log(LogLevel::Error, "adapter %s lacks hostQueryReset", props_.deviceName);
    return false;
  }

  uint32_t en = 0;
  vkEnumerateDeviceExtensionProperties(phys_, nullptr, &en, nullptr);
  std::vector<VkExtensionProperties> dext(en);
  vkEnumerateDeviceExtensionProperties(phys_, nullptr, &en, dext.data());
  std::vector<const char*> exts;
  for (auto& e : dext)
    // VK_KHR_swapchain requires VK_KHR_surface on the instance: without window
    // surfaces (headless), the device is created without it.
    if (surfaceExt_ && std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0) {
      exts.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
      swapchainExt_ = true;
    }

  float prio = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = queueFamily_;
  qci.queueCount = 1;
  qci.pQueuePriorities = &prio;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.pNext = &e2;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = static_cast<uint32_t>(exts.size());
  dci.ppEnabledExtensionNames = exts.data();
  VkResult r = vkCreateDevice(phys_, &dci, nullptr, &device_);
  if (r != VK_SUCCESS) {
    Log(LogLevel::Error, "vkCreateDevice failed (VkResult %d)", r);
    return false;
  }
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

  std::snprintf(adapter_.Description, sizeof(adapter_.Description), "%s", props_.deviceName);
  VkPhysicalDeviceDriverProperties drv{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  p2.pNext = &drv;
  vkGetPhysicalDeviceProperties2(phys_, &p2);
  std::string driver = std::string(drv.driverName) + " " + drv.driverInfo;
  std::snprintf(adapter_.Driver, sizeof(adapter_.Driver), "%s", driver.c_str());
  adapter_.VendorId = props_.vendorID;
  adapter_.DeviceId = props_.deviceID;
  adapter_.ApiVersion = props_.apiVersion;
  adapter_.IsSoftware = props_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  adapter_.SupportsBC = bc_;
  adapter_.TimestampPeriodNs = tsBits ? props_.limits.timestampPeriod : 0.0f;
  return true;
}

bool DeviceImpl::AllocateMemory(const VkMemoryRequirements& req, VkMemoryPropertyFlags want,
                                VkMemoryPropertyFlags fallback, VkDeviceMemory* out,
                                VkMemoryPropertyFlags* got) {
  for (VkMemoryPropertyFlags flags : {want, fallback}) {
    for (uint32_t i = 0; i < memProps_.memoryTypeCount; ++i) {
      if (!(req.memoryTypeBits & (1u << i))) continue;
      if ((memProps_.memoryTypes[i].propertyFlags & flags) != flags) continue;
      VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
      ai.allocationSize = req.size;
      ai.memoryTypeIndex = i;
      if (vkAllocateMemory(device_, &ai, nullptr, out) == VK_SUCCESS) {
        if (got) *got = memProps_.memoryTypes[i].propertyFlags;
        return true;
      }
    }
  }
  Log(LogLevel::Error, "out of device memory (%llu bytes)",
      static_cast<unsigned long long>(req.size));
  return false;
}

bool DeviceImpl::CreateBufferRaw(VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                                 VkBuffer* buf, VkDeviceMemory* mem, uint8_t** mapped) {
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = std::max<VkDeviceSize>(size, 4);
  bci.usage = usage;
  if (vkCreateBuffer(device_, &bci, nullptr, buf) != VK_SUCCESS) return false;
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, *buf, &req);
  VkMemoryPropertyFlags want =
      hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                        VK_MEMORY_PROPERTY_HOST_CACHED_BIT
                  : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  VkMemoryPropertyFlags fallback =
      hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT : 0;
  if (!AllocateMemory(req, want, fallback, mem)) {
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
  if (!setObjectName || !handle) return;
  VkDebugUtilsObjectNameInfoEXT ni{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  ni.objectType = type;
  ni.objectHandle = handle;
  ni.pObjectName = name.c_str();
  setObjectName(device_, &ni);
}

bool DeviceImpl::CreateDummies() {
  dummyUniformSize = std::min<VkDeviceSize>(65536, props_.limits.maxUniformBufferRange);
  VkDeviceMemory mem;
  if (!CreateBufferRaw(dummyUniformSize,
                       VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                           VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                       false, &dummyUniform, &mem, nullptr))
    return false;
  dummyVertex = dummyUniform;
  dummyGarbage_.push_back({VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(dummyUniform)});
  dummyGarbage_.push_back({VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(mem)});

  VkImage images[2];
  for (int i = 0; i < 2; ++i) {
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = i == 0 ? VK_IMAGE_TYPE_2D : VK_IMAGE_TYPE_1D;
    ici.format = VK_FORMAT_R8G8B8A8_UNORM;
    ici.extent = {1, 1, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    vkCreateImage(device_, &ici, nullptr, &images[i]);
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, images[i], &req);
    VkDeviceMemory im;
    if (!AllocateMemory(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, &im)) return false;
    vkBindImageMemory(device_, images[i], im, 0);
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = images[i];
    vci.viewType = i == 0 ? VK_IMAGE_VIEW_TYPE_2D : VK_IMAGE_VIEW_TYPE_1D;
    vci.format = VK_FORMAT_R8G8B8A8_UNORM;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view;
    vkCreateImageView(device_, &vci, nullptr, &view);
    (i == 0 ? dummyImageView2D : dummyImageView1D) = view;
    dummyGarbage_.push_back({VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<uint64_t>(view)});
    dummyGarbage_.push_back({VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(images[i])});
    dummyGarbage_.push_back({VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(im)});
  }
  VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sci.maxLod = VK_LOD_CLAMP_NONE;
  vkCreateSampler(device_, &sci, nullptr, &dummySampler);
  dummyGarbage_.push_back({VK_OBJECT_TYPE_SAMPLER, reinterpret_cast<uint64_t>(dummySampler)});

  // Zero the dummies and make the images shader-readable (first upload batch).
  VkCommandBuffer cb = UploadCmd();
  vkCmdFillBuffer(cb, dummyUniform, 0, VK_WHOLE_SIZE, 0);
  VkImageMemoryBarrier2 b[2]{};
  for (int i = 0; i < 2; ++i) {
    b[i].sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2;
    b[i].srcStageMask = VK_PIPELINE_STAGE_2_NONE;
    b[i].dstStageMask = VK_PIPELINE_STAGE_2_CLEAR_BIT;
    b[i].dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    b[i].oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b[i].newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b[i].srcQueueFamilyIndex = b[i].dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b[i].image = images[i];
    b[i].subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  }
  VkDependencyInfo di{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  di.imageMemoryBarrierCount = 2;
  di.pImageMemoryBarriers = b;
  vkCmdPipelineBarrier2(cb, &di);
  VkClearColorValue zero{};
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  for (int i = 0; i < 2; ++i)
    vkCmdClearColorImage(cb, images[i], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
  for (int i = 0; i < 2; ++i) {
    b[i].srcStageMask = VK_PIPELINE_STAGE_2_CLEAR_BIT;
    b[i].srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    b[i].dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b[i].dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT;
    b[i].oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b[i].newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  }
  vkCmdPipelineBarrier2(cb, &di);
  return true;
}

HRESULT DeviceImpl::Init(const DEVICE_CREATE_DESC& desc) {
  log_ = desc.Log;
  logUser_ = desc.LogUser;
  ValidationMode mode = ResolveValidation(desc.Validation);
  if (!CreateInstance(desc, mode)) return E_FAIL;
  if (!PickAdapter(desc)) return DXGI_ERROR_UNSUPPORTED;
  if (!CreateLogicalDevice()) return DXGI_ERROR_UNSUPPORTED;
  uint32_t fif = desc.FramesInFlight ? desc.FramesInFlight : 2;
  if (fif > 8) {
    Log(LogLevel::Warning, "FramesInFlight %u clamped to 8", fif);
    fif = 8;
  }
  frames_.resize(fif);
  pipelines_.Init(this);
  InitFrames();
  if (!CreateDummies()) return E_OUTOFMEMORY;
  context_ = std::make_unique<ContextImpl>(this);
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
  DestroyFrames();
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
  s->ObjectsDestroyed = objectsDestroyed;
  uint64_t pending = 0;
  for (auto& f : frames_) pending += f.garbage.size();
  s->DeferredDestructionsPending = pending;
  s->LiveObjects = internalRefs_.load();
}

bool DeviceImpl::CheckFormatSupport(DXGI_FORMAT format, UINT bindFlags) const {
  const FormatInfo* f = GetFormatInfo(format);
  if (!f) return false;
  if (f->bc && !bc_) return false;
  VkFormat vf = f->vk;
  if (format == DXGI_FORMAT_R32_TYPELESS && (bindFlags & BIND_DEPTH_STENCIL)) vf = VK_FORMAT_D32_SFLOAT;
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(phys_, vf, &fp);
  VkFormatFeatureFlags need = 0;
  if (bindFlags & BIND_SHADER_RESOURCE) need |= VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
  if (bindFlags & BIND_RENDER_TARGET)
    need |= VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT;
  if (bindFlags & BIND_DEPTH_STENCIL) need |= VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if ((fp.optimalTilingFeatures & need) != need) {
    // Integer render targets do not blend.
    if ((bindFlags & BIND_RENDER_TARGET) && f->integer) {
      need &= ~VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT;
      if ((fp.optimalTilingFeatures & need) == need) goto buffers;
    }
    return false;
  }
buffers:
  if (bindFlags & BIND_VERTEX_BUFFER) {
    if (!(fp.bufferFeatures & VK_FORMAT_FEATURE_VERTEX_BUFFER_BIT)) return false;
  }
  if (bindFlags & BIND_INDEX_BUFFER)
    return format == DXGI_FORMAT_R16_UINT || format == DXGI_FORMAT_R32_UINT;
  return true;
}

void DeviceImpl::WaitIdle() {
  if (!device_) return;
  vkDeviceWaitIdle(device_);
  CompletedSerial();
}

}  // namespace impl

HRESULT CreateDevice(const DEVICE_CREATE_DESC* desc, Device** device, DeviceContext** context) {
  if (device) *device = nullptr;
  if (context) *context = nullptr;
  DEVICE_CREATE_DESC d = desc ? *desc : DEVICE_CREATE_DESC{};
  if (!device) {
    (d.Log ? d.Log : impl::DefaultLog)(LogLevel::Error, "CreateDevice: device pointer is null",
                                       d.LogUser);
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
