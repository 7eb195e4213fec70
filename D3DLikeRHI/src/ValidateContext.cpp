// Validation of context calls: slot ranges and bind flags of the setters,
// clears, Map, UpdateSubresource, copies, queries, deferred contexts and UAVs
// (see Validate.h; blits in ValidateBlit.cpp).
#include <cstdlib>
#include <cstring>

#include "Topology.h"
#include "Validate.h"

namespace d3dl::impl {

bool ValidateSlots(ValidationDevice& dev, const char* stage, const char* fn, UINT start, UINT num, UINT count) {
  if (start < count && num <= count - start) return true;
  dev.Log(LogLevel::Error, "%s%s: slots %u..%u out of range (0..%u)", stage, fn, start, start + num, count - 1);
  return false;
}

bool ValidateVertexBuffer(ValidationDevice& dev, const BUFFER_DESC* desc, UINT slot) {
  if (!desc || (desc->BindFlags & BIND_VERTEX_BUFFER)) return true;
  dev.Log(LogLevel::Error, "IASetVertexBuffers: buffer in slot %u lacks BIND_VERTEX_BUFFER; unbound", slot);
  return false;
}

bool ValidateConstantBuffer(ValidationDevice& dev, ShaderStage stage, const BUFFER_DESC* desc, UINT slot) {
  if (!desc || (desc->BindFlags & BIND_CONSTANT_BUFFER)) return true;
  dev.Log(LogLevel::Error, "%sSetConstantBuffers: buffer in slot %u lacks BIND_CONSTANT_BUFFER; unbound",
          StagePrefix(stage), slot);
  return false;
}

bool ValidateIndexBuffer(ValidationDevice& dev, const BUFFER_DESC* desc, DXGI_FORMAT format) {
  if (desc && !(desc->BindFlags & BIND_INDEX_BUFFER)) {
    dev.Log(LogLevel::Error, "IASetIndexBuffer: buffer lacks BIND_INDEX_BUFFER; unbound");
    return false;
  }
  if (desc && format != DXGI_FORMAT_R16_UINT && format != DXGI_FORMAT_R32_UINT) {
    dev.Log(LogLevel::Error, "IASetIndexBuffer: Format %s is not R16_UINT or R32_UINT; unbound", FormatName(format));
    return false;
  }
  return true;
}

bool ValidateViewports(ValidationDevice& dev, UINT num, const VIEWPORT* viewports) {
  if (num && !viewports) {
    dev.Log(LogLevel::Error, "RSSetViewports: pViewports is null");
    return false;
  }
  if (num > 1) dev.Log(LogLevel::Warning, "RSSetViewports: %u viewports; only the first is used", num);
  return true;
}

bool ValidateScissorRects(ValidationDevice& dev, UINT num, const RECT* rects) {
  if (!num || rects) return true;
  dev.Log(LogLevel::Error, "RSSetScissorRects: pRects is null");
  return false;
}

bool ValidateRenderTargets(ValidationDevice& dev, UINT num, RenderTargetView* const* rtvs) {
  if (num <= SIMULTANEOUS_RENDER_TARGET_COUNT && (!num || rtvs)) return true;
  dev.Log(LogLevel::Error, "OMSetRenderTargets: %u views (at most 8, array required)", num);
  return false;
}

// D3D11: every bound view has the same sample count (one rasterization rate).
bool ValidateTargetSamples(ValidationDevice& dev, UINT num, const UINT* rtvSamples, UINT dsvSamples) {
  uint32_t samples = dsvSamples;
  for (UINT i = 0; i < num; ++i) {
    if (!rtvSamples[i]) continue;
    const uint32_t n = rtvSamples[i];
    if (samples && n != samples) {
      dev.Log(LogLevel::Error, "OMSetRenderTargets: render target %u has SampleDesc.Count %u, another bound view %u", i, n, samples);
      return false;
    }
    samples = n;
  }
  return true;
}

// ---------------------------------------------------------------------------
bool ValidateClearRenderTargetView(ValidationDevice& dev, RenderTargetView* rtv, const float color[4]) {
  if (rtv && color) return true;
  dev.Log(LogLevel::Error, "ClearRenderTargetView: %s is null", rtv ? "ColorRGBA" : "pRenderTargetView");
  return false;
}

bool ValidateClearDepthStencilView(ValidationDevice& dev, DepthStencilView* dsv) {
  if (dsv) return true;
  dev.Log(LogLevel::Error, "ClearDepthStencilView: pDepthStencilView is null");
  return false;
}

bool ValidateClearView(ValidationDevice& dev, const View* view, bool renderTarget, const float color[4],
                       const RECT* rects, UINT numRects) {
  if (!view || !color || (numRects && !rects)) {
    dev.Log(LogLevel::Error, "ClearView: %s is null", !view ? "pView" : !color ? "Color" : "pRect");
    return false;
  }
  if (!renderTarget) dev.Log(LogLevel::Error, "ClearView: only render-target views are supported");
  return renderTarget;
}

// ---------------------------------------------------------------------------
// Map
namespace {
bool CpuAccessAllows(MAP type, UINT cpuAccess) {
  const bool reads = type == MAP_READ || type == MAP_READ_WRITE;
  return !(reads && !(cpuAccess & CPU_ACCESS_READ)) && !(type != MAP_READ && !(cpuAccess & CPU_ACCESS_WRITE));
}

HRESULT ValidateCpuAccess(ValidationDevice& dev, MAP type, UINT cpuAccess) {
  if (CpuAccessAllows(type, cpuAccess)) return S_OK;
  dev.Log(LogLevel::Error, "Map: MapType %u does not match CPUAccessFlags 0x%x", type, cpuAccess);
  return E_INVALIDARG;
}

HRESULT ValidateMapBuffer(ValidationDevice& dev, const ResourceInfo& b, UINT sub, MAP type) {
  if (sub != 0) {
    dev.Log(LogLevel::Error, "Map: buffers have one subresource (got %u)", sub);
    return E_INVALIDARG;
  }
  const bool dynamic = b.usage == USAGE_DYNAMIC;
  if (b.IsConstantBuffer()) {
    if (type != MAP_READ && type != MAP_READ_WRITE && dynamic) return S_OK;
    dev.Log(LogLevel::Error, "Map: a constant buffer can be mapped only with WRITE_DISCARD and USAGE_DYNAMIC");
    return E_INVALIDARG;
  }
  if (dynamic) {
    if (type == MAP_WRITE_DISCARD || type == MAP_WRITE_NO_OVERWRITE) return S_OK;
    dev.Log(LogLevel::Error, "Map: USAGE_DYNAMIC buffers accept WRITE_DISCARD or WRITE_NO_OVERWRITE only (got %u)", type);
    return E_INVALIDARG;
  }
  if (b.usage == USAGE_STAGING) return ValidateCpuAccess(dev, type, b.cpuAccessFlags);
  dev.Log(LogLevel::Error, "Map: only DYNAMIC or STAGING buffers can be mapped");
  return E_INVALIDARG;
}

HRESULT ValidateMapTexture(ValidationDevice& dev, const ResourceInfo& t, UINT sub, MAP type) {
  UINT mip, layer;
  if (!t.IsTexture() || !t.DecodeSub(sub, &mip, &layer)) {
    dev.Log(LogLevel::Error, "Map: subresource %u out of range", sub);
    return E_INVALIDARG;
  }
  if (t.usage == USAGE_STAGING) return ValidateCpuAccess(dev, type, t.cpuAccessFlags);
  if (t.usage == USAGE_DYNAMIC) {
    if (type == MAP_WRITE_DISCARD) return S_OK;
    dev.Log(LogLevel::Error, "Map: DYNAMIC textures accept WRITE_DISCARD only (got %u)", type);
    return E_INVALIDARG;
  }
  dev.Log(LogLevel::Error, "Map: only DYNAMIC or STAGING textures can be mapped");
  return E_INVALIDARG;
}
}  // namespace

HRESULT ValidateMap(ValidationDevice& dev, const ResourceInfo& r, UINT sub, MAP type, const MAPPED_SUBRESOURCE* mapped) {
  if (r.dimension == RESOURCE_DIMENSION_UNKNOWN || !mapped) {
    dev.Log(LogLevel::Error, "Map: %s is null", r.dimension != RESOURCE_DIMENSION_UNKNOWN ? "pMappedResource" : "pResource");
    return E_INVALIDARG;
  }
  if (type < MAP_READ || type > MAP_WRITE_NO_OVERWRITE) {
    dev.Log(LogLevel::Error, "Map: invalid MapType %u", type);
    return E_INVALIDARG;
  }
  if (r.IsBuffer()) return ValidateMapBuffer(dev, r, sub, type);
  return ValidateMapTexture(dev, r, sub, type);
}

// ---------------------------------------------------------------------------
// UpdateSubresource
namespace {
bool ValidateUpdateBuffer(ValidationDevice& dev, const ResourceInfo& b, UINT sub, const BOX* box, BOX* region) {
  const UINT width = b.byteWidth;
  const UINT lo = box ? box->left : 0, hi = box ? box->right : width;
  if (sub != 0 || hi > width || lo > hi) {
    dev.Log(LogLevel::Error, "UpdateSubresource: range [%u, %u) outside the buffer (%u bytes)", lo, hi, width);
    return false;
  }
  if (lo == hi) return false;
  if (b.usage == USAGE_IMMUTABLE || b.usage == USAGE_DYNAMIC) {
    dev.Log(LogLevel::Error, "UpdateSubresource: buffer Usage %u cannot be updated (use Map for DYNAMIC)", b.usage);
    return false;
  }
  *region = BOX{lo, 0, 0, hi, 1, 1};
  return true;
}

bool ValidateUpdateTexture(ValidationDevice& dev, const ResourceInfo& t, UINT sub, const BOX* box, UINT rowPitch,
                           BOX* region) {
  UINT mip, layer;
  if (!t.DecodeSub(sub, &mip, &layer)) {
    dev.Log(LogLevel::Error, "UpdateSubresource: subresource %u out of range", sub);
    return false;
  }
  const uint32_t mw = t.MipWidth(mip), mh = t.MipHeight(mip);
  const BOX b = box ? *box : BOX{0, 0, 0, mw, mh, 1};
  if (b.right > mw || b.bottom > mh || b.left >= b.right || b.top >= b.bottom) {
    if (box && (b.left >= b.right || b.top >= b.bottom)) return false;  // empty box: no-op, as D3D
    dev.Log(LogLevel::Error, "UpdateSubresource: box (%u,%u)-(%u,%u) outside mip %u (%ux%u)", b.left, b.top, b.right,
            b.bottom, mip, mw, mh);
    return false;
  }
  const FormatInfo& f = *GetFormatInfo(t.format);
  if (f.bc && ((b.left % 4) || (b.top % 4))) {
    dev.Log(LogLevel::Error, "UpdateSubresource: box of a block-compressed texture must be 4-aligned");
    return false;
  }
  const uint32_t pitch = LinearLayout(f, b.right - b.left, b.bottom - b.top).rowPitch;
  if (rowPitch != 0 && rowPitch < pitch) {
    dev.Log(LogLevel::Error, "UpdateSubresource: SrcRowPitch %u is smaller than a row (%u bytes)", rowPitch, pitch);
    return false;
  }
  *region = b;
  return true;
}
}  // namespace

bool ValidateUpdateSubresource(ValidationDevice& dev, const ResourceInfo& dst, UINT sub, const BOX* box, const void* data,
                               UINT rowPitch, BOX* region) {
  if (dst.dimension == RESOURCE_DIMENSION_UNKNOWN || !data) {
    dev.Log(LogLevel::Error, "UpdateSubresource: %s is null",
            dst.dimension != RESOURCE_DIMENSION_UNKNOWN ? "pSrcData" : "pDstResource");
    return false;
  }
  if (dst.IsBuffer()) return ValidateUpdateBuffer(dev, dst, sub, box, region);
  if (dst.usage == USAGE_IMMUTABLE || dst.usage == USAGE_DYNAMIC) {
    dev.Log(LogLevel::Error, "UpdateSubresource: texture Usage %u cannot be updated", dst.usage);
    return false;
  }
  return ValidateUpdateTexture(dev, dst, sub, box, rowPitch, region);
}

// ---------------------------------------------------------------------------
// Copies
namespace {
bool ValidateCopyBufferRegion(ValidationDevice& dev, const ResourceInfo& dst, UINT dstX, const ResourceInfo& src,
                              const BOX* box) {
  const UINT lo = box ? box->left : 0, hi = box ? box->right : src.byteWidth;
  if (lo >= hi || hi > src.byteWidth || dstX + (hi - lo) > dst.byteWidth) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: buffer range [%u, %u) -> %u out of bounds", lo, hi, dstX);
    return false;
  }
  const bool writable = !dst.IsConstantBuffer() && dst.usage != USAGE_DYNAMIC && dst.usage != USAGE_IMMUTABLE;
  if (!writable) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: the destination buffer must be DEFAULT or STAGING (not a constant, dynamic or immutable buffer)");
    return false;
  }
  return true;
}

