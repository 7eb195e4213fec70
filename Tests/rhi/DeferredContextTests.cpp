// Deferred contexts: command lists recorded on worker threads and executed on
// the immediate context, compared with the same draws on the immediate
// context and with a CPU rasterisation of the rectangles they draw.
#include <thread>

#include "RhiTest.h"

namespace rhitest {
namespace {

constexpr uint32_t kW = 64, kH = 64;
const float kBlack[4] = {0, 0, 0, 1};

// An axis-aligned rectangle in pixels, [x0, x1) x [y0, y1), of one colour.
struct Quad {
  int x0, y0, x1, y1;
  float color[4];
};

struct QuadConstants {  // cbuffer Quad of quad_cb_vs.hlsl
  float rect[4];
  float color[4];
};

QuadConstants ToConstants(const Quad& q) {
  auto cx = [](int x) { return float(x) * 2.0f / kW - 1.0f; };
  auto cy = [](int y) { return 1.0f - float(y) * 2.0f / kH; };
  return {{cx(q.x0), cy(q.y0), cx(q.x1), cy(q.y1)}, {q.color[0], q.color[1], q.color[2], q.color[3]}};
}

// Overlapping rectangles with colours that are exact in 8-bit UNORM.
std::vector<Quad> MakeQuads(uint32_t seed, uint32_t count) {
  static const float kLevels[4] = {0.0f, 0.2f, 0.6f, 1.0f};
  std::vector<Quad> quads;
  uint32_t s = seed * 2654435761u + 12345u;
  auto next = [&s](uint32_t n) {
    s = s * 1664525u + 1013904223u;
    return (s >> 8) % n;
  };
  for (uint32_t i = 0; i < count; ++i) {
    Quad q;
    q.x0 = int(next(kW - 8));
    q.y0 = int(next(kH - 8));
    q.x1 = q.x0 + 4 + int(next(12));
    q.y1 = q.y0 + 4 + int(next(12));
    q.x1 = std::min(q.x1, int(kW));
    q.y1 = std::min(q.y1, int(kH));
    for (int c = 0; c < 3; ++c) q.color[c] = kLevels[next(4)];
    q.color[3] = 1.0f;
    quads.push_back(q);
  }
  return quads;
}

// CPU reference: pixel centres inside each rectangle take its colour, in order.
std::vector<uint8_t> Rasterise(const std::vector<Quad>& quads) {
  std::vector<uint8_t> px(kW * kH * 4, 0);
  for (uint32_t i = 3; i < px.size(); i += 4) px[i] = 255;
  for (const Quad& q : quads)
    for (int y = q.y0; y < q.y1; ++y)
      for (int x = q.x0; x < q.x1; ++x)
        for (int c = 0; c < 4; ++c) px[(y * kW + x) * 4 + c] = uint8_t(std::lround(q.color[c] * 255.0f));
  return px;
}

// Number of pixels whose channels differ by more than `tol` (first one reported).
int CountDifferences(const drrtest::Image& img, const std::vector<uint8_t>& ref, int tol, const char* what) {
  int bad = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      auto p = img.RGBA8(x, y);
      for (int c = 0; c < 4; ++c)
        if (std::abs(int(p[c]) - int(ref[(y * kW + x) * 4 + c])) > tol) {
          if (bad++ == 0) ADD_FAILURE() << what << ": first difference at (" << x << "," << y << ") channel " << c;
          break;
        }
    }
  return bad;
}

std::vector<uint8_t> Pixels(const drrtest::Image& img) {
  std::vector<uint8_t> px;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x)
      for (uint8_t v : img.RGBA8(x, y)) px.push_back(v);
  return px;
}

class RhiDeferred : public RhiTest {
 protected:
  void SetUp() override {
    RhiTest::SetUp();
    vs_ = LoadVertexShader("rhi_quad_cb_vs.spv");
    ps_ = LoadPixelShader("rhi_color_ps.spv");
    RASTERIZER_DESC rd;
    rd.CullMode = CULL_NONE;
    ASSERT_EQ(device()->CreateRasterizerState(&rd, rs_.ReleaseAndGetAddressOf()), S_OK);
    cb_ = MakeCB(sizeof(QuadConstants));
  }
  void TearDown() override {
    vs_ = {};
    ps_ = {};
    rs_ = {};
    cb_ = {};
    RhiTest::TearDown();
  }

