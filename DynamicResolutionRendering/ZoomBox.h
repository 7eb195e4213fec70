// Zoom box geometry, as the original's ZoomBox.cpp/.hlsl (the pass is
// passes/ZoomBoxPass.h): the back buffer is copied to a texture and a region of 2 % of its width and height around the zoom
// centre is shown 10x magnified (point sampling, clamped) in a box left of
// the screen's centre line, with a white one-pixel frame around the box and
// around the source region, joined by two lines.
#pragma once

#include <array>

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

}  // namespace drr
