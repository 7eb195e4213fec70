// Validation of object creation: descriptions, initial data and the
// resources views are made of (see Validate.h).
#include <cmath>
#include <cstring>

#include "Validate.h"

namespace d3dl::impl {
namespace {
uint32_t FullMipCount(uint32_t w, uint32_t h) {
  uint32_t m = 1;
  while (w > 1 || h > 1) {
    w = std::max(1u, w / 2);
    h = std::max(1u, h / 2);
    ++m;
  }
  return m;
}
bool ValidCompare(COMPARISON_FUNC f) { return f >= COMPARISON_NEVER && f <= COMPARISON_ALWAYS; }
bool ValidBlend(BLEND b) {
  return (b >= BLEND_ZERO && b <= BLEND_SRC_ALPHA_SAT) || b == BLEND_BLEND_FACTOR || b == BLEND_INV_BLEND_FACTOR;
}
bool ValidAddress(TEXTURE_ADDRESS_MODE m) { return m >= TEXTURE_ADDRESS_WRAP && m <= TEXTURE_ADDRESS_MIRROR_ONCE; }
bool ValidBlendOp(BLEND_OP o) { return o >= BLEND_OP_ADD && o <= BLEND_OP_MAX; }
bool ValidStencilOp(STENCIL_OP o) { return o >= STENCIL_OP_KEEP && o <= STENCIL_OP_DECR; }
bool ValidStencilFace(const DEPTH_STENCILOP_DESC& f) {
  return ValidCompare(f.StencilFunc) && ValidStencilOp(f.StencilFailOp) && ValidStencilOp(f.StencilPassOp) &&
         ValidStencilOp(f.StencilDepthFailOp);
}
}  // namespace

bool ValidatePointers(ValidationDevice& dev, const char* fn, const void* desc, const char* descName, const void* out,
                      const char* outName) {
  if (desc && out) return true;
  dev.Log(LogLevel::Error, "%s: %s is null", fn, desc ? outName : descName);
  return false;
}

// ---------------------------------------------------------------------------
// Buffers
namespace {
// SRV/UAV buffers are structured or raw (typed
// buffer views are not supported), DEFAULT or IMMUTABLE (no UAV).
HRESULT ValidateBufferViewFlags(ValidationDevice& dev, const BUFFER_DESC& d) {
  const bool structured = d.MiscFlags & RESOURCE_MISC_BUFFER_STRUCTURED;
  const bool raw = d.MiscFlags & RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS;
  const bool views = d.BindFlags & (BIND_SHADER_RESOURCE | BIND_UNORDERED_ACCESS);
  const char* fn = "CreateBuffer";
  if (structured && raw) {
    dev.Log(LogLevel::Error, "%s: RESOURCE_MISC_BUFFER_STRUCTURED and RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS together", fn);
  } else if (structured && (d.StructureByteStride == 0 || d.StructureByteStride % 4 || d.StructureByteStride > 2048 ||
                            d.ByteWidth % d.StructureByteStride)) {
    dev.Log(LogLevel::Error, "%s: StructureByteStride %u must be a multiple of 4 in 4..2048 dividing ByteWidth %u", fn,
            d.StructureByteStride, d.ByteWidth);
  } else if (raw && d.ByteWidth % 4) {
    dev.Log(LogLevel::Error, "%s: a raw buffer's ByteWidth %u must be a multiple of 4", fn, d.ByteWidth);
  } else if (views && !structured && !raw) {
    dev.Log(LogLevel::Error, "%s: BindFlags 0x%x: buffer views need RESOURCE_MISC_BUFFER_STRUCTURED or _ALLOW_RAW_VIEWS (typed buffer views are not supported)", fn, d.BindFlags);
  } else if (views && d.Usage != USAGE_DEFAULT && d.Usage != USAGE_IMMUTABLE) {
    dev.Log(LogLevel::Error, "%s: buffers with views need USAGE_DEFAULT or USAGE_IMMUTABLE (Usage %u)", fn, d.Usage);
  } else if ((d.BindFlags & BIND_UNORDERED_ACCESS) && d.Usage != USAGE_DEFAULT) {
    dev.Log(LogLevel::Error, "%s: BIND_UNORDERED_ACCESS needs USAGE_DEFAULT (Usage %u)", fn, d.Usage);
  } else if ((d.MiscFlags & RESOURCE_MISC_DRAWINDIRECT_ARGS) &&
             (d.Usage == USAGE_DYNAMIC || d.Usage == USAGE_STAGING || (d.BindFlags & BIND_CONSTANT_BUFFER))) {
    // Argument buffers live in device memory (constant buffers are CPU shadows and ring slices).
    dev.Log(LogLevel::Error, "%s: RESOURCE_MISC_DRAWINDIRECT_ARGS needs USAGE_DEFAULT or USAGE_IMMUTABLE and no BIND_CONSTANT_BUFFER", fn);
  } else {
    return S_OK;
  }
  return E_INVALIDARG;
}

HRESULT ValidateBufferBinding(ValidationDevice& dev, const BUFFER_DESC& d) {
  if (d.BindFlags & (BIND_RENDER_TARGET | BIND_DEPTH_STENCIL)) {
    dev.Log(LogLevel::Error, "CreateBuffer: BindFlags 0x%x: buffer render-target/depth views are not supported", d.BindFlags);
    return E_INVALIDARG;
  }
  const HRESULT views = ValidateBufferViewFlags(dev, d);
  if (FAILED(views)) return views;
  const bool isCB = d.BindFlags & BIND_CONSTANT_BUFFER;
  if (isCB && (d.BindFlags & ~static_cast<UINT>(BIND_CONSTANT_BUFFER))) {
    dev.Log(LogLevel::Error, "CreateBuffer: BIND_CONSTANT_BUFFER cannot be combined with other bind flags (0x%x)", d.BindFlags);
    return E_INVALIDARG;
  }
  if (isCB && (d.ByteWidth % 16 != 0 || d.ByteWidth > 65536 || d.ByteWidth > dev.caps().maxUniformBufferRange)) {
    dev.Log(LogLevel::Error, "CreateBuffer: constant buffer ByteWidth %u must be a multiple of 16 and <= 65536", d.ByteWidth);
    return E_INVALIDARG;
  }
  return S_OK;
}

HRESULT ValidateBufferUsage(ValidationDevice& dev, const BUFFER_DESC& d, const SUBRESOURCE_DATA* init) {
  if (d.Usage > USAGE_STAGING) {
    dev.Log(LogLevel::Error, "CreateBuffer: invalid Usage %u", d.Usage);
    return E_INVALIDARG;
  }
  if (d.Usage == USAGE_IMMUTABLE && (!init || !init->pSysMem)) {
    dev.Log(LogLevel::Error, "CreateBuffer: USAGE_IMMUTABLE needs initial data");
    return E_INVALIDARG;
  }
  if (d.Usage == USAGE_DYNAMIC && !(d.CPUAccessFlags & CPU_ACCESS_WRITE)) {
    dev.Log(LogLevel::Error, "CreateBuffer: USAGE_DYNAMIC needs CPU_ACCESS_WRITE");
    return E_INVALIDARG;
  }
  if (d.Usage == USAGE_STAGING && (d.BindFlags || !d.CPUAccessFlags)) {
    dev.Log(LogLevel::Error, "CreateBuffer: USAGE_STAGING needs BindFlags 0 and CPU access (BindFlags 0x%x)", d.BindFlags);
    return E_INVALIDARG;
  }
  if (d.Usage != USAGE_STAGING && d.Usage != USAGE_DYNAMIC && d.CPUAccessFlags) {
    dev.Log(LogLevel::Error, "CreateBuffer: CPUAccessFlags 0x%x need USAGE_DYNAMIC or USAGE_STAGING", d.CPUAccessFlags);
    return E_INVALIDARG;
  }
  return S_OK;
}
}  // namespace

HRESULT ValidateCreateBuffer(ValidationDevice& dev, const BUFFER_DESC* desc, const SUBRESOURCE_DATA* init, Buffer** out) {
  if (!ValidatePointers(dev, "CreateBuffer", desc, "pDesc", out, "ppBuffer")) return E_INVALIDARG;
  const BUFFER_DESC& d = *desc;
  if (d.ByteWidth == 0) {
    dev.Log(LogLevel::Error, "CreateBuffer: ByteWidth is 0");
    return E_INVALIDARG;
  }
  HRESULT hr = ValidateBufferBinding(dev, d);
  if (SUCCEEDED(hr)) hr = ValidateBufferUsage(dev, d, init);
  if (FAILED(hr)) return hr;
  const bool isCB = d.BindFlags & BIND_CONSTANT_BUFFER;
  const UINT otherUses = BIND_VERTEX_BUFFER | BIND_INDEX_BUFFER | BIND_SHADER_RESOURCE | BIND_UNORDERED_ACCESS;
  if (!isCB && d.Usage != USAGE_STAGING && !(d.BindFlags & otherUses) && !(d.MiscFlags & RESOURCE_MISC_DRAWINDIRECT_ARGS)) {
    dev.Log(LogLevel::Error, "CreateBuffer: BindFlags 0x%x: need a vertex, index, constant, shader-resource or unordered-access binding", d.BindFlags);
    return E_INVALIDARG;
  }
  if (init && !init->pSysMem) {
    dev.Log(LogLevel::Error, "CreateBuffer: pInitialData->pSysMem is null");
    return E_INVALIDARG;
  }
  return S_OK;
}

// ---------------------------------------------------------------------------
// Textures
namespace {
HRESULT ValidateTextureShape(ValidationDevice& dev, const char* fn, bool is1D, TEXTURE2D_DESC& d) {
  const ValidationCaps& caps = dev.caps();
  const uint32_t maxDim = is1D ? caps.maxTexture1D : caps.maxTexture2D;
  if (d.Width == 0 || d.Height == 0 || d.Width > maxDim || d.Height > maxDim) {
    dev.Log(LogLevel::Error, "%s: size %ux%u is invalid (1..%u)", fn, d.Width, d.Height, maxDim);
    return E_INVALIDARG;
  }
  if (d.ArraySize == 0 || d.ArraySize > caps.maxArrayLayers) {
    dev.Log(LogLevel::Error, "%s: ArraySize %u is invalid", fn, d.ArraySize);
    return E_INVALIDARG;
  }
  const FormatInfo* f = GetFormatInfo(d.Format);
  if (!f) {
    dev.Log(LogLevel::Error, "%s: Format %u (%s) is not supported", fn, d.Format, FormatName(d.Format));
    return E_INVALIDARG;
  }
  if (f->bc && !caps.bc) {
    dev.Log(LogLevel::Error, "%s: Format %s: the adapter has no BC support", fn, f->name);
    return DXGI_ERROR_UNSUPPORTED;
  }
  if (f->bc && ((d.Width % 4) || (d.Height % 4)) && !(d.Width < 4 && d.Height < 4)) {
    dev.Log(LogLevel::Error, "%s: %s needs a size multiple of 4 (got %ux%u)", fn, f->name, d.Width, d.Height);
    return E_INVALIDARG;
  }
  const uint32_t full = FullMipCount(d.Width, d.Height);
  if (d.MipLevels == 0) d.MipLevels = full;
  if (d.MipLevels > full) {
    dev.Log(LogLevel::Error, "%s: MipLevels %u exceeds the full chain of %u for %ux%u", fn, d.MipLevels, full, d.Width, d.Height);
    return E_INVALIDARG;
  }
  return S_OK;
}

HRESULT ValidateTextureUsage(ValidationDevice& dev, const char* fn, const TEXTURE2D_DESC& d) {
  if (d.Usage > USAGE_STAGING) {
    dev.Log(LogLevel::Error, "%s: invalid Usage %u", fn, d.Usage);
    return E_INVALIDARG;
  }
  if (d.Usage == USAGE_STAGING) {
    if (d.BindFlags) {
      dev.Log(LogLevel::Error, "%s: USAGE_STAGING textures cannot have BindFlags (0x%x)", fn, d.BindFlags);
      return E_INVALIDARG;
    }
    if (!(d.CPUAccessFlags & (CPU_ACCESS_READ | CPU_ACCESS_WRITE))) {
      dev.Log(LogLevel::Error, "%s: USAGE_STAGING needs CPUAccessFlags", fn);
      return E_INVALIDARG;
    }
  } else if (d.Usage == USAGE_DYNAMIC) {
    if (!(d.CPUAccessFlags & CPU_ACCESS_WRITE) || (d.CPUAccessFlags & CPU_ACCESS_READ)) {
      dev.Log(LogLevel::Error, "%s: USAGE_DYNAMIC needs CPUAccessFlags = CPU_ACCESS_WRITE (0x%x)", fn, d.CPUAccessFlags);
      return E_INVALIDARG;
    }
  } else if (d.CPUAccessFlags) {
    dev.Log(LogLevel::Error, "%s: CPUAccessFlags 0x%x need USAGE_DYNAMIC or USAGE_STAGING", fn, d.CPUAccessFlags);
    return E_INVALIDARG;
  }
  return S_OK;
}

HRESULT ValidateTextureBinding(ValidationDevice& dev, const char* fn, const TEXTURE2D_DESC& d) {
  const FormatInfo* f = GetFormatInfo(d.Format);
  if (d.BindFlags & (BIND_VERTEX_BUFFER | BIND_INDEX_BUFFER | BIND_CONSTANT_BUFFER)) {
    dev.Log(LogLevel::Error, "%s: BindFlags 0x%x include buffer bindings", fn, d.BindFlags);
    return E_INVALIDARG;
  }
  if ((d.BindFlags & BIND_UNORDERED_ACCESS) && (f->depth || (d.BindFlags & BIND_DEPTH_STENCIL) || d.Usage != USAGE_DEFAULT)) {
    dev.Log(LogLevel::Error, "%s: BIND_UNORDERED_ACCESS needs a USAGE_DEFAULT colour texture", fn);
    return E_INVALIDARG;
  }
  if ((d.BindFlags & BIND_DEPTH_STENCIL) && (d.BindFlags & BIND_RENDER_TARGET)) {
    dev.Log(LogLevel::Error, "%s: BIND_DEPTH_STENCIL and BIND_RENDER_TARGET together", fn);
    return E_INVALIDARG;
  }
  if ((d.BindFlags & BIND_DEPTH_STENCIL) && DepthImageFormat(*f) == VK_FORMAT_UNDEFINED) {
    dev.Log(LogLevel::Error, "%s: BIND_DEPTH_STENCIL needs D32_FLOAT, R32_TYPELESS, D24_UNORM_S8_UINT or R24G8_TYPELESS (got %s)", fn, f->name);
    return E_INVALIDARG;
  }
  if (f->family == DXGI_FORMAT_R24G8_TYPELESS && !(d.BindFlags & BIND_DEPTH_STENCIL)) {
    dev.Log(LogLevel::Error, "%s: %s textures need BIND_DEPTH_STENCIL (packed depth-stencil has no colour or staging form here)", fn, f->name);
    return E_INVALIDARG;
  }
  if (f->depth && (d.BindFlags & BIND_RENDER_TARGET)) {
    dev.Log(LogLevel::Error, "%s: %s cannot be a render target", fn, f->name);
    return E_INVALIDARG;
  }
  if ((d.MiscFlags & RESOURCE_MISC_GENERATE_MIPS) &&
      (d.BindFlags & (BIND_RENDER_TARGET | BIND_SHADER_RESOURCE)) != (BIND_RENDER_TARGET | BIND_SHADER_RESOURCE)) {
    dev.Log(LogLevel::Error, "%s: RESOURCE_MISC_GENERATE_MIPS needs BIND_RENDER_TARGET | BIND_SHADER_RESOURCE", fn);
    return E_INVALIDARG;
  }
  if (d.Usage != USAGE_STAGING && !dev.CheckFormatSupport(d.Format, d.BindFlags)) {
    dev.Log(LogLevel::Error, "%s: Format %s does not support BindFlags 0x%x on this adapter", fn, f->name, d.BindFlags);
    return E_INVALIDARG;
  }
  return S_OK;
}

// One entry per subresource with data; rows at least as long as the mip's.
HRESULT ValidateInitialData(ValidationDevice& dev, const char* fn, const TEXTURE2D_DESC& d, const SUBRESOURCE_DATA* init) {
  if (d.Usage == USAGE_IMMUTABLE && !init) {
    dev.Log(LogLevel::Error, "%s: USAGE_IMMUTABLE needs initial data", fn);
    return E_INVALIDARG;
  }
  if (!init) return S_OK;
  const uint32_t subCount = d.MipLevels * d.ArraySize;
  for (uint32_t i = 0; i < subCount; ++i)
    if (!init[i].pSysMem) {
      dev.Log(LogLevel::Error, "%s: pInitialData[%u].pSysMem is null", fn, i);
      return E_INVALIDARG;
    }
  if (d.Usage == USAGE_STAGING) return S_OK;  // staging copies take the pitch as given
  const FormatInfo& f = *GetFormatInfo(d.Format);
  for (uint32_t i = 0; i < subCount; ++i) {
    const uint32_t m = i % d.MipLevels;
    const uint32_t pitch = LinearLayout(f, std::max(1u, d.Width >> m), std::max(1u, d.Height >> m)).rowPitch;
    const uint32_t srcPitch = init[i].SysMemPitch ? init[i].SysMemPitch : pitch;
    if (srcPitch < pitch) {
      dev.Log(LogLevel::Error, "%s: pInitialData[%u].SysMemPitch %u is smaller than a row (%u bytes)", fn, i, srcPitch, pitch);
      return E_INVALIDARG;
    }
  }
  return S_OK;
}
}  // namespace

// ---- Cube maps and multisampled textures.
static HRESULT ValidateCubeDesc(ValidationDevice& dev, const char* fn, bool is1D, const TEXTURE2D_DESC& d) {
  if (!(d.MiscFlags & RESOURCE_MISC_TEXTURECUBE)) return S_OK;
  if (is1D || d.ArraySize == 0 || d.ArraySize % 6 != 0 || d.Width != d.Height || d.SampleDesc.Count != 1) {
    dev.Log(LogLevel::Error, "%s: RESOURCE_MISC_TEXTURECUBE needs a square single-sampled Texture2D with ArraySize 6*n (got %ux%u, ArraySize %u, SampleDesc.Count %u)",
            fn, d.Width, d.Height, d.ArraySize, d.SampleDesc.Count);
    return E_INVALIDARG;
  }
  return S_OK;
}

static HRESULT ValidateMultisampleDesc(ValidationDevice& dev, const char* fn, bool is1D, const TEXTURE2D_DESC& d,
                                const SUBRESOURCE_DATA* init) {
  const UINT n = d.SampleDesc.Count;
  const char* problem = nullptr;
  if (n == 0 || (n & (n - 1)) || n > 32) problem = "must be 1, 2, 4, 8, 16 or 32";
  else if (n == 1 && d.SampleDesc.Quality != 0) problem = "Quality must be 0";
  const bool standard = d.SampleDesc.Quality == STANDARD_MULTISAMPLE_PATTERN;  // Vulkan's only pattern
  if (problem || n == 1) {
    if (problem) dev.Log(LogLevel::Error, "%s: SampleDesc.Count %u / Quality %u: %s", fn, n, d.SampleDesc.Quality, problem);
    return problem ? E_INVALIDARG : S_OK;
  }
  UINT levels = 0;
  if (is1D) problem = "1-D textures cannot be multisampled";
  else if (d.MipLevels != 1) problem = "multisampled textures have exactly one mip (MipLevels 1)";
  else if (d.Usage != USAGE_DEFAULT) problem = "multisampled textures must be USAGE_DEFAULT";
  else if (init) problem = "multisampled textures cannot have initial data";
  else if (!(d.BindFlags & (BIND_RENDER_TARGET | BIND_DEPTH_STENCIL))) problem = "multisampled textures need BIND_RENDER_TARGET or BIND_DEPTH_STENCIL";
  else if (d.MiscFlags & RESOURCE_MISC_GENERATE_MIPS) problem = "RESOURCE_MISC_GENERATE_MIPS is not allowed";
  else if (FAILED(dev.CheckMultisampleQualityLevels(d.Format, n, &levels)) || levels == 0) problem = "not supported for this format on this adapter (CheckMultisampleQualityLevels)";
  else if (d.SampleDesc.Quality >= levels && !standard) problem = "Quality must be 0 or STANDARD_MULTISAMPLE_PATTERN";
  else if ((d.BindFlags & BIND_SHADER_RESOURCE) && !(dev.SampledSampleCounts(d) & n)) problem = "cannot be sampled (TEXTURE2DMS) with this format on this adapter";
  if (!problem) return S_OK;
  dev.Log(LogLevel::Error, "%s: SampleDesc.Count %u (%s, MipLevels %u): %s", fn, n, FormatName(d.Format), d.MipLevels, problem);
  return E_INVALIDARG;
}

HRESULT ValidateCreateTexture(ValidationDevice& dev, const char* fn, bool is1D, const SUBRESOURCE_DATA* init,
                              TEXTURE2D_DESC* desc) {
  if (is1D && (desc->BindFlags & BIND_DEPTH_STENCIL)) {
    dev.Log(LogLevel::Error, "CreateTexture1D: BIND_DEPTH_STENCIL is not supported for 1-D textures");
    return E_INVALIDARG;
  }
  HRESULT hr = ValidateTextureShape(dev, fn, is1D, *desc);
  if (SUCCEEDED(hr)) hr = ValidateTextureUsage(dev, fn, *desc);
  if (SUCCEEDED(hr)) hr = ValidateTextureBinding(dev, fn, *desc);
  if (SUCCEEDED(hr)) hr = ValidateCubeDesc(dev, fn, is1D, *desc);
  if (SUCCEEDED(hr)) hr = ValidateMultisampleDesc(dev, fn, is1D, *desc, init);
  if (SUCCEEDED(hr)) hr = ValidateInitialData(dev, fn, *desc, init);
  return hr;
}

// ---------------------------------------------------------------------------
// ---------------------------------------------------------------------------
// Buffer and texture UAVs, buffer SRVs
HRESULT BufferSrvRequest(ValidationDevice& dev, const SHADER_RESOURCE_VIEW_DESC* desc, BufferViewRequest* req) {
  if (!desc) return S_OK;
  if (desc->ViewDimension != SRV_DIMENSION_BUFFEREX && desc->ViewDimension != SRV_DIMENSION_BUFFER) {
    dev.Log(LogLevel::Error, "%s: ViewDimension %u does not match a buffer (SRV_DIMENSION_BUFFEREX)", kSrvKind.fn,
            desc->ViewDimension);
    return E_INVALIDARG;
  }
  const BUFFEREX_SRV& e = desc->BufferEx;
  *req = {desc->Format, e.FirstElement, e.NumElements, e.Flags & ~UINT(BUFFEREX_SRV_FLAG_RAW),
          (e.Flags & BUFFEREX_SRV_FLAG_RAW) != 0};
  return S_OK;
}

HRESULT BufferUavRequest(ValidationDevice& dev, const UNORDERED_ACCESS_VIEW_DESC* desc, BufferViewRequest* req) {
  if (!desc) return S_OK;
  if (desc->ViewDimension != UAV_DIMENSION_BUFFER) {
    dev.Log(LogLevel::Error, "%s: ViewDimension %u does not match a buffer (UAV_DIMENSION_BUFFER)", kUavKind.fn,
            desc->ViewDimension);
    return E_INVALIDARG;
  }
  const BUFFER_UAV& u = desc->Buffer;
  *req = {desc->Format, u.FirstElement, u.NumElements, u.Flags & ~UINT(BUFFER_UAV_FLAG_RAW),
          (u.Flags & BUFFER_UAV_FLAG_RAW) != 0};
  return S_OK;
}

HRESULT ValidateBufferView(ValidationDevice& dev, const ViewKindInfo& kind, const ResourceInfo& d, const void* out,
                           const BufferViewRequest* req, UINT64* offset, UINT64* range) {
  const char* fn = kind.fn;
  if (!out || !d.IsBuffer()) {
    dev.Log(LogLevel::Error, "%s: %s is null", fn, out ? "pResource" : kind.outName);
    return E_INVALIDARG;
  }
  const bool structured = d.miscFlags & RESOURCE_MISC_BUFFER_STRUCTURED;
  if (!(d.bindFlags & kind.bind)) {
    dev.Log(LogLevel::Error, "%s: the buffer was not created with %s (BindFlags 0x%x)", fn, kind.bindName, d.bindFlags);
    return E_INVALIDARG;
  }
  if (!req && !structured) {
    dev.Log(LogLevel::Error, "%s: a view of a raw buffer needs a description (R32_TYPELESS, RAW flag)", fn);
    return E_INVALIDARG;
  }
  const BufferViewRequest whole{DXGI_FORMAT_UNKNOWN, 0, d.byteWidth / std::max(1u, d.structureStride), 0, false};
  const BufferViewRequest& q = req ? *req : whole;
  const UINT extraFlags = q.flags & ~1u;  // anything but RAW: append/consume counters
  if (extraFlags) {
    dev.Log(LogLevel::Error, "%s: Flags 0x%x: append/consume counters are not supported", fn, q.flags);
    return E_NOTIMPL;
  }
  if (q.raw != (q.format == DXGI_FORMAT_R32_TYPELESS) || (q.raw && !(d.miscFlags & RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS)) ||
      (!q.raw && (!structured || q.format != DXGI_FORMAT_UNKNOWN))) {
    dev.Log(LogLevel::Error, "%s: Format %s with Flags 0x%x does not fit the buffer (raw views: R32_TYPELESS + RAW flag + RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS; structured: UNKNOWN + RESOURCE_MISC_BUFFER_STRUCTURED; typed buffer views are not supported)",
            fn, FormatName(q.format), q.flags);
    return E_INVALIDARG;
  }
  const uint64_t element = q.raw ? 4 : d.structureStride;
  const uint64_t end = (uint64_t(q.first) + q.num) * element;
  const uint64_t align = dev.caps().storageBufferAlign;
  if (q.num == 0 || end > d.byteWidth) {
    dev.Log(LogLevel::Error, "%s: elements [%u, %u + %u) out of range (%llu elements)", fn, q.first, q.first, q.num,
            static_cast<unsigned long long>(d.byteWidth / element));
    return E_INVALIDARG;
  }
  if ((q.first * element) % align) {
    dev.Log(LogLevel::Error, "%s: FirstElement %u starts at byte %llu, not a multiple of the adapter's storage alignment %llu",
            fn, q.first, static_cast<unsigned long long>(q.first * element), static_cast<unsigned long long>(align));
    return E_INVALIDARG;
  }
  *offset = q.first * element;
  *range = q.num * element;
  return S_OK;
}

HRESULT ValidateTextureUav(ValidationDevice& dev, const ResourceInfo& t, const UNORDERED_ACCESS_VIEW_DESC* desc,
                           const void* out, ViewFormat* format, uint32_t* mip) {
  const char* fn = kUavKind.fn;
  HRESULT hr = ValidateViewResource(dev, kUavKind, t, out, desc ? desc->Format : DXGI_FORMAT_UNKNOWN, format);
  if (FAILED(hr)) return hr;
  *mip = desc ? desc->Texture2D.MipSlice : 0;
  if (t.dimension != RESOURCE_DIMENSION_TEXTURE2D || t.arraySize != 1 ||
      (desc && desc->ViewDimension != UAV_DIMENSION_TEXTURE2D && desc->ViewDimension != UAV_DIMENSION_UNKNOWN)) {
    dev.Log(LogLevel::Error, "%s: only UAVs of single 2-D textures are supported (ViewDimension %u)", fn,
            desc ? desc->ViewDimension : 0u);
    return E_INVALIDARG;
  }
  if (!dev.CheckFormatSupport(format->format, BIND_UNORDERED_ACCESS)) {
    dev.Log(LogLevel::Error, "%s: Format %s cannot be written as a UAV on this adapter", fn, FormatName(format->format));
    return E_INVALIDARG;
  }
  if (*mip >= t.mipLevels) {
    dev.Log(LogLevel::Error, "%s: MipSlice %u out of range (%u mips)", fn, *mip, t.mipLevels);
    return E_INVALIDARG;
  }
  return S_OK;
}

// ---------------------------------------------------------------------------
// Pipeline state objects, shaders, queries, swap chains
HRESULT ValidateSamplerDesc(ValidationDevice& dev, const SAMPLER_DESC* desc, SamplerState** out) {
  const char* fn = "CreateSamplerState";
  if (!ValidatePointers(dev, fn, desc, "pSamplerDesc", out, "ppSamplerState")) return E_INVALIDARG;
  const SAMPLER_DESC& d = *desc;
  // D3D11 FILTER bits: mip (bits 0-1), mag (2-3), min (4-5), anisotropic 0x40,
  // reduction (7-8): 0 standard, 1 comparison, 2 minimum, 3 maximum.
  const uint32_t f = d.Filter;
  const bool anisotropic = (f & 0x40) != 0;
  const uint32_t reduction = (f >> 7) & 3;
  if (f & ~0x1D5u) {
    dev.Log(LogLevel::Error, "%s: Filter 0x%x is not a D3D11 filter", fn, f);
  } else if (anisotropic && (f & 0x15) != 0x15) {
    dev.Log(LogLevel::Error, "%s: Filter 0x%x: anisotropic filters need linear min/mag/mip bits", fn, f);
  } else if (!ValidAddress(d.AddressU) || !ValidAddress(d.AddressV) || !ValidAddress(d.AddressW)) {
    dev.Log(LogLevel::Error, "%s: invalid address mode (U %u, V %u, W %u)", fn, d.AddressU, d.AddressV, d.AddressW);
  } else if (!std::isfinite(d.MipLODBias) || d.MipLODBias < -16.0f || d.MipLODBias > 15.99f) {
    dev.Log(LogLevel::Error, "%s: MipLODBias %g out of range [-16, 15.99]", fn, d.MipLODBias);
  } else if (anisotropic && (d.MaxAnisotropy < 1 || d.MaxAnisotropy > 16)) {
    dev.Log(LogLevel::Error, "%s: MaxAnisotropy %u out of range [1, 16]", fn, d.MaxAnisotropy);
  } else if (reduction == 1 && !ValidCompare(d.ComparisonFunc)) {
    dev.Log(LogLevel::Error, "%s: ComparisonFunc %u is invalid", fn, d.ComparisonFunc);
  } else if (reduction >= 2 && !dev.caps().minmax) {
    dev.Log(LogLevel::Error, "%s: Filter 0x%x needs min/max reduction (samplerFilterMinmax), which this adapter lacks", fn, f);
  } else if (std::isnan(d.MinLOD) || std::isnan(d.MaxLOD) || d.MinLOD > d.MaxLOD) {
    dev.Log(LogLevel::Error, "%s: MinLOD %g > MaxLOD %g", fn, d.MinLOD, d.MaxLOD);
  } else {
    return S_OK;
  }
  return E_INVALIDARG;
}

HRESULT ValidateBlendDesc(ValidationDevice& dev, const BLEND_DESC* desc, BlendState** out) {
  const char* fn = "CreateBlendState";
  if (!ValidatePointers(dev, fn, desc, "pBlendStateDesc", out, "ppBlendState")) return E_INVALIDARG;
  const uint32_t n = desc->IndependentBlendEnable ? SIMULTANEOUS_RENDER_TARGET_COUNT : 1;
  for (uint32_t i = 0; i < n; ++i) {
    const auto& r = desc->RenderTarget[i];
    if (!ValidBlend(r.SrcBlend) || !ValidBlend(r.DestBlend) || !ValidBlend(r.SrcBlendAlpha) ||
        !ValidBlend(r.DestBlendAlpha) || !ValidBlendOp(r.BlendOp) || !ValidBlendOp(r.BlendOpAlpha)) {
      dev.Log(LogLevel::Error, "%s: RenderTarget[%u] has an invalid blend factor or op", fn, i);
      return E_INVALIDARG;
    }
    // Vulkan without independentBlend needs every attachment's state equal.
    if (i > 0 && !dev.caps().independentBlend &&
        std::memcmp(&r, &desc->RenderTarget[0], sizeof(r)) != 0) {
      dev.Log(LogLevel::Error, "%s: RenderTarget[%u] differs from RenderTarget[0] with IndependentBlendEnable, but the adapter lacks independentBlend", fn, i);
      return DXGI_ERROR_UNSUPPORTED;
    }
  }
  return S_OK;
}

HRESULT ValidateDepthStencilDesc(ValidationDevice& dev, const DEPTH_STENCIL_DESC* desc, DepthStencilState** out) {
  const char* fn = "CreateDepthStencilState";
  if (!ValidatePointers(dev, fn, desc, "pDepthStencilDesc", out, "ppDepthStencilState")) return E_INVALIDARG;
  const auto& d = *desc;
  if (!ValidCompare(d.DepthFunc) || d.DepthWriteMask > DEPTH_WRITE_MASK_ALL || !ValidStencilFace(d.FrontFace) ||
      !ValidStencilFace(d.BackFace)) {
    dev.Log(LogLevel::Error, "%s: invalid DepthFunc %u / DepthWriteMask %u / stencil ops", fn, d.DepthFunc, d.DepthWriteMask);
    return E_INVALIDARG;
  }
  return S_OK;
}

HRESULT ValidateRasterizerDesc(ValidationDevice& dev, const RASTERIZER_DESC* desc, RasterizerState** out) {
  const char* fn = "CreateRasterizerState";
  if (!ValidatePointers(dev, fn, desc, "pRasterizerDesc", out, "ppRasterizerState")) return E_INVALIDARG;
  const auto& d = *desc;
  if (d.FillMode != FILL_SOLID && d.FillMode != FILL_WIREFRAME) {
    dev.Log(LogLevel::Error, "%s: FillMode %u is invalid", fn, d.FillMode);
    return E_INVALIDARG;
  }
  if (d.CullMode < CULL_NONE || d.CullMode > CULL_BACK) {
    dev.Log(LogLevel::Error, "%s: CullMode %u is invalid", fn, d.CullMode);
    return E_INVALIDARG;
  }
  if (d.FillMode == FILL_WIREFRAME && !dev.caps().fillNonSolid) {
    dev.Log(LogLevel::Error, "%s: FILL_WIREFRAME needs fillModeNonSolid", fn);
    return DXGI_ERROR_UNSUPPORTED;
  }
  return S_OK;
}

HRESULT ValidateShaderBytecode(ValidationDevice& dev, const char* fn, const void* code, size_t len, const void* out) {
  if (!ValidatePointers(dev, fn, code, "pShaderBytecode", out, "ppShader")) return E_INVALIDARG;
  if (len < 20 || len % 4 != 0) {
    dev.Log(LogLevel::Error, "%s: bytecode length %zu is not SPIR-V (a multiple of 4, at least 20)", fn, len);
    return E_INVALIDARG;
  }
  return S_OK;
}

HRESULT ValidateCreateQuery(ValidationDevice& dev, const QUERY_DESC* desc, Query** out) {
  if (!ValidatePointers(dev, "CreateQuery", desc, "pQueryDesc", out, "ppQuery")) return E_INVALIDARG;
  if (desc->Query != QUERY_EVENT && desc->Query != QUERY_TIMESTAMP && desc->Query != QUERY_TIMESTAMP_DISJOINT &&
      desc->Query != QUERY_PIPELINE_STATISTICS) {
    dev.Log(LogLevel::Error, "CreateQuery: query type %u is not supported", desc->Query);
    return E_INVALIDARG;
  }
  if (desc->Query == QUERY_PIPELINE_STATISTICS && !dev.caps().pipelineStatistics) {
    dev.Log(LogLevel::Error, "CreateQuery: QUERY_PIPELINE_STATISTICS needs pipelineStatisticsQuery, which the adapter %s lacks",
            dev.caps().adapterName);
    return E_NOTIMPL;
  }
  return S_OK;
}

HRESULT ValidateHeadlessSwapChain(ValidationDevice& dev, const SWAP_CHAIN_DESC& d) {
  if (d.Width == 0 || d.Height == 0 || d.BufferCount == 0 || d.BufferCount > 16) {
    dev.Log(LogLevel::Error, "CreateHeadlessSwapChain: size %ux%u / BufferCount %u invalid (a headless swap chain needs an explicit size, 1..16 buffers)", d.Width, d.Height, d.BufferCount);
    return E_INVALIDARG;
  }
  if (!dev.CheckFormatSupport(d.Format, BIND_RENDER_TARGET | BIND_SHADER_RESOURCE)) {
    dev.Log(LogLevel::Error, "CreateHeadlessSwapChain: Format %s cannot be a render target", FormatName(d.Format));
    return E_INVALIDARG;
  }
  return S_OK;
}

}  // namespace d3dl::impl
