// drr_scene_record_bench: CPU time of Scene::Render (Docs/Threads.md) with the
// draws recorded on the immediate context (1 thread, as the original) against
// N deferred contexts on N threads, in alternating pairs so that load from
// other processes hits both alike. Timed (wall clock): the whole Render call,
// that is the frame move, culling, the recording, FinishCommandList and the
// ExecuteCommandList calls; not timed: Flush and the wait for the GPU.
//
//   drr_scene_record_bench [--scene PATH] [--threads N] [--pairs K] [--frames F]
//                          [--size WxH] [--no-take-over] [--idle-ms MS] [google benchmark flags]
// --no-take-over: every chunk on its worker, however late the worker starts.
// --idle-ms: after each frame's (untimed) wait for the GPU, sleep MS more
//   milliseconds (0 to 100, default 0), so that every timed Render begins
//   after both CPUs had nothing to do, as a frame held back by VSync does.
//   drr_scene_record_bench --smoke [--scene PATH]   1, 2 and 3 threads give the same
//                                                  image, validation-clean
//   drr_scene_record_bench --contention [--scene PATH] [--threads N] [--pairs K] [--frames F]
//                          each chunk's time beside the other threads over its time alone
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "d3dl/D3DLike.h"
#include "scene/Scene.h"

namespace {

using d3dl::ComPtr;
uint64_t g_messages = 0;

void OnLog(d3dl::LogLevel level, const char* message, void*) {
  if (level == d3dl::LogLevel::Validation || level == d3dl::LogLevel::Error) {
    ++g_messages;
    std::fprintf(stderr, "rhi: %s\n", message);
  }
}

struct Target {
  ComPtr<d3dl::Texture2D> texture, staging;
  ComPtr<d3dl::RenderTargetView> rtv;
  bool Init(d3dl::Device* device, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT format) {
    d3dl::TEXTURE2D_DESC td;
    td.Width = w;
    td.Height = h;
    td.Format = format;
    td.BindFlags = d3dl::BIND_RENDER_TARGET;
    d3dl::TEXTURE2D_DESC sd = td;
    sd.BindFlags = 0;
    sd.Usage = d3dl::USAGE_STAGING;
    sd.CPUAccessFlags = d3dl::CPU_ACCESS_READ;
    return d3dl::SUCCEEDED(device->CreateTexture2D(&td, nullptr, texture.GetAddressOf())) &&
           d3dl::SUCCEEDED(device->CreateRenderTargetView(texture.Get(), nullptr, rtv.GetAddressOf())) &&
           d3dl::SUCCEEDED(device->CreateTexture2D(&sd, nullptr, staging.GetAddressOf()));
  }
};

// The scene of the sample's default view (its first scene camera at a fixed
// time) into a colour + velocity + depth target of the given size.
class SceneFrame {
 public:
  bool Init(const std::string& scenePath, uint32_t w, uint32_t h, std::string* error) {
    d3dl::DEVICE_CREATE_DESC dd;
    dd.Log = OnLog;
    dd.EnableWindowSurfaces = false;
    dd.ApplicationName = "scene-record-benchmark";
    if (d3dl::FAILED(d3dl::CreateDevice(&dd, device_.GetAddressOf(), context_.GetAddressOf()))) {
      *error = "CreateDevice failed";
      return false;
    }
    w_ = w;
    h_ = h;
    d3dl::TEXTURE2D_DESC dd2;
    dd2.Width = w;
    dd2.Height = h;
    dd2.Format = d3dl::DXGI_FORMAT_D32_FLOAT;
    dd2.BindFlags = d3dl::BIND_DEPTH_STENCIL;
    if (!colour_.Init(device_.Get(), w, h, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM) ||
        !velocity_.Init(device_.Get(), w, h, d3dl::DXGI_FORMAT_R16G16_FLOAT) ||
        d3dl::FAILED(device_->CreateTexture2D(&dd2, nullptr, depth_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateDepthStencilView(depth_.Get(), nullptr, dsv_.GetAddressOf()))) {
      *error = "creating the targets failed";
      return false;
    }
    drr::SceneLoadOptions so;
    so.maxAnisotropy = 1;  // trilinear, as the sample on a CPU rasteriser
    scene_ = drr::Scene::Load(device_.Get(), scenePath, so, error);
    if (!scene_) return false;
    scene_->Update(3.0);
    const drr::CameraPose pose = scene_->Camera(0);
    params_.view = pose.view;
    params_.proj = glm::perspectiveRH_ZO(pose.fovY, float(w) / float(h), pose.nearZ, pose.farZ);
    params_.viewport = d3dl::VIEWPORT{0, 0, float(w), float(h), 0, 1};
    return true;
  }
  ~SceneFrame() {
    if (device_) device_->WaitIdle();
    scene_.reset();
  }

  // Clears, then times Render alone (milliseconds).
  double Render(int threads) {
    d3dl::RenderTargetView* rtvs[2] = {colour_.rtv.Get(), velocity_.rtv.Get()};
    const float black[4] = {0, 0, 0, 0};
    context_->ClearRenderTargetView(rtvs[0], black);
    context_->ClearRenderTargetView(rtvs[1], black);
    context_->ClearDepthStencilView(dsv_.Get(), d3dl::CLEAR_DEPTH, 1.f, 0);
    context_->OMSetRenderTargets(2, rtvs, dsv_.Get());
    context_->RSSetViewports(1, &*params_.viewport);
    params_.recordingThreads = threads;
    const auto start = std::chrono::steady_clock::now();
    scene_->Render(context_.Get(), params_);
    const auto stop = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::milli>(stop - start).count();
  }
  // Not timed: submit and wait, so that the GPU (a CPU rasteriser here) does
  // not run beside the next recording; then the idle pause, if any.
  void Finish() {
    context_->OMSetRenderTargets(0, nullptr, nullptr);
    context_->Flush();
    device_->WaitIdle();
    if (idleMs_ > 0) std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(idleMs_));
  }
  void SetIdleMs(double ms) { idleMs_ = ms; }
  std::vector<uint8_t> ReadColour() {
    context_->OMSetRenderTargets(0, nullptr, nullptr);
    context_->CopyResource(colour_.staging.Get(), colour_.texture.Get());
    std::vector<uint8_t> pixels(size_t(w_) * h_ * 4);
    d3dl::MAPPED_SUBRESOURCE m;
    if (d3dl::FAILED(context_->Map(colour_.staging.Get(), 0, d3dl::MAP_READ, 0, &m))) return {};
    for (uint32_t y = 0; y < h_; ++y)
      std::memcpy(&pixels[size_t(y) * w_ * 4], static_cast<const uint8_t*>(m.pData) + size_t(y) * m.RowPitch,
                  size_t(w_) * 4);
    context_->Unmap(colour_.staging.Get(), 0);
    return pixels;
  }
  drr::SceneStats Stats() const { return scene_->Stats(); }
  void SetWorkersAlways(bool on) { params_.callerTakesLateChunks = !on; }
  void SetChunkTiming(bool evenChunks, bool callerAfterWorkers) {
    params_.evenChunks = evenChunks;
    params_.callerDrawsAfterWorkers = callerAfterWorkers;
  }
  uint64_t Messages() const { return DeviceStats().ValidationMessages + g_messages; }
  d3dl::DEVICE_STATS DeviceStats() const {
    d3dl::DEVICE_STATS stats;
    device_->GetStats(&stats);
    return stats;
  }

