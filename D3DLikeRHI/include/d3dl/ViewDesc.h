// D3DLikeRHI public types: view descriptions (shader-resource, render-target,
// depth-stencil and unordered-access views of textures and buffers).
#pragma once

#include "d3dl/Formats.h"

namespace d3dl {

// UNKNOWN = the dimension the texture implies: 1-D/2-D, their arrays when
// ArraySize > 1, TEXTURE2DMS(ARRAY) when multisampled, TEXTURECUBE(ARRAY) for
// RESOURCE_MISC_TEXTURECUBE textures (SRVs only).
enum SRV_DIMENSION : uint32_t {
  SRV_DIMENSION_UNKNOWN = 0,
  SRV_DIMENSION_TEXTURE1D = 2,
  SRV_DIMENSION_TEXTURE1DARRAY = 3,
  SRV_DIMENSION_TEXTURE2D = 4,
  SRV_DIMENSION_TEXTURE2DARRAY = 5,
  SRV_DIMENSION_TEXTURE2DMS = 6,
  SRV_DIMENSION_TEXTURE2DMSARRAY = 7,
  SRV_DIMENSION_TEXTURECUBE = 9,
  SRV_DIMENSION_TEXTURECUBEARRAY = 10,
};

enum RTV_DIMENSION : uint32_t {
  RTV_DIMENSION_UNKNOWN = 0,
  RTV_DIMENSION_TEXTURE1D = 2,
  RTV_DIMENSION_TEXTURE1DARRAY = 3,
  RTV_DIMENSION_TEXTURE2D = 4,
  RTV_DIMENSION_TEXTURE2DARRAY = 5,
  RTV_DIMENSION_TEXTURE2DMS = 6,
  RTV_DIMENSION_TEXTURE2DMSARRAY = 7,
};

enum DSV_DIMENSION : uint32_t {
  DSV_DIMENSION_UNKNOWN = 0,
  DSV_DIMENSION_TEXTURE1D = 1,
  DSV_DIMENSION_TEXTURE1DARRAY = 2,
  DSV_DIMENSION_TEXTURE2D = 3,
  DSV_DIMENSION_TEXTURE2DARRAY = 4,
  DSV_DIMENSION_TEXTURE2DMS = 5,
  DSV_DIMENSION_TEXTURE2DMSARRAY = 6,
};

struct TEX_SRV {
  UINT MostDetailedMip = 0;
  UINT MipLevels = ~0u;  // ~0u = all from MostDetailedMip
};

// D3D11's array members of the view unions, flattened: which array slices an
// *ARRAY view covers (TEXTURE2DARRAY, TEXTURE1DARRAY, TEXTURE2DMSARRAY).
// ArraySize ~0u = all slices from FirstArraySlice (a port convenience).
struct TEX_ARRAY_RANGE {
  UINT FirstArraySlice = 0;
  UINT ArraySize = ~0u;
};

// TEXTURECUBEARRAY: the first face (a multiple of 6 in D3D11 practice, any
// slice is allowed) and the number of cubes (~0u = all that fit).
struct TEXCUBE_ARRAY_SRV {
  UINT First2DArrayFace = 0;
  UINT NumCubes = ~0u;
};

// Elements of a structured or raw buffer an SRV
// sees (ViewDimension SRV_DIMENSION_BUFFEREX; Flags BUFFEREX_SRV_FLAG_RAW).
struct BUFFEREX_SRV {
  UINT FirstElement = 0;
  UINT NumElements = 0;
  UINT Flags = 0;
};

struct SHADER_RESOURCE_VIEW_DESC {
  DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;  // UNKNOWN = the texture's format
  SRV_DIMENSION ViewDimension = SRV_DIMENSION_UNKNOWN;
  TEX_SRV Texture{};  // mips (not for TEXTURE2DMS*)
  TEX_ARRAY_RANGE Array{};
  TEXCUBE_ARRAY_SRV CubeArray{};
  BUFFEREX_SRV BufferEx{};  // structured and raw buffers
};

struct RENDER_TARGET_VIEW_DESC {
  DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;
  RTV_DIMENSION ViewDimension = RTV_DIMENSION_UNKNOWN;
  UINT MipSlice = 0;
  TEX_ARRAY_RANGE Array{};  // *ARRAY dimensions; the others view slice 0
};

struct DEPTH_STENCIL_VIEW_DESC {
  DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;
  DSV_DIMENSION ViewDimension = DSV_DIMENSION_UNKNOWN;
  UINT Flags = 0;
  UINT MipSlice = 0;
  TEX_ARRAY_RANGE Array{};  // *ARRAY dimensions (a shadow-map slice or range)
};

// ---------------------------------------------------------------------------
// Buffer SRVs and UAVs (D3D11 numbering)
// (BIND_UNORDERED_ACCESS and the RESOURCE_MISC_* buffer flags sit in their
// enums in ResourceDesc.h, so that they combine with the others.)
inline constexpr SRV_DIMENSION SRV_DIMENSION_BUFFER = static_cast<SRV_DIMENSION>(1);
inline constexpr SRV_DIMENSION SRV_DIMENSION_BUFFEREX = static_cast<SRV_DIMENSION>(11);

enum BUFFEREX_SRV_FLAG : uint32_t {
  BUFFEREX_SRV_FLAG_RAW = 0x1,
};

enum UAV_DIMENSION : uint32_t {
  UAV_DIMENSION_UNKNOWN = 0,
  UAV_DIMENSION_BUFFER = 1,
  UAV_DIMENSION_TEXTURE2D = 4,
};

enum BUFFER_UAV_FLAG : uint32_t {
  BUFFER_UAV_FLAG_RAW = 0x1,
  BUFFER_UAV_FLAG_APPEND = 0x2,   // not supported (E_NOTIMPL)
  BUFFER_UAV_FLAG_COUNTER = 0x4,  // not supported (E_NOTIMPL)
};

struct BUFFER_UAV {
  UINT FirstElement = 0;
  UINT NumElements = 0;
  UINT Flags = 0;
};

struct TEX2D_UAV {
  UINT MipSlice = 0;
};

// D3D11 keeps Buffer and Texture2D in a union; here they are plain members.
struct UNORDERED_ACCESS_VIEW_DESC {
  DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;  // buffers: UNKNOWN (structured) or R32_TYPELESS (raw)
  UAV_DIMENSION ViewDimension = UAV_DIMENSION_UNKNOWN;
  BUFFER_UAV Buffer{};
  TEX2D_UAV Texture2D{};
};

// OMSetRenderTargetsAndUnorderedAccessViews: leave that half of the bindings as it is.
inline constexpr UINT KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL = 0xffffffffu;
inline constexpr UINT KEEP_UNORDERED_ACCESS_VIEWS = 0xffffffffu;

}  // namespace d3dl