bool CopyCompatible(const ResourceInfo& dst, const ResourceInfo& src) {
  const FormatInfo &d = *GetFormatInfo(dst.format), &s = *GetFormatInfo(src.format);
  const bool staging = dst.usage == USAGE_STAGING || src.usage == USAGE_STAGING;
  return d.bytes == s.bytes && d.bc == s.bc && (staging || (dst.depth == src.depth && dst.stencil == src.stencil));
}
}  // namespace

bool ValidateCopyTextureRegion(ValidationDevice& dev, const ResourceInfo& dst, UINT dstSub, UINT x, UINT y,
                               const ResourceInfo& src, UINT srcSub, const BOX* box) {
  UINT dm, dl, sm, sl;
  if (!dst.DecodeSub(dstSub, &dm, &dl) || !src.DecodeSub(srcSub, &sm, &sl)) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: subresource out of range (dst %u, src %u)", dstSub, srcSub);
    return false;
  }
  if (!CopyCompatible(dst, src)) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: formats %s and %s are not copy-compatible", FormatName(dst.format),
            FormatName(src.format));
    return false;
  }
  if (dst.samples != src.samples) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: sample counts differ (dst %u, src %u); use ResolveSubresource",
            dst.samples, src.samples);
    return false;
  }
  if (dst.stencil || src.stencil) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: copies of packed depth-stencil textures are not supported");
    return false;
  }
  const uint32_t sw = src.MipWidth(sm), sh = src.MipHeight(sm);
  const uint32_t dw = dst.MipWidth(dm), dh = dst.MipHeight(dm);
  const BOX b = box ? *box : BOX{0, 0, 0, sw, sh, 1};
  if (b.left >= b.right || b.top >= b.bottom || b.right > sw || b.bottom > sh || x + (b.right - b.left) > dw ||
      y + (b.bottom - b.top) > dh) {
    if (box && (b.left >= b.right || b.top >= b.bottom)) return false;  // empty box: no-op
    dev.Log(LogLevel::Error, "CopySubresourceRegion: box (%u,%u)-(%u,%u) at (%u,%u) out of bounds (src %ux%u, dst %ux%u)",
            b.left, b.top, b.right, b.bottom, x, y, sw, sh, dw, dh);
    return false;
  }
  if (dst.usage == USAGE_STAGING && src.usage == USAGE_STAGING) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: staging-to-staging copies are not supported");
    return false;
  }
  return true;
}

