// Sampler, blend, depth-stencil and rasterizer state objects: D3D11
// descriptions decoded into Vulkan create-info pieces once, at creation.
#include <cmath>

#include "Context.h"

namespace d3dl::impl {
namespace {

bool ToAddress(TEXTURE_ADDRESS_MODE m, VkSamplerAddressMode* out) {
  switch (m) {
    case TEXTURE_ADDRESS_WRAP: *out = VK_SAMPLER_ADDRESS_MODE_REPEAT; return true;
    case TEXTURE_ADDRESS_MIRROR: *out = VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT; return true;
    case TEXTURE_ADDRESS_CLAMP: *out = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE; return true;
    case TEXTURE_ADDRESS_BORDER: *out = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER; return true;
    case TEXTURE_ADDRESS_MIRROR_ONCE: *out = VK_SAMPLER_ADDRESS_MODE_MIRROR_CLAMP_TO_EDGE; return true;
  }
  return false;
}

VkBlendFactor ToBlend(BLEND b) {
  switch (b) {
    case BLEND_ZERO: return VK_BLEND_FACTOR_ZERO;
    case BLEND_ONE: return VK_BLEND_FACTOR_ONE;
    case BLEND_SRC_COLOR: return VK_BLEND_FACTOR_SRC_COLOR;
    case BLEND_INV_SRC_COLOR: return VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR;
    case BLEND_SRC_ALPHA: return VK_BLEND_FACTOR_SRC_ALPHA;
    case BLEND_INV_SRC_ALPHA: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    case BLEND_DEST_ALPHA: return VK_BLEND_FACTOR_DST_ALPHA;
    case BLEND_INV_DEST_ALPHA: return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
    case BLEND_DEST_COLOR: return VK_BLEND_FACTOR_DST_COLOR;
    case BLEND_INV_DEST_COLOR: return VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR;
    case BLEND_SRC_ALPHA_SAT: return VK_BLEND_FACTOR_SRC_ALPHA_SATURATE;
    case BLEND_BLEND_FACTOR: return VK_BLEND_FACTOR_CONSTANT_COLOR;
    case BLEND_INV_BLEND_FACTOR: return VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_COLOR;
  }
  return VK_BLEND_FACTOR_MAX_ENUM;
}
// Alpha channel: colour factors become their alpha forms (as D3D does).
VkBlendFactor ToBlendAlpha(BLEND b) {
  switch (b) {
    case BLEND_SRC_COLOR: return VK_BLEND_FACTOR_SRC_ALPHA;
    case BLEND_INV_SRC_COLOR: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    case BLEND_DEST_COLOR: return VK_BLEND_FACTOR_DST_ALPHA;
    case BLEND_INV_DEST_COLOR: return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
    case BLEND_BLEND_FACTOR: return VK_BLEND_FACTOR_CONSTANT_ALPHA;
    case BLEND_INV_BLEND_FACTOR: return VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_ALPHA;
    default: return ToBlend(b);
  }
}
VkBlendOp ToBlendOp(BLEND_OP o) {
  switch (o) {
    case BLEND_OP_ADD: return VK_BLEND_OP_ADD;
    case BLEND_OP_SUBTRACT: return VK_BLEND_OP_SUBTRACT;
    case BLEND_OP_REV_SUBTRACT: return VK_BLEND_OP_REVERSE_SUBTRACT;
    case BLEND_OP_MIN: return VK_BLEND_OP_MIN;
    case BLEND_OP_MAX: return VK_BLEND_OP_MAX;
  }
  return VK_BLEND_OP_MAX_ENUM;
}
VkStencilOp ToStencilOp(STENCIL_OP o) {
  switch (o) {
    case STENCIL_OP_KEEP: return VK_STENCIL_OP_KEEP;
    case STENCIL_OP_ZERO: return VK_STENCIL_OP_ZERO;
    case STENCIL_OP_REPLACE: return VK_STENCIL_OP_REPLACE;
    case STENCIL_OP_INCR_SAT: return VK_STENCIL_OP_INCREMENT_AND_CLAMP;
    case STENCIL_OP_DECR_SAT: return VK_STENCIL_OP_DECREMENT_AND_CLAMP;
    case STENCIL_OP_INVERT: return VK_STENCIL_OP_INVERT;
    case STENCIL_OP_INCR: return VK_STENCIL_OP_INCREMENT_AND_WRAP;
    case STENCIL_OP_DECR: return VK_STENCIL_OP_DECREMENT_AND_WRAP;
  }
  return VK_STENCIL_OP_KEEP;
}
bool ValidCompare(COMPARISON_FUNC f) { return f >= COMPARISON_NEVER && f <= COMPARISON_ALWAYS; }
bool ValidBlend(BLEND b) { return ToBlend(b) != VK_BLEND_FACTOR_MAX_ENUM; }
bool ValidBlendOp(BLEND_OP o) { return o >= BLEND_OP_ADD && o <= BLEND_OP_MAX; }
bool ValidStencilOp(STENCIL_OP o) { return o >= STENCIL_OP_KEEP && o <= STENCIL_OP_DECR; }

}  // namespace

SamplerImpl::~SamplerImpl() { dev_->Defer(VK_OBJECT_TYPE_SAMPLER, reinterpret_cast<uint64_t>(sampler)); }
void SamplerImpl::OnDebugName() { dev_->SetName(VK_OBJECT_TYPE_SAMPLER, reinterpret_cast<uint64_t>(sampler), name_); }

HRESULT DeviceImpl::CreateSamplerState(const SAMPLER_DESC* desc, SamplerState** out) {
  const char* fn = "CreateSamplerState";
  if (out) *out = nullptr;
  if (!desc || !out) {
    Log(LogLevel::Error, "%s: %s is null", fn, desc ? "ppSamplerState" : "pSamplerDesc");
    return E_INVALIDARG;
  }
  const SAMPLER_DESC& d = *desc;
  // D3D11 FILTER bits: mip (bits 0-1), mag (2-3), min (4-5), anisotropic 0x40,
  // reduction (7-8): 0 standard, 1 comparison, 2 minimum, 3 maximum.
  const uint32_t f = d.Filter;
  if (f & ~0x1D5u) {
    Log(LogLevel::Error, "%s: Filter 0x%x is not a D3D11 filter", fn, f);
    return E_INVALIDARG;
  }
  const bool anisotropic = (f & 0x40) != 0;
  const uint32_t reduction = (f >> 7) & 3;
  if (anisotropic && (f & 0x15) != 0x15) {
    Log(LogLevel::Error, "%s: Filter 0x%x: anisotropic filters need linear min/mag/mip bits", fn, f);
    return E_INVALIDARG;
  }
  VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  ci.minFilter = (f & 0x10) ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  ci.magFilter = (f & 0x04) ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  ci.mipmapMode = (f & 0x01) ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  if (!ToAddress(d.AddressU, &ci.addressModeU) || !ToAddress(d.AddressV, &ci.addressModeV) ||
      !ToAddress(d.AddressW, &ci.addressModeW)) {
    Log(LogLevel::Error, "%s: invalid address mode (U %u, V %u, W %u)", fn, d.AddressU, d.AddressV, d.AddressW);
    return E_INVALIDARG;
  }
  if (!mirrorOnce_) {
    for (VkSamplerAddressMode* m : {&ci.addressModeU, &ci.addressModeV, &ci.addressModeW})
      if (*m == VK_SAMPLER_ADDRESS_MODE_MIRROR_CLAMP_TO_EDGE) {
        Log(LogLevel::Warning, "%s: TEXTURE_ADDRESS_MIRROR_ONCE needs samplerMirrorClampToEdge; using CLAMP", fn);
        *m = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
      }
  }
  if (!std::isfinite(d.MipLODBias) || d.MipLODBias < -16.0f || d.MipLODBias > 15.99f) {
    Log(LogLevel::Error, "%s: MipLODBias %g out of range [-16, 15.99]", fn, d.MipLODBias);
    return E_INVALIDARG;
  }
  ci.mipLodBias = std::clamp(d.MipLODBias, -props_.limits.maxSamplerLodBias, props_.limits.maxSamplerLodBias);
  if (anisotropic) {
    if (d.MaxAnisotropy < 1 || d.MaxAnisotropy > 16) {
      Log(LogLevel::Error, "%s: MaxAnisotropy %u out of range [1, 16]", fn, d.MaxAnisotropy);
      return E_INVALIDARG;
    }
    if (anisotropy_) {
      ci.anisotropyEnable = VK_TRUE;
      ci.maxAnisotropy = std::min(static_cast<float>(d.MaxAnisotropy), props_.limits.maxSamplerAnisotropy);
    }
  }
  if (reduction == 1) {
    if (!ValidCompare(d.ComparisonFunc)) {
      Log(LogLevel::Error, "%s: ComparisonFunc %u is invalid", fn, d.ComparisonFunc);
      return E_INVALIDARG;
    }
    ci.compareEnable = VK_TRUE;
    ci.compareOp = ToVkCompare(d.ComparisonFunc);
  }
  VkSamplerReductionModeCreateInfo red{VK_STRUCTURE_TYPE_SAMPLER_REDUCTION_MODE_CREATE_INFO};
  if (reduction >= 2) {
    if (!minmax_) {
      Log(LogLevel::Error, "%s: Filter 0x%x needs min/max reduction (samplerFilterMinmax), which this adapter lacks", fn, f);
      return E_INVALIDARG;
    }
    red.reductionMode = reduction == 2 ? VK_SAMPLER_REDUCTION_MODE_MIN : VK_SAMPLER_REDUCTION_MODE_MAX;
    ci.pNext = &red;
  }
  // Border colour: Vulkan has three fixed ones (without custom border colours).
  const float* c = d.BorderColor;
  if (c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 0) {
    ci.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  } else if (c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 1) {
    ci.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK;
  } else if (c[0] == 1 && c[1] == 1 && c[2] == 1 && c[3] == 1) {
    ci.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  } else {
    float lum = (c[0] + c[1] + c[2]) / 3.0f;
    ci.borderColor = c[3] < 0.5f ? VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK
                     : lum < 0.5f ? VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK
                                  : VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    bool border = d.AddressU == TEXTURE_ADDRESS_BORDER || d.AddressV == TEXTURE_ADDRESS_BORDER ||
                  d.AddressW == TEXTURE_ADDRESS_BORDER;
    if (border)
      Log(LogLevel::Warning, "%s: BorderColor (%g, %g, %g, %g) has no Vulkan equivalent; using %s", fn,
          c[0], c[1], c[2], c[3],
          ci.borderColor == VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK ? "transparent black"
          : ci.borderColor == VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK    ? "opaque black"
                                                                    : "opaque white");
  }
  if (std::isnan(d.MinLOD) || std::isnan(d.MaxLOD) || d.MinLOD > d.MaxLOD) {
    Log(LogLevel::Error, "%s: MinLOD %g > MaxLOD %g", fn, d.MinLOD, d.MaxLOD);
    return E_INVALIDARG;
  }
  ci.minLod = std::max(0.0f, d.MinLOD);
  ci.maxLod = d.MaxLOD >= FLOAT32_MAX ? VK_LOD_CLAMP_NONE : std::max(ci.minLod, d.MaxLOD);
  auto* s = new SamplerImpl(this);
  s->desc = d;
  if (vkCreateSampler(device_, &ci, nullptr, &s->sampler) != VK_SUCCESS) {
    Log(LogLevel::Error, "%s: vkCreateSampler failed", fn);
    s->Release();
    return E_OUTOFMEMORY;
  }
  *out = s;
  return S_OK;
}

void FillBlendState(const BLEND_DESC& d, VkPipelineColorBlendAttachmentState* out) {
  for (uint32_t i = 0; i < SIMULTANEOUS_RENDER_TARGET_COUNT; ++i) {
    const RENDER_TARGET_BLEND_DESC& r = d.RenderTarget[d.IndependentBlendEnable ? i : 0];
    VkPipelineColorBlendAttachmentState& a = out[i];
    a.blendEnable = r.BlendEnable ? VK_TRUE : VK_FALSE;
    a.srcColorBlendFactor = ToBlend(r.SrcBlend);
    a.dstColorBlendFactor = ToBlend(r.DestBlend);
    a.colorBlendOp = ToBlendOp(r.BlendOp);
    a.srcAlphaBlendFactor = ToBlendAlpha(r.SrcBlendAlpha);
    a.dstAlphaBlendFactor = ToBlendAlpha(r.DestBlendAlpha);
    a.alphaBlendOp = ToBlendOp(r.BlendOpAlpha);
    a.colorWriteMask = r.RenderTargetWriteMask & 0xF;  // same bit order R,G,B,A
  }
}

HRESULT DeviceImpl::CreateBlendState(const BLEND_DESC* desc, BlendState** out) {
  const char* fn = "CreateBlendState";
  if (out) *out = nullptr;
  if (!desc || !out) {
    Log(LogLevel::Error, "%s: %s is null", fn, desc ? "ppBlendState" : "pBlendStateDesc");
    return E_INVALIDARG;
  }
  uint32_t n = desc->IndependentBlendEnable ? SIMULTANEOUS_RENDER_TARGET_COUNT : 1;
  for (uint32_t i = 0; i < n; ++i) {
    const auto& r = desc->RenderTarget[i];
    if (!ValidBlend(r.SrcBlend) || !ValidBlend(r.DestBlend) || !ValidBlend(r.SrcBlendAlpha) ||
        !ValidBlend(r.DestBlendAlpha) || !ValidBlendOp(r.BlendOp) || !ValidBlendOp(r.BlendOpAlpha)) {
      Log(LogLevel::Error, "%s: RenderTarget[%u] has an invalid blend factor or op", fn, i);
      return E_INVALIDARG;
    }
  }
  auto* s = new BlendImpl(this);
  s->desc = *desc;
  FillBlendState(*desc, s->att);
  *out = s;
  return S_OK;
}

void FillDepthState(const DEPTH_STENCIL_DESC& d, VkPipelineDepthStencilStateCreateInfo* ci) {
  *ci = {VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  ci->depthTestEnable = d.DepthEnable ? VK_TRUE : VK_FALSE;
  ci->depthWriteEnable = d.DepthEnable && d.DepthWriteMask == DEPTH_WRITE_MASK_ALL;
  ci->depthCompareOp = ToVkCompare(d.DepthFunc);
  ci->stencilTestEnable = d.StencilEnable ? VK_TRUE : VK_FALSE;
  auto face = [&](const DEPTH_STENCILOP_DESC& o, VkStencilOpState* s) {
    s->failOp = ToStencilOp(o.StencilFailOp);
    s->passOp = ToStencilOp(o.StencilPassOp);
    s->depthFailOp = ToStencilOp(o.StencilDepthFailOp);
    s->compareOp = ToVkCompare(o.StencilFunc);
    s->compareMask = d.StencilReadMask;
    s->writeMask = d.StencilWriteMask;
  };
  face(d.FrontFace, &ci->front);
  face(d.BackFace, &ci->back);
  ci->minDepthBounds = 0.0f;
  ci->maxDepthBounds = 1.0f;
}

HRESULT DeviceImpl::CreateDepthStencilState(const DEPTH_STENCIL_DESC* desc, DepthStencilState** out) {
  const char* fn = "CreateDepthStencilState";
  if (out) *out = nullptr;
  if (!desc || !out) {
    Log(LogLevel::Error, "%s: %s is null", fn, desc ? "ppDepthStencilState" : "pDepthStencilDesc");
    return E_INVALIDARG;
  }
  const auto& d = *desc;
  if (!ValidCompare(d.DepthFunc) || d.DepthWriteMask > DEPTH_WRITE_MASK_ALL ||
      !ValidCompare(d.FrontFace.StencilFunc) || !ValidCompare(d.BackFace.StencilFunc) ||
      !ValidStencilOp(d.FrontFace.StencilFailOp) || !ValidStencilOp(d.FrontFace.StencilPassOp) ||
      !ValidStencilOp(d.FrontFace.StencilDepthFailOp) || !ValidStencilOp(d.BackFace.StencilFailOp) ||
      !ValidStencilOp(d.BackFace.StencilPassOp) || !ValidStencilOp(d.BackFace.StencilDepthFailOp)) {
    Log(LogLevel::Error, "%s: invalid DepthFunc %u / DepthWriteMask %u / stencil ops", fn, d.DepthFunc, d.DepthWriteMask);
    return E_INVALIDARG;
  }
  auto* s = new DepthStencilImpl(this);
  s->desc = d;
  FillDepthState(d, &s->ci);
  *out = s;
  return S_OK;
}

void FillRasterState(const RASTERIZER_DESC& d, bool depthClamp, VkPipelineRasterizationStateCreateInfo* ci) {
  *ci = {VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  ci->depthClampEnable = (!d.DepthClipEnable && depthClamp) ? VK_TRUE : VK_FALSE;
  ci->polygonMode = d.FillMode == FILL_WIREFRAME ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL;
  ci->cullMode = d.CullMode == CULL_FRONT  ? VK_CULL_MODE_FRONT_BIT
                 : d.CullMode == CULL_BACK ? VK_CULL_MODE_BACK_BIT
                                           : VK_CULL_MODE_NONE;
  // The viewport has a negative height, so framebuffer coordinates equal D3D
  // window coordinates (y down); D3D's "clockwise" is then Vulkan's clockwise.
  ci->frontFace = d.FrontCounterClockwise ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
  ci->depthBiasEnable = (d.DepthBias != 0 || d.SlopeScaledDepthBias != 0.0f) ? VK_TRUE : VK_FALSE;
  ci->depthBiasConstantFactor = static_cast<float>(d.DepthBias);
  ci->depthBiasClamp = d.DepthBiasClamp;
  ci->depthBiasSlopeFactor = d.SlopeScaledDepthBias;
  ci->lineWidth = 1.0f;
}

HRESULT DeviceImpl::CreateRasterizerState(const RASTERIZER_DESC* desc, RasterizerState** out) {
  const char* fn = "CreateRasterizerState";
  if (out) *out = nullptr;
  if (!desc || !out) {
    Log(LogLevel::Error, "%s: %s is null", fn, desc ? "ppRasterizerState" : "pRasterizerDesc");
    return E_INVALIDARG;
  }
  const auto& d = *desc;
  if (d.FillMode != FILL_SOLID && d.FillMode != FILL_WIREFRAME) {
    Log(LogLevel::Error, "%s: FillMode %u is invalid", fn, d.FillMode);
    return E_INVALIDARG;
  }
  if (d.CullMode < CULL_NONE || d.CullMode > CULL_BACK) {
    Log(LogLevel::Error, "%s: CullMode %u is invalid", fn, d.CullMode);
    return E_INVALIDARG;
  }
  if (d.FillMode == FILL_WIREFRAME && !fillNonSolid_) {
    Log(LogLevel::Error, "%s: FILL_WIREFRAME needs fillModeNonSolid", fn);
    return DXGI_ERROR_UNSUPPORTED;
  }
  auto* s = new RasterizerImpl(this);
  s->desc = d;
  FillRasterState(d, depthClamp_, &s->ci);
  *out = s;
  return S_OK;
}

}  // namespace d3dl::impl
