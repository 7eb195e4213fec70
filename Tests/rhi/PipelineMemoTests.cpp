// Each context's memo in front of the shared pipeline cache (PipelineCache.h):
// pipelines that alternate draw by draw are looked up in the shared, locked
// cache only on their first use, whichever memo slots their keys fall into,
// and a deferred context draws with the pipelines the immediate context made
// for the default states instead of making its own.
#include "RhiTest.h"

namespace rhitest {
namespace {

constexpr uint32_t kSize = 8;
const float kGrey[4] = {0.5f, 0.5f, 0.5f, 1};

// Distinct blend descriptions, all of which leave the solid colour as drawn
// (write masks, with blending off, ONE/ZERO added or the maximum).
std::vector<ComPtr<BlendState>> MakeBlendStates(Device* device, uint32_t count) {
  std::vector<ComPtr<BlendState>> states;
  for (uint32_t i = 0; states.size() < count; ++i) {
    BLEND_DESC d;
    RENDER_TARGET_BLEND_DESC& rt = d.RenderTarget[0];
    rt.RenderTargetWriteMask = uint8_t(1 + i % 15);
    rt.BlendEnable = i / 15 % 3 != 0;
    rt.SrcBlend = rt.SrcBlendAlpha = BLEND_ONE;
    rt.DestBlend = rt.DestBlendAlpha = BLEND_ZERO;
    rt.BlendOp = rt.BlendOpAlpha = i / 15 % 3 == 2 ? BLEND_OP_MAX : BLEND_OP_ADD;
    ComPtr<BlendState> s;
    EXPECT_EQ(device->CreateBlendState(&d, s.GetAddressOf()), S_OK);
    states.push_back(s);
  }
  return states;
}

uint64_t Lookups(Device* device) {
  DEVICE_STATS s;
  device->GetStats(&s);
  return s.PipelineCacheLookups;
}

class RhiPipelineMemo : public RhiTest {};

// 40 keys in a memo of 64 entries: whatever slots they hash to, some pairs
// share one (with a direct-mapped memo such a pair missed at every draw).
// Every pair alternates for four draws, in which each may be looked up in the
// shared cache once, then four more, none of which may reach it.
TEST_F(RhiPipelineMemo, AlternatingPipelinesReachTheSharedCacheOnlyOnTheirFirstUse) {
  auto rt = MakeRenderTarget(kSize, kSize);
  Bind(rt, kSize, kSize);
  BindSolidFullScreen(kGrey);
  const auto blends = MakeBlendStates(device(), 40);
  const auto alternate = [&](size_t i, size_t j) {
    for (int k = 0; k < 4; ++k) {
      context()->OMSetBlendState(blends[k % 2 ? j : i].Get(), nullptr, 0xffffffffu);
      context()->Draw(3, 0);
    }
  };
  int thrashingPairs = 0;
  for (size_t i = 0; i < blends.size(); ++i)
    for (size_t j = i + 1; j < blends.size(); ++j) {
      alternate(i, j);
      const uint64_t before = Lookups(device());
      alternate(i, j);
      const uint64_t lookups = Lookups(device()) - before;
      if (lookups != 0 && thrashingPairs++ == 0)
        ADD_FAILURE() << "blend states " << i << " and " << j << " reached the shared cache " << lookups
                      << " times in 4 alternating draws after their first 4";
    }
  EXPECT_EQ(thrashingPairs, 0) << "of " << blends.size() * (blends.size() - 1) / 2 << " pairs";
  EXPECT_TRUE(Near(ReadBack(rt.texture.Get()).RGBA8(3, 3)[0], 128)) << "the draws drew the solid grey";
}

// The default rasterizer, blend and depth-stencil states are objects of each
// context; pipelines made for them serve every context.
TEST_F(RhiPipelineMemo, ADeferredContextDrawsWithTheDefaultStatePipelinesOfTheImmediateContext) {
  auto rt = MakeRenderTarget(kSize, kSize);
  auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
  auto ps = LoadPixelShader("rhi_solid_ps.spv");
  auto cb = MakeCB(16, USAGE_DEFAULT, kGrey);
  // Targets, shaders and colour; no rasterizer, blend or depth-stencil state.
  const auto drawSolid = [&](DeviceContext* c) {
    c->OMSetRenderTargets(1, rt.rtv.GetAddressOf(), nullptr);
    VIEWPORT vp{0, 0, float(kSize), float(kSize), 0, 1};
    c->RSSetViewports(1, &vp);
    c->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    c->VSSetShader(vs.Get());
    c->PSSetShader(ps.Get());
    c->PSSetConstantBuffers(0, 1, cb.GetAddressOf());
    c->Draw(3, 0);
  };
  drawSolid(context());
  DEVICE_STATS before, after;
  device()->GetStats(&before);
  ComPtr<DeviceContext> deferred;
  ASSERT_EQ(device()->CreateDeferredContext(0, deferred.GetAddressOf()), S_OK);
  drawSolid(deferred.Get());
  ComPtr<CommandList> list;
  ASSERT_EQ(deferred->FinishCommandList(0, list.GetAddressOf()), S_OK);
  device()->GetStats(&after);
  EXPECT_EQ(after.PipelinesCreated, before.PipelinesCreated) << "the deferred context made a pipeline of its own";

  const float black[4] = {0, 0, 0, 1};
  context()->ClearRenderTargetView(rt.rtv.Get(), black);
  context()->ExecuteCommandList(list.Get(), 1);
  EXPECT_TRUE(Near(ReadBack(rt.texture.Get()).RGBA8(3, 3)[0], 128)) << "the list drew the solid grey";
}

}  // namespace
}  // namespace rhitest