bool ValidateCopySubresourceRegion(ValidationDevice& dev, const ResourceInfo& dst, UINT dstSub, UINT x, UINT y,
                                   const ResourceInfo& src, UINT srcSub, const BOX* box, bool same) {
  if (dst.dimension == RESOURCE_DIMENSION_UNKNOWN || src.dimension == RESOURCE_DIMENSION_UNKNOWN) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: %s is null",
            dst.dimension != RESOURCE_DIMENSION_UNKNOWN ? "pSrcResource" : "pDstResource");
    return false;
  }
  if (same && dstSub == srcSub) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: source and destination are the same subresource");
    return false;
  }
  if (dst.IsBuffer() && src.IsBuffer()) {
    if (!dstSub && !srcSub) return ValidateCopyBufferRegion(dev, dst, x, src, box);
    dev.Log(LogLevel::Error, "CopySubresourceRegion: buffers have one subresource");
    return false;
  }
  if (!dst.IsTexture() || !src.IsTexture()) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: cannot copy between a buffer and a texture");
    return false;
  }
  if (dst.usage == USAGE_IMMUTABLE) {
    dev.Log(LogLevel::Error, "CopySubresourceRegion: the destination is IMMUTABLE");
    return false;
  }
  return ValidateCopyTextureRegion(dev, dst, dstSub, x, y, src, srcSub, box);
}

