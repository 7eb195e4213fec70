// Hull, domain and geometry shaders and the pipeline statistics query:
// tessellated primitive and domain-shader counts against the tessellator's
// formula, a geometry shader's quads against a CPU raster, patch-list sizes
// 1..32, and the front layer's errors for stages that do not fit together.
#include <algorithm>
#include <functional>
#include <map>

#include "RhiTest.h"
#include "d3dl/ShaderCompiler.h"

namespace rhitest {
namespace {

constexpr uint32_t kW = 64, kH = 64;
const float kBlack[4] = {0, 0, 0, 1};

// Integer partitioning of a quad domain with every factor >= 1 (rounded up):
// the inner (a-2) x (b-2) grid of quads, and one ring joining each outer
// edge's segments to the inner edge facing it. Uniform factors N give 2 N^2.
// (inside factors of 1 with larger outer factors are promoted to 2.)
struct QuadFactors {
  float edges[4];   // SV_TessFactor, edges u = 0, v = 0, u = 1, v = 1
  float inside[2];  // SV_InsideTessFactor, along u and v
  float pad[2];     // a constant buffer is a whole number of 16-byte registers
};
static_assert(sizeof(QuadFactors) == 32);
struct QuadTessellation {
  uint64_t triangles, vertices;
};
QuadTessellation ExpectedQuadTessellation(const QuadFactors& f) {
  int e[4], in[2];
  for (int i = 0; i < 4; ++i) e[i] = int(std::ceil(f.edges[i]));
  for (int i = 0; i < 2; ++i) in[i] = int(std::ceil(f.inside[i]));
  const bool allOne = e[0] == 1 && e[1] == 1 && e[2] == 1 && e[3] == 1 && in[0] == 1 && in[1] == 1;
  if (allOne) return {2, 4};
  for (int& i : in) i = std::max(i, 2);
  const int a = in[0] - 2, b = in[1] - 2;  // inner segments along u and v
  // Edges u = 0 and u = 1 run along v and face the inner v edges.
  const uint64_t ring = uint64_t(e[0] + b) + (e[1] + a) + (e[2] + b) + (e[3] + a);
  const uint64_t innerVertices = uint64_t(a + 1) * (b + 1);
  const uint64_t outerVertices = uint64_t(e[0] + e[1] + e[2] + e[3]);
  return {uint64_t(2 * a * b) + ring, innerVertices + outerVertices};
}

class RhiTessellation : public RhiTest {
 protected:
  // Counts the pipeline statistics of what `draw` records.
  template <class F>
  QUERY_DATA_PIPELINE_STATISTICS Statistics(F&& draw) {
    QUERY_DESC qd;
    qd.Query = QUERY_PIPELINE_STATISTICS;
    ComPtr<Query> q;
    EXPECT_EQ(device()->CreateQuery(&qd, q.ReleaseAndGetAddressOf()), S_OK);
    QUERY_DATA_PIPELINE_STATISTICS s{};
    if (!q) return s;
    context()->Begin(q.Get());
    draw();
    context()->End(q.Get());
    HRESULT hr;
    while ((hr = context()->GetData(q.Get(), &s, sizeof(s), 0)) == S_FALSE) {
    }
    EXPECT_EQ(hr, S_OK);
    return s;
  }
  template <class T>
  ComPtr<T> Load(const char* file, HRESULT (Device::*create)(const void*, size_t, T**)) {
    auto code = LoadSpirv(file);
    ComPtr<T> s;
    EXPECT_EQ((device()->*create)(code.data(), code.size() * 4, s.ReleaseAndGetAddressOf()), S_OK) << file;
    return s;
  }
  ComPtr<RasterizerState> NoCulling() {
    RASTERIZER_DESC rd;
    rd.CullMode = CULL_NONE;
    ComPtr<RasterizerState> rs;
    EXPECT_EQ(device()->CreateRasterizerState(&rd, rs.ReleaseAndGetAddressOf()), S_OK);
    return rs;
  }
  // A width x 1 RGBA8 texture of `texels` (0xAABBGGRR).
  ComPtr<ShaderResourceView> Texels(const std::vector<uint32_t>& texels) {
    auto t = MakeTexture(UINT(texels.size()), 1, DXGI_FORMAT_R8G8B8A8_UNORM, texels.data());
    return MakeSRV(t.Get());
  }
  // Binds the quad-patch pipeline: VS, HS (factors in b1), DS (placement in
  // b2, colour from t3 with s1), PS.
  void BindQuadPatch(Buffer* factors, Buffer* placement, ShaderResourceView* colour, SamplerState* smp) {
    context()->IASetInputLayout(nullptr);
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_4_CONTROL_POINT_PATCHLIST);
    context()->VSSetShader(vs_.Get());
    context()->HSSetShader(hs_.Get());
    context()->HSSetConstantBuffers(1, 1, &factors);
    context()->DSSetShader(ds_.Get());
    context()->DSSetConstantBuffers(2, 1, &placement);
    context()->DSSetShaderResources(3, 1, &colour);
    context()->DSSetSamplers(1, 1, &smp);
    context()->PSSetShader(ps_.Get());
    context()->RSSetState(noCull_.Get());
  }
  void LoadQuadPatchShaders() {
    vs_ = LoadVertexShader("rhi_tess_patch_vs.spv");
    hs_ = Load("rhi_tess_quad_hs.spv", &Device::CreateHullShader);
    ds_ = Load("rhi_tess_quad_ds.spv", &Device::CreateDomainShader);
    ps_ = LoadPixelShader("rhi_tess_colour_ps.spv");
    noCull_ = NoCulling();
  }
  void ExpectNoErrors() {
    std::string all;
    for (auto& m : Messages())
      if (m.level == LogLevel::Error || m.level == LogLevel::Warning) all += m.text + "\n";
    EXPECT_TRUE(all.empty()) << all;
  }

