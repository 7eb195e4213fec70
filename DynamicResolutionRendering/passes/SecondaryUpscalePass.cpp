#include "passes/Passes.h"

namespace drr {

// The primary upscale's output (or TAAU's new history) to the back buffer.
bool SecondaryUpscalePass::Record(PassFrame& f) {
  const FrameSetup& s = f.Setup();
  RenderTargetSet& rts = f.RTs();
  Target(f.ctx, f.backBuffer.rtv, s.backBufferViewport);
  UploadUpscale(f.ctx, s.uc);
  BindSamplers(f.ctx);
  d3dl::ShaderResourceView* source =
      s.TAAU() ? rts.UpscaleHistory(s.historyCur).srv.Get() : rts[RT::UpscaleOutput].srv.Get();
  DrawDynamic(f.ctx, m_PS.Get(), s.dc, {source});
  return true;
}

}  // namespace drr
