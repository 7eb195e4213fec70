#include "passes/Deferred.h"

namespace drr {

// The directional light, the scene's point and spot lights (shadowed spots
// through the comparison sampler) and SSAO, into the scene's colour target.
bool LightingPass::Record(PassFrame& f) {
  RenderTargetSet& rts = f.RTs();
  Target(f.ctx, f.scene.rtv[0], f.Setup().sceneViewport);
  d3dl::SamplerState* cmp = m_Shared.m_ShadowSampler.Get();
  f.ctx->PSSetSamplers(0, 1, &cmp);
  d3dl::ShaderResourceView* ao = f.plan->deferredFrame.ssao ? rts[RT::GBufferAO].srv.Get() : nullptr;
  Draw(f.ctx, m_Kit.dynamicVS.Get(), m_PS.Get(), m_Shared.m_CB.Get(),
       {rts[RT::GBufferDiffuse].srv.Get(), rts[RT::GBufferSpecular].srv.Get(), rts[RT::GBufferNormal].srv.Get(), ao,
        m_Shared.Depth(f), rts[RT::SpotShadowMaps].srv.Get()});
  return true;
}

}  // namespace drr
