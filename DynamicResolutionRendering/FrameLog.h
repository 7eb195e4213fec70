// What the sample records about its frames and hands to tests, scripts and
// users: one record per frame (kept as FrameRecords says), the captures (back buffer with and without the
// GUI, the scene's colour and velocity targets), the screenshot and the JSON
// report.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "DeviceResources.h"
#include "DynamicResolution.h"
#include "FrameProfiler.h"
#include "Options.h"
#include "Readback.h"
#include "RenderTargets.h"

namespace drr {

class Scene;
struct GuiLayout;

struct FrameRecord {
  int64_t frame = 0;
  float scaleX = 1, scaleY = 1;
  uint32_t viewportW = 0, viewportH = 0;
  double cpuFrameMs = 0;
  // Latest GPU results (ms) available at this frame (they lag a few frames).
  double gpuFrame = 0, gpuClear = 0, gpuScene = 0, gpuPostP = 0, gpuScale = 0;
  // True when a new inner-frame GPU result arrived this frame (else gpuFrame
  // repeats an older one), and that result's delay in frames (GPUTimer::LastDelay).
  bool gpuFrameNew = false;
  uint32_t gpuFrameDelay = 0;
  bool rendered = true;  // false while minimised
  uint32_t backBufferW = 0, backBufferH = 0;  // 0x0 while minimised
  bool fullscreen = false;
};

enum class Capture { BackBuffer, BackBufferNoGui, SceneColor, Velocity, Count };

// The sample's state the report describes, besides the frame records.
struct ReportInfo {
  const Options* options = nullptr;
  double refreshHz = 60, budgetMs = 0;
  int lawLatencyFrames = 0;
  std::string adapter, driver, scenePath;
  uint32_t backBuffer[2] = {0, 0}, dynamicRT[2] = {0, 0};
  const RenderTargetSet* targets = nullptr;
  const std::map<std::string, uint64_t>* passesRun = nullptr;
  uint64_t validationMessages = 0;
  int64_t framesRendered = 0, framesMinimised = 0;
  float finalScale[2] = {1, 1};
  const Scene* scene = nullptr;
  const std::vector<std::string>* warnings = nullptr;
  const GuiLayout* gui = nullptr;  // the panel's place when it was drawn (GuiLogic.h)
};

// Where the per-frame records go. Memory: a vector that in-process callers
// read (Frames()), for runs of bounded length (tests, the bench). Stream: an
// anonymous temporary file the report reads back at the end, so resident
// memory stays flat however long the run; Frames() stays empty. Off: no
// records (a run without a report).
enum class FrameRecords { Memory, Stream, Off };

class FrameLog {
 public:
  // Switches the records' storage; records already kept are dropped.
  // False (and Off) when the temporary file cannot be created.
  bool SetRecords(FrameRecords mode);
  FrameRecords Records() const { return m_Mode; }
  // A rendered frame: scales, viewport, sizes and the latest GPU results.
  void AddRendered(int64_t frame, const DynamicResolution& dr, bool dynamic, const BackBuffer& bb, bool fullscreen,
                   double elapsedSeconds, const FrameTimers& timers);
  void AddMinimised(int64_t frame, bool fullscreen);
  const std::vector<FrameRecord>& Frames() const { return m_Frames; }
  // Every record kept, in frame order, from memory or the stream.
  void ForEachFrame(const std::function<void(const FrameRecord&)>& visit) const;

  // Captures: requested for the next frame, queued as copies during it,
  // read once the frame was presented.
  void RequestCapture() { m_Requested = true; }
  bool BeginFrame();  // true when this frame captures
  bool Capturing() const { return m_Capturing; }
  void Queue(d3dl::Device* device, d3dl::DeviceContext* ctx, d3dl::Texture2D* texture, Capture kind);
  void Resolve(d3dl::Device* device, d3dl::DeviceContext* ctx);
  void DropPending() { m_Pending.clear(); }
  const Image& Captured(Capture kind) const { return m_Captured[int(kind)]; }

  bool SaveScreenshot(const std::string& path, bool noGui, std::string* error) const;
  bool WriteReport(const std::string& path, const ReportInfo& info, std::string* error) const;

 private:
  struct Pending {
    d3dl::ComPtr<d3dl::Texture2D> staging;
    Capture kind;
  };
  void Add(const FrameRecord& r);
  struct CloseFile {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  FrameRecords m_Mode = FrameRecords::Memory;
  std::vector<FrameRecord> m_Frames;
  std::unique_ptr<std::FILE, CloseFile> m_Stream;
  bool m_StreamFailed = false;
  bool m_Requested = false, m_Capturing = false;
  std::vector<Pending> m_Pending;
  Image m_Captured[int(Capture::Count)];
};

}  // namespace drr