  ComPtr<DeviceContext> MakeDeferred() {
    ComPtr<DeviceContext> ctx;
    EXPECT_EQ(device()->CreateDeferredContext(0, ctx.ReleaseAndGetAddressOf()), S_OK);
    return ctx;
  }

  // Binds everything the quads need (a deferred context starts from the defaults).
  void BindQuadState(DeviceContext* ctx, RenderTargetView* rtv, Buffer* cb) {
    ctx->OMSetRenderTargets(1, &rtv, nullptr);
    VIEWPORT vp{0, 0, float(kW), float(kH), 0, 1};
    ctx->RSSetViewports(1, &vp);
    ctx->RSSetState(rs_.Get());
    ctx->IASetInputLayout(nullptr);
    ctx->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    ctx->VSSetShader(vs_.Get());
    ctx->PSSetShader(ps_.Get());
    ctx->VSSetConstantBuffers(0, 1, &cb);
  }

  // One Map(WRITE_DISCARD) of the shared constant buffer per quad; returns the failed maps.
  int RecordQuads(DeviceContext* ctx, RenderTargetView* rtv, const std::vector<Quad>& quads) {
    BindQuadState(ctx, rtv, cb_.Get());
    int failures = 0;
    for (const Quad& q : quads) {
      MAPPED_SUBRESOURCE m;
      if (ctx->Map(cb_.Get(), 0, MAP_WRITE_DISCARD, 0, &m) != S_OK) {
        ++failures;
        continue;
      }
      const QuadConstants c = ToConstants(q);
      std::memcpy(m.pData, &c, sizeof(c));
      ctx->Unmap(cb_.Get(), 0);
      ctx->Draw(6, 0);
    }
    return failures;
  }

  ComPtr<CommandList> Finish(DeviceContext* ctx, BOOL restore = 0) {
    ComPtr<CommandList> list;
    EXPECT_EQ(ctx->FinishCommandList(restore, list.ReleaseAndGetAddressOf()), S_OK);
    return list;
  }

  RenderTargetView* BoundTarget(DeviceContext* ctx) {
    RenderTargetView* rtv = nullptr;
    ctx->OMGetRenderTargets(1, &rtv, nullptr);
    if (rtv) rtv->Release();  // only compared, the test holds the view
    return rtv;
  }

  // A full-screen triangle that copies a texture into a target texel for
  // texel (rhi_sample_ps at scale 1, point sampling).
  struct SampledCopy {
    ComPtr<VertexShader> vs;
    ComPtr<PixelShader> ps;
    ComPtr<SamplerState> point;
    ComPtr<Buffer> params;
  };
  SampledCopy MakeSampledCopy() {
    const float params[4] = {1, 1, 0, 0};
    return {LoadVertexShader("rhi_fullscreen_vs.spv"), LoadPixelShader("rhi_sample_ps.spv"),
            MakeSampler(FILTER_MIN_MAG_MIP_POINT), MakeCB(16, USAGE_DEFAULT, params)};
  }
  // Binds everything the copy needs (a deferred context starts from the defaults) and draws it.
  static void RecordSampledCopy(DeviceContext* c, const SampledCopy& copy, RenderTargetView* out,
                                ShaderResourceView* srv) {
    c->OMSetRenderTargets(1, &out, nullptr);
    VIEWPORT vp{0, 0, float(kW), float(kH), 0, 1};
    c->RSSetViewports(1, &vp);
    c->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    c->VSSetShader(copy.vs.Get());
    c->PSSetShader(copy.ps.Get());
    c->PSSetShaderResources(0, 1, &srv);
    c->PSSetSamplers(0, 1, copy.point.GetAddressOf());
    c->PSSetConstantBuffers(0, 1, copy.params.GetAddressOf());
    c->Draw(3, 0);
  }

