// Per-frame linear allocator in host-visible, persistently mapped memory
// (ConstantRing.cpp): constants, WRITE_DISCARD data, dynamic vertex/index
// data and upload staging.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace d3dl::impl {

class DeviceImpl;

struct RingAlloc {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  uint8_t* ptr = nullptr;
};

class ConstantRing {
 public:
  struct Chunk {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    uint8_t* ptr = nullptr;
    VkDeviceSize size = 0;
  };
  void Init(DeviceImpl* dev) { dev_ = dev; }
  void Destroy();
  void Reset();  // the frame that used these chunks has completed
  void DeferDestroy();  // a command list's ring: destroyed after the current frame's fence
  bool Allocate(VkDeviceSize size, VkDeviceSize align, RingAlloc* out);
  // Hot path of Allocate (one per constant-buffer Map): succeeds only when the
  // current chunk has room. `align` is a power of two (all callers; Vulkan
  // guarantees it for minUniformBufferOffsetAlignment).
  bool TryAllocate(VkDeviceSize size, VkDeviceSize align, RingAlloc* out) {
    if (current_ >= chunks_.size() || size == 0) return false;
    const Chunk& c = chunks_[current_];
    const VkDeviceSize off = (offset_ + align - 1) & ~(align - 1);
    if (off + size > c.size) return false;
    out->buffer = c.buffer;
    out->offset = off;
    out->ptr = c.ptr + off;
    offset_ = off + size;
    return true;
  }
  uint64_t bytesAllocated = 0;

 private:
  bool NewChunk(VkDeviceSize minSize);
  DeviceImpl* dev_ = nullptr;
  std::vector<Chunk> chunks_;
  size_t current_ = 0;
  VkDeviceSize offset_ = 0;
};

}  // namespace d3dl::impl
