// The frame's decisions, made once from the settings and what the frame
// starts from: the path (forward or deferred, dynamic or full resolution),
// the temporal mode, the filter's kind, the render targets the frame needs,
// the ordered list of passes it records (named as the report's passes_run
// counts them), the viewports, history indices and constants the passes read
// (FrameConstants.h), the scene's parameters and the temporal state the frame
// leaves behind. PlanFrame is a pure function: the same settings and inputs
// give the same plan, so the plan of every mode is unit-tested on the CPU
// (Tests/sample/FramePlanTest.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "DynamicResolution.h"
#include "FrameConstants.h"
#include "Options.h"
#include "RenderTargets.h"
#include "ResolveFilters.h"
#include "scene/Scene.h"

namespace drr {

// The passes of passes/, one object each (PassRegistry.h).
enum class PassId {
  MarkOutside,     // test aid: marks what lies outside the viewport (not counted)
  ClearFinalNone,  // None shows the whole RT: its final target zeroed
  Clear,           // ClearPS or ClearAPI
  Scene,           // the forward scene
  ShadowMaps, GBuffer, SSAO, Lighting,  // the deferred scene (Docs/Deferred.md)
  MotionBlur,
  Resolve,           // the resolve filter or spatial upscale (ResolveFilters.h)
  TemporalUpsample,  // TAAU (Docs/Upscaling.md)
  Sharpen, SecondaryUpscale,
  ZoomBox, GUI,
  Count
};

// The original's timer brackets, in frame order: each stage's passes run
// inside its GPU timer (FrameTimers), started and stopped even when the
// stage has no pass this frame, as the original's are.
enum class PassStage { Prepare, Clear, Scene, Post, Scale, Overlay, Gui, Count };

struct PlannedPass {
  PassId id;
  std::string name;  // as counted in passes_run
  PassStage stage;
};

// What the plan reads besides the settings.
struct FrameInputs {
  uint32_t backBufferW = 1, backBufferH = 1;
  d3dl::DXGI_FORMAT backBufferFormat = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;  // the zoom box copies it
  uint32_t shadowedLights = 0;  // the scene's spot lights that cast shadows
  bool guiDrawn = false;        // the panel or the text draws this frame
  bool softwareAdapter = false; // a CPU rasteriser (--upscale-shader auto then picks pixel shaders)
  // Dynamic resolution after this frame's control step (DynamicResolution).
  DynamicViewport viewport;
  uint32_t dynamicW = 1, dynamicH = 1;  // the dynamic RT
  glm::vec2 rtScale{1.0f};              // viewport / dynamic RT
  float scaleX = 1.0f;
  TemporalState history;  // as the last frame left it (TemporalHistory)
  // The camera, and the eye of the specular term without and with fix camera-eye.
  CameraPose camera;
  glm::vec3 firstPersonEye{0.0f}, viewingEye{0.0f};
  bool resetVelocity = false;  // the scene's previous matrices restart (first frame, resize, cut)
};

struct FramePlan {
  bool dynamic = true, deferred = false;
  TemporalMode temporal = TemporalMode::None;
  FilterKind filterKind = FilterKind::Spatial;
  // The final/velocity pair alternates each frame (the original's test,
  // quirk included: see PlanFrame).
  bool flipsTargets = false;
  bool secondary = false;  // the secondary upscale runs after the primary
  RenderTargetPlan targets;
  std::vector<PlannedPass> passes;  // in recording order
  FrameSetup setup;                 // viewports, indices, constants
  SceneRenderParams scene;          // the scene pass's (forward or G-buffer)
  DeferredFrame deferredFrame;
  TemporalState history;            // what this frame leaves (TemporalHistory::Commit)

  bool TAA() const { return temporal == TemporalMode::TAA; }
  bool TAAU() const { return temporal == TemporalMode::TAAU; }
  bool Runs(const std::string& pass) const;
  bool Runs(PassId pass) const;
  std::vector<std::string> PassNames() const;
  std::vector<RT> NeededTargets() const;  // in the table's order
};

FramePlan PlanFrame(const Options& options, const FrameInputs& inputs);

}  // namespace drr
