#include "FrameConstants.h"

#include <cstring>
#include <utility>

namespace drr {

namespace {
// Upscaling tuning (Docs/Upscaling.md).
constexpr float kUnsharpAmount = 0.5f;          // Directional and Gaussian Unsharp
// TAAU, tuned on the Arena's moving cinematic camera at 0.5 and 0.71
// (Docs/Upscaling.md): history is worth most where nothing moves; each
// resampling of a moving history blurs it, so there the current frame counts more.
constexpr float kHistoryWeightStill = 32.0f;    // most frames' worth of history, still pixels
constexpr float kHistoryWeightMoving = 1.5f;    // ... pixels moving kMotionPixels a frame or more
constexpr float kMotionPixels = 0.25f;          // output pixels per frame counted as fully moving
constexpr float kClipGammaStill = 2.0f;         // neighbourhood box half-size in sigmas
constexpr float kClipGammaMoving = 1.25f;
constexpr float kSampleSigmaStill = 0.4f;       // output pixels: sharp where history accumulates
constexpr float kSampleSigmaMoving = 0.55f;     // smoother where the current frame dominates
constexpr float kClearColor[4] = {0.0f, 0.1f, 0.1f, 1.0f};

float RadicalInverse(uint32_t i, uint32_t base) {
  float f = 1.0f, r = 0.0f;
  for (; i > 0; i /= base) {
    f /= float(base);
    r += f * float(i % base);
  }
  return r;
}
}  // namespace

glm::vec2 UpsampleJitter(uint32_t index) {
  return glm::vec2(RadicalInverse(index + 1, 2), RadicalInverse(index + 1, 3)) - 0.5f;
}

TemporalState AdvanceTemporal(TemporalState h, FrameSetup& s, glm::vec2 ratio, bool symmetric) {
  h.jitterPrev = h.jitterCurr;
  h.ratioPrev = h.ratioCurr;
  h.ratioCurr = ratio;
  h.jitterCurr = glm::vec2(0.f);
  const glm::vec2 viewport(s.sceneViewport.Width, s.sceneViewport.Height);
  if (s.TAA()) {
    // The original's pairs move the scene right and up (+x, +y in clip
    // space); in this struct's y-down pixels the y component changes sign.
    static const glm::vec2 kAsymmetric[2] = {{0.0f, 0.0f}, {0.5f, -0.5f}};
    static const glm::vec2 kSymmetric[2] = {{-0.25f, 0.25f}, {0.25f, -0.25f}};
    h.jitterCurr = (symmetric ? kSymmetric : kAsymmetric)[h.current] / viewport;
  }
  if (s.TAAU()) {
    // Halton jitter; held while paused, since the scene then redraws with its last matrices.
    if (!h.valid) h.jitterIndex = 0;
    const uint32_t index = s.holdJitter ? h.jitterIndex + kUpsampleJitterLength - 1 : h.jitterIndex++;
    h.jitterCurr = UpsampleJitter(index % kUpsampleJitterLength) / viewport;
    h.upsampleCurrent = h.valid ? 1 - h.upsampleCurrent : 0;
    s.historyCur = h.upsampleCurrent;
    s.historyPrev = 1 - h.upsampleCurrent;
    s.historyValid = h.valid;
  }
  if (!h.valid) {
    h.jitterPrev = h.jitterCurr;
    h.ratioPrev = h.ratioCurr;
  }
  s.cur = h.current;
  s.prev = (s.TAA() && h.valid) ? 1 - h.current : h.current;
  return h;
}

void FillConstants(FrameSetup& s, const TemporalState& h, glm::vec2 dyn, glm::vec2 bb) {
  DynamicConstants& dc = s.dc;
  dc = {{h.ratioCurr.x, h.ratioCurr.y}, {h.ratioPrev.x, h.ratioPrev.y}, {h.jitterCurr.x, h.jitterCurr.y},
        {h.jitterPrev.x, h.jitterPrev.y}, {dyn.x, dyn.y}, {1.0f / dyn.x, 1.0f / dyn.y}, {}, {bb.x, bb.y}, {}, 0, {}};
  std::memcpy(dc.clearColor, kClearColor, sizeof kClearColor);
  s.fc = {{bb.x, bb.y}, {1.0f / bb.x, 1.0f / bb.y}, {}, 0, {}};
  std::memcpy(s.fc.clearColor, kClearColor, sizeof kClearColor);
  dc.fixes = s.fc.fixes = s.fixes.bits;
  const glm::vec2 out(s.outputViewport.Width, s.outputViewport.Height);
  const glm::vec2 jitterPx = h.jitterCurr * glm::vec2(s.sceneViewport.Width, s.sceneViewport.Height);
  s.uc = {{out.x, out.y}, {1.0f / out.x, 1.0f / out.y}, {s.TAAU() ? jitterPx.x : 0.0f, s.TAAU() ? jitterPx.y : 0.0f},
          s.historyValid ? 1.0f : 0.0f, kUnsharpAmount, {out.x, out.y}, {1.0f / out.x, 1.0f / out.y},
          {kHistoryWeightStill, kHistoryWeightMoving, kClipGammaStill, kClipGammaMoving},
          {kSampleSigmaStill, kSampleSigmaMoving}, kMotionPixels, 0.0f};
}

void FillResolveConstants(FrameSetup& s) {
  DynamicConstants& rc = s.resolve;
  rc = s.dc;
  if (KindOf(s.filter) == FilterKind::Debug) rc.ratioCurr[0] = rc.ratioCurr[1] = rc.ratioPrev[0] = rc.ratioPrev[1] = 1.0f;
  s.resolveCur = s.pausedSwap ? s.prev : s.cur;
  s.resolvePrev = s.pausedSwap ? s.cur : s.prev;
  if (s.pausedSwap) {
    std::swap(rc.ratioCurr, rc.ratioPrev);
    std::swap(rc.jitterCurr, rc.jitterPrev);
  }
}

}  // namespace drr
