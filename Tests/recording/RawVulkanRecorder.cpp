// Hand-written Vulkan 1.3 baseline: what a careful engine would record for
// "N draws with changing constants" — one pipeline, one descriptor set with a
// dynamic uniform buffer, constants written into a mapped ring, one
// vkCmdBindDescriptorSets (new dynamic offset) + vkCmdDraw per draw.
#include "d3dl/ShaderCompiler.h"
#include <vulkan/vulkan.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "RawVulkanDispatch.h"
#include "Recorder.h"

namespace drrbench {
namespace {

#define VK_TRY(expr)                                            \
  do {                                                          \
    VkResult r_ = (expr);                                       \
    if (r_ != VK_SUCCESS) {                                     \
      *error = std::string(#expr) + " failed: " + std::to_string(r_); \
      return false;                                             \
    }                                                           \
  } while (0)

uint64_t g_rawValidationMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL OnDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void*) {
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    ++g_rawValidationMessages;
    std::fprintf(stderr, "raw vulkan validation: %s\n", data->pMessage);
  }
  return VK_FALSE;
}

class RawVulkanRecorder final : public Recorder {
 public:
  explicit RawVulkanRecorder(const VkAllocationCallbacks* poolAllocator) : poolAllocator_(poolAllocator) {}
  ~RawVulkanRecorder() override { Destroy(); }

  bool Init(std::string* error) override {
    const char* mode = std::getenv("D3DL_VALIDATION");
    const bool validation = mode && std::strcmp(mode, "0") != 0;
    const bool sync = mode && std::strcmp(mode, "sync") == 0;

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "raw-vulkan-baseline";
    app.apiVersion = VK_API_VERSION_1_3;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* ext = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkValidationFeatureEnableEXT syncFeature =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &syncFeature;
    VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ici.pApplicationInfo = &app;
    if (validation) {
      ici.enabledLayerCount = 1;
      ici.ppEnabledLayerNames = &layer;
      ici.enabledExtensionCount = 1;
      ici.ppEnabledExtensionNames = &ext;
      if (sync) ici.pNext = &features;
    }
    VK_TRY(vkCreateInstance(&ici, nullptr, &instance_));
    if (validation) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
      VkDebugUtilsMessengerCreateInfoEXT mci{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
      mci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
      mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                        VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                        VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
      mci.pfnUserCallback = OnDebugMessage;
      if (create) VK_TRY(create(instance_, &mci, nullptr, &messenger_));
    }

    // Same adapter choice as D3DLikeRHI: a discrete GPU if there is one.
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance_, &count, nullptr);
    if (count == 0) {
      *error = "no Vulkan physical device";
      return false;
    }
    std::vector<VkPhysicalDevice> gpus(count);
    vkEnumeratePhysicalDevices(instance_, &count, gpus.data());
    gpu_ = gpus[0];
    for (VkPhysicalDevice g : gpus) {
      VkPhysicalDeviceProperties p;
      vkGetPhysicalDeviceProperties(g, &p);
      if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU) {
        gpu_ = g;
        break;
      }
    }
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(gpu_, &props);
    uboAlign_ = static_cast<uint32_t>(props.limits.minUniformBufferOffsetAlignment);
    if (uboAlign_ < sizeof(DrawConstants)) uboAlign_ = sizeof(DrawConstants);

    uint32_t qfCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(gpu_, &qfCount, nullptr);
    std::vector<VkQueueFamilyProperties> qfs(qfCount);
    vkGetPhysicalDeviceQueueFamilyProperties(gpu_, &qfCount, qfs.data());
    for (uint32_t i = 0; i < qfCount; ++i) {
      if (qfs[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
        queueFamily_ = i;
        break;
      }
    }

    float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = queueFamily_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    f13.dynamicRendering = VK_TRUE;
    f13.synchronization2 = VK_TRUE;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = &f13;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    VK_TRY(vkCreateDevice(gpu_, &dci, nullptr, &device_));
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

    if (!CreateTarget(error) || !CreatePipeline(error) || !dispatch_.Init(gpu_, device_, error)) return false;

    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.queueFamilyIndex = queueFamily_;
    VK_TRY(vkCreateCommandPool(device_, &pci, poolAllocator_, &pool_));
    VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cai.commandPool = pool_;
    cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cai.commandBufferCount = 1;
    VK_TRY(vkAllocateCommandBuffers(device_, &cai, &cmd_));
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_TRY(vkCreateFence(device_, &fci, nullptr, &fence_));
    BeginCommandBuffer();
    return true;
  }

