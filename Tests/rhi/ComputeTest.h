// Helpers of the compute tests (ComputeTests.cpp, DeferredComputeTests.cpp):
// compute shaders, UAV textures and buffers, and buffer read-back.
#pragma once

#include <vector>

#include "RhiTest.h"

namespace rhitest {

class ComputeTest : public RhiTest {
 protected:
  ComPtr<ComputeShader> LoadCS(const char* file) {
    auto code = LoadSpirv(file);
    ComPtr<ComputeShader> cs;
    EXPECT_EQ(device()->CreateComputeShader(code.data(), code.size() * 4, cs.ReleaseAndGetAddressOf()), S_OK) << file;
    return cs;
  }
  // A DEFAULT texture with SRV + UAV bindings (and initial data if given).
  ComPtr<Texture2D> MakeUavTexture(UINT w, UINT h, DXGI_FORMAT f, const void* data = nullptr,
                                   UINT extraBind = BIND_SHADER_RESOURCE) {
    return MakeTexture(w, h, f, data, 1, nullptr, BIND_UNORDERED_ACCESS | extraBind);
  }
  ComPtr<UnorderedAccessView> MakeUAV(Resource* r, const UNORDERED_ACCESS_VIEW_DESC* desc = nullptr) {
    ComPtr<UnorderedAccessView> v;
    EXPECT_EQ(device()->CreateUnorderedAccessView(r, desc, v.ReleaseAndGetAddressOf()), S_OK);
    return v;
  }
  // A structured (stride > 0) or raw (stride 0) buffer with SRV and UAV bindings.
  ComPtr<Buffer> MakeViewBuffer(UINT bytes, UINT stride, const void* data, UINT misc = 0) {
    BUFFER_DESC d;
    d.ByteWidth = bytes;
    d.BindFlags = BIND_SHADER_RESOURCE | BIND_UNORDERED_ACCESS;
    d.MiscFlags = misc | (stride ? RESOURCE_MISC_BUFFER_STRUCTURED : RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS);
    d.StructureByteStride = stride;
    SUBRESOURCE_DATA init{data, 0, 0};
    ComPtr<Buffer> b;
    EXPECT_EQ(device()->CreateBuffer(&d, data ? &init : nullptr, b.ReleaseAndGetAddressOf()), S_OK);
    return b;
  }
  static UNORDERED_ACCESS_VIEW_DESC RawUavDesc(UINT first, UINT num) {
    UNORDERED_ACCESS_VIEW_DESC d;
    d.Format = DXGI_FORMAT_R32_TYPELESS;
    d.ViewDimension = UAV_DIMENSION_BUFFER;
    d.Buffer = {first, num, BUFFER_UAV_FLAG_RAW};
    return d;
  }
  // The buffer's bytes, through a STAGING copy.
  std::vector<uint8_t> ReadBuffer(Buffer* b) {
    BUFFER_DESC d;
    b->GetDesc(&d);
    BUFFER_DESC sd;
    sd.ByteWidth = d.ByteWidth;
    sd.Usage = USAGE_STAGING;
    sd.CPUAccessFlags = CPU_ACCESS_READ;
    ComPtr<Buffer> staging;
    EXPECT_EQ(device()->CreateBuffer(&sd, nullptr, staging.ReleaseAndGetAddressOf()), S_OK);
    context()->CopyResource(staging.Get(), b);
    MAPPED_SUBRESOURCE m;
    std::vector<uint8_t> out(d.ByteWidth);
    EXPECT_EQ(context()->Map(staging.Get(), 0, MAP_READ, 0, &m), S_OK);
    if (m.pData) std::memcpy(out.data(), m.pData, out.size());
    context()->Unmap(staging.Get(), 0);
    return out;
  }
  std::vector<uint32_t> ReadWords(Buffer* b) {
    auto bytes = ReadBuffer(b);
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
  }
  void BindUav(UnorderedAccessView* uav, UINT slot = 0) { context()->CSSetUnorderedAccessViews(slot, 1, &uav, nullptr); }
};

}  // namespace rhitest
