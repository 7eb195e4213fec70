// The hand-written Vulkan side of the dispatch benchmark (compute and
// unordered access), on the device of RawVulkanRecorder: one compute
// pipeline, one descriptor set (a dynamic uniform buffer in a mapped ring and
// the UAV as a storage buffer, at the bindings of d3dl/Bindings.h), per
// dispatch a vkCmdBindDescriptorSets with the new offset, vkCmdDispatch and
// the buffer barrier D3D11's ordering of dependent dispatches needs.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace drrbench {

class RawVulkanDispatch {
 public:
  bool Init(VkPhysicalDevice gpu, VkDevice device, std::string* error);
  void Destroy();
  // Records into `cmd`: fill the UAV with 0, n dispatches, copy to the read-back buffer.
  void Record(VkCommandBuffer cmd, uint32_t n);
  std::vector<uint32_t> Words() const;  // after the submission completed

 private:
  bool CreateBuffer(VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible, VkBuffer* buffer,
                    VkDeviceMemory* memory, void** mapped, std::string* error);
  bool CreatePipeline(std::string* error);
  bool EnsureRing(uint32_t n, std::string* error);
  void BufferBarrier(VkCommandBuffer cmd, VkBuffer buffer, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                     VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

  VkPhysicalDevice gpu_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  uint32_t uboAlign_ = 256;
  VkBuffer words_ = VK_NULL_HANDLE, readback_ = VK_NULL_HANDLE, ring_ = VK_NULL_HANDLE;
  VkDeviceMemory wordsMemory_ = VK_NULL_HANDLE, readbackMemory_ = VK_NULL_HANDLE, ringMemory_ = VK_NULL_HANDLE;
  void* readbackMapped_ = nullptr;
  void* ringMapped_ = nullptr;
  VkDeviceSize ringSize_ = 0;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace drrbench
