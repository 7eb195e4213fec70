// CommandMemory.h: per-size free lists carved from 64 KiB chunks.
#include "CommandMemory.h"

#include <cstdlib>
#include <cstring>

namespace d3dl::impl {
namespace {

// In front of every block: its usable size, and for a block from the system
// allocator the pointer to free (null for a small block).
struct Header {
  size_t capacity;
  void* system;
};
static_assert(sizeof(Header) == 16, "the header keeps 16-byte alignment");

Header* HeaderOf(void* p) { return static_cast<Header*>(p) - 1; }

VKAPI_ATTR void* VKAPI_CALL AllocateCb(void* user, size_t size, size_t alignment, VkSystemAllocationScope) {
  return static_cast<CommandMemory*>(user)->Allocate(size, alignment);
}
VKAPI_ATTR void* VKAPI_CALL ReallocateCb(void* user, void* p, size_t size, size_t alignment,
                                         VkSystemAllocationScope) {
  return static_cast<CommandMemory*>(user)->Reallocate(p, size, alignment);
}
VKAPI_ATTR void VKAPI_CALL FreeCb(void* user, void* p) { static_cast<CommandMemory*>(user)->Free(p); }

}  // namespace

CommandMemory::CommandMemory() {
  callbacks_.pUserData = this;
  callbacks_.pfnAllocation = AllocateCb;
  callbacks_.pfnReallocation = ReallocateCb;
  callbacks_.pfnFree = FreeCb;
}

CommandMemory::~CommandMemory() {
  for (void* c : chunks_) std::free(c);
}

void* CommandMemory::Allocate(size_t size, size_t alignment) {
  if (size == 0) return nullptr;
  ++allocations_;
  if (size <= kMaxSmall && alignment <= kGranule) return AllocateSmall((size - 1) / kGranule);
  return AllocateLarge(size, alignment);
}

void* CommandMemory::AllocateSmall(size_t cls) {
  if (FreeBlock* b = free_[cls]) {
    free_[cls] = b->next;
    ++reused_;
    return b;
  }
  const size_t capacity = (cls + 1) * kGranule;
  const size_t bytes = sizeof(Header) + capacity;
  if (bumpLeft_ < bytes) {
    void* chunk = std::malloc(kChunkBytes);  // malloc's 16-byte alignment
    if (!chunk) return nullptr;
    chunks_.push_back(chunk);
    bump_ = static_cast<uint8_t*>(chunk);
    bumpLeft_ = kChunkBytes;  // the tail of the previous chunk is left unused
  }
  Header* h = reinterpret_cast<Header*>(bump_);
  bump_ += bytes;
  bumpLeft_ -= bytes;
  h->capacity = capacity;
  h->system = nullptr;
  return h + 1;
}

void* CommandMemory::AllocateLarge(size_t size, size_t alignment) {
  if (alignment < kGranule) alignment = kGranule;
  if (size > SIZE_MAX - alignment - sizeof(Header)) return nullptr;
  void* system = std::malloc(size + alignment + sizeof(Header));
  if (!system) return nullptr;
  uintptr_t user = reinterpret_cast<uintptr_t>(system) + sizeof(Header);
  user = (user + alignment - 1) & ~uintptr_t(alignment - 1);
  Header* h = HeaderOf(reinterpret_cast<void*>(user));
  h->capacity = size;
  h->system = system;
  return h + 1;
}

void* CommandMemory::Reallocate(void* p, size_t size, size_t alignment) {
  if (!p) return Allocate(size, alignment);
  if (size == 0) {
    Free(p);
    return nullptr;
  }
  const Header* h = HeaderOf(p);
  const bool aligned = (reinterpret_cast<uintptr_t>(p) & (alignment - 1)) == 0;
  if (size <= h->capacity && aligned) return p;
  void* q = Allocate(size, alignment);
  if (!q) return nullptr;  // p stays valid, as the callback's contract says
  std::memcpy(q, p, h->capacity < size ? h->capacity : size);
  Free(p);
  return q;
}

void CommandMemory::Free(void* p) {
  if (!p) return;
  Header* h = HeaderOf(p);
  if (h->system) {
    std::free(h->system);
    return;
  }
  FreeBlock* b = static_cast<FreeBlock*>(p);
  const size_t cls = h->capacity / kGranule - 1;
  b->next = free_[cls];
  free_[cls] = b;
}

}  // namespace d3dl::impl