  ComPtr<VertexShader> vs_;
  ComPtr<HullShader> hs_;
  ComPtr<DomainShader> ds_;
  ComPtr<PixelShader> ps_;
  ComPtr<RasterizerState> noCull_;
};

TEST_F(RhiTessellation, QuadPatchCountsMatchTheTessellatorFormula) {
  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  LoadQuadPatchShaders();
  const float placement[4] = {1, 1, 0, 0};
  auto factorsCB = MakeCB(32);
  auto placementCB = MakeCB(16, USAGE_DEFAULT, placement);
  auto colour = Texels({0xff00ff00u});
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  const QuadFactors cases[] = {
      {{1, 1, 1, 1}, {1, 1}},  {{2, 2, 2, 2}, {2, 2}},  {{3, 3, 3, 3}, {3, 3}},
      {{5, 5, 5, 5}, {5, 5}},  {{8, 8, 8, 8}, {8, 8}},  {{16, 16, 16, 16}, {16, 16}},
      {{2, 3, 4, 5}, {3, 4}},  {{1, 6, 1, 6}, {4, 3}},  {{2.5f, 3.2f, 1, 7}, {5.5f, 3}},
  };
  for (const QuadFactors& f : cases) {
    const QuadTessellation want = ExpectedQuadTessellation(f);
    SCOPED_TRACE(::testing::Message() << "edges " << f.edges[0] << "," << f.edges[1] << "," << f.edges[2] << ","
                                      << f.edges[3] << " inside " << f.inside[0] << "," << f.inside[1]);
    WriteCB(factorsCB.Get(), &f, sizeof(f));
    context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
    BindQuadPatch(factorsCB.Get(), placementCB.Get(), colour.Get(), smp.Get());
    const auto s = Statistics([&] { context()->Draw(4, 0); });
    EXPECT_EQ(s.IAVertices, 4u);
    EXPECT_EQ(s.IAPrimitives, 1u);
    EXPECT_EQ(s.HSInvocations, 1u) << "patches";
    EXPECT_EQ(s.CInvocations, want.triangles) << "tessellated triangles reaching the clipper";
    // The specification invokes the domain shader at least once per domain
    // point; a driver may shade a shared point once per batch it falls in.
    EXPECT_GE(s.DSInvocations, want.vertices) << "at least one domain shader invocation per domain point";
    EXPECT_EQ(s.GSInvocations, 0u);
  }
  ExpectNoErrors();
}

// The patch is the clip-space square [-0.5, 0.5]^2 moved by the DS's b2 and
// coloured by its t3: every pixel centre inside is the texel, the rest black.
TEST_F(RhiTessellation, DomainShaderPlacesAndColoursThePatch) {
  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  LoadQuadPatchShaders();
  const float placement[4] = {1, 0.5f, 0.25f, -0.25f};  // x in [-0.25, 0.75], y in [-0.5, 0]
  const QuadFactors f{{4, 4, 4, 4}, {4, 4}};
  auto factorsCB = MakeCB(sizeof(QuadFactors), USAGE_DEFAULT, &f);
  auto placementCB = MakeCB(16, USAGE_DEFAULT, placement);
  auto colour = Texels({0xff2080e0u});
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  BindQuadPatch(factorsCB.Get(), placementCB.Get(), colour.Get(), smp.Get());
  context()->Draw(4, 0);
  auto img = ReadBack(rt.texture.Get());
  // Clip x -0.25..0.75 -> pixels 24..56; clip y 0..-0.5 -> rows 32..48.
  int wrong = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      const bool inside = x >= 24 && x < 56 && y >= 32 && y < 48;
      const auto p = img.RGBA8(x, y);
      const std::array<uint8_t, 4> want = inside ? std::array<uint8_t, 4>{0xe0, 0x80, 0x20, 0xff}
                                                 : std::array<uint8_t, 4>{0, 0, 0, 255};
      wrong += p != want;
    }
  EXPECT_EQ(wrong, 0) << "pixels differing from the CPU raster of the placed patch";
  ExpectNoErrors();
}

