// Layout/access tracking and synchronization2 barriers. Every image
// subresource and every device-local buffer remembers its layout, its last
// write and the reads since; a new use emits the smallest barrier that makes
// it safe (and that synchronization validation accepts).
#include "Context.h"

namespace d3dl::impl {

bool Transition(SyncState& s, const Usage& u, BarrierInfo* out) {
  const bool layoutChange = u.layout != s.layout && u.layout != VK_IMAGE_LAYOUT_UNDEFINED;
  if (layoutChange || u.write) {
    bool fresh = !s.pending && s.readStages == 0;
    if (!layoutChange && fresh) {
      // First write to a resource nobody touched: no hazard.
    } else {
      out->srcStage = s.writeStages | s.readStages;
      if (!out->srcStage) out->srcStage = VK_PIPELINE_STAGE_2_NONE;
      out->srcAccess = s.writeAccess;
      out->dstStage = u.stages;
      out->dstAccess = u.access;
      out->oldLayout = s.layout;
      out->newLayout = layoutChange ? u.layout : s.layout;
    }
    if (layoutChange) s.layout = u.layout;
    s.pending = true;
    s.writeStages = u.stages;
    s.writeAccess = u.write ? u.access : 0;
    s.visible = u.write ? 0 : u.stages;
    s.readStages = u.write ? 0 : u.stages;
    return !(!layoutChange && fresh);
  }
  // A read in the current layout.
  bool covered = (s.visible & VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT) || !(u.stages & ~s.visible);
  bool need = s.pending && !covered;
  if (need) {
    out->srcStage = s.writeStages;
    out->srcAccess = s.writeAccess;
    out->dstStage = u.stages;
    out->dstAccess = u.access;
    out->oldLayout = out->newLayout = s.layout;
    s.visible |= u.stages;
  }
  s.readStages |= u.stages;
  return need;
}

void ContextImpl::UseTexture(TextureCore* t, uint32_t baseMip, uint32_t mips, uint32_t baseLayer,
                             uint32_t layers, const Usage& u) {
  TextureImage& img = t->Cur();
  const uint32_t mipCount = t->desc.MipLevels;
  for (uint32_t l = baseLayer; l < baseLayer + layers; ++l) {
    for (uint32_t m = baseMip; m < baseMip + mips; ++m) {
      SyncState& s = img.sync[l * mipCount + m];
      BarrierInfo bi;
      if (!Transition(s, u, &bi)) continue;
      VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
      b.srcStageMask = bi.srcStage;
      b.srcAccessMask = bi.srcAccess;
      b.dstStageMask = bi.dstStage;
      b.dstAccessMask = bi.dstAccess;
      b.oldLayout = bi.oldLayout;
      b.newLayout = bi.newLayout;
      b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      b.image = img.image;
      b.subresourceRange = {t->aspect, m, 1, l, 1};
      // Merge with the previous barrier of the same image when only the mip differs.
      if (!imageBarriers_.empty()) {
        auto& p = imageBarriers_.back();
        if (p.image == b.image && p.srcStageMask == b.srcStageMask &&
            p.srcAccessMask == b.srcAccessMask && p.dstStageMask == b.dstStageMask &&
            p.dstAccessMask == b.dstAccessMask && p.oldLayout == b.oldLayout &&
            p.newLayout == b.newLayout && p.subresourceRange.baseArrayLayer == l &&
            p.subresourceRange.layerCount == 1 &&
            p.subresourceRange.baseMipLevel + p.subresourceRange.levelCount == m) {
          ++p.subresourceRange.levelCount;
          continue;
        }
      }
      imageBarriers_.push_back(b);
    }
  }
  if (u.layout != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) dirty_ |= kSrvLayouts;
}

void ContextImpl::UseBuffer(VkBuffer buf, SyncState& s, const Usage& u) {
  BarrierInfo bi;
  if (!Transition(s, u, &bi)) return;
  VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  b.srcStageMask = bi.srcStage;
  b.srcAccessMask = bi.srcAccess;
  b.dstStageMask = bi.dstStage;
  b.dstAccessMask = bi.dstAccess;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = buf;
  b.offset = 0;
  b.size = VK_WHOLE_SIZE;
  bufferBarriers_.push_back(b);
  if (u.write) dirty_ |= kVertexBuffers | kIndexBuffer;
}

void ContextImpl::FlushBarriers() {
  if (imageBarriers_.empty() && bufferBarriers_.empty()) return;
  EndRendering();
  VkDependencyInfo di{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  di.imageMemoryBarrierCount = static_cast<uint32_t>(imageBarriers_.size());
  di.pImageMemoryBarriers = imageBarriers_.data();
  di.bufferMemoryBarrierCount = static_cast<uint32_t>(bufferBarriers_.size());
  di.pBufferMemoryBarriers = bufferBarriers_.data();
  vkCmdPipelineBarrier2(dev_->Cmd(), &di);
  imageBarriers_.clear();
  bufferBarriers_.clear();
}

}  // namespace d3dl::impl
