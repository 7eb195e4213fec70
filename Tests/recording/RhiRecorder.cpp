// The same frame as RawVulkanRecorder, written as a D3D11 programmer would:
// Map(WRITE_DISCARD) of one constant buffer + Draw, 'n' times (or + Dispatch
// on one UAV: compute and unordered access).
#include "d3dl/ShaderCompiler.h"
#include <cstring>
#include <fstream>
#include <vector>

#include "RhiDrawSetup.h"

namespace drrbench {
namespace {

using d3dl::ComPtr;

class RhiRecorder final : public Recorder {
 public:
  bool Init(std::string* error) override {
    return r_.Init("rhi-record-benchmark", error) && InitDispatch(BenchShaderDir(), error);
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
    if (d3dl::FAILED(r_.device->CreateBuffer(&wd, nullptr, words_.GetAddressOf())) ||
        d3dl::FAILED(r_.device->CreateBuffer(&sd, nullptr, wordsStaging_.GetAddressOf())) ||
        d3dl::FAILED(r_.device->CreateBuffer(&cd, nullptr, dispatchConstants_.GetAddressOf())) ||
        d3dl::FAILED(r_.device->CreateUnorderedAccessView(words_.Get(), &ud, wordsUav_.GetAddressOf())) ||
        d3dl::FAILED(r_.device->CreateComputeShader(cs.data(), cs.size() * 4, cs_.GetAddressOf()))) {
      *error = "creating the dispatch benchmark resources failed (shaders in " + dir + ")";
      return false;
    }
    return true;
  }

  void RecordDispatches(uint32_t n) override {
    d3dl::DeviceContext* ctx = r_.context.Get();
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
    if (d3dl::FAILED(r_.context->Map(wordsStaging_.Get(), 0, d3dl::MAP_READ, 0, &m))) return {};
    std::memcpy(words.data(), m.pData, words.size() * 4);
    r_.context->Unmap(wordsStaging_.Get(), 0);
    return words;
  }

  void Record(uint32_t n) override {
    d3dl::DeviceContext* ctx = r_.context.Get();
    const float black[4] = {0, 0, 0, 0};
    ctx->ClearRenderTargetView(r_.rtv.Get(), black);
    r_.BindDrawState(ctx);
    r_.RecordDraws(ctx, 0, n, n);
    ctx->CopyResource(r_.staging.Get(), r_.target.Get());
  }

  void SubmitAndWait() override {
    r_.context->Flush();
    r_.device->WaitIdle();
  }

  std::vector<uint8_t> ReadBack() override { return r_.ReadStaging(); }
  uint64_t ValidationMessages() const override { return r_.Messages(); }

 private:
  RhiDrawSetup r_;
  // Compute and unordered access
  ComPtr<d3dl::Buffer> words_, wordsStaging_, dispatchConstants_;
  ComPtr<d3dl::UnorderedAccessView> wordsUav_;
  ComPtr<d3dl::ComputeShader> cs_;
};

}  // namespace

Recorder* CreateRhiRecorder() { return new RhiRecorder(); }

}  // namespace drrbench
