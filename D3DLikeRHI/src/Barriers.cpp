// Layout/access tracking and synchronization2 barriers. Every image
// subresource and every device-local buffer remembers its layout, its last
// write and the reads since; a new use emits the smallest barrier that makes
// it safe (and that synchronization validation accepts).
#include "ContextImmediate.h"

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
  // Stored only when it changes: recording threads read the resource's
  // other fields at every draw, and a store, even of the same value, would
  // take the cache line from them.
  if ((s.readStages & u.stages) != u.stages) s.readStages |= u.stages;
  return need;
}

namespace {
// The stage/access half shared by image and buffer barriers.
template <class B>
void FillBarrier(B& b, const BarrierInfo& info) {
  b.srcStageMask = info.srcStage;
  b.srcAccessMask = info.srcAccess;
  b.dstStageMask = info.dstStage;
  b.dstAccessMask = info.dstAccess;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
}

// `next` continues `prev` one mip further down, with the same accesses.
bool ExtendsByOneMip(const VkImageMemoryBarrier2& prev, const VkImageMemoryBarrier2& next) {
  const auto& p = prev.subresourceRange;
  return prev.image == next.image && prev.srcStageMask == next.srcStageMask &&
         prev.srcAccessMask == next.srcAccessMask && prev.dstStageMask == next.dstStageMask &&
         prev.dstAccessMask == next.dstAccessMask && prev.oldLayout == next.oldLayout &&
         prev.newLayout == next.newLayout &&
         p.baseArrayLayer == next.subresourceRange.baseArrayLayer && p.layerCount == 1 &&
         p.baseMipLevel + p.levelCount == next.subresourceRange.baseMipLevel;
}
}  // namespace

VkImageMemoryBarrier2 ImageBarrier(VkImage image, const VkImageSubresourceRange& range, const BarrierInfo& info) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  FillBarrier(b, info);
  b.oldLayout = info.oldLayout;
  b.newLayout = info.newLayout;
  b.image = image;
  b.subresourceRange = range;
  return b;
}

void RecordImageBarriers(VkCommandBuffer cmd, const VkImageMemoryBarrier2* barriers, uint32_t count) {
  VkDependencyInfo di{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  di.imageMemoryBarrierCount = count;
  di.pImageMemoryBarriers = barriers;
  vkCmdPipelineBarrier2(cmd, &di);
}

TransferInit TransferInitBarriers(VkPipelineStageFlags2 transferStage, VkAccessFlags2 laterAccess,
                                  VkImageLayout finalLayout) {
  TransferInit t;
  t.before = {VK_PIPELINE_STAGE_2_NONE, transferStage, 0, VK_ACCESS_2_TRANSFER_WRITE_BIT,
              VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
  t.after = {transferStage, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, laterAccess,
             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, finalLayout};
  return t;
}

void BarrierBatch::AddImage(VkImage image, VkImageAspectFlags aspect, uint32_t mip,
                            uint32_t layer, const BarrierInfo& info) {
  const VkImageMemoryBarrier2 b = ImageBarrier(image, {aspect, mip, 1, layer, 1}, info);
  if (!images_.empty() && ExtendsByOneMip(images_.back(), b)) {
    ++images_.back().subresourceRange.levelCount;
    return;
  }
  images_.push_back(b);
}

void BarrierBatch::AddBuffer(VkBuffer buffer, const BarrierInfo& info) {
  VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  FillBarrier(b, info);
  b.buffer = buffer;
  b.offset = 0;
  b.size = VK_WHOLE_SIZE;
  buffers_.push_back(b);
}

void BarrierBatch::Record(VkCommandBuffer cmd) {
  // Null for empty arrays: drivers that copy the arrays (lavapipe) then skip
  // a zero-sized allocation.
  VkDependencyInfo di{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  di.imageMemoryBarrierCount = static_cast<uint32_t>(images_.size());
  di.pImageMemoryBarriers = images_.empty() ? nullptr : images_.data();
  di.bufferMemoryBarrierCount = static_cast<uint32_t>(buffers_.size());
  di.pBufferMemoryBarriers = buffers_.empty() ? nullptr : buffers_.data();
  vkCmdPipelineBarrier2(cmd, &di);
  images_.clear();
  buffers_.clear();
}

// ---------------------------------------------------------------------------
void ImmediateContext::UseTexture(TextureCore* t, const SubresourceRange& r, const Usage& u) {
  TextureImage& img = t->Cur();
  const uint32_t mipCount = t->desc.MipLevels;
  for (uint32_t l = r.baseLayer; l < r.baseLayer + r.layers; ++l) {
    for (uint32_t m = r.baseMip; m < r.baseMip + r.mips; ++m) {
      BarrierInfo info;
      if (Transition(img.sync[l * mipCount + m], u, &info))
        barriers_.AddImage(img.image, t->aspect, m, l, info);
    }
  }
  if (u.layout != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) dirty_ |= kSrvLayouts;
}

void ImmediateContext::UseBuffer(VkBuffer buf, SyncState& s, const Usage& u) {
  BarrierInfo info;
  if (!Transition(s, u, &info)) return;
  barriers_.AddBuffer(buf, info);
  if (u.write) dirty_ |= kVertexBuffers | kIndexBuffer;
}

void ContextImpl::FlushBarriers() {
  if (barriers_.Empty()) return;
  EndRendering();
  barriers_.Record(Cmd());
}

}  // namespace d3dl::impl