  ComPtr<VertexShader> vs_;
  ComPtr<PixelShader> ps_;
  ComPtr<RasterizerState> rs_;
  ComPtr<Buffer> cb_;
};

// Two lists recorded at the same time on two threads, both renaming the same
// dynamic constant buffer per draw, executed twice: identical images, equal
// to the same draws on the immediate context and to the CPU reference.
TEST_F(RhiDeferred, ListsFromTwoThreadsReplayTwiceLikeImmediateDraws) {
  auto rt = MakeRenderTarget(kW, kH);
  const std::vector<Quad> quads[2] = {MakeQuads(1, 60), MakeQuads(2, 60)};
  ComPtr<DeviceContext> ctx[2] = {MakeDeferred(), MakeDeferred()};
  ComPtr<CommandList> lists[2];
  int failures[2] = {0, 0};
  std::thread workers[2];
  for (int t = 0; t < 2; ++t)
    workers[t] = std::thread([&, t] {
      failures[t] = RecordQuads(ctx[t].Get(), rt.rtv.Get(), quads[t]);
      failures[t] += ctx[t]->FinishCommandList(0, lists[t].ReleaseAndGetAddressOf()) == S_OK ? 0 : 1;
    });
  for (auto& w : workers) w.join();
  ASSERT_EQ(failures[0] + failures[1], 0);

  DEVICE_STATS before, after;
  device()->GetStats(&before);
  std::vector<uint8_t> runs[2];
  for (auto& run : runs) {
    context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
    context()->ExecuteCommandList(lists[0].Get(), 0);
    context()->ExecuteCommandList(lists[1].Get(), 0);
    run = Pixels(ReadBack(rt.texture.Get()));
  }
  EXPECT_TRUE(runs[0] == runs[1]) << "the second execution drew a different image";
  device()->GetStats(&after);
  EXPECT_EQ(after.DrawCalls - before.DrawCalls, 2u * 120u) << "a list's draws count at each execution";

  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  EXPECT_EQ(RecordQuads(context(), rt.rtv.Get(), quads[0]), 0);
  EXPECT_EQ(RecordQuads(context(), rt.rtv.Get(), quads[1]), 0);
  auto immediate = ReadBack(rt.texture.Get());
  EXPECT_TRUE(Pixels(immediate) == runs[0]) << "command lists and immediate draws differ";

  std::vector<Quad> all = quads[0];
  all.insert(all.end(), quads[1].begin(), quads[1].end());
  EXPECT_EQ(CountDifferences(immediate, Rasterise(all), 1, "against the CPU reference"), 0);
}

TEST_F(RhiDeferred, FinishCommandListResetsOrKeepsTheDeferredState) {
  auto rt = MakeRenderTarget(kW, kH);
  auto ctx = MakeDeferred();
  EXPECT_EQ(ctx->GetType(), DEVICE_CONTEXT_DEFERRED);
  EXPECT_EQ(context()->GetType(), DEVICE_CONTEXT_IMMEDIATE);
  EXPECT_EQ(BoundTarget(ctx.Get()), nullptr) << "a new deferred context has default state";
  ctx->OMSetRenderTargets(1, rt.rtv.GetAddressOf(), nullptr);
  auto kept = Finish(ctx.Get(), 1);
  EXPECT_EQ(BoundTarget(ctx.Get()), rt.rtv.Get()) << "FinishCommandList(TRUE) keeps the state";
  auto reset = Finish(ctx.Get(), 0);
  EXPECT_EQ(BoundTarget(ctx.Get()), nullptr) << "FinishCommandList(FALSE) restores default state";
  // Empty lists execute as no-ops.
  context()->ExecuteCommandList(kept.Get(), 1);
  context()->ExecuteCommandList(reset.Get(), 1);
}

