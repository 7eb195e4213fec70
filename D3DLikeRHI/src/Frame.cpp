// Frames: one command buffer (+ an upload command buffer submitted before it),
// a fence, a constant ring, descriptor pools, a timestamp pool and a list of
// handles to destroy once the frame's fence has signalled.
#include "Context.h"

namespace d3dl::impl {
namespace {
constexpr uint32_t kTimestampsPerFrame = 1024;
constexpr uint32_t kSetsPerPool = 512;
}  // namespace

void DeviceImpl::InitFrames() {
  for (auto& f : frames_) {
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pci.queueFamilyIndex = queueFamily_;
    vkCreateCommandPool(device_, &pci, nullptr, &f.pool);
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = f.pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    vkAllocateCommandBuffers(device_, &ai, &f.cmd);
    vkAllocateCommandBuffers(device_, &ai, &f.uploadCmd);
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    vkCreateFence(device_, &fci, nullptr, &f.fence);
    VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qci.queryCount = kTimestampsPerFrame;
    vkCreateQueryPool(device_, &qci, nullptr, &f.queryPool);
    vkResetQueryPool(device_, f.queryPool, 0, kTimestampsPerFrame);
    VkSemaphoreCreateInfo sci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    vkCreateSemaphore(device_, &sci, nullptr, &f.acquireSemaphore);
    f.ring.Init(this);
  }
  slot_ = static_cast<uint32_t>(serial_ % frames_.size());
  BeginFrame();
}

void DeviceImpl::DestroyFrames() {
  for (auto& f : frames_) {
    for (QueryImpl* q : f.queries) q->Release();
    f.queries.clear();
    for (auto& g : f.garbage) DestroyNow(g);
    f.garbage.clear();
    f.ring.Destroy();
    for (auto p : f.descPools) vkDestroyDescriptorPool(device_, p, nullptr);
    f.descPools.clear();
    if (f.queryPool) vkDestroyQueryPool(device_, f.queryPool, nullptr);
    if (f.fence) vkDestroyFence(device_, f.fence, nullptr);
    if (f.pool) vkDestroyCommandPool(device_, f.pool, nullptr);
    if (f.acquireSemaphore) vkDestroySemaphore(device_, f.acquireSemaphore, nullptr);
    f = FrameSlot{};
  }
  frames_.clear();
}

void DeviceImpl::RecycleSlot(FrameSlot& f) {
  if (f.submitted) {
    vkWaitForFences(device_, 1, &f.fence, VK_TRUE, UINT64_MAX);
    vkResetFences(device_, 1, &f.fence);
    completed_ = std::max(completed_, f.serial);
    f.submitted = false;
  }
  // Timestamps of this frame: read them before the pool is reset.
  for (QueryImpl* q : f.queries) {
    if (q->serial == f.serial && q->pool == f.queryPool && !q->resolved) {
      uint64_t v = 0;
      if (vkGetQueryPoolResults(device_, f.queryPool, q->index, 1, sizeof(v), &v, sizeof(v),
                                VK_QUERY_RESULT_64_BIT) == VK_SUCCESS) {
        q->value = v;
        q->resolved = true;
      }
    }
    q->Release();
  }
  f.queries.clear();
  if (f.queriesUsed) vkResetQueryPool(device_, f.queryPool, 0, f.queriesUsed);
  f.queriesUsed = 0;
  objectsDestroyed += f.garbage.size();
  for (auto& g : f.garbage) DestroyNow(g);
  f.garbage.clear();
  f.ring.Reset();
  for (auto p : f.descPools) vkResetDescriptorPool(device_, p, 0);
  f.descPoolCurrent = 0;
}

void DeviceImpl::BeginFrame() {
  FrameSlot& f = frames_[slot_];
  RecycleSlot(f);
  f.serial = serial_;
  vkResetCommandPool(device_, f.pool, 0);
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(f.cmd, &bi);
  f.uploadUsed = false;
  if (context_) context_->OnFrameBegin();
}

VkCommandBuffer DeviceImpl::UploadCmd() {
  FrameSlot& f = frames_[slot_];
  if (!f.uploadUsed) {
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(f.uploadCmd, &bi);
    f.uploadUsed = true;
  }
  return f.uploadCmd;
}

void DeviceImpl::SubmitFrame(const std::vector<VkSemaphore>& wait,
                             const std::vector<VkSemaphore>& signal) {
  FrameSlot& f = frames_[slot_];
  if (context_) {
    context_->EndRendering();
    context_->FlushBarriers();
    context_->SaveDiscardedConstants();  // their ring slices die with this frame
  }
  // Everything written this frame becomes visible to the host (Map READ).
  VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  mb.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  mb.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
  mb.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  mb.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  VkDependencyInfo di{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  di.memoryBarrierCount = 1;
  di.pMemoryBarriers = &mb;
  vkCmdPipelineBarrier2(f.cmd, &di);
  vkEndCommandBuffer(f.cmd);

  VkCommandBufferSubmitInfo cbs[2]{};
  uint32_t n = 0;
  if (f.uploadUsed) {
    // Uploads are ordered before every command of the frame.
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
    cbs[n].sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO;
    cbs[n++].commandBuffer = f.uploadCmd;
  }
  cbs[n].sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO;
  cbs[n++].commandBuffer = f.cmd;
  std::vector<VkSemaphore> waits = pendingWaits_;
  pendingWaits_.clear();
  waits.insert(waits.end(), wait.begin(), wait.end());
  std::vector<VkSemaphoreSubmitInfo> w(waits.size()), s(signal.size());
  for (size_t i = 0; i < waits.size(); ++i) {
    w[i] = {VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    w[i].semaphore = waits[i];
    w[i].stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  }
  for (size_t i = 0; i < signal.size(); ++i) {
    s[i] = {VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    s[i].semaphore = signal[i];
    s[i].stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  }
  VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  si.commandBufferInfoCount = n;
  si.pCommandBufferInfos = cbs;
  si.waitSemaphoreInfoCount = static_cast<uint32_t>(w.size());
  si.pWaitSemaphoreInfos = w.data();
  si.signalSemaphoreInfoCount = static_cast<uint32_t>(s.size());
  si.pSignalSemaphoreInfos = s.data();
  VkResult r = vkQueueSubmit2(queue_, 1, &si, f.fence);
  if (r != VK_SUCCESS) Log(LogLevel::Error, "vkQueueSubmit2 failed (VkResult %d)", r);
  f.submitted = r == VK_SUCCESS;
  ++stats.FramesSubmitted;
  ++serial_;
  slot_ = static_cast<uint32_t>(serial_ % frames_.size());
  BeginFrame();
}

uint64_t DeviceImpl::CompletedSerial() {
  for (auto& f : frames_)
    if (f.submitted && f.serial > completed_ && vkGetFenceStatus(device_, f.fence) == VK_SUCCESS)
      completed_ = std::max(completed_, f.serial);
  return completed_;
}

void DeviceImpl::WaitForSerial(uint64_t serial) {
  if (serial <= completed_) return;
  if (serial >= serial_) {
    Log(LogLevel::Error, "internal: waiting for frame %llu that was not submitted",
        static_cast<unsigned long long>(serial));
    return;
  }
  FrameSlot& f = frames_[serial % frames_.size()];
  if (f.serial == serial && f.submitted) {
    vkWaitForFences(device_, 1, &f.fence, VK_TRUE, UINT64_MAX);
    completed_ = std::max(completed_, serial);
  } else {
    completed_ = std::max(completed_, serial);  // its slot was already recycled
  }
}

void DeviceImpl::Defer(VkObjectType type, uint64_t handle) {
  if (!handle) return;
  if (orphaned_ || shuttingDown_ || frames_.empty()) {
    ++objectsDestroyed;
    DestroyNow({type, handle});
    return;
  }
  frames_[slot_].garbage.push_back({type, handle});
}

void DeviceImpl::DestroyNow(const Garbage& g) {
  switch (g.type) {
    case VK_OBJECT_TYPE_BUFFER:
      vkDestroyBuffer(device_, reinterpret_cast<VkBuffer>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_IMAGE:
      vkDestroyImage(device_, reinterpret_cast<VkImage>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_IMAGE_VIEW:
      vkDestroyImageView(device_, reinterpret_cast<VkImageView>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_DEVICE_MEMORY:
      vkFreeMemory(device_, reinterpret_cast<VkDeviceMemory>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_SAMPLER:
      vkDestroySampler(device_, reinterpret_cast<VkSampler>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_SHADER_MODULE:
      vkDestroyShaderModule(device_, reinterpret_cast<VkShaderModule>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_PIPELINE:
      vkDestroyPipeline(device_, reinterpret_cast<VkPipeline>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_PIPELINE_LAYOUT:
      vkDestroyPipelineLayout(device_, reinterpret_cast<VkPipelineLayout>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT:
      vkDestroyDescriptorSetLayout(device_, reinterpret_cast<VkDescriptorSetLayout>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_SEMAPHORE:
      vkDestroySemaphore(device_, reinterpret_cast<VkSemaphore>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_SWAPCHAIN_KHR:
      vkDestroySwapchainKHR(device_, reinterpret_cast<VkSwapchainKHR>(g.handle), nullptr);
      break;
    case VK_OBJECT_TYPE_SURFACE_KHR:
      vkDestroySurfaceKHR(instance_, reinterpret_cast<VkSurfaceKHR>(g.handle), nullptr);
      break;
    default:
      Log(LogLevel::Error, "internal: cannot destroy object type %d", g.type);
  }
}

bool DeviceImpl::AllocateRingSlow(VkDeviceSize size, VkDeviceSize align, RingAlloc* out) {
  auto& ring = frames_[slot_].ring;
  uint64_t before = ring.bytesAllocated;
  bool ok = ring.Allocate(size, align, out);
  stats.RingBytesAllocated += ring.bytesAllocated - before;
  return ok;
}

VkDescriptorSet DeviceImpl::AllocateSet(VkDescriptorSetLayout layout) {
  FrameSlot& f = frames_[slot_];
  for (;;) {
    if (f.descPoolCurrent >= f.descPools.size()) {
      VkDescriptorPoolSize sizes[] = {
          {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, kSetsPerPool * 8},
          {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kSetsPerPool * 16},
          {VK_DESCRIPTOR_TYPE_SAMPLER, kSetsPerPool * 8},
      };
      VkDescriptorPoolCreateInfo ci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
      ci.maxSets = kSetsPerPool;
      ci.poolSizeCount = 3;
      ci.pPoolSizes = sizes;
      VkDescriptorPool pool;
      if (vkCreateDescriptorPool(device_, &ci, nullptr, &pool) != VK_SUCCESS) return VK_NULL_HANDLE;
      f.descPools.push_back(pool);
    }
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = f.descPools[f.descPoolCurrent];
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkResult r = vkAllocateDescriptorSets(device_, &ai, &set);
    if (r == VK_SUCCESS) {
      ++stats.DescriptorSetsAllocated;
      return set;
    }
    if (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL) return VK_NULL_HANDLE;
    ++f.descPoolCurrent;
  }
}

bool DeviceImpl::AllocateTimestamp(QueryImpl* q, uint32_t* index) {
  FrameSlot& f = frames_[slot_];
  if (f.queriesUsed >= kTimestampsPerFrame) return false;
  *index = f.queriesUsed++;
  q->AddRef();
  f.queries.push_back(q);
  q->pool = f.queryPool;
  return true;
}

}  // namespace d3dl::impl
