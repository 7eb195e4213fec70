// Rasterisation conventions: orientation, culling, viewports, pixel centres,
// clears, render-to-texture, depth, input layouts.
#include "RhiTest.h"

namespace rhitest {
namespace {

class RhiRender : public RhiTest {};

constexpr uint32_t kW = 64, kH = 64;
const float kBlack[4] = {0, 0, 0, 1};

// Top vertex red, bottom-right green, bottom-left blue: clockwise on screen.
std::vector<ColorVertex> Triangle(bool clockwise) {
  ColorVertex top{{0.0f, 0.8f, 0.5f, 1}, {1, 0, 0, 1}};
  ColorVertex br{{0.8f, -0.8f, 0.5f, 1}, {0, 1, 0, 1}};
  ColorVertex bl{{-0.8f, -0.8f, 0.5f, 1}, {0, 0, 1, 1}};
  if (clockwise) return {top, br, bl};
  return {top, bl, br};
}

TEST_F(RhiRender, TriangleOrientationAndColours) {
  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  DrawColored(Triangle(true));
  auto img = ReadBack(rt.texture.Get());
  // Clip +Y is up: the red vertex is near the top row, green bottom-right, blue bottom-left.
  auto top = img.RGBA8(32, 8), br = img.RGBA8(56, 56), bl = img.RGBA8(7, 56);
  EXPECT_GT(top[0], 200) << "red vertex at the top";
  EXPECT_LT(top[1], 60);
  EXPECT_GT(br[1], 200) << "green vertex bottom-right";
  EXPECT_GT(bl[2], 200) << "blue vertex bottom-left";
  // Outside the triangle: cleared.
  EXPECT_EQ(img.RGBA8(2, 2)[0], 0);
  EXPECT_EQ(img.RGBA8(61, 2)[1], 0);
}

TEST_F(RhiRender, ClockwiseIsFrontFaceByDefault) {
  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  // Default rasterizer state: CULL_BACK, FrontCounterClockwise = 0.
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  DrawColored(Triangle(true));
  auto cw = ReadBack(rt.texture.Get());
  EXPECT_GT(cw.RGBA8(32, 40)[3], 0) << "a clockwise triangle is front-facing and drawn";

  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  DrawColored(Triangle(false));
  auto ccw = ReadBack(rt.texture.Get());
  auto p = ccw.RGBA8(32, 40);
  EXPECT_EQ(p[0] + p[1] + p[2], 0) << "a counter-clockwise triangle is back-facing and culled";

  // FrontCounterClockwise = 1 flips it.
  RASTERIZER_DESC rd;
  rd.FrontCounterClockwise = 1;
  ComPtr<RasterizerState> rs;
  ASSERT_EQ(device()->CreateRasterizerState(&rd, rs.ReleaseAndGetAddressOf()), S_OK);
  context()->RSSetState(rs.Get());
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  DrawColored(Triangle(false));
  auto ccwFront = ReadBack(rt.texture.Get());
  EXPECT_GT(ccwFront.RGBA8(32, 40)[3], 0);
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  DrawColored(Triangle(true));
  auto cwBack = ReadBack(rt.texture.Get());
  p = cwBack.RGBA8(32, 40);
  EXPECT_EQ(p[0] + p[1] + p[2], 0);

  // CULL_FRONT with the default winding culls the clockwise triangle.
  RASTERIZER_DESC rf;
  rf.CullMode = CULL_FRONT;
  ASSERT_EQ(device()->CreateRasterizerState(&rf, rs.ReleaseAndGetAddressOf()), S_OK);
  context()->RSSetState(rs.Get());
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  DrawColored(Triangle(true));
  auto cf = ReadBack(rt.texture.Get());
  p = cf.RGBA8(32, 40);
  EXPECT_EQ(p[0] + p[1] + p[2], 0);
}

TEST_F(RhiRender, ViewportSubRectangleLeavesTheRestUntouched) {
  auto rt = MakeRenderTarget(kW, kH);
  context()->OMSetRenderTargets(1, rt.rtv.GetAddressOf(), nullptr);
  const float blue[4] = {0, 0, 1, 1};
  context()->ClearRenderTargetView(rt.rtv.Get(), blue);
  VIEWPORT vp{16, 8, 32, 16, 0, 1};
  context()->RSSetViewports(1, &vp);
  const float red[4] = {1, 0, 0, 1};
  BindSolidFullScreen(red);
  context()->Draw(3, 0);
  auto img = ReadBack(rt.texture.Get());
  int wrong = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      bool inside = x >= 16 && x < 48 && y >= 8 && y < 24;
      auto p = img.RGBA8(x, y);
      if (inside ? (p[0] != 255 || p[2] != 0) : (p[0] != 0 || p[2] != 255)) ++wrong;
    }
  EXPECT_EQ(wrong, 0);
}

TEST_F(RhiRender, PixelCentresAreAtHalfIntegers) {
  auto rt = MakeRenderTarget(16, 8, DXGI_FORMAT_R32G32_FLOAT);
  Bind(rt, 16, 8);
  auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
  auto ps = LoadPixelShader("rhi_position_ps.spv");
  context()->VSSetShader(vs.Get());
  context()->PSSetShader(ps.Get());
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  context()->Draw(3, 0);
  auto img = ReadBack(rt.texture.Get());
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      ASSERT_FLOAT_EQ(img.Float(x, y, 0), x + 0.5f);
      ASSERT_FLOAT_EQ(img.Float(x, y, 1), y + 0.5f);
    }
}

