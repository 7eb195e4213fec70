#include "passes/Deferred.h"

namespace drr {

// Ambient occlusion from depth and normals at the dynamic resolution. The
// depth target is no longer bound for writing (the G-buffer pass ended).
bool SSAOPass::Record(PassFrame& f) {
  RenderTargetSet& rts = f.RTs();
  Target(f.ctx, rts[RT::GBufferAO].rtv.Get(), f.Setup().sceneViewport);
  Draw(f.ctx, m_Kit.dynamicVS.Get(), m_PS.Get(), m_Shared.m_CB.Get(),
       {m_Shared.Depth(f), rts[RT::GBufferNormal].srv.Get()});
  return true;
}

}  // namespace drr
