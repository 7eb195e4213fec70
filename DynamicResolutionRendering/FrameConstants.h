// The frame's numbers, computed once by PlanFrame (FramePlan.h) and read by
// the passes: viewports, the final/velocity and TAAU history indices, the
// jitter and RT ratios of this frame and the last (TemporalState), and the
// constant buffers of the post-processing shaders.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "Fixes.h"
#include "ResolveFilters.h"
#include "TemporalMode.h"
#include "d3dl/D3DLike.h"

namespace drr {

// Constants of PostProcessDynamic.hlsl (cbPostProcessDynamic).
struct DynamicConstants {
  float ratioCurr[2], ratioPrev[2];
  float jitterCurr[2], jitterPrev[2];
  float dynSize[2], invDynSize[2];
  float noiseOffset[2], backBufferSize[2];
  float clearColor[4];
  uint32_t fixes;  // FixSet bits (Shaders/FixList.hlsli)
  uint32_t pad[3];
};
static_assert(sizeof(DynamicConstants) == 96);

// Constants of PostProcess.hlsl (cbPostProcess), the full-resolution path.
struct FullConstants {
  float size[2], invSize[2];
  float clearColor[4];
  uint32_t fixes;  // FixSet bits (Shaders/FixList.hlsli)
  float pad[7];
};
static_assert(sizeof(FullConstants) == 64);

// Constants of the upscalers (Shaders/UpscaleCommon.hlsli, cbUpscale at b1).
struct UpscaleConstants {
  float outputSize[2], invOutputSize[2];
  float jitterPx[2];      // TAAU: this frame's jitter in dynamic pixels (y down)
  float historyValid;     // TAAU: 0 on a reset
  float sharpness;        // unsharp amount of Directional and Gaussian Unsharp
  float sourceSize[2], invSourceSize[2];  // the secondary upscale's source
  float temporalParams[4];  // max history weight still / moving, clip gamma still / moving
  // TAAU: a sample's weight falls as (1 - d^2 / (2.2 sigma)^2)^2, d in output
  // pixels, sigma still / moving; and the output pixels per frame counted as fully moving.
  float sampleSigma[2];
  float motionPixels;
  float pad;
};
static_assert(sizeof(UpscaleConstants) == 80);

// TAAU's sub-pixel jitter: Halton(2, 3) points 1..kUpsampleJitterLength,
// centred on 0 (dynamic pixels, each axis in (-0.5, 0.5)).
constexpr uint32_t kUpsampleJitterLength = 16;
glm::vec2 UpsampleJitter(uint32_t index);

// The viewports, indices and constants of one frame.
struct FrameSetup {
  bool dynamic = true, motionBlur = true, psClear = true;
  TemporalMode temporal = TemporalMode::None;  // FramePlan::temporal
  Filter filter = Filter::TAA;
  FixSet fixes;
  int cur = 0, prev = 0;  // final/velocity targets written and read as history
  // The original's paused TAA with target 1 current: the resolve reads target 0
  // as current and 1 as history, with their jitters and ratios swapped.
  bool pausedSwap = false;
  // What the resolve reads: its constants (None's ratios 1, the paused swap
  // applied; the Noise offset is the pass's) and its current / history targets.
  DynamicConstants resolve{};
  int resolveCur = 0, resolvePrev = 0;
  d3dl::VIEWPORT sceneViewport{}, backBufferViewport{};
  DynamicConstants dc{};
  FullConstants fc{};
  // Upscaling (Docs/Upscaling.md). outputViewport: what the primary upscale
  // (spatial or TAAU) writes, the back buffer's unless the secondary upscale runs.
  bool secondary = false, holdJitter = false;
  bool computeUpscale = false;  // the upscalers as compute passes (ComputeUpscale.h)
  int historyCur = 0, historyPrev = 0;  // TAAU's output-resolution history pair
  bool historyValid = false;
  d3dl::VIEWPORT outputViewport{};
  UpscaleConstants uc{};

  bool TAA() const { return temporal == TemporalMode::TAA; }
  bool TAAU() const { return temporal == TemporalMode::TAAU; }
};

// The temporal filters' state between frames (TemporalHistory.h owns it):
// which final/velocity target the last frame wrote, whether the other one
// holds a frame of the current allocation, the jitter (fractions of the
// viewport) and RT ratios of the last frame and the one before.
struct TemporalState {
  int current = 0;
  bool valid = false;
  glm::vec2 jitterCurr{0.f}, jitterPrev{0.f}, ratioCurr{1.f}, ratioPrev{1.f};
  // TAAU: which history target the last frame wrote and the next jitter
  // index; both restart when the history is invalid (valid is shared with TAA).
  int upsampleCurrent = 0;
  uint32_t jitterIndex = 0;
  bool operator==(const TemporalState&) const = default;
};

// This frame's state from the last (current already chosen): the original's
// jitter pair ((0,0)/(0.5,0.5) px, or -0.25/+0.25 px symmetric, in clip-space
// directions: x right, y up) or TAAU's Halton point, the ratios, and s.cur,
// s.prev and TAAU's indices. The viewports are already in s.
TemporalState AdvanceTemporal(TemporalState h, FrameSetup& s, glm::vec2 ratio, bool symmetric);
// The constants of both post-processing paths for this frame (the fixes from s.fixes).
void FillConstants(FrameSetup& s, const TemporalState& h, glm::vec2 dynamicRT, glm::vec2 backBuffer);

// The resolve's view of the frame (FrameSetup::resolve), after pausedSwap is set.
void FillResolveConstants(FrameSetup& s);

// The deferred part of the frame (Docs/Deferred.md).
struct DeferredFrame {
  bool ssao = true;
  bool localLights = true;      // the scene's LIGHT entries (and their shadow maps)
  float shadowScale = 1.0f;     // the shadow maps' dynamic scale (ShadowMapScale)
  glm::vec2 ratio{1.0f};        // viewport / G-buffer size: DynamicResolution's RT scale
};

}  // namespace drr
