// Views of a deferred renderer: texture-array slices and cube faces as render
// targets and shadow maps, cube sampling, MSAA coverage through
// ResolveSubresource and Texture2DMS.Load, and the descriptions the RHI rejects.
#include "FormatTestKit.h"

namespace rhitest {
namespace {

const float kRed[4] = {1, 0, 0, 1};

// A solid colour per slice: (10 + 20 s, 255 - 20 s, 255 * (s & 1), 255).
std::array<uint8_t, 4> SliceColour(uint32_t s) {
  return {uint8_t(10 + 20 * s), uint8_t(255 - 20 * s), uint8_t((s & 1) * 255), 255};
}

// Drawing into one array slice, and clearing a slice range, leaves the other
// slices untouched; a TEXTURE2DARRAY SRV starting at slice 1 reads slice 1 as 0.
TEST_F(RhiFormats, RenderingIntoOneSliceLeavesTheOthersUntouched) {
  constexpr uint32_t W = 8, H = 8, N = 4;
  auto tex = MakeTex(Desc(W, H, DXGI_FORMAT_R8G8B8A8_UNORM, BIND_RENDER_TARGET | BIND_SHADER_RESOURCE, N));
  for (uint32_t s = 0; s < N; ++s) {
    const auto c = SliceColour(s);
    const float f[4] = {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1};
    context()->ClearRenderTargetView(SliceRtv(tex.Get(), s, 1).Get(), f);
  }
  // Red into slice 2 with a draw; blue over slices [0, 2) with one clear of a range view.
  auto slice2 = SliceRtv(tex.Get(), 2, 1);
  context()->OMSetRenderTargets(1, slice2.GetAddressOf(), nullptr);
  SetViewport(W, H);
  auto cb = MakeCB(16, USAGE_DEFAULT, kRed);
  DrawFullScreen("rhi_solid_ps.spv", {}, cb.Get());
  const float blue[4] = {0, 0, 1, 1};
  auto range = SliceRtv(tex.Get(), 0, 2);
  context()->OMSetRenderTargets(1, range.GetAddressOf(), nullptr);
  context()->ClearRenderTargetView(range.Get(), blue);
  context()->OMSetRenderTargets(0, nullptr, nullptr);
  const std::array<uint8_t, 4> want[N] = {{0, 0, 255, 255}, {0, 0, 255, 255}, {255, 0, 0, 255}, SliceColour(3)};
  for (uint32_t s = 0; s < N; ++s) {
    const Image img = ReadSub(tex.Get(), CalcSubresource(0, s, 1));
    int wrong = 0;
    for (uint32_t y = 0; y < H; ++y)
      for (uint32_t x = 0; x < W; ++x) wrong += img.RGBA8(x, y) != want[s];
    EXPECT_EQ(wrong, 0) << "slice " << s;
  }
  // Slices [1, 4) through a TEXTURE2DARRAY SRV: its slice 2 is the texture's slice 3.
  SHADER_RESOURCE_VIEW_DESC sd;
  sd.ViewDimension = SRV_DIMENSION_TEXTURE2DARRAY;
  sd.Array = {1, 3};
  ComPtr<ShaderResourceView> srv;
  ASSERT_EQ(device()->CreateShaderResourceView(tex.Get(), &sd, srv.ReleaseAndGetAddressOf()), S_OK);
  auto out = MakeRenderTarget(W, H);
  Bind(out, W, H);
  const uint32_t slice[4] = {2, 0, 0, 0};
  auto sliceCb = MakeCB(16, USAGE_DEFAULT, slice);
  DrawFullScreen("rhi_fmt_array_ps.spv", {srv.Get()}, sliceCb.Get());
  EXPECT_EQ(ReadBack(out.texture.Get()).RGBA8(3, 5), SliceColour(3));
}

// A cube shadow map: all faces cleared through one range DSV, depth drawn
// into face 3 only (a one-slice DSV, no colour target, no pixel shader).
TEST_F(RhiFormats, DepthIntoOneCubeFaceLeavesTheOtherFaces) {
  constexpr uint32_t S = 16;
  auto cube = MakeTex(Desc(S, S, DXGI_FORMAT_R32_TYPELESS, BIND_DEPTH_STENCIL | BIND_SHADER_RESOURCE, 6, 1,
                           RESOURCE_MISC_TEXTURECUBE));
  context()->ClearDepthStencilView(SliceDsv(cube.Get(), 0, 6).Get(), CLEAR_DEPTH, 1.0f, 0);
  auto face3 = SliceDsv(cube.Get(), 3, 1);
  context()->OMSetRenderTargets(0, nullptr, face3.Get());
  SetViewport(S, S);
  std::vector<ColorVertex> quad;
  for (auto [x, y] : {std::pair{-1, 1}, {1, 1}, {1, -1}, {-1, 1}, {1, -1}, {-1, -1}})
    quad.push_back({{float(x), float(y), 0.25f, 1}, {1, 1, 1, 1}});
  auto code = LoadSpirv("rhi_color_vs.spv");
  auto vs = LoadVertexShader("rhi_color_vs.spv");
  auto il = ColorLayout(code);
  auto vb = MakeBuffer(BIND_VERTEX_BUFFER, quad.data(), UINT(quad.size() * sizeof(ColorVertex)));
  UINT stride = sizeof(ColorVertex), offset = 0;
  context()->IASetInputLayout(il.Get());
  context()->IASetVertexBuffers(0, 1, vb.GetAddressOf(), &stride, &offset);
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  context()->VSSetShader(vs.Get());
  context()->PSSetShader(nullptr);
  context()->Draw(6, 0);
  context()->OMSetRenderTargets(0, nullptr, nullptr);
  for (uint32_t f = 0; f < 6; ++f) {
    const Image img = ReadSub(cube.Get(), CalcSubresource(0, f, 1));
    const float want = f == 3 ? 0.25f : 1.0f;
    int wrong = 0;
    for (uint32_t y = 0; y < S; ++y)
      for (uint32_t x = 0; x < S; ++x) wrong += img.Float(x, y) != want;
    EXPECT_EQ(wrong, 0) << "face " << f;
  }
}

// The face a direction selects: the major axis, +X -X +Y -Y +Z -Z = 0..5.
uint32_t CubeFace(const float d[3]) {
  const float ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
  if (ax >= ay && ax >= az) return d[0] > 0 ? 0 : 1;
  if (ay >= az) return d[1] > 0 ? 2 : 3;
  return d[2] > 0 ? 4 : 5;
}

// Sampling a TEXTURECUBE / TEXTURECUBEARRAY view in a direction returns the
// colour of the face (and cube) the CPU picks by the major axis.
TEST_F(RhiFormats, CubeSamplingPicksTheMajorAxisFace) {
  constexpr uint32_t S = 4, Slices = 12;
  std::vector<std::array<uint8_t, 4>> texels(S * S * Slices);
  std::vector<SUBRESOURCE_DATA> init(Slices);
  for (uint32_t s = 0; s < Slices; ++s) {
    for (uint32_t i = 0; i < S * S; ++i) texels[s * S * S + i] = SliceColour(s);
    init[s] = {texels.data() + s * S * S, S * 4, 0};
  }
  auto cube = MakeTex(Desc(S, S, DXGI_FORMAT_R8G8B8A8_UNORM, BIND_SHADER_RESOURCE, Slices, 1, RESOURCE_MISC_TEXTURECUBE),
                      init.data());
  SHADER_RESOURCE_VIEW_DESC cd;
  cd.ViewDimension = SRV_DIMENSION_TEXTURECUBE;
  ComPtr<ShaderResourceView> cubeSrv, arraySrv;
  ASSERT_EQ(device()->CreateShaderResourceView(cube.Get(), &cd, cubeSrv.ReleaseAndGetAddressOf()), S_OK);
  const HRESULT hr = device()->CreateShaderResourceView(cube.Get(), nullptr, arraySrv.ReleaseAndGetAddressOf());
  if (hr == DXGI_ERROR_UNSUPPORTED) GTEST_SKIP() << "no imageCubeArray on this adapter";
  ASSERT_EQ(hr, S_OK) << "a cube texture of 12 slices defaults to TEXTURECUBEARRAY";
  // xyz: direction; w: cube index of the array view, -1: the TEXTURECUBE view.
  const float dirs[8][4] = {{1, 0.2f, -0.3f, -1}, {-1, 0.5f, 0.4f, -1}, {0.1f, 1, 0.3f, -1},  {0.2f, -0.9f, -0.5f, -1},
                            {-0.3f, 0.2f, 1, -1}, {0.3f, 0.4f, -1, 0},  {0.9f, -0.3f, 0.2f, 1}, {0.1f, 0.2f, -0.8f, 1}};
  auto cb = MakeCB(sizeof(dirs), USAGE_DEFAULT, dirs);
  auto out = MakeRenderTarget(8, 1);
  Bind(out, 8, 1);
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  context()->PSSetSamplers(0, 1, smp.GetAddressOf());
  DrawFullScreen("rhi_fmt_cube_ps.spv", {cubeSrv.Get(), arraySrv.Get()}, cb.Get());
  const Image img = ReadBack(out.texture.Get());
  for (uint32_t i = 0; i < 8; ++i) {
    const uint32_t slice = 6 * uint32_t(std::max(0.0f, dirs[i][3])) + CubeFace(dirs[i]);
    EXPECT_EQ(img.RGBA8(i, 0), SliceColour(slice)) << "direction " << i << " should pick slice " << slice;
  }
}

// Unbound Texture2DArray / TextureCube(Array) / Texture2DMS slots read zeros
// (D3D11) through dummy views of the declared shape, validation-clean.
TEST_F(RhiFormats, UnboundArrayCubeAndMultisampledSlotsReadZero) {
  const float dirs[8][4] = {{1, 0, 0, -1}, {0, 1, 0, 0}};
  const uint32_t slice[4] = {0, 0, 0, 0};
  auto dirCb = MakeCB(sizeof(dirs), USAGE_DEFAULT, dirs);
  auto sliceCb = MakeCB(16, USAGE_DEFAULT, slice);
  const float grey[4] = {0.5f, 0.5f, 0.5f, 0.5f};
  for (auto [ps, cb] : {std::pair{"rhi_fmt_cube_ps.spv", dirCb.Get()}, {"rhi_fmt_array_ps.spv", sliceCb.Get()},
                        {"rhi_fmt_ms_ps.spv", static_cast<Buffer*>(nullptr)}}) {
    auto out = MakeRenderTarget(2, 1);
    Bind(out, 2, 1);
    context()->ClearRenderTargetView(out.rtv.Get(), grey);
    DrawFullScreen(ps, {}, cb);
    const Image img = ReadBack(out.texture.Get());
    EXPECT_EQ(img.RGBA8(0, 0), (std::array<uint8_t, 4>{0, 0, 0, 0})) << ps;
    EXPECT_EQ(img.RGBA8(1, 0), (std::array<uint8_t, 4>{0, 0, 0, 0})) << ps;
  }
}

// ---------------------------------------------------------------------------
// MSAA: the standard 4x pattern (D3D and Vulkan agree), in pixel units from
// the pixel's top-left corner.
constexpr float kSamples4[4][2] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};

// Which of a pixel's 4 samples a triangle (pixel coordinates) covers; false
// when a sample lies within 1/1000 px of an edge (either answer is right).
bool Coverage(const float tri[3][2], uint32_t x, uint32_t y, bool covered[4]) {
  for (int s = 0; s < 4; ++s) {
    const double px = x + kSamples4[s][0], py = y + kSamples4[s][1];
    double e[3];
    for (int i = 0; i < 3; ++i) {
      const float* a = tri[i];
      const float* b = tri[(i + 1) % 3];
      const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
      e[i] = ((b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])) / len;
      if (std::abs(e[i]) < 1e-3) return false;
    }
    covered[s] = (e[0] > 0 && e[1] > 0 && e[2] > 0) || (e[0] < 0 && e[1] < 0 && e[2] < 0);
  }
  return true;
}

