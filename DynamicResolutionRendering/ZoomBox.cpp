#include "ZoomBox.h"

#include <cstring>

namespace drr {

namespace {
struct ZoomConstants {  // cbZoomBox in Shaders/ZoomBox.hlsl
  float quad[4];
  float source[4];
  float frame[12][4];  // xy used
};
}  // namespace

ZoomBoxGeometry MakeZoomBoxGeometry(float u, float v) {
  using G = ZoomBoxGeometry;
  G g;
  g.quad = {G::kBoxRight, G::kBoxBottom, G::kBoxLeft, G::kBoxTop};
  // The box's bottom shows the source's bottom (larger v), its right the source's right.
  g.source = {u + G::kSourceHalf, v + G::kSourceHalf, u - G::kSourceHalf, v - G::kSourceHalf};
  const float l = G::kBoxLeft - G::kFrameOutset, r = G::kBoxRight + G::kFrameOutset;
  const float b = G::kBoxBottom - G::kFrameOutset, t = G::kBoxTop + G::kFrameOutset;
  const float cx = (u - 0.5f) * 2.0f, cy = (0.5f - v) * 2.0f, m = G::kMarkerHalf;
  g.frame = {{{r, b}, {r, t}, {l, t}, {l, b}, {r, b},  // frame, ending at its bottom-right
              {cx - m, cy - m}, {cx - m, cy + m}, {cx + m, cy + m}, {cx + m, cy - m}, {cx - m, cy - m},  // marker
              {cx - m, cy + m}, {r, t}}};  // up its left side, back to the frame's top-right
  return g;
}

bool ZoomBox::LoadShaders(const ShaderLibrary& lib, bool fromSource, std::string* error) {
  d3dl::ComPtr<d3dl::VertexShader> zoomVS, frameVS;
  d3dl::ComPtr<d3dl::PixelShader> zoomPS, framePS;
  if (!lib.CreateVertexShader(m_Device, "ZoomBox_ZoomVS", fromSource, zoomVS.GetAddressOf(), nullptr, error) ||
      !lib.CreateVertexShader(m_Device, "ZoomBox_FrameVS", fromSource, frameVS.GetAddressOf(), nullptr, error) ||
      !lib.CreatePixelShader(m_Device, "ZoomBox_ZoomPS", fromSource, zoomPS.GetAddressOf(), error) ||
      !lib.CreatePixelShader(m_Device, "ZoomBox_FramePS", fromSource, framePS.GetAddressOf(), error))
    return false;
  m_ZoomVS = zoomVS;
  m_FrameVS = frameVS;
  m_ZoomPS = zoomPS;
  m_FramePS = framePS;
  return true;
}

bool ZoomBox::Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error) {
  m_Device = device;
  if (!LoadShaders(shaders, false, error)) return false;
  d3dl::BUFFER_DESC cb;
  cb.ByteWidth = sizeof(ZoomConstants);
  cb.Usage = d3dl::USAGE_DYNAMIC;
  cb.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  cb.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  d3dl::SAMPLER_DESC sd;  // clamped, as the original's
  sd.Filter = d3dl::FILTER_MIN_MAG_MIP_POINT;
  d3dl::DEPTH_STENCIL_DESC dd;
  dd.DepthEnable = 0;
  dd.DepthWriteMask = d3dl::DEPTH_WRITE_MASK_ZERO;
  if (d3dl::FAILED(device->CreateBuffer(&cb, nullptr, m_CB.ReleaseAndGetAddressOf())) ||
      d3dl::FAILED(device->CreateSamplerState(&sd, m_Point.ReleaseAndGetAddressOf())) ||
      d3dl::FAILED(device->CreateDepthStencilState(&dd, m_NoDepth.ReleaseAndGetAddressOf()))) {
    if (error) *error = "zoom box: cannot create its states";
    return false;
  }
  return true;
}

void ZoomBox::ReleaseCopy() {
  m_CopySRV = nullptr;
  m_Copy = nullptr;
  m_CopyW = m_CopyH = 0;
  m_Bytes = 0;
}

