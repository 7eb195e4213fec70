// The scene's draws split across threads (Docs/Threads.md), as the 3DMark 11
// design: the main thread records on the immediate context and executes the
// lists there; the workers record only, each on its own deferred context.
#include <atomic>
#include <chrono>

#include "scene/SceneImpl.h"

namespace drr {

bool SceneImpl::RecordThreaded(d3dl::DeviceContext* immediate, const SceneRenderParams& p, FrameDraw& f,
                               const std::function<void()>& prepare) {
  const int threads = std::min(p.recordingThreads, kMaxRecordingThreads);
  if (!pool || pool->Threads() != threads) {
    pool.reset();
    std::string error;
    pool = RecordingPool::Create(device.Get(), threads, &error);
    if (!pool) {
      Warn(error);
      return false;
    }
  }
  // A list starts from the default state: the workers bind the caller's
  // targets (read back with references added, released at the end).
  immediate->OMGetRenderTargets(2, f.rtv, &f.dsv);
  f.viewport = *p.viewport;

  // The workers are woken first and set their context's frame state while
  // this thread builds the draw list; they start drawing once it is published.
  // Chunk t > 0 goes to worker t unless this thread, done with chunk 0, finds
  // it still unclaimed (a worker not yet scheduled, on a loaded machine): it
  // then draws it itself on the immediate context, so the frame is never
  // slower than waiting for the scheduler. Taken chunks stay a prefix of the
  // list, which keeps the draw order.
  enum Owner : int { kFree, kWorker, kCaller };
  const size_t n = size_t(threads);
  std::atomic<bool> planned{false};
  std::vector<std::atomic<int>> owner(n);
  std::vector<ComPtr<d3dl::CommandList>> lists(n);
  std::vector<uint32_t> issued(n, 0);
  std::vector<double> chunkMs(n, 0.0), wakeMs(n, 0.0);
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  const Clock::time_point woken = Clock::now();
  const auto chunk = [&](size_t t) {
    const ChunkRange r = SplitEvenly(uint32_t(drawList.size()), uint32_t(n), uint32_t(t));
    return std::pair(drawList.data() + r.first, drawList.data() + r.last);
  };
  const auto claim = [&](size_t t, Owner who) {
    int expected = kFree;
    return owner[t].compare_exchange_strong(expected, who, std::memory_order_acq_rel);
  };
  const std::function<void(int)> worker = [&](int thread) {
    const size_t t = size_t(thread);
    const Clock::time_point start = Clock::now();
    wakeMs[t] = ms(woken, start);
    if (!claim(t, kWorker)) return;
    d3dl::DeviceContext* dc = pool->Context(thread);
    BeginDraws(dc, f, true);
    planned.wait(false, std::memory_order_acquire);
    const Clock::time_point drawing = Clock::now();
    const auto [first, last] = chunk(t);
    issued[t] = RecordDraws(dc, f, first, last);
    dc->FinishCommandList(0, lists[t].GetAddressOf());
    chunkMs[t] = ms(drawing, Clock::now());
  };
  pool->Start(&worker);
  prepare();
  planned.store(true, std::memory_order_release);
  planned.notify_all();
  BeginDraws(immediate, f, false);
  const Clock::time_point drawing = Clock::now();
  size_t onImmediate = 0;  // chunks [0, onImmediate) drawn here
  do {
    const auto [first, last] = chunk(onImmediate++);
    issued[0] += RecordDraws(immediate, f, first, last);
  } while (onImmediate < n && p.callerTakesLateChunks && claim(onImmediate, kCaller));
  chunkMs[0] = ms(drawing, Clock::now());
  pool->Wait();
  // The workers' lists in draw-list order after the chunks drawn here, so
  // the image is the single-threaded one.
  for (size_t t = onImmediate; t < n; ++t)
    if (lists[t] && issued[t] > 0) immediate->ExecuteCommandList(lists[t].Get(), 1);
  for (d3dl::RenderTargetView* v : f.rtv)
    if (v) v->Release();
  if (f.dsv) f.dsv->Release();
  stats.recordingThreads = uint32_t(threads);
  stats.drawsPerThread = issued;
  stats.chunkMs = chunkMs;
  stats.callerChunks = uint32_t(onImmediate);
  stats.wakeMs = wakeMs;
  return true;
}

}  // namespace drr