TEST_F(RhiFormats, MsaaEdgeResolvesToTheCoverageWeightedAverage) {
  constexpr uint32_t W = 32, H = 32;
  const DXGI_FORMAT f = DXGI_FORMAT_R16G16B16A16_FLOAT;
  UINT levels = 0;
  ASSERT_EQ(device()->CheckMultisampleQualityLevels(f, 4, &levels), S_OK);
  if (levels == 0) GTEST_SKIP() << "no 4x MSAA for R16G16B16A16_FLOAT";
  EXPECT_EQ(levels, 1u) << "Vulkan has one (standard) pattern per count";
  ASSERT_EQ(device()->CheckMultisampleQualityLevels(f, 3, &levels), S_OK);
  EXPECT_EQ(levels, 0u);
  auto ms = MakeTex(Desc(W, H, f, BIND_RENDER_TARGET | BIND_SHADER_RESOURCE, 1, 4));
  auto resolved = MakeTex(Desc(W, H, f, BIND_SHADER_RESOURCE));
  ComPtr<RenderTargetView> rtv;
  ASSERT_EQ(device()->CreateRenderTargetView(ms.Get(), nullptr, rtv.ReleaseAndGetAddressOf()), S_OK);
  ComPtr<ShaderResourceView> srv;
  ASSERT_EQ(device()->CreateShaderResourceView(ms.Get(), nullptr, srv.ReleaseAndGetAddressOf()), S_OK);

  // Vertices on the 1/256-pixel grid, so the rasteriser's snapping is exact.
  const float tri[3][2] = {{3.125f, 2.6875f}, {29.3125f, 9.59375f}, {11.8125f, 30.203125f}};
  std::vector<ColorVertex> v;
  for (auto& p : tri) v.push_back({{p[0] / W * 2 - 1, 1 - p[1] / H * 2, 0.5f, 1}, {1, 1, 1, 1}});
  const float clear[4] = {0, 0, 0, 0};
  context()->OMSetRenderTargets(1, rtv.GetAddressOf(), nullptr);
  SetViewport(W, H);
  context()->ClearRenderTargetView(rtv.Get(), clear);
  NoCulling();
  DrawColored(v);
  context()->OMSetRenderTargets(0, nullptr, nullptr);
  context()->ResolveSubresource(resolved.Get(), 0, ms.Get(), 0, f);
  // Each sample read back on its own (Texture2DMS.Load) into RGBA32F.
  auto samples = MakeRenderTarget(W, H, DXGI_FORMAT_R32G32B32A32_FLOAT);
  Bind(samples, W, H);
  DrawFullScreen("rhi_fmt_ms_ps.spv", {srv.Get()});
  const Image avg = ReadBack(resolved.Get()), each = ReadBack(samples.texture.Get());
  int checked = 0, partial = 0, wrongAvg = 0, wrongSample = 0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      bool cov[4];
      if (!Coverage(tri, x, y, cov)) continue;
      ++checked;
      const int n = cov[0] + cov[1] + cov[2] + cov[3];
      partial += n > 0 && n < 4;
      for (uint32_t c = 0; c < 4; ++c) wrongAvg += avg.Float(x, y, c) != n / 4.0f;
      for (uint32_t s = 0; s < 4; ++s) wrongSample += each.Float(x, y, s) != (cov[s] ? 1.0f : 0.0f);
    }
  EXPECT_GT(checked, int(W * H) - 16);
  EXPECT_GT(partial, 40) << "the edges cross many pixels";
  EXPECT_EQ(wrongAvg, 0) << "resolved value = covered samples / 4";
  EXPECT_EQ(wrongSample, 0) << "sample i covered exactly at the standard position i";
}

