// Host memory for one VkCommandPool (VkAllocationCallbacks): a command
// list's, or one frame slot's of the immediate context.
//
// A driver that stores commands in host memory (lavapipe keeps one heap
// allocation per recorded command, a few for a descriptor-set bind) calls the
// pool's allocator for every command and frees it all at vkResetCommandPool.
// With the default allocator that is malloc/free per command, on two
// recording threads at once. This allocator keeps freed blocks in per-size
// free lists for the next recording into the same pool, so a recycled pool
// records into warm memory it already owns; memory goes back to the system
// only when the pool is destroyed.
//
// Not locked: Vulkan calls a pool's allocator only from the thread that calls
// a command on that pool or its buffers, and those are externally
// synchronized (one context records into one pool at a time).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace d3dl::impl {

class CommandMemory {
 public:
  CommandMemory();
  ~CommandMemory();
  CommandMemory(const CommandMemory&) = delete;
  CommandMemory& operator=(const CommandMemory&) = delete;

  const VkAllocationCallbacks* callbacks() const { return &callbacks_; }

  void* Allocate(size_t size, size_t alignment);
  void* Reallocate(void* p, size_t size, size_t alignment);
  void Free(void* p);

  // Counters for tests: blocks handed out in total, and how many of them
  // came from a free list rather than new memory.
  uint64_t allocations() const { return allocations_; }
  uint64_t reused() const { return reused_; }

 private:
  // Size classes of 16 bytes up to kMaxSmall; larger or more strictly
  // aligned blocks go to the system allocator.
  static constexpr size_t kGranule = 16;
  static constexpr size_t kMaxSmall = 1024;
  static constexpr size_t kClasses = kMaxSmall / kGranule;
  static constexpr size_t kChunkBytes = 64 * 1024;

  struct FreeBlock {
    FreeBlock* next;
  };
  void* AllocateSmall(size_t cls);
  void* AllocateLarge(size_t size, size_t alignment);

  VkAllocationCallbacks callbacks_{};
  FreeBlock* free_[kClasses] = {};
  std::vector<void*> chunks_;
  uint8_t* bump_ = nullptr;
  size_t bumpLeft_ = 0;
  uint64_t allocations_ = 0, reused_ = 0;
};

}  // namespace d3dl::impl
