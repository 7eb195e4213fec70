// What every pass of the frame shares: the frame it records into (PassFrame)
// and the Pass interface. A pass is one object (PassRegistry.h) that loads
// its shaders, creates its device objects once and records itself when the
// frame plan (FramePlan.h) lists it. Pass::Run brackets each recording with
// a debug event and the pass count of the profiler; the registry's loop runs
// the stage timers around them.
#pragma once

#include <functional>
#include <string>

#include "DeviceResources.h"
#include "FramePlan.h"
#include "FrameProfiler.h"
#include "RenderTargets.h"
#include "ShaderLibrary.h"
#include "d3dl/D3DLike.h"

namespace drr {

class Scene;

// Where the scene draws (colour, velocity when needed, depth).
struct SceneTargets {
  d3dl::RenderTargetView* rtv[2] = {nullptr, nullptr};
  uint32_t count = 1;
  d3dl::DepthStencilView* dsv = nullptr;
  d3dl::Texture2D* colour = nullptr;
  d3dl::Texture2D* velocity = nullptr;
};
SceneTargets ChooseSceneTargets(RenderTargetSet& targets, const FrameSetup& setup, const BackBuffer& bb);

// One frame as the passes see it.
struct PassFrame {
  d3dl::DeviceContext* ctx = nullptr;
  const FramePlan* plan = nullptr;
  RenderTargetSet* targets = nullptr;
  SceneTargets scene;
  BackBuffer backBuffer;
  drr::Scene* sceneData = nullptr;
  FrameProfiler* profiler = nullptr;
  float zoomCentre[2] = {0.5f, 0.5f};  // UV of the back buffer
  // The GUI pass: builds and draws the panel; true when it drew.
  std::function<bool(d3dl::DeviceContext*)> gui;

  const FrameSetup& Setup() const { return plan->setup; }
  RenderTargetSet& RTs() const { return *targets; }
};

class Pass {
 public:
  virtual ~Pass() = default;
  // Device objects other than shaders (after the first LoadShaders).
  virtual bool Init(d3dl::Device*, std::string*) { return true; }
  virtual bool LoadShaders(ShaderLoad&) { return true; }
  virtual void Release() {}
  // Debug event, Record, and the pass count (under `name`) when it recorded.
  void Run(PassFrame& f, const std::string& name);

 protected:
  // False when nothing was recorded (not counted).
  virtual bool Record(PassFrame& f) = 0;
};

}  // namespace drr