TEST_F(RhiRender, OneTexelPerPixelPointCopyIsExact) {
  const uint32_t n = 32;
  std::vector<uint32_t> texels(n * n);
  uint32_t seed = 12345;
  for (auto& t : texels) t = (seed = seed * 1664525u + 1013904223u);
  auto tex = MakeTexture(n, n, DXGI_FORMAT_R8G8B8A8_UNORM, texels.data());
  auto srv = MakeSRV(tex.Get());
  auto rt = MakeRenderTarget(n, n);
  Bind(rt, n, n);
  for (FILTER f : {FILTER_MIN_MAG_MIP_POINT, FILTER_MIN_MAG_MIP_LINEAR}) {
    auto smp = MakeSampler(f);
    DrawSampled(srv.Get(), smp.Get());
    auto img = ReadBack(rt.texture.Get());
    int diff = 0;
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x) {
        auto p = img.RGBA8(x, y);
        uint32_t v = p[0] | (p[1] << 8) | (p[2] << 16) | (uint32_t(p[3]) << 24);
        if (f == FILTER_MIN_MAG_MIP_POINT ? v != texels[y * n + x] : false) ++diff;
        // Linear at texel centres also reproduces the texel (within rounding).
        if (f != FILTER_MIN_MAG_MIP_POINT) {
          const uint8_t* t = reinterpret_cast<const uint8_t*>(&texels[y * n + x]);
          for (int c = 0; c < 4; ++c) diff += !Near(p[c], t[c], 1);
        }
      }
    EXPECT_EQ(diff, 0) << "filter 0x" << std::hex << f;
  }
}

TEST_F(RhiRender, ClearViewWithRectsClearsOnlyThoseRects) {
  auto rt = MakeRenderTarget(kW, kH);
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  const float green[4] = {0, 1, 0, 1};
  RECT rects[2] = {{4, 4, 12, 10}, {40, 30, 64, 64}};
  // Not bound as a render target: the RHI opens a short rendering scope.
  context()->ClearView(rt.rtv.Get(), green, rects, 2);
  auto img = ReadBack(rt.texture.Get());
  auto check = [&](const drrtest::Image& im) {
    int wrong = 0;
    for (uint32_t y = 0; y < kH; ++y)
      for (uint32_t x = 0; x < kW; ++x) {
        bool in = (x >= 4 && x < 12 && y >= 4 && y < 10) || (x >= 40 && y >= 30);
        if (im.RGBA8(x, y)[1] != (in ? 255 : 0)) ++wrong;
      }
    return wrong;
  };
  EXPECT_EQ(check(img), 0);
  // Bound as a render target, inside a rendering scope.
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  Bind(rt, kW, kH);
  context()->ClearView(rt.rtv.Get(), green, rects, 2);
  EXPECT_EQ(check(ReadBack(rt.texture.Get())), 0);
}

