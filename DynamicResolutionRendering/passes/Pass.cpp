#include "passes/Pass.h"

namespace drr {

void Pass::Run(PassFrame& f, const std::string& name) {
  f.ctx->BeginEvent(name.c_str());
  const bool recorded = Record(f);
  f.ctx->EndEvent();
  if (recorded) f.profiler->CountPass(name.c_str());
}

SceneTargets ChooseSceneTargets(RenderTargetSet& rts, const FrameSetup& s, const BackBuffer& bb) {
  SceneTargets t;
  if (s.dynamic) {
    RenderTarget& colour = s.motionBlur ? rts[RT::ColorDynamic] : rts.Final(s.cur);
    t.rtv[0] = colour.rtv.Get();
    t.colour = colour.texture.Get();
    if (s.motionBlur || s.temporal != TemporalMode::None) {
      RenderTarget& velocity = rts.Velocity((s.TAA() && !s.motionBlur) ? s.cur : 0);
      t.rtv[1] = velocity.rtv.Get();
      t.velocity = velocity.texture.Get();
    }
    t.dsv = rts[RT::DepthDynamic].dsv.Get();
  } else {
    t.rtv[0] = s.motionBlur ? rts[RT::ColorFull].rtv.Get() : bb.rtv;
    t.colour = s.motionBlur ? rts[RT::ColorFull].texture.Get() : bb.texture;
    if (s.motionBlur) {
      t.rtv[1] = rts[RT::VelocityFull].rtv.Get();
      t.velocity = rts[RT::VelocityFull].texture.Get();
    }
    t.dsv = rts[RT::DepthFull].dsv.Get();
  }
  t.count = t.rtv[1] ? 2 : 1;
  return t;
}

}  // namespace drr
