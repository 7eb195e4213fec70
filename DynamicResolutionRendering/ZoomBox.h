// Zoom box, as the original's ZoomBox.cpp/.hlsl: the back buffer is copied to
// a texture and a region of 2 % of its width and height around the zoom
// centre is shown 10x magnified (point sampling, clamped) in a box left of
// the screen's centre line, with a white one-pixel frame around the box and
// around the source region, joined by two lines.
#pragma once

#include <array>
#include <string>

#include "ShaderLibrary.h"
#include "d3dl/D3DLike.h"

namespace drr {

// The original's numbers, in normalised device coordinates (+Y up) and UV.
struct ZoomBoxGeometry {
  static constexpr float kBoxLeft = -0.95f, kBoxRight = -0.55f, kBoxBottom = -0.2f, kBoxTop = 0.2f;
  static constexpr float kSourceHalf = 0.01f;   // UV half size of the magnified region
  static constexpr float kFrameOutset = 0.01f;  // NDC, frame around the box
  static constexpr float kMarkerHalf = 0.02f;   // NDC half size of the source marker
  // (box width in NDC / 2) / (2 kSourceHalf): the same on both axes.
  static constexpr float kMagnification = (kBoxRight - kBoxLeft) / 2.0f / (2.0f * kSourceHalf);

  // The quad as a strip of 4 vertices: the first at (right, bottom), the
  // last at (left, top); x, y of the first then of the last.
  std::array<float, 4> quad{};
  std::array<float, 4> source{};  // UV at the first and the last vertex
  // One line strip: the frame, a line to the marker's bottom-left corner,
  // the marker, then a line back to the frame's top-right corner.
  std::array<std::array<float, 2>, 12> frame{};
};
// centre in UV of the back buffer (0..1, unclamped as the original's).
ZoomBoxGeometry MakeZoomBoxGeometry(float centreU, float centreV);

class ZoomBox {
 public:
  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error);
  // Keeps the old shaders on error (F4).
  bool LoadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error);
  void Release();
  // Called when the back buffer changes size; the copy is made lazily.
  void ReleaseCopy();
  // Draws the box into bbRTV (bound by this call); the zoom centre in UV
  // of the back buffer (the original's SetZoomCenterPosition).
  void Render(d3dl::DeviceContext* ctx, d3dl::Texture2D* backBuffer, d3dl::RenderTargetView* bbRTV,
              uint32_t bbW, uint32_t bbH, float centreU, float centreV);
  uint64_t Bytes() const { return m_Bytes; }

 private:
  bool EnsureCopy(d3dl::Texture2D* backBuffer);
  void Upload(d3dl::DeviceContext* ctx, const ZoomBoxGeometry& g);

  d3dl::Device* m_Device = nullptr;
  d3dl::ComPtr<d3dl::VertexShader> m_ZoomVS, m_FrameVS;
  d3dl::ComPtr<d3dl::PixelShader> m_ZoomPS, m_FramePS;
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
