// Instance, validation messenger, adapter choice, logical device and the
// dummy resources bound where a shader expects one and none is bound.
#include <cstdio>
#include <cstdlib>

#include "Context.h"

namespace d3dl::impl {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL DebugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
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

template <class F>
F InstanceProc(VkInstance instance, const char* name) {
  return reinterpret_cast<F>(vkGetInstanceProcAddr(instance, name));
}

VkDebugUtilsMessengerCreateInfoEXT MessengerInfo(DeviceImpl* dev) {
  VkDebugUtilsMessengerCreateInfoEXT mci{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  mci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                    VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  mci.pfnUserCallback = DebugCallback;
  mci.pUserData = dev;
  return mci;
}

}  // namespace

// Instance extensions: debug utils, and every window-system surface the
// loader offers (what glfwGetRequiredInstanceExtensions would return, without
// needing a display at device creation).
static std::vector<const char*> ChooseInstanceExtensions(const DEVICE_CREATE_DESC& desc, DeviceFeatures* f) {
  const auto available = InstanceExtensions();
  auto has = [&](const char* e) { return std::find(available.begin(), available.end(), e) != available.end(); };
  std::vector<const char*> exts;
  if (has(VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
    exts.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    f->debugUtils = true;
  }
  if (desc.EnableWindowSurfaces) {
    for (const char* e : {"VK_KHR_surface", "VK_KHR_xcb_surface", "VK_KHR_xlib_surface", "VK_KHR_wayland_surface",
                          "VK_KHR_win32_surface", "VK_EXT_metal_surface"})
      if (has(e)) exts.push_back(e);
    f->surface = has("VK_KHR_surface");
  }
  return exts;
}

bool DeviceImpl::CreateInstance(const DEVICE_CREATE_DESC& desc, ValidationMode mode) {
  std::vector<const char*> exts = ChooseInstanceExtensions(desc, &features_), layers;
  bool validation = mode != ValidationMode::Off;
  if (validation && !HasLayer("VK_LAYER_KHRONOS_validation")) {
    Log(LogLevel::Warning, "VK_LAYER_KHRONOS_validation is not installed; validation is off");
    validation = false;
  }
  if (validation) layers.push_back("VK_LAYER_KHRONOS_validation");
  stats.ValidationRequested = mode;
  stats.Validation = validation ? mode : ValidationMode::Off;
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
  const VkDebugUtilsMessengerCreateInfoEXT mci = MessengerInfo(this);
  const void* chain = features_.debugUtils && validation ? &mci : nullptr;
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
  LoadDebugUtils(validation, mci);
  if (validation)
    Log(LogLevel::Info, "Vulkan validation on%s", mode == ValidationMode::CoreAndSync ? " (with synchronization validation)" : "");
  return true;
}

void DeviceImpl::LoadDebugUtils(bool validation, const VkDebugUtilsMessengerCreateInfoEXT& mci) {
  if (!features_.debugUtils) return;
  auto create = InstanceProc<PFN_vkCreateDebugUtilsMessengerEXT>(instance_, "vkCreateDebugUtilsMessengerEXT");
  if (validation && create) create(instance_, &mci, nullptr, &messenger_);
  debugUtils_.cmdBeginLabel = InstanceProc<PFN_vkCmdBeginDebugUtilsLabelEXT>(instance_, "vkCmdBeginDebugUtilsLabelEXT");
  debugUtils_.cmdEndLabel = InstanceProc<PFN_vkCmdEndDebugUtilsLabelEXT>(instance_, "vkCmdEndDebugUtilsLabelEXT");
  debugUtils_.setObjectName = InstanceProc<PFN_vkSetDebugUtilsObjectNameEXT>(instance_, "vkSetDebugUtilsObjectNameEXT");
}

bool DeviceImpl::PickAdapter(const DEVICE_CREATE_DESC& desc) {
  uint32_t n = 0;
  vkEnumeratePhysicalDevices(instance_, &n, nullptr);
  std::vector<VkPhysicalDevice> devs(n);
  vkEnumeratePhysicalDevices(instance_, &n, devs.data());
  const char* filter = desc.AdapterNameFilter;
  if (!filter || !*filter) filter = std::getenv("D3DL_ADAPTER");
  int best = -1, bestScore = -1;
  for (uint32_t i = 0; i < n; ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(devs[i], &p);
    if (p.apiVersion < VK_API_VERSION_1_3) continue;
    if (filter && *filter && !std::strstr(p.deviceName, filter)) continue;
    const int score = p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU     ? 4
                      : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? 3
                      : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU    ? 2
                                                                               : 1;
    if (score > bestScore) {
      bestScore = score;
      best = static_cast<int>(i);
    }
  }
  if (best < 0) {
    Log(LogLevel::Error, "no Vulkan 1.3 adapter found%s%s", filter ? " matching filter " : "", filter ? filter : "");
    return false;
  }
  phys_ = devs[best];
  vkGetPhysicalDeviceProperties(phys_, &props_);
  vkGetPhysicalDeviceMemoryProperties(phys_, &memProps_);
  uboAlign_ = std::max<VkDeviceSize>(16, props_.limits.minUniformBufferOffsetAlignment);
  return true;
}

// Required: dynamicRendering, synchronization2, hostQueryReset; the optional
// features are enabled when present and remembered in features_.
bool DeviceImpl::EnableFeatures(VkPhysicalDeviceFeatures2* e2, VkPhysicalDeviceVulkan12Features* e12,
                                VkPhysicalDeviceVulkan13Features* e13) {
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
  e12->pNext = e13;
  e2->pNext = e12;
  e13->dynamicRendering = VK_TRUE;
  e13->synchronization2 = VK_TRUE;
  e13->maintenance4 = f13.maintenance4;  // relaxed VS/PS interface matching, as in D3D
  // HLSL `discard` compiles to OpDemoteToHelperInvocation for Vulkan 1.3 (a required 1.3 feature).
  e13->shaderDemoteToHelperInvocation = f13.shaderDemoteToHelperInvocation;
  e12->hostQueryReset = f12.hostQueryReset;
  e12->samplerFilterMinmax = f12.samplerFilterMinmax;
  e12->samplerMirrorClampToEdge = f12.samplerMirrorClampToEdge;
  const VkPhysicalDeviceFeatures& f = f2.features;
  VkPhysicalDeviceFeatures& e = e2->features;
  e.samplerAnisotropy = f.samplerAnisotropy;
  e.textureCompressionBC = f.textureCompressionBC;
  e.fillModeNonSolid = f.fillModeNonSolid;
  e.depthClamp = f.depthClamp;
  e.independentBlend = f.independentBlend;
  e.depthBiasClamp = f.depthBiasClamp;
  e.fragmentStoresAndAtomics = f.fragmentStoresAndAtomics;
  // A non-zero StartInstanceLocation in Draw*InstancedIndirect's arguments
  // (valid in D3D11) is undefined in Vulkan without it.
  e.drawIndirectFirstInstance = f.drawIndirectFirstInstance;
  features_.fragmentStores = f.fragmentStoresAndAtomics;
  features_.mirrorOnce = f12.samplerMirrorClampToEdge;
  features_.minmax = f12.samplerFilterMinmax;
  features_.anisotropy = f.samplerAnisotropy;
  features_.bc = f.textureCompressionBC;
  features_.fillNonSolid = f.fillModeNonSolid;
  features_.depthClamp = f.depthClamp;
  // Optional stages and pipeline statistics: enabled only when reported.
  e.tessellationShader = f.tessellationShader;
  e.geometryShader = f.geometryShader;
  e.pipelineStatisticsQuery = f.pipelineStatisticsQuery;
  features_.tessellation = f.tessellationShader;
  features_.geometry = f.geometryShader;
  features_.pipelineStatistics = f.pipelineStatisticsQuery;
  e.imageCubeArray = f.imageCubeArray;  // TEXTURECUBEARRAY views
  features_.cubeArray = f.imageCubeArray;
  features_.independentBlend = f.independentBlend;
  if (!f12.hostQueryReset) {
    Log(LogLevel::Error, "adapter %s lacks hostQueryReset", props_.deviceName);
    return false;
  }
  FillValidationCaps();
  return true;
}

// What the validation layer checks against, from the adapter's limits and
// the features enabled above.
void DeviceImpl::FillValidationCaps() {
  const VkPhysicalDeviceLimits& lim = props_.limits;
  ValidationCaps& c = caps_;
  c.maxTexture1D = lim.maxImageDimension1D;
  c.maxTexture2D = lim.maxImageDimension2D;
  c.maxArrayLayers = lim.maxImageArrayLayers;
  c.maxUniformBufferRange = lim.maxUniformBufferRange;
  c.storageBufferAlign = lim.minStorageBufferOffsetAlignment;
  for (int i = 0; i < 3; ++i) c.maxDispatch[i] = lim.maxComputeWorkGroupCount[i];
  c.bc = features_.bc;
  c.minmax = features_.minmax;
  c.independentBlend = features_.independentBlend;
  c.fillNonSolid = features_.fillNonSolid;
  c.pipelineStatistics = features_.pipelineStatistics;
  c.cubeArray = features_.cubeArray;
  std::snprintf(c.adapterName, sizeof(c.adapterName), "%s", props_.deviceName);
}

bool DeviceImpl::CreateLogicalDevice() {
  uint32_t qn = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(phys_, &qn, nullptr);
  std::vector<VkQueueFamilyProperties> qf(qn);
  vkGetPhysicalDeviceQueueFamilyProperties(phys_, &qn, qf.data());
  auto graphics = std::find_if(qf.begin(), qf.end(), [](const auto& q) { return (q.queueFlags & VK_QUEUE_GRAPHICS_BIT) != 0; });
  if (graphics == qf.end()) {
    Log(LogLevel::Error, "adapter %s has no graphics queue", props_.deviceName);
    return false;
  }
  queueFamily_ = static_cast<uint32_t>(graphics - qf.begin());
  VkPhysicalDeviceVulkan12Features e12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features e13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 e2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  if (!EnableFeatures(&e2, &e12, &e13)) return false;
  // VK_KHR_swapchain requires VK_KHR_surface on the instance: without window
  // surfaces (headless), the device is created without it.
  uint32_t en = 0;
  vkEnumerateDeviceExtensionProperties(phys_, nullptr, &en, nullptr);
  std::vector<VkExtensionProperties> dext(en);
  vkEnumerateDeviceExtensionProperties(phys_, nullptr, &en, dext.data());
  std::vector<const char*> exts;
  for (auto& e : dext)
    if (features_.surface && std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0) {
      exts.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
      features_.swapchain = true;
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
  FillAdapterDesc(qf[queueFamily_].timestampValidBits);
  return true;
}

void DeviceImpl::FillAdapterDesc(uint32_t timestampBits) {
  std::snprintf(adapter_.Description, sizeof(adapter_.Description), "%s", props_.deviceName);
  VkPhysicalDeviceDriverProperties drv{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  p2.pNext = &drv;
  vkGetPhysicalDeviceProperties2(phys_, &p2);
  const std::string driver = std::string(drv.driverName) + " " + drv.driverInfo;
  std::snprintf(adapter_.Driver, sizeof(adapter_.Driver), "%s", driver.c_str());
  adapter_.VendorId = props_.vendorID;
  adapter_.DeviceId = props_.deviceID;
  adapter_.ApiVersion = props_.apiVersion;
  adapter_.IsSoftware = props_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  adapter_.SupportsBC = features_.bc;
  adapter_.TimestampPeriodNs = timestampBits ? props_.limits.timestampPeriod : 0.0f;
}

// ---------------------------------------------------------------------------
bool DeviceImpl::CreateDummyImage(VkImageType type, VkImage* image, VkImageView* view) {
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.imageType = type;
  ici.format = VK_FORMAT_R8G8B8A8_UNORM;
  ici.extent = {1, 1, 1};
  ici.mipLevels = 1;
  ici.arrayLayers = 1;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  vkCreateImage(device_, &ici, nullptr, image);
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device_, *image, &req);
  VkDeviceMemory mem;
  if (!AllocateMemory(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, &mem)) return false;
  vkBindImageMemory(device_, *image, mem, 0);
  VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vci.image = *image;
  vci.viewType = type == VK_IMAGE_TYPE_2D ? VK_IMAGE_VIEW_TYPE_2D : VK_IMAGE_VIEW_TYPE_1D;
  vci.format = VK_FORMAT_R8G8B8A8_UNORM;
  vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCreateImageView(device_, &vci, nullptr, view);
  dummyGarbage_.push_back({VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<uint64_t>(*view)});
  dummyGarbage_.push_back({VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(*image)});
  dummyGarbage_.push_back({VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(mem)});
  return true;
}

bool DeviceImpl::CreateDummies() {
  dummies_.uniformSize = std::min<VkDeviceSize>(65536, props_.limits.maxUniformBufferRange);
  VkDeviceMemory mem;
  if (!CreateBufferRaw(dummies_.uniformSize,
                       VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       false, &dummies_.uniform, &mem, nullptr))
    return false;
  dummyGarbage_.push_back({VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(dummies_.uniform)});
  dummyGarbage_.push_back({VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(mem)});
  VkImage images[2];
  if (!CreateDummyImage(VK_IMAGE_TYPE_2D, &images[0], &dummies_.view2D) ||
      !CreateDummyImage(VK_IMAGE_TYPE_1D, &images[1], &dummies_.view1D))
    return false;
  VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sci.maxLod = VK_LOD_CLAMP_NONE;
  vkCreateSampler(device_, &sci, nullptr, &dummies_.sampler);
  dummyGarbage_.push_back({VK_OBJECT_TYPE_SAMPLER, reinterpret_cast<uint64_t>(dummies_.sampler)});
  ClearDummies(images);
  return CreateViewDummies(images[1]);
}

// Zeroes the dummies and makes the images shader-readable (first upload batch).
void DeviceImpl::ClearDummies(const VkImage images[2]) {
  const TransferInit t = TransferInitBarriers(VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_MEMORY_READ_BIT,
                                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkCommandBuffer cb = UploadCmd();
  vkCmdFillBuffer(cb, dummies_.uniform, 0, VK_WHOLE_SIZE, 0);
  VkImageMemoryBarrier2 b[2] = {ImageBarrier(images[0], range, t.before), ImageBarrier(images[1], range, t.before)};
  RecordImageBarriers(cb, b, 2);
  VkClearColorValue zero{};
  for (int i = 0; i < 2; ++i) vkCmdClearColorImage(cb, images[i], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
  for (int i = 0; i < 2; ++i) b[i] = ImageBarrier(images[i], range, t.after);
  RecordImageBarriers(cb, b, 2);
}

}  // namespace d3dl::impl