// The tessellator's winding is read in the domain with its origin at the
// upper left (u right, v down: D3D11's and Vulkan's default). This patch's
// v runs up the screen, so "triangle_cw" triangles appear counter-clockwise:
// back faces under the default rasterizer state; "triangle_ccw" ones are drawn.
TEST_F(RhiTessellation, OutputTopologyWindingDecidesCulling) {
  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  LoadQuadPatchShaders();
  const float placement[4] = {1, 1, 0, 0};
  const QuadFactors f{{3, 3, 3, 3}, {3, 3}};
  auto factorsCB = MakeCB(sizeof(QuadFactors), USAGE_DEFAULT, &f);
  auto placementCB = MakeCB(16, USAGE_DEFAULT, placement);
  auto colour = Texels({0xffffffffu});
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  ShaderCompileDesc cd;
  cd.SourcePath = TestSourcePath("tess_quad_hs.hlsl");
  cd.Stage = ShaderStage::Hull;
  cd.Defines = {{"OUTPUT_TOPOLOGY", "\"triangle_ccw\""}};
  std::vector<uint32_t> code;
  std::string errors;
  ASSERT_EQ(CompileHLSL(cd, &code, &errors), S_OK) << errors;
  ComPtr<HullShader> ccw;
  ASSERT_EQ(device()->CreateHullShader(code.data(), code.size() * 4, ccw.ReleaseAndGetAddressOf()), S_OK);
  for (HullShader* hs : {hs_.Get(), ccw.Get()}) {
    const bool clockwise = hs == hs_.Get();
    SCOPED_TRACE(clockwise ? "triangle_cw" : "triangle_ccw");
    context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
    BindQuadPatch(factorsCB.Get(), placementCB.Get(), colour.Get(), smp.Get());
    context()->HSSetShader(hs);
    context()->RSSetState(nullptr);  // CULL_BACK, clockwise front faces
    const auto s = Statistics([&] { context()->Draw(4, 0); });
    EXPECT_EQ(s.CInvocations, 18u);
    auto img = ReadBack(rt.texture.Get());
    EXPECT_EQ(img.RGBA8(32, 32)[0], clockwise ? 0 : 255);
  }
  ExpectNoErrors();
}

