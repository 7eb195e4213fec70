// Helpers shared by the RHI tests (on top of drrtest::RenderTest).
#pragma once

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "RenderTest.h"

namespace rhitest {
using namespace d3dl;

struct ColorVertex {
  float pos[4];
  float color[4];
};

// A source file the build copied into rhi-test-sources/ beside the test
// binary (Tests/rhi/CMakeLists.txt): found from the running executable, so the
// suite reads it wherever the binary and that folder are carried together.
inline std::string TestSourcePath(const char* name) {
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe");
  return (exe.parent_path() / "rhi-test-sources" / name).string();
}

class RhiTest : public drrtest::RenderTest {
 protected:
  ComPtr<Buffer> MakeBuffer(UINT bind, const void* data, UINT size, USAGE usage = USAGE_DEFAULT) {
    BUFFER_DESC d;
    d.ByteWidth = size;
    d.BindFlags = bind;
    d.Usage = usage;
    if (usage == USAGE_DYNAMIC) d.CPUAccessFlags = CPU_ACCESS_WRITE;
    SUBRESOURCE_DATA init{data, 0, 0};
    ComPtr<Buffer> b;
    EXPECT_EQ(device()->CreateBuffer(&d, data ? &init : nullptr, b.ReleaseAndGetAddressOf()), S_OK);
    return b;
  }
  ComPtr<Buffer> MakeCB(UINT size, USAGE usage = USAGE_DYNAMIC, const void* data = nullptr) {
    return MakeBuffer(BIND_CONSTANT_BUFFER, data, size, usage);
  }
  void WriteCB(Buffer* cb, const void* data, size_t size) {
    MAPPED_SUBRESOURCE m;
    ASSERT_EQ(context()->Map(cb, 0, MAP_WRITE_DISCARD, 0, &m), S_OK);
    std::memcpy(m.pData, data, size);
    context()->Unmap(cb, 0);
  }
  ComPtr<Texture2D> MakeTexture(UINT w, UINT h, DXGI_FORMAT f, const void* data, UINT mips = 1,
                                const SUBRESOURCE_DATA* perMip = nullptr, UINT bind = BIND_SHADER_RESOURCE,
                                UINT misc = 0) {
    TEXTURE2D_DESC d;
    d.Width = w;
    d.Height = h;
    d.MipLevels = mips;
    d.Format = f;
    d.BindFlags = bind;
    d.MiscFlags = misc;
    SUBRESOURCE_DATA init{data, w * FormatBytesPerElement(f), 0};
    ComPtr<Texture2D> t;
    EXPECT_EQ(device()->CreateTexture2D(&d, perMip ? perMip : (data ? &init : nullptr), t.ReleaseAndGetAddressOf()), S_OK);
    return t;
  }
  ComPtr<ShaderResourceView> MakeSRV(Resource* r) {
    ComPtr<ShaderResourceView> v;
    EXPECT_EQ(device()->CreateShaderResourceView(r, nullptr, v.ReleaseAndGetAddressOf()), S_OK);
    return v;
  }
  ComPtr<SamplerState> MakeSampler(FILTER f, TEXTURE_ADDRESS_MODE a = TEXTURE_ADDRESS_CLAMP, float bias = 0.0f) {
    SAMPLER_DESC d;
    d.Filter = f;
    d.AddressU = d.AddressV = d.AddressW = a;
    d.MipLODBias = bias;
    ComPtr<SamplerState> s;
    EXPECT_EQ(device()->CreateSamplerState(&d, s.ReleaseAndGetAddressOf()), S_OK);
    return s;
  }
  ComPtr<InputLayout> ColorLayout(const std::vector<uint32_t>& vsCode) {
    INPUT_ELEMENT_DESC e[2];
    e[0].SemanticName = "POSITION";
    e[0].Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    e[1].SemanticName = "COLOR";
    e[1].Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    ComPtr<InputLayout> il;
    EXPECT_EQ(device()->CreateInputLayout(e, 2, vsCode.data(), vsCode.size() * 4, il.ReleaseAndGetAddressOf()), S_OK);
    return il;
  }
  // Draws `verts` (triangle list) with the colour shaders.
  void DrawColored(const std::vector<ColorVertex>& verts) {
    auto code = LoadSpirv("rhi_color_vs.spv");
    auto vs = LoadVertexShader("rhi_color_vs.spv");
    auto ps = LoadPixelShader("rhi_color_ps.spv");
    auto il = ColorLayout(code);
    auto vb = MakeBuffer(BIND_VERTEX_BUFFER, verts.data(), UINT(verts.size() * sizeof(ColorVertex)));
    UINT stride = sizeof(ColorVertex), offset = 0;
    context()->IASetInputLayout(il.Get());
    context()->IASetVertexBuffers(0, 1, vb.GetAddressOf(), &stride, &offset);
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->VSSetShader(vs.Get());
    context()->PSSetShader(ps.Get());
    context()->Draw(UINT(verts.size()), 0);
  }
  // Binds the full-screen triangle filled with `rgba` (its constant buffer at
  // b0) without drawing; the context's slots hold the shaders and the buffer.
  void BindSolidFullScreen(const float rgba[4]) {
    auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
    auto ps = LoadPixelShader("rhi_solid_ps.spv");
    auto cb = MakeCB(16, USAGE_DEFAULT, rgba);
    context()->VSSetShader(vs.Get());
    context()->PSSetShader(ps.Get());
    context()->PSSetConstantBuffers(0, 1, cb.GetAddressOf());
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  }
  // Full-screen pass sampling `srv` with `smp` into the bound target.
  void DrawSampled(ShaderResourceView* srv, SamplerState* smp, float su = 1, float sv = 1, float ou = 0, float ov = 0) {
    auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
    auto ps = LoadPixelShader("rhi_sample_ps.spv");
    float params[4] = {su, sv, ou, ov};
    auto cb = MakeCB(16, USAGE_DEFAULT, params);
    context()->IASetInputLayout(nullptr);
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->VSSetShader(vs.Get());
    context()->PSSetShader(ps.Get());
    context()->PSSetShaderResources(0, 1, &srv);
    context()->PSSetSamplers(0, 1, &smp);
    context()->PSSetConstantBuffers(0, 1, cb.GetAddressOf());
    context()->Draw(3, 0);
  }
  void Bind(const drrtest::RenderTarget& rt, uint32_t w, uint32_t h, DepthStencilView* dsv = nullptr) {
    context()->OMSetRenderTargets(1, rt.rtv.GetAddressOf(), dsv);
    SetViewport(w, h);
  }
};

inline bool Near(uint8_t a, int b, int tol = 1) { return std::abs(int(a) - b) <= tol; }

}  // namespace rhitest