 private:
  ComPtr<d3dl::Device> device_;
  ComPtr<d3dl::DeviceContext> context_;
  Target colour_, velocity_;
  ComPtr<d3dl::Texture2D> depth_;
  ComPtr<d3dl::DepthStencilView> dsv_;
  std::unique_ptr<drr::Scene> scene_;
  drr::SceneRenderParams params_;
  uint32_t w_ = 0, h_ = 0;
  double idleMs_ = 0;
};

std::unique_ptr<SceneFrame> g_frame;  // reset before main returns (drivers unload first)

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t m = v.size();
  return m % 2 ? v[m / 2] : 0.5 * (v[m / 2 - 1] + v[m / 2]);
}

// Median Render time of the benchmark's frames; the mean goes to the counters.
std::map<std::string, double> g_medianMs;
// Where every frame's time went, by thread count: per thread its chunk, its
// wake-up and its FinishCommandList; the serial parts (Render, draw-list
// build, the wait for the workers, the list executions); and the frames in
// which the caller drew a worker's chunk (the worker had not started).
struct FrameTimes {
  std::vector<std::vector<double>> chunk, wake, finish;  // [thread][frame]
  std::vector<double> render, plan, wait, execute;       // [frame]
  size_t takenOver = 0;
  void Add(double renderMs, const drr::SceneStats& st) {
    const size_t n = st.chunkMs.size();
    chunk.resize(n);
    wake.resize(n);
    finish.resize(n);
    for (size_t k = 0; k < n; ++k) {
      chunk[k].push_back(st.chunkMs[k]);
      wake[k].push_back(k < st.wakeMs.size() ? st.wakeMs[k] : 0.0);
      finish[k].push_back(k < st.finishMs.size() ? st.finishMs[k] : 0.0);
    }
    render.push_back(renderMs);
    plan.push_back(st.planMs);
    wait.push_back(st.waitMs);
    execute.push_back(st.executeMs);
    takenOver += st.callerChunks > 1 ? 1 : 0;
  }
};
std::map<int, FrameTimes> g_times;

