// The scene's draws split across threads (Docs/Threads.md), as the 3DMark 11
// design: the main thread records on the immediate context and executes the
// lists there; the workers record only, each on its own deferred context.
#include <atomic>
#include <chrono>

#include "scene/SceneImpl.h"

namespace drr {
namespace {

using Clock = std::chrono::steady_clock;
double Ms(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// Who draws a chunk: its worker, or the caller's thread when it got there
// first (the worker had not run yet).
enum Owner : int { kFree, kWorker, kCaller };

// What the threads of one frame share. Each worker writes only its own slots;
// the caller reads them after RecordingPool::Wait.
struct ChunkedFrame {
  explicit ChunkedFrame(size_t n)
      : owner(n), lists(n), issued(n, 0), chunkMs(n, 0.0), wakeMs(n, 0.0), finishMs(n, 0.0) {}
  bool Claim(size_t t, Owner who) {
    int expected = kFree;
    return owner[t].compare_exchange_strong(expected, who, std::memory_order_acq_rel);
  }
  std::atomic<bool> planned{false};  // the draw list is built
  std::vector<std::atomic<int>> owner;
  std::vector<ComPtr<d3dl::CommandList>> lists;
  std::vector<uint32_t> issued;
  std::vector<double> chunkMs, wakeMs, finishMs;
  const Clock::time_point woken = Clock::now();
};

}  // namespace

bool SceneImpl::EnsurePool(int threads) {
  if (pool && pool->Threads() == threads) return true;
  pool.reset();
  std::string error;
  pool = RecordingPool::Create(device.Get(), threads, &error);
  if (!pool) Warn(error);
  return pool != nullptr;
}

// The workers are woken first and set their context's frame state while this
// thread builds the draw list; they start drawing once it is published. The
// chunks' sizes follow the threads' measured speeds (ChunkBalance).
// Chunk t > 0 goes to worker t unless this thread, done with chunk 0, finds it
// still unclaimed (a worker not scheduled yet, on a loaded machine): it then
// draws it itself on the immediate context, so a frame never waits for the
// scheduler. Chunks taken here stay a prefix of the list: the order holds.
bool SceneImpl::RecordThreaded(d3dl::DeviceContext* immediate, int threads, const SceneRenderParams& p, FrameDraw& f,
                               const std::function<void()>& prepare) {
  threads = std::min(threads, kMaxRecordingThreads);
  if (!EnsurePool(threads)) return false;
  // A list starts from the default state: the workers bind the caller's
  // targets (read back with references added, released at the end).
  immediate->OMGetRenderTargets(d3dl::UINT(std::size(f.rtv)), f.rtv, &f.dsv);
  f.viewport = *p.viewport;
  const size_t n = size_t(threads);
  ChunkedFrame frame(n);
  const auto chunk = [&](size_t t) {
    const uint32_t draws = uint32_t(drawList.size());
    const ChunkRange r = p.evenChunks ? SplitEvenly(draws, uint32_t(n), uint32_t(t))
                                      : chunkBalance.Split(draws, uint32_t(n), uint32_t(t));
    return std::pair(drawList.data() + r.first, drawList.data() + r.last);
  };
  const std::function<void(int)> worker = [&](int thread) {
    const size_t t = size_t(thread);
    frame.wakeMs[t] = Ms(frame.woken, Clock::now());
    if (!frame.Claim(t, kWorker)) return;
    d3dl::DeviceContext* dc = pool->Context(thread);
    BeginDraws(dc, f, true);
    frame.planned.wait(false, std::memory_order_acquire);
    const Clock::time_point drawing = Clock::now();
    const auto [first, last] = chunk(t);
    frame.issued[t] = RecordDraws(dc, f, first, last);
    const Clock::time_point finishing = Clock::now();
    dc->FinishCommandList(0, frame.lists[t].GetAddressOf());
    const Clock::time_point finished = Clock::now();
    frame.finishMs[t] = Ms(finishing, finished);
    frame.chunkMs[t] = Ms(drawing, finished);
  };
  pool->Start(&worker);
  const Clock::time_point planning = Clock::now();
  prepare();
  const Clock::time_point planned = Clock::now();
  frame.planned.store(true, std::memory_order_release);
  frame.planned.notify_all();
  BeginDraws(immediate, f, false);
  if (p.callerDrawsAfterWorkers) pool->Wait();
  const Clock::time_point drawing = Clock::now();
  size_t onImmediate = 0;  // chunks [0, onImmediate) drawn here
  do {
    const auto [first, last] = chunk(onImmediate++);
    frame.issued[0] += RecordDraws(immediate, f, first, last);
  } while (onImmediate < n && p.callerTakesLateChunks && frame.Claim(onImmediate, kCaller));
  const Clock::time_point drawn = Clock::now();
  frame.chunkMs[0] = Ms(drawing, drawn);
  pool->Wait();
  const Clock::time_point joined = Clock::now();
  for (size_t t = 0; t < n; ++t) chunkBalance.Observe(uint32_t(n), uint32_t(t), frame.issued[t], frame.chunkMs[t]);
  // The workers' lists in draw-list order after the chunks drawn here, so the
  // image is the single-threaded one.
  for (size_t t = onImmediate; t < n; ++t)
    if (frame.lists[t] && frame.issued[t] > 0) immediate->ExecuteCommandList(frame.lists[t].Get(), 1);
  stats.planMs = Ms(planning, planned);
  stats.waitMs = Ms(drawn, joined);
  stats.executeMs = Ms(joined, Clock::now());
  for (d3dl::RenderTargetView* v : f.rtv)
    if (v) v->Release();
  if (f.dsv) f.dsv->Release();
  stats.recordingThreads = uint32_t(threads);
  stats.drawsPerThread = frame.issued;
  stats.chunkMs = frame.chunkMs;
  stats.wakeMs = frame.wakeMs;
  stats.finishMs = frame.finishMs;
  stats.callerChunks = uint32_t(onImmediate);
  return true;
}

}  // namespace drr