bool ValidateCopyResource(ValidationDevice& dev, const ResourceInfo& d, const ResourceInfo& s, bool same) {
  const bool null = d.dimension == RESOURCE_DIMENSION_UNKNOWN || s.dimension == RESOURCE_DIMENSION_UNKNOWN;
  if (null || same) {
    dev.Log(LogLevel::Error, "CopyResource: %s", !null ? "source and destination are the same" : "null resource");
    return false;
  }
  if (d.IsBuffer() || s.IsBuffer()) {
    if (d.IsBuffer() && s.IsBuffer() && d.byteWidth == s.byteWidth) return ValidateCopyBufferRegion(dev, d, 0, s, nullptr);
    dev.Log(LogLevel::Error, "CopyResource: buffers must have the same size");
    return false;
  }
  if (d.dimension != s.dimension || d.width != s.width || d.height != s.height || d.mipLevels != s.mipLevels ||
      d.arraySize != s.arraySize) {
    dev.Log(LogLevel::Error, "CopyResource: textures differ in size, mips or array size (%ux%u/%u vs %ux%u/%u)",
            d.width, d.height, d.mipLevels, s.width, s.height, s.mipLevels);
    return false;
  }
  if (d.usage == USAGE_IMMUTABLE) {
    dev.Log(LogLevel::Error, "CopyResource: the destination is IMMUTABLE");
    return false;
  }
  return true;
}

