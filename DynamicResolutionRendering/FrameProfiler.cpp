#include "FrameProfiler.h"

namespace drr {

bool FrameTimers::Init(d3dl::Device* device) {
  for (AveragedGPUTimer* t : {&frame, &clear, &scene, &postP, &scale})
    if (d3dl::FAILED(t->Init(device))) return false;
  return true;
}

void FrameTimers::Release() {
  for (AveragedGPUTimer* t : {&frame, &clear, &scene, &postP, &scale}) t->Release();
}

bool FrameTimers::Update(d3dl::DeviceContext* ctx) {
  const bool newAverage = frame.Update(ctx);
  for (AveragedGPUTimer* t : {&clear, &scene, &postP, &scale}) t->Update(ctx);
  return newAverage;
}

bool FrameProfiler::Init(d3dl::Device* device) { return m_Timers.Init(device); }

void FrameProfiler::Release() { m_Timers.Release(); }

void FrameProfiler::EndFrame(int64_t frame, float scaleX) {
  if (frame < 0) return;
  m_Scales[size_t(frame) % kScaleHistory] = {frame, scaleX};
}

double FrameProfiler::ScaleOfFrame(int64_t frame) const {
  if (frame < 0) return 0.0;
  const FrameScale& s = m_Scales[size_t(frame) % kScaleHistory];
  return s.frame == frame ? double(s.scaleX) : 0.0;
}

}  // namespace drr
