#include "passes/ZoomBoxPass.h"

#include <cstring>

namespace drr {

bool ZoomBoxPass::Init(d3dl::Device* device, std::string* error) {
  if (!m_CB.Create(device)) {
    *error = "zoom box: cannot create its states";
    return false;
  }
  return true;
}

bool ZoomBoxPass::LoadShaders(ShaderLoad& load) {
  return load.Load({{"ZoomBox_ZoomVS", &m_ZoomVS}, {"ZoomBox_FrameVS", &m_FrameVS}},
                   {{"ZoomBox_ZoomPS", &m_ZoomPS}, {"ZoomBox_FramePS", &m_FramePS}});
}

void ZoomBoxPass::Release() {
  m_ZoomVS = m_FrameVS = nullptr;
  m_ZoomPS = m_FramePS = nullptr;
  m_CB.Release();
}

bool ZoomBoxPass::Record(PassFrame& f) {
  d3dl::DeviceContext* ctx = f.ctx;
  const BackBuffer& bb = f.backBuffer;
  const RenderTarget& copy = f.RTs()[RT::ZoomBoxCopy];
  ctx->OMSetRenderTargets(0, nullptr, nullptr);
  if (!m_ZoomVS || bb.width == 0 || bb.height == 0 || !copy.Valid() || copy.width != bb.width ||
      copy.height != bb.height)
    return true;
  ctx->CopyResource(copy.texture.Get(), bb.texture);
  const ZoomBoxGeometry g = MakeZoomBoxGeometry(f.zoomCentre[0], f.zoomCentre[1]);
  Constants c{};
  std::memcpy(c.quad, g.quad.data(), sizeof c.quad);
  std::memcpy(c.source, g.source.data(), sizeof c.source);
  for (size_t i = 0; i < g.frame.size(); ++i) {
    c.frame[i][0] = g.frame[i][0];
    c.frame[i][1] = g.frame[i][1];
  }
  m_CB.Upload(ctx, c);
  d3dl::VIEWPORT vp;
  vp.Width = float(bb.width);
  vp.Height = float(bb.height);
  ctx->RSSetViewports(1, &vp);
  ctx->RSSetState(nullptr);  // the default state, as the original's
  ctx->OMSetRenderTargets(1, &bb.rtv, nullptr);
  ctx->OMSetDepthStencilState(m_Kit.noDepth.Get(), 0);
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  ctx->IASetInputLayout(nullptr);
  ctx->VSSetConstantBuffers(0, 1, m_CB.Address());
  // The magnified quad (point sampling), then the frame over it, as the original.
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
  ctx->VSSetShader(m_ZoomVS.Get());
  ctx->PSSetShader(m_ZoomPS.Get());
  ctx->PSSetShaderResources(0, 1, copy.srv.GetAddressOf());
  ctx->PSSetSamplers(0, 1, m_Kit.point.GetAddressOf());
  ctx->Draw(4, 0);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_LINESTRIP);
  ctx->VSSetShader(m_FrameVS.Get());
  ctx->PSSetShader(m_FramePS.Get());
  ctx->Draw(12, 0);
  d3dl::ShaderResourceView* none = nullptr;
  ctx->PSSetShaderResources(0, 1, &none);
  ctx->OMSetDepthStencilState(nullptr, 0);
  return true;
}

}  // namespace drr
