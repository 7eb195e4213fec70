// Hand-written Vulkan dispatches for the dispatch benchmark (see RawVulkanDispatch.h).
#include "RawVulkanDispatch.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "Recorder.h"
#include "d3dl/Bindings.h"
#include "d3dl/ShaderCompiler.h"

namespace drrbench {

#define VK_TRY(expr)                                                  \
  do {                                                                \
    VkResult r_ = (expr);                                             \
    if (r_ != VK_SUCCESS) {                                           \
      *error = std::string(#expr) + " failed: " + std::to_string(r_); \
      return false;                                                   \
    }                                                                 \
  } while (0)

namespace {
constexpr uint32_t kCbBinding = d3dl::VulkanBinding(d3dl::ShaderStage::Compute, d3dl::RegisterClass::ConstantBuffer, 0);
constexpr uint32_t kUavBinding = d3dl::VulkanBinding(d3dl::ShaderStage::Compute, d3dl::RegisterClass::UnorderedAccess, 0);
constexpr VkDeviceSize kWordsBytes = kDispatchWords * 4;
}  // namespace

bool RawVulkanDispatch::Init(VkPhysicalDevice gpu, VkDevice device, std::string* error) {
  gpu_ = gpu;
  device_ = device;
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(gpu_, &props);
  uboAlign_ = std::max<uint32_t>(static_cast<uint32_t>(props.limits.minUniformBufferOffsetAlignment),
                                 sizeof(DispatchConstants));
  return CreateBuffer(kWordsBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      false, &words_, &wordsMemory_, nullptr, error) &&
         CreateBuffer(kWordsBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, &readback_, &readbackMemory_,
                      &readbackMapped_, error) &&
         CreatePipeline(error) && EnsureRing(1024, error);
}

bool RawVulkanDispatch::CreateBuffer(VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible, VkBuffer* buffer,
                                     VkDeviceMemory* memory, void** mapped, std::string* error) {
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = size;
  bci.usage = usage;
  VK_TRY(vkCreateBuffer(device_, &bci, nullptr, buffer));
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, *buffer, &req);
  const VkMemoryPropertyFlags want = hostVisible
                                         ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                         : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  VkPhysicalDeviceMemoryProperties mp;
  vkGetPhysicalDeviceMemoryProperties(gpu_, &mp);
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = UINT32_MAX;
  for (uint32_t i = 0; i < mp.memoryTypeCount && mai.memoryTypeIndex == UINT32_MAX; ++i)
    if ((req.memoryTypeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) mai.memoryTypeIndex = i;
  VK_TRY(vkAllocateMemory(device_, &mai, nullptr, memory));
  VK_TRY(vkBindBufferMemory(device_, *buffer, *memory, 0));
  if (mapped) VK_TRY(vkMapMemory(device_, *memory, 0, VK_WHOLE_SIZE, 0, mapped));
  return true;
}

bool RawVulkanDispatch::CreatePipeline(std::string* error) {
  std::vector<uint32_t> code;  // file reading only: the recording itself is raw Vulkan
  if (d3dl::FAILED(d3dl::ReadSpirvFile(BenchShaderDir() + "/BenchDispatch.cs.spv", &code, error))) return false;
  VkShaderModuleCreateInfo smi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  smi.codeSize = code.size() * 4;
  smi.pCode = code.data();
  VK_TRY(vkCreateShaderModule(device_, &smi, nullptr, &module_));
  VkDescriptorSetLayoutBinding bindings[2]{};
  bindings[0] = {kCbBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  bindings[1] = {kUavBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo dli{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  dli.bindingCount = 2;
  dli.pBindings = bindings;
  VK_TRY(vkCreateDescriptorSetLayout(device_, &dli, nullptr, &setLayout_));
  VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &setLayout_;
  VK_TRY(vkCreatePipelineLayout(device_, &pli, nullptr, &layout_));
  VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
  VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpi.maxSets = 1;
  dpi.poolSizeCount = 2;
  dpi.pPoolSizes = sizes;
  VK_TRY(vkCreateDescriptorPool(device_, &dpi, nullptr, &pool_));
  VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  dai.descriptorPool = pool_;
  dai.descriptorSetCount = 1;
  dai.pSetLayouts = &setLayout_;
  VK_TRY(vkAllocateDescriptorSets(device_, &dai, &set_));
  VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_COMPUTE_BIT, module_,
              "CSMain", nullptr};
  ci.layout = layout_;
  VK_TRY(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline_));
  return true;
}

// A ring of n constant slots (grown when needed) and the set pointing at it.
bool RawVulkanDispatch::EnsureRing(uint32_t n, std::string* error) {
  const VkDeviceSize needed = VkDeviceSize(n) * uboAlign_;
  if (ring_ && ringSize_ >= needed) return true;
  if (ring_) {
    vkDestroyBuffer(device_, ring_, nullptr);
    vkFreeMemory(device_, ringMemory_, nullptr);
  }
  if (!CreateBuffer(needed, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true, &ring_, &ringMemory_, &ringMapped_, error))
    return false;
  ringSize_ = needed;
  VkDescriptorBufferInfo infos[2] = {{ring_, 0, sizeof(DispatchConstants)}, {words_, 0, kWordsBytes}};
  VkWriteDescriptorSet writes[2]{};
  for (int i = 0; i < 2; ++i) {
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = set_;
    writes[i].dstBinding = i == 0 ? kCbBinding : kUavBinding;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = i == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(device_, 2, writes, 0, nullptr);
  return true;
}

void RawVulkanDispatch::BufferBarrier(VkCommandBuffer cmd, VkBuffer buffer, VkPipelineStageFlags2 srcStage,
                                      VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                                      VkAccessFlags2 dstAccess) {
  VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  b.srcStageMask = srcStage;
  b.srcAccessMask = srcAccess;
  b.dstStageMask = dstStage;
  b.dstAccessMask = dstAccess;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = buffer;
  b.size = VK_WHOLE_SIZE;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.bufferMemoryBarrierCount = 1;
  dep.pBufferMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

void RawVulkanDispatch::Record(VkCommandBuffer cmd, uint32_t n) {
  std::string error;
  if (!EnsureRing(n, &error)) std::abort();
  constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  constexpr VkAccessFlags2 kStorage = VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  vkCmdFillBuffer(cmd, words_, 0, VK_WHOLE_SIZE, 0);
  BufferBarrier(cmd, words_, VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                kCompute, kStorage);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  auto* ring = static_cast<uint8_t*>(ringMapped_);
  for (uint32_t i = 0; i < n; ++i) {
    if (i) BufferBarrier(cmd, words_, kCompute, kStorage, kCompute, kStorage);  // the previous dispatch's writes
    const uint32_t offset = i * uboAlign_;
    const DispatchConstants c = ConstantsForDispatch(i);
    std::memcpy(ring + offset, &c, sizeof(c));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 1, &offset);
    vkCmdDispatch(cmd, 1, 1, 1);
  }
  BufferBarrier(cmd, words_, kCompute, kStorage, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  const VkBufferCopy region{0, 0, kWordsBytes};
  vkCmdCopyBuffer(cmd, words_, readback_, 1, &region);
  BufferBarrier(cmd, readback_, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

std::vector<uint32_t> RawVulkanDispatch::Words() const {
  const auto* p = static_cast<const uint32_t*>(readbackMapped_);
  return std::vector<uint32_t>(p, p + kDispatchWords);
}

void RawVulkanDispatch::Destroy() {
  if (!device_) return;
  vkDestroyPipeline(device_, pipeline_, nullptr);
  vkDestroyDescriptorPool(device_, pool_, nullptr);
  vkDestroyPipelineLayout(device_, layout_, nullptr);
  vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
  vkDestroyShaderModule(device_, module_, nullptr);
  for (VkBuffer b : {words_, readback_, ring_}) vkDestroyBuffer(device_, b, nullptr);
  for (VkDeviceMemory m : {wordsMemory_, readbackMemory_, ringMemory_}) vkFreeMemory(device_, m, nullptr);
  device_ = VK_NULL_HANDLE;
}

}  // namespace drrbench
