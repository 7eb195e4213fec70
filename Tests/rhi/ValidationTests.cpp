// Bad input returns an error and a log message (never a crash or a
// validation message), missing state skips draws, and the register-to-binding
// formula agrees between Bindings.h, cmake/HLSL.cmake and the compiled SPIR-V.
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "RhiTest.h"

namespace rhitest {
namespace {

class RhiValidation : public RhiTest {
 protected:
  // Expects `hr` to be a failure and exactly one new error message mentioning `what`.
  void ExpectRejected(HRESULT hr, const char* what, HRESULT expected = E_INVALIDARG) {
    EXPECT_EQ(hr, expected) << what;
    EXPECT_GE(CountMessages(LogLevel::Error) + CountMessages(LogLevel::Warning), 1u) << what << ": no message logged";
    bool named = CountMessages(LogLevel::Error, what) + CountMessages(LogLevel::Warning, what) > 0;
    std::string all;
    for (auto& m : Messages()) all += m.text + "\n";
    EXPECT_TRUE(named) << "message should mention '" << what << "', got:\n" << all;
    ClearMessages();
  }
  // A call without a result (a context call): exactly one error or warning,
  // an error naming `what`.
  void ExpectRejected(const char* what) {
    std::string all;
    for (auto& m : Messages()) all += m.text + "\n";
    EXPECT_EQ(CountMessages(LogLevel::Error) + CountMessages(LogLevel::Warning), 1u) << what << ": one message expected, got:\n" << all;
    EXPECT_EQ(CountMessages(LogLevel::Error, what), 1u) << "the error should mention '" << what << "', got:\n" << all;
    ClearMessages();
  }
};

TEST_F(RhiValidation, InvalidDescriptionsAreRejectedWithAMessage) {
  ComPtr<Buffer> b;
  BUFFER_DESC bd;
  ExpectRejected(device()->CreateBuffer(nullptr, nullptr, b.ReleaseAndGetAddressOf()), "pDesc");
  bd.BindFlags = BIND_VERTEX_BUFFER;
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, b.ReleaseAndGetAddressOf()), "ByteWidth");
  bd.ByteWidth = 20;
  bd.BindFlags = BIND_CONSTANT_BUFFER;
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, b.ReleaseAndGetAddressOf()), "multiple of 16");
  bd.ByteWidth = 64;
  bd.Usage = USAGE_IMMUTABLE;
  bd.BindFlags = BIND_VERTEX_BUFFER;
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, b.ReleaseAndGetAddressOf()), "IMMUTABLE");
  EXPECT_FALSE(b);

  ComPtr<Texture2D> t;
  TEXTURE2D_DESC td;
  td.Width = 0;
  td.Height = 4;
  td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  td.BindFlags = BIND_SHADER_RESOURCE;
  ExpectRejected(device()->CreateTexture2D(&td, nullptr, t.ReleaseAndGetAddressOf()), "size");
  td.Width = 4;
  td.Format = static_cast<DXGI_FORMAT>(999);
  ExpectRejected(device()->CreateTexture2D(&td, nullptr, t.ReleaseAndGetAddressOf()), "Format 999");
  td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  td.MipLevels = 4;
  ExpectRejected(device()->CreateTexture2D(&td, nullptr, t.ReleaseAndGetAddressOf()), "MipLevels 4");
  td.MipLevels = 1;
  td.SampleDesc.Count = 4;
  ExpectRejected(device()->CreateTexture2D(&td, nullptr, t.ReleaseAndGetAddressOf()), "SampleDesc.Count");
  td.SampleDesc.Count = 1;
  td.Format = DXGI_FORMAT_D32_FLOAT;
  td.BindFlags = BIND_RENDER_TARGET;
  ExpectRejected(device()->CreateTexture2D(&td, nullptr, t.ReleaseAndGetAddressOf()), "D32_FLOAT");
  td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  td.BindFlags = BIND_SHADER_RESOURCE;
  td.Usage = USAGE_STAGING;
  ExpectRejected(device()->CreateTexture2D(&td, nullptr, t.ReleaseAndGetAddressOf()), "STAGING");
  td.Usage = USAGE_DEFAULT;
  ASSERT_EQ(device()->CreateTexture2D(&td, nullptr, t.ReleaseAndGetAddressOf()), S_OK);

  // Views with the wrong bind flags / ranges.
  ComPtr<RenderTargetView> rtv;
  ExpectRejected(device()->CreateRenderTargetView(t.Get(), nullptr, rtv.ReleaseAndGetAddressOf()), "BIND_RENDER_TARGET");
  ComPtr<DepthStencilView> dsv;
  ExpectRejected(device()->CreateDepthStencilView(t.Get(), nullptr, dsv.ReleaseAndGetAddressOf()), "BIND_DEPTH_STENCIL");
  ComPtr<ShaderResourceView> srv;
  SHADER_RESOURCE_VIEW_DESC sv;
  sv.ViewDimension = SRV_DIMENSION_TEXTURE2D;
  sv.Texture.MostDetailedMip = 3;
  ExpectRejected(device()->CreateShaderResourceView(t.Get(), &sv, srv.ReleaseAndGetAddressOf()), "MostDetailedMip");
  ExpectRejected(device()->CreateShaderResourceView(nullptr, nullptr, srv.ReleaseAndGetAddressOf()), "pResource");
  sv.Texture.MostDetailedMip = 0;
  sv.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
  ExpectRejected(device()->CreateShaderResourceView(t.Get(), &sv, srv.ReleaseAndGetAddressOf()), "not compatible");

  // States.
  ComPtr<SamplerState> s;
  SAMPLER_DESC sd;
  sd.AddressU = static_cast<TEXTURE_ADDRESS_MODE>(0);
  ExpectRejected(device()->CreateSamplerState(&sd, s.ReleaseAndGetAddressOf()), "address mode");
  sd.AddressU = TEXTURE_ADDRESS_WRAP;
  sd.Filter = FILTER_ANISOTROPIC;
  sd.MaxAnisotropy = 17;
  ExpectRejected(device()->CreateSamplerState(&sd, s.ReleaseAndGetAddressOf()), "MaxAnisotropy 17");
  sd.MaxAnisotropy = 4;
  sd.MinLOD = 5;
  sd.MaxLOD = 1;
  ExpectRejected(device()->CreateSamplerState(&sd, s.ReleaseAndGetAddressOf()), "MinLOD");
  RASTERIZER_DESC rd;
  rd.CullMode = static_cast<CULL_MODE>(7);
  ComPtr<RasterizerState> rs;
  ExpectRejected(device()->CreateRasterizerState(&rd, rs.ReleaseAndGetAddressOf()), "CullMode 7");
  BLEND_DESC bl;
  bl.RenderTarget[0].SrcBlend = static_cast<BLEND>(99);
  ComPtr<BlendState> bs;
  ExpectRejected(device()->CreateBlendState(&bl, bs.ReleaseAndGetAddressOf()), "blend factor");

  // Shaders: not SPIR-V, wrong stage, bindings not following the formula.
  ComPtr<VertexShader> vs;
  const char junk[] = "DXBC this is not SPIR-V at all...";
  ExpectRejected(device()->CreateVertexShader(junk, 32, vs.ReleaseAndGetAddressOf()), "not SPIR-V");
  ExpectRejected(device()->CreateVertexShader(nullptr, 32, vs.ReleaseAndGetAddressOf()), "pShaderBytecode");
  auto psCode = LoadSpirv("rhi_color_ps.spv");
  ExpectRejected(device()->CreateVertexShader(psCode.data(), psCode.size() * 4, vs.ReleaseAndGetAddressOf()), "pixel shader");
  auto vsCode = LoadSpirv("rhi_bindings_vs.spv");
  ComPtr<PixelShader> ps;
  ExpectRejected(device()->CreatePixelShader(vsCode.data(), vsCode.size() * 4, ps.ReleaseAndGetAddressOf()), "vertex shader");

  // Input layouts: missing semantic, bad format, bad slot.
  auto colorVs = LoadSpirv("rhi_color_vs.spv");
  INPUT_ELEMENT_DESC e[2];
  e[0].SemanticName = "POSITION";
  e[0].Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
  ComPtr<InputLayout> il;
  ExpectRejected(device()->CreateInputLayout(e, 1, colorVs.data(), colorVs.size() * 4, il.ReleaseAndGetAddressOf()), "COLOR0");
  e[1].SemanticName = "COLOR";
  e[1].Format = DXGI_FORMAT_BC1_UNORM;
  ExpectRejected(device()->CreateInputLayout(e, 2, colorVs.data(), colorVs.size() * 4, il.ReleaseAndGetAddressOf()), "not a vertex format");
  e[1].Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  e[1].InputSlot = 16;
  ExpectRejected(device()->CreateInputLayout(e, 2, colorVs.data(), colorVs.size() * 4, il.ReleaseAndGetAddressOf()), "InputSlot 16");
  e[1].InputSlot = 1;
  e[1].SemanticName = "color";  // case-insensitive
  EXPECT_EQ(device()->CreateInputLayout(e, 2, colorVs.data(), colorVs.size() * 4, il.ReleaseAndGetAddressOf()), S_OK);

  // Context calls with bad arguments.
  context()->VSSetConstantBuffers(14, 1, b.GetAddressOf());
  EXPECT_EQ(CountMessages(LogLevel::Error, "out of range"), 1u);
  ClearMessages();
  MAPPED_SUBRESOURCE m;
  ExpectRejected(context()->Map(t.Get(), 0, MAP_WRITE_DISCARD, 0, &m), "DYNAMIC or STAGING");
  ExpectRejected(context()->Map(t.Get(), 5, MAP_READ, 0, &m), "subresource 5");
  QUERY_DESC qd;
  qd.Query = static_cast<QUERY>(42);
  ComPtr<Query> q;
  ExpectRejected(device()->CreateQuery(&qd, q.ReleaseAndGetAddressOf()), "query type 42");
  SWAP_CHAIN_DESC scd;
  ComPtr<SwapChain> sc;
  ExpectRejected(device()->CreateHeadlessSwapChain(&scd, sc.ReleaseAndGetAddressOf()), "explicit size");
}

