// The fixture of the format and view tests (FormatTests.cpp,
// FormatViewTests.cpp): textures of any description, slice views, one-slice
// read-back, full-screen passes.
#pragma once

#include <string>
#include <vector>

#include "RhiTest.h"

namespace rhitest {

using drrtest::Image;
class RhiFormats : public RhiTest {
 protected:
  static TEXTURE2D_DESC Desc(UINT w, UINT h, DXGI_FORMAT f, UINT bind, UINT arraySize = 1, UINT samples = 1,
                             UINT misc = 0) {
    TEXTURE2D_DESC d;
    d.Width = w;
    d.Height = h;
    d.Format = f;
    d.BindFlags = bind;
    d.ArraySize = arraySize;
    d.SampleDesc.Count = samples;
    d.MiscFlags = misc;
    return d;
  }
  ComPtr<Texture2D> MakeTex(const TEXTURE2D_DESC& d, const SUBRESOURCE_DATA* init = nullptr) {
    ComPtr<Texture2D> t;
    EXPECT_EQ(device()->CreateTexture2D(&d, init, t.ReleaseAndGetAddressOf()), S_OK) << FormatName(d.Format);
    return t;
  }
  ComPtr<RenderTargetView> SliceRtv(Texture2D* t, UINT first, UINT count) {
    RENDER_TARGET_VIEW_DESC d;
    d.ViewDimension = RTV_DIMENSION_TEXTURE2DARRAY;
    d.Array = {first, count};
    ComPtr<RenderTargetView> v;
    EXPECT_EQ(device()->CreateRenderTargetView(t, &d, v.ReleaseAndGetAddressOf()), S_OK);
    return v;
  }
  ComPtr<DepthStencilView> SliceDsv(Texture2D* t, UINT first, UINT count) {
    DEPTH_STENCIL_VIEW_DESC d;
    d.Format = DXGI_FORMAT_D32_FLOAT;
    d.ViewDimension = DSV_DIMENSION_TEXTURE2DARRAY;
    d.Array = {first, count};
    ComPtr<DepthStencilView> v;
    EXPECT_EQ(device()->CreateDepthStencilView(t, &d, v.ReleaseAndGetAddressOf()), S_OK);
    return v;
  }
  // Subresource `sub` (mip 0 of a slice) through a one-slice STAGING copy.
  Image ReadSub(Texture2D* t, UINT sub) {
    TEXTURE2D_DESC d;
    t->GetDesc(&d);
    TEXTURE2D_DESC s = Desc(d.Width, d.Height, d.Format, 0);
    s.Usage = USAGE_STAGING;
    s.CPUAccessFlags = CPU_ACCESS_READ;
    auto staging = MakeTex(s);
    context()->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, t, sub, nullptr);
    Image img;
    std::string error;
    EXPECT_TRUE(drr::MapStaging(context(), staging.Get(), &img, &error)) << error;
    return img;
  }
  // A full-screen pass of `ps` (fullscreen_vs) with SRVs t0.. and an optional b0.
  void DrawFullScreen(const char* ps, std::vector<ShaderResourceView*> srvs, Buffer* cb = nullptr) {
    auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
    auto p = LoadPixelShader(ps);
    context()->IASetInputLayout(nullptr);
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->VSSetShader(vs.Get());
    context()->PSSetShader(p.Get());
    if (!srvs.empty()) context()->PSSetShaderResources(0, UINT(srvs.size()), srvs.data());
    if (cb) context()->PSSetConstantBuffers(0, 1, &cb);
    context()->Draw(3, 0);
  }
  void NoCulling() {
    RASTERIZER_DESC rd;
    rd.CullMode = CULL_NONE;
    ComPtr<RasterizerState> rs;
    ASSERT_EQ(device()->CreateRasterizerState(&rd, rs.ReleaseAndGetAddressOf()), S_OK);
    context()->RSSetState(rs.Get());
  }
};

inline uint32_t U32(const Image& img, uint32_t x, uint32_t y, uint32_t i = 0) {
  uint32_t w;
  std::memcpy(&w, img.At(x, y) + 4 * i, 4);
  return w;
}
inline uint32_t U16(const Image& img, uint32_t x, uint32_t y, uint32_t i) {
  uint16_t h;
  std::memcpy(&h, img.At(x, y) + 2 * i, 2);
  return h;
}

}  // namespace rhitest
