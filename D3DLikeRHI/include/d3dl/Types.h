// D3DLikeRHI public types: plain D3D11-style enums and *_DESC structs.
//
// Enum values are Direct3D 11's own numbers, so code and constants from the
// D3D11 documentation (filter bit layout, formats) carry over unchanged.
#pragma once

#include <cstddef>
#include <cstdint>

namespace d3dl {

using HRESULT = int32_t;
using UINT = uint32_t;
using UINT64 = uint64_t;
using BOOL = int32_t;

inline constexpr HRESULT S_OK = 0;
inline constexpr HRESULT S_FALSE = 1;  // query data not ready yet
inline constexpr HRESULT E_NOTIMPL = static_cast<HRESULT>(0x80004001u);
inline constexpr HRESULT E_FAIL = static_cast<HRESULT>(0x80004005u);
inline constexpr HRESULT E_OUTOFMEMORY = static_cast<HRESULT>(0x8007000Eu);
inline constexpr HRESULT E_INVALIDARG = static_cast<HRESULT>(0x80070057u);
inline constexpr HRESULT DXGI_ERROR_UNSUPPORTED = static_cast<HRESULT>(0x887A0004u);
inline constexpr HRESULT DXGI_ERROR_DEVICE_REMOVED = static_cast<HRESULT>(0x887A0005u);
inline constexpr HRESULT DXGI_ERROR_WAS_STILL_DRAWING = static_cast<HRESULT>(0x887A000Au);
inline constexpr HRESULT DXGI_STATUS_OCCLUDED = static_cast<HRESULT>(0x087A0001u);

inline constexpr bool SUCCEEDED(HRESULT hr) { return hr >= 0; }
inline constexpr bool FAILED(HRESULT hr) { return hr < 0; }

// Human-readable name of an HRESULT ("E_INVALIDARG", ...).
const char* HResultName(HRESULT hr);

// ---------------------------------------------------------------------------
// Formats (DXGI_FORMAT numbering; only the subset the sample and loaders need).
enum DXGI_FORMAT : uint32_t {
  DXGI_FORMAT_UNKNOWN = 0,
  DXGI_FORMAT_R32G32B32A32_FLOAT = 2,
  DXGI_FORMAT_R32G32B32_FLOAT = 6,
  DXGI_FORMAT_R16G16B16A16_TYPELESS = 9,  // typeless families (views name a typed member)
  DXGI_FORMAT_R16G16B16A16_FLOAT = 10,
  DXGI_FORMAT_R16G16B16A16_UNORM = 11,
  DXGI_FORMAT_R32G32_FLOAT = 16,
  DXGI_FORMAT_R10G10B10A2_TYPELESS = 23,
  DXGI_FORMAT_R10G10B10A2_UNORM = 24,
  DXGI_FORMAT_R11G11B10_FLOAT = 26,
  DXGI_FORMAT_R8G8B8A8_TYPELESS = 27,
  DXGI_FORMAT_R8G8B8A8_UNORM = 28,
  DXGI_FORMAT_R8G8B8A8_UNORM_SRGB = 29,
  DXGI_FORMAT_R8G8B8A8_UINT = 30,
  DXGI_FORMAT_R16G16_FLOAT = 34,
  DXGI_FORMAT_R32_TYPELESS = 39,  // depth texture that is also sampled
  DXGI_FORMAT_D32_FLOAT = 40,
  DXGI_FORMAT_R32_FLOAT = 41,
  DXGI_FORMAT_R32_UINT = 42,
  DXGI_FORMAT_R24G8_TYPELESS = 44,         // depth-stencil texture that is also sampled
  DXGI_FORMAT_D24_UNORM_S8_UINT = 45,      // Vulkan D24_UNORM_S8_UINT, where the adapter has it
  DXGI_FORMAT_R24_UNORM_X8_TYPELESS = 46,  // SRV of the depth half of R24G8_TYPELESS
  DXGI_FORMAT_R8G8_UNORM = 49,
  DXGI_FORMAT_R16_FLOAT = 54,
  DXGI_FORMAT_R16_UINT = 57,
  DXGI_FORMAT_R8_UNORM = 61,
  DXGI_FORMAT_BC1_UNORM = 71,
  DXGI_FORMAT_BC1_UNORM_SRGB = 72,
  DXGI_FORMAT_BC2_UNORM = 74,
  DXGI_FORMAT_BC2_UNORM_SRGB = 75,
  DXGI_FORMAT_BC3_UNORM = 77,
  DXGI_FORMAT_BC3_UNORM_SRGB = 78,
  DXGI_FORMAT_BC4_UNORM = 80,
  DXGI_FORMAT_BC4_SNORM = 81,
  DXGI_FORMAT_BC5_UNORM = 83,
  DXGI_FORMAT_BC5_SNORM = 84,
  DXGI_FORMAT_B8G8R8A8_UNORM = 87,
  DXGI_FORMAT_B8G8R8A8_UNORM_SRGB = 91,
};

// Bytes per texel (or per 4x4 block for BC formats); 0 for unknown formats.
UINT FormatBytesPerElement(DXGI_FORMAT format);
bool FormatIsBlockCompressed(DXGI_FORMAT format);
const char* FormatName(DXGI_FORMAT format);

// ---------------------------------------------------------------------------
// Resources
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
  BIND_UNORDERED_ACCESS = 0x80,  // compute and unordered access
};

