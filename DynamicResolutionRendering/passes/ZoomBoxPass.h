// The zoom box (ZoomBox.h): the back buffer copied to a texture of its size
// and format (the render-target table's RT::ZoomBoxCopy), a region around
// the zoom centre drawn 10x magnified with point sampling, and the white
// frame and source marker over it.
#pragma once

#include "ZoomBox.h"
#include "passes/FullScreenPass.h"

namespace drr {

class ZoomBoxPass : public FullScreenPass {
 public:
  using FullScreenPass::FullScreenPass;
  bool Init(d3dl::Device* device, std::string* error) override;
  bool LoadShaders(ShaderLoad& load) override;
  void Release() override;

 protected:
  bool Record(PassFrame& f) override;

 private:
  struct Constants {  // cbZoomBox in Shaders/ZoomBox.hlsl
    float quad[4];
    float source[4];
    float frame[12][4];  // xy used
  };
  d3dl::ComPtr<d3dl::VertexShader> m_ZoomVS, m_FrameVS;
  d3dl::ComPtr<d3dl::PixelShader> m_ZoomPS, m_FramePS;
  ConstantBuffer<Constants> m_CB;
};

}  // namespace drr