// FinishCommandList(TRUE): the list holds what was bound, and the context
// keeps references of its own to the state it keeps, so a buffer the
// application released is still drawn by the next list after the first is gone.
TEST_F(RhiDeferred, KeptStateStaysAliveForTheNextList) {
  auto rt = MakeRenderTarget(kW, kH);
  const Quad q{12, 4, 60, 30, {1, 0.5f, 0, 1}};
  auto ctx = MakeDeferred();
  DEVICE_STATS before;
  device()->GetStats(&before);
  {
    const QuadConstants c = ToConstants(q);
    auto cb = MakeCB(sizeof(c), USAGE_DEFAULT, &c);
    BindQuadState(ctx.Get(), rt.rtv.Get(), cb.Get());
  }
  ctx->Draw(6, 0);
  Finish(ctx.Get(), 1);  // released at once
  DEVICE_STATS kept;
  device()->GetStats(&kept);
  EXPECT_EQ(kept.LiveObjects, before.LiveObjects + 1) << "the context holds its kept state's buffer";
  ctx->Draw(6, 0);
  auto second = Finish(ctx.Get(), 0);
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  context()->ExecuteCommandList(second.Get(), 1);
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({q}), 1, "kept state"), 0);
  second = {};
  DEVICE_STATS after;
  device()->GetStats(&after);
  EXPECT_EQ(after.LiveObjects, before.LiveObjects);
}

// restoreContextState TRUE: the immediate context draws on with its own state
// after the list; FALSE: it is left in default state (a draw is skipped).
TEST_F(RhiDeferred, ExecuteCommandListRestoresOrClearsTheImmediateState) {
  auto rt = MakeRenderTarget(kW, kH);
  const Quad red{0, 0, 32, 64, {1, 0, 0, 1}}, green{32, 0, 64, 64, {0, 1, 0, 1}};
  auto ctx = MakeDeferred();
  ASSERT_EQ(RecordQuads(ctx.Get(), rt.rtv.Get(), {red}), 0);
  auto list = Finish(ctx.Get());

  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  const QuadConstants gc = ToConstants(green);
  auto greenCb = MakeCB(sizeof(gc), USAGE_DEFAULT, &gc);
  BindQuadState(context(), rt.rtv.Get(), greenCb.Get());
  context()->ExecuteCommandList(list.Get(), 1);
  EXPECT_EQ(BoundTarget(context()), rt.rtv.Get());
  context()->Draw(6, 0);  // the immediate context's own constant buffer, shaders, target
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({red, green}), 1, "restore TRUE"), 0);

  BindQuadState(context(), rt.rtv.Get(), greenCb.Get());
  context()->ExecuteCommandList(list.Get(), 0);
  EXPECT_EQ(BoundTarget(context()), nullptr);
  context()->Draw(6, 0);
  EXPECT_EQ(CountMessages(LogLevel::Error, "no vertex shader"), 1u) << "default state after restore FALSE";
  ClearMessages();
}

// A constant buffer the list reads without writing holds its contents at
// execution; one the list updates holds the list's data afterwards.
TEST_F(RhiDeferred, ConstantBuffersAreReadAtExecutionAndUpdatedByTheList) {
  auto rt = MakeRenderTarget(kW, kH);
  const Quad red{0, 0, 64, 64, {1, 0, 0, 1}}, blue{0, 0, 64, 64, {0, 0, 1, 1}}, half{0, 0, 32, 64, {0, 1, 0, 1}};
  const QuadConstants rc = ToConstants(red), bc = ToConstants(blue), hc = ToConstants(half);
  auto cb = MakeCB(sizeof(rc), USAGE_DEFAULT, &rc);
  auto ctx = MakeDeferred();
  BindQuadState(ctx.Get(), rt.rtv.Get(), cb.Get());
  ctx->Draw(6, 0);
  auto reads = Finish(ctx.Get());
  BindQuadState(ctx.Get(), rt.rtv.Get(), cb.Get());
  ctx->UpdateSubresource(cb.Get(), 0, nullptr, &hc, 0, 0);
  ctx->Draw(6, 0);
  auto updates = Finish(ctx.Get());

  context()->ExecuteCommandList(reads.Get(), 0);
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({red}), 1, "first execution"), 0);
  context()->UpdateSubresource(cb.Get(), 0, nullptr, &bc, 0, 0);
  context()->ExecuteCommandList(reads.Get(), 0);
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({blue}), 1, "after an update"), 0);
  // Executed twice in one frame with different contents in between.
  context()->ExecuteCommandList(reads.Get(), 0);
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  context()->UpdateSubresource(cb.Get(), 0, nullptr, &hc, 0, 0);
  context()->ExecuteCommandList(reads.Get(), 0);
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({half}), 1, "twice in a frame"), 0);

  context()->UpdateSubresource(cb.Get(), 0, nullptr, &rc, 0, 0);
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  context()->ExecuteCommandList(updates.Get(), 0);
  BindQuadState(context(), rt.rtv.Get(), cb.Get());
  context()->Draw(6, 0);  // the buffer now holds the list's update
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({half}), 1, "the list's update"), 0);
}

