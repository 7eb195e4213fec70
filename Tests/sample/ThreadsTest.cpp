// Multithreaded scene recording (Docs/Threads.md), in process under core +
// synchronization validation: the Arena on 1 (the immediate context), 2 and
// 3 threads gives the same pixels, bit for bit, and the default (1 thread)
// the same as 4 on the Arena and the many-object Arena; the split is
// contiguous, even until the threads' speeds are known and then in
// proportion to them; the automatic mode adds threads only where each gets
// enough draws; the thread count follows the GUI at run time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <numeric>

#include "DynamicResolutionRendering.h"
#include "SampleTestKit.h"
#include "scene/RecordingThreads.h"
#include "scene/Scene.h"
#include "scene/SceneThreads.h"

using namespace drr;
using namespace drr::testkit;

namespace {

Options ArenaOptions(int threads) {
  Options o = HeadlessOptions(160, 90, 3.0);
  o.threads = threads;
  return o;
}

struct Frame {
  Image colour, velocity;
  SceneStats stats;
};

Frame RenderArena(const Options& o) {
  return RunFresh(o, 3, [](Sample& s, Image&& colour) {
    return Frame{std::move(colour), s.CapturedVelocity(), s.GetScene()->Stats()};
  });
}

bool SamePixels(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

// The per-thread counts add up to the draws issued. Each thread drew one
// chunk (sized by ChunkBalance, tested below), unless the main thread took over
// the chunks of workers the scheduler had not run yet (a loaded machine):
// then those workers drew nothing.
void ExpectSplit(const SceneStats& s, uint32_t threads) {
  EXPECT_EQ(s.recordingThreads, threads);
  ASSERT_EQ(s.drawsPerThread.size(), threads);
  EXPECT_EQ(std::accumulate(s.drawsPerThread.begin(), s.drawsPerThread.end(), 0u), s.drawsIssued);
  ASSERT_GE(s.callerChunks, 1u);
  ASSERT_LE(s.callerChunks, threads);
  for (uint32_t t = 1; t < s.callerChunks; ++t) EXPECT_EQ(s.drawsPerThread[t], 0u);
  const auto from = s.drawsPerThread.begin() + (s.callerChunks > 1 ? s.callerChunks : 0);
  const auto fewest = std::min_element(from, s.drawsPerThread.end());
  if (fewest != s.drawsPerThread.end() && s.drawsIssued >= threads) {
    EXPECT_GT(*fewest, 0u);
  }
  if (s.callerChunks > 1) std::printf("[threads] the main thread drew %u chunks\n", s.callerChunks);
}

}  // namespace

TEST(RecordingSplit, ContiguousChunksDifferByAtMostOneDraw) {
  for (uint32_t draws : {0u, 1u, 2u, 59u, 60u, 1000u}) {
    for (uint32_t chunks : {1u, 2u, 3u, 8u}) {
      uint32_t next = 0;
      for (uint32_t c = 0; c < chunks; ++c) {
        const ChunkRange r = SplitEvenly(draws, chunks, c);
        EXPECT_EQ(r.first, next) << draws << " draws, chunk " << c << " of " << chunks;
        EXPECT_GE(r.last, r.first);
        EXPECT_LE(r.last - r.first, draws / chunks + 1);
        EXPECT_GE(r.last - r.first, draws / chunks);
        next = r.last;
      }
      EXPECT_EQ(next, draws);
    }
  }
}

// Chunks of the balance cover [0, draws) in order, without gaps.
std::vector<uint32_t> ChunkSizes(const ChunkBalance& b, uint32_t draws, uint32_t chunks) {
  std::vector<uint32_t> sizes;
  uint32_t next = 0;
  for (uint32_t c = 0; c < chunks; ++c) {
    const ChunkRange r = b.Split(draws, chunks, c);
    EXPECT_EQ(r.first, next) << "chunk " << c << " of " << chunks;
    EXPECT_GE(r.last, r.first);
    sizes.push_back(r.last - r.first);
    next = r.last;
  }
  EXPECT_EQ(next, draws);
  return sizes;
}

TEST(RecordingSplit, BalanceIsEvenUntilEveryThreadsSpeedIsKnown) {
  ChunkBalance b;
  EXPECT_EQ(ChunkSizes(b, 1000, 3), (std::vector<uint32_t>{333, 333, 334}));
  b.Observe(3, 0, 500, 1.0);
  b.Observe(3, 1, 500, 2.0);  // thread 2 still unknown
  EXPECT_EQ(ChunkSizes(b, 1000, 3), (std::vector<uint32_t>{333, 333, 334}));
}

TEST(RecordingSplit, BalanceGivesTheFasterThreadMoreDraws) {
  ChunkBalance b;
  b.Observe(2, 0, 1000, 2.0);  // 2 us a draw
  b.Observe(2, 1, 1000, 4.0);  // twice as slow: a third of the draws
  EXPECT_EQ(ChunkSizes(b, 3000, 2), (std::vector<uint32_t>{2000, 1000}));
  // Equal expected times: 2000 * 2 us = 1000 * 4 us.
  EXPECT_DOUBLE_EQ(b.MsPerDraw(0) * 2000, b.MsPerDraw(1) * 1000);
  // A running average: one frame at the other speed moves it a quarter of the way.
  b.Observe(2, 1, 1000, 2.0);
  EXPECT_DOUBLE_EQ(b.MsPerDraw(1), 0.004 + ChunkBalance::kLearningRate * (0.002 - 0.004));
}

TEST(RecordingSplit, BalanceKeepsASlowThreadsShareAndIgnoresUselessFrames) {
  ChunkBalance b;
  b.Observe(2, 0, 1000, 1.0);
  b.Observe(2, 1, 1000, 500.0);  // a worker descheduled for half a second
  // Clamped to kMaxSpeedRatio (3): a quarter of the draws, not 1 in 500.
  EXPECT_EQ(ChunkSizes(b, 1000, 2), (std::vector<uint32_t>{750, 250}));
  ChunkBalance c;
  c.Observe(2, 0, 1000, 1.0);
  c.Observe(2, 1, ChunkBalance::kMinDraws - 1, 5.0);  // too few draws: mostly fixed costs
  c.Observe(2, 1, 1000, 0.0);
  c.Observe(2, 1, 1000, -1.0);
  c.Observe(2, 1, 1000, std::numeric_limits<double>::quiet_NaN());
  c.Observe(2, 1, 1000, std::numeric_limits<double>::infinity());
  c.Observe(2, 5, 1000, 1.0);  // no such thread
  EXPECT_EQ(c.MsPerDraw(1), 0.0);
  EXPECT_EQ(ChunkSizes(c, 1000, 2), (std::vector<uint32_t>{500, 500}));
  // Another thread count starts over.
  b.Observe(3, 0, 1000, 1.0);
  EXPECT_EQ(b.MsPerDraw(1), 0.0);
  EXPECT_EQ(ChunkSizes(b, 999, 3), (std::vector<uint32_t>{333, 333, 333}));
  EXPECT_EQ(ChunkSizes(b, 0, 3), (std::vector<uint32_t>{0, 0, 0}));
}

TEST(RecordingSplit, ExplicitCountsPassAndZeroStaysAutomatic) {
  EXPECT_EQ(RecordingThreadsFor(0), 0);
  EXPECT_EQ(RecordingThreadsFor(1), 1);
  EXPECT_EQ(RecordingThreadsFor(3), 3);
  EXPECT_EQ(RecordingThreadsFor(100), kMaxRecordingThreads);
}

// A thread per kMinDrawsPerRecordingThread draws, at most one per core and
// kAutoRecordingThreads; one thread below the threshold (the Arenas' 40 to 60
// draws), whatever the cores.
TEST(RecordingSplit, AutomaticAddsAThreadPerThresholdOfDraws) {
  const uint32_t k = kMinDrawsPerRecordingThread;
  EXPECT_EQ(AutoRecordingThreads(0, 16), 1);
  EXPECT_EQ(AutoRecordingThreads(59, 16), 1);
  EXPECT_EQ(AutoRecordingThreads(2 * k - 1, 16), 1);
  EXPECT_EQ(AutoRecordingThreads(2 * k, 16), 2);
  EXPECT_EQ(AutoRecordingThreads(3 * k, 16), 3);
  EXPECT_EQ(AutoRecordingThreads(100 * k, 16), kAutoRecordingThreads);
  EXPECT_EQ(AutoRecordingThreads(100 * k, 2), 2);
  EXPECT_EQ(AutoRecordingThreads(100 * k, 1), 1);
  EXPECT_EQ(AutoRecordingThreads(100 * k, 0), 1);  // cores unknown
}

// The default view (TAA, motion blur: colour and velocity targets) and one
// with every fix (sRGB targets, frustum culling) from the first-person
// camera, where the culling leaves gaps in the draw list.
TEST(RecordingThreads, ArenaIsBitIdenticalOnOneTwoAndThreeThreads) {
  for (bool fixes : {false, true}) {
    Options base = ArenaOptions(1);
    if (fixes) {
      base.fixes = FixSet::All();
      base.camera = 0;
    }
    const Frame one = RenderArena(base);
    ASSERT_FALSE(one.colour.Empty());
    if (fixes) {
      EXPECT_GT(one.stats.drawsCulled, 0u);
    }
    ExpectSplit(one.stats, 1);
    for (int threads : {2, 3}) {
      Options o = base;
      o.threads = threads;
      const Frame many = RenderArena(o);
      const Diff d = Compare(one.colour, many.colour);
      std::printf("[threads] fixes %d, %d threads: %llu px differ, draws %u (culled %u)\n", int(fixes), threads,
                  (unsigned long long)d.differing, many.stats.drawsIssued, many.stats.drawsCulled);
      EXPECT_TRUE(SamePixels(one.colour, many.colour)) << threads << " threads, fixes " << fixes;
      EXPECT_TRUE(SamePixels(one.velocity, many.velocity)) << threads << " threads, fixes " << fixes;
      EXPECT_EQ(many.stats.drawsIssued, one.stats.drawsIssued);
      EXPECT_EQ(many.stats.drawsCulled, one.stats.drawsCulled);
      ExpectSplit(many.stats, uint32_t(threads));
    }
  }
}

// The port's other scene paths on the recording threads: the G-buffer of
// the deferred renderer (four targets read back for the lists) and the
// adaptive tessellation (hull and domain stages, their constants mapped per
// draw on each context) give the single-threaded pixels too.
TEST(RecordingThreads, DeferredAndTessellatedArenaIsBitIdenticalOnTwoThreads) {
  Options base = ArenaOptions(1);
  base.renderer = Renderer::Deferred;
  base.tessellation = true;
  base.tessPixelsPerEdge = 4.0;
  const Frame one = RenderArena(base);
  ASSERT_FALSE(one.colour.Empty());
  EXPECT_GT(one.stats.tessellatedDraws, 0u);
  Options o = base;
  o.threads = 2;
  const Frame two = RenderArena(o);
  const Diff d = Compare(one.colour, two.colour);
  std::printf("[threads] deferred + tessellation, 2 threads: %llu px differ\n", (unsigned long long)d.differing);
  EXPECT_TRUE(SamePixels(one.colour, two.colour));
  EXPECT_TRUE(SamePixels(one.velocity, two.velocity));
  EXPECT_EQ(two.stats.tessellatedDraws, one.stats.tessellatedDraws);
  EXPECT_EQ(two.stats.patchesSubmitted, one.stats.patchesSubmitted);
  ExpectSplit(two.stats, 2);
}

// By default the scene records on the immediate context, as the original;
// the GUI's setting (ApplySettings) changes the count from the next frame,
// the pool is rebuilt and the paused frame stays the same. The automatic
// mode (0) keeps the Arena's few draws on one thread.
TEST(RecordingThreads, DefaultIsOneThreadAndTheCountChangesAtRunTime) {
  Options o = HeadlessOptions(160, 90, 3.0);
  EXPECT_EQ(o.threads, 1);
  o.pause = true;
  Sample s;
  if (!Start(s, o)) return;
  const Image first = RenderAndCapture(s, 2);
  const SceneStats initial = s.GetScene()->Stats();
  EXPECT_EQ(initial.recordingThreads, 1u);
  const uint32_t automatic = uint32_t(AutoRecordingThreads(initial.drawsIssued));
  EXPECT_EQ(automatic, 1u) << initial.drawsIssued << " draws";
  for (int threads : {3, 0, 2}) {
    Options next = s.Settings();
    next.threads = threads;
    s.ApplySettings(next);
    const Image again = RenderAndCapture(s, 2);
    EXPECT_TRUE(SamePixels(first, again)) << threads << " threads";
    EXPECT_EQ(s.GetScene()->Stats().recordingThreads, threads == 0 ? automatic : uint32_t(threads));
  }
  Finish(s);
}

// The default (1 thread, the immediate context) and --threads 4 render the
// same images, bit for bit, on the Arena and on the many-object Arena (about
// 3000 draws); there the automatic mode records on more than one thread where
// the machine has more than one core, with the same image again.
TEST(RecordingThreads, DefaultMatchesFourThreadsOnBothArenas) {
  for (const char* scene : {"", DRR_TEST_ARENA_PROPS_DIR "/scene_description.txt"}) {
    Options base = HeadlessOptions(160, 90, 3.0);
    base.scene = scene;
    const Frame one = RenderArena(base);
    ASSERT_FALSE(one.colour.Empty()) << scene;
    ExpectSplit(one.stats, 1);
    Options four = base;
    four.threads = 4;
    const Frame many = RenderArena(four);
    std::printf("[threads] %s: default and 4 threads, %llu px differ, draws %u\n", *scene ? "props" : "arena",
                (unsigned long long)Compare(one.colour, many.colour).differing, many.stats.drawsIssued);
    EXPECT_TRUE(SamePixels(one.colour, many.colour)) << scene;
    EXPECT_TRUE(SamePixels(one.velocity, many.velocity)) << scene;
    EXPECT_EQ(many.stats.drawsIssued, one.stats.drawsIssued);
    ExpectSplit(many.stats, 4);
    if (!*scene) continue;
    EXPECT_GT(one.stats.drawsIssued, 2000u);
    Options automatic = base;
    automatic.threads = 0;
    const Frame chosen = RenderArena(automatic);
    EXPECT_EQ(chosen.stats.recordingThreads, uint32_t(AutoRecordingThreads(one.stats.drawsIssued)));
    EXPECT_TRUE(SamePixels(one.colour, chosen.colour));
  }
}