enum CPU_ACCESS_FLAG : uint32_t {
  CPU_ACCESS_WRITE = 0x10000,
  CPU_ACCESS_READ = 0x20000,
};

enum RESOURCE_MISC_FLAG : uint32_t {
  RESOURCE_MISC_GENERATE_MIPS = 0x1,
  RESOURCE_MISC_TEXTURECUBE = 0x4,  // Texture2D with ArraySize 6*n, Width == Height
  // Compute and unordered access
  RESOURCE_MISC_DRAWINDIRECT_ARGS = 0x10,       // DispatchIndirect arguments
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

// ---------------------------------------------------------------------------
// Views
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

// Compute and unordered access: elements of a structured or raw buffer an SRV
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
  BUFFEREX_SRV BufferEx{};  // buffers (compute and unordered access)
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
// Sampler (D3D11_FILTER bit layout: min<<4 | mag<<2 | mip, 0x40 anisotropic,
// 0x80 comparison, 0x100 minimum, 0x180 maximum reduction).
enum FILTER : uint32_t {
  FILTER_MIN_MAG_MIP_POINT = 0x0,
  FILTER_MIN_MAG_POINT_MIP_LINEAR = 0x1,
  FILTER_MIN_POINT_MAG_LINEAR_MIP_POINT = 0x4,
  FILTER_MIN_POINT_MAG_MIP_LINEAR = 0x5,
  FILTER_MIN_LINEAR_MAG_MIP_POINT = 0x10,
  FILTER_MIN_LINEAR_MAG_POINT_MIP_LINEAR = 0x11,
  FILTER_MIN_MAG_LINEAR_MIP_POINT = 0x14,
  FILTER_MIN_MAG_MIP_LINEAR = 0x15,
  FILTER_ANISOTROPIC = 0x55,
  FILTER_COMPARISON_MIN_MAG_MIP_POINT = 0x80,
  FILTER_COMPARISON_MIN_MAG_POINT_MIP_LINEAR = 0x81,
  FILTER_COMPARISON_MIN_POINT_MAG_LINEAR_MIP_POINT = 0x84,
  FILTER_COMPARISON_MIN_POINT_MAG_MIP_LINEAR = 0x85,
  FILTER_COMPARISON_MIN_LINEAR_MAG_MIP_POINT = 0x90,
  FILTER_COMPARISON_MIN_LINEAR_MAG_POINT_MIP_LINEAR = 0x91,
  FILTER_COMPARISON_MIN_MAG_LINEAR_MIP_POINT = 0x94,
  FILTER_COMPARISON_MIN_MAG_MIP_LINEAR = 0x95,
  FILTER_COMPARISON_ANISOTROPIC = 0xD5,
  FILTER_MINIMUM_MIN_MAG_MIP_POINT = 0x100,
  FILTER_MINIMUM_MIN_MAG_MIP_LINEAR = 0x115,
  FILTER_MINIMUM_ANISOTROPIC = 0x155,
  FILTER_MAXIMUM_MIN_MAG_MIP_POINT = 0x180,
  FILTER_MAXIMUM_MIN_MAG_MIP_LINEAR = 0x195,
  FILTER_MAXIMUM_ANISOTROPIC = 0x1D5,
};

enum TEXTURE_ADDRESS_MODE : uint32_t {
  TEXTURE_ADDRESS_WRAP = 1,
  TEXTURE_ADDRESS_MIRROR = 2,
  TEXTURE_ADDRESS_CLAMP = 3,
  TEXTURE_ADDRESS_BORDER = 4,
  TEXTURE_ADDRESS_MIRROR_ONCE = 5,
};

enum COMPARISON_FUNC : uint32_t {
  COMPARISON_NEVER = 1,
  COMPARISON_LESS = 2,
  COMPARISON_EQUAL = 3,
  COMPARISON_LESS_EQUAL = 4,
  COMPARISON_GREATER = 5,
  COMPARISON_NOT_EQUAL = 6,
  COMPARISON_GREATER_EQUAL = 7,
  COMPARISON_ALWAYS = 8,
};

inline constexpr float FLOAT32_MAX = 3.402823466e+38f;

struct SAMPLER_DESC {
  FILTER Filter = FILTER_MIN_MAG_MIP_LINEAR;
  TEXTURE_ADDRESS_MODE AddressU = TEXTURE_ADDRESS_CLAMP;
  TEXTURE_ADDRESS_MODE AddressV = TEXTURE_ADDRESS_CLAMP;
  TEXTURE_ADDRESS_MODE AddressW = TEXTURE_ADDRESS_CLAMP;
  float MipLODBias = 0.0f;
  UINT MaxAnisotropy = 1;
  COMPARISON_FUNC ComparisonFunc = COMPARISON_NEVER;
  float BorderColor[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  float MinLOD = -FLOAT32_MAX;
  float MaxLOD = FLOAT32_MAX;
};

// ---------------------------------------------------------------------------
// Output merger / rasterizer state
enum BLEND : uint32_t {
  BLEND_ZERO = 1,
  BLEND_ONE = 2,
  BLEND_SRC_COLOR = 3,
  BLEND_INV_SRC_COLOR = 4,
  BLEND_SRC_ALPHA = 5,
  BLEND_INV_SRC_ALPHA = 6,
  BLEND_DEST_ALPHA = 7,
  BLEND_INV_DEST_ALPHA = 8,
  BLEND_DEST_COLOR = 9,
  BLEND_INV_DEST_COLOR = 10,
  BLEND_SRC_ALPHA_SAT = 11,
  BLEND_BLEND_FACTOR = 14,
  BLEND_INV_BLEND_FACTOR = 15,
};

enum BLEND_OP : uint32_t {
  BLEND_OP_ADD = 1,
  BLEND_OP_SUBTRACT = 2,
  BLEND_OP_REV_SUBTRACT = 3,
  BLEND_OP_MIN = 4,
  BLEND_OP_MAX = 5,
};

enum COLOR_WRITE_ENABLE : uint8_t {
  COLOR_WRITE_ENABLE_RED = 1,
  COLOR_WRITE_ENABLE_GREEN = 2,
  COLOR_WRITE_ENABLE_BLUE = 4,
  COLOR_WRITE_ENABLE_ALPHA = 8,
  COLOR_WRITE_ENABLE_ALL = 15,
};

inline constexpr UINT SIMULTANEOUS_RENDER_TARGET_COUNT = 8;

struct RENDER_TARGET_BLEND_DESC {
  BOOL BlendEnable = 0;
  BLEND SrcBlend = BLEND_ONE;
  BLEND DestBlend = BLEND_ZERO;
  BLEND_OP BlendOp = BLEND_OP_ADD;
  BLEND SrcBlendAlpha = BLEND_ONE;
  BLEND DestBlendAlpha = BLEND_ZERO;
  BLEND_OP BlendOpAlpha = BLEND_OP_ADD;
  uint8_t RenderTargetWriteMask = COLOR_WRITE_ENABLE_ALL;
};

struct BLEND_DESC {
  BOOL AlphaToCoverageEnable = 0;
  BOOL IndependentBlendEnable = 0;
  RENDER_TARGET_BLEND_DESC RenderTarget[SIMULTANEOUS_RENDER_TARGET_COUNT]{};
};

enum DEPTH_WRITE_MASK : uint32_t {
  DEPTH_WRITE_MASK_ZERO = 0,
  DEPTH_WRITE_MASK_ALL = 1,
};

enum STENCIL_OP : uint32_t {
  STENCIL_OP_KEEP = 1,
  STENCIL_OP_ZERO = 2,
  STENCIL_OP_REPLACE = 3,
  STENCIL_OP_INCR_SAT = 4,
  STENCIL_OP_DECR_SAT = 5,
  STENCIL_OP_INVERT = 6,
  STENCIL_OP_INCR = 7,
  STENCIL_OP_DECR = 8,
};

struct DEPTH_STENCILOP_DESC {
  STENCIL_OP StencilFailOp = STENCIL_OP_KEEP;
  STENCIL_OP StencilDepthFailOp = STENCIL_OP_KEEP;
  STENCIL_OP StencilPassOp = STENCIL_OP_KEEP;
  COMPARISON_FUNC StencilFunc = COMPARISON_ALWAYS;
};

struct DEPTH_STENCIL_DESC {
  BOOL DepthEnable = 1;
  DEPTH_WRITE_MASK DepthWriteMask = DEPTH_WRITE_MASK_ALL;
  COMPARISON_FUNC DepthFunc = COMPARISON_LESS;
  BOOL StencilEnable = 0;
  uint8_t StencilReadMask = 0xff;
  uint8_t StencilWriteMask = 0xff;
  DEPTH_STENCILOP_DESC FrontFace{};
  DEPTH_STENCILOP_DESC BackFace{};
};

enum FILL_MODE : uint32_t {
  FILL_WIREFRAME = 2,
  FILL_SOLID = 3,
};

enum CULL_MODE : uint32_t {
  CULL_NONE = 1,
  CULL_FRONT = 2,
  CULL_BACK = 3,
};

struct RASTERIZER_DESC {
  FILL_MODE FillMode = FILL_SOLID;
  CULL_MODE CullMode = CULL_BACK;
  BOOL FrontCounterClockwise = 0;  // D3D default: clockwise triangles face front
  int32_t DepthBias = 0;
  float DepthBiasClamp = 0.0f;
  float SlopeScaledDepthBias = 0.0f;
  BOOL DepthClipEnable = 1;
  BOOL ScissorEnable = 0;
  BOOL MultisampleEnable = 0;
  BOOL AntialiasedLineEnable = 0;
};

// ---------------------------------------------------------------------------
// Input assembler
enum PRIMITIVE_TOPOLOGY : uint32_t {
  PRIMITIVE_TOPOLOGY_UNDEFINED = 0,
  PRIMITIVE_TOPOLOGY_POINTLIST = 1,
  PRIMITIVE_TOPOLOGY_LINELIST = 2,
  PRIMITIVE_TOPOLOGY_LINESTRIP = 3,
  PRIMITIVE_TOPOLOGY_TRIANGLELIST = 4,
  PRIMITIVE_TOPOLOGY_TRIANGLESTRIP = 5,
  // Tessellation: patch lists of 1..32 control points (D3D11's values 33..64).
  PRIMITIVE_TOPOLOGY_1_CONTROL_POINT_PATCHLIST = 33,
  PRIMITIVE_TOPOLOGY_2_CONTROL_POINT_PATCHLIST = 34,
  PRIMITIVE_TOPOLOGY_3_CONTROL_POINT_PATCHLIST = 35,
  PRIMITIVE_TOPOLOGY_4_CONTROL_POINT_PATCHLIST = 36,
  PRIMITIVE_TOPOLOGY_5_CONTROL_POINT_PATCHLIST = 37,
  PRIMITIVE_TOPOLOGY_6_CONTROL_POINT_PATCHLIST = 38,
  PRIMITIVE_TOPOLOGY_7_CONTROL_POINT_PATCHLIST = 39,
  PRIMITIVE_TOPOLOGY_8_CONTROL_POINT_PATCHLIST = 40,
  PRIMITIVE_TOPOLOGY_9_CONTROL_POINT_PATCHLIST = 41,
  PRIMITIVE_TOPOLOGY_10_CONTROL_POINT_PATCHLIST = 42,
  PRIMITIVE_TOPOLOGY_11_CONTROL_POINT_PATCHLIST = 43,
  PRIMITIVE_TOPOLOGY_12_CONTROL_POINT_PATCHLIST = 44,
  PRIMITIVE_TOPOLOGY_13_CONTROL_POINT_PATCHLIST = 45,
  PRIMITIVE_TOPOLOGY_14_CONTROL_POINT_PATCHLIST = 46,
  PRIMITIVE_TOPOLOGY_15_CONTROL_POINT_PATCHLIST = 47,
  PRIMITIVE_TOPOLOGY_16_CONTROL_POINT_PATCHLIST = 48,
  PRIMITIVE_TOPOLOGY_17_CONTROL_POINT_PATCHLIST = 49,
  PRIMITIVE_TOPOLOGY_18_CONTROL_POINT_PATCHLIST = 50,
  PRIMITIVE_TOPOLOGY_19_CONTROL_POINT_PATCHLIST = 51,
  PRIMITIVE_TOPOLOGY_20_CONTROL_POINT_PATCHLIST = 52,
  PRIMITIVE_TOPOLOGY_21_CONTROL_POINT_PATCHLIST = 53,
  PRIMITIVE_TOPOLOGY_22_CONTROL_POINT_PATCHLIST = 54,
  PRIMITIVE_TOPOLOGY_23_CONTROL_POINT_PATCHLIST = 55,
  PRIMITIVE_TOPOLOGY_24_CONTROL_POINT_PATCHLIST = 56,
  PRIMITIVE_TOPOLOGY_25_CONTROL_POINT_PATCHLIST = 57,
  PRIMITIVE_TOPOLOGY_26_CONTROL_POINT_PATCHLIST = 58,
  PRIMITIVE_TOPOLOGY_27_CONTROL_POINT_PATCHLIST = 59,
  PRIMITIVE_TOPOLOGY_28_CONTROL_POINT_PATCHLIST = 60,
  PRIMITIVE_TOPOLOGY_29_CONTROL_POINT_PATCHLIST = 61,
  PRIMITIVE_TOPOLOGY_30_CONTROL_POINT_PATCHLIST = 62,
  PRIMITIVE_TOPOLOGY_31_CONTROL_POINT_PATCHLIST = 63,
  PRIMITIVE_TOPOLOGY_32_CONTROL_POINT_PATCHLIST = 64,
};

// Tessellation: the patch-list topology of `n` control points (1..32).
inline constexpr PRIMITIVE_TOPOLOGY PatchListTopology(UINT n) {
  return static_cast<PRIMITIVE_TOPOLOGY>(PRIMITIVE_TOPOLOGY_1_CONTROL_POINT_PATCHLIST + n - 1);
}

enum INPUT_CLASSIFICATION : uint32_t {
  INPUT_PER_VERTEX_DATA = 0,
  INPUT_PER_INSTANCE_DATA = 1,
};

inline constexpr UINT APPEND_ALIGNED_ELEMENT = 0xffffffffu;
inline constexpr UINT IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT = 16;

struct INPUT_ELEMENT_DESC {
  const char* SemanticName = nullptr;
  UINT SemanticIndex = 0;
  DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;
  UINT InputSlot = 0;
  UINT AlignedByteOffset = APPEND_ALIGNED_ELEMENT;
  INPUT_CLASSIFICATION InputSlotClass = INPUT_PER_VERTEX_DATA;
  UINT InstanceDataStepRate = 0;
};

struct VIEWPORT {
  float TopLeftX = 0.0f;
  float TopLeftY = 0.0f;
  float Width = 0.0f;
  float Height = 0.0f;
  float MinDepth = 0.0f;
  float MaxDepth = 1.0f;
};

// ---------------------------------------------------------------------------
// Context operations
enum MAP : uint32_t {
  MAP_READ = 1,
  MAP_WRITE = 2,
  MAP_READ_WRITE = 3,
  MAP_WRITE_DISCARD = 4,
  MAP_WRITE_NO_OVERWRITE = 5,
};

enum MAP_FLAG : uint32_t {
  MAP_FLAG_DO_NOT_WAIT = 0x100000,
};

struct MAPPED_SUBRESOURCE {
  void* pData = nullptr;
  UINT RowPitch = 0;
  UINT DepthPitch = 0;
};

enum CLEAR_FLAG : uint32_t {
  CLEAR_DEPTH = 0x1,
  CLEAR_STENCIL = 0x2,
};

// ---------------------------------------------------------------------------
// Queries
enum QUERY : uint32_t {
  QUERY_EVENT = 0,
  QUERY_TIMESTAMP = 2,
  QUERY_TIMESTAMP_DISJOINT = 3,
  QUERY_PIPELINE_STATISTICS = 4,  // Begin/End; QUERY_DATA_PIPELINE_STATISTICS
};

struct QUERY_DESC {
  QUERY Query = QUERY_EVENT;
  UINT MiscFlags = 0;
};

struct QUERY_DATA_TIMESTAMP_DISJOINT {
  UINT64 Frequency = 0;  // ticks per second
  BOOL Disjoint = 0;
};

// Pipeline statistics (D3D11 field order; counters the adapter cannot count
// read as 0: the geometry ones without geometry shaders, HS/DS without
// tessellation). HSInvocations counts patches, as Vulkan does.
struct QUERY_DATA_PIPELINE_STATISTICS {
  UINT64 IAVertices = 0;
  UINT64 IAPrimitives = 0;
  UINT64 VSInvocations = 0;
  UINT64 GSInvocations = 0;
  UINT64 GSPrimitives = 0;
  UINT64 CInvocations = 0;
  UINT64 CPrimitives = 0;
  UINT64 PSInvocations = 0;
  UINT64 HSInvocations = 0;
  UINT64 DSInvocations = 0;
  UINT64 CSInvocations = 0;
};

enum ASYNC_GETDATA_FLAG : uint32_t {
  ASYNC_GETDATA_DONOTFLUSH = 0x1,
};

// ---------------------------------------------------------------------------
// Compute and unordered access (D3D11 numbering)
// (BIND_UNORDERED_ACCESS and the RESOURCE_MISC_* buffer flags sit in their
// enums above, so that they combine with the others.)
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

// ---------------------------------------------------------------------------
// Swap chain
struct SWAP_CHAIN_DESC {
  UINT Width = 0;   // 0 = the window's framebuffer size
  UINT Height = 0;
  DXGI_FORMAT Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  UINT BufferCount = 2;
};

// ---------------------------------------------------------------------------
// Device creation and diagnostics
enum class LogLevel : uint32_t { Info, Warning, Error, Validation };

// Receives every message of the RHI, including Vulkan validation messages
// (LogLevel::Validation). Called from the thread that made the API call.
using LogCallback = void (*)(LogLevel level, const char* message, void* user);

enum class ValidationMode : uint32_t {
  FromEnvironment,  // D3DL_VALIDATION=0|1|sync decides (default: off)
  Off,
  Core,             // VK_LAYER_KHRONOS_validation
  CoreAndSync,      // plus synchronization validation
};

struct DEVICE_CREATE_DESC {
  ValidationMode Validation = ValidationMode::FromEnvironment;
  LogCallback Log = nullptr;  // nullptr = print warnings and errors to stderr
  void* LogUser = nullptr;
  UINT FramesInFlight = 2;    // frames the CPU may record ahead of the GPU
  bool EnableWindowSurfaces = true;  // request the GLFW surface extensions
  const char* AdapterNameFilter = nullptr;  // substring of the adapter name, or D3DL_ADAPTER
  const char* ApplicationName = "D3DLikeRHI";
};

struct ADAPTER_DESC {
  char Description[256] = {};  // "llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H100 ..."
  char Driver[256] = {};       // "Mesa 22.3.6 (LLVM 15.0.6)"
  UINT VendorId = 0;
  UINT DeviceId = 0;
  UINT ApiVersion = 0;
  bool IsSoftware = false;
  bool SupportsBC = false;
  float TimestampPeriodNs = 1.0f;
};

struct DEVICE_STATS {
  UINT64 ValidationMessages = 0;  // since device creation
  UINT64 PipelinesCreated = 0;
  UINT64 DescriptorSetsAllocated = 0;
  UINT64 DrawCalls = 0;
  UINT64 RingBytesAllocated = 0;
  UINT64 FramesSubmitted = 0;
  // Added by the Vulkan backend (debug counters for deferred destruction).
  UINT64 ObjectsDestroyed = 0;             // Vulkan handles actually destroyed
  UINT64 DeferredDestructionsPending = 0;  // handles waiting for a frame fence
  UINT64 LiveObjects = 0;                  // API objects (resources, views, states...) alive
};

// ---- Deferred contexts (D3D11_DEVICE_CONTEXT_TYPE) -------------------------
enum DEVICE_CONTEXT_TYPE : uint32_t {
  DEVICE_CONTEXT_IMMEDIATE = 0,
  DEVICE_CONTEXT_DEFERRED = 1,
};
// A call made on the wrong kind of context (FinishCommandList on the
// immediate context, GetData on a deferred one).
inline constexpr HRESULT DXGI_ERROR_INVALID_CALL = static_cast<HRESULT>(0x887A0001u);

}  // namespace d3dl