// OMSetBlendState's sample mask: a full-target quad with mask 0b0101 writes
// samples 0 and 2 only, so the resolve is half the colour.
TEST_F(RhiFormats, SampleMaskSelectsTheWrittenSamples) {
  constexpr uint32_t W = 4, H = 4;
  const DXGI_FORMAT f = DXGI_FORMAT_R16G16B16A16_FLOAT;
  UINT levels = 0;
  ASSERT_EQ(device()->CheckMultisampleQualityLevels(f, 4, &levels), S_OK);
  if (levels == 0) GTEST_SKIP() << "no 4x MSAA for R16G16B16A16_FLOAT";
  auto ms = MakeTex(Desc(W, H, f, BIND_RENDER_TARGET | BIND_SHADER_RESOURCE, 1, 4));
  auto resolved = MakeTex(Desc(W, H, f, BIND_SHADER_RESOURCE));
  ComPtr<RenderTargetView> rtv;
  ASSERT_EQ(device()->CreateRenderTargetView(ms.Get(), nullptr, rtv.ReleaseAndGetAddressOf()), S_OK);
  ComPtr<ShaderResourceView> srv;
  ASSERT_EQ(device()->CreateShaderResourceView(ms.Get(), nullptr, srv.ReleaseAndGetAddressOf()), S_OK);
  const float clear[4] = {0, 0, 0, 0};
  context()->OMSetRenderTargets(1, rtv.GetAddressOf(), nullptr);
  SetViewport(W, H);
  context()->ClearRenderTargetView(rtv.Get(), clear);
  context()->OMSetBlendState(nullptr, nullptr, 0x5);
  const float white[4] = {1, 1, 1, 1};
  auto cb = MakeCB(16, USAGE_DEFAULT, white);
  DrawFullScreen("rhi_solid_ps.spv", {}, cb.Get());
  context()->OMSetBlendState(nullptr, nullptr, 0xffffffff);
  context()->OMSetRenderTargets(0, nullptr, nullptr);
  context()->ResolveSubresource(resolved.Get(), 0, ms.Get(), 0, f);
  auto samples = MakeRenderTarget(W, H, DXGI_FORMAT_R32G32B32A32_FLOAT);
  Bind(samples, W, H);
  DrawFullScreen("rhi_fmt_ms_ps.spv", {srv.Get()});
  const Image avg = ReadBack(resolved.Get()), each = ReadBack(samples.texture.Get());
  int wrong = 0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      for (uint32_t c = 0; c < 4; ++c) wrong += avg.Float(x, y, c) != 0.5f;
      for (uint32_t s = 0; s < 4; ++s) wrong += each.Float(x, y, s) != (s % 2 == 0 ? 1.0f : 0.0f);
    }
  EXPECT_EQ(wrong, 0);
}

