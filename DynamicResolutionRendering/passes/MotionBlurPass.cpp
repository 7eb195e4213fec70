#include "passes/Passes.h"

namespace drr {

bool MotionBlurPass::LoadShaders(ShaderLoad& load) {
  return load.Load({}, {{"PostProcessDynamic_MotionBlurPS", &m_Dynamic}, {"PostProcess_MotionBlurPS", &m_Full}});
}

void MotionBlurPass::Release() { m_Dynamic = m_Full = nullptr; }

// Into the final target (dynamic) or the back buffer (full resolution).
bool MotionBlurPass::Record(PassFrame& f) {
  const FrameSetup& s = f.Setup();
  RenderTargetSet& rts = f.RTs();
  Target(f.ctx, s.dynamic ? rts.Final(s.cur).rtv.Get() : f.backBuffer.rtv, s.sceneViewport);
  BindSamplers(f.ctx);
  const RenderTarget& colour = rts[s.dynamic ? RT::ColorDynamic : RT::ColorFull];
  const RenderTarget& velocity = rts[s.dynamic ? RT::VelocityDynamic0 : RT::VelocityFull];
  if (s.dynamic) DrawDynamic(f.ctx, m_Dynamic.Get(), s.dc, {colour.srv.Get(), nullptr, velocity.srv.Get()});
  else DrawFull(f.ctx, m_Full.Get(), s.fc, {colour.srv.Get(), nullptr, velocity.srv.Get()});
  return true;
}

}  // namespace drr
