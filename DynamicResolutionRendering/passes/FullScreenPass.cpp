#include "passes/FullScreenPass.h"

namespace drr {

bool FullScreenKit::Init(d3dl::Device* device, std::string* error) {
  d3dl::SAMPLER_DESC pointDesc;
  pointDesc.Filter = d3dl::FILTER_MIN_LINEAR_MAG_MIP_POINT;
  pointDesc.MinLOD = 0.0f;  // the original's zeroed descriptions
  pointDesc.ComparisonFunc = d3dl::COMPARISON_ALWAYS;
  d3dl::SAMPLER_DESC linearDesc = pointDesc;
  linearDesc.Filter = d3dl::FILTER_MIN_MAG_MIP_LINEAR;
  d3dl::SAMPLER_DESC wrapDesc = linearDesc;
  wrapDesc.AddressU = wrapDesc.AddressV = wrapDesc.AddressW = d3dl::TEXTURE_ADDRESS_WRAP;
  d3dl::RASTERIZER_DESC rd;
  rd.CullMode = d3dl::CULL_NONE;
  if (!dynamic.Create(device) || !full.Create(device) || !upscale.Create(device) ||
      d3dl::FAILED(device->CreateSamplerState(&pointDesc, point.GetAddressOf())) ||
      d3dl::FAILED(device->CreateSamplerState(&linearDesc, linear.GetAddressOf())) ||
      d3dl::FAILED(device->CreateSamplerState(&wrapDesc, linearWrap.GetAddressOf())) ||
      !CreateNoDepthState(device, &noDepth) ||
      d3dl::FAILED(device->CreateRasterizerState(&rd, noCull.GetAddressOf()))) {
    *error = "cannot create the post-processing states";
    return false;
  }
  return true;
}

bool FullScreenKit::LoadShaders(ShaderLoad& load) {
  return load.Load({{"PostProcessDynamic_FullScreenVS", &dynamicVS}, {"PostProcess_FullScreenVS", &fullVS}}, {});
}

void FullScreenKit::Release() {
  noDepth = nullptr;
  noCull = nullptr;
  point = linear = linearWrap = nullptr;
  dynamicVS = fullVS = nullptr;
  dynamic.Release();
  full.Release();
  upscale.Release();
}

void FullScreenPass::Target(d3dl::DeviceContext* ctx, d3dl::RenderTargetView* rtv, const d3dl::VIEWPORT& viewport) {
  ctx->OMSetRenderTargets(1, &rtv, nullptr);
  ctx->RSSetViewports(1, &viewport);
}

void FullScreenPass::BindSamplers(d3dl::DeviceContext* ctx, bool linearS0) const {
  d3dl::SamplerState* samplers[3] = {linearS0 ? m_Kit.linear.Get() : m_Kit.point.Get(), m_Kit.linear.Get(),
                                     m_Kit.linearWrap.Get()};
  ctx->PSSetSamplers(0, 3, samplers);
}

void FullScreenPass::UploadUpscale(d3dl::DeviceContext* ctx, const UpscaleConstants& uc) const {
  m_Kit.upscale.Upload(ctx, uc);
  ctx->PSSetConstantBuffers(1, 1, m_Kit.upscale.Address());
}

void FullScreenPass::Draw(d3dl::DeviceContext* ctx, d3dl::VertexShader* vs, d3dl::PixelShader* ps, d3dl::Buffer* cb0,
                          std::initializer_list<d3dl::ShaderResourceView*> srvs) const {
  constexpr uint32_t kSlots = 7;  // t6: the upscalers' depth
  if (srvs.size() > 0) ctx->PSSetShaderResources(0, uint32_t(srvs.size()), srvs.begin());
  ctx->IASetInputLayout(nullptr);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  ctx->RSSetState(m_Kit.noCull.Get());
  ctx->OMSetDepthStencilState(m_Kit.noDepth.Get(), 0);
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  ctx->VSSetShader(vs);
  ctx->VSSetConstantBuffers(0, 1, &cb0);
  ctx->PSSetConstantBuffers(0, 1, &cb0);
  ctx->PSSetShader(ps);
  ctx->Draw(3, 0);
  d3dl::ShaderResourceView* none[kSlots] = {};
  ctx->PSSetShaderResources(0, kSlots, none);
}

void FullScreenPass::DrawDynamic(d3dl::DeviceContext* ctx, d3dl::PixelShader* ps, const DynamicConstants& dc,
                                 std::initializer_list<d3dl::ShaderResourceView*> srvs) const {
  m_Kit.dynamic.Upload(ctx, dc);
  Draw(ctx, m_Kit.dynamicVS.Get(), ps, m_Kit.dynamic.Get(), srvs);
}

void FullScreenPass::DrawFull(d3dl::DeviceContext* ctx, d3dl::PixelShader* ps, const FullConstants& fc,
                              std::initializer_list<d3dl::ShaderResourceView*> srvs) const {
  m_Kit.full.Upload(ctx, fc);
  Draw(ctx, m_Kit.fullVS.Get(), ps, m_Kit.full.Get(), srvs);
}

}  // namespace drr
