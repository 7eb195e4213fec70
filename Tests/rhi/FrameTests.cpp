// Frame-level behaviour: constant ring under 1,000 WRITE_DISCARDs, dynamic
// vertex buffers, queries, deferred destruction, headless swap chain.
#include <chrono>
#include <thread>

#include "RhiTest.h"

namespace rhitest {
namespace {

class RhiFrame : public RhiTest {};

TEST_F(RhiFrame, ThousandWriteDiscardsOfOneConstantBufferInOneFrame) {
  const uint32_t W = 40, H = 25;  // 1,000 pixels
  auto rt = MakeRenderTarget(W, H);
  Bind(rt, W, H);
  const float black[4] = {0, 0, 0, 0};
  context()->ClearRenderTargetView(rt.rtv.Get(), black);
  auto vs = LoadVertexShader("rhi_quad_cb_vs.spv");
  auto ps = LoadPixelShader("rhi_color_ps.spv");
  auto cb = MakeCB(32);
  context()->VSSetShader(vs.Get());
  context()->PSSetShader(ps.Get());
  context()->VSSetConstantBuffers(0, 1, cb.GetAddressOf());
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  DEVICE_STATS before;
  device()->GetStats(&before);
  for (uint32_t i = 0; i < W * H; ++i) {
    uint32_t x = i % W, y = i / W;
    float data[8] = {-1 + 2.0f * x / W, 1 - 2.0f * y / H, -1 + 2.0f * (x + 1) / W, 1 - 2.0f * (y + 1) / H,
                     (i % 256) / 255.0f, (i / 256) / 255.0f, 77 / 255.0f, 1};
    WriteCB(cb.Get(), data, sizeof(data));
    context()->Draw(6, 0);
  }
  DEVICE_STATS after;
  device()->GetStats(&after);
  EXPECT_EQ(after.DrawCalls - before.DrawCalls, W * H);
  EXPECT_LE(after.DescriptorSetsAllocated - before.DescriptorSetsAllocated, 2u)
      << "only the constants changed: the same descriptor set is rebound with new dynamic offsets";
  EXPECT_EQ(after.FramesSubmitted, before.FramesSubmitted) << "all in one frame";
  auto img = ReadBack(rt.texture.Get());
  int wrong = 0;
  for (uint32_t i = 0; i < W * H; ++i) {
    auto p = img.RGBA8(i % W, i / W);
    if (p[0] != i % 256 || p[1] != i / 256 || p[2] != 77 || p[3] != 255) ++wrong;
  }
  EXPECT_EQ(wrong, 0);
}

TEST_F(RhiFrame, ConstantBufferWrittenInAnEarlierFrameIsStillValid) {
  auto rt = MakeRenderTarget(4, 4);
  auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
  auto ps = LoadPixelShader("rhi_solid_ps.spv");
  const float c[4] = {0, 1, 0, 1};
  auto cbDefault = MakeCB(16, USAGE_DEFAULT);
  context()->UpdateSubresource(cbDefault.Get(), 0, nullptr, c, 0, 0);
  auto cbDynamic = MakeCB(16);
  WriteCB(cbDynamic.Get(), c, 16);
  for (auto* cb : {cbDefault.Get(), cbDynamic.Get()}) {
    for (int frame = 0; frame < 4; ++frame) context()->Flush();  // the ring slices are recycled
    Bind(rt, 4, 4);
    context()->VSSetShader(vs.Get());
    context()->PSSetShader(ps.Get());
    context()->PSSetConstantBuffers(0, 1, &cb);
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->Draw(3, 0);
    EXPECT_EQ(ReadBack(rt.texture.Get()).RGBA8(1, 1)[1], 255);
  }
}

TEST_F(RhiFrame, DynamicVertexBufferLikeImGui) {
  auto rt = MakeRenderTarget(32, 32);
  auto code = LoadSpirv("rhi_color_vs.spv");
  auto vs = LoadVertexShader("rhi_color_vs.spv");
  auto ps = LoadPixelShader("rhi_color_ps.spv");
  auto il = ColorLayout(code);
  auto vb = MakeBuffer(BIND_VERTEX_BUFFER, nullptr, 64 * sizeof(ColorVertex), USAGE_DYNAMIC);
  std::vector<uint16_t> idx = {0, 1, 2, 0, 2, 3};
  auto ib = MakeBuffer(BIND_INDEX_BUFFER, nullptr, 64, USAGE_DYNAMIC);
  for (int frame = 0; frame < 5; ++frame) {
    Bind(rt, 32, 32);
    const float black[4] = {0, 0, 0, 1};
    context()->ClearRenderTargetView(rt.rtv.Get(), black);
    // Two "command lists" per frame, appended with NO_OVERWRITE after a DISCARD.
    MAPPED_SUBRESOURCE m;
    ASSERT_EQ(context()->Map(vb.Get(), 0, MAP_WRITE_DISCARD, 0, &m), S_OK);
    auto* v = static_cast<ColorVertex*>(m.pData);
    float g = frame / 4.0f;
    v[0] = {{-1, 1, 0, 1}, {1, g, 0, 1}};
    v[1] = {{0, 1, 0, 1}, {1, g, 0, 1}};
    v[2] = {{0, -1, 0, 1}, {1, g, 0, 1}};
    v[3] = {{-1, -1, 0, 1}, {1, g, 0, 1}};
    context()->Unmap(vb.Get(), 0);
    ASSERT_EQ(context()->Map(ib.Get(), 0, MAP_WRITE_DISCARD, 0, &m), S_OK);
    std::memcpy(m.pData, idx.data(), idx.size() * 2);
    context()->Unmap(ib.Get(), 0);
    UINT stride = sizeof(ColorVertex), off = 0;
    context()->IASetInputLayout(il.Get());
    context()->IASetVertexBuffers(0, 1, vb.GetAddressOf(), &stride, &off);
    context()->IASetIndexBuffer(ib.Get(), DXGI_FORMAT_R16_UINT, 0);
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->VSSetShader(vs.Get());
    context()->PSSetShader(ps.Get());
    context()->DrawIndexed(6, 0, 0);
    ASSERT_EQ(context()->Map(vb.Get(), 0, MAP_WRITE_NO_OVERWRITE, 0, &m), S_OK);
    v = static_cast<ColorVertex*>(m.pData);
    v[4] = {{0, 1, 0, 1}, {0, 0, 1, 1}};
    v[5] = {{1, 1, 0, 1}, {0, 0, 1, 1}};
    v[6] = {{1, -1, 0, 1}, {0, 0, 1, 1}};
    v[7] = {{0, -1, 0, 1}, {0, 0, 1, 1}};
    context()->Unmap(vb.Get(), 0);
    context()->DrawIndexed(6, 0, 4);
    auto img = ReadBack(rt.texture.Get());
    EXPECT_EQ(img.RGBA8(8, 16)[0], 255);
    EXPECT_TRUE(Near(img.RGBA8(8, 16)[1], int(std::lround(g * 255)))) << frame;
    EXPECT_EQ(img.RGBA8(24, 16)[2], 255);
    EXPECT_EQ(img.RGBA8(24, 16)[0], 0);
  }
}

TEST_F(RhiFrame, TimestampsAreMonotonicAndDisjointIsSane) {
  QUERY_DESC qd;
  qd.Query = QUERY_TIMESTAMP_DISJOINT;
  ComPtr<Query> disjoint, t0, t1, t2;
  ASSERT_EQ(device()->CreateQuery(&qd, disjoint.ReleaseAndGetAddressOf()), S_OK);
  qd.Query = QUERY_TIMESTAMP;
  for (auto* q : {&t0, &t1, &t2}) ASSERT_EQ(device()->CreateQuery(&qd, q->ReleaseAndGetAddressOf()), S_OK);
  auto rt = MakeRenderTarget(64, 64);
  for (int frame = 0; frame < 3; ++frame) {
    context()->Begin(disjoint.Get());
    context()->End(t0.Get());
    Bind(rt, 64, 64);
    const float c[4] = {1, 0, 0, 1};
    context()->BeginEvent("clear");
    context()->ClearRenderTargetView(rt.rtv.Get(), c);
    context()->EndEvent();
    context()->End(t1.Get());
    auto smp = MakeSampler(FILTER_MIN_MAG_MIP_LINEAR);
    auto other = MakeRenderTarget(64, 64);
    DrawSampled(other.srv.Get(), smp.Get());
    context()->End(t2.Get());
    context()->End(disjoint.Get());
    UINT64 v[3] = {};
    QUERY_DATA_TIMESTAMP_DISJOINT dj;
    EXPECT_EQ(context()->GetData(t0.Get(), &v[0], sizeof(UINT64), ASYNC_GETDATA_DONOTFLUSH), S_FALSE);
    auto start = std::chrono::steady_clock::now();
    HRESULT hr;
    while ((hr = context()->GetData(disjoint.Get(), &dj, sizeof(dj), 0)) == S_FALSE) {
      ASSERT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_EQ(hr, S_OK);
    EXPECT_EQ(dj.Disjoint, 0);
    EXPECT_GE(dj.Frequency, 1000000u);
    EXPECT_LE(dj.Frequency, 100000000000ull);
    int i = 0;
    for (auto* q : {t0.Get(), t1.Get(), t2.Get()}) ASSERT_EQ(context()->GetData(q, &v[i++], sizeof(UINT64), 0), S_OK);
    EXPECT_GT(v[0], 0u);
    EXPECT_LE(v[0], v[1]);
    EXPECT_LE(v[1], v[2]);
    EXPECT_LT(v[2] - v[0], dj.Frequency * 10) << "less than 10 s between the timestamps";
  }
  // Event query.
  qd.Query = QUERY_EVENT;
  ComPtr<Query> ev;
  ASSERT_EQ(device()->CreateQuery(&qd, ev.ReleaseAndGetAddressOf()), S_OK);
  context()->End(ev.Get());
  BOOL done = 0;
  auto start = std::chrono::steady_clock::now();
  while (context()->GetData(ev.Get(), &done, sizeof(done), 0) == S_FALSE)
    ASSERT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_EQ(done, 1);
}

TEST_F(RhiFrame, DeferredDestructionAfterTheFence) {
  auto rt = MakeRenderTarget(16, 16);
  uint32_t texel = 0xff00ff00u;
  auto tex = MakeTexture(1, 1, DXGI_FORMAT_R8G8B8A8_UNORM, &texel);
  auto srv = MakeSRV(tex.Get());
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  Bind(rt, 16, 16);
  DrawSampled(srv.Get(), smp.Get());  // GPU work that uses tex, recorded, not yet submitted
  std::vector<ColorVertex> tri = {{{-1, 1, 0, 1}, {1, 0, 0, 1}}, {{1, 1, 0, 1}, {1, 0, 0, 1}}, {{-1, -1, 0, 1}, {1, 0, 0, 1}}};
  DrawColored(tri);  // a vertex buffer used and released inside
  DEVICE_STATS s0;
  device()->GetStats(&s0);
  // Release everything: the context keeps references until it is cleared.
  context()->ClearState();
  srv.Reset();
  tex.Reset();
  DEVICE_STATS s1;
  device()->GetStats(&s1);
  EXPECT_EQ(s1.ObjectsDestroyed, s0.ObjectsDestroyed) << "nothing is destroyed while the frame may use it";
  EXPECT_GE(s1.DeferredDestructionsPending, 4u) << "image, memory, view, buffer...";
  EXPECT_LT(s1.LiveObjects, s0.LiveObjects);
  // Keep drawing frames.
  for (int frame = 0; frame < 3; ++frame) {
    Bind(rt, 16, 16);
    const float c[4] = {0, 0, float(frame) / 3, 1};
    context()->ClearRenderTargetView(rt.rtv.Get(), c);
    auto t = MakeTexture(1, 1, DXGI_FORMAT_R8G8B8A8_UNORM, &texel);  // released at the end of the iteration
    auto v = MakeSRV(t.Get());
    DrawSampled(v.Get(), smp.Get());
    context()->Flush();
  }
  DEVICE_STATS s2;
  device()->GetStats(&s2);
  EXPECT_GE(s2.ObjectsDestroyed, s0.ObjectsDestroyed + s1.DeferredDestructionsPending);
  device()->WaitIdle();
}

TEST_F(RhiFrame, HeadlessSwapChainPresentsSeveralFrames) {
  SWAP_CHAIN_DESC sd;
  sd.Width = 32;
  sd.Height = 24;
  sd.BufferCount = 3;
  ComPtr<SwapChain> sc;
  ASSERT_EQ(device()->CreateHeadlessSwapChain(&sd, sc.ReleaseAndGetAddressOf()), S_OK);
  EXPECT_TRUE(sc->IsHeadless());
  ComPtr<Texture2D> bb;
  ASSERT_EQ(sc->GetBuffer(0, bb.ReleaseAndGetAddressOf()), S_OK);
  TEXTURE2D_DESC d;
  bb->GetDesc(&d);
  EXPECT_EQ(d.Width, 32u);
  EXPECT_EQ(d.Height, 24u);
  EXPECT_EQ(d.Format, DXGI_FORMAT_R8G8B8A8_UNORM);
  ComPtr<RenderTargetView> rtv;
  ASSERT_EQ(device()->CreateRenderTargetView(bb.Get(), nullptr, rtv.ReleaseAndGetAddressOf()), S_OK);
  auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
  auto ps = LoadPixelShader("rhi_solid_ps.spv");
  auto cb = MakeCB(16);
  for (int frame = 0; frame < 6; ++frame) {
    ComPtr<Texture2D> cur;
    ASSERT_EQ(sc->GetBuffer(0, cur.ReleaseAndGetAddressOf()), S_OK);
    EXPECT_EQ(cur.Get(), bb.Get());
    context()->OMSetRenderTargets(1, rtv.GetAddressOf(), nullptr);
    SetViewport(32, 24);
    const float black[4] = {0, 0, 0, 1};
    context()->ClearRenderTargetView(rtv.Get(), black);
    const float c[4] = {frame / 5.0f, 1 - frame / 5.0f, 0.5f, 1};
    WriteCB(cb.Get(), c, 16);
    context()->VSSetShader(vs.Get());
    context()->PSSetShader(ps.Get());
    context()->PSSetConstantBuffers(0, 1, cb.GetAddressOf());
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->Draw(3, 0);
    auto img = ReadBack(bb.Get());
    EXPECT_TRUE(Near(img.RGBA8(31, 23)[0], int(std::lround(c[0] * 255)))) << frame;
    EXPECT_TRUE(Near(img.RGBA8(0, 0)[1], int(std::lround(c[1] * 255)))) << frame;
    EXPECT_EQ(sc->Present(1, 0), S_OK);
  }
  // ResizeBuffers needs every reference released.
  EXPECT_EQ(sc->ResizeBuffers(0, 16, 16, DXGI_FORMAT_UNKNOWN, 0), E_INVALIDARG);
  context()->OMSetRenderTargets(0, nullptr, nullptr);
  rtv.Reset();
  bb.Reset();
  EXPECT_EQ(sc->ResizeBuffers(0, 16, 16, DXGI_FORMAT_UNKNOWN, 0), S_OK);
  ASSERT_EQ(sc->GetBuffer(0, bb.ReleaseAndGetAddressOf()), S_OK);
  bb->GetDesc(&d);
  EXPECT_EQ(d.Width, 16u);
}

}  // namespace
}  // namespace rhitest