TEST_F(RhiValidation, DrawsWithMissingStateAreSkippedAndLoggedOnce) {
  for (int i = 0; i < 3; ++i) context()->Draw(3, 0);
  EXPECT_EQ(CountMessages(LogLevel::Error, "no vertex shader"), 1u);
  auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
  context()->VSSetShader(vs.Get());
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  for (int i = 0; i < 3; ++i) context()->Draw(3, 0);
  EXPECT_EQ(CountMessages(LogLevel::Error, "no render target"), 1u);
  context()->DrawIndexed(3, 0, 0);
  DEVICE_STATS st;
  device()->GetStats(&st);
  EXPECT_EQ(st.DrawCalls, 0u);
  // Input layout that does not feed the shader's inputs.
  auto rt = MakeRenderTarget(4, 4);
  Bind(rt, 4, 4);
  auto cvs = LoadVertexShader("rhi_color_vs.spv");
  context()->VSSetShader(cvs.Get());
  context()->Draw(3, 0);
  EXPECT_EQ(CountMessages(LogLevel::Error, "has no element"), 1u);
  context()->Flush();
}

// Indirect draws: an argument buffer without RESOURCE_MISC_DRAWINDIRECT_ARGS,
// an offset that is not a multiple of 4 or arguments past the buffer's end
// drop the call with one error; with every state bound, so that nothing else
// would stop the draw, and the same buffer then draws.
TEST_F(RhiValidation, IndirectDrawArgumentsAreRejectedWithAMessage) {
  BUFFER_DESC bd;
  bd.ByteWidth = 48;
  bd.BindFlags = BIND_CONSTANT_BUFFER;
  bd.MiscFlags = RESOURCE_MISC_DRAWINDIRECT_ARGS;
  ComPtr<Buffer> args;
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, args.ReleaseAndGetAddressOf()), "BIND_CONSTANT_BUFFER");
  bd.BindFlags = 0;
  bd.ByteWidth = 36;
  // A full-screen triangle (3 vertices, 1 instance): DrawInstancedIndirect's
  // record at byte 0, DrawIndexedInstancedIndirect's at byte 16.
  const UINT words[9] = {3, 1, 0, 0, 3, 1, 0, 0, 0};
  const SUBRESOURCE_DATA init{words, 0, 0};
  ASSERT_EQ(device()->CreateBuffer(&bd, &init, args.ReleaseAndGetAddressOf()), S_OK);
  const uint16_t indices[3] = {0, 1, 2};
  auto ib = MakeBuffer(BIND_INDEX_BUFFER, indices, sizeof(indices));
  auto noFlag = MakeBuffer(BIND_INDEX_BUFFER, words, sizeof(words));

  auto rt = MakeRenderTarget(4, 4);
  Bind(rt, 4, 4);
  const float black[4] = {0, 0, 0, 1}, red[4] = {1, 0, 0, 1};
  context()->ClearRenderTargetView(rt.rtv.Get(), black);
  BindSolidFullScreen(red);
  context()->IASetIndexBuffer(ib.Get(), DXGI_FORMAT_R16_UINT, 0);

  context()->DrawInstancedIndirect(nullptr, 0);
  ExpectRejected("DrawInstancedIndirect: pBufferForArgs is null");
  context()->DrawInstancedIndirect(noFlag.Get(), 0);
  ExpectRejected("DrawInstancedIndirect: the buffer was not created with RESOURCE_MISC_DRAWINDIRECT_ARGS");
  context()->DrawIndexedInstancedIndirect(noFlag.Get(), 0);
  ExpectRejected("DrawIndexedInstancedIndirect: the buffer was not created with RESOURCE_MISC_DRAWINDIRECT_ARGS");
  context()->DrawInstancedIndirect(args.Get(), 2);
  ExpectRejected("AlignedByteOffsetForArgs 2 is not a multiple of 4");
  context()->DrawIndexedInstancedIndirect(args.Get(), 6);
  ExpectRejected("AlignedByteOffsetForArgs 6 is not a multiple of 4");
  context()->DrawInstancedIndirect(args.Get(), 24);  // 24 + 16 > 36
  ExpectRejected("AlignedByteOffsetForArgs 24: its 16 bytes of arguments pass the end of the 36-byte buffer");
  context()->DrawIndexedInstancedIndirect(args.Get(), 20);  // 20 + 20 > 36, where 20 + 16 fits
  ExpectRejected("AlignedByteOffsetForArgs 20: its 20 bytes of arguments pass the end of the 36-byte buffer");
  context()->DrawIndexedInstancedIndirect(args.Get(), 0xfffffffcu);  // the end past 2^32
  ExpectRejected("AlignedByteOffsetForArgs 4294967292");
  DEVICE_STATS st;
  device()->GetStats(&st);
  EXPECT_EQ(st.DrawCalls, 0u);
  EXPECT_EQ(ReadBack(rt.texture.Get()).RGBA8(1, 1)[0], 0) << "a rejected call drew";

  context()->DrawInstancedIndirect(args.Get(), 0);
  context()->DrawIndexedInstancedIndirect(args.Get(), 16);  // 16 + 20 = 36: the last bytes
  EXPECT_EQ(CountMessages(LogLevel::Error) + CountMessages(LogLevel::Warning), 0u);
  device()->GetStats(&st);
  EXPECT_EQ(st.DrawCalls, 2u);
  EXPECT_EQ(ReadBack(rt.texture.Get()).RGBA8(1, 1)[0], 255);
}

