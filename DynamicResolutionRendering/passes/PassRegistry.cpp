#include "passes/PassRegistry.h"

#include "passes/Passes.h"

#include "ComputeUpscale.h"

namespace drr {

namespace {
// The original's GPU timer of each stage (none for the first and the last two).
AveragedGPUTimer* StageTimer(FrameTimers& t, PassStage stage) {
  switch (stage) {
    case PassStage::Clear: return &t.clear;
    case PassStage::Scene: return &t.scene;
    case PassStage::Post: return &t.postP;
    case PassStage::Scale: return &t.scale;
    default: return nullptr;
  }
}

// Post-processing: the passes whose compiled shaders a reload reports.
bool IsPostProcessing(PassId id) {
  return id == PassId::Clear || (id >= PassId::MotionBlur && id <= PassId::SecondaryUpscale);
}
}  // namespace

PassRegistry::PassRegistry() {
  auto set = [this](PassId id, Pass* pass) { m_Passes[size_t(id)].reset(pass); };
  set(PassId::MarkOutside, new MarkOutsidePass);
  set(PassId::ClearFinalNone, new ClearFinalNonePass);
  set(PassId::Clear, new ClearPass(m_Kit));
  set(PassId::Scene, new ScenePass);
  set(PassId::ShadowMaps, new ShadowMapPass(m_Deferred));
  set(PassId::GBuffer, new GBufferPass(m_Deferred));
  set(PassId::SSAO, new SSAOPass(m_Kit, m_Deferred));
  set(PassId::Lighting, new LightingPass(m_Kit, m_Deferred));
  set(PassId::MotionBlur, new MotionBlurPass(m_Kit));
  set(PassId::Resolve, new ResolvePass(m_Kit));
  set(PassId::TemporalUpsample, new TemporalUpsamplePass(m_Kit));
  set(PassId::Sharpen, new SharpenPass(m_Kit));
  set(PassId::SecondaryUpscale, new SecondaryUpscalePass(m_Kit));
  set(PassId::ZoomBox, new ZoomBoxPass(m_Kit));
  set(PassId::GUI, new GuiPass);
}

PassRegistry::~PassRegistry() = default;

bool PassRegistry::Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error) {
  m_Device = device;
  m_Compute.reset();  // a second Init (renderer or device change) makes it anew on this device
  size_t compiled = 0;
  if (!LoadShaders(shaders, false, error, &compiled) || !m_Kit.Init(device, error) ||
      !m_Deferred.Init(device, error))
    return false;
  for (auto& pass : m_Passes)
    if (!pass->Init(device, error)) return false;
  m_Compute = std::make_unique<ComputeUpscale>();
  std::string computeUnavailable;  // then its Record declines, with a notice, and Scale records pixel shaders
  m_Compute->Init(device, shaders, &computeUnavailable);
  return true;
}

bool PassRegistry::LoadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error,
                               size_t* postCompiled) {
  ShaderLoad post{m_Device, &shaders, fromSource, error}, other = post;
  bool ok = m_Kit.LoadShaders(post);
  for (size_t i = 0; ok && i < m_Passes.size(); ++i)
    ok = m_Passes[i]->LoadShaders(IsPostProcessing(PassId(i)) ? post : other);
  *postCompiled = post.compiled;
  size_t computeCompiled = 0;
  if (ok && m_Compute) ok = m_Compute->LoadShaders(shaders, fromSource, error, &computeCompiled);
  *postCompiled += computeCompiled;
  return ok;
}

void PassRegistry::Release() {
  for (auto& pass : m_Passes) pass->Release();
  if (m_Compute) m_Compute->Release();
  m_Compute.reset();
  m_Deferred.Release();
  m_Kit.Release();
}

// The Scale stage's passes as ComputeUpscale's dispatches (counted under the
// same pass names); false where the plan wants pixel shaders, the stage is
// empty, the filter is one of the original's or the device cannot.
bool PassRegistry::RecordedAsCompute(PassFrame& frame, PassStage stage) {
  if (stage != PassStage::Scale || !frame.Setup().computeUpscale || !m_Compute) return false;
  bool any = false;
  for (const PlannedPass& p : frame.plan->passes) any = any || p.stage == stage;
  return any && m_Compute->Record(frame.ctx, frame.Setup(), frame.RTs(), frame.backBuffer, frame.profiler);
}

void PassRegistry::Record(PassFrame& frame, const std::function<void(PassStage)>& afterStage) {
  FrameTimers& timers = frame.profiler->Timers();
  for (int stage = 0; stage < int(PassStage::Count); ++stage) {
    AveragedGPUTimer* timer = StageTimer(timers, PassStage(stage));
    if (timer) timer->Start(frame.ctx);
    if (!RecordedAsCompute(frame, PassStage(stage)))
      for (const PlannedPass& p : frame.plan->passes)
        if (p.stage == PassStage(stage)) m_Passes[size_t(p.id)]->Run(frame, p.name);
    if (timer) timer->Stop(frame.ctx);
    afterStage(PassStage(stage));
  }
}

}  // namespace drr
