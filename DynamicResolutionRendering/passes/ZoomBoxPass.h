// The zoom box (ZoomBox.h): the back buffer copied to a texture of its size
// and format, a region around the zoom centre drawn 10x magnified with point
// sampling, and the white frame and source marker over it.
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
  // Called when the back buffer changes size; the copy is made lazily.
  void ReleaseCopy();
  uint64_t Bytes() const { return m_Bytes; }

 protected:
  bool Record(PassFrame& f) override;

 private:
  struct Constants {  // cbZoomBox in Shaders/ZoomBox.hlsl
    float quad[4];
    float source[4];
    float frame[12][4];  // xy used
  };
  bool EnsureCopy(d3dl::Texture2D* backBuffer);

  d3dl::Device* m_Device = nullptr;
  d3dl::ComPtr<d3dl::VertexShader> m_ZoomVS, m_FrameVS;
  d3dl::ComPtr<d3dl::PixelShader> m_ZoomPS, m_FramePS;
  ConstantBuffer<Constants> m_CB;
  d3dl::ComPtr<d3dl::Texture2D> m_Copy;
  d3dl::ComPtr<d3dl::ShaderResourceView> m_CopySRV;
  uint32_t m_CopyW = 0, m_CopyH = 0;
  d3dl::DXGI_FORMAT m_CopyFormat = d3dl::DXGI_FORMAT_UNKNOWN;
  uint64_t m_Bytes = 0;
};

}  // namespace drr