// ---------------------------------------------------------------------------
// The binding formula.
std::map<std::string, uint32_t> ReflectBindings(const std::vector<uint32_t>& w) {
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, uint32_t> bindings, sets, varType, pointee;
  for (size_t i = 5; i < w.size();) {
    uint32_t op = w[i] & 0xffff, n = w[i] >> 16;
    if (n == 0) break;
    if (op == 5 /*OpName*/) names[w[i + 1]] = reinterpret_cast<const char*>(&w[i + 2]);
    if (op == 71 /*OpDecorate*/ && w[i + 2] == 33 /*Binding*/) bindings[w[i + 1]] = w[i + 3];
    if (op == 71 && w[i + 2] == 34 /*DescriptorSet*/) sets[w[i + 1]] = w[i + 3];
    if (op == 32 /*OpTypePointer*/) pointee[w[i + 1]] = w[i + 3];
    if (op == 59 /*OpVariable*/) varType[w[i + 2]] = w[i + 1];
    i += n;
  }
  std::map<std::string, uint32_t> r;
  for (auto& [id, b] : bindings) {
    std::string name = names[id];
    if (name.empty()) name = names[pointee[varType[id]]];  // cbuffer: the block type carries the name
    EXPECT_EQ(sets[id], 0u) << name;
    r[name] = b;
  }
  return r;
}

