// Vulkan-backend extension of the immediate context: scaled, filtered copies
// (vkCmdBlitImage). D3D11 has no equivalent (it would draw a full-screen quad).
#pragma once

#include "d3dl/Interfaces.h"

namespace d3dl {

class BlitExtension {
 public:
  // Scaled copy of srcRect of `src` (mip 0, slice 0) to dstRect of `dst`
  // (mip 0, slice 0) with vkCmdBlitImage. The filter is read as a sampler's
  // would be: the magnification half (bit 0x04) when the blit enlarges or
  // keeps the size on both axes, else the minification half (bit 0x10);
  // linear -> VK_FILTER_LINEAR, point -> VK_FILTER_NEAREST (anisotropic is
  // linear). Rectangles are in texels, right/bottom exclusive;
  // a rectangle with right < left (bottom < top) mirrors the image. Both
  // textures must be non-staging colour textures of blittable formats and
  // different resources; barriers and layouts are tracked as for
  // CopySubresourceRegion. Used by --bench to time the physical floor of
  // the scale pass (a fixed-function upscale of the viewport region).
  virtual void BlitRegion(Texture2D* dst, const RECT& dstRect, Texture2D* src,
                          const RECT& srcRect, FILTER filter) = 0;

 protected:
  ~BlitExtension() = default;
};

// The blit extension of a context, or nullptr when its backend has none. No
// reference is added: it lives as long as the context.
BlitExtension* GetBlitExtension(DeviceContext* context);

}  // namespace d3dl
