// CPU unit tests of the backend's command-pool allocator (CommandMemory.h):
// the VkAllocationCallbacks contract (alignment, reallocation keeping the
// contents, size 0 and null pointers), the reuse of freed blocks, and the
// rewind that starts a recording again at the beginning of its chunks.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "CommandMemory.h"

namespace {

using d3dl::impl::CommandMemory;

bool AlignedTo(const void* p, size_t alignment) { return reinterpret_cast<uintptr_t>(p) % alignment == 0; }

TEST(CommandMemory, BlocksHonourTheRequestedAlignment) {
  CommandMemory m;
  const VkAllocationCallbacks* cb = m.callbacks();
  for (size_t alignment : {1u, 4u, 8u, 16u, 32u, 64u, 256u, 4096u}) {
    for (size_t size : {1u, 24u, 100u, 1024u, 1025u, 70000u}) {
      void* p = cb->pfnAllocation(cb->pUserData, size, alignment, VK_SYSTEM_ALLOCATION_SCOPE_OBJECT);
      ASSERT_NE(p, nullptr) << size << " bytes aligned to " << alignment;
      EXPECT_TRUE(AlignedTo(p, alignment)) << size << " bytes aligned to " << alignment;
      std::memset(p, 0xAB, size);  // the whole block is writable (ASan checks the bounds)
      cb->pfnFree(cb->pUserData, p);
    }
  }
}

TEST(CommandMemory, FreedBlocksServeTheNextRecording) {
  CommandMemory m;
  // One "recording": commands of a few sizes, then all freed (the pool's reset).
  auto record = [&] {
    std::vector<void*> blocks;
    for (int i = 0; i < 1000; ++i) blocks.push_back(m.Allocate(16 + size_t(i % 5) * 40, 8));
    for (void* p : blocks) m.Free(p);
  };
  record();
  EXPECT_EQ(m.allocations(), 1000u);
  EXPECT_EQ(m.reused(), 0u);
  record();
  EXPECT_EQ(m.allocations(), 2000u);
  EXPECT_EQ(m.reused(), 1000u) << "the second recording takes every block from the free lists";
}

// A pool's life as a driver that frees every command at reset lives it: its
// own objects first, then recordings, each freed entirely by a reset.
TEST(CommandMemory, RewoundRecordingsReuseTheSameAddressesInOrder) {
  CommandMemory m;
  void* poolObject = m.Allocate(200, 8);  // the command buffer's own state
  std::memset(poolObject, 0, 200);
  m.StartRecordings();
  auto record = [&] {
    std::vector<void*> blocks;
    for (int i = 0; i < 3000; ++i) blocks.push_back(m.Allocate(16 + size_t(i % 7) * 24, 8));  // > one chunk
    return blocks;
  };
  const std::vector<void*> first = record();
  for (size_t i = 1; i < first.size(); ++i) ASSERT_NE(first[i], first[i - 1]);
  for (void* p : first) m.Free(p);
  EXPECT_TRUE(m.Rewind());
  const std::vector<void*> second = record();
  EXPECT_EQ(second, first) << "the same blocks in the same order: a linear arena";
  for (void* p : second) std::memset(p, 0xCD, 16);
  EXPECT_NE(*static_cast<uint8_t*>(poolObject), 0xCD) << "the pool's own block is not handed out";
  for (void* p : second) m.Free(p);
  EXPECT_TRUE(m.Rewind());
  EXPECT_EQ(m.rewinds(), 2u);
  m.Free(poolObject);
}

TEST(CommandMemory, ABlockAliveAfterTheResetStopsTheRewind) {
  CommandMemory m;
  m.StartRecordings();
  void* kept = m.Allocate(64, 8);
  std::memset(kept, 0x5A, 64);
  std::vector<void*> blocks;
  for (int i = 0; i < 100; ++i) blocks.push_back(m.Allocate(64, 8));
  for (void* p : blocks) m.Free(p);
  EXPECT_FALSE(m.Rewind()) << "one recording block is still alive";
  // The next recording takes the freed blocks, never the live one.
  for (int i = 0; i < 200; ++i) {
    void* p = m.Allocate(64, 8);
    ASSERT_NE(p, kept);
    std::memset(p, 0, 64);
  }
  for (int i = 0; i < 64; ++i) ASSERT_EQ(static_cast<uint8_t*>(kept)[i], 0x5A) << "byte " << i;
  EXPECT_EQ(m.rewinds(), 0u);
  m.Free(kept);
}

TEST(CommandMemory, NoRewindBeforeRecordingsStart) {
  CommandMemory m;
  void* p = m.Allocate(32, 8);
  m.Free(p);
  EXPECT_FALSE(m.Rewind());
}

TEST(CommandMemory, ReallocationKeepsTheContents) {
  CommandMemory m;
  const VkAllocationCallbacks* cb = m.callbacks();
  auto* p = static_cast<uint8_t*>(cb->pfnAllocation(cb->pUserData, 40, 8, VK_SYSTEM_ALLOCATION_SCOPE_COMMAND));
  ASSERT_NE(p, nullptr);
  for (int i = 0; i < 40; ++i) p[i] = uint8_t(i);
  // Grown past the small classes, then shrunk: the common prefix survives.
  auto* q = static_cast<uint8_t*>(cb->pfnReallocation(cb->pUserData, p, 5000, 64, VK_SYSTEM_ALLOCATION_SCOPE_COMMAND));
  ASSERT_NE(q, nullptr);
  EXPECT_TRUE(AlignedTo(q, 64));
  for (int i = 0; i < 40; ++i) ASSERT_EQ(q[i], uint8_t(i)) << "byte " << i;
  auto* r = static_cast<uint8_t*>(cb->pfnReallocation(cb->pUserData, q, 20, 8, VK_SYSTEM_ALLOCATION_SCOPE_COMMAND));
  ASSERT_NE(r, nullptr);
  for (int i = 0; i < 20; ++i) ASSERT_EQ(r[i], uint8_t(i)) << "byte " << i;
  // Size 0 frees and returns null; a null pointer allocates.
  EXPECT_EQ(cb->pfnReallocation(cb->pUserData, r, 0, 8, VK_SYSTEM_ALLOCATION_SCOPE_COMMAND), nullptr);
  void* s = cb->pfnReallocation(cb->pUserData, nullptr, 12, 4, VK_SYSTEM_ALLOCATION_SCOPE_COMMAND);
  EXPECT_NE(s, nullptr);
  cb->pfnFree(cb->pUserData, s);
  cb->pfnFree(cb->pUserData, nullptr);  // allowed, does nothing
}

TEST(CommandMemory, ImpossibleSizesFailWithNull) {
  CommandMemory m;
  EXPECT_EQ(m.Allocate(0, 8), nullptr);
  EXPECT_EQ(m.Allocate(SIZE_MAX - 8, 16), nullptr);
}

}  // namespace