// Map(WRITE_NO_OVERWRITE) after a WRITE_DISCARD in the same list writes the same slice.
TEST_F(RhiDeferred, NoOverwriteAfterDiscardKeepsTheSlice) {
  auto rt = MakeRenderTarget(kW, kH);
  const Quad left{0, 0, 32, 64, {1, 1, 0, 1}}, right{32, 0, 64, 64, {0, 1, 1, 1}};
  auto ctx = MakeDeferred();
  BindQuadState(ctx.Get(), rt.rtv.Get(), cb_.Get());
  MAPPED_SUBRESOURCE m;
  ASSERT_EQ(ctx->Map(cb_.Get(), 0, MAP_WRITE_DISCARD, 0, &m), S_OK);
  QuadConstants c = ToConstants(right);
  std::memcpy(m.pData, &c, sizeof(c));
  ctx->Unmap(cb_.Get(), 0);
  ASSERT_EQ(ctx->Map(cb_.Get(), 0, MAP_WRITE_NO_OVERWRITE, 0, &m), S_OK);
  c = ToConstants(left);
  std::memcpy(m.pData, &c, sizeof(c));  // the same slice: the draw below sees `left`
  ctx->Unmap(cb_.Get(), 0);
  ctx->Draw(6, 0);
  auto list = Finish(ctx.Get());
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  context()->ExecuteCommandList(list.Get(), 0);
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({left}), 1, "no-overwrite"), 0);
}

// List 1 renders into a texture, list 2 samples it; recorded concurrently, so
// neither knows the texture's layout: the entry/exit states bridge them.
TEST_F(RhiDeferred, TextureRenderedByOneListIsSampledByTheNext) {
  auto tex = MakeRenderTarget(kW, kH);
  auto out = MakeRenderTarget(kW, kH);
  const std::vector<Quad> quads = MakeQuads(7, 20);
  const SampledCopy copy = MakeSampledCopy();
  ComPtr<DeviceContext> ctx[2] = {MakeDeferred(), MakeDeferred()};
  ComPtr<CommandList> lists[2];
  std::thread render([&] {
    const float black[4] = {0, 0, 0, 1};
    ctx[0]->ClearRenderTargetView(tex.rtv.Get(), black);
    RecordQuads(ctx[0].Get(), tex.rtv.Get(), quads);
    ctx[0]->FinishCommandList(0, lists[0].ReleaseAndGetAddressOf());
  });
  std::thread sample([&] {
    RecordSampledCopy(ctx[1].Get(), copy, out.rtv.Get(), tex.srv.Get());
    ctx[1]->FinishCommandList(0, lists[1].ReleaseAndGetAddressOf());
  });
  render.join();
  sample.join();
  ASSERT_TRUE(lists[0] && lists[1]);
  context()->ExecuteCommandList(lists[0].Get(), 0);
  context()->ExecuteCommandList(lists[1].Get(), 0);
  EXPECT_EQ(CountDifferences(ReadBack(out.texture.Get()), Rasterise(quads), 1, "sampled"), 0);
  // The texture left in the list's exit state: the immediate context clears it
  // and list 2 samples what is current at its execution.
  const float white[4] = {1, 1, 1, 1};
  context()->ClearRenderTargetView(tex.rtv.Get(), white);
  context()->ExecuteCommandList(lists[1].Get(), 0);
  auto img = ReadBack(out.texture.Get());
  EXPECT_EQ(img.RGBA8(5, 5)[0], 255);
  EXPECT_EQ(img.RGBA8(60, 60)[1], 255);
}