// Points -> quads in the GS (half-size and target size from b0, colour
// texel [SV_PrimitiveID] of t2 through s3), against a CPU raster.
TEST_F(RhiTessellation, GeometryShaderExpandsPointsToQuads) {
  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  auto vsCode = LoadSpirv("rhi_tess_points_vs.spv");
  auto vs = LoadVertexShader("rhi_tess_points_vs.spv");
  auto gs = Load("rhi_tess_quads_gs.spv", &Device::CreateGeometryShader);
  auto ps = LoadPixelShader("rhi_tess_colour_ps.spv");
  INPUT_ELEMENT_DESC e;
  e.SemanticName = "POSITION";
  e.Format = DXGI_FORMAT_R32G32_FLOAT;
  ComPtr<InputLayout> il;
  ASSERT_EQ(device()->CreateInputLayout(&e, 1, vsCode.data(), vsCode.size() * 4, il.ReleaseAndGetAddressOf()), S_OK);
  const float centres[][2] = {{12, 12}, {40, 16}, {20, 44}, {50, 50}, {56, 30}};
  const uint32_t colours[] = {0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xff00ffffu, 0xffff00ffu};
  const uint32_t count = 5;
  const float halfSize = 5;
  auto vb = MakeBuffer(BIND_VERTEX_BUFFER, centres, sizeof(centres));
  const float expand[4] = {halfSize, halfSize, float(kW), float(kH)};
  auto cb = MakeCB(16, USAGE_DEFAULT, expand);
  auto srv = Texels(std::vector<uint32_t>(colours, colours + count));
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  auto noCull = NoCulling();
  UINT stride = 8, offset = 0;
  context()->ClearRenderTargetView(rt.rtv.Get(), kBlack);
  context()->IASetInputLayout(il.Get());
  context()->IASetVertexBuffers(0, 1, vb.GetAddressOf(), &stride, &offset);
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_POINTLIST);
  context()->VSSetShader(vs.Get());
  context()->GSSetShader(gs.Get());
  context()->GSSetConstantBuffers(0, 1, cb.GetAddressOf());
  context()->GSSetShaderResources(2, 1, srv.GetAddressOf());
  context()->GSSetSamplers(3, 1, smp.GetAddressOf());
  context()->PSSetShader(ps.Get());
  context()->RSSetState(noCull.Get());
  const auto s = Statistics([&] { context()->Draw(count, 0); });
  EXPECT_EQ(s.IAVertices, count);
  EXPECT_EQ(s.IAPrimitives, count);
  EXPECT_EQ(s.GSInvocations, count);
  EXPECT_EQ(s.GSPrimitives, 2u * count) << "a 4-vertex strip is two triangles";
  EXPECT_EQ(s.CInvocations, 2u * count);
  EXPECT_EQ(s.HSInvocations, 0u);

  auto img = ReadBack(rt.texture.Get());
  int wrong = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      uint32_t want = 0xff000000u;
      for (uint32_t i = 0; i < count; ++i)
        if (x + 0.5f > centres[i][0] - halfSize && x + 0.5f < centres[i][0] + halfSize &&
            y + 0.5f > centres[i][1] - halfSize && y + 0.5f < centres[i][1] + halfSize)
          want = colours[i];
      const auto p = img.RGBA8(x, y);
      const uint32_t got = p[0] | p[1] << 8 | p[2] << 16 | uint32_t(p[3]) << 24;
      wrong += got != want;
    }
  EXPECT_EQ(wrong, 0) << "pixels differing from the CPU raster of the quads";
  ExpectNoErrors();
}

// Every patch size 1..32: three patches of n control points each give three
// HS patches and 3n vertex-shader invocations; 0 and 33 control points are
// not topologies.
TEST_F(RhiTessellation, PatchListsOf1To32ControlPointsDrawAnd0And33AreRejected) {
  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  auto vs = LoadVertexShader("rhi_tess_patch_vs.spv");
  auto ds = Load("rhi_tess_tri_ds.spv", &Device::CreateDomainShader);
  auto ps = LoadPixelShader("rhi_tess_colour_ps.spv");
  auto noCull = NoCulling();
  context()->IASetInputLayout(nullptr);
  context()->VSSetShader(vs.Get());
  context()->DSSetShader(ds.Get());
  context()->PSSetShader(ps.Get());
  context()->RSSetState(noCull.Get());
  for (uint32_t n = 1; n <= 32; ++n) {
    SCOPED_TRACE(::testing::Message() << n << " control points");
    ShaderCompileDesc cd;
    cd.SourcePath = TestSourcePath("tess_sized_hs.hlsl");
    cd.Stage = ShaderStage::Hull;
    cd.Defines = {{"CONTROL_POINTS", std::to_string(n)}};
    std::vector<uint32_t> code;
    std::string errors;
    ASSERT_EQ(CompileHLSL(cd, &code, &errors), S_OK) << errors;
    ComPtr<HullShader> hs;
    ASSERT_EQ(device()->CreateHullShader(code.data(), code.size() * 4, hs.ReleaseAndGetAddressOf()), S_OK);
    context()->HSSetShader(hs.Get());
    context()->IASetPrimitiveTopology(PatchListTopology(n));
    const auto s = Statistics([&] { context()->Draw(3 * n, 0); });
    EXPECT_EQ(s.IAVertices, 3u * n);
    EXPECT_EQ(s.VSInvocations, 3u * n);
    EXPECT_EQ(s.IAPrimitives, 3u);
    EXPECT_EQ(s.HSInvocations, 3u);
    EXPECT_EQ(s.CInvocations, 3u) << "one triangle per patch (all factors 1)";
  }
  ExpectNoErrors();

  // D3D11 values 32 and 65 would be patch lists of 0 and 33 control points.
  for (uint32_t value : {32u, 65u, 6u, 0xffffffffu}) {
    context()->IASetPrimitiveTopology(static_cast<PRIMITIVE_TOPOLOGY>(value));
    EXPECT_EQ(CountMessages(LogLevel::Error, "topology " + std::to_string(value) + " is not supported"), 1u) << value;
  }
  // The rejected calls left the 32-point topology set.
  const auto s = Statistics([&] { context()->Draw(64, 0); });
  EXPECT_EQ(s.HSInvocations, 2u);
  EXPECT_EQ(s.IAVertices, 64u);
}

