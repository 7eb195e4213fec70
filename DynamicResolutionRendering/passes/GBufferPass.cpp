#include "passes/Deferred.h"

namespace drr {

// Diffuse, specular, normal, then the velocity the forward path would write;
// then the constants the SSAO and lighting passes read.
bool GBufferPass::Record(PassFrame& f) {
  if (!f.plan->Runs(PassId::ShadowMaps)) {
    m_Shared.BeginFrame();
    m_Shared.Placeholder(f);
  }
  RenderTargetSet& rts = f.RTs();
  d3dl::RenderTargetView* gbuffer[4] = {rts[RT::GBufferDiffuse].rtv.Get(), rts[RT::GBufferSpecular].rtv.Get(),
                                        rts[RT::GBufferNormal].rtv.Get(), f.scene.rtv[1]};
  f.ctx->OMSetRenderTargets(f.scene.rtv[1] ? 4 : 3, gbuffer, f.scene.dsv);
  f.ctx->RSSetViewports(1, &f.Setup().sceneViewport);
  f.sceneData->Render(f.ctx, f.plan->scene);
  m_Shared.FillConstants(f);
  return true;
}

}  // namespace drr