  // The command buffer was begun after the previous submission's wait (as the
  // RHI does at its frame boundary), so only the frame's commands are timed.
  void Record(uint32_t n) override {
    EnsureRing(n);

    Transition(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
               VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = view_;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {kTargetSize, kTargetSize}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &color;
    vkCmdBeginRendering(cmd_, &ri);
    vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    // D3D convention, as the RHI does it: negative viewport height.
    VkViewport vp{0.0f, float(kTargetSize), float(kTargetSize), -float(kTargetSize), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {kTargetSize, kTargetSize}};
    vkCmdSetViewport(cmd_, 0, 1, &vp);
    vkCmdSetScissor(cmd_, 0, 1, &scissor);

    auto* ring = static_cast<uint8_t*>(ringMapped_);
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t offset = i * uboAlign_;
      const DrawConstants c = ConstantsForDraw(i, n);
      std::memcpy(ring + offset, &c, sizeof(c));
      vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 1,
                              &offset);
      vkCmdDraw(cmd_, 3, 1, 0, 0);
    }
    vkCmdEndRendering(cmd_);

    Transition(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
               VK_ACCESS_2_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {kTargetSize, kTargetSize, 1};
    vkCmdCopyImageToBuffer(cmd_, image_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_, 1,
                           &region);
    VkMemoryBarrier2 hostRead{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    hostRead.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    hostRead.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    hostRead.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    hostRead.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &hostRead;
    vkCmdPipelineBarrier2(cmd_, &dep);
    vkEndCommandBuffer(cmd_);
  }

  void SubmitAndWait() override {
    VkCommandBufferSubmitInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cbi.commandBuffer = cmd_;
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &cbi;
    vkQueueSubmit2(queue_, 1, &si, fence_);
    vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
    vkResetFences(device_, 1, &fence_);
    BeginCommandBuffer();
  }

  std::vector<uint8_t> ReadBack() override {
    const auto* p = static_cast<const uint8_t*>(readbackMapped_);
    return std::vector<uint8_t>(p, p + kTargetSize * kTargetSize * 4);
  }

  uint64_t ValidationMessages() const override { return g_rawValidationMessages; }

  // Compute and unordered access: the dispatch frame (RawVulkanDispatch).
  void RecordDispatches(uint32_t n) override {
    dispatch_.Record(cmd_, n);
    vkEndCommandBuffer(cmd_);
  }
  std::vector<uint32_t> ReadBackWords() override { return dispatch_.Words(); }

 private:
  void BeginCommandBuffer() {
    vkResetCommandPool(device_, pool_, 0);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd_, &bi);
  }