// One list samples a texture, samples it again the same way (a read the list
// skips: nothing would change), renders into it and samples it once more: the
// write must void the skipped read, or the last draw samples a texture still
// in the attachment layout without a barrier (validation errors; lavapipe,
// which runs commands in order, still draws the right image).
TEST_F(RhiDeferred, ATextureRenderedAfterARepeatedReadIsSampledAfresh) {
  auto tex = MakeRenderTarget(kW, kH);
  auto other = MakeRenderTarget(kW, kH);
  auto out = MakeRenderTarget(kW, kH);
  const std::vector<Quad> first = MakeQuads(11, 12), second = MakeQuads(12, 12);
  const SampledCopy copy = MakeSampledCopy();
  auto ctx = MakeDeferred();
  const auto sampleInto = [&](ShaderResourceView* view) { RecordSampledCopy(ctx.Get(), copy, out.rtv.Get(), view); };
  ctx->ClearRenderTargetView(tex.rtv.Get(), kBlack);
  ctx->ClearRenderTargetView(other.rtv.Get(), kBlack);
  EXPECT_EQ(RecordQuads(ctx.Get(), tex.rtv.Get(), first), 0);
  sampleInto(tex.srv.Get());    // into the read layout
  sampleInto(other.srv.Get());  // another texture, so that the next bind is a new read
  sampleInto(tex.srv.Get());    // the same read again: skipped
  EXPECT_EQ(RecordQuads(ctx.Get(), tex.rtv.Get(), second), 0);
  sampleInto(tex.srv.Get());    // after the write: must be read afresh
  auto list = Finish(ctx.Get());
  ASSERT_TRUE(list);
  context()->ExecuteCommandList(list.Get(), 0);
  std::vector<Quad> both = first;
  both.insert(both.end(), second.begin(), second.end());
  EXPECT_EQ(CountDifferences(ReadBack(out.texture.Get()), Rasterise(both), 1, "sampled after the write"), 0);
}

// The SRV/render-target hazard rule is per context: a texture bound as a
// target on a deferred context stays bindable as an SRV elsewhere.
TEST_F(RhiDeferred, HazardRuleIsPerContext) {
  auto tex = MakeRenderTarget(kW, kH);
  auto ctx = MakeDeferred();
  ctx->OMSetRenderTargets(1, tex.rtv.GetAddressOf(), nullptr);
  context()->PSSetShaderResources(0, 1, tex.srv.GetAddressOf());
  EXPECT_EQ(CountMessages(LogLevel::Warning, "bound as a render target"), 0u);
  ctx->PSSetShaderResources(0, 1, tex.srv.GetAddressOf());
  EXPECT_EQ(CountMessages(LogLevel::Warning, "bound as a render target"), 1u) << "still applies within a context";
  ClearMessages();
}

// A list keeps what it uses alive: released by the application before the
// execution, still drawn; everything goes once the list is released.
TEST_F(RhiDeferred, ListKeepsItsObjectsAlive) {
  auto rt = MakeRenderTarget(kW, kH);
  DEVICE_STATS before;
  device()->GetStats(&before);
  const Quad q{8, 8, 40, 40, {0, 1, 0, 1}};
  ComPtr<CommandList> list;
  {
    auto ctx = MakeDeferred();
    const QuadConstants c = ToConstants(q);
    auto cb = MakeCB(sizeof(c), USAGE_DEFAULT, &c);
    ComPtr<RenderTargetView> rtv;
    ASSERT_EQ(device()->CreateRenderTargetView(rt.texture.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    BindQuadState(ctx.Get(), rtv.Get(), cb.Get());
    ctx->Draw(6, 0);
    list = Finish(ctx.Get());
  }  // the context, the view and the buffer are released here
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  context()->ExecuteCommandList(list.Get(), 0);
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({q}), 1, "after release"), 0);
  DEVICE_STATS held;
  device()->GetStats(&held);
  EXPECT_GE(held.LiveObjects, before.LiveObjects + 3) << "the list holds the view, the buffer and itself";
  list = {};
  DEVICE_STATS after;
  device()->GetStats(&after);
  EXPECT_EQ(after.LiveObjects, before.LiveObjects);
}