// Stages that do not fit together skip the draw with one error each.
TEST_F(RhiTessellation, MismatchedStagesSkipTheDrawWithAnError) {
  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  LoadQuadPatchShaders();
  auto gs = Load("rhi_tess_quads_gs.spv", &Device::CreateGeometryShader);
  const QuadFactors f{{2, 2, 2, 2}, {2, 2}};
  const float placement[4] = {1, 1, 0, 0};
  auto factorsCB = MakeCB(sizeof(QuadFactors), USAGE_DEFAULT, &f);
  auto placementCB = MakeCB(16, USAGE_DEFAULT, placement);
  auto colour = Texels({0xffffffffu});
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  struct Case {
    const char* message;
    std::function<void()> setup;
  };
  const Case cases[] = {
      {"hull shader is bound without a domain shader", [&] { context()->DSSetShader(nullptr); }},
      {"domain shader is bound without a hull shader", [&] { context()->HSSetShader(nullptr); }},
      {"patch-list topology needs a hull and a domain shader",
       [&] {
         context()->HSSetShader(nullptr);
         context()->DSSetShader(nullptr);
       }},
      {"need a PRIMITIVE_TOPOLOGY_<n>_CONTROL_POINT_PATCHLIST",
       [&] { context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST); }},
      // Point-input GS after a triangle-emitting tessellator.
      {"geometry shader's input primitive", [&] { context()->GSSetShader(gs.Get()); }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.message);
    BindQuadPatch(factorsCB.Get(), placementCB.Get(), colour.Get(), smp.Get());
    context()->GSSetShader(nullptr);
    c.setup();
    ClearMessages();
    const auto s = Statistics([&] { context()->Draw(4, 0); });
    EXPECT_EQ(s.VSInvocations, 0u) << "the draw was skipped";
    EXPECT_EQ(CountMessages(LogLevel::Error, c.message), 1u);
  }
  context()->GSSetShader(nullptr);
  BindQuadPatch(factorsCB.Get(), placementCB.Get(), colour.Get(), smp.Get());
  const auto ok = Statistics([&] { context()->Draw(4, 0); });
  EXPECT_EQ(ok.HSInvocations, 1u) << "the complete pipeline draws again";
}

