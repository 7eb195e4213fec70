// The scene's draws split across deferred contexts (Docs/Threads.md), as the
// 3DMark 11 design: the main thread records on a deferred context too and
// alone executes the lists on the immediate context; the workers record only.
#include <atomic>

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
  // With references added, released at the end.
  immediate->OMGetRenderTargets(2, f.rtv, &f.dsv);
  f.viewport = *p.viewport;

  // The workers are woken first and set their context's frame state while
  // this thread builds the draw list; they start drawing once it is published.
  std::atomic<bool> planned{false};
  std::vector<ComPtr<d3dl::CommandList>> lists(static_cast<size_t>(threads));
  std::vector<uint32_t> issued(size_t(threads), 0);
  const std::function<void(int)> job = [&](int t) {
    d3dl::DeviceContext* dc = pool->Context(t);
    BeginDraws(dc, f, true);
    planned.wait(false, std::memory_order_acquire);
    const ChunkRange r = SplitEvenly(uint32_t(drawList.size()), uint32_t(threads), uint32_t(t));
    issued[size_t(t)] = RecordDraws(dc, f, drawList.data() + r.first, drawList.data() + r.last);
    dc->FinishCommandList(0, lists[size_t(t)].GetAddressOf());
  };
  pool->Start(&job);
  prepare();
  planned.store(true, std::memory_order_release);
  planned.notify_all();
  job(0);
  pool->Wait();
  // In draw-list order, so the image is the single-threaded one.
  for (int t = 0; t < threads; ++t)
    if (lists[size_t(t)] && issued[size_t(t)] > 0) immediate->ExecuteCommandList(lists[size_t(t)].Get(), 1);
  for (d3dl::RenderTargetView* v : f.rtv)
    if (v) v->Release();
  if (f.dsv) f.dsv->Release();
  stats.recordingThreads = uint32_t(threads);
  stats.drawsPerThread = issued;
  return true;
}

}  // namespace drr
