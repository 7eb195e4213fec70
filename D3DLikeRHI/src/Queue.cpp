// The device queue's frames: a fence, a ring, an upload command buffer
// submitted ahead of the frame's commands, and the handles to destroy once
// the frame's fence has signalled.
#include "Device.h"

namespace d3dl::impl {
namespace {
VkSemaphoreSubmitInfo SemaphoreInfo(VkSemaphore s) {
  VkSemaphoreSubmitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  info.semaphore = s;
  info.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  return info;
}

VkCommandBufferSubmitInfo CommandBufferInfo(VkCommandBuffer cmd) {
  VkCommandBufferSubmitInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  info.commandBuffer = cmd;
  return info;
}
}  // namespace

void FrameQueue::Init(DeviceImpl* dev, VkQueue queue, uint32_t frames) {
  dev_ = dev;
  queue_ = queue;
  frames_.resize(frames);
  const VkDevice d = dev->vk();
  for (auto& f : frames_) {
    dev->CreateCommandBuffer(&f.uploadPool, &f.uploadCmd);
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    vkCreateFence(d, &fci, nullptr, &f.fence);
    VkSemaphoreCreateInfo sci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    vkCreateSemaphore(d, &sci, nullptr, &f.acquireSemaphore);
    f.ring.Init(dev);
  }
  slot_ = static_cast<uint32_t>(serial_ % frames_.size());
  BeginFrame();
}

void FrameQueue::Destroy() {
  const VkDevice d = dev_ ? dev_->vk() : VK_NULL_HANDLE;
  for (auto& f : frames_) {
    for (auto& g : f.garbage) dev_->DestroyNow(g);
    f.garbage.clear();
    f.ring.Destroy();
    if (f.fence) vkDestroyFence(d, f.fence, nullptr);
    if (f.uploadPool) vkDestroyCommandPool(d, f.uploadPool, nullptr);
    if (f.acquireSemaphore) vkDestroySemaphore(d, f.acquireSemaphore, nullptr);
  }
  frames_.clear();
}

// The fence of the frame that last used this slot has signalled (or is
// waited for here): its garbage goes, its ring and upload pool are reused.
void FrameQueue::Recycle(Frame& f) {
  const VkDevice d = dev_->vk();
  if (f.submitted) {
    vkWaitForFences(d, 1, &f.fence, VK_TRUE, UINT64_MAX);
    vkResetFences(d, 1, &f.fence);
    NoteCompleted(f.serial);
    f.submitted = false;
  }
  std::vector<Garbage> garbage;
  {
    std::lock_guard<std::mutex> lock(garbageMutex_);
    garbage.swap(f.garbage);
  }
  dev_->stats.ObjectsDestroyed += garbage.size();
  for (auto& g : garbage) dev_->DestroyNow(g);
  f.ring.Reset();
  vkResetCommandPool(d, f.uploadPool, 0);
  f.uploadUsed = false;
}

void FrameQueue::BeginFrame() {
  Frame& f = frames_[slot_];
  Recycle(f);
  f.serial = serial_;
}

VkCommandBuffer FrameQueue::UploadCmd() {
  Frame& f = frames_[slot_];
  if (!f.uploadUsed) {
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(f.uploadCmd, &bi);
    f.uploadUsed = true;
  }
  return f.uploadCmd;
}

// Ends the upload command buffer when something was recorded into it: its
// uploads are ordered before every command of the frame.
uint32_t FrameQueue::EndUploads(Frame& f, VkCommandBufferSubmitInfo* out) {
  if (!f.uploadUsed) return 0;
  VkMemoryBarrier2 ub{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  ub.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  ub.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  ub.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  ub.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
  VkDependencyInfo udi{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  udi.memoryBarrierCount = 1;
  udi.pMemoryBarriers = &ub;
  vkCmdPipelineBarrier2(f.uploadCmd, &udi);
  vkEndCommandBuffer(f.uploadCmd);
  *out = CommandBufferInfo(f.uploadCmd);
  return 1;
}

void FrameQueue::Submit(VkCommandBuffer cmd, VkSemaphore signal) {
  Frame& f = frames_[slot_];
  VkCommandBufferSubmitInfo cbs[2];
  uint32_t n = EndUploads(f, &cbs[0]);
  cbs[n++] = CommandBufferInfo(cmd);
  std::vector<VkSemaphoreSubmitInfo> waits;
  for (VkSemaphore s : pendingWaits_) waits.push_back(SemaphoreInfo(s));
  pendingWaits_.clear();
  const VkSemaphoreSubmitInfo signalInfo = SemaphoreInfo(signal);
  VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  si.commandBufferInfoCount = n;
  si.pCommandBufferInfos = cbs;
  si.waitSemaphoreInfoCount = static_cast<uint32_t>(waits.size());
  si.pWaitSemaphoreInfos = waits.data();
  si.signalSemaphoreInfoCount = signal ? 1 : 0;
  si.pSignalSemaphoreInfos = &signalInfo;
  VkResult r = vkQueueSubmit2(queue_, 1, &si, f.fence);
  if (r != VK_SUCCESS) dev_->Log(LogLevel::Error, "vkQueueSubmit2 failed (VkResult %d)", r);
  f.submitted = r == VK_SUCCESS;
  ++dev_->stats.FramesSubmitted;
  {
    std::lock_guard<std::mutex> lock(garbageMutex_);
    ++serial_;
    slot_ = static_cast<uint32_t>(serial_ % frames_.size());
  }
  BeginFrame();
}

uint64_t FrameQueue::CompletedSerial() {
  for (auto& f : frames_)
    if (f.submitted && f.serial > completed_ && vkGetFenceStatus(dev_->vk(), f.fence) == VK_SUCCESS)
      NoteCompleted(f.serial);
  return completed_;
}

void FrameQueue::WaitForSerial(uint64_t serial) {
  if (serial <= completed_) return;
  if (serial >= serial_) {
    dev_->Log(LogLevel::Error, "internal: waiting for frame %llu that was not submitted",
              static_cast<unsigned long long>(serial));
    return;
  }
  Frame& f = frames_[serial % frames_.size()];
  if (f.serial == serial && f.submitted) vkWaitForFences(dev_->vk(), 1, &f.fence, VK_TRUE, UINT64_MAX);
  NoteCompleted(serial);  // else its slot was already recycled
}

size_t FrameQueue::PendingGarbage() const {
  std::lock_guard<std::mutex> lock(garbageMutex_);
  size_t n = 0;
  for (auto& f : frames_) n += f.garbage.size();
  return n;
}

bool FrameQueue::AllocateRingSlow(VkDeviceSize size, VkDeviceSize align, RingAlloc* out) {
  auto& ring = frames_[slot_].ring;
  uint64_t before = ring.bytesAllocated;
  bool ok = ring.Allocate(size, align, out);
  dev_->stats.RingBytesAllocated += ring.bytesAllocated - before;
  return ok;
}

}  // namespace d3dl::impl
