// What the sample measures about its own frames: the original's five GPU
// timers (frame, clear, scene, post-processing, scale), how often each pass
// ran, and the scale each frame rendered at, so that a GPU result that
// arrives a few frames late is paired with its own frame's scale. The passes
// bracket their work with it; the control step and the frame log read it.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>

#include "GPUTimer.h"
#include "d3dl/D3DLike.h"

namespace drr {

// The original's five GPU timers.
struct FrameTimers {
  AveragedGPUTimer frame{10}, clear{10}, scene{10}, postP{10}, scale{10};
  bool Init(d3dl::Device* device);
  void Release();
  bool Update(d3dl::DeviceContext* ctx);  // true when the frame timer has a new average
};

class FrameProfiler {
 public:
  bool Init(d3dl::Device* device);
  void Release();

  // Top of a rendered frame: reads the results that arrived.
  void Poll(d3dl::DeviceContext* ctx) { m_Timers.Update(ctx); }
  const FrameTimers& Timers() const { return m_Timers; }
  FrameTimers& Timers() { return m_Timers; }

  void CountPass(const char* name) { ++m_PassesRun[name]; }
  const std::map<std::string, uint64_t>& PassesRun() const { return m_PassesRun; }

  // End of a frame: the scale X it rendered at (0 for a frame not rendered).
  void EndFrame(int64_t frame, float scaleX);
  // Scale X that frame `frame` rendered at; 0 when it was not rendered or is
  // older than the last kScaleHistory frames (a GPU result's delay is a few).
  double ScaleOfFrame(int64_t frame) const;
  // The scale of the frame the last inner-frame result measured.
  double ScaleOfLastResult(int64_t currentFrame) const {
    return ScaleOfFrame(currentFrame - int64_t(m_Timers.frame.LastDelayFrames()));
  }

  static constexpr size_t kScaleHistory = 64;

 private:
  FrameTimers m_Timers;
  std::map<std::string, uint64_t> m_PassesRun;
  struct FrameScale {
    int64_t frame = -1;
    float scaleX = 0;
  };
  std::array<FrameScale, kScaleHistory> m_Scales{};
};

}  // namespace drr