TEST_F(RhiRender, RenderToTextureThenSampleWithoutManualBarriers) {
  auto a = MakeRenderTarget(16, 16);
  auto b = MakeRenderTarget(16, 16);
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  for (int frame = 0; frame < 3; ++frame) {
    const float c[4] = {0.25f * frame, 0.5f, 1.0f, 1.0f};
    // Pass 1: draw a solid colour into A.
    Bind(a, 16, 16);
    BindSolidFullScreen(c);
    context()->Draw(3, 0);
    // Pass 2: sample A into B (A is transitioned by the RHI).
    Bind(b, 16, 16);
    DrawSampled(a.srv.Get(), smp.Get());
    auto img = ReadBack(b.texture.Get());
    auto p = img.RGBA8(9, 9);
    EXPECT_TRUE(Near(p[0], int(std::lround(c[0] * 255)))) << int(p[0]);
    EXPECT_TRUE(Near(p[1], 128)) << int(p[1]);
    EXPECT_EQ(p[2], 255);
    // Unbind A from the pixel shader before it becomes a target again (D3D rule; the RHI also does it).
    ShaderResourceView* none = nullptr;
    context()->PSSetShaderResources(0, 1, &none);
    context()->Flush();
  }
}

TEST_F(RhiRender, DepthTestWithD32AndD3DDepthRange) {
  auto rt = MakeRenderTarget(kW, kH);
  TEXTURE2D_DESC dd;
  dd.Width = kW;
  dd.Height = kH;
  dd.Format = DXGI_FORMAT_R32_TYPELESS;
  dd.BindFlags = BIND_DEPTH_STENCIL | BIND_SHADER_RESOURCE;
  ComPtr<Texture2D> depth;
  ASSERT_EQ(device()->CreateTexture2D(&dd, nullptr, depth.ReleaseAndGetAddressOf()), S_OK);
  DEPTH_STENCIL_VIEW_DESC dvd;
  dvd.Format = DXGI_FORMAT_D32_FLOAT;
  dvd.ViewDimension = DSV_DIMENSION_TEXTURE2D;
  ComPtr<DepthStencilView> dsv;
  ASSERT_EQ(device()->CreateDepthStencilView(depth.Get(), &dvd, dsv.ReleaseAndGetAddressOf()), S_OK);
  SHADER_RESOURCE_VIEW_DESC svd;
  svd.Format = DXGI_FORMAT_R32_FLOAT;
  svd.ViewDimension = SRV_DIMENSION_TEXTURE2D;
  ComPtr<ShaderResourceView> depthSrv;
  ASSERT_EQ(device()->CreateShaderResourceView(depth.Get(), &svd, depthSrv.ReleaseAndGetAddressOf()), S_OK);

  Bind(rt, kW, kH, dsv.Get());
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  context()->ClearDepthStencilView(dsv.Get(), CLEAR_DEPTH, 1.0f, 0);
  auto quad = [](float z, float r, float g, float b, float x0, float x1) {
    std::vector<ColorVertex> v;
    ColorVertex a{{x0, 0.9f, z, 1}, {r, g, b, 1}}, bb{{x1, 0.9f, z, 1}, {r, g, b, 1}},
        c{{x1, -0.9f, z, 1}, {r, g, b, 1}}, d{{x0, -0.9f, z, 1}, {r, g, b, 1}};
    return std::vector<ColorVertex>{a, bb, c, a, c, d};  // clockwise on screen
  };
  auto green = quad(0.5f, 0, 1, 0, -0.9f, 0.9f);
  auto red = quad(0.7f, 1, 0, 0, -0.9f, 0.0f);   // behind: hidden
  auto blue = quad(0.25f, 0, 0, 1, 0.0f, 0.9f);  // in front: visible
  green.insert(green.end(), red.begin(), red.end());
  green.insert(green.end(), blue.begin(), blue.end());
  DrawColored(green);
  auto img = ReadBack(rt.texture.Get());
  EXPECT_EQ(img.RGBA8(16, 32)[1], 255) << "left half: green (z 0.5) beats red (z 0.7)";
  EXPECT_EQ(img.RGBA8(16, 32)[0], 0);
  EXPECT_EQ(img.RGBA8(48, 32)[2], 255) << "right half: blue (z 0.25) beats green";
  // The depth buffer holds clip z (D3D range 0..1), readable through R32_TYPELESS.
  context()->OMSetRenderTargets(0, nullptr, nullptr);
  auto dimg = ReadBack(depth.Get());
  EXPECT_NEAR(dimg.Float(16, 32), 0.5f, 1e-6);
  EXPECT_NEAR(dimg.Float(48, 32), 0.25f, 1e-6);
  EXPECT_EQ(dimg.Float(1, 1), 1.0f);
  // And sampled as R32_FLOAT.
  auto out = MakeRenderTarget(kW, kH, DXGI_FORMAT_R32_FLOAT);
  Bind(out, kW, kH);
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  DrawSampled(depthSrv.Get(), smp.Get());
  auto s = ReadBack(out.texture.Get());
  EXPECT_NEAR(s.Float(16, 32), 0.5f, 1e-6);
  EXPECT_NEAR(s.Float(48, 32), 0.25f, 1e-6);
}

