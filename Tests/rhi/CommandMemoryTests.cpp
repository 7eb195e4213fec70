// CPU unit tests of the backend's command-pool allocator (CommandMemory.h):
// the VkAllocationCallbacks contract (alignment, reallocation keeping the
// contents, size 0 and null pointers) and the reuse of freed blocks.
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
