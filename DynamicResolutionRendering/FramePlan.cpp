#include "FramePlan.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "DeferredSettings.h"
#include "scene/RecordingThreads.h"

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

bool ShadowMapsDrawn(const Options& o, const FrameInputs& in) {
  return o.renderer == Renderer::Deferred && o.localLights && in.shadowedLights > 0;
}

RenderTargetPlan TargetsOf(const Options& o, const FrameInputs& in, TemporalMode temporal) {
  RenderTargetPlan p;
  p.dynamic = o.dynamicResolution;
  p.superSampling = o.superSampling;
  p.motionBlur = o.motionBlur;
  p.temporal = temporal;
  p.srgbColour = o.fixes.Has(Fix::SrgbTargets);
  p.backBufferW = in.backBufferW;
  p.backBufferH = in.backBufferH;
  // Upscaling (Docs/Upscaling.md): the sharpening pass and the secondary upscale's output size.
  p.sharpenPass = o.dynamicResolution && KindOf(o.filter) == FilterKind::SpatialSharpen;
  const double secondary = o.dynamicResolution ? o.secondaryScreenPercentage / 100.0 : 1.0;
  p.outputW = std::max(1u, uint32_t(std::lround(in.backBufferW * secondary)));
  p.outputH = std::max(1u, uint32_t(std::lround(in.backBufferH * secondary)));
  // Deferred shading (Docs/Deferred.md): the G-buffer exists only with it.
  p.deferred = o.renderer == Renderer::Deferred;
  p.ssao = p.deferred && o.ssao;
  // Its shadow maps: a slice per shadowed spot when they are drawn, else the
  // lighting pass's 1x1 placeholder.
  const bool shadows = ShadowMapsDrawn(o, in);
  p.shadowSlices = !p.deferred ? 0 : shadows ? in.shadowedLights : 1;
  p.shadowMapSize = !p.deferred ? 0 : shadows ? o.shadowMapSize : 1;
  p.zoomBox = o.zoom;
  p.backBufferFormat = in.backBufferFormat;
  return p;
}

using PassList = std::vector<PlannedPass>;

// The scene's part: the forward scene pass, or the deferred renderer's.
void ScenePasses(const FramePlan& p, const Options& o, const FrameInputs& in, PassList* out) {
  if (!p.deferred) {
    out->push_back({PassId::Scene, "Scene", PassStage::Scene});
    return;
  }
  if (ShadowMapsDrawn(o, in)) out->push_back({PassId::ShadowMaps, "ShadowMaps", PassStage::Scene});
  out->push_back({PassId::GBuffer, "GBuffer", PassStage::Scene});
  if (p.targets.ssao) out->push_back({PassId::SSAO, "SSAO", PassStage::Scene});
  out->push_back({PassId::Lighting, "Lighting", PassStage::Scene});
}

// The resolve filter's pass name (the fast variant reads the velocity motion
// blur left in the colour's alpha), then sharpening and the secondary upscale.
void ScalePasses(const FramePlan& p, const Options& o, PassList* out) {
  if (!p.dynamic) return;
  const FilterInfo& f = GetFilterInfo(o.filter);
  const PassId primary = p.TAAU() ? PassId::TemporalUpsample : PassId::Resolve;
  out->push_back({primary, o.motionBlur && f.fastShader ? f.fastPass : f.pass, PassStage::Scale});
  if (p.filterKind == FilterKind::SpatialSharpen) out->push_back({PassId::Sharpen, "Sharpen", PassStage::Scale});
  if (p.secondary) out->push_back({PassId::SecondaryUpscale, "SecondaryUpscale", PassStage::Scale});
}

PassList PassesOf(const FramePlan& p, const Options& o, const FrameInputs& in) {
  PassList passes;
  const bool wholeTarget = p.dynamic && p.filterKind == FilterKind::Debug;  // None shows the whole RT
  const bool noneFix = o.fixes.Has(Fix::NoneShowsRT);
  if (p.dynamic && o.debugMarkerOutside) passes.push_back({PassId::MarkOutside, "MarkOutside", PassStage::Prepare});
  // Zeroed before the scene with the fix; the original zeroes it after.
  if (wholeTarget && noneFix) passes.push_back({PassId::ClearFinalNone, "ClearFinalNone", PassStage::Prepare});
  passes.push_back({PassId::Clear, o.psClear ? "ClearPS" : "ClearAPI", PassStage::Clear});
  ScenePasses(p, o, in, &passes);
  if (wholeTarget && !noneFix) passes.push_back({PassId::ClearFinalNone, "ClearFinalNone", PassStage::Post});
  if (o.motionBlur)
    passes.push_back({PassId::MotionBlur, p.dynamic ? "MotionBlurDynamic" : "MotionBlurFull", PassStage::Post});
  ScalePasses(p, o, &passes);
  if (o.zoom) passes.push_back({PassId::ZoomBox, "ZoomBox", PassStage::Overlay});
  if (in.guiDrawn) passes.push_back({PassId::GUI, "GUI", PassStage::Gui});
  return passes;
}

