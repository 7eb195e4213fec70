// Reuse of command-list recordings (CommandList.h): a deferred context takes
// a parked recording whose last execution has completed, resets its command
// pool, descriptor pools and ring on its own thread, and records into it.
// A new recording (Vulkan objects, ring chunk) is made only when none is free.
#include "Context.h"

namespace d3dl::impl {
namespace {
// Parked recordings per context: enough for the frames in flight times a few
// lists per frame; more are destroyed rather than kept.
constexpr size_t kMaxParked = 8;
}  // namespace

ListRecycler::~ListRecycler() {
  for (Parked& p : parked_) DestroyRecording(dev_, *p.rec);
}

void ListRecycler::Close() {
  std::vector<Parked> parked;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    parked.swap(parked_);
  }
  for (Parked& p : parked) DestroyRecording(dev_, *p.rec);
}

std::unique_ptr<ListRecording> ListRecycler::Take() {
  const uint64_t completed = dev_->queue().CompletedSerialSeen();
  std::unique_ptr<ListRecording> rec;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t i = 0; i < parked_.size(); ++i) {
      if (parked_[i].lastExecuted > completed) continue;
      rec = std::move(parked_[i].rec);
      parked_[i] = std::move(parked_.back());
      parked_.pop_back();
      break;
    }
  }
  if (!rec) return Create();
  Reset(*rec);
  return rec;
}

void ListRecycler::Give(std::unique_ptr<ListRecording> rec, uint64_t lastExecuted) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!closed_ && parked_.size() < kMaxParked) {
      parked_.push_back({std::move(rec), lastExecuted});
      return;
    }
  }
  DestroyRecording(dev_, *rec);
}

std::unique_ptr<ListRecording> ListRecycler::Create() {
  auto rec = std::make_unique<ListRecording>();
  rec->ring.Init(dev_);
  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.queueFamilyIndex = dev_->queueFamily();
  rec->memory = std::make_unique<CommandMemory>();
  vkCreateCommandPool(dev_->vk(), &pci, rec->memory->callbacks(), &rec->pool);
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = rec->pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_SECONDARY;
  ai.commandBufferCount = 1;
  vkAllocateCommandBuffers(dev_->vk(), &ai, &rec->cmd);
  rec->memory->StartRecordings();
  return rec;
}

// The GPU is done with it: its pools and ring start over; the containers are
// emptied but keep their capacity.
void ListRecycler::Reset(ListRecording& rec) {
  vkResetCommandPool(dev_->vk(), rec.pool, 0);  // the secondary buffer returns to the initial state
  dev_->CountCommandPoolReset(rec.memory->Rewind());
  for (VkDescriptorPool p : rec.descPools) vkResetDescriptorPool(dev_->vk(), p, 0);
  rec.descPoolCurrent = 0;
  rec.ring.Reset();
  rec.syncs.clear();
  rec.syncIndex.clear();
  rec.slices.clear();
  rec.imports.clear();
  rec.uses.clear();
  rec.retained.Clear();
  rec.held.clear();
  rec.draws = 0;
  ++rec.readEpoch;
  rec.lastBuffer = nullptr;
  rec.lastEntry = nullptr;
}

}  // namespace d3dl::impl