void RenderFrames(benchmark::State& state, int threads, const std::string& key) {
  std::vector<double> ms;
  for (auto _ : state) {
    const double t = g_frame->Render(threads);
    state.SetIterationTime(t * 1e-3);
    ms.push_back(t);
    g_times[threads].Add(t, g_frame->Stats());
    g_frame->Finish();
  }
  g_medianMs[key] = Median(ms);
  const drr::SceneStats s = g_frame->Stats();
  state.counters["threads"] = s.recordingThreads;
  state.counters["draws"] = s.drawsIssued;
  state.counters["median_ms"] = Median(ms);
}

std::string DrawsPerThread(const drr::SceneStats& s) {
  std::string out;
  for (uint32_t n : s.drawsPerThread) out += (out.empty() ? "" : " + ") + std::to_string(n);
  return out;
}

int Smoke() {
  g_frame->SetWorkersAlways(true);  // every chunk on its worker's deferred context
  std::vector<uint8_t> images[3];
  for (int t = 1; t <= 3; ++t) {
    g_frame->Render(t);
    images[t - 1] = g_frame->ReadColour();
    g_frame->Finish();
    const drr::SceneStats s = g_frame->Stats();
    std::printf("%d thread(s): draws %s\n", t, DrawsPerThread(s).c_str());
  }
  size_t lit = 0, differing = 0;
  for (size_t i = 0; i + 3 < images[0].size(); i += 4) {
    lit += images[0][i] | images[0][i + 1] | images[0][i + 2] ? 1 : 0;
    for (int k = 1; k < 3; ++k) differing += images[k].size() != images[0].size() ||
                                             std::memcmp(&images[0][i], &images[k][i], 4) != 0;
  }
  const uint64_t messages = g_frame->Messages();
  std::printf("scene record smoke: %zu lit pixels, %zu differing pixels, %llu messages\n", lit, differing,
              static_cast<unsigned long long>(messages));
  const bool ok = !images[0].empty() && lit > 0 && differing == 0 && messages == 0;
  std::printf("%d passed, %d failed\n", ok ? 1 : 0, ok ? 0 : 1);
  return ok ? 0 : 1;
}

// Each thread's median, " / " between threads.
std::string PerThreadMedians(const std::vector<std::vector<double>>& perThread) {
  std::string out;
  for (size_t k = 0; k < perThread.size(); ++k) {
    char b[32];
    std::snprintf(b, sizeof b, "%s%.3f", k ? " / " : "", Median(perThread[k]));
    out += b;
  }
  return out;
}

// The frames split by whether every worker was running before the draw list
// was published (its wake-up delay at most the draw list's time), so that it
// could start on its chunk at once, and each part's median Render.
void PrintOnTimeSplit(int threads, const FrameTimes& serial) {
  std::vector<double> onTime, late;
  for (size_t i = 0; i < serial.render.size(); ++i) {
    bool started = true;
    for (size_t k = 1; k < serial.wake.size(); ++k) started = started && serial.wake[k][i] <= serial.plan[i];
    (started ? onTime : late).push_back(serial.render[i]);
  }
  std::printf("%d thread(s): every worker running before the draw list was published in %zu of %zu frames; "
              "Render %.3f ms in those, %.3f ms in the others (medians)\n",
              threads, onTime.size(), serial.render.size(), Median(onTime), Median(late));
}

