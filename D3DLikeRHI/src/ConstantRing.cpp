// Per-frame linear allocator for constants, WRITE_DISCARD data, dynamic
// vertex/index data and upload staging: host-visible, persistently mapped
// chunks that grow on demand and are reused when the frame's fence signals.
#include "Device.h"

namespace d3dl::impl {
namespace {
constexpr VkDeviceSize kChunkSize = 4ull << 20;
constexpr VkBufferUsageFlags kRingUsage =
    VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
    VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
}  // namespace

bool ConstantRing::NewChunk(VkDeviceSize minSize) {
  Chunk c;
  c.size = std::max(kChunkSize, minSize);
  VkDeviceMemory mem;
  if (!dev_->CreateBufferRaw(c.size, kRingUsage, true, &c.buffer, &mem, &c.ptr)) return false;
  c.memory = mem;
  bytesAllocated += c.size;
  chunks_.push_back(c);
  return true;
}

bool ConstantRing::Allocate(VkDeviceSize size, VkDeviceSize align, RingAlloc* out) {
  if (size == 0) size = 4;
  for (;;) {
    if (current_ < chunks_.size()) {
      Chunk& c = chunks_[current_];
      VkDeviceSize off = (offset_ + align - 1) / align * align;
      if (off + size <= c.size) {
        out->buffer = c.buffer;
        out->offset = off;
        out->ptr = c.ptr + off;
        offset_ = off + size;
        return true;
      }
      ++current_;
      offset_ = 0;
      continue;
    }
    // Reuse a later free chunk that fits, else make a new one.
    if (!NewChunk(size)) return false;
    current_ = chunks_.size() - 1;
    offset_ = 0;
  }
}

void ConstantRing::Reset() {
  // Oversized chunks (large uploads) are released; standard chunks are kept.
  std::vector<Chunk> keep;
  for (auto& c : chunks_) {
    if (c.size > kChunkSize || keep.size() >= 4) {
      dev_->DestroyNow({VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(c.buffer)});
      dev_->DestroyNow({VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(c.memory)});
    } else {
      keep.push_back(c);
    }
  }
  chunks_ = std::move(keep);
  current_ = 0;
  offset_ = 0;
}

void ConstantRing::DeferDestroy() {
  for (auto& c : chunks_) {
    dev_->Defer(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(c.buffer));
    dev_->Defer(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(c.memory));
  }
  chunks_.clear();
}

void ConstantRing::Destroy() {
  for (auto& c : chunks_) {
    dev_->DestroyNow({VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(c.buffer)});
    dev_->DestroyNow({VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(c.memory)});
  }
  chunks_.clear();
}

}  // namespace d3dl::impl
