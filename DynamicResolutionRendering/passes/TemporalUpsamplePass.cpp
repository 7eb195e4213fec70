#include "passes/Passes.h"

namespace drr {

bool TemporalUpsamplePass::LoadShaders(ShaderLoad& load) { return LoadFilterShaders(load, true, &m_Shaders); }

// One draw writes the new history and, unless the secondary upscale follows, the back buffer.
bool TemporalUpsamplePass::Record(PassFrame& f) {
  const FrameSetup& s = f.Setup();
  RenderTargetSet& rts = f.RTs();
  d3dl::RenderTargetView* rtv[2] = {rts.UpscaleHistory(s.historyCur).rtv.Get(), f.backBuffer.rtv};
  f.ctx->OMSetRenderTargets(s.secondary ? 1 : 2, rtv, nullptr);
  f.ctx->RSSetViewports(1, &s.outputViewport);
  UploadUpscale(f.ctx, s.uc);
  BindSamplers(f.ctx);
  DrawDynamic(f.ctx, FilterShader(m_Shaders, s), s.dc,
              {rts.Final(s.cur).srv.Get(), rts.UpscaleHistory(s.historyPrev).srv.Get(), rts.Velocity(0).srv.Get(),
               nullptr, nullptr, nullptr, rts[RT::DepthDynamic].srv.Get()});
  return true;
}

}  // namespace drr