// Where the time goes: each thread's chunk (first draw to the end of its
// list), each worker's wake-up delay and FinishCommandList, and the serial
// parts of the frame, medians over every frame.
void PrintThreadTimes() {
  for (const auto& [threads, serial] : g_times) {
    std::printf("%d thread(s): chunk ms per thread (medians) %s; wake-up ms %s; FinishCommandList ms %s\n", threads,
                PerThreadMedians(serial.chunk).c_str(), PerThreadMedians(serial.wake).c_str(),
                PerThreadMedians(serial.finish).c_str());
    std::printf("%d thread(s): Render %.3f ms, draw list %.3f ms, wait for the workers %.3f ms, list executions "
                "%.3f ms (medians); a worker's chunk drawn by the caller in %zu of %zu frames\n",
                threads, Median(serial.render), Median(serial.plan), Median(serial.wait), Median(serial.execute),
                serial.takenOver, serial.render.size());
    if (threads > 1) PrintOnTimeSplit(threads, serial);
  }
}

void PrintPairs(int pairs, int threads) {
  std::vector<double> ratios;
  for (int k = 0; k < pairs; ++k) {
    const std::string one = "1/" + std::to_string(k), many = "N/" + std::to_string(k);
    const double t1 = g_medianMs.count(one) ? g_medianMs[one] : 0, tn = g_medianMs.count(many) ? g_medianMs[many] : 0;
    if (t1 <= 0 || tn <= 0) continue;
    ratios.push_back(tn / t1);
    std::printf("pair %d: 1 thread %.3f ms, %d threads %.3f ms (medians), ratio %.3f\n", k, t1, threads, tn, tn / t1);
  }
  if (ratios.empty()) return;
  const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
  std::printf("ratio %d-thread / 1-thread Scene::Render (%zu pairs, hardware threads %u): median %.3f, min %.3f, "
              "max %.3f\n",
              threads, ratios.size(), std::thread::hardware_concurrency(), Median(ratios), *lo, *hi);
}

