#include "ZoomBox.h"

#include <algorithm>
#include <cmath>
#include <cstring>


namespace drr {

namespace {
struct ZoomConstants {
  float destRect[4];
  float sourceRect[4];
  float borderColor[4];
};
}  // namespace

bool ZoomBox::LoadShaders(const ShaderLibrary& lib, bool fromSource, std::string* error) {
  d3dl::ComPtr<d3dl::VertexShader> vs;
  d3dl::ComPtr<d3dl::PixelShader> zoom, border;
  if (!lib.CreateVertexShader(m_Device, "ZoomBox_ZoomVS", fromSource, vs.GetAddressOf(), nullptr, error) ||
      !lib.CreatePixelShader(m_Device, "ZoomBox_ZoomPS", fromSource, zoom.GetAddressOf(), error) ||
      !lib.CreatePixelShader(m_Device, "ZoomBox_BorderPS", fromSource, border.GetAddressOf(), error))
    return false;
  m_VS = vs;
  m_ZoomPS = zoom;
  m_BorderPS = border;
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
  d3dl::SAMPLER_DESC sd;
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
  m_VS = nullptr;
  m_ZoomPS = m_BorderPS = nullptr;
  m_CB = nullptr;
  m_Point = nullptr;
  m_NoDepth = nullptr;
  m_Device = nullptr;
}

void ZoomBox::Render(d3dl::DeviceContext* ctx, d3dl::Texture2D* backBuffer,
                     d3dl::RenderTargetView* bbRTV, uint32_t bbW, uint32_t bbH, float cx, float cy) {
  if (!m_VS || bbW < 8 || bbH < 8) return;
  d3dl::TEXTURE2D_DESC bd;
  backBuffer->GetDesc(&bd);
  if (!m_Copy || m_CopyW != bd.Width || m_CopyH != bd.Height || m_CopyFormat != bd.Format) {
    ReleaseCopy();
    d3dl::TEXTURE2D_DESC d;
    d.Width = bd.Width;
    d.Height = bd.Height;
    d.Format = bd.Format;
    d.BindFlags = d3dl::BIND_SHADER_RESOURCE;
    if (d3dl::FAILED(m_Device->CreateTexture2D(&d, nullptr, m_Copy.ReleaseAndGetAddressOf())) ||
        d3dl::FAILED(m_Device->CreateShaderResourceView(m_Copy.Get(), nullptr,
                                                        m_CopySRV.ReleaseAndGetAddressOf()))) {
      ReleaseCopy();
      return;
    }
    m_Copy->SetDebugName("ZoomBoxCopy");
    m_CopyW = bd.Width;
    m_CopyH = bd.Height;
    m_CopyFormat = bd.Format;
    m_Bytes = uint64_t(bd.Width) * bd.Height * d3dl::FormatBytesPerElement(bd.Format);
  }
  ctx->CopyResource(m_Copy.Get(), backBuffer);

  // Box: a third of the back-buffer height, in the bottom-left corner.
  const float size = std::floor(std::min(bbW, bbH) / 3.0f);
  const float margin = 10.0f, border = 2.0f;
  const float x0 = margin, y1 = float(bbH) - margin, x1 = x0 + size, y0 = y1 - size;
  auto ndcX = [&](float x) { return x / float(bbW) * 2.0f - 1.0f; };
  auto ndcY = [&](float y) { return 1.0f - y / float(bbH) * 2.0f; };
  const float half = size / kMagnification * 0.5f;
  const float scx = std::clamp(cx, half, float(bbW) - half);
  const float scy = std::clamp(cy, half, float(bbH) - half);

  d3dl::VIEWPORT vp;
  vp.Width = float(bbW);
  vp.Height = float(bbH);
  ctx->RSSetViewports(1, &vp);
  ctx->RSSetState(nullptr);
  ctx->OMSetRenderTargets(1, &bbRTV, nullptr);
  ctx->OMSetDepthStencilState(m_NoDepth.Get(), 0);
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  ctx->IASetInputLayout(nullptr);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
  ctx->VSSetShader(m_VS.Get());
  ctx->VSSetConstantBuffers(0, 1, m_CB.GetAddressOf());
  ctx->PSSetConstantBuffers(0, 1, m_CB.GetAddressOf());

  auto draw = [&](d3dl::PixelShader* ps, float ax0, float ay0, float ax1, float ay1) {
    ZoomConstants c{};
    c.destRect[0] = ndcX(ax0);
    c.destRect[1] = ndcY(ay0);
    c.destRect[2] = ndcX(ax1);
    c.destRect[3] = ndcY(ay1);
    c.sourceRect[0] = (scx - half) / float(bbW);
    c.sourceRect[1] = (scy - half) / float(bbH);
    c.sourceRect[2] = (scx + half) / float(bbW);
    c.sourceRect[3] = (scy + half) / float(bbH);
    c.borderColor[0] = 1.0f;
    c.borderColor[1] = 0.8f;
    c.borderColor[2] = 0.1f;
    c.borderColor[3] = 1.0f;
    d3dl::MAPPED_SUBRESOURCE m;
    if (d3dl::SUCCEEDED(ctx->Map(m_CB.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &m))) {
      std::memcpy(m.pData, &c, sizeof c);
      ctx->Unmap(m_CB.Get(), 0);
    }
    ctx->PSSetShader(ps);
    ctx->Draw(4, 0);
  };
  draw(m_BorderPS.Get(), x0 - border, y0 - border, x1 + border, y1 + border);
  ctx->PSSetShaderResources(0, 1, m_CopySRV.GetAddressOf());
  ctx->PSSetSamplers(0, 1, m_Point.GetAddressOf());
  draw(m_ZoomPS.Get(), x0, y0, x1, y1);
  d3dl::ShaderResourceView* none = nullptr;
  ctx->PSSetShaderResources(0, 1, &none);
  ctx->OMSetDepthStencilState(nullptr, 0);
}

}  // namespace drr
