// Synchronisation state of image subresources and buffers, the uses that
// need barriers, and the batch that records them (Barriers.cpp).
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

namespace d3dl::impl {

// Layout and last accesses of one image subresource or one buffer.
struct SyncState {
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 writeStages = 0;  // stages of the last write / layout transition
  VkAccessFlags2 writeAccess = 0;         // access of the last write (0: transition only)
  VkPipelineStageFlags2 visible = 0;      // stages the last write is already visible to
  VkPipelineStageFlags2 readStages = 0;   // reads since the last write
  bool pending = false;                   // a write/transition happened
};

struct Usage {
  VkPipelineStageFlags2 stages;
  VkAccessFlags2 access;
  VkImageLayout layout;
  bool write;
  bool operator==(const Usage&) const = default;
};

namespace usage {
// Every graphics shader stage (vertex, hull, domain and geometry are the
// pre-rasterization stages; valid whether or not the device has them).
inline constexpr VkPipelineStageFlags2 kShaderStages =
    VK_PIPELINE_STAGE_2_PRE_RASTERIZATION_SHADERS_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
inline constexpr Usage ShaderRead{kShaderStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, false};
inline constexpr Usage ColorAttachment{
    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true};
inline constexpr Usage DepthAttachment{
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
    VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, true};
inline constexpr Usage TransferSrc{VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                                   VK_ACCESS_2_TRANSFER_READ_BIT,
                                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, false};
inline constexpr Usage TransferDst{
    VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
    VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, true};
// vkCmdResolveImage (ResolveSubresource) runs in its own transfer stage.
inline constexpr Usage ResolveSrc{VK_PIPELINE_STAGE_2_RESOLVE_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, false};
inline constexpr Usage ResolveDst{VK_PIPELINE_STAGE_2_RESOLVE_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, true};
inline constexpr Usage Present{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
                               VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, false};
inline constexpr Usage VertexRead{VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT |
                                      VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT,
                                  VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT |
                                      VK_ACCESS_2_INDEX_READ_BIT,
                                  VK_IMAGE_LAYOUT_UNDEFINED, false};
inline constexpr Usage BufferCopySrc{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                                     VK_IMAGE_LAYOUT_UNDEFINED, false};
inline constexpr Usage BufferCopyDst{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                     VK_IMAGE_LAYOUT_UNDEFINED, true};

// Shader reads and writes by a given set of stages (SRVs and UAVs).
inline constexpr VkPipelineStageFlags2 kComputeStage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr Usage SampledRead(VkPipelineStageFlags2 stages) {
  return {stages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, false};
}
constexpr Usage StorageBufferRead(VkPipelineStageFlags2 stages) {
  return {stages, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED, false};
}
// A UAV: read and written, images in GENERAL; every use counts as a write,
// so consecutive dispatches on one resource are serialised as in D3D11.
constexpr Usage StorageWrite(VkPipelineStageFlags2 stages, bool image) {
  return {stages, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
          image ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_UNDEFINED, true};
}
inline constexpr Usage IndirectRead{VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                                    VK_IMAGE_LAYOUT_UNDEFINED, false};
inline constexpr Usage BufferFillDst{VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
                                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED, true};
}  // namespace usage

// The barrier a use needs: source/destination stages, accesses and layouts.
struct BarrierInfo {
  VkPipelineStageFlags2 srcStage, dstStage;
  VkAccessFlags2 srcAccess, dstAccess;
  VkImageLayout oldLayout, newLayout;
};
// Computes the barrier needed before `u` and updates `s`. Returns false if
// no barrier is needed.
bool Transition(SyncState& s, const Usage& u, BarrierInfo* out);

// One image barrier (queue family ignored), and a dependency of image
// barriers recorded at once (uploads and dummies outside the batches).
VkImageMemoryBarrier2 ImageBarrier(VkImage image, const VkImageSubresourceRange& range, const BarrierInfo& info);
void RecordImageBarriers(VkCommandBuffer cmd, const VkImageMemoryBarrier2* barriers, uint32_t count);

// An image initialised by a transfer command (copy or clear) of the upload
// batch: UNDEFINED -> TRANSFER_DST before it, TRANSFER_DST -> `finalLayout`
// after it, visible to every later command's `laterAccess`.
struct TransferInit {
  BarrierInfo before, after;
};
TransferInit TransferInitBarriers(VkPipelineStageFlags2 transferStage, VkAccessFlags2 laterAccess,
                                  VkImageLayout finalLayout);

// Mips and array layers of a texture that one use touches.
struct SubresourceRange {
  uint32_t baseMip = 0, mips = 1, baseLayer = 0, layers = 1;
  bool operator==(const SubresourceRange&) const = default;
};
inline SubresourceRange OneSubresource(uint32_t mip, uint32_t layer) { return {mip, 1, layer, 1}; }

// Barriers collected between two recording points, recorded as one
// vkCmdPipelineBarrier2.
class BarrierBatch {
 public:
  BarrierBatch() {
    images_.reserve(32);
    buffers_.reserve(16);
  }
  bool Empty() const { return images_.empty() && buffers_.empty(); }
  // Merged with the previous barrier of the same image when only the mip differs.
  void AddImage(VkImage image, VkImageAspectFlags aspect, uint32_t mip, uint32_t layer,
                const BarrierInfo& info);
  void AddBuffer(VkBuffer buffer, const BarrierInfo& info);
  void Record(VkCommandBuffer cmd);  // and empties the batch

 private:
  std::vector<VkImageMemoryBarrier2> images_;
  std::vector<VkBufferMemoryBarrier2> buffers_;
};

}  // namespace d3dl::impl
