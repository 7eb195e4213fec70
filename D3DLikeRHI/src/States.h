// Sampler, blend, depth-stencil and rasterizer state objects (States.cpp):
// D3D11 descriptions decoded into Vulkan create-info pieces at creation.
#pragma once

#include "Objects.h"

namespace d3dl::impl {

class SamplerImpl final : public Child<SamplerState> {
 public:
  using Child::Child;
  ~SamplerImpl() override;
  void GetDesc(SAMPLER_DESC* d) const override {
    if (d) *d = desc;
  }
  void OnDebugName() override;
  SAMPLER_DESC desc{};
  VkSampler sampler = VK_NULL_HANDLE;
};

class BlendImpl final : public Child<BlendState> {
 public:
  using Child::Child;
  void GetDesc(BLEND_DESC* d) const override {
    if (d) *d = desc;
  }
  BLEND_DESC desc{};
  VkPipelineColorBlendAttachmentState att[SIMULTANEOUS_RENDER_TARGET_COUNT]{};
};

class DepthStencilImpl final : public Child<DepthStencilState> {
 public:
  using Child::Child;
  void GetDesc(DEPTH_STENCIL_DESC* d) const override {
    if (d) *d = desc;
  }
  DEPTH_STENCIL_DESC desc{};
  VkPipelineDepthStencilStateCreateInfo ci{};
};

class RasterizerImpl final : public Child<RasterizerState> {
 public:
  using Child::Child;
  void GetDesc(RASTERIZER_DESC* d) const override {
    if (d) *d = desc;
  }
  RASTERIZER_DESC desc{};
  VkPipelineRasterizationStateCreateInfo ci{};
};

// VK_BLEND_FACTOR_MAX_ENUM / false for values outside the D3D11 enums.
VkBlendFactor ToVkBlendFactor(BLEND b);
bool ToVkAddressMode(TEXTURE_ADDRESS_MODE m, VkSamplerAddressMode* out);

void FillBlendState(const BLEND_DESC& d, VkPipelineColorBlendAttachmentState* out);
void FillDepthState(const DEPTH_STENCIL_DESC& d, VkPipelineDepthStencilStateCreateInfo* out);
void FillRasterState(const RASTERIZER_DESC& d, bool depthClamp,
                     VkPipelineRasterizationStateCreateInfo* out);

}  // namespace d3dl::impl
