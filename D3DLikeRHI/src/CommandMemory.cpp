// CommandMemory.h: small blocks carved in order from 64 KiB chunks, rewound
// when a pool reset has freed every recording block.
#include "CommandMemory.h"

#include <cstdlib>
#include <cstring>

namespace d3dl::impl {
namespace {

// In front of every block: its usable size, and who owns it: a small block
// carved before or after StartRecordings, or for a block from the system
// allocator the pointer to free.
struct Header {
  size_t capacity;
  uintptr_t owner;
};
static_assert(sizeof(Header) == 16, "the header keeps 16-byte alignment");
constexpr uintptr_t kSmallBlock = 0;           // carved before StartRecordings
constexpr uintptr_t kSmallRecordingBlock = 1;  // carved or reused after it
// Any other owner is the system allocation's address (malloc's, never 0 or 1).

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
  Header* h = nullptr;
  if (FreeBlock* b = free_[cls]) {
    free_[cls] = b->next;
    ++reused_;
    h = HeaderOf(b);
  } else {
    const size_t capacity = (cls + 1) * kGranule;
    const size_t bytes = sizeof(Header) + capacity;
    // The tail of a chunk too short for this block is left unused.
    if (kChunkBytes - at_.used < bytes && !NextChunk()) return nullptr;
    h = reinterpret_cast<Header*>(static_cast<uint8_t*>(chunks_[at_.chunk - 1]) + at_.used);
    at_.used += bytes;
    h->capacity = capacity;
  }
  h->owner = recording_ ? kSmallRecordingBlock : kSmallBlock;
  if (recording_) ++liveRecordingBlocks_;
  return h + 1;
}

// Moves the bump allocator to the next chunk: one kept from before the last
// rewind, or a new one.
bool CommandMemory::NextChunk() {
  if (at_.chunk == chunks_.size()) {
    void* chunk = std::malloc(kChunkBytes);  // malloc's 16-byte alignment
    if (!chunk) return false;
    chunks_.push_back(chunk);
  }
  ++at_.chunk;
  at_.used = 0;
  return true;
}

void CommandMemory::StartRecordings() {
  recording_ = true;
  recordingsStart_ = at_;
  liveRecordingBlocks_ = 0;
}

bool CommandMemory::Rewind() {
  if (!recording_ || liveRecordingBlocks_ != 0) return false;
  at_ = recordingsStart_;
  // Every block in the lists lies in memory the bump allocator hands out
  // again, or is one of the pool's own freed blocks (kept until destruction).
  for (FreeBlock*& head : free_) head = nullptr;
  ++rewinds_;
  return true;
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
  h->owner = reinterpret_cast<uintptr_t>(system);
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
  if (h->owner != kSmallBlock && h->owner != kSmallRecordingBlock) {
    std::free(reinterpret_cast<void*>(h->owner));
    return;
  }
  if (h->owner == kSmallRecordingBlock) --liveRecordingBlocks_;
  FreeBlock* b = static_cast<FreeBlock*>(p);
  const size_t cls = h->capacity / kGranule - 1;
  b->next = free_[cls];
  free_[cls] = b;
}

}  // namespace d3dl::impl
