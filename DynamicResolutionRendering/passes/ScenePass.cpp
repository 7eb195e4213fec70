#include "passes/Passes.h"
#include "scene/Scene.h"

namespace drr {

bool ScenePass::Record(PassFrame& f) {
  f.ctx->OMSetRenderTargets(f.scene.count, f.scene.rtv, f.scene.dsv);
  f.ctx->RSSetViewports(1, &f.Setup().sceneViewport);
  f.sceneData->Render(f.ctx, f.plan->scene);
  return true;
}

}  // namespace drr