// ---------------------------------------------------------------------------
class RhiFormatValidation : public RhiFormats {
 protected:
  void ExpectRejected(HRESULT hr, const char* what, HRESULT expected = E_INVALIDARG) {
    EXPECT_EQ(hr, expected) << what;
    std::string all;
    for (auto& m : Messages()) all += m.text + "\n";
    EXPECT_GE(CountMessages(LogLevel::Error, what), 1u) << "expected an error mentioning '" << what << "', got:\n" << all;
    ClearMessages();
  }
  template <class Call>
  void ExpectLogged(Call call, const char* what) {
    call();
    ExpectRejected(E_INVALIDARG, what);
  }
};

TEST_F(RhiFormatValidation, BadTextureDescriptionsAreRejectedWithMessages) {
  ComPtr<Texture2D> t;
  auto create = [&](TEXTURE2D_DESC d) { return device()->CreateTexture2D(&d, nullptr, t.ReleaseAndGetAddressOf()); };
  TEXTURE2D_DESC msMips = Desc(16, 16, DXGI_FORMAT_R8G8B8A8_UNORM, BIND_RENDER_TARGET, 1, 4);
  msMips.MipLevels = 2;
  ExpectRejected(create(msMips), "exactly one mip");
  ExpectRejected(create(Desc(16, 16, DXGI_FORMAT_R8G8B8A8_UNORM, BIND_RENDER_TARGET, 1, 3)), "SampleDesc.Count 3");
  TEXTURE2D_DESC quality = Desc(16, 16, DXGI_FORMAT_R8G8B8A8_UNORM, BIND_RENDER_TARGET, 1, 4);
  quality.SampleDesc.Quality = 1;
  ExpectRejected(create(quality), "Quality must be 0");
  quality.SampleDesc.Quality = STANDARD_MULTISAMPLE_PATTERN;
  EXPECT_EQ(create(quality), S_OK) << "the standard pattern is the one Vulkan uses";
  ExpectRejected(create(Desc(16, 16, DXGI_FORMAT_R8G8B8A8_UNORM, BIND_SHADER_RESOURCE, 5, 1, RESOURCE_MISC_TEXTURECUBE)),
                 "ArraySize 6*n");
  ExpectRejected(create(Desc(16, 8, DXGI_FORMAT_R8G8B8A8_UNORM, BIND_SHADER_RESOURCE, 6, 1, RESOURCE_MISC_TEXTURECUBE)),
                 "square");
  ExpectRejected(create(Desc(16, 16, DXGI_FORMAT_R24G8_TYPELESS, BIND_SHADER_RESOURCE)), "need BIND_DEPTH_STENCIL");
  ExpectRejected(create(Desc(16, 16, DXGI_FORMAT_R8G8B8A8_UNORM, BIND_DEPTH_STENCIL)), "BIND_DEPTH_STENCIL needs");
  EXPECT_FALSE(t);
}

