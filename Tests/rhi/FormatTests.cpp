// Formats of a deferred renderer: an 8-target G-buffer of every listed
// format against CPU-quantised values, per-target write masks, and depth
// through a typeless texture's SRV (FormatViewTests.cpp: arrays, cubes, MSAA).
#include "FormatReference.h"
#include "FormatTestKit.h"

namespace rhitest {
namespace {

namespace ref = fmtref;

// ---------------------------------------------------------------------------
// G-buffer: 8 targets, each format's codes against the CPU encoding.
struct GBufferTarget {
  DXGI_FORMAT texture, view;  // view UNKNOWN: the texture's format
  // The GPU codes of pixel (x, y) and, per channel, the codes the Vulkan
  // specification allows for the shader's value (one code where it fixes it).
  void (*codes)(const Image&, uint32_t x, uint32_t y, uint32_t* got, ref::CodeRange* want, uint32_t* n);
  bool srgb;  // sRGB colour channels may differ by one code (approximate transfer function)
};

ref::CodeRange Exact(uint32_t code) { return {code, code}; }

float Scaled(uint32_t x, uint32_t y, uint32_t t, uint32_t c, float mul, float add) {
  return ref::Value(x, y, t, c) * mul + add;  // exact in float32, as on the GPU
}

const GBufferTarget kGBuffer[8] = {
    {DXGI_FORMAT_R10G10B10A2_UNORM, DXGI_FORMAT_UNKNOWN,
     [](const Image& i, uint32_t x, uint32_t y, uint32_t* g, ref::CodeRange* w, uint32_t* n) {
       const uint32_t p = U32(i, x, y);
       *n = 4;
       for (uint32_t c = 0; c < 3; ++c) {
         g[c] = (p >> (10 * c)) & 1023;
         w[c] = ref::UnormAllowed(ref::Value(x, y, 0, c), 10);
       }
       g[3] = p >> 30;
       w[3] = ref::UnormAllowed(ref::Value(x, y, 0, 3), 2);
     },
     false},
    {DXGI_FORMAT_R8_UNORM, DXGI_FORMAT_UNKNOWN,
     [](const Image& i, uint32_t x, uint32_t y, uint32_t* g, ref::CodeRange* w, uint32_t* n) {
       *n = 1;
       g[0] = *i.At(x, y);
       w[0] = ref::UnormAllowed(ref::Value(x, y, 1, 0), 8);
     },
     false},
    {DXGI_FORMAT_R11G11B10_FLOAT, DXGI_FORMAT_UNKNOWN,
     [](const Image& i, uint32_t x, uint32_t y, uint32_t* g, ref::CodeRange* w, uint32_t* n) {
       const uint32_t p = U32(i, x, y);
       *n = 3;
       g[0] = p & 2047, g[1] = (p >> 11) & 2047, g[2] = p >> 22;
       for (uint32_t c = 0; c < 3; ++c) {
         const float v = Scaled(x, y, 2, c, 40, -4);  // negatives clamp to 0
         w[c] = c < 2 ? ref::Float11Allowed(v) : ref::Float10Allowed(v);
       }
     },
     false},
    {DXGI_FORMAT_R16G16B16A16_FLOAT, DXGI_FORMAT_UNKNOWN,
     [](const Image& i, uint32_t x, uint32_t y, uint32_t* g, ref::CodeRange* w, uint32_t* n) {
       *n = 4;
       for (uint32_t c = 0; c < 4; ++c) {
         g[c] = U16(i, x, y, c);
         w[c] = Exact(ref::Half(Scaled(x, y, 3, c, 64, -16)));  // exact in half
       }
     },
     false},
    {DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, DXGI_FORMAT_UNKNOWN,
     [](const Image& i, uint32_t x, uint32_t y, uint32_t* g, ref::CodeRange* w, uint32_t* n) {
       *n = 4;
       for (uint32_t c = 0; c < 4; ++c) {
         g[c] = i.At(x, y)[c];
         const float v = ref::Value(x, y, 4, c);
         w[c] = c < 3 ? Exact(ref::Srgb8(v)) : ref::UnormAllowed(v, 8);  // alpha stays linear
       }
     },
     true},
    {DXGI_FORMAT_R8G8B8A8_UNORM, DXGI_FORMAT_UNKNOWN,
     [](const Image& i, uint32_t x, uint32_t y, uint32_t* g, ref::CodeRange* w, uint32_t* n) {
       *n = 4;
       for (uint32_t c = 0; c < 4; ++c) {
         g[c] = i.At(x, y)[c];
         w[c] = ref::UnormAllowed(ref::Value(x, y, 5, c), 8);
       }
     },
     false},
    {DXGI_FORMAT_R16G16_FLOAT, DXGI_FORMAT_UNKNOWN,
     [](const Image& i, uint32_t x, uint32_t y, uint32_t* g, ref::CodeRange* w, uint32_t* n) {
       *n = 2;
       for (uint32_t c = 0; c < 2; ++c) {
         g[c] = U16(i, x, y, c);
         w[c] = Exact(ref::Half(Scaled(x, y, 6, c, 1024, -100)));  // integers below 2^11
       }
     },
     false},
    {DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_R32_FLOAT,
     [](const Image& i, uint32_t x, uint32_t y, uint32_t* g, ref::CodeRange* w, uint32_t* n) {
       *n = 1;
       g[0] = U32(i, x, y);
       const float v = Scaled(x, y, 7, 0, 3, -1);
       std::memcpy(&w[0].lo, &v, 4);
       w[0].hi = w[0].lo;
     },
     false},
};

TEST_F(RhiFormats, GBufferRoundTripThroughEightFormats) {
  constexpr uint32_t W = 32, H = 16;
  ComPtr<Texture2D> tex[8];
  ComPtr<RenderTargetView> rtv[8];
  RenderTargetView* bound[8];
  for (int t = 0; t < 8; ++t) {
    tex[t] = MakeTex(Desc(W, H, kGBuffer[t].texture, BIND_RENDER_TARGET | BIND_SHADER_RESOURCE));
    RENDER_TARGET_VIEW_DESC vd;
    vd.Format = kGBuffer[t].view;
    ASSERT_EQ(device()->CreateRenderTargetView(tex[t].Get(), &vd, rtv[t].ReleaseAndGetAddressOf()), S_OK);
    bound[t] = rtv[t].Get();
  }
  context()->OMSetRenderTargets(8, bound, nullptr);
  SetViewport(W, H);
  DrawFullScreen("rhi_fmt_gbuffer_ps.spv", {});
  context()->OMSetRenderTargets(0, nullptr, nullptr);
  for (int t = 0; t < 8; ++t) {
    const Image img = ReadBack(tex[t].Get());
    int exact = 0, near = 0, wrong = 0;
    std::string first;
    for (uint32_t y = 0; y < H; ++y)
      for (uint32_t x = 0; x < W; ++x) {
        uint32_t got[4], n;
        ref::CodeRange want[4];
        kGBuffer[t].codes(img, x, y, got, want, &n);
        for (uint32_t c = 0; c < n; ++c) {
          if (want[c].Holds(got[c])) {
            ++exact;
          } else if (kGBuffer[t].srgb && c < 3 && ref::WithinOneStep(got[c], want[c].lo)) {
            ++near;
          } else {
            if (!wrong++) first = "(" + std::to_string(x) + "," + std::to_string(y) + ") channel " + std::to_string(c) +
                                  ": got " + std::to_string(got[c]) + ", want " + std::to_string(want[c].lo) +
                                  (want[c].hi != want[c].lo ? ".." + std::to_string(want[c].hi) : "");
          }
        }
      }
    EXPECT_EQ(wrong, 0) << "target " << t << " " << FormatName(kGBuffer[t].texture) << ": first mismatch " << first;
    EXPECT_GT(exact, int(W * H) / 2) << FormatName(kGBuffer[t].texture);
    if (near) std::printf("target %d %s: %d sRGB codes one step off\n", t, FormatName(kGBuffer[t].texture), near);
  }
}

// IndependentBlendEnable = 1 applies each target's write mask; 0 applies
// RenderTarget[0]'s to all eight.
TEST_F(RhiFormats, EightTargetsHonourPerTargetWriteMasks) {
  constexpr uint32_t W = 8, H = 8;
  const float white[4] = {1, 1, 1, 1};  // 255: the shader never writes 1.0 to targets 0 and 5
  for (BOOL independent : {1, 0}) {
    drrtest::RenderTarget rt[8];
    RenderTargetView* bound[8];
    for (int t = 0; t < 8; ++t) {
      rt[t] = MakeRenderTarget(W, H);
      bound[t] = rt[t].rtv.Get();
      context()->ClearRenderTargetView(bound[t], white);
    }
    BLEND_DESC bd;
    bd.IndependentBlendEnable = independent;
    bd.RenderTarget[2].RenderTargetWriteMask = 0;
    bd.RenderTarget[5].RenderTargetWriteMask = COLOR_WRITE_ENABLE_RED | COLOR_WRITE_ENABLE_ALPHA;
    ComPtr<BlendState> bs;
    ASSERT_EQ(device()->CreateBlendState(&bd, bs.ReleaseAndGetAddressOf()), S_OK);
    context()->OMSetBlendState(bs.Get(), nullptr, 0xffffffff);
    context()->OMSetRenderTargets(8, bound, nullptr);
    SetViewport(W, H);
    DrawFullScreen("rhi_fmt_gbuffer_ps.spv", {});
    context()->OMSetRenderTargets(0, nullptr, nullptr);
    context()->OMSetBlendState(nullptr, nullptr, 0xffffffff);
    const Image t0 = ReadBack(rt[0].texture.Get()), t2 = ReadBack(rt[2].texture.Get()), t5 = ReadBack(rt[5].texture.Get());
    int wrong = 0;
    for (uint32_t y = 0; y < H; ++y)
      for (uint32_t x = 0; x < W; ++x)
        for (uint32_t c = 0; c < 4; ++c) {
          const bool masked5 = independent && (c == 1 || c == 2);
          const float v2 = std::clamp(Scaled(x, y, 2, c, 40, -4), 0.0f, 1.0f);
          const ref::CodeRange kept{255u, 255u};
          wrong += !ref::UnormAllowed(ref::Value(x, y, 0, c), 8).Holds(t0.RGBA8(x, y)[c]);
          wrong += !(independent ? kept : ref::UnormAllowed(v2, 8)).Holds(t2.RGBA8(x, y)[c]);
          wrong += !(masked5 ? kept : ref::UnormAllowed(ref::Value(x, y, 5, c), 8)).Holds(t5.RGBA8(x, y)[c]);
        }
    EXPECT_EQ(wrong, 0) << "IndependentBlendEnable " << independent;
  }
}

// ---------------------------------------------------------------------------
// Depth written through a typeless texture's DSV and read through its SRV
// equals the rasteriser's depth: the plane through the vertices' z.
struct DepthFamily {
  DXGI_FORMAT texture, dsv, srv;
  float tolerance;     // against the CPU plane
  bool copyable;       // a STAGING copy of the depth aspect is possible
};

class RhiDepthFormats : public RhiFormats, public ::testing::WithParamInterface<DepthFamily> {};

TEST_P(RhiDepthFormats, DepthReadThroughTheSrvEqualsTheRasterisedPlane) {
  const DepthFamily fam = GetParam();
  constexpr uint32_t W = 32, H = 32;
  if (!device()->CheckFormatSupport(fam.texture, BIND_DEPTH_STENCIL | BIND_SHADER_RESOURCE))
    GTEST_SKIP() << FormatName(fam.texture) << " is not a depth format on this adapter";
  auto depth = MakeTex(Desc(W, H, fam.texture, BIND_DEPTH_STENCIL | BIND_SHADER_RESOURCE));
  DEPTH_STENCIL_VIEW_DESC dvd;
  dvd.Format = fam.dsv;
  ComPtr<DepthStencilView> dsv;
  ASSERT_EQ(device()->CreateDepthStencilView(depth.Get(), &dvd, dsv.ReleaseAndGetAddressOf()), S_OK);
  SHADER_RESOURCE_VIEW_DESC svd;
  svd.Format = fam.srv;
  ComPtr<ShaderResourceView> srv;
  ASSERT_EQ(device()->CreateShaderResourceView(depth.Get(), &svd, srv.ReleaseAndGetAddressOf()), S_OK);

  // Pixel-space vertices (multiples of 1/256 px) and their depths.
  const float px[3][3] = {{2.5f, 3.25f, 0.1f}, {30.0f, 9.5f, 0.9f}, {9.75f, 29.0f, 0.45f}};
  std::vector<ColorVertex> tri;
  for (auto& v : px) tri.push_back({{v[0] / W * 2 - 1, 1 - v[1] / H * 2, v[2], 1}, {1, 1, 1, 1}});
  auto colour = MakeRenderTarget(W, H);
  Bind(colour, W, H, dsv.Get());
  context()->ClearDepthStencilView(dsv.Get(), CLEAR_DEPTH | CLEAR_STENCIL, 1.0f, 0);
  NoCulling();
  DrawColored(tri);
  auto out = MakeRenderTarget(W, H, DXGI_FORMAT_R32_FLOAT);
  Bind(out, W, H);
  DrawFullScreen("rhi_fmt_load_ps.spv", {srv.Get()});
  ShaderResourceView* none = nullptr;
  context()->PSSetShaderResources(0, 1, &none);
  const Image sampled = ReadBack(out.texture.Get());
  Image copied;
  if (fam.copyable) copied = ReadBack(depth.Get());

  int inside = 0, wrong = 0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      double l[3];
      const double area = (px[1][0] - px[0][0]) * (px[2][1] - px[0][1]) - (px[2][0] - px[0][0]) * (px[1][1] - px[0][1]);
      for (int i = 0; i < 3; ++i) {
        const float* a = px[(i + 1) % 3];
        const float* b = px[(i + 2) % 3];
        l[i] = ((b[0] - a[0]) * (cy - a[1]) - (cx - a[0]) * (b[1] - a[1])) / area;
      }
      const double minL = std::min({l[0], l[1], l[2]});
      if (std::abs(minL) < 1e-3) continue;  // on an edge: either answer is right
      const double want = minL > 0 ? l[0] * px[0][2] + l[1] * px[1][2] + l[2] * px[2][2] : 1.0;
      inside += minL > 0;
      const float got = sampled.Float(x, y);
      if (std::abs(got - want) > fam.tolerance) ++wrong;
      if (fam.copyable && copied.Float(x, y) != got) ++wrong;  // the SRV reads the stored bits
    }
  EXPECT_GT(inside, 200);
  EXPECT_EQ(wrong, 0) << FormatName(fam.texture);
}

INSTANTIATE_TEST_SUITE_P(Families, RhiDepthFormats,
                         ::testing::Values(DepthFamily{DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_D32_FLOAT,
                                                       DXGI_FORMAT_R32_FLOAT, 2e-6f, true},
                                           DepthFamily{DXGI_FORMAT_R24G8_TYPELESS, DXGI_FORMAT_D24_UNORM_S8_UINT,
                                                       DXGI_FORMAT_R24_UNORM_X8_TYPELESS, 2.0f / (1 << 24), false}),
                         [](const auto& info) { return std::string(FormatName(info.param.texture)); });

// D24_UNORM_S8_UINT's stencil: a left-half quad writes 1 (REPLACE), then a
// full-screen quad drawn where stencil EQUAL 1 colours only the left half.
TEST_F(RhiFormats, D24S8StencilMasksASecondDraw) {
  constexpr uint32_t W = 16, H = 8;
  if (!device()->CheckFormatSupport(DXGI_FORMAT_D24_UNORM_S8_UINT, BIND_DEPTH_STENCIL))
    GTEST_SKIP() << "no D24_UNORM_S8_UINT depth-stencil on this adapter";
  auto ds = MakeTex(Desc(W, H, DXGI_FORMAT_D24_UNORM_S8_UINT, BIND_DEPTH_STENCIL));
  ComPtr<DepthStencilView> dsv;
  ASSERT_EQ(device()->CreateDepthStencilView(ds.Get(), nullptr, dsv.ReleaseAndGetAddressOf()), S_OK);
  auto rt = MakeRenderTarget(W, H);
  Bind(rt, W, H, dsv.Get());
  const float black[4] = {0, 0, 0, 1};
  context()->ClearRenderTargetView(rt.rtv.Get(), black);
  context()->ClearDepthStencilView(dsv.Get(), CLEAR_DEPTH | CLEAR_STENCIL, 1.0f, 0);
  auto stencilState = [&](COMPARISON_FUNC func, STENCIL_OP pass) {
    DEPTH_STENCIL_DESC d;
    d.DepthEnable = 0;
    d.StencilEnable = 1;
    d.FrontFace.StencilFunc = d.BackFace.StencilFunc = func;
    d.FrontFace.StencilPassOp = d.BackFace.StencilPassOp = pass;
    ComPtr<DepthStencilState> s;
    EXPECT_EQ(device()->CreateDepthStencilState(&d, s.ReleaseAndGetAddressOf()), S_OK);
    return s;
  };
  auto quad = [](float x0, float x1, float r, float g) {
    ColorVertex a{{x0, 1, 0.5f, 1}, {r, g, 0, 1}}, b{{x1, 1, 0.5f, 1}, {r, g, 0, 1}}, c{{x1, -1, 0.5f, 1}, {r, g, 0, 1}},
        d{{x0, -1, 0.5f, 1}, {r, g, 0, 1}};
    return std::vector<ColorVertex>{a, b, c, a, c, d};
  };
  auto write = stencilState(COMPARISON_ALWAYS, STENCIL_OP_REPLACE);
  context()->OMSetDepthStencilState(write.Get(), 1);
  DrawColored(quad(-1, 0, 1, 0));  // left half red, stencil 1
  auto test = stencilState(COMPARISON_EQUAL, STENCIL_OP_KEEP);
  context()->OMSetDepthStencilState(test.Get(), 1);
  DrawColored(quad(-1, 1, 0, 1));  // green where stencil == 1
  context()->OMSetDepthStencilState(nullptr, 0);
  const Image img = ReadBack(rt.texture.Get());
  int wrong = 0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      const auto p = img.RGBA8(x, y);
      wrong += x < W / 2 ? (p[0] != 0 || p[1] != 255) : (p[0] != 0 || p[1] != 0);
    }
  EXPECT_EQ(wrong, 0);
}

