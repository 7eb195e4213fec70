#include "RhiDrawSetup.h"

#include <cstdio>
#include <cstring>

#include "d3dl/ShaderCompiler.h"

namespace drrbench {
namespace {

uint64_t g_loggedMessages = 0;  // the log callback has no per-device context

void OnLog(d3dl::LogLevel level, const char* message, void*) {
  if (level == d3dl::LogLevel::Validation || level == d3dl::LogLevel::Error) {
    ++g_loggedMessages;
    std::fprintf(stderr, "rhi: %s\n", message);
  }
}

}  // namespace

RhiDrawSetup::~RhiDrawSetup() {
  if (device) device->WaitIdle();
}

bool RhiDrawSetup::Init(const char* applicationName, std::string* error) {
  d3dl::DEVICE_CREATE_DESC dd;
  dd.Log = OnLog;
  dd.EnableWindowSurfaces = false;
  dd.ApplicationName = applicationName;
  if (d3dl::FAILED(d3dl::CreateDevice(&dd, device.GetAddressOf(), context.GetAddressOf()))) {
    *error = "CreateDevice failed";
    return false;
  }
  d3dl::TEXTURE2D_DESC td;
  td.Width = td.Height = kTargetSize;
  td.Format = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM;
  td.BindFlags = d3dl::BIND_RENDER_TARGET;
  d3dl::TEXTURE2D_DESC sd = td;
  sd.BindFlags = 0;
  sd.Usage = d3dl::USAGE_STAGING;
  sd.CPUAccessFlags = d3dl::CPU_ACCESS_READ;
  d3dl::BUFFER_DESC bd;
  bd.ByteWidth = sizeof(DrawConstants);
  bd.Usage = d3dl::USAGE_DYNAMIC;
  bd.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  bd.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  const std::string dir = BenchShaderDir();
  std::vector<uint32_t> vsWords, psWords;
  if (d3dl::FAILED(d3dl::ReadSpirvFile(dir + "/BenchDraw.vs.spv", &vsWords, error)) ||
      d3dl::FAILED(d3dl::ReadSpirvFile(dir + "/BenchDraw.ps.spv", &psWords, error)))
    return false;
  d3dl::RASTERIZER_DESC rd;
  rd.CullMode = d3dl::CULL_NONE;
  const bool ok =
      d3dl::SUCCEEDED(device->CreateTexture2D(&td, nullptr, target.GetAddressOf())) &&
      d3dl::SUCCEEDED(device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf())) &&
      d3dl::SUCCEEDED(device->CreateTexture2D(&sd, nullptr, staging.GetAddressOf())) &&
      d3dl::SUCCEEDED(device->CreateBuffer(&bd, nullptr, constants.GetAddressOf())) &&
      d3dl::SUCCEEDED(device->CreateVertexShader(vsWords.data(), vsWords.size() * 4, vs.GetAddressOf())) &&
      d3dl::SUCCEEDED(device->CreatePixelShader(psWords.data(), psWords.size() * 4, ps.GetAddressOf())) &&
      d3dl::SUCCEEDED(device->CreateRasterizerState(&rd, rs.GetAddressOf()));
  if (!ok) *error = "creating the benchmark resources failed (shaders in " + dir + ")";
  return ok;
}

void RhiDrawSetup::BindDrawState(d3dl::DeviceContext* ctx) const {
  ctx->OMSetRenderTargets(1, rtv.GetAddressOf(), nullptr);
  d3dl::VIEWPORT vp{0, 0, float(kTargetSize), float(kTargetSize), 0, 1};
  ctx->RSSetViewports(1, &vp);
  ctx->RSSetState(rs.Get());
  ctx->IASetInputLayout(nullptr);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  ctx->VSSetShader(vs.Get());
  ctx->PSSetShader(ps.Get());
  ctx->VSSetConstantBuffers(0, 1, constants.GetAddressOf());
}

void RhiDrawSetup::RecordDraws(d3dl::DeviceContext* ctx, uint32_t first, uint32_t last, uint32_t n) const {
  for (uint32_t i = first; i < last; ++i) {
    d3dl::MAPPED_SUBRESOURCE m;
    ctx->Map(constants.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &m);
    const DrawConstants c = ConstantsForDraw(i, n);
    std::memcpy(m.pData, &c, sizeof(c));
    ctx->Unmap(constants.Get(), 0);
    ctx->Draw(3, 0);
  }
}

std::vector<uint8_t> RhiDrawSetup::ReadStaging() const {
  d3dl::MAPPED_SUBRESOURCE m;
  std::vector<uint8_t> pixels(kTargetSize * kTargetSize * 4);
  if (d3dl::FAILED(context->Map(staging.Get(), 0, d3dl::MAP_READ, 0, &m))) return {};
  for (uint32_t y = 0; y < kTargetSize; ++y)
    std::memcpy(&pixels[y * kTargetSize * 4], static_cast<const uint8_t*>(m.pData) + y * m.RowPitch,
                kTargetSize * 4);
  context->Unmap(staging.Get(), 0);
  return pixels;
}

uint64_t RhiDrawSetup::Messages() const {
  d3dl::DEVICE_STATS stats;
  device->GetStats(&stats);
  return stats.ValidationMessages + g_loggedMessages;
}

}  // namespace drrbench
