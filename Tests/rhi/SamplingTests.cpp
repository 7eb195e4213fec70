// Sampler filters and LOD bias, texture uploads, copies, GenerateMips.
#include "RhiTest.h"

namespace rhitest {
namespace {

class RhiSampling : public RhiTest {};

bool IsHard(uint8_t v) { return v == 0 || v == 255; }

TEST_F(RhiSampling, MagnificationPointVsLinear) {
  // 2x2 checker: white at (0,0) and (1,1).
  uint32_t checker[4] = {0xffffffffu, 0xff000000u, 0xff000000u, 0xffffffffu};
  auto tex = MakeTexture(2, 2, DXGI_FORMAT_R8G8B8A8_UNORM, checker);
  auto srv = MakeSRV(tex.Get());
  auto rt = MakeRenderTarget(8, 8);
  Bind(rt, 8, 8);
  for (FILTER f : {FILTER_MIN_MAG_MIP_POINT, FILTER_MIN_LINEAR_MAG_MIP_POINT}) {
    auto smp = MakeSampler(f);
    DrawSampled(srv.Get(), smp.Get());
    auto img = ReadBack(rt.texture.Get());
    int wrong = 0;
    for (uint32_t y = 0; y < 8; ++y)
      for (uint32_t x = 0; x < 8; ++x) {
        bool white = (x < 4) == (y < 4);
        if (img.RGBA8(x, y)[0] != (white ? 255 : 0)) ++wrong;
      }
    EXPECT_EQ(wrong, 0) << "filter 0x" << std::hex << f << ": magnification must be point (hard edges)";
  }
  auto linear = MakeSampler(FILTER_MIN_MAG_MIP_LINEAR);
  DrawSampled(srv.Get(), linear.Get());
  auto img = ReadBack(rt.texture.Get());
  // Pixel (3,3): uv 0.4375 -> texel coordinate 0.375: weights 0.625/0.375 per axis.
  // value = 0.625^2 + 0.375^2 = 0.53125 (white share).
  EXPECT_TRUE(Near(img.RGBA8(3, 3)[0], int(std::lround(0.53125 * 255)), 2)) << int(img.RGBA8(3, 3)[0]);
  int soft = 0;
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 8; ++x) soft += !IsHard(img.RGBA8(x, y)[0]);
  EXPECT_GT(soft, 16) << "linear magnification blends";
}

TEST_F(RhiSampling, MinificationLinearAverages) {
  // 4x4 texture, each 2x2 block has 4 distinct grey levels.
  uint8_t v[16] = {0, 40, 80, 120, 160, 200, 240, 20, 60, 100, 140, 180, 220, 10, 30, 50};
  std::vector<uint32_t> texels(16);
  for (int i = 0; i < 16; ++i) texels[i] = 0xff000000u | v[i] | (v[i] << 8) | (v[i] << 16);
  auto tex = MakeTexture(4, 4, DXGI_FORMAT_R8G8B8A8_UNORM, texels.data());
  auto srv = MakeSRV(tex.Get());
  auto rt = MakeRenderTarget(2, 2);
  Bind(rt, 2, 2);
  auto smp = MakeSampler(FILTER_MIN_LINEAR_MAG_MIP_POINT);
  DrawSampled(srv.Get(), smp.Get());
  auto img = ReadBack(rt.texture.Get());
  for (int by = 0; by < 2; ++by)
    for (int bx = 0; bx < 2; ++bx) {
      int sum = 0;
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) sum += v[(by * 2 + y) * 4 + bx * 2 + x];
      EXPECT_TRUE(Near(img.RGBA8(bx, by)[0], (sum + 2) / 4, 1)) << bx << "," << by << ": " << int(img.RGBA8(bx, by)[0]);
    }
  // Point minification picks one texel of each block (the one at floor(uv * 4)).
  auto point = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  DrawSampled(srv.Get(), point.Get());
  auto p = ReadBack(rt.texture.Get());
  EXPECT_EQ(p.RGBA8(0, 0)[0], v[1 * 4 + 1]);
  EXPECT_EQ(p.RGBA8(1, 1)[0], v[3 * 4 + 3]);
}