TEST_F(RhiValidation, BindingFormulaMatchesHeaderCMakeAndSpirv) {
  // 1. cmake/HLSL.cmake, parsed at test time.
  const std::string hlslCmake = TestSourcePath("HLSL.cmake");
  std::ifstream in(hlslCmake);
  ASSERT_TRUE(in) << hlslCmake;
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  auto value = [&](const char* var) {
    std::smatch m;
    std::regex re(std::string("set\\(") + var + "\\s+([0-9]+)\\)");
    EXPECT_TRUE(std::regex_search(text, m, re)) << var;
    return m.empty() ? ~0u : static_cast<uint32_t>(std::stoul(m[1]));
  };
  EXPECT_EQ(value("D3DL_STAGE_STRIDE"), kStageBindingStride);
  EXPECT_EQ(value("D3DL_CBUFFER_BASE"), kConstantBufferBase);
  EXPECT_EQ(value("D3DL_TEXTURE_BASE"), kTextureBase);
  EXPECT_EQ(value("D3DL_SAMPLER_BASE"), kSamplerBase);
  EXPECT_NE(text.find("--shift-UBO-binding"), std::string::npos);

  // 2. The compiled SPIR-V declares what the formula says.
  auto ps = ReflectBindings(LoadSpirv("rhi_bindings_ps.spv"));
  EXPECT_EQ(ps["Extra"], VulkanBinding(ShaderStage::Pixel, RegisterClass::ConstantBuffer, 3));
  EXPECT_EQ(ps["texA"], VulkanBinding(ShaderStage::Pixel, RegisterClass::Texture, 5));
  EXPECT_EQ(ps["smpB"], VulkanBinding(ShaderStage::Pixel, RegisterClass::Sampler, 2));
  EXPECT_EQ(ps["texA"], 72u + 16u + 5u);
  // u# and buffer SRVs of the compute stage (5): cs_raw_cs.hlsl declares t1 and u2.
  EXPECT_EQ(value("D3DL_UAV_BASE"), kUnorderedAccessBase);
  EXPECT_NE(text.find("--shift-UAV-binding"), std::string::npos);
  auto cs = ReflectBindings(LoadSpirv("rhi_cs_raw_cs.spv"));
  EXPECT_EQ(cs["g_RawIn"], VulkanBinding(ShaderStage::Compute, RegisterClass::Texture, 1));
  EXPECT_EQ(cs["g_RawOut"], VulkanBinding(ShaderStage::Compute, RegisterClass::UnorderedAccess, 2));
  EXPECT_EQ(cs["g_RawOut"], 5u * 72u + 64u + 2u);
  auto vs = ReflectBindings(LoadSpirv("rhi_bindings_vs.spv"));
  EXPECT_EQ(vs["VSParams"], VulkanBinding(ShaderStage::Vertex, RegisterClass::ConstantBuffer, 1));
  EXPECT_EQ(vs["vsTex"], VulkanBinding(ShaderStage::Vertex, RegisterClass::Texture, 2));
  EXPECT_EQ(vs["vsSmp"], VulkanBinding(ShaderStage::Vertex, RegisterClass::Sampler, 1));

  // 3. The RHI binds D3D slots to exactly those bindings: draw with resources
  // in VS t2/s1/b1 and PS t5/s2/b3.
  uint32_t red = 0xff0000ffu, white = 0xffffffffu;
  auto texA = MakeTexture(1, 1, DXGI_FORMAT_R8G8B8A8_UNORM, &red);
  auto texV = MakeTexture(1, 1, DXGI_FORMAT_R8G8B8A8_UNORM, &white);
  auto srvA = MakeSRV(texA.Get());
  auto srvV = MakeSRV(texV.Get());
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  const float tint[4] = {1, 1, 1, 0.5f};
  const float offset[4] = {0, 0, 0, 0};
  auto cbP = MakeCB(16, USAGE_DEFAULT, tint);
  auto cbV = MakeCB(16, USAGE_DEFAULT, offset);
  auto rt = MakeRenderTarget(4, 4);
  Bind(rt, 4, 4);
  auto v = LoadVertexShader("rhi_bindings_vs.spv");
  auto p = LoadPixelShader("rhi_bindings_ps.spv");
  context()->VSSetShader(v.Get());
  context()->PSSetShader(p.Get());
  context()->VSSetShaderResources(2, 1, srvV.GetAddressOf());
  context()->VSSetSamplers(1, 1, smp.GetAddressOf());
  context()->VSSetConstantBuffers(1, 1, cbV.GetAddressOf());
  context()->PSSetShaderResources(5, 1, srvA.GetAddressOf());
  context()->PSSetSamplers(2, 1, smp.GetAddressOf());
  context()->PSSetConstantBuffers(3, 1, cbP.GetAddressOf());
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  context()->Draw(3, 0);
  auto img = ReadBack(rt.texture.Get());
  auto px = img.RGBA8(2, 2);
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[1], 0);
  EXPECT_TRUE(Near(px[3], 128)) << int(px[3]);
}

