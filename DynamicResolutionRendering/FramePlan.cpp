#include "FramePlan.h"

#include <algorithm>
#include <cmath>

namespace drr {

namespace {
TemporalMode TemporalOf(const Options& o) {
  // Only with dynamic resolution on does a temporal filter keep a history.
  if (!o.dynamicResolution) return TemporalMode::None;
  switch (KindOf(o.filter)) {
    case FilterKind::TemporalAA: return TemporalMode::TAA;
    case FilterKind::TemporalUpsample: return TemporalMode::TAAU;
    default: return TemporalMode::None;
  }
}

RenderTargetPlan TargetsOf(const Options& o, const FrameInputs& in, TemporalMode temporal) {
  RenderTargetPlan p;
  p.dynamic = o.dynamicResolution;
  p.superSampling = o.superSampling;
  p.motionBlur = o.motionBlur;
  p.taa = temporal == TemporalMode::TAA;
  p.srgbColour = o.fixes.Has(Fix::SrgbTargets);
  p.backBufferW = in.backBufferW;
  p.backBufferH = in.backBufferH;
  // Upscaling (Docs/Upscaling.md): TAAU's history and the secondary upscale's output size.
  p.taau = temporal == TemporalMode::TAAU;
  p.sharpenPass = o.dynamicResolution && KindOf(o.filter) == FilterKind::SpatialSharpen;
  const double secondary = o.dynamicResolution ? o.secondaryScreenPercentage / 100.0 : 1.0;
  p.outputW = std::max(1u, uint32_t(std::lround(in.backBufferW * secondary)));
  p.outputH = std::max(1u, uint32_t(std::lround(in.backBufferH * secondary)));
  // Deferred shading (Docs/Deferred.md): the G-buffer exists only with it.
  p.deferred = o.renderer == Renderer::Deferred;
  p.ssao = p.deferred && o.ssao;
  return p;
}

// The scene's part: the forward scene pass, or the deferred renderer's.
void ScenePasses(const FramePlan& p, const Options& o, const FrameInputs& in, std::vector<std::string>* out) {
  if (!p.deferred) {
    out->push_back("Scene");
    return;
  }
  if (o.localLights && in.shadowedLights > 0) out->push_back("ShadowMaps");
  out->push_back("GBuffer");
  if (p.targets.ssao) out->push_back("SSAO");
  out->push_back("Lighting");
}

// The resolve filter's pass name (the fast variant reads the velocity motion
// blur left in the colour's alpha), then sharpening and the secondary upscale.
void ScalePasses(const FramePlan& p, const Options& o, std::vector<std::string>* out) {
  if (!p.dynamic) return;
  const FilterInfo& f = GetFilterInfo(o.filter);
  out->push_back(o.motionBlur && f.fastShader ? f.fastPass : f.pass);
  if (p.filterKind == FilterKind::SpatialSharpen) out->push_back("Sharpen");
  if (p.secondary) out->push_back("SecondaryUpscale");
}
}  // namespace

bool FramePlan::Runs(const std::string& pass) const {
  return std::find(passes.begin(), passes.end(), pass) != passes.end();
}

std::vector<RT> FramePlan::NeededTargets() const {
  std::vector<RT> rts;
  for (int i = 0; i < int(RT::Count); ++i)
    if (RenderTargetSet::Needed(RT(i), targets)) rts.push_back(RT(i));
  return rts;
}

FramePlan PlanFrame(const Options& o, const FrameInputs& in) {
  FramePlan p;
  p.dynamic = o.dynamicResolution;
  p.deferred = o.renderer == Renderer::Deferred;
  p.temporal = TemporalOf(o);
  p.filterKind = KindOf(o.filter);
  // The original flips the final/velocity pair when `enabled && TAA || TAA_NO
  // || TAA_BASIC`: by operator precedence TAA Noise Offset and TAA Basic flip
  // it with dynamic resolution off too, where a paused scene then alternates
  // between its last two frames. The taa-flip fix flips only when TAA runs.
  const bool quirk = o.filter == Filter::TAANoiseOffset || o.filter == Filter::TAABasic;
  p.flipsTargets = p.TAA() || (!o.fixes.Has(Fix::TaaFlip) && quirk);
  p.targets = TargetsOf(o, in, p.temporal);
  p.secondary = p.dynamic && p.targets.Secondary();

  std::vector<std::string>& passes = p.passes;
  const bool wholeTarget = p.dynamic && p.filterKind == FilterKind::Debug;  // None shows the whole RT
  const bool noneFix = o.fixes.Has(Fix::NoneShowsRT);
  if (wholeTarget && noneFix) passes.push_back("ClearFinalNone");  // zeroed before the scene
  passes.push_back(o.psClear ? "ClearPS" : "ClearAPI");
  ScenePasses(p, o, in, &passes);
  if (wholeTarget && !noneFix) passes.push_back("ClearFinalNone");  // the original: after the scene
  if (o.motionBlur) passes.push_back(p.dynamic ? "MotionBlurDynamic" : "MotionBlurFull");
  ScalePasses(p, o, &passes);
  if (o.zoom) passes.push_back("ZoomBox");
  if (in.guiDrawn) passes.push_back("GUI");
  return p;
}

}  // namespace drr