// What a later draw of the list binds anew (a constant buffer, a rasterizer
// state, a render-target view) is kept too, although the context has let go
// of it and the application released it before the execution.
TEST_F(RhiDeferred, ListKeepsWhatItsLaterDrawsBound) {
  auto rt = MakeRenderTarget(kW, kH);
  const Quad first{4, 4, 20, 20, {1, 0, 0, 1}}, second{30, 30, 60, 50, {0, 0.6f, 1, 1}};
  auto ctx = MakeDeferred();
  const QuadConstants c1 = ToConstants(first);
  auto cb1 = MakeCB(sizeof(c1), USAGE_DEFAULT, &c1);
  BindQuadState(ctx.Get(), rt.rtv.Get(), cb1.Get());
  ctx->Draw(6, 0);
  DEVICE_STATS before;
  device()->GetStats(&before);
  {
    const QuadConstants c2 = ToConstants(second);
    auto cb2 = MakeCB(sizeof(c2), USAGE_DEFAULT, &c2);
    ComPtr<RenderTargetView> rtv2;
    ASSERT_EQ(device()->CreateRenderTargetView(rt.texture.Get(), nullptr, rtv2.GetAddressOf()), S_OK);
    RASTERIZER_DESC rd;
    rd.CullMode = CULL_NONE;
    ComPtr<RasterizerState> rs2;
    ASSERT_EQ(device()->CreateRasterizerState(&rd, rs2.GetAddressOf()), S_OK);
    ctx->OMSetRenderTargets(1, rtv2.GetAddressOf(), nullptr);
    ctx->RSSetState(rs2.Get());
    ctx->VSSetConstantBuffers(0, 1, cb2.GetAddressOf());
    ctx->Draw(6, 0);
    BindQuadState(ctx.Get(), rt.rtv.Get(), cb1.Get());  // the context lets go of them
  }
  DEVICE_STATS held;
  device()->GetStats(&held);
  EXPECT_GE(held.LiveObjects, before.LiveObjects + 3) << "the list being recorded holds the three";
  auto list = Finish(ctx.Get());
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  context()->ExecuteCommandList(list.Get(), 0);
  EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({first, second}), 1, "after release"), 0);
}

// A context keeps what its slots hold alive, as D3D11's do, with one
// reference per object (Pins.h). A buffer the application released while it
// was bound is still drawn after the context has bound more objects than its
// table holds before it drops the unbound ones (4096). The immediate context
// releases those dropped, so its live objects stay bounded, and the rest at
// the submit after the unbind; a deferred context hands them to its list,
// which holds every object bound while it was recorded (a D3D11 list records
// the binds) until it goes.
TEST_F(RhiDeferred, BoundObjectsStayAliveAndUnboundOnesGoOnBothContexts) {
  constexpr int kOthers = 4200;  // more than the table's 4096 pins before it drops the unbound ones
  auto rt = MakeRenderTarget(kW, kH);
  const Quad q{6, 10, 50, 44, {0.2f, 0.4f, 1, 1}};
  for (bool deferred : {false, true}) {
    SCOPED_TRACE(deferred ? "deferred" : "immediate");
    DEVICE_STATS before;
    device()->GetStats(&before);
    ComPtr<DeviceContext> ctx = deferred ? MakeDeferred() : ComPtr<DeviceContext>(context());
    {
      const QuadConstants c = ToConstants(q);
      auto cb = MakeCB(sizeof(c), USAGE_DEFAULT, &c);
      BindQuadState(ctx.Get(), rt.rtv.Get(), cb.Get());
    }  // the application's reference to the quad's buffer is gone
    UINT64 mostAlive = 0;
    for (int i = 0; i < kOthers; ++i) {
      auto other = MakeCB(16);
      ctx->PSSetConstantBuffers(1, 1, other.GetAddressOf());
      DEVICE_STATS now;
      device()->GetStats(&now);
      mostAlive = std::max(mostAlive, now.LiveObjects - before.LiveObjects);
    }
    if (deferred)
      EXPECT_GE(mostAlive, UINT64(kOthers)) << "the list holds every buffer bound while it was recorded";
    else
      EXPECT_LE(mostAlive, 4096u + 2u) << "unbound buffers are released once the table is full";
    DEVICE_STATS bound;
    device()->GetStats(&bound);
    EXPECT_GE(bound.LiveObjects, before.LiveObjects + 2) << "the quad's buffer and the last other one are bound";
    context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
    ctx->Draw(6, 0);
    if (deferred) context()->ExecuteCommandList(Finish(ctx.Get()).Get(), 0);  // the list holds the quad's buffer
    EXPECT_EQ(CountDifferences(ReadBack(rt.texture.Get()), Rasterise({q}), 1, "released while bound"), 0);
    if (!deferred) {  // unbound, then gone at the submit
      Buffer* none = nullptr;
      ctx->VSSetConstantBuffers(0, 1, &none);
      ctx->PSSetConstantBuffers(1, 1, &none);
      ctx->Flush();
    }
    ctx = {};  // the deferred context goes, and the list went after its execution
    DEVICE_STATS after;
    device()->GetStats(&after);
    EXPECT_EQ(after.LiveObjects, before.LiveObjects);
  }
}

