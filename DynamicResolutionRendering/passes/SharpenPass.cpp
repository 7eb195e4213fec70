#include "passes/Passes.h"

namespace drr {

// The edge-adaptive upscale's output into the back buffer or the secondary upscale's source.
bool SharpenPass::Record(PassFrame& f) {
  const FrameSetup& s = f.Setup();
  RenderTargetSet& rts = f.RTs();
  Target(f.ctx, s.secondary ? rts[RT::UpscaleOutput].rtv.Get() : f.backBuffer.rtv, s.outputViewport);
  UploadUpscale(f.ctx, s.uc);
  DrawDynamic(f.ctx, m_PS.Get(), s.dc, {rts[RT::UpscaleSharpenInput].srv.Get()});
  return true;
}

}  // namespace drr