bool ValidateGenerateMips(ValidationDevice& dev, const ViewInfo* srv) {
  if (!srv) {
    dev.Log(LogLevel::Error, "GenerateMips: pShaderResourceView is null");
    return false;
  }
  const ResourceInfo& t = srv->resource;
  if (!t.IsTexture() || !(t.miscFlags & RESOURCE_MISC_GENERATE_MIPS)) {
    dev.Log(LogLevel::Error, "GenerateMips: the texture was not created with RESOURCE_MISC_GENERATE_MIPS");
    return false;
  }
  const uint32_t need = FORMAT_FEATURE_BLIT_SRC | FORMAT_FEATURE_BLIT_DST | FORMAT_FEATURE_FILTER_LINEAR;
  if ((dev.FormatFeatures(t.format) & need) != need) {
    dev.Log(LogLevel::Error, "GenerateMips: format %s cannot be blitted with linear filtering", FormatName(t.format));
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------------
// Queries
bool ValidateBegin(ValidationDevice& dev, const QUERY_DESC& desc) {
  if (desc.Query == QUERY_TIMESTAMP_DISJOINT || desc.Query == QUERY_PIPELINE_STATISTICS) return true;
  dev.Log(LogLevel::Warning, "Begin: query type %u has no Begin (only End)", desc.Query);
  return false;
}

bool ValidateGetData(ValidationDevice& dev, const QueryInfo* q, const void* data, UINT size) {
  if (!q) {
    dev.Log(LogLevel::Error, "GetData: pAsync is null");
    return false;
  }
  if (data && size != q->dataSize) {
    dev.Log(LogLevel::Error, "GetData: DataSize %u, expected %u", size, q->dataSize);
    return false;
  }
  if (!q->ended) {
    dev.Log(LogLevel::Error, "GetData: the query was never ended");
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------------
// Tessellation: primitive topologies
bool ValidateTopology(ValidationDevice& dev, PRIMITIVE_TOPOLOGY t) {
  if (IsSupportedTopology(t)) return true;
  dev.Log(LogLevel::Error,
          "IASetPrimitiveTopology: topology %u is not supported (1..5: point/line/triangle lists and strips, "
          "33..64: patch lists of 1..32 control points); ignored",
          uint32_t(t));
  return false;
}

// Deferred contexts and command lists
HRESULT ValidateCreateDeferredContext(ValidationDevice& dev, UINT flags, DeviceContext** out) {
  if (!out) {
    dev.Log(LogLevel::Error, "CreateDeferredContext: ppDeferredContext is null");
    return E_INVALIDARG;
  }
  *out = nullptr;
  if (flags == 0) return S_OK;
  dev.Log(LogLevel::Error, "CreateDeferredContext: ContextFlags must be 0 (got 0x%x)", flags);
  return E_INVALIDARG;
}

HRESULT ValidateFinishCommandList(ValidationDevice& dev, bool deferredContext, CommandList** out) {
  if (!deferredContext) {
    dev.Log(LogLevel::Error, "FinishCommandList: only a deferred context records command lists");
    return DXGI_ERROR_INVALID_CALL;
  }
  if (out) return S_OK;
  dev.Log(LogLevel::Error, "FinishCommandList: ppCommandList is null");
  return E_INVALIDARG;
}

bool ValidateExecuteCommandList(ValidationDevice& dev, bool deferredContext, const CommandList* list, bool ownList) {
  if (deferredContext) {
    dev.Log(LogLevel::Error, "ExecuteCommandList: not supported on deferred contexts by this port (execute on the immediate context)");
    return false;
  }
  if (!list) {
    dev.Log(LogLevel::Error, "ExecuteCommandList: pCommandList is null");
    return false;
  }
  if (ownList) return true;
  dev.Log(LogLevel::Error, "ExecuteCommandList: the command list belongs to another device");
  return false;
}

HRESULT ValidateDeferredMap(ValidationDevice& dev, const ResourceInfo& r, UINT sub, MAP type,
                            const MAPPED_SUBRESOURCE* mapped, bool discardedInList) {
  if (r.dimension == RESOURCE_DIMENSION_UNKNOWN || !mapped) {
    dev.Log(LogLevel::Error, "Map: %s is null", r.dimension != RESOURCE_DIMENSION_UNKNOWN ? "pMappedResource" : "pResource");
    return E_INVALIDARG;
  }
  if (!r.IsBuffer()) {
    dev.Log(LogLevel::Error, "Map: textures cannot be mapped on deferred contexts by this port");
    return E_NOTIMPL;
  }
  if (sub != 0) {
    dev.Log(LogLevel::Error, "Map: buffers have one subresource (got %u)", sub);
    return E_INVALIDARG;
  }
  if (r.usage != USAGE_DYNAMIC) {
    dev.Log(LogLevel::Error, "Map: a deferred context maps USAGE_DYNAMIC buffers only");
    return E_INVALIDARG;
  }
  if (type == MAP_WRITE_DISCARD || (type == MAP_WRITE_NO_OVERWRITE && discardedInList)) return S_OK;
  dev.Log(LogLevel::Error,
          "Map: a deferred context accepts WRITE_DISCARD, or WRITE_NO_OVERWRITE after a WRITE_DISCARD of the "
          "same buffer in this command list (got MapType %u)", type);
  return E_INVALIDARG;
}

bool ValidateDeferredUpdate(ValidationDevice& dev, const ResourceInfo& dst) {
  if (dst.IsConstantBuffer()) return true;
  dev.Log(LogLevel::Error, "UpdateSubresource: on deferred contexts this port updates constant buffers only");
  return false;
}

// UAV binding, dispatch and indirect arguments
bool ValidateUavBinding(ValidationDevice& dev, const char* fn, const ViewInfo* uav, UINT slot) {
  if (!uav || uav->resource.dimension != RESOURCE_DIMENSION_UNKNOWN) return true;
  dev.Log(LogLevel::Error, "%s: slot %u: not an unordered access view; unbound", fn, slot);
  return false;
}

bool ValidateDispatch(ValidationDevice& dev, UINT x, UINT y, UINT z) {
  const uint32_t* lim = dev.caps().maxDispatch;
  const UINT d3dMax = 65535;  // D3D11_CS_DISPATCH_MAX_THREAD_GROUPS_PER_DIMENSION
  if (x <= std::min(d3dMax, lim[0]) && y <= std::min(d3dMax, lim[1]) && z <= std::min(d3dMax, lim[2])) return true;
  dev.Log(LogLevel::Error, "Dispatch: %u x %u x %u thread groups; at most 65535 per dimension (adapter: %u x %u x %u)",
          x, y, z, lim[0], lim[1], lim[2]);
  return false;
}

bool ValidateIndirectArgs(ValidationDevice& dev, const char* fn, const ResourceInfo& args, UINT offset, UINT argBytes) {
  if (args.dimension == RESOURCE_DIMENSION_UNKNOWN) {
    dev.Log(LogLevel::Error, "%s: pBufferForArgs is null", fn);
  } else if (!(args.miscFlags & RESOURCE_MISC_DRAWINDIRECT_ARGS)) {
    dev.Log(LogLevel::Error, "%s: the buffer was not created with RESOURCE_MISC_DRAWINDIRECT_ARGS", fn);
  } else if (offset % 4) {
    dev.Log(LogLevel::Error, "%s: AlignedByteOffsetForArgs %u is not a multiple of 4", fn, offset);
  } else if (uint64_t(offset) + argBytes > args.byteWidth) {
    dev.Log(LogLevel::Error, "%s: AlignedByteOffsetForArgs %u: its %u bytes of arguments pass the end of the %u-byte buffer",
            fn, offset, argBytes, args.byteWidth);
  } else {
    return true;
  }
  return false;
}

bool ValidateClearUav(ValidationDevice& dev, const ViewInfo* uav, const void* values, bool isFloat) {
  const char* fn = isFloat ? "ClearUnorderedAccessViewFloat" : "ClearUnorderedAccessViewUint";
  if (!uav || !values) {
    dev.Log(LogLevel::Error, "%s: %s is null", fn, uav ? "Values" : "pUnorderedAccessView");
    return false;
  }
  const FormatInfo* f = uav->resource.IsTexture() ? GetFormatInfo(uav->format) : nullptr;
  if (isFloat && (!f || f->integer)) {
    dev.Log(LogLevel::Error, "%s: only views of FLOAT/UNORM textures take float clears (use ClearUnorderedAccessViewUint for %s)", fn,
            f ? f->name : "raw and structured buffers");
    return false;
  }
  if (f && !isFloat && !UavClearBitsSupported(uav->format)) {
    dev.Log(LogLevel::Error, "%s: bit-exact clears of %s are not supported", fn, f->name);
    return false;
  }
  return true;
}

bool ValidateOMUavs(ValidationDevice& dev, UINT numRTVs, UINT uavStart, UINT numUAVs) {
  const char* fn = "OMSetRenderTargetsAndUnorderedAccessViews";
  if (numUAVs == KEEP_UNORDERED_ACCESS_VIEWS) return true;
  if (uavStart > kMaxUnorderedAccessSlots || numUAVs > kMaxUnorderedAccessSlots - uavStart) {
    dev.Log(LogLevel::Error, "%s: UAV slots %u..%u out of range (0..%u)", fn, uavStart, uavStart + numUAVs,
            kMaxUnorderedAccessSlots - 1);
    return false;
  }
  if (numUAVs && numRTVs != KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL && uavStart < numRTVs) {
    dev.Log(LogLevel::Error, "%s: UAVStartSlot %u overlaps the %u render targets (render targets and UAVs share the slots)",
            fn, uavStart, numRTVs);
    return false;
  }
  return true;
}

}  // namespace d3dl::impl
