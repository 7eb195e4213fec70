// CPU unit tests of the table that holds a context's references to its bound
// objects (Pins.h): one reference per object however often it is pinned,
// releases only of the objects not kept, each exactly once, and the rest
// released when the table goes.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "Pins.h"

namespace {

using d3dl::impl::PinTable;

void ReleaseIt(const PinTable::Entry& e) { e.release(e.object); }

struct Counted {
  unsigned refs = 1;  // the application's
  unsigned AddRef() { return ++refs; }
  unsigned Release() { return --refs; }
};

TEST(PinTable, AnObjectPinnedTwiceIsReferencedOnce) {
  Counted a, b;
  PinTable t;
  EXPECT_TRUE(t.Pin(&a));
  EXPECT_FALSE(t.Pin(&a));
  EXPECT_TRUE(t.Pin(&b));
  EXPECT_EQ(a.refs, 2u);
  EXPECT_EQ(b.refs, 2u);
  EXPECT_EQ(t.size(), 2u);
}

TEST(PinTable, OnlyTheObjectsNotKeptAreReleased) {
  Counted a, b, c;
  PinTable t;
  t.Pin(&a);
  t.Pin(&b);
  t.Pin(&c);
  t.DropUnless([&](const void* p) { return p == &b; }, ReleaseIt);
  EXPECT_EQ(a.refs, 1u);
  EXPECT_EQ(b.refs, 2u);
  EXPECT_EQ(c.refs, 1u);
  EXPECT_TRUE(t.Pinned(&b));
  EXPECT_FALSE(t.Pinned(&a));
  EXPECT_FALSE(t.Pin(&b)) << "still pinned after the compaction";
  EXPECT_TRUE(t.Pin(&a)) << "pinned anew, with a new reference";
  EXPECT_EQ(a.refs, 2u);
}

TEST(PinTable, ManyObjectsSurviveTheTablesGrowth) {
  std::vector<std::unique_ptr<Counted>> objects(5000);
  PinTable t;
  for (auto& o : objects) {
    o = std::make_unique<Counted>();
    EXPECT_TRUE(t.Pin(o.get()));
  }
  size_t found = 0, referencedOnce = 0;
  for (auto& o : objects) {
    found += t.Pinned(o.get()) && !t.Pin(o.get());
    referencedOnce += o->refs == 2;
  }
  EXPECT_EQ(found, objects.size());
  EXPECT_EQ(referencedOnce, objects.size());
  // Keep every other one.
  t.DropUnless(
      [&](const void* p) {
        for (size_t i = 0; i < objects.size(); i += 2)
          if (objects[i].get() == p) return true;
        return false;
      },
      ReleaseIt);
  EXPECT_EQ(t.size(), objects.size() / 2);
  for (size_t i = 0; i < objects.size(); ++i) {
    EXPECT_EQ(objects[i]->refs, i % 2 ? 1u : 2u) << i;
    EXPECT_EQ(t.Pinned(objects[i].get()), i % 2 == 0) << i;
  }
}

// A deferred context hands its dropped pins to its list: the references stay
// until the receiver releases them, each once.
TEST(PinTable, DroppedPinsAreHandedOnWithTheirReferences) {
  Counted a, b;
  PinTable t;
  t.Pin(&a);
  t.Pin(&b);
  std::vector<PinTable::Entry> list;
  t.DropAll([&](const PinTable::Entry& e) { list.push_back(e); });
  EXPECT_EQ(t.size(), 0u);
  EXPECT_EQ(a.refs, 2u);
  EXPECT_EQ(b.refs, 2u);
  ASSERT_EQ(list.size(), 2u);
  for (const auto& e : list) ReleaseIt(e);
  EXPECT_EQ(a.refs, 1u);
  EXPECT_EQ(b.refs, 1u);
}

TEST(PinTable, TheTableReleasesWhatItStillHoldsWhenItGoes) {
  Counted a, b;
  {
    PinTable t;
    t.Pin(&a);
    t.Pin(&b);
  }
  EXPECT_EQ(a.refs, 1u);
  EXPECT_EQ(b.refs, 1u);
}

}  // namespace
