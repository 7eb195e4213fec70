// The same frame as RawVulkanRecorder, written as a D3D11 programmer would:
// Map(WRITE_DISCARD) of one constant buffer + Draw, 'n' times (or + Dispatch
// on one UAV: compute and unordered access).
#include "d3dl/ShaderCompiler.h"
#include <cstring>
#include <fstream>
#include <vector>

#include "Recorder.h"
#include "d3dl/D3DLike.h"

namespace drrbench {
namespace {

using d3dl::ComPtr;

uint64_t g_rhiMessages = 0;

void OnLog(d3dl::LogLevel level, const char* message, void*) {
  if (level == d3dl::LogLevel::Validation || level == d3dl::LogLevel::Error) {
    ++g_rhiMessages;
    std::fprintf(stderr, "rhi: %s\n", message);
  }
}

class RhiRecorder final : public Recorder {
 public:
  ~RhiRecorder() override {
    if (device_) device_->WaitIdle();
  }

  bool Init(std::string* error) override {
    d3dl::DEVICE_CREATE_DESC dd;
    dd.Log = OnLog;
    dd.EnableWindowSurfaces = false;
    dd.ApplicationName = "rhi-record-benchmark";
    if (d3dl::FAILED(d3dl::CreateDevice(&dd, device_.GetAddressOf(), context_.GetAddressOf()))) {
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
    std::vector<uint32_t> vs, ps;
    if (d3dl::FAILED(d3dl::ReadSpirvFile(dir + "/BenchDraw.vs.spv", &vs, error)) ||
        d3dl::FAILED(d3dl::ReadSpirvFile(dir + "/BenchDraw.ps.spv", &ps, error)))
      return false;
    d3dl::RASTERIZER_DESC rd;
    rd.CullMode = d3dl::CULL_NONE;
    if (d3dl::FAILED(device_->CreateTexture2D(&td, nullptr, target_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateRenderTargetView(target_.Get(), nullptr, rtv_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateTexture2D(&sd, nullptr, staging_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateBuffer(&bd, nullptr, constants_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateVertexShader(vs.data(), vs.size() * 4, vs_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreatePixelShader(ps.data(), ps.size() * 4, ps_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateRasterizerState(&rd, rs_.GetAddressOf()))) {
      *error = "creating the benchmark resources failed (shaders in " + dir + ")";
      return false;
    }
    return InitDispatch(dir, error);
  }

  // Compute and unordered access: one raw UAV buffer, its staging copy, a
  // DYNAMIC constant buffer and the compute shader.
  bool InitDispatch(const std::string& dir, std::string* error) {
    std::vector<uint32_t> cs;
    if (d3dl::FAILED(d3dl::ReadSpirvFile(dir + "/BenchDispatch.cs.spv", &cs, error))) return false;
    d3dl::BUFFER_DESC wd;
    wd.ByteWidth = kDispatchWords * 4;
    wd.BindFlags = d3dl::BIND_UNORDERED_ACCESS;
    wd.MiscFlags = d3dl::RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS;
    d3dl::BUFFER_DESC sd;
    sd.ByteWidth = wd.ByteWidth;
    sd.Usage = d3dl::USAGE_STAGING;
    sd.CPUAccessFlags = d3dl::CPU_ACCESS_READ;
    d3dl::BUFFER_DESC cd;
    cd.ByteWidth = sizeof(DispatchConstants);
    cd.Usage = d3dl::USAGE_DYNAMIC;
    cd.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
    cd.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
    d3dl::UNORDERED_ACCESS_VIEW_DESC ud;
    ud.Format = d3dl::DXGI_FORMAT_R32_TYPELESS;
    ud.ViewDimension = d3dl::UAV_DIMENSION_BUFFER;
    ud.Buffer = {0, kDispatchWords, d3dl::BUFFER_UAV_FLAG_RAW};
    if (d3dl::FAILED(device_->CreateBuffer(&wd, nullptr, words_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateBuffer(&sd, nullptr, wordsStaging_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateBuffer(&cd, nullptr, dispatchConstants_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateUnorderedAccessView(words_.Get(), &ud, wordsUav_.GetAddressOf())) ||
        d3dl::FAILED(device_->CreateComputeShader(cs.data(), cs.size() * 4, cs_.GetAddressOf()))) {
      *error = "creating the dispatch benchmark resources failed (shaders in " + dir + ")";
      return false;
    }
    return true;
  }

  void RecordDispatches(uint32_t n) override {
    d3dl::DeviceContext* ctx = context_.Get();
    const d3dl::UINT zero[4] = {};
    ctx->ClearUnorderedAccessViewUint(wordsUav_.Get(), zero);
    ctx->CSSetShader(cs_.Get());
    ctx->CSSetConstantBuffers(0, 1, dispatchConstants_.GetAddressOf());
    ctx->CSSetUnorderedAccessViews(0, 1, wordsUav_.GetAddressOf(), nullptr);
    for (uint32_t i = 0; i < n; ++i) {
      d3dl::MAPPED_SUBRESOURCE m;
      ctx->Map(dispatchConstants_.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &m);
      const DispatchConstants c = ConstantsForDispatch(i);
      std::memcpy(m.pData, &c, sizeof(c));
      ctx->Unmap(dispatchConstants_.Get(), 0);
      ctx->Dispatch(1, 1, 1);
    }
    ctx->CopyResource(wordsStaging_.Get(), words_.Get());
  }

  std::vector<uint32_t> ReadBackWords() override {
    d3dl::MAPPED_SUBRESOURCE m;
    std::vector<uint32_t> words(kDispatchWords);
    if (d3dl::FAILED(context_->Map(wordsStaging_.Get(), 0, d3dl::MAP_READ, 0, &m))) return {};
    std::memcpy(words.data(), m.pData, words.size() * 4);
    context_->Unmap(wordsStaging_.Get(), 0);
    return words;
  }

  void Record(uint32_t n) override {
    d3dl::DeviceContext* ctx = context_.Get();
    const float black[4] = {0, 0, 0, 0};
    ctx->ClearRenderTargetView(rtv_.Get(), black);
    ctx->OMSetRenderTargets(1, rtv_.GetAddressOf(), nullptr);
    d3dl::VIEWPORT vp{0, 0, float(kTargetSize), float(kTargetSize), 0, 1};
    ctx->RSSetViewports(1, &vp);
    ctx->RSSetState(rs_.Get());
    ctx->IASetInputLayout(nullptr);
    ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    ctx->VSSetShader(vs_.Get());
    ctx->PSSetShader(ps_.Get());
    ctx->VSSetConstantBuffers(0, 1, constants_.GetAddressOf());
    for (uint32_t i = 0; i < n; ++i) {
      d3dl::MAPPED_SUBRESOURCE m;
      ctx->Map(constants_.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &m);
      const DrawConstants c = ConstantsForDraw(i, n);
      std::memcpy(m.pData, &c, sizeof(c));
      ctx->Unmap(constants_.Get(), 0);
      ctx->Draw(3, 0);
    }
    ctx->CopyResource(staging_.Get(), target_.Get());
  }

  void SubmitAndWait() override {
    context_->Flush();
    device_->WaitIdle();
  }

  std::vector<uint8_t> ReadBack() override {
    d3dl::MAPPED_SUBRESOURCE m;
    std::vector<uint8_t> pixels(kTargetSize * kTargetSize * 4);
    if (d3dl::FAILED(context_->Map(staging_.Get(), 0, d3dl::MAP_READ, 0, &m))) return {};
    for (uint32_t y = 0; y < kTargetSize; ++y) {
      std::memcpy(&pixels[y * kTargetSize * 4], static_cast<const uint8_t*>(m.pData) + y * m.RowPitch,
                  kTargetSize * 4);
    }
    context_->Unmap(staging_.Get(), 0);
    return pixels;
  }

  uint64_t ValidationMessages() const override {
    d3dl::DEVICE_STATS stats;
    device_->GetStats(&stats);
    return stats.ValidationMessages + g_rhiMessages;
  }

 private:
  ComPtr<d3dl::Device> device_;
  ComPtr<d3dl::DeviceContext> context_;
  ComPtr<d3dl::Texture2D> target_, staging_;
  ComPtr<d3dl::RenderTargetView> rtv_;
  ComPtr<d3dl::Buffer> constants_;
  ComPtr<d3dl::VertexShader> vs_;
  ComPtr<d3dl::PixelShader> ps_;
  ComPtr<d3dl::RasterizerState> rs_;
  // Compute and unordered access
  ComPtr<d3dl::Buffer> words_, wordsStaging_, dispatchConstants_;
  ComPtr<d3dl::UnorderedAccessView> wordsUav_;
  ComPtr<d3dl::ComputeShader> cs_;
};

}  // namespace

Recorder* CreateRhiRecorder() { return new RhiRecorder(); }

}  // namespace drrbench
