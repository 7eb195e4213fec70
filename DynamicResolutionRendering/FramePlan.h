// The frame's decisions, made once from the settings: the path (forward or
// deferred, dynamic or full resolution), the temporal mode, the filter's
// kind, the render targets the frame needs, and the ordered list of passes
// it records (named as the report's passes_run counts them). PlanFrame is a
// pure function: the same settings and inputs give the same plan, so the
// plan of every mode is unit-tested on the CPU (Tests/sample/FramePlanTest.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Options.h"
#include "RenderTargets.h"
#include "ResolveFilters.h"

namespace drr {

enum class TemporalMode { None, TAA, TAAU };

// What the plan reads besides the settings.
struct FrameInputs {
  uint32_t backBufferW = 1, backBufferH = 1;
  uint32_t shadowedLights = 0;  // the scene's spot lights that cast shadows
  bool guiDrawn = false;        // the panel or the text draws this frame
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
  std::vector<std::string> passes;  // in recording order

  bool TAA() const { return temporal == TemporalMode::TAA; }
  bool TAAU() const { return temporal == TemporalMode::TAAU; }
  bool Runs(const std::string& pass) const;
  std::vector<RT> NeededTargets() const;  // in the table's order
};

FramePlan PlanFrame(const Options& options, const FrameInputs& inputs);

}  // namespace drr