// Compute and unordered access: bad descriptions are refused at creation,
// bad context calls are logged and skipped.
TEST_F(RhiValidation, ComputeAndUavArgumentsAreRejectedWithAMessage) {
  ComPtr<Buffer> raw;
  BUFFER_DESC bd;
  bd.ByteWidth = 64;
  bd.BindFlags = BIND_UNORDERED_ACCESS;
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, raw.ReleaseAndGetAddressOf()), "typed buffer views");
  bd.MiscFlags = RESOURCE_MISC_BUFFER_STRUCTURED;
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, raw.ReleaseAndGetAddressOf()), "StructureByteStride 0");
  bd.StructureByteStride = 24;  // does not divide 64
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, raw.ReleaseAndGetAddressOf()), "StructureByteStride 24");
  bd.StructureByteStride = 16;
  bd.MiscFlags = RESOURCE_MISC_BUFFER_STRUCTURED | RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS;
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, raw.ReleaseAndGetAddressOf()), "together");
  bd.MiscFlags = RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS;
  bd.Usage = USAGE_DYNAMIC;
  bd.CPUAccessFlags = CPU_ACCESS_WRITE;
  ExpectRejected(device()->CreateBuffer(&bd, nullptr, raw.ReleaseAndGetAddressOf()), "USAGE_DEFAULT");
  bd.Usage = USAGE_DEFAULT;
  bd.CPUAccessFlags = 0;
  ASSERT_EQ(device()->CreateBuffer(&bd, nullptr, raw.ReleaseAndGetAddressOf()), S_OK);

  ComPtr<UnorderedAccessView> uav;
  ExpectRejected(device()->CreateUnorderedAccessView(raw.Get(), nullptr, uav.ReleaseAndGetAddressOf()), "needs a description");
  UNORDERED_ACCESS_VIEW_DESC ud;
  ud.Format = DXGI_FORMAT_R32_TYPELESS;
  ud.ViewDimension = UAV_DIMENSION_BUFFER;
  ud.Buffer = {0, 16, BUFFER_UAV_FLAG_RAW | BUFFER_UAV_FLAG_APPEND};
  ExpectRejected(device()->CreateUnorderedAccessView(raw.Get(), &ud, uav.ReleaseAndGetAddressOf()), "counters", E_NOTIMPL);
  ud.Buffer = {0, 17, BUFFER_UAV_FLAG_RAW};
  ExpectRejected(device()->CreateUnorderedAccessView(raw.Get(), &ud, uav.ReleaseAndGetAddressOf()), "out of range");
  ud.Buffer = {0, 16, 0};
  ExpectRejected(device()->CreateUnorderedAccessView(raw.Get(), &ud, uav.ReleaseAndGetAddressOf()), "R32_TYPELESS");
  ud.Buffer = {0, 16, BUFFER_UAV_FLAG_RAW};
  ASSERT_EQ(device()->CreateUnorderedAccessView(raw.Get(), &ud, uav.ReleaseAndGetAddressOf()), S_OK);
  ComPtr<ShaderResourceView> srv;
  ExpectRejected(device()->CreateShaderResourceView(raw.Get(), nullptr, srv.ReleaseAndGetAddressOf()), "BIND_SHADER_RESOURCE");
  auto tex = MakeTexture(4, 4, DXGI_FORMAT_R8G8B8A8_UNORM, nullptr);
  ExpectRejected(device()->CreateUnorderedAccessView(tex.Get(), nullptr, uav.ReleaseAndGetAddressOf()), "BIND_UNORDERED_ACCESS");
  ComPtr<ComputeShader> cs;
  const auto psCode = LoadSpirv("rhi_color_ps.spv");
  ExpectRejected(device()->CreateComputeShader(psCode.data(), psCode.size() * 4, cs.ReleaseAndGetAddressOf()), "pixel shader");

  // Context calls: logged, nothing recorded.
  ASSERT_EQ(device()->CreateUnorderedAccessView(raw.Get(), &ud, uav.ReleaseAndGetAddressOf()), S_OK);
  auto expectLogged = [&](const char* what) {
    EXPECT_GE(CountMessages(LogLevel::Error, what), 1u) << what;
    ClearMessages();
  };
  UnorderedAccessView* u = uav.Get();
  context()->CSSetUnorderedAccessViews(7, 2, &u, nullptr);
  expectLogged("slots 7..9");
  context()->Dispatch(1, 1, 1);
  expectLogged("no compute shader");
  context()->Dispatch(70000, 1, 1);
  expectLogged("65535");
  context()->DispatchIndirect(raw.Get(), 0);
  expectLogged("RESOURCE_MISC_DRAWINDIRECT_ARGS");
  bd.MiscFlags = RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS | RESOURCE_MISC_DRAWINDIRECT_ARGS;
  ComPtr<Buffer> args;
  ASSERT_EQ(device()->CreateBuffer(&bd, nullptr, args.ReleaseAndGetAddressOf()), S_OK);
  context()->DispatchIndirect(args.Get(), 56);  // 56 + 12 > 64
  expectLogged("AlignedByteOffsetForArgs 56");
  const float values[4] = {};
  context()->ClearUnorderedAccessViewFloat(u, values);
  expectLogged("float clears");
  context()->ClearUnorderedAccessViewFloat(nullptr, values);
  expectLogged("pUnorderedAccessView is null");
  context()->DispatchIndirect(nullptr, 0);
  expectLogged("pBufferForArgs is null");
  EXPECT_EQ(context()->GetData(nullptr, nullptr, 0, 0), E_INVALIDARG);
  expectLogged("pAsync is null");
  auto rt = MakeRenderTarget(4, 4);
  context()->OMSetRenderTargetsAndUnorderedAccessViews(1, rt.rtv.GetAddressOf(), nullptr, 0, 1, &u, nullptr);
  expectLogged("overlaps");
  auto accumulate = LoadSpirv("rhi_cs_accumulate_cs.spv");
  ASSERT_EQ(device()->CreateComputeShader(accumulate.data(), accumulate.size() * 4, cs.ReleaseAndGetAddressOf()), S_OK);
  context()->CSSetShader(cs.Get());
  context()->Dispatch(1, 1, 1);  // u0 unbound
  expectLogged("UAV slot");
}

}  // namespace
}  // namespace rhitest