// The header-only sRGB pairs against the RHI's format table, by name: a
// format is sRGB exactly when its name ends in _SRGB, its linear twin is the
// table's format of the name without it, and every UNORM format with an _SRGB
// twin in the table maps to it.
TEST(RhiFormatNames, SrgbPairsAgreeWithTheFormatTable) {
  const std::string suffix = "_SRGB";
  auto inTable = [](DXGI_FORMAT f) { return std::string(FormatName(f)) != "UNSUPPORTED_FORMAT"; };
  auto byName = [&](const std::string& name) {
    for (uint32_t v = 1; v < 256; ++v)
      if (inTable(DXGI_FORMAT(v)) && name == FormatName(DXGI_FORMAT(v))) return DXGI_FORMAT(v);
    return DXGI_FORMAT_UNKNOWN;
  };
  int srgbFormats = 0;
  for (uint32_t v = 1; v < 256; ++v) {
    const auto f = DXGI_FORMAT(v);
    if (!inTable(f)) continue;
    const std::string name = FormatName(f);
    const bool named = name.size() > suffix.size() && name.ends_with(suffix);
    EXPECT_EQ(FormatIsSrgb(f), named) << name;
    if (named) {
      ++srgbFormats;
      EXPECT_EQ(FormatLinearOf(f), byName(name.substr(0, name.size() - suffix.size()))) << name;
      EXPECT_EQ(FormatSrgbOf(FormatLinearOf(f)), f) << name;
    } else {
      EXPECT_EQ(FormatLinearOf(f), f) << name;
      const DXGI_FORMAT twin = byName(name + suffix);
      EXPECT_EQ(FormatSrgbOf(f), twin == DXGI_FORMAT_UNKNOWN ? f : twin) << name;
    }
  }
  EXPECT_EQ(srgbFormats, 5);
}

}  // namespace
}  // namespace rhitest
