// Validation of views (formats within a typeless family, dimensions, mips and
// array slices) and of ResolveSubresource (see Validate.h).
#include "Validate.h"

namespace d3dl::impl {

// ---------------------------------------------------------------------------
// Formats
namespace {
// Depth textures: DSVs name the depth format (D32_FLOAT, D24_UNORM_S8_UINT)
// and see every aspect; SRVs name the colour-like member (R32_FLOAT,
// R24_UNORM_X8_TYPELESS) and read the depth aspect.
HRESULT DepthViewFormat(ValidationDevice& dev, const ViewKindInfo& kind, const ResourceInfo& t, const FormatInfo& f,
                        ViewFormat* format) {
  const bool dsv = kind.bind == BIND_DEPTH_STENCIL;
  if (dsv && !f.depth) {
    dev.Log(LogLevel::Error, "%s: Format %s is not a depth format (texture %s)", kind.fn, f.name, FormatName(t.format));
    return E_INVALIDARG;
  }
  *format = {f.dxgi, dsv ? ViewAspect::Attachment : ViewAspect::Depth};
  return S_OK;
}
}  // namespace

HRESULT ValidateViewResource(ValidationDevice& dev, const ViewKindInfo& kind, const ResourceInfo& t, const void* out,
                             DXGI_FORMAT requested, ViewFormat* format) {
  const char* fn = kind.fn;
  if (!out) {
    dev.Log(LogLevel::Error, "%s: %s is null", fn, kind.outName);
    return E_INVALIDARG;
  }
  if (t.dimension == RESOURCE_DIMENSION_UNKNOWN) {
    dev.Log(LogLevel::Error, "%s: pResource is null", fn);
    return E_INVALIDARG;
  }
  if (!t.IsTexture()) {
    dev.Log(LogLevel::Error, "%s: the resource is a buffer; only texture views are supported", fn);
    return E_INVALIDARG;
  }
  if (!(t.bindFlags & kind.bind)) {
    dev.Log(LogLevel::Error, "%s: the texture was not created with %s (BindFlags 0x%x)", fn, kind.bindName, t.bindFlags);
    return E_INVALIDARG;
  }
  const DXGI_FORMAT f = requested == DXGI_FORMAT_UNKNOWN ? t.format : requested;
  const FormatInfo* fi = GetFormatInfo(f);
  if (!fi) {
    dev.Log(LogLevel::Error, "%s: Format %u (%s) cannot be used for a view", fn, f, FormatName(f));
    return E_INVALIDARG;
  }
  if (fi->typeless) {
    dev.Log(LogLevel::Error, "%s: Format %s is typeless: the view must name a typed format of the texture's family%s", fn,
            fi->name, requested == DXGI_FORMAT_UNKNOWN ? " (a description with Format is required)" : "");
    return E_INVALIDARG;
  }
  if (!SameFamily(*GetFormatInfo(t.format), *fi)) {
    dev.Log(LogLevel::Error, "%s: view Format %s is not compatible with texture Format %s (not in its typeless family)", fn,
            fi->name, FormatName(t.format));
    return E_INVALIDARG;
  }
  if (t.depth) return DepthViewFormat(dev, kind, t, *fi, format);
  if (fi->depth) {
    dev.Log(LogLevel::Error, "%s: Format %s is a depth format; texture %s has no depth binding", fn, fi->name,
            FormatName(t.format));
    return E_INVALIDARG;
  }
  *format = {f, ViewAspect::Color};
  return S_OK;
}

// ---------------------------------------------------------------------------
// Dimensions
ViewDim FromSrvDimension(SRV_DIMENSION d) {
  switch (d) {
    case SRV_DIMENSION_UNKNOWN: return ViewDim::Unknown;
    case SRV_DIMENSION_TEXTURE1D: return ViewDim::Tex1D;
    case SRV_DIMENSION_TEXTURE1DARRAY: return ViewDim::Tex1DArray;
    case SRV_DIMENSION_TEXTURE2D: return ViewDim::Tex2D;
    case SRV_DIMENSION_TEXTURE2DARRAY: return ViewDim::Tex2DArray;
    case SRV_DIMENSION_TEXTURE2DMS: return ViewDim::Tex2DMS;
    case SRV_DIMENSION_TEXTURE2DMSARRAY: return ViewDim::Tex2DMSArray;
    case SRV_DIMENSION_TEXTURECUBE: return ViewDim::Cube;
    case SRV_DIMENSION_TEXTURECUBEARRAY: return ViewDim::CubeArray;
  }
  return ViewDim::Invalid;
}
ViewDim FromRtvDimension(RTV_DIMENSION d) {
  switch (d) {
    case RTV_DIMENSION_UNKNOWN: return ViewDim::Unknown;
    case RTV_DIMENSION_TEXTURE1D: return ViewDim::Tex1D;
    case RTV_DIMENSION_TEXTURE1DARRAY: return ViewDim::Tex1DArray;
    case RTV_DIMENSION_TEXTURE2D: return ViewDim::Tex2D;
    case RTV_DIMENSION_TEXTURE2DARRAY: return ViewDim::Tex2DArray;
    case RTV_DIMENSION_TEXTURE2DMS: return ViewDim::Tex2DMS;
    case RTV_DIMENSION_TEXTURE2DMSARRAY: return ViewDim::Tex2DMSArray;
  }
  return ViewDim::Invalid;
}
ViewDim FromDsvDimension(DSV_DIMENSION d) {
  switch (d) {
    case DSV_DIMENSION_UNKNOWN: return ViewDim::Unknown;
    case DSV_DIMENSION_TEXTURE1D: return ViewDim::Tex1D;
    case DSV_DIMENSION_TEXTURE1DARRAY: return ViewDim::Tex1DArray;
    case DSV_DIMENSION_TEXTURE2D: return ViewDim::Tex2D;
    case DSV_DIMENSION_TEXTURE2DARRAY: return ViewDim::Tex2DArray;
    case DSV_DIMENSION_TEXTURE2DMS: return ViewDim::Tex2DMS;
    case DSV_DIMENSION_TEXTURE2DMSARRAY: return ViewDim::Tex2DMSArray;
  }
  return ViewDim::Invalid;
}

namespace {
bool IsArrayDim(ViewDim d) {
  return d == ViewDim::Tex1DArray || d == ViewDim::Tex2DArray || d == ViewDim::Tex2DMSArray || d == ViewDim::CubeArray;
}
bool IsMsDim(ViewDim d) { return d == ViewDim::Tex2DMS || d == ViewDim::Tex2DMSArray; }
bool IsCubeDim(ViewDim d) { return d == ViewDim::Cube || d == ViewDim::CubeArray; }
bool IsCube(const ResourceInfo& t) { return (t.miscFlags & RESOURCE_MISC_TEXTURECUBE) != 0; }
const char* DimName(ViewDim d) {
  static const char* const kNames[] = {"UNKNOWN", "TEXTURE1D", "TEXTURE1DARRAY", "TEXTURE2D", "TEXTURE2DARRAY",
                                       "TEXTURE2DMS", "TEXTURE2DMSARRAY", "TEXTURECUBE", "TEXTURECUBEARRAY", "(invalid)"};
  return kNames[static_cast<int>(d)];
}

// What a view without a description (or with UNKNOWN) covers.
ViewDim DefaultDim(const ResourceInfo& t, bool srv) {
  const bool array = t.arraySize > 1;
  if (t.dimension == RESOURCE_DIMENSION_TEXTURE1D) return array ? ViewDim::Tex1DArray : ViewDim::Tex1D;
  if (t.samples > 1) return array ? ViewDim::Tex2DMSArray : ViewDim::Tex2DMS;
  if (srv && IsCube(t)) return t.arraySize == 6 ? ViewDim::Cube : ViewDim::CubeArray;
  return array ? ViewDim::Tex2DArray : ViewDim::Tex2D;
}

// The dimension must fit the texture: 1-D or 2-D, multisampled or not, cube
// flag, and a single-slice dimension only for a single-slice texture.
HRESULT CheckDimension(ValidationDevice& dev, const char* fn, const ResourceInfo& t, ViewDim d) {
  const char* problem = nullptr;
  const bool is1D = d == ViewDim::Tex1D || d == ViewDim::Tex1DArray;
  if (is1D != (t.dimension == RESOURCE_DIMENSION_TEXTURE1D)) problem = "does not match the texture's dimension (1-D/2-D)";
  else if (IsMsDim(d) && t.samples == 1) problem = "is multisampled but the texture has SampleDesc.Count 1";
  else if (!IsMsDim(d) && t.samples > 1) problem = "is single-sampled but the texture is multisampled (use TEXTURE2DMS or TEXTURE2DMSARRAY)";
  else if (IsCubeDim(d) && !IsCube(t)) problem = "needs a texture created with RESOURCE_MISC_TEXTURECUBE";
  else if (!IsArrayDim(d) && !IsCubeDim(d) && t.arraySize > 1) problem = "views one slice but the texture is an array (use an *ARRAY dimension)";
  if (!problem) return S_OK;
  dev.Log(LogLevel::Error, "%s: ViewDimension %s %s (ArraySize %u, SampleDesc.Count %u, MiscFlags 0x%x)", fn,
          DimName(d), problem, t.arraySize, t.samples, t.miscFlags);
  return E_INVALIDARG;
}

// Array slices: the whole texture for single-slice dimensions, `range` for
// arrays, 6 faces for a cube, 6 * NumCubes faces for a cube array.
HRESULT LayerRange(ValidationDevice& dev, const char* fn, const ResourceInfo& t, ViewDim d, const TEX_ARRAY_RANGE& range,
                   const TEXCUBE_ARRAY_SRV& cubes, ViewShape* shape) {
  const uint32_t total = t.arraySize;
  uint32_t first = 0, count = 1;
  if (d == ViewDim::Cube) {
    count = 6;
  } else if (d == ViewDim::CubeArray) {
    if (!dev.caps().cubeArray) {
      dev.Log(LogLevel::Error, "%s: TEXTURECUBEARRAY needs the imageCubeArray feature, which this adapter lacks", fn);
      return DXGI_ERROR_UNSUPPORTED;
    }
    first = cubes.First2DArrayFace;
    const uint32_t n = cubes.NumCubes == ~0u ? (first < total ? (total - first) / 6 : 0) : cubes.NumCubes;
    count = 6 * n;
  } else if (IsArrayDim(d)) {
    first = range.FirstArraySlice;
    count = range.ArraySize == ~0u ? (first < total ? total - first : 0) : range.ArraySize;
  }
  if (count == 0 || first >= total || count > total - first) {
    dev.Log(LogLevel::Error, "%s: array slices [%u, %u + %u) out of range (texture has %u)", fn, first, first, count, total);
    return E_INVALIDARG;
  }
  shape->baseLayer = first;
  shape->layerCount = count;
  shape->dim = d;
  return S_OK;
}

HRESULT SrvMips(ValidationDevice& dev, const ResourceInfo& t, const TEX_SRV& mips, ViewShape* shape) {
  const char* fn = kSrvKind.fn;
  const uint32_t total = t.mipLevels;
  const uint32_t most = mips.MostDetailedMip;
  if (most >= total) {
    dev.Log(LogLevel::Error, "%s: MostDetailedMip %u out of range (texture has %u mips)", fn, most, total);
    return E_INVALIDARG;
  }
  const uint32_t count = mips.MipLevels == ~0u ? total - most : mips.MipLevels;
  if (count == 0 || most + count > total) {
    dev.Log(LogLevel::Error, "%s: MipLevels %u out of range (texture has %u mips)", fn, count, total);
    return E_INVALIDARG;
  }
  shape->baseMip = most;
  shape->mipCount = count;
  return S_OK;
}
}  // namespace

HRESULT ValidateSrvShape(ValidationDevice& dev, const ResourceInfo& t, const SHADER_RESOURCE_VIEW_DESC* desc,
                         ViewShape* shape) {
  const SHADER_RESOURCE_VIEW_DESC d = desc ? *desc : SHADER_RESOURCE_VIEW_DESC{};
  ViewDim dim = FromSrvDimension(d.ViewDimension);
  if (dim == ViewDim::Invalid) {
    dev.Log(LogLevel::Error, "%s: ViewDimension %u is invalid", kSrvKind.fn, static_cast<UINT>(d.ViewDimension));
    return E_INVALIDARG;
  }
  if (dim == ViewDim::Unknown) dim = DefaultDim(t, true);
  HRESULT hr = CheckDimension(dev, kSrvKind.fn, t, dim);
  if (SUCCEEDED(hr) && !IsMsDim(dim)) hr = SrvMips(dev, t, d.Texture, shape);
  if (SUCCEEDED(hr)) hr = LayerRange(dev, kSrvKind.fn, t, dim, d.Array, d.CubeArray, shape);
  return hr;
}

HRESULT ValidateTargetShape(ValidationDevice& dev, const ViewKindInfo& kind, const ResourceInfo& t, ViewDim dim,
                            UINT rawDim, UINT mip, const TEX_ARRAY_RANGE& range, ViewShape* shape) {
  if (dim == ViewDim::Invalid) {
    dev.Log(LogLevel::Error, "%s: ViewDimension %u is invalid", kind.fn, rawDim);
    return E_INVALIDARG;
  }
  if (dim == ViewDim::Unknown) dim = DefaultDim(t, false);
  HRESULT hr = CheckDimension(dev, kind.fn, t, dim);
  if (FAILED(hr)) return hr;
  if (mip >= t.mipLevels) {
    dev.Log(LogLevel::Error, "%s: MipSlice %u out of range (texture has %u mips)", kind.fn, mip, t.mipLevels);
    return E_INVALIDARG;
  }
  shape->baseMip = mip;
  shape->mipCount = 1;
  return LayerRange(dev, kind.fn, t, dim, range, {}, shape);
}

// ---------------------------------------------------------------------------
// ResolveSubresource: D3D11 resolves float and UNORM formats only (no
// integer, no depth); vkCmdResolveImage also needs both images created with
// the same VkFormat and a destination format with colour-attachment support.
bool ValidateResolveSubresource(ValidationDevice& dev, const ResourceInfo& td, UINT dstSub, const ResourceInfo& ts,
                                UINT srcSub, DXGI_FORMAT format) {
  const char* fn = "ResolveSubresource";
  if (!td.IsTexture() || !ts.IsTexture()) {
    dev.Log(LogLevel::Error, "%s: %s is not a texture", fn, !td.IsTexture() ? "pDstResource" : "pSrcResource");
    return false;
  }
  UINT dm, dl, sm, sl;
  const FormatInfo* f = GetFormatInfo(format);
  const FormatInfo &tdf = *GetFormatInfo(td.format), &tsf = *GetFormatInfo(ts.format);
  const char* problem = nullptr;
  if (!td.DecodeSub(dstSub, &dm, &dl) || !ts.DecodeSub(srcSub, &sm, &sl)) problem = "subresource out of range";
  else if (ts.samples == 1) problem = "the source is not multisampled";
  else if (td.samples != 1) problem = "the destination is multisampled";
  else if (td.usage == USAGE_STAGING || td.usage == USAGE_IMMUTABLE) problem = "the destination must be a DEFAULT texture";
  else if (td.MipWidth(dm) != ts.MipWidth(sm) || td.MipHeight(dm) != ts.MipHeight(sm)) problem = "source and destination sizes differ";
  else if (!f || f->typeless) problem = "Format must be a typed format";
  else if (!SameFamily(tsf, *f) || !SameFamily(tdf, *f)) problem = "Format is not in the family of both textures";
  else if (f->integer || f->depth || ts.depth) problem = "integer and depth formats cannot be resolved (D3D11 rule)";
  else if (tsf.vk != tdf.vk) problem = "source and destination were created with different formats (vkCmdResolveImage needs the same)";
  if (!problem) return true;
  dev.Log(LogLevel::Error, "%s: %s (dst %s x%u sub %u, src %s x%u sub %u, Format %s)", fn, problem, tdf.name,
          td.samples, dstSub, tsf.name, ts.samples, srcSub, FormatName(format));
  return false;
}

}  // namespace d3dl::impl
