// Host memory for one VkCommandPool (VkAllocationCallbacks): a command
// list's, or one frame slot's of the immediate context.
//
// A driver that stores commands in host memory (lavapipe keeps one heap
// allocation per recorded command, a few for a descriptor-set bind) calls the
// pool's allocator for every command and frees it all at vkResetCommandPool.
// With the default allocator that is malloc/free per command, on two
// recording threads at once. This allocator carves small blocks in order
// from 64 KiB chunks it keeps. When a reset has freed every block allocated
// since the pool's own objects were made (StartRecordings), Rewind() starts
// the next recording at the beginning of the same chunks: its commands land
// in consecutive addresses, as in a linear arena, instead of in the order of
// a free list (one dependent cache miss per command). A block still alive
// after a reset stops the rewind; freed blocks then serve later requests
// from per-size free lists. Memory goes back to the system only when the
// pool is destroyed.
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

  // Blocks allocated from here on belong to recordings; those before (the
  // pool's and its command buffers' own objects) are not expected back at a
  // reset. Call once, after the pool and its command buffers are made.
  void StartRecordings();
  // Call after vkResetCommandPool: when every recording block has been freed,
  // the next allocation starts again where StartRecordings left the chunks.
  // Returns whether it did.
  bool Rewind();

  // Counters for tests: blocks handed out in total, and how many of them
  // came from a free list rather than new memory.
  uint64_t allocations() const { return allocations_; }
  uint64_t reused() const { return reused_; }
  uint64_t rewinds() const { return rewinds_; }

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
  bool NextChunk();

  // Where the bump allocator stands: how many chunks it has entered (the
  // current one is chunks_[chunk - 1]) and the bytes used in the current one.
  struct Position {
    size_t chunk = 0;
    size_t used = kChunkBytes;  // no chunk yet: the first request takes one
  };

  VkAllocationCallbacks callbacks_{};
  FreeBlock* free_[kClasses] = {};
  std::vector<void*> chunks_;  // in bump order; kept for the next rewind
  Position at_, recordingsStart_;
  bool recording_ = false;       // StartRecordings was called
  uint64_t liveRecordingBlocks_ = 0;
  uint64_t allocations_ = 0, reused_ = 0, rewinds_ = 0;
};

}  // namespace d3dl::impl
