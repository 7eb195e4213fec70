// CPU unit tests of the set of objects a deferred context's list holds a
// reference to (CommandList.h): each object once, also when two objects share
// a slot of the recent-object table, and nothing left over after Clear.
#include <gtest/gtest.h>

#include <cstdint>

#include "CommandList.h"

namespace {

using d3dl::impl::RetainedSet;

const void* Object(uintptr_t address) { return reinterpret_cast<const void*>(address); }

TEST(RetainedSet, EachObjectIsNewOnce) {
  RetainedSet s;
  EXPECT_TRUE(s.Insert(Object(0x1000)));
  EXPECT_FALSE(s.Insert(Object(0x1000)));
  EXPECT_TRUE(s.Insert(Object(0x2010)));
  EXPECT_FALSE(s.Insert(Object(0x1000)));
  EXPECT_FALSE(s.Insert(Object(0x2010)));
}

TEST(RetainedSet, ObjectsSharingARecentSlotAreEachNewOnce) {
  RetainedSet s;
  // 4096 bytes apart: the same slot of the 256-entry table (address >> 4).
  const void* a = Object(0x10000);
  const void* b = Object(0x11000);
  EXPECT_TRUE(s.Insert(a));
  EXPECT_TRUE(s.Insert(b));  // evicts a from the slot
  EXPECT_FALSE(s.Insert(a)) << "found in the set behind the table";
  EXPECT_FALSE(s.Insert(b));
}

TEST(RetainedSet, ClearForgetsTheTableToo) {
  RetainedSet s;
  EXPECT_TRUE(s.Insert(Object(0x3000)));
  s.Clear();
  EXPECT_TRUE(s.Insert(Object(0x3000))) << "the next list must take its own reference";
}

}  // namespace
