// The context's side of a frame: one command buffer per queue frame slot,
// descriptor pools and a timestamp pool per slot, and the end of a frame
// (SubmitFrame), after which the queue recycles the next slot.
#include "Context.h"

namespace d3dl::impl {
namespace {
constexpr uint32_t kTimestampsPerFrame = 1024;
constexpr uint32_t kSetsPerPool = 512;
}  // namespace

ContextImpl::ContextImpl(DeviceImpl* dev) : dev_(dev) { CreateDefaultStates(); }

ContextImpl::~ContextImpl() {
  if (activeStatistics_) activeStatistics_->Release();
  SaveDiscardedConstants();
  ClearState();
  defaults_ = {};
  DestroyCommandFrames();
}

void ContextImpl::CreateCommandFrames() {
  const VkDevice d = dev_->vk();
  frames_.resize(dev_->queue().FrameCount());
  for (auto& f : frames_) {
    f.memory = std::make_unique<CommandMemory>();
    dev_->CreateCommandBuffer(&f.pool, &f.cmd, f.memory->callbacks());
    f.memory->StartRecordings();
    VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qci.queryCount = kTimestampsPerFrame;
    vkCreateQueryPool(d, &qci, nullptr, &f.queryPool);
    vkResetQueryPool(d, f.queryPool, 0, kTimestampsPerFrame);
  }
}

// The device is idle (DeviceImpl::Release waits for it before this).
void ContextImpl::DestroyCommandFrames() {
  const VkDevice d = dev_->vk();
  for (auto& f : frames_) {
    for (QueryImpl* q : f.queries) q->Release();
    for (auto p : f.descPools) vkDestroyDescriptorPool(d, p, nullptr);
    if (f.queryPool) vkDestroyQueryPool(d, f.queryPool, nullptr);
    if (f.pool) vkDestroyCommandPool(d, f.pool, f.memory ? f.memory->callbacks() : nullptr);
  }
  frames_.clear();
}

// The queue has waited for the fence of the frame that used this slot.
void ContextImpl::RecycleCommandFrame(CommandFrame& f) {
  const VkDevice d = dev_->vk();
  // Timestamps of that frame: read them before the pool is reset.
  for (QueryImpl* q : f.queries) {
    if (q->serial == f.serial && q->pool == f.queryPool && !q->resolved) {
      uint64_t v = 0;
      if (vkGetQueryPoolResults(d, f.queryPool, q->index, 1, sizeof(v), &v, sizeof(v),
                                VK_QUERY_RESULT_64_BIT) == VK_SUCCESS) {
        q->value = v;
        q->resolved = true;
      }
    }
    q->Release();
  }
  f.queries.clear();
  if (f.queriesUsed) vkResetQueryPool(d, f.queryPool, 0, f.queriesUsed);
  f.queriesUsed = 0;
  for (auto p : f.descPools) vkResetDescriptorPool(d, p, 0);
  f.descPoolCurrent = 0;
  vkResetCommandPool(d, f.pool, 0);
  dev_->CountCommandPoolReset(f.memory->Rewind());
}

void ContextImpl::BeginCommandFrame() {
  CommandFrame& f = frames_[dev_->queue().Slot()];
  RecycleCommandFrame(f);
  f.serial = dev_->CurrentSerial();
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(f.cmd, &bi);
  cmd_ = f.cmd;
  rendering_ = false;
  MarkDirtyAll();
  labelDepth_ = 0;
}

void ContextImpl::EndCommandFrame(TextureCore* present) {
  EndRendering();
  CutStatisticsAtFrameEnd();
  if (present) UseTexture(present, SubresourceRange{}, usage::Present);
  FlushBarriers();
  SaveDiscardedConstants();  // their ring slices die with this frame
  // Everything written this frame becomes visible to the host (Map READ).
  VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  mb.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  mb.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
  mb.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  mb.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  VkDependencyInfo di{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  di.memoryBarrierCount = 1;
  di.pMemoryBarriers = &mb;
  vkCmdPipelineBarrier2(cmd_, &di);
  vkEndCommandBuffer(cmd_);
}

void ContextImpl::SubmitFrame(TextureCore* present, VkSemaphore signal) {
  EndCommandFrame(present);
  dev_->queue().Submit(cmd_, signal);
  BeginCommandFrame();
  CompactPins();  // objects unbound this frame are released, as D3D11 would have at the unbind
}

void ContextImpl::Flush() { SubmitFrame(); }

VkDescriptorSet ContextImpl::AllocateSet(VkDescriptorSetLayout layout) {
  const DescriptorPools from = SetPools();
  std::vector<VkDescriptorPool>& pools = from.pools;
  size_t& current = from.current;
  for (;;) {
    if (current >= pools.size()) {
      VkDescriptorPoolSize sizes[] = {
          {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, kSetsPerPool * 8},
          {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kSetsPerPool * 16},
          {VK_DESCRIPTOR_TYPE_SAMPLER, kSetsPerPool * 8},
          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kSetsPerPool * 4},  // buffer SRVs and UAVs
          {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kSetsPerPool * 2},
      };
      VkDescriptorPoolCreateInfo ci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
      ci.maxSets = kSetsPerPool;
      ci.poolSizeCount = static_cast<uint32_t>(std::size(sizes));
      ci.pPoolSizes = sizes;
      VkDescriptorPool pool;
      if (vkCreateDescriptorPool(dev_->vk(), &ci, nullptr, &pool) != VK_SUCCESS) return VK_NULL_HANDLE;
      pools.push_back(pool);
    }
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pools[current];
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkResult r = vkAllocateDescriptorSets(dev_->vk(), &ai, &set);
    if (r == VK_SUCCESS) {
      if (from.countStats) ++dev_->stats.DescriptorSetsAllocated;
      return set;
    }
    if (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL) return VK_NULL_HANDLE;
    ++current;
  }
}

bool ContextImpl::AllocateTimestamp(QueryImpl* q, uint32_t* index) {
  CommandFrame& f = frames_[dev_->queue().Slot()];
  if (f.queriesUsed >= kTimestampsPerFrame) return false;
  *index = f.queriesUsed++;
  q->AddRef();
  f.queries.push_back(q);
  q->pool = f.queryPool;
  return true;
}

}  // namespace d3dl::impl