TEST_F(RhiSampling, MipLodBiasSelectsMoreDetailedMip) {
  // 16x16 texture, 4 mips with distinct colours: red, green, blue, white.
  const uint32_t colours[4] = {0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xffffffffu};
  std::vector<std::vector<uint32_t>> mips(4);
  SUBRESOURCE_DATA init[4];
  for (uint32_t m = 0; m < 4; ++m) {
    uint32_t s = 16 >> m;
    mips[m].assign(s * s, colours[m]);
    init[m] = {mips[m].data(), s * 4, 0};
  }
  auto tex = MakeTexture(16, 16, DXGI_FORMAT_R8G8B8A8_UNORM, nullptr, 4, init);
  auto srv = MakeSRV(tex.Get());
  auto rt = MakeRenderTarget(8, 8);
  Bind(rt, 8, 8);
  // uv spans 0..s over 8 pixels of a 16-texel texture: 2s texels per pixel, LOD = log2(2s) = 0.8.
  const float s = std::pow(2.0f, 0.8f) / 2.0f;
  for (FILTER f : {FILTER_MIN_MAG_MIP_POINT, FILTER_MIN_MAG_MIP_LINEAR}) {
    auto noBias = MakeSampler(f, TEXTURE_ADDRESS_WRAP, 0.0f);
    DrawSampled(srv.Get(), noBias.Get(), s, s);
    auto a = ReadBack(rt.texture.Get()).RGBA8(4, 4);
    auto bias = MakeSampler(f, TEXTURE_ADDRESS_WRAP, -0.5f);
    DrawSampled(srv.Get(), bias.Get(), s, s);
    auto b = ReadBack(rt.texture.Get()).RGBA8(4, 4);
    // LOD 0.8: mip 1 (green) dominates; LOD 0.3 with bias -0.5: mip 0 (red) dominates.
    EXPECT_GT(a[1], a[0]) << "filter 0x" << std::hex << f << " no bias: r=" << std::dec << int(a[0]) << " g=" << int(a[1]);
    EXPECT_GT(b[0], b[1]) << "filter 0x" << std::hex << f << " bias -0.5: r=" << std::dec << int(b[0]) << " g=" << int(b[1]);
    if (f == FILTER_MIN_MAG_MIP_POINT) {
      EXPECT_EQ(a[1], 255);
      EXPECT_EQ(b[0], 255);
    } else {
      EXPECT_TRUE(Near(a[1], 204, 16)) << int(a[1]);  // 80 % mip 1
      EXPECT_TRUE(Near(b[0], 178, 16)) << int(b[0]);  // 70 % mip 0
    }
  }
}

TEST_F(RhiSampling, SamplerDescriptionsDecode) {
  for (FILTER f : {FILTER_ANISOTROPIC, FILTER_COMPARISON_MIN_MAG_MIP_LINEAR, FILTER_MINIMUM_MIN_MAG_MIP_LINEAR,
                   FILTER_MAXIMUM_ANISOTROPIC, FILTER_MIN_POINT_MAG_MIP_LINEAR}) {
    SAMPLER_DESC d;
    d.Filter = f;
    d.MaxAnisotropy = 16;
    d.ComparisonFunc = COMPARISON_LESS_EQUAL;
    ComPtr<SamplerState> s;
    EXPECT_EQ(device()->CreateSamplerState(&d, s.ReleaseAndGetAddressOf()), S_OK) << std::hex << f;
  }
  SAMPLER_DESC d;
  d.AddressU = TEXTURE_ADDRESS_BORDER;
  d.AddressV = TEXTURE_ADDRESS_MIRROR_ONCE;
  d.BorderColor[0] = 0.5f;
  ComPtr<SamplerState> s;
  ClearMessages();
  EXPECT_EQ(device()->CreateSamplerState(&d, s.ReleaseAndGetAddressOf()), S_OK);
  EXPECT_EQ(CountMessages(LogLevel::Warning, "BorderColor"), 1u);
  // Border colour black: sampling outside [0,1] gives transparent black.
  uint32_t white = 0xffffffffu;
  auto tex = MakeTexture(1, 1, DXGI_FORMAT_R8G8B8A8_UNORM, &white);
  auto srv = MakeSRV(tex.Get());
  SAMPLER_DESC bd;
  bd.Filter = FILTER_MIN_MAG_MIP_POINT;
  bd.AddressU = bd.AddressV = TEXTURE_ADDRESS_BORDER;
  bd.BorderColor[0] = bd.BorderColor[1] = bd.BorderColor[2] = bd.BorderColor[3] = 0;
  ASSERT_EQ(device()->CreateSamplerState(&bd, s.ReleaseAndGetAddressOf()), S_OK);
  auto rt = MakeRenderTarget(4, 4);
  Bind(rt, 4, 4);
  DrawSampled(srv.Get(), s.Get(), 2, 2);  // uv 0..2: right/bottom half outside
  auto img = ReadBack(rt.texture.Get());
  EXPECT_EQ(img.RGBA8(0, 0)[0], 255);
  EXPECT_EQ(img.RGBA8(3, 3)[3], 0);
}

