#include "ConstantBuffer.h"

#include <cstring>

namespace drr {

void UploadConstants(d3dl::DeviceContext* ctx, d3dl::Buffer* buffer, const void* data, size_t size) {
  d3dl::MAPPED_SUBRESOURCE m;
  if (d3dl::SUCCEEDED(ctx->Map(buffer, 0, d3dl::MAP_WRITE_DISCARD, 0, &m))) {
    std::memcpy(m.pData, data, size);
    ctx->Unmap(buffer, 0);
  }
}

bool CreateConstantBuffer(d3dl::Device* device, size_t size, d3dl::ComPtr<d3dl::Buffer>* buffer) {
  d3dl::BUFFER_DESC cb;
  cb.ByteWidth = uint32_t(size);
  cb.Usage = d3dl::USAGE_DYNAMIC;
  cb.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  cb.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  return d3dl::SUCCEEDED(device->CreateBuffer(&cb, nullptr, buffer->ReleaseAndGetAddressOf()));
}

bool CreateNoDepthState(d3dl::Device* device, d3dl::ComPtr<d3dl::DepthStencilState>* state) {
  d3dl::DEPTH_STENCIL_DESC nd;
  nd.DepthEnable = 0;
  nd.DepthWriteMask = d3dl::DEPTH_WRITE_MASK_ZERO;
  return d3dl::SUCCEEDED(device->CreateDepthStencilState(&nd, state->ReleaseAndGetAddressOf()));
}

}  // namespace drr