void ZoomBox::Release() {
  ReleaseCopy();
  m_ZoomVS = m_FrameVS = nullptr;
  m_ZoomPS = m_FramePS = nullptr;
  m_CB = nullptr;
  m_Point = nullptr;
  m_NoDepth = nullptr;
  m_Device = nullptr;
}

// A texture of the back buffer's size and format (the original's zoom texture).
bool ZoomBox::EnsureCopy(d3dl::Texture2D* backBuffer) {
  d3dl::TEXTURE2D_DESC bd;
  backBuffer->GetDesc(&bd);
  if (m_Copy && m_CopyW == bd.Width && m_CopyH == bd.Height && m_CopyFormat == bd.Format) return true;
  ReleaseCopy();
  d3dl::TEXTURE2D_DESC d;
  d.Width = bd.Width;
  d.Height = bd.Height;
  d.Format = bd.Format;
  d.BindFlags = d3dl::BIND_SHADER_RESOURCE;
  if (d3dl::FAILED(m_Device->CreateTexture2D(&d, nullptr, m_Copy.ReleaseAndGetAddressOf())) ||
      d3dl::FAILED(m_Device->CreateShaderResourceView(m_Copy.Get(), nullptr, m_CopySRV.ReleaseAndGetAddressOf()))) {
    ReleaseCopy();
    return false;
  }
  m_Copy->SetDebugName("ZoomBoxCopy");
  m_CopyW = bd.Width;
  m_CopyH = bd.Height;
  m_CopyFormat = bd.Format;
  m_Bytes = uint64_t(bd.Width) * bd.Height * d3dl::FormatBytesPerElement(bd.Format);
  return true;
}

void ZoomBox::Upload(d3dl::DeviceContext* ctx, const ZoomBoxGeometry& g) {
  ZoomConstants c{};
  std::memcpy(c.quad, g.quad.data(), sizeof c.quad);
  std::memcpy(c.source, g.source.data(), sizeof c.source);
  for (size_t i = 0; i < g.frame.size(); ++i) {
    c.frame[i][0] = g.frame[i][0];
    c.frame[i][1] = g.frame[i][1];
  }
  d3dl::MAPPED_SUBRESOURCE m;
  if (d3dl::SUCCEEDED(ctx->Map(m_CB.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &m))) {
    std::memcpy(m.pData, &c, sizeof c);
    ctx->Unmap(m_CB.Get(), 0);
  }
}

void ZoomBox::Render(d3dl::DeviceContext* ctx, d3dl::Texture2D* backBuffer, d3dl::RenderTargetView* bbRTV,
                     uint32_t bbW, uint32_t bbH, float centreU, float centreV) {
  if (!m_ZoomVS || bbW == 0 || bbH == 0 || !EnsureCopy(backBuffer)) return;
  ctx->CopyResource(m_Copy.Get(), backBuffer);
  Upload(ctx, MakeZoomBoxGeometry(centreU, centreV));

  d3dl::VIEWPORT vp;
  vp.Width = float(bbW);
  vp.Height = float(bbH);
  ctx->RSSetViewports(1, &vp);
  ctx->RSSetState(nullptr);
  ctx->OMSetRenderTargets(1, &bbRTV, nullptr);
  ctx->OMSetDepthStencilState(m_NoDepth.Get(), 0);
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  ctx->IASetInputLayout(nullptr);
  ctx->VSSetConstantBuffers(0, 1, m_CB.GetAddressOf());
  // The magnified quad, then the frame over it, as the original.
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
  ctx->VSSetShader(m_ZoomVS.Get());
  ctx->PSSetShader(m_ZoomPS.Get());
  ctx->PSSetShaderResources(0, 1, m_CopySRV.GetAddressOf());
  ctx->PSSetSamplers(0, 1, m_Point.GetAddressOf());
  ctx->Draw(4, 0);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_LINESTRIP);
  ctx->VSSetShader(m_FrameVS.Get());
  ctx->PSSetShader(m_FramePS.Get());
  ctx->Draw(12, 0);
  d3dl::ShaderResourceView* none = nullptr;
  ctx->PSSetShaderResources(0, 1, &none);
  ctx->OMSetDepthStencilState(nullptr, 0);
}

}  // namespace drr