// --contention: what the recording threads cost each other. Frames come in
// pairs with equal chunks: in one the caller records its chunk after the
// workers have finished theirs (every chunk alone), in the other beside them
// (the normal frame); which comes first alternates. Per chunk, the ratio of
// its time beside the others to its time alone, over the pairs: above 1 is
// the cost of sharing (cache lines written by both threads, locks), on the
// same draws, and slow phases of the machine hit both frames of a pair.
// Every chunk is drawn on its own thread (no take-over of a late worker's
// chunk), so every pair is usable; a chunk's time starts when its thread has
// the draw list, so a late start does not count.
int Contention(int threads, int pairs, int frames) {
  const size_t n = size_t(threads);
  g_frame->SetWorkersAlways(true);
  std::vector<std::vector<double>> ratios(n), alone(n);
  int skipped = 0;
  for (int i = 0; i < pairs * frames; ++i) {
    std::vector<double> ms[2];  // [0] alone, [1] beside the others
    bool usable = true;
    for (int k = 0; k < 2; ++k) {
      const int together = (i % 2) ^ k;
      g_frame->SetChunkTiming(true, together == 0);
      g_frame->Render(threads);
      const drr::SceneStats st = g_frame->Stats();
      usable = usable && st.callerChunks == 1 && st.chunkMs.size() == n;
      ms[together] = st.chunkMs;
      g_frame->Finish();
    }
    if (!usable) {
      ++skipped;
      continue;
    }
    for (size_t t = 0; t < n; ++t) {
      ratios[t].push_back(ms[1][t] / ms[0][t]);
      alone[t].push_back(ms[0][t]);
    }
  }
  g_frame->SetChunkTiming(false, false);
  g_frame->SetWorkersAlways(false);
  std::printf("chunk times beside the other threads / alone, %d threads, equal chunks (%s draws), %zu frame pairs "
              "(%d skipped: a chunk not on its thread)\n",
              threads, DrawsPerThread(g_frame->Stats()).c_str(), ratios[0].size(), skipped);
  for (size_t t = 0; t < n && !ratios[t].empty(); ++t)
    std::printf("chunk %zu (%s): alone %.3f ms (median); beside / alone median %.3f\n", t,
                t == 0 ? "caller, immediate context" : "worker, deferred context", Median(alone[t]),
                Median(ratios[t]));
  // Every pair's ratio: scripts/threads-tables.py gives the intervals.
  for (size_t t = 0; t < n; ++t) {
    std::printf("chunk %zu ratios:", t);
    for (double r : ratios[t]) std::printf(" %.4f", r);
    std::printf("\n");
  }
  const uint64_t messages = g_frame->Messages();
  std::printf("validation messages: %llu\n", static_cast<unsigned long long>(messages));
  return ratios[0].empty() || messages != 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene = DRR_ARENA_LARGE_DIR "/scene_description.txt";
  int threads = 2, pairs = 10, frames = 30;
  double idleMs = 0;
  uint32_t w = 320, h = 180;
  bool smoke = false, takeOver = true, contention = false;
  std::vector<char*> args{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const auto value = [&] { return i + 1 < argc ? argv[++i] : (char*)""; };
    if (std::strcmp(argv[i], "--smoke") == 0) smoke = true;
    else if (std::strcmp(argv[i], "--contention") == 0) contention = true;
    else if (std::strcmp(argv[i], "--no-take-over") == 0) takeOver = false;
    else if (std::strcmp(argv[i], "--scene") == 0) scene = value();
    else if (std::strcmp(argv[i], "--threads") == 0) threads = std::atoi(value());
    else if (std::strcmp(argv[i], "--pairs") == 0) pairs = std::atoi(value());
    else if (std::strcmp(argv[i], "--frames") == 0) frames = std::atoi(value());
    else if (std::strcmp(argv[i], "--idle-ms") == 0) idleMs = std::strtod(value(), nullptr);
    else if (std::strcmp(argv[i], "--size") == 0) {
      if (std::sscanf(value(), "%ux%u", &w, &h) != 2) w = 0;
    } else args.push_back(argv[i]);
  }
  if ((threads < 2 && threads != 0) || threads > 8 || pairs < 1 || pairs > 1000 || frames < 1 || frames > 100000 || w < 1 ||
      h < 1 || w > 4096 || h > 4096 || !(idleMs >= 0 && idleMs <= 100)) {
    std::fprintf(stderr, "--threads expects [2, 8] or 0 (automatic), --pairs [1, 1000], --frames [1, 100000], --size WxH "
                         "up to 4096, --idle-ms [0, 100]\n");
    return 2;
  }
  g_frame = std::make_unique<SceneFrame>();
  std::string error;
  if (!g_frame->Init(scene, w, h, &error)) {
    std::fprintf(stderr, "scene record benchmark: %s\n", error.c_str());
    return 1;
  }
  g_frame->SetWorkersAlways(!takeOver);
  g_frame->SetIdleMs(idleMs);
  int rc = 0;
  if (smoke) {
    rc = Smoke();
  } else if (contention) {
    rc = Contention(threads < 2 ? 2 : threads, pairs, frames);
  } else {
    for (int k = 0; k < pairs; ++k) {
      const std::string suffix = "/pair:" + std::to_string(k);
      benchmark::RegisterBenchmark(("BM_Scene1Thread" + suffix).c_str(),
                                   [k](benchmark::State& s) { RenderFrames(s, 1, "1/" + std::to_string(k)); })
          ->Unit(benchmark::kMicrosecond)->UseManualTime()->Iterations(frames);
      benchmark::RegisterBenchmark(("BM_SceneThreads" + suffix).c_str(),
                                   [threads, k](benchmark::State& s) { RenderFrames(s, threads, "N/" + std::to_string(k)); })
          ->Unit(benchmark::kMicrosecond)->UseManualTime()->Iterations(frames);
    }
    int n = static_cast<int>(args.size());
    benchmark::Initialize(&n, args.data());
    benchmark::RunSpecifiedBenchmarks();
    std::printf("draws per thread at %d threads: %s\n", threads, DrawsPerThread(g_frame->Stats()).c_str());
    PrintThreadTimes();
    const d3dl::DEVICE_STATS ds = g_frame->DeviceStats();
    std::printf("command pools reset %llu times, host memory started over %llu times\n",
                static_cast<unsigned long long>(ds.CommandPoolResets),
                static_cast<unsigned long long>(ds.CommandPoolRewinds));
    PrintPairs(pairs, threads);
    benchmark::Shutdown();
  }
  g_frame.reset();
  return rc;
}