TEST_F(RhiRender, SceneVertexFormatDeliversEveryAttribute) {
  struct SceneVertex {
    float pos[3], normal[3], uv[2], tangent[3], binormal[3];
  };
  static_assert(sizeof(SceneVertex) == 56);
  INPUT_ELEMENT_DESC e[5];
  const char* names[5] = {"POSITION", "NORMAL", "TEXCOORD", "TANGENT", "BINORMAL"};
  DXGI_FORMAT fmts[5] = {DXGI_FORMAT_R32G32B32_FLOAT, DXGI_FORMAT_R32G32B32_FLOAT, DXGI_FORMAT_R32G32_FLOAT,
                         DXGI_FORMAT_R32G32B32_FLOAT, DXGI_FORMAT_R32G32B32_FLOAT};
  for (int i = 0; i < 5; ++i) {
    e[i].SemanticName = names[i];
    e[i].Format = fmts[i];
  }
  auto code = LoadSpirv("rhi_attrib_vs.spv");
  ComPtr<InputLayout> il;
  ASSERT_EQ(device()->CreateInputLayout(e, 5, code.data(), code.size() * 4, il.ReleaseAndGetAddressOf()), S_OK);
  // Every vertex carries the same attribute values (flat), a quad covering the target.
  std::vector<SceneVertex> v;
  float xy[6][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, 1}, {1, -1}, {-1, -1}};
  for (auto& p : xy)
    v.push_back({{p[0], p[1], 0.25f}, {0.1f, 0.2f, 0.3f}, {0.4f, 0.5f}, {0.6f, 0.7f, 0.8f}, {0.9f, 0.15f, 0.35f}});
  auto vb = MakeBuffer(BIND_VERTEX_BUFFER, v.data(), UINT(v.size() * sizeof(SceneVertex)));
  drrtest::RenderTarget rts[5];
  RenderTargetView* rtvs[5];
  for (int i = 0; i < 5; ++i) {
    rts[i] = MakeRenderTarget(8, 8, DXGI_FORMAT_R32G32B32A32_FLOAT);
    rtvs[i] = rts[i].rtv.Get();
  }
  context()->OMSetRenderTargets(5, rtvs, nullptr);
  SetViewport(8, 8);
  auto vs = LoadVertexShader("rhi_attrib_vs.spv");
  auto ps = LoadPixelShader("rhi_attrib_ps.spv");
  UINT stride = 56, off = 0;
  context()->IASetInputLayout(il.Get());
  context()->IASetVertexBuffers(0, 1, vb.GetAddressOf(), &stride, &off);
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  context()->VSSetShader(vs.Get());
  context()->PSSetShader(ps.Get());
  context()->Draw(6, 0);
  context()->OMSetRenderTargets(0, nullptr, nullptr);
  float expect[5][3] = {{v[0].pos[0], v[0].pos[1], 0.25f}, {0.1f, 0.2f, 0.3f}, {0.4f, 0.5f, 0}, {0.6f, 0.7f, 0.8f}, {0.9f, 0.15f, 0.35f}};
  for (int i = 0; i < 5; ++i) {
    auto img = ReadBack(rts[i].texture.Get());
    for (int c = (i == 0 ? 2 : 0); c < 3; ++c) EXPECT_FLOAT_EQ(img.Float(4, 4, c), expect[i][c]) << names[i] << " component " << c;
  }
}

}  // namespace
}  // namespace rhitest