TEST_F(RhiDeferred, BadUsesAreRejected) {
  auto ctx = MakeDeferred();
  auto expectError = [this](const char* what) {
    EXPECT_GE(CountMessages(LogLevel::Error, what), 1u) << "no error naming " << what;
    ClearMessages();
  };
  ComPtr<DeviceContext> none;
  EXPECT_EQ(device()->CreateDeferredContext(1, none.GetAddressOf()), E_INVALIDARG);
  expectError("ContextFlags");
  ComPtr<CommandList> list;
  EXPECT_EQ(context()->FinishCommandList(0, list.GetAddressOf()), DXGI_ERROR_INVALID_CALL);
  expectError("FinishCommandList");
  EXPECT_EQ(ctx->FinishCommandList(0, nullptr), E_INVALIDARG);
  expectError("ppCommandList");
  context()->ExecuteCommandList(nullptr, 0);
  expectError("pCommandList is null");
  list = Finish(ctx.Get());
  ctx->ExecuteCommandList(list.Get(), 0);
  expectError("ExecuteCommandList");

  QUERY_DESC qd{QUERY_EVENT};
  ComPtr<Query> query;
  ASSERT_EQ(device()->CreateQuery(&qd, query.GetAddressOf()), S_OK);
  BOOL done = 0;
  EXPECT_EQ(ctx->GetData(query.Get(), &done, sizeof(done), 0), DXGI_ERROR_INVALID_CALL);
  expectError("GetData");
  ctx->Flush();
  expectError("Flush");

  MAPPED_SUBRESOURCE m;
  EXPECT_EQ(ctx->Map(cb_.Get(), 0, MAP_WRITE_NO_OVERWRITE, 0, &m), E_INVALIDARG) << "NO_OVERWRITE before DISCARD";
  expectError("WRITE_NO_OVERWRITE");
  EXPECT_EQ(ctx->Map(cb_.Get(), 0, MAP_WRITE, 0, &m), E_INVALIDARG);
  expectError("WRITE_DISCARD");
  const float data[4] = {};
  auto fixed = MakeBuffer(BIND_VERTEX_BUFFER, data, sizeof(data));
  EXPECT_EQ(ctx->Map(fixed.Get(), 0, MAP_WRITE_DISCARD, 0, &m), E_INVALIDARG);
  expectError("USAGE_DYNAMIC");
  EXPECT_EQ(m.pData, nullptr);
  ctx->UpdateSubresource(fixed.Get(), 0, nullptr, data, 0, 0);
  expectError("constant buffers only");
  ctx->CopyResource(fixed.Get(), fixed.Get());
  expectError("CopyResource");
}

}  // namespace
}  // namespace rhitest