  uint32_t FindMemory(uint32_t typeBits, VkMemoryPropertyFlags flags) const {
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(gpu_, &mp);
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i) {
      if ((typeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & flags) == flags) return i;
    }
    return UINT32_MAX;
  }

  bool CreateBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkBuffer* buffer,
                    VkDeviceMemory* memory, void** mapped, std::string* error) {
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size;
    bci.usage = usage;
    VK_TRY(vkCreateBuffer(device_, &bci, nullptr, buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, *buffer, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = FindMemory(
        req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VK_TRY(vkAllocateMemory(device_, &mai, nullptr, memory));
    VK_TRY(vkBindBufferMemory(device_, *buffer, *memory, 0));
    VK_TRY(vkMapMemory(device_, *memory, 0, VK_WHOLE_SIZE, 0, mapped));
    return true;
  }

  bool CreateTarget(std::string* error) {
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = VK_FORMAT_R8G8B8A8_UNORM;
    ici.extent = {kTargetSize, kTargetSize, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VK_TRY(vkCreateImage(device_, &ici, nullptr, &image_));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, image_, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = FindMemory(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_TRY(vkAllocateMemory(device_, &mai, nullptr, &imageMemory_));
    VK_TRY(vkBindImageMemory(device_, image_, imageMemory_, 0));
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = image_;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = ici.format;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VK_TRY(vkCreateImageView(device_, &vci, nullptr, &view_));
    return CreateBuffer(kTargetSize * kTargetSize * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, &readback_,
                        &readbackMemory_, &readbackMapped_, error);
  }

  bool CreatePipeline(std::string* error) {
    const std::string dir = BenchShaderDir();
    std::vector<uint32_t> vs, ps;  // file reading only: the recording itself is raw Vulkan
    if (d3dl::FAILED(d3dl::ReadSpirvFile(dir + "/BenchDraw.vs.spv", &vs, error)) ||
        d3dl::FAILED(d3dl::ReadSpirvFile(dir + "/BenchDraw.ps.spv", &ps, error)))
      return false;
    VkShaderModuleCreateInfo smi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    smi.codeSize = vs.size() * 4;
    smi.pCode = vs.data();
    VK_TRY(vkCreateShaderModule(device_, &smi, nullptr, &vsModule_));
    smi.codeSize = ps.size() * 4;
    smi.pCode = ps.data();
    VK_TRY(vkCreateShaderModule(device_, &smi, nullptr, &psModule_));

    VkDescriptorSetLayoutBinding binding{};
    binding.binding = 0;  // VS b0 by the binding formula
    binding.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
    binding.descriptorCount = 1;
    binding.stageFlags = VK_SHADER_STAGE_VERTEX_BIT;
    VkDescriptorSetLayoutCreateInfo dli{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    dli.bindingCount = 1;
    dli.pBindings = &binding;
    VK_TRY(vkCreateDescriptorSetLayout(device_, &dli, nullptr, &setLayout_));
    VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pli.setLayoutCount = 1;
    pli.pSetLayouts = &setLayout_;
    VK_TRY(vkCreatePipelineLayout(device_, &pli, nullptr, &layout_));

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1};
    VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpi.maxSets = 1;
    dpi.poolSizeCount = 1;
    dpi.pPoolSizes = &size;
    VK_TRY(vkCreateDescriptorPool(device_, &dpi, nullptr, &descriptorPool_));
    VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dai.descriptorPool = descriptorPool_;
    dai.descriptorSetCount = 1;
    dai.pSetLayouts = &setLayout_;
    VK_TRY(vkAllocateDescriptorSets(device_, &dai, &set_));

    VkPipelineShaderStageCreateInfo stages[2]{};
    stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
                 VK_SHADER_STAGE_VERTEX_BIT, vsModule_, "VSMain", nullptr};
    stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
                 VK_SHADER_STAGE_FRAGMENT_BIT, psModule_, "PSMain", nullptr};
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vps{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vps.viewportCount = 1;
    vps.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = VK_CULL_MODE_NONE;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineColorBlendAttachmentState blend{};
    blend.colorWriteMask = 0xf;
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = 1;
    cb.pAttachments = &blend;
    VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    ds.dynamicStateCount = 2;
    ds.pDynamicStates = dyn;
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkPipelineRenderingCreateInfo rci{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rci.colorAttachmentCount = 1;
    rci.pColorAttachmentFormats = &format;
    VkGraphicsPipelineCreateInfo gpi{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    gpi.pNext = &rci;
    gpi.stageCount = 2;
    gpi.pStages = stages;
    gpi.pVertexInputState = &vi;
    gpi.pInputAssemblyState = &ia;
    gpi.pViewportState = &vps;
    gpi.pRasterizationState = &rs;
    gpi.pMultisampleState = &ms;
    gpi.pColorBlendState = &cb;
    gpi.pDynamicState = &ds;
    gpi.layout = layout_;
    VK_TRY(vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &gpi, nullptr, &pipeline_));
    return true;
  }

  void EnsureRing(uint32_t n) {
    const VkDeviceSize needed = VkDeviceSize(n) * uboAlign_;
    if (ring_ && ringSize_ >= needed) return;
    DestroyRing();
    std::string error;
    if (!CreateBuffer(needed, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &ring_, &ringMemory_,
                      &ringMapped_, &error)) {
      std::fprintf(stderr, "raw vulkan: %s\n", error.c_str());
      std::abort();
    }
    ringSize_ = needed;
    VkDescriptorBufferInfo info{ring_, 0, sizeof(DrawConstants)};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
  }

  void Transition(VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                  VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                  VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = srcStage;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dstStage;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image_;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd_, &dep);
  }

  void DestroyRing() {
    if (!ring_) return;
    vkDestroyBuffer(device_, ring_, nullptr);
    vkFreeMemory(device_, ringMemory_, nullptr);
    ring_ = VK_NULL_HANDLE;
  }

  void Destroy() {
    if (device_) {
      vkDeviceWaitIdle(device_);
      dispatch_.Destroy();
      DestroyRing();
      vkDestroyFence(device_, fence_, nullptr);
      vkDestroyCommandPool(device_, pool_, poolAllocator_);
      vkDestroyPipeline(device_, pipeline_, nullptr);
      vkDestroyDescriptorPool(device_, descriptorPool_, nullptr);
      vkDestroyPipelineLayout(device_, layout_, nullptr);
      vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
      vkDestroyShaderModule(device_, vsModule_, nullptr);
      vkDestroyShaderModule(device_, psModule_, nullptr);
      vkDestroyImageView(device_, view_, nullptr);
      vkDestroyImage(device_, image_, nullptr);
      vkFreeMemory(device_, imageMemory_, nullptr);
      vkDestroyBuffer(device_, readback_, nullptr);
      vkFreeMemory(device_, readbackMemory_, nullptr);
      vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy) destroy(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
    device_ = VK_NULL_HANDLE;
    instance_ = VK_NULL_HANDLE;
  }

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice gpu_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  uint32_t uboAlign_ = 256;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory imageMemory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkBuffer readback_ = VK_NULL_HANDLE;
  VkDeviceMemory readbackMemory_ = VK_NULL_HANDLE;
  void* readbackMapped_ = nullptr;
  VkBuffer ring_ = VK_NULL_HANDLE;
  VkDeviceMemory ringMemory_ = VK_NULL_HANDLE;
  void* ringMapped_ = nullptr;
  VkDeviceSize ringSize_ = 0;
  VkShaderModule vsModule_ = VK_NULL_HANDLE, psModule_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  const VkAllocationCallbacks* poolAllocator_;  // the command pool's host memory (null: the driver's)
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  RawVulkanDispatch dispatch_;  // compute and unordered access
};

}  // namespace

Recorder* CreateRawVulkanRecorder(const VkAllocationCallbacks* poolAllocator) {
  return new RawVulkanRecorder(poolAllocator);
}

}  // namespace drrbench
