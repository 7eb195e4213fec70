// What the validation layer (Validate.h) sees of the device and of
// resources: D3D11 terms and plain numbers, nothing of Vulkan. DeviceImpl is
// a ValidationDevice; DescribeResource gives a resource's ResourceInfo.
#pragma once

#include <algorithm>

#include "d3dl/Interfaces.h"

namespace d3dl::impl {

// ---- What the validation layer knows of the device
// The adapter's limits and optional features that change what is valid
// (filled once when the device is created).
struct ValidationCaps {
  uint32_t maxTexture1D = 0, maxTexture2D = 0, maxArrayLayers = 0;
  uint32_t maxUniformBufferRange = 0;
  uint64_t storageBufferAlign = 1;  // byte alignment of a buffer view's first element
  uint32_t maxDispatch[3] = {};     // thread groups per dimension
  bool bc = false, minmax = false, independentBlend = false, fillNonSolid = false;
  bool pipelineStatistics = false, cubeArray = false;
  char adapterName[256] = {};
};
// What the adapter can do with a format besides binding it (FormatFeatures).
enum FormatFeature : uint32_t {
  FORMAT_FEATURE_BLIT_SRC = 0x1,
  FORMAT_FEATURE_BLIT_DST = 0x2,
  FORMAT_FEATURE_FILTER_LINEAR = 0x4,  // sampled or blitted with linear filtering
};
// The device as the validators see it (DeviceImpl is one).
class ValidationDevice {
 public:
  void Log(LogLevel level, const char* fmt, ...) const __attribute__((format(printf, 3, 4)));
  const ValidationCaps& caps() const { return caps_; }
  virtual bool CheckFormatSupport(DXGI_FORMAT format, UINT bindFlags) const = 0;
  virtual HRESULT CheckMultisampleQualityLevels(DXGI_FORMAT format, UINT sampleCount, UINT* levels) const = 0;
  // FormatFeature bits of a colour texture of `format` (optimal tiling).
  virtual uint32_t FormatFeatures(DXGI_FORMAT format) const = 0;
  // The sample counts (each count's own bit: 1, 2, 4...) a texture of this
  // description can have and still be sampled.
  virtual UINT SampledSampleCounts(const TEXTURE2D_DESC& desc) const = 0;

 protected:
  ~ValidationDevice() = default;
  ValidationCaps caps_;
  LogCallback log_ = nullptr;  // nullptr: warnings and errors to stderr
  void* logUser_ = nullptr;
};

// A read-only view of a resource in D3D11 terms (DescribeResource).
struct ResourceInfo {
  RESOURCE_DIMENSION dimension = RESOURCE_DIMENSION_UNKNOWN;  // UNKNOWN: no resource
  DXGI_FORMAT format = DXGI_FORMAT_UNKNOWN;                   // textures
  UINT width = 0, height = 1, arraySize = 1, mipLevels = 1, samples = 1;
  UINT byteWidth = 0, structureStride = 0;  // buffers
  USAGE usage = USAGE_DEFAULT;
  UINT bindFlags = 0, cpuAccessFlags = 0, miscFlags = 0;
  bool depth = false;    // a depth(-stencil) image: BIND_DEPTH_STENCIL or a depth format
  bool stencil = false;  // a depth image with a stencil aspect too
  bool IsTexture() const { return dimension == RESOURCE_DIMENSION_TEXTURE1D || dimension == RESOURCE_DIMENSION_TEXTURE2D; }
  bool IsBuffer() const { return dimension == RESOURCE_DIMENSION_BUFFER; }
  bool IsConstantBuffer() const { return IsBuffer() && (bindFlags & BIND_CONSTANT_BUFFER); }
  UINT MipWidth(UINT mip) const { return std::max(1u, width >> mip); }
  UINT MipHeight(UINT mip) const { return std::max(1u, height >> mip); }
  // D3D11's subresource index; false when out of range.
  bool DecodeSub(UINT sub, UINT* mip, UINT* layer) const {
    if (sub >= mipLevels * arraySize) return false;
    *mip = sub % mipLevels;
    *layer = sub / mipLevels;
    return true;
  }
};
ResourceInfo DescribeResource(Resource* r);  // Resources.cpp
// A view in D3D11 terms (DescribeView, Views.cpp): the resource it names
// (UNKNOWN dimension: none) and the format it reads a texture as.
struct ViewInfo {
  ResourceInfo resource;
  DXGI_FORMAT format = DXGI_FORMAT_UNKNOWN;
};

}  // namespace d3dl::impl