// The HS/DS/GS bindings follow the formula of Bindings.h (checked in the
// SPIR-V), and Create* rejects other stages and off-formula bindings.
TEST_F(RhiTessellation, CreateChecksStageAndBindingFormula) {
  auto bindingsOf = [](const std::vector<uint32_t>& w) {
    std::map<uint32_t, uint32_t> byId;  // id -> binding
    for (size_t i = 5; i < w.size(); i += w[i] >> 16)
      if ((w[i] & 0xffff) == 71 /*OpDecorate*/ && w[i + 2] == 33 /*Binding*/) byId[w[i + 1]] = w[i + 3];
    std::vector<uint32_t> b;
    for (auto& [id, binding] : byId) b.push_back(binding);
    std::sort(b.begin(), b.end());
    return b;
  };
  EXPECT_EQ(bindingsOf(LoadSpirv("rhi_tess_quad_hs.spv")),
            (std::vector<uint32_t>{VulkanBinding(ShaderStage::Hull, RegisterClass::ConstantBuffer, 1)}));
  EXPECT_EQ(bindingsOf(LoadSpirv("rhi_tess_quad_ds.spv")),
            (std::vector<uint32_t>{VulkanBinding(ShaderStage::Domain, RegisterClass::ConstantBuffer, 2),
                                   VulkanBinding(ShaderStage::Domain, RegisterClass::Texture, 3),
                                   VulkanBinding(ShaderStage::Domain, RegisterClass::Sampler, 1)}));
  EXPECT_EQ(bindingsOf(LoadSpirv("rhi_tess_quads_gs.spv")),
            (std::vector<uint32_t>{VulkanBinding(ShaderStage::Geometry, RegisterClass::ConstantBuffer, 0),
                                   VulkanBinding(ShaderStage::Geometry, RegisterClass::Texture, 2),
                                   VulkanBinding(ShaderStage::Geometry, RegisterClass::Sampler, 3)}));

  auto vsCode = LoadSpirv("rhi_tess_patch_vs.spv");
  ComPtr<HullShader> hs;
  EXPECT_EQ(device()->CreateHullShader(vsCode.data(), vsCode.size() * 4, hs.ReleaseAndGetAddressOf()), E_INVALIDARG);
  EXPECT_EQ(CountMessages(LogLevel::Error, "is a vertex shader"), 1u);
  auto hsCode = LoadSpirv("rhi_tess_quad_hs.spv");
  ComPtr<GeometryShader> gs;
  EXPECT_EQ(device()->CreateGeometryShader(hsCode.data(), hsCode.size() * 4, gs.ReleaseAndGetAddressOf()),
            E_INVALIDARG);
  EXPECT_EQ(CountMessages(LogLevel::Error, "is a hull shader"), 1u);
  // The HS's b1 moved to the pixel stage's b1: off the formula for a hull shader.
  for (size_t i = 5; i < hsCode.size(); i += hsCode[i] >> 16)
    if ((hsCode[i] & 0xffff) == 71 && hsCode[i + 2] == 33)
      hsCode[i + 3] = VulkanBinding(ShaderStage::Pixel, RegisterClass::ConstantBuffer, 1);
  EXPECT_EQ(device()->CreateHullShader(hsCode.data(), hsCode.size() * 4, hs.ReleaseAndGetAddressOf()), E_INVALIDARG);
  EXPECT_EQ(CountMessages(LogLevel::Error, "binding formula"), 1u);
  EXPECT_FALSE(hs);
  EXPECT_FALSE(gs);
}

// Begin/End misuse is reported; a query spanning a Flush counts the work
// before it.
TEST_F(RhiTessellation, StatisticsQueryMisuseIsReported) {
  QUERY_DESC qd;
  qd.Query = QUERY_PIPELINE_STATISTICS;
  ComPtr<Query> a, b;
  ASSERT_EQ(device()->CreateQuery(&qd, a.ReleaseAndGetAddressOf()), S_OK);
  ASSERT_EQ(device()->CreateQuery(&qd, b.ReleaseAndGetAddressOf()), S_OK);
  EXPECT_EQ(a->GetDataSize(), sizeof(QUERY_DATA_PIPELINE_STATISTICS));
  context()->End(a.Get());
  EXPECT_EQ(CountMessages(LogLevel::Error, "was not begun"), 1u);
  context()->Begin(a.Get());
  context()->Begin(b.Get());
  EXPECT_EQ(CountMessages(LogLevel::Error, "another QUERY_PIPELINE_STATISTICS query is active"), 1u);

  auto rt = MakeRenderTarget(kW, kH);
  Bind(rt, kW, kH);
  LoadQuadPatchShaders();
  const QuadFactors f{{3, 3, 3, 3}, {3, 3}};
  const float placement[4] = {1, 1, 0, 0};
  auto factorsCB = MakeCB(sizeof(QuadFactors), USAGE_DEFAULT, &f);
  auto placementCB = MakeCB(16, USAGE_DEFAULT, placement);
  auto colour = Texels({0xffffffffu});
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  BindQuadPatch(factorsCB.Get(), placementCB.Get(), colour.Get(), smp.Get());
  context()->Draw(4, 0);
  context()->Flush();
  EXPECT_EQ(CountMessages(LogLevel::Warning, "active at a Flush/Present"), 1u);
  context()->Draw(4, 0);
  context()->End(a.Get());  // already ended by the Flush: no further message
  EXPECT_EQ(CountMessages(LogLevel::Error, "was not begun"), 1u);
  QUERY_DATA_PIPELINE_STATISTICS s{};
  HRESULT hr;
  while ((hr = context()->GetData(a.Get(), &s, sizeof(s), 0)) == S_FALSE) {
  }
  EXPECT_EQ(hr, S_OK);
  EXPECT_EQ(s.HSInvocations, 1u) << "only the draw before the Flush";
  EXPECT_EQ(s.CInvocations, 18u);
}

}  // namespace
}  // namespace rhitest