TEST_F(RhiFormatValidation, BadViewsAreRejectedWithMessages) {
  auto depth = MakeTex(Desc(16, 16, DXGI_FORMAT_R32_TYPELESS, BIND_DEPTH_STENCIL | BIND_SHADER_RESOURCE, 4));
  auto colour = MakeTex(Desc(16, 16, DXGI_FORMAT_R32_TYPELESS, BIND_RENDER_TARGET | BIND_SHADER_RESOURCE));
  ComPtr<DepthStencilView> dsv;
  DEPTH_STENCIL_VIEW_DESC dd;
  dd.Format = DXGI_FORMAT_R32_TYPELESS;
  dd.ViewDimension = DSV_DIMENSION_TEXTURE2DARRAY;
  ExpectRejected(device()->CreateDepthStencilView(depth.Get(), &dd, dsv.ReleaseAndGetAddressOf()), "typeless");
  ExpectRejected(device()->CreateDepthStencilView(depth.Get(), nullptr, dsv.ReleaseAndGetAddressOf()), "typeless");
  dd.Format = DXGI_FORMAT_R32_FLOAT;
  ExpectRejected(device()->CreateDepthStencilView(depth.Get(), &dd, dsv.ReleaseAndGetAddressOf()), "not a depth format");
  dd.Format = DXGI_FORMAT_D32_FLOAT;
  dd.Array = {2, 3};
  ExpectRejected(device()->CreateDepthStencilView(depth.Get(), &dd, dsv.ReleaseAndGetAddressOf()), "out of range");
  dd.ViewDimension = DSV_DIMENSION_TEXTURE2D;
  ExpectRejected(device()->CreateDepthStencilView(depth.Get(), &dd, dsv.ReleaseAndGetAddressOf()), "*ARRAY");
  ComPtr<ShaderResourceView> srv;
  SHADER_RESOURCE_VIEW_DESC sd;
  sd.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  ExpectRejected(device()->CreateShaderResourceView(colour.Get(), &sd, srv.ReleaseAndGetAddressOf()), "typeless family");
  sd.Format = DXGI_FORMAT_R32_FLOAT;
  sd.ViewDimension = SRV_DIMENSION_TEXTURECUBE;
  ExpectRejected(device()->CreateShaderResourceView(colour.Get(), &sd, srv.ReleaseAndGetAddressOf()), "TEXTURECUBE");
  sd.ViewDimension = SRV_DIMENSION_TEXTURE2DMS;
  ExpectRejected(device()->CreateShaderResourceView(colour.Get(), &sd, srv.ReleaseAndGetAddressOf()), "multisampled");
  sd.ViewDimension = static_cast<SRV_DIMENSION>(8);  // BUFFEREX: not a texture view
  ExpectRejected(device()->CreateShaderResourceView(colour.Get(), &sd, srv.ReleaseAndGetAddressOf()), "ViewDimension 8");
  EXPECT_FALSE(dsv);
  EXPECT_FALSE(srv);
}

