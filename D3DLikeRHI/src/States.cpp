// Sampler, blend, depth-stencil and rasterizer state objects: D3D11
// descriptions decoded into Vulkan create-info pieces once, at creation.
// Descriptions are checked by Validate*Desc first.
#include <cmath>

#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {

bool ToVkAddressMode(TEXTURE_ADDRESS_MODE m, VkSamplerAddressMode* out) {
  switch (m) {
    case TEXTURE_ADDRESS_WRAP: *out = VK_SAMPLER_ADDRESS_MODE_REPEAT; return true;
    case TEXTURE_ADDRESS_MIRROR: *out = VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT; return true;
    case TEXTURE_ADDRESS_CLAMP: *out = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE; return true;
    case TEXTURE_ADDRESS_BORDER: *out = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER; return true;
    case TEXTURE_ADDRESS_MIRROR_ONCE: *out = VK_SAMPLER_ADDRESS_MODE_MIRROR_CLAMP_TO_EDGE; return true;
  }
  return false;
}

VkBlendFactor ToVkBlendFactor(BLEND b) {
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

namespace {
// Alpha channel: colour factors become their alpha forms (as D3D does).
VkBlendFactor ToBlendAlpha(BLEND b) {
  switch (b) {
    case BLEND_SRC_COLOR: return VK_BLEND_FACTOR_SRC_ALPHA;
    case BLEND_INV_SRC_COLOR: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    case BLEND_DEST_COLOR: return VK_BLEND_FACTOR_DST_ALPHA;
    case BLEND_INV_DEST_COLOR: return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
    case BLEND_BLEND_FACTOR: return VK_BLEND_FACTOR_CONSTANT_ALPHA;
    case BLEND_INV_BLEND_FACTOR: return VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_ALPHA;
    default: return ToVkBlendFactor(b);
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

// Vulkan has three fixed border colours (without custom border colours):
// the nearest one, with a warning when it is none of them and used.
VkBorderColor ToBorderColor(DeviceImpl& dev, const SAMPLER_DESC& d) {
  const float* c = d.BorderColor;
  if (c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 0) return VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  if (c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 1) return VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK;
  if (c[0] == 1 && c[1] == 1 && c[2] == 1 && c[3] == 1) return VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  const float lum = (c[0] + c[1] + c[2]) / 3.0f;
  const VkBorderColor nearest = c[3] < 0.5f ? VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK
                                : lum < 0.5f ? VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK
                                             : VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  const bool border = d.AddressU == TEXTURE_ADDRESS_BORDER || d.AddressV == TEXTURE_ADDRESS_BORDER ||
                      d.AddressW == TEXTURE_ADDRESS_BORDER;
  if (border)
    dev.Log(LogLevel::Warning, "CreateSamplerState: BorderColor (%g, %g, %g, %g) has no Vulkan equivalent; using %s",
            c[0], c[1], c[2], c[3],
            nearest == VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK ? "transparent black"
            : nearest == VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK    ? "opaque black"
                                                               : "opaque white");
  return nearest;
}

// Filter, address modes and LOD of a validated description.
void FillSampler(DeviceImpl& dev, const SAMPLER_DESC& d, VkSamplerCreateInfo* ci) {
  const uint32_t f = d.Filter;
  ci->minFilter = (f & 0x10) ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  ci->magFilter = (f & 0x04) ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  ci->mipmapMode = (f & 0x01) ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  ToVkAddressMode(d.AddressU, &ci->addressModeU);
  ToVkAddressMode(d.AddressV, &ci->addressModeV);
  ToVkAddressMode(d.AddressW, &ci->addressModeW);
  if (!dev.features().mirrorOnce) {
    for (VkSamplerAddressMode* m : {&ci->addressModeU, &ci->addressModeV, &ci->addressModeW})
      if (*m == VK_SAMPLER_ADDRESS_MODE_MIRROR_CLAMP_TO_EDGE) {
        dev.Log(LogLevel::Warning, "CreateSamplerState: TEXTURE_ADDRESS_MIRROR_ONCE needs samplerMirrorClampToEdge; using CLAMP");
        *m = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
      }
  }
  const auto& lim = dev.props().limits;
  ci->mipLodBias = std::clamp(d.MipLODBias, -lim.maxSamplerLodBias, lim.maxSamplerLodBias);
  if ((f & 0x40) && dev.features().anisotropy) {
    ci->anisotropyEnable = VK_TRUE;
    ci->maxAnisotropy = std::min(static_cast<float>(d.MaxAnisotropy), lim.maxSamplerAnisotropy);
  }
  if (((f >> 7) & 3) == 1) {
    ci->compareEnable = VK_TRUE;
    ci->compareOp = ToVkCompare(d.ComparisonFunc);
  }
  ci->minLod = std::max(0.0f, d.MinLOD);
  ci->maxLod = d.MaxLOD >= FLOAT32_MAX ? VK_LOD_CLAMP_NONE : std::max(ci->minLod, d.MaxLOD);
}

// The fixed-function state objects: a validated description decoded once.
template <class Impl, class Desc, class Iface, class Decode>
HRESULT MakeState(DeviceImpl* dev, HRESULT valid, const Desc* desc, Iface** out, Decode decode) {
  if (FAILED(valid)) return valid;
  auto* s = new Impl(dev);
  s->desc = *desc;
  decode(*desc, s);
  *out = s;
  return S_OK;
}

}  // namespace

SamplerImpl::~SamplerImpl() { dev_->Defer(VK_OBJECT_TYPE_SAMPLER, reinterpret_cast<uint64_t>(sampler)); }
void SamplerImpl::OnDebugName() { dev_->SetName(VK_OBJECT_TYPE_SAMPLER, reinterpret_cast<uint64_t>(sampler), name_); }

HRESULT DeviceImpl::CreateSamplerState(const SAMPLER_DESC* desc, SamplerState** out) {
  if (out) *out = nullptr;
  const HRESULT valid = ValidateSamplerDesc(*this, desc, out);
  if (FAILED(valid)) return valid;
  const SAMPLER_DESC& d = *desc;
  VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  FillSampler(*this, d, &ci);
  // Reduction bits 7-8: 2 minimum, 3 maximum.
  const uint32_t reduction = (d.Filter >> 7) & 3;
  VkSamplerReductionModeCreateInfo red{VK_STRUCTURE_TYPE_SAMPLER_REDUCTION_MODE_CREATE_INFO};
  if (reduction >= 2) {
    red.reductionMode = reduction == 2 ? VK_SAMPLER_REDUCTION_MODE_MIN : VK_SAMPLER_REDUCTION_MODE_MAX;
    ci.pNext = &red;
  }
  ci.borderColor = ToBorderColor(*this, d);
  auto* s = new SamplerImpl(this);
  s->desc = d;
  if (vkCreateSampler(device_, &ci, nullptr, &s->sampler) != VK_SUCCESS) {
    Log(LogLevel::Error, "CreateSamplerState: vkCreateSampler failed");
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
    a.srcColorBlendFactor = ToVkBlendFactor(r.SrcBlend);
    a.dstColorBlendFactor = ToVkBlendFactor(r.DestBlend);
    a.colorBlendOp = ToBlendOp(r.BlendOp);
    a.srcAlphaBlendFactor = ToBlendAlpha(r.SrcBlendAlpha);
    a.dstAlphaBlendFactor = ToBlendAlpha(r.DestBlendAlpha);
    a.alphaBlendOp = ToBlendOp(r.BlendOpAlpha);
    a.colorWriteMask = r.RenderTargetWriteMask & 0xF;  // same bit order R,G,B,A
  }
}

HRESULT DeviceImpl::CreateBlendState(const BLEND_DESC* desc, BlendState** out) {
  if (out) *out = nullptr;
  return MakeState<BlendImpl>(this, ValidateBlendDesc(*this, desc, out), desc, out,
                              [](const BLEND_DESC& d, BlendImpl* s) { FillBlendState(d, s->att); });
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
  if (out) *out = nullptr;
  return MakeState<DepthStencilImpl>(this, ValidateDepthStencilDesc(*this, desc, out), desc, out,
                                     [](const DEPTH_STENCIL_DESC& d, DepthStencilImpl* s) { FillDepthState(d, &s->ci); });
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
  if (out) *out = nullptr;
  const bool depthClamp = features_.depthClamp;
  return MakeState<RasterizerImpl>(
      this, ValidateRasterizerDesc(*this, desc, out), desc, out,
      [depthClamp](const RASTERIZER_DESC& d, RasterizerImpl* s) { FillRasterState(d, depthClamp, &s->ci); });
}

}  // namespace d3dl::impl
