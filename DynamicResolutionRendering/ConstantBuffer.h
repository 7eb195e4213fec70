// What every unit that draws creates the same way: a dynamic constant buffer
// holding one struct (uploaded with Map(WRITE_DISCARD), copy, Unmap) and the
// depth-stencil state with no depth test or write.
#pragma once

#include <cstddef>

#include "d3dl/D3DLike.h"

namespace drr {

void UploadConstants(d3dl::DeviceContext* ctx, d3dl::Buffer* buffer, const void* data, size_t size);
bool CreateConstantBuffer(d3dl::Device* device, size_t size, d3dl::ComPtr<d3dl::Buffer>* buffer);
bool CreateNoDepthState(d3dl::Device* device, d3dl::ComPtr<d3dl::DepthStencilState>* state);

// A dynamic constant buffer holding one T.
template <class T>
class ConstantBuffer {
 public:
  bool Create(d3dl::Device* device) { return CreateConstantBuffer(device, sizeof(T), &m_Buffer); }
  void Release() { m_Buffer = nullptr; }
  void Upload(d3dl::DeviceContext* ctx, const T& value) { UploadConstants(ctx, m_Buffer.Get(), &value, sizeof value); }
  d3dl::Buffer* Get() const { return m_Buffer.Get(); }
  d3dl::Buffer* const* Address() const { return m_Buffer.GetAddressOf(); }

 private:
  d3dl::ComPtr<d3dl::Buffer> m_Buffer;
};

}  // namespace drr