TEST_F(RhiSampling, UpdateSubresourceBoxAndCopySubresourceRegion) {
  std::vector<uint32_t> zero(16 * 16, 0xff000000u);
  TEXTURE2D_DESC d;
  d.Width = d.Height = 16;
  d.MipLevels = 2;
  d.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  d.BindFlags = BIND_SHADER_RESOURCE;
  SUBRESOURCE_DATA init[2] = {{zero.data(), 64, 0}, {zero.data(), 32, 0}};
  ComPtr<Texture2D> tex;
  ASSERT_EQ(device()->CreateTexture2D(&d, init, tex.ReleaseAndGetAddressOf()), S_OK);
  std::vector<uint32_t> patch(4 * 3, 0xff00ff00u);
  BOX box{2, 5, 0, 6, 8, 1};
  context()->UpdateSubresource(tex.Get(), 0, &box, patch.data(), 16, 0);
  std::vector<uint32_t> mip1(8 * 8, 0xffff0000u);
  context()->UpdateSubresource(tex.Get(), 1, nullptr, mip1.data(), 32, 0);
  auto img = ReadBack(tex.Get());
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      bool in = x >= 2 && x < 6 && y >= 5 && y < 8;
      ASSERT_EQ(img.RGBA8(x, y)[1], in ? 255 : 0) << x << "," << y;
    }
  EXPECT_EQ(ReadBack(tex.Get(), 1).RGBA8(7, 7)[2], 255);

  // Copy the patch region into another texture at an offset.
  auto dst = MakeTexture(16, 16, DXGI_FORMAT_R8G8B8A8_UNORM, zero.data());
  BOX src{2, 5, 0, 6, 8, 1};
  context()->CopySubresourceRegion(dst.Get(), 0, 10, 1, 0, tex.Get(), 0, &src);
  auto out = ReadBack(dst.Get());
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      bool in = x >= 10 && x < 14 && y >= 1 && y < 4;
      ASSERT_EQ(out.RGBA8(x, y)[1], in ? 255 : 0) << x << "," << y;
    }
  // Whole-resource copy, then sample the copy.
  auto full = MakeTexture(16, 16, DXGI_FORMAT_R8G8B8A8_UNORM, nullptr, 2);
  context()->CopyResource(full.Get(), tex.Get());
  EXPECT_EQ(ReadBack(full.Get(), 1).RGBA8(0, 0)[2], 255);
  EXPECT_EQ(ReadBack(full.Get()).RGBA8(3, 6)[1], 255);
}

TEST_F(RhiSampling, GenerateMipsAveragesLevels) {
  // 4x4: left half white, right half black -> mip 1 (2x2) columns, mip 2 (1x1) grey.
  std::vector<uint32_t> texels(16);
  for (int i = 0; i < 16; ++i) texels[i] = (i % 4) < 2 ? 0xffffffffu : 0xff000000u;
  TEXTURE2D_DESC d;
  d.Width = d.Height = 4;
  d.MipLevels = 0;  // full chain: 3 levels
  d.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  d.BindFlags = BIND_SHADER_RESOURCE | BIND_RENDER_TARGET;
  d.MiscFlags = RESOURCE_MISC_GENERATE_MIPS;
  ComPtr<Texture2D> tex;
  ASSERT_EQ(device()->CreateTexture2D(&d, nullptr, tex.ReleaseAndGetAddressOf()), S_OK);
  TEXTURE2D_DESC got;
  tex->GetDesc(&got);
  EXPECT_EQ(got.MipLevels, 3u);
  context()->UpdateSubresource(tex.Get(), 0, nullptr, texels.data(), 16, 0);
  auto srv = MakeSRV(tex.Get());
  context()->GenerateMips(srv.Get());
  auto m1 = ReadBack(tex.Get(), 1);
  EXPECT_EQ(m1.RGBA8(0, 0)[0], 255);
  EXPECT_EQ(m1.RGBA8(1, 1)[0], 0);
  auto m2 = ReadBack(tex.Get(), 2);
  EXPECT_TRUE(Near(m2.RGBA8(0, 0)[0], 128, 2)) << int(m2.RGBA8(0, 0)[0]);
  // And the mips are sampled afterwards (layout back to shader-read).
  auto rt = MakeRenderTarget(1, 1);
  Bind(rt, 1, 1);
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  DrawSampled(srv.Get(), smp.Get());
  EXPECT_TRUE(Near(ReadBack(rt.texture.Get()).RGBA8(0, 0)[0], 128, 2));
}

}  // namespace
}  // namespace rhitest
