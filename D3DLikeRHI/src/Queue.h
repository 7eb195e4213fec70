// The device queue and its frames (Queue.cpp): fences and serials, the ring,
// the upload command buffer submitted ahead of each frame, swap-chain acquire
// semaphores and the handles destroyed once a frame's fence has signalled.
// Contexts record their own command buffers and hand them to Submit.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <mutex>
#include <vector>

#include "CommandMemory.h"
#include "Ring.h"

namespace d3dl::impl {

struct Garbage {
  VkObjectType type;
  uint64_t handle;
  CommandMemory* memory = nullptr;  // a command pool's allocator, deleted after the pool
};

class FrameQueue {
 public:
  // Creates the per-frame objects and begins the first frame.
  void Init(DeviceImpl* dev, VkQueue queue, uint32_t frames);
  void Destroy();
  bool Ready() const { return !frames_.empty(); }

  VkQueue vk() const { return queue_; }
  uint32_t FrameCount() const { return static_cast<uint32_t>(frames_.size()); }
  uint32_t Slot() const { return slot_; }
  uint64_t CurrentSerial() const { return serial_; }  // the frame being recorded

  // Per-frame resources of the frame being recorded.
  inline bool AllocateRing(VkDeviceSize size, VkDeviceSize align, RingAlloc* out);
  VkCommandBuffer UploadCmd();  // begun lazily, submitted before the frame's commands
  // Any thread (command lists and objects are released on worker threads too).
  void Defer(const Garbage& g) {
    std::lock_guard<std::mutex> lock(garbageMutex_);
    frames_[slot_].garbage.push_back(g);
  }
  size_t PendingGarbage() const;
  VkSemaphore AcquireSemaphore() const { return frames_[slot_].acquireSemaphore; }
  // Semaphores the next submission waits for (swap-chain acquires).
  void AddPendingWait(VkSemaphore s) { pendingWaits_.push_back(s); }

  // Submits [uploads, cmd] with the frame's fence (signalling `signal` when
  // given), then begins the next frame: its slot is recycled once the fence
  // of the frame that used it before has signalled.
  void Submit(VkCommandBuffer cmd, VkSemaphore signal);
  uint64_t CompletedSerial();  // polls fences
  // The last completed frame this queue has seen (fence waited or polled),
  // without polling: any thread (deferred contexts recycling their lists).
  uint64_t CompletedSerialSeen() const { return completed_.load(std::memory_order_acquire); }
  void WaitForSerial(uint64_t serial);

 private:
  struct Frame {
    VkFence fence = VK_NULL_HANDLE;
    uint64_t serial = 0;  // frame recorded in this slot
    bool submitted = false;
    std::vector<Garbage> garbage;
    ConstantRing ring;
    VkCommandPool uploadPool = VK_NULL_HANDLE;
    VkCommandBuffer uploadCmd = VK_NULL_HANDLE;
    bool uploadUsed = false;
    VkSemaphore acquireSemaphore = VK_NULL_HANDLE;
  };
  void BeginFrame();
  void Recycle(Frame& f);
  uint32_t EndUploads(Frame& f, VkCommandBufferSubmitInfo* out);
  bool AllocateRingSlow(VkDeviceSize size, VkDeviceSize align, RingAlloc* out);

  DeviceImpl* dev_ = nullptr;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::vector<Frame> frames_;
  uint32_t slot_ = 0;
  uint64_t serial_ = 1;
  // Written by the immediate context's thread only (NoteCompleted).
  std::atomic<uint64_t> completed_{0};
  void NoteCompleted(uint64_t serial) {
    if (serial > completed_.load(std::memory_order_relaxed)) completed_.store(serial, std::memory_order_release);
  }
  std::vector<VkSemaphore> pendingWaits_;
  // Guards the frames' garbage lists and slot_ against Defer from other threads.
  mutable std::mutex garbageMutex_;
};

inline bool FrameQueue::AllocateRing(VkDeviceSize size, VkDeviceSize align, RingAlloc* out) {
  if (frames_[slot_].ring.TryAllocate(size, align, out)) return true;
  return AllocateRingSlow(size, align, out);  // a new chunk: keeps the stats
}

}  // namespace d3dl::impl
