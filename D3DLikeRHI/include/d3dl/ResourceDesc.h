// D3DLikeRHI public types: what describes a resource (usage, bind, CPU access
// and misc flags, buffer and texture descriptions, initial data) and the
// regions calls name in it (subresource index, BOX, RECT).
#pragma once

#include "d3dl/Formats.h"

namespace d3dl {

enum USAGE : uint32_t {
  USAGE_DEFAULT = 0,
  USAGE_IMMUTABLE = 1,
  USAGE_DYNAMIC = 2,
  USAGE_STAGING = 3,
};

enum BIND_FLAG : uint32_t {
  BIND_VERTEX_BUFFER = 0x1,
  BIND_INDEX_BUFFER = 0x2,
  BIND_CONSTANT_BUFFER = 0x4,
  BIND_SHADER_RESOURCE = 0x8,
  BIND_RENDER_TARGET = 0x20,
  BIND_DEPTH_STENCIL = 0x40,
  BIND_UNORDERED_ACCESS = 0x80,  // UAVs (u#) of compute and pixel shaders
};

enum CPU_ACCESS_FLAG : uint32_t {
  CPU_ACCESS_WRITE = 0x10000,
  CPU_ACCESS_READ = 0x20000,
};

enum RESOURCE_MISC_FLAG : uint32_t {
  RESOURCE_MISC_GENERATE_MIPS = 0x1,
  RESOURCE_MISC_TEXTURECUBE = 0x4,  // Texture2D with ArraySize 6*n, Width == Height
  // Buffers read or written by shaders as arrays, or as indirect arguments
  RESOURCE_MISC_DRAWINDIRECT_ARGS = 0x10,       // Draw*Indirect / DispatchIndirect arguments
  RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS = 0x20,  // ByteAddressBuffer views (R32_TYPELESS)
  RESOURCE_MISC_BUFFER_STRUCTURED = 0x40,       // StructuredBuffer views (StructureByteStride)
};

enum RESOURCE_DIMENSION : uint32_t {
  RESOURCE_DIMENSION_UNKNOWN = 0,
  RESOURCE_DIMENSION_BUFFER = 1,
  RESOURCE_DIMENSION_TEXTURE1D = 2,
  RESOURCE_DIMENSION_TEXTURE2D = 3,
};

struct BUFFER_DESC {
  UINT ByteWidth = 0;
  USAGE Usage = USAGE_DEFAULT;
  UINT BindFlags = 0;
  UINT CPUAccessFlags = 0;
  UINT MiscFlags = 0;
  UINT StructureByteStride = 0;
};

struct SUBRESOURCE_DATA {
  const void* pSysMem = nullptr;
  UINT SysMemPitch = 0;       // bytes per row (textures)
  UINT SysMemSlicePitch = 0;  // unused for 1-D/2-D
};

struct SAMPLE_DESC {
  UINT Count = 1;
  UINT Quality = 0;  // 0, or STANDARD_MULTISAMPLE_PATTERN (what Vulkan always uses)
};
inline constexpr UINT STANDARD_MULTISAMPLE_PATTERN = 0xffffffffu;

struct TEXTURE1D_DESC {
  UINT Width = 0;
  UINT MipLevels = 1;  // 0 = full chain
  UINT ArraySize = 1;
  DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;
  USAGE Usage = USAGE_DEFAULT;
  UINT BindFlags = 0;
  UINT CPUAccessFlags = 0;
  UINT MiscFlags = 0;
};

struct TEXTURE2D_DESC {
  UINT Width = 0;
  UINT Height = 0;
  UINT MipLevels = 1;  // 0 = full chain
  UINT ArraySize = 1;
  DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;
  SAMPLE_DESC SampleDesc{};
  USAGE Usage = USAGE_DEFAULT;
  UINT BindFlags = 0;
  UINT CPUAccessFlags = 0;
  UINT MiscFlags = 0;
};

// Subresource index as in D3D11: MipSlice + ArraySlice * MipLevels.
inline constexpr UINT CalcSubresource(UINT mipSlice, UINT arraySlice, UINT mipLevels) {
  return mipSlice + arraySlice * mipLevels;
}

struct BOX {
  UINT left = 0, top = 0, front = 0;
  UINT right = 0, bottom = 0, back = 1;
};

struct RECT {
  int32_t left = 0, top = 0, right = 0, bottom = 0;
};

}  // namespace d3dl