// The viewports, TAA jitter, ratios, target indices and constants; returns
// the temporal state the frame leaves.
TemporalState SetupOf(const FramePlan& p, const Options& o, const FrameInputs& in, FrameSetup* s) {
  s->dynamic = p.dynamic;
  s->temporal = p.temporal;
  s->motionBlur = o.motionBlur;
  s->psClear = o.psClear;
  s->filter = o.filter;
  s->fixes = o.fixes;
  s->backBufferViewport = {0, 0, float(in.backBufferW), float(in.backBufferH), 0, 1};
  const DynamicViewport& v = in.viewport;
  s->sceneViewport = p.dynamic ? d3dl::VIEWPORT{v.TopLeftX, v.TopLeftY, v.Width, v.Height, v.MinDepth, v.MaxDepth}
                               : s->backBufferViewport;
  s->secondary = p.secondary;
  s->holdJitter = o.pause;
  s->computeUpscale = UseComputeUpscale(o.upscaleShader, in.softwareAdapter);
  s->outputViewport = p.secondary ? d3dl::VIEWPORT{0, 0, float(p.targets.outputW), float(p.targets.outputH), 0, 1}
                                  : s->backBufferViewport;
  TemporalState h = in.history;
  h.current = p.flipsTargets ? 1 - h.current : 0;
  h = AdvanceTemporal(h, *s, p.dynamic ? in.rtScale : glm::vec2(1.f), o.symmetricTAA);
  FillConstants(*s, h, glm::vec2(in.dynamicW, in.dynamicH), glm::vec2(in.backBufferW, in.backBufferH));
  // The original's paused TAA resolve reads target 0 as the current frame.
  s->pausedSwap = o.pause && s->TAA() && s->cur == 1;
  FillResolveConstants(*s);
  return h;
}

std::vector<std::string> SplitCommas(const std::string& list) {
  std::vector<std::string> out;
  for (size_t at = 0; at < list.size();) {
    const size_t comma = std::min(list.find(',', at), list.size());
    if (comma > at) out.push_back(list.substr(at, comma - at));
    at = comma + 1;
  }
  return out;
}

SceneRenderParams SceneOf(const FramePlan& p, const Options& o, const FrameInputs& in, const TemporalState& h) {
  const float aspect = float(std::max(in.backBufferW, 1u)) / float(std::max(in.backBufferH, 1u));
  SceneRenderParams sp;
  sp.view = in.camera.view;
  sp.proj = glm::perspectiveRH_ZO(in.camera.fovY, aspect, in.camera.nearZ, in.camera.farZ);
  // Jitter in pixels (x right, y down) -> NDC (+Y up).
  sp.jitterNdc = glm::vec2(2.0f * h.jitterCurr.x, -2.0f * h.jitterCurr.y);
  sp.mipBiasSampler = p.TAA() && o.taaMipBias;
  // TAAU's automatic view mip bias: log2(screen percentage) + the user's bias.
  if (p.TAAU() && o.autoMipBias) sp.viewMipBias = std::log2(in.scaleX) + float(o.mipBias);
  sp.mipBiasOptOut = SplitCommas(o.mipBiasOptOut);
  sp.resetHistory = in.resetVelocity;
  sp.paused = o.pause;
  sp.target = h.current;
  sp.showCameras = o.showCameras;
  sp.shadingEye = o.fixes.Has(Fix::CameraEye) ? in.viewingEye : in.firstPersonEye;
  sp.frustumCulling = o.fixes.Has(Fix::FrustumCull);
  sp.tessellation.enabled = o.tessellation;
  sp.tessellation.pixelsPerEdge = float(o.tessPixelsPerEdge);
  sp.tessellation.maxFactor = float(o.maxTessFactor);
  sp.tessellation.viewportHeight = p.setup.sceneViewport.Height;  // the dynamic viewport: factors follow the scale
  sp.recordingThreads = RecordingThreadsFor(o.threads);
  sp.gbuffer = p.deferred;  // the deferred scene writes its materials (GBufferPass)
  // Velocity is written where a pass reads it (ChooseSceneTargets).
  sp.writeVelocity = p.dynamic ? (o.motionBlur || p.TAA() || p.TAAU()) : o.motionBlur;
  sp.viewport = p.setup.sceneViewport;  // deferred contexts set it themselves
  return sp;
}

// The shadow maps' dynamic scale (their law on the main scale) and the
// G-buffer's read ratio: the resolve's RT scale on the dynamic path, back
// buffer / G-buffer (the dynamic RT's size) on the full one.
DeferredFrame DeferredOf(const FramePlan& p, const Options& o, const FrameInputs& in) {
  DeferredFrame f;
  f.ssao = p.targets.ssao;
  f.localLights = o.localLights;
  f.shadowScale = ShadowMapScale(o.shadowLaw, float(o.shadowScale), p.dynamic ? in.scaleX : 1.0f);
  const FrameSetup& s = p.setup;
  f.ratio = p.dynamic ? glm::vec2(s.dc.ratioCurr[0], s.dc.ratioCurr[1])
                      : glm::vec2(s.sceneViewport.Width / float(in.dynamicW), s.sceneViewport.Height / float(in.dynamicH));
  return f;
}
}  // namespace

bool FramePlan::Runs(const std::string& pass) const {
  return std::any_of(passes.begin(), passes.end(), [&](const PlannedPass& p) { return p.name == pass; });
}

bool FramePlan::Runs(PassId pass) const {
  return std::any_of(passes.begin(), passes.end(), [&](const PlannedPass& p) { return p.id == pass; });
}

std::vector<std::string> FramePlan::PassNames() const {
  std::vector<std::string> names;
  for (const PlannedPass& p : passes) names.push_back(p.name);
  return names;
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
  p.passes = PassesOf(p, o, in);
  p.history = SetupOf(p, o, in, &p.setup);
  p.scene = SceneOf(p, o, in, p.history);
  p.deferredFrame = DeferredOf(p, o, in);
  // A temporal filter's history holds this frame once it has resolved.
  if (p.TAA() || p.TAAU()) p.history.valid = true;
  return p;
}

}  // namespace drr