TEST_F(RhiFormatValidation, BadResolvesAndMixedSampleCountsAreRejected) {
  const DXGI_FORMAT f = DXGI_FORMAT_R8G8B8A8_UNORM;
  auto ms = MakeTex(Desc(8, 8, f, BIND_RENDER_TARGET, 1, 4));
  auto single = MakeTex(Desc(8, 8, f, BIND_RENDER_TARGET));
  auto small = MakeTex(Desc(4, 4, f, BIND_RENDER_TARGET));
  auto msUint = MakeTex(Desc(8, 8, DXGI_FORMAT_R8G8B8A8_UINT, BIND_RENDER_TARGET, 1, 4));
  auto uintDst = MakeTex(Desc(8, 8, DXGI_FORMAT_R8G8B8A8_UINT, BIND_RENDER_TARGET));
  ExpectLogged([&] { context()->ResolveSubresource(single.Get(), 0, single.Get(), 0, f); }, "not multisampled");
  ExpectLogged([&] { context()->ResolveSubresource(small.Get(), 0, ms.Get(), 0, f); }, "sizes differ");
  ExpectLogged([&] { context()->ResolveSubresource(uintDst.Get(), 0, msUint.Get(), 0, DXGI_FORMAT_R8G8B8A8_UINT); },
               "integer");
  ExpectLogged([&] { context()->ResolveSubresource(single.Get(), 0, ms.Get(), 0, DXGI_FORMAT_R32_FLOAT); }, "family");
  ExpectLogged([&] { context()->CopyResource(single.Get(), ms.Get()); }, "ResolveSubresource");
  ComPtr<RenderTargetView> a, b;
  ASSERT_EQ(device()->CreateRenderTargetView(ms.Get(), nullptr, a.ReleaseAndGetAddressOf()), S_OK);
  ASSERT_EQ(device()->CreateRenderTargetView(single.Get(), nullptr, b.ReleaseAndGetAddressOf()), S_OK);
  RenderTargetView* both[2] = {a.Get(), b.Get()};
  ExpectLogged([&] { context()->OMSetRenderTargets(2, both, nullptr); }, "SampleDesc.Count");
}

}  // namespace
}  // namespace rhitest
