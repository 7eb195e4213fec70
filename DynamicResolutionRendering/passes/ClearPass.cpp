// The clears: the scene's targets (ClearPass), and two small ones ahead of or
// after it (MarkOutsidePass, ClearFinalNonePass).
#include "passes/Passes.h"

namespace drr {

namespace {
constexpr float kZero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
constexpr float kMarkerColor[4] = {1.0f, 0.0f, 1.0f, 1.0f};      // magenta, never in the Arena
constexpr float kMarkerVelocity[4] = {0.5f, -0.5f, 0.0f, 0.0f};  // a huge velocity
}  // namespace

bool MarkOutsidePass::Record(PassFrame& f) {
  f.ctx->ClearRenderTargetView(f.scene.rtv[0], kMarkerColor);
  if (f.scene.rtv[1]) f.ctx->ClearRenderTargetView(f.scene.rtv[1], kMarkerVelocity);
  f.ctx->ClearRenderTargetView(f.RTs().Final(f.Setup().cur).rtv.Get(), kMarkerColor);
  return false;  // a test aid, not one of the frame's passes
}

bool ClearFinalNonePass::Record(PassFrame& f) {
  f.ctx->ClearRenderTargetView(f.RTs().Final(f.Setup().cur).rtv.Get(), kZero);
  return true;
}

bool ClearPass::LoadShaders(ShaderLoad& load) {
  return load.Load({}, {{"PostProcessDynamic_ClearPS", &m_Clear},
                        {"PostProcessDynamic_ClearVelocityPS", &m_ClearVelocity},
                        {"PostProcess_ClearPS", &m_FullClear},
                        {"PostProcess_ClearVelocityPS", &m_FullClearVelocity}});
}

void ClearPass::Release() { m_Clear = m_ClearVelocity = m_FullClear = m_FullClearVelocity = nullptr; }

bool ClearPass::Record(PassFrame& f) {
  const FrameSetup& s = f.Setup();
  const SceneTargets& t = f.scene;
  f.ctx->ClearDepthStencilView(t.dsv, d3dl::CLEAR_DEPTH, 1.0f, 0);
  if (!s.psClear) {
    // The API clear covers the whole views, not just the viewport.
    if (t.rtv[1]) f.ctx->ClearRenderTargetView(t.rtv[1], kZero);
    f.ctx->ClearRenderTargetView(t.rtv[0], s.dc.clearColor);
    return true;
  }
  f.ctx->OMSetRenderTargets(t.count, t.rtv, nullptr);
  f.ctx->RSSetViewports(1, &s.sceneViewport);
  const bool velocity = t.count == 2;
  if (s.dynamic) DrawDynamic(f.ctx, velocity ? m_ClearVelocity.Get() : m_Clear.Get(), s.dc);
  else DrawFull(f.ctx, velocity ? m_FullClearVelocity.Get() : m_FullClear.Get(), s.fc);
  return true;
}

}  // namespace drr
