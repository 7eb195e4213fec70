// CPU units of the barrier tracker (Sync.h, Barriers.cpp): what Transition
// decides for reads after a write, and that a read the state already covers
// stores nothing. The immediate context tracks every texture and vertex or
// index buffer a draw reads; recording threads read those objects' other
// fields at every draw, and a store, even of an unchanged value, takes the
// cache line from them. The state sits on a page of its own that the test
// makes read-only, so a store there ends the process.
#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <new>

#include "Sync.h"

namespace {

using d3dl::impl::BarrierInfo;
using d3dl::impl::SyncState;
using d3dl::impl::Transition;
namespace usage = d3dl::impl::usage;

class PageSync {
 public:
  PageSync() {
    page_ = size_t(sysconf(_SC_PAGESIZE));
    void* p = mmap(nullptr, page_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p != MAP_FAILED) memory_ = p;
    if (memory_) state_ = new (memory_) SyncState();
  }
  ~PageSync() {
    if (memory_) munmap(memory_, page_);
  }
  bool Ok() const { return state_ != nullptr; }
  SyncState& State() { return *state_; }
  bool ReadOnly(bool on) { return mprotect(memory_, page_, on ? PROT_READ : PROT_READ | PROT_WRITE) == 0; }

 private:
  size_t page_ = 0;
  void* memory_ = nullptr;
  SyncState* state_ = nullptr;
};

TEST(SyncState, AReadAfterAWriteWaitsOnceThenCoveredReadsStoreNothing) {
  PageSync page;
  ASSERT_TRUE(page.Ok());
  SyncState& s = page.State();
  BarrierInfo info;
  // Rendered to, then sampled: a layout change with a barrier.
  Transition(s, usage::ColorAttachment, &info);
  EXPECT_TRUE(Transition(s, usage::ShaderRead, &info));
  EXPECT_EQ(s.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  const SyncState before = s;
  ASSERT_TRUE(page.ReadOnly(true));
  // The same read again, many times (a texture sampled by every draw): no
  // barrier and no store (a store would fault on the read-only page).
  for (int i = 0; i < 100; ++i) EXPECT_FALSE(Transition(s, usage::ShaderRead, &info));
  ASSERT_TRUE(page.ReadOnly(false));
  EXPECT_EQ(s.readStages, before.readStages);
  EXPECT_EQ(s.visible, before.visible);
}

TEST(SyncState, AReadBySomeNewStageIsStillRecorded) {
  PageSync page;
  ASSERT_TRUE(page.Ok());
  SyncState& s = page.State();
  BarrierInfo info;
  Transition(s, usage::BufferCopyDst, &info);  // uploaded
  EXPECT_TRUE(Transition(s, usage::VertexRead, &info));
  ASSERT_TRUE(page.ReadOnly(true));
  EXPECT_FALSE(Transition(s, usage::VertexRead, &info));
  ASSERT_TRUE(page.ReadOnly(false));
  // A read from a stage the state has not seen since the write: a barrier
  // for it, and its stage joins the reads the next write must wait for.
  EXPECT_TRUE(Transition(s, usage::IndirectRead, &info));
  EXPECT_EQ(s.readStages & usage::IndirectRead.stages, usage::IndirectRead.stages);
  EXPECT_EQ(s.readStages & usage::VertexRead.stages, usage::VertexRead.stages);
  // The next write waits for both readers.
  EXPECT_TRUE(Transition(s, usage::BufferCopyDst, &info));
  EXPECT_EQ(info.srcStage & usage::IndirectRead.stages, usage::IndirectRead.stages);
  EXPECT_EQ(info.srcStage & usage::VertexRead.stages, usage::VertexRead.stages);
}

}  // namespace
