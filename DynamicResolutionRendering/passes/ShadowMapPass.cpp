#include <algorithm>
#include <cmath>

#include "passes/Deferred.h"

namespace drr {

namespace {
// The depth compare bias (clip z) on top of the raster's slope bias.
constexpr float kShadowCompareBias = 2e-5f;
}  // namespace

bool ShadowMapPass::Record(PassFrame& f) {
  DeferredShared& s = m_Shared;
  s.BeginFrame();
  const DeferredFrame& d = f.plan->deferredFrame;
  const Scene& scene = *f.sceneData;
  for (const SceneLight& l : scene.Lights()) s.m_ShadowedSpots += l.shadow;
  // The table's array, a slice per shadowed spot (RenderTargetPlan::shadowSlices).
  const RenderTarget& maps = f.RTs()[RT::SpotShadowMaps];
  if (!maps.Valid() || maps.slices < s.m_ShadowedSpots) return false;
  const float size = float(maps.width);
  const float used = std::max(1.0f, std::floor(d.shadowScale * size));
  const d3dl::VIEWPORT viewport{0, 0, used, used, 0, 1};
  DeferredConstants& c = s.m_Constants;
  c.shadow = glm::vec4(used / size, 1.0f / size, kShadowCompareBias, 0.0f);
  s.m_ShadowScaleUsed = c.shadow.x;
  uint32_t slice = 0;
  for (const SceneLight& l : scene.Lights()) {
    if (!l.shadow) continue;
    c.shadowViewProj[slice] = SpotShadowViewProj(l);
    d3dl::DepthStencilView* dsv = maps.sliceDsv[slice].Get();
    f.ctx->OMSetRenderTargets(0, nullptr, dsv);
    f.ctx->ClearDepthStencilView(dsv, d3dl::CLEAR_DEPTH, 1.0f, 0);
    f.ctx->RSSetViewports(1, &viewport);
    s.m_ShadowDraws += f.sceneData->RenderDepth(f.ctx, c.shadowViewProj[slice]);
    ++slice;
  }
  return c.shadow.x > 0;
}

}  // namespace drr
