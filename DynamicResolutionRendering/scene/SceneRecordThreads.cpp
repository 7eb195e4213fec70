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
  std::atomic<bool> planned{false};
  std::vector<ComPtr<d3dl::CommandList>> lists(static_cast<size_t>(threads));
  std::vector<uint32_t> issued(static_cast<size_t>(threads), 0);
  std::vector<double> chunkMs(static_cast<size_t>(threads), 0.0), wakeMs(static_cast<size_t>(threads), 0.0);
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  const Clock::time_point woken = Clock::now();
  const auto chunk = [&](int t) {
    const ChunkRange r = SplitEvenly(uint32_t(drawList.size()), uint32_t(threads), uint32_t(t));
    return std::pair(drawList.data() + r.first, drawList.data() + r.last);
  };
  const std::function<void(int)> worker = [&](int t) {
    const Clock::time_point start = Clock::now();
    wakeMs[size_t(t)] = ms(woken, start);
    d3dl::DeviceContext* dc = pool->Context(t);
    BeginDraws(dc, f, true);
    planned.wait(false, std::memory_order_acquire);
    const Clock::time_point drawing = Clock::now();
    const auto [first, last] = chunk(t);
    issued[size_t(t)] = RecordDraws(dc, f, first, last);
    dc->FinishCommandList(0, lists[size_t(t)].GetAddressOf());
    chunkMs[size_t(t)] = ms(drawing, Clock::now());
  };
  pool->Start(&worker);
  prepare();
  planned.store(true, std::memory_order_release);
  planned.notify_all();
  BeginDraws(immediate, f, false);
  const Clock::time_point drawing = Clock::now();
  const auto [first, last] = chunk(0);
  issued[0] = RecordDraws(immediate, f, first, last);
  chunkMs[0] = ms(drawing, Clock::now());
  pool->Wait();
  // In draw-list order after the first chunk, so the image is the
  // single-threaded one.
  for (int t = 1; t < threads; ++t)
    if (lists[size_t(t)] && issued[size_t(t)] > 0) immediate->ExecuteCommandList(lists[size_t(t)].Get(), 1);
  for (d3dl::RenderTargetView* v : f.rtv)
    if (v) v->Release();
  if (f.dsv) f.dsv->Release();
  stats.recordingThreads = uint32_t(threads);
  stats.drawsPerThread = issued;
  stats.chunkMs = chunkMs;
  stats.wakeMs = wakeMs;
  return true;
}

}  // namespace drr
