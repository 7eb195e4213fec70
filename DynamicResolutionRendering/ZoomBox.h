// Zoom box: a magnified inset of the back buffer, for inspecting the filters
// (2017 update of the sample). The back buffer is copied to a texture, then a
// bordered quad shows a region around the zoom centre magnified.
#pragma once

#include <string>

#include "ShaderLibrary.h"
#include "d3dl/D3DLike.h"

namespace drr {

class ZoomBox {
 public:
  static constexpr float kMagnification = 4.0f;

  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error);
  // Keeps the old shaders on error (F4).
  bool LoadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error);
  void Release();
  // Called when the back buffer changes size; the copy is made lazily.
  void ReleaseCopy();
  // Draws the box into bbRTV (bound by this call). centre in back-buffer pixels.
  void Render(d3dl::DeviceContext* ctx, d3dl::Texture2D* backBuffer, d3dl::RenderTargetView* bbRTV,
              uint32_t bbW, uint32_t bbH, float centreX, float centreY);
  uint64_t Bytes() const { return m_Bytes; }

 private:
  d3dl::Device* m_Device = nullptr;
  d3dl::ComPtr<d3dl::VertexShader> m_VS;
  d3dl::ComPtr<d3dl::PixelShader> m_ZoomPS, m_BorderPS;
  d3dl::ComPtr<d3dl::Buffer> m_CB;
  d3dl::ComPtr<d3dl::SamplerState> m_Point;
  d3dl::ComPtr<d3dl::DepthStencilState> m_NoDepth;
  d3dl::ComPtr<d3dl::Texture2D> m_Copy;
  d3dl::ComPtr<d3dl::ShaderResourceView> m_CopySRV;
  uint32_t m_CopyW = 0, m_CopyH = 0;
  d3dl::DXGI_FORMAT m_CopyFormat = d3dl::DXGI_FORMAT_UNKNOWN;
  uint64_t m_Bytes = 0;
};

}  // namespace drr
