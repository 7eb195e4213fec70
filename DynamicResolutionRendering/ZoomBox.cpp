#include "ZoomBox.h"

namespace drr {


ZoomBoxGeometry MakeZoomBoxGeometry(float u, float v) {
  using G = ZoomBoxGeometry;
  G g;
  g.quad = {G::kBoxRight, G::kBoxBottom, G::kBoxLeft, G::kBoxTop};
  // The box's bottom shows the source's bottom (larger v), its right the source's right.
  g.source = {u + G::kSourceHalf, v + G::kSourceHalf, u - G::kSourceHalf, v - G::kSourceHalf};
  const float l = G::kBoxLeft - G::kFrameOutset, r = G::kBoxRight + G::kFrameOutset;
  const float b = G::kBoxBottom - G::kFrameOutset, t = G::kBoxTop + G::kFrameOutset;
  const float cx = (u - 0.5f) * 2.0f, cy = (0.5f - v) * 2.0f, m = G::kMarkerHalf;
  g.frame = {{{r, b}, {r, t}, {l, t}, {l, b}, {r, b},  // frame, ending at its bottom-right
              {cx - m, cy - m}, {cx - m, cy + m}, {cx + m, cy + m}, {cx + m, cy - m}, {cx - m, cy - m},  // marker
              {cx - m, cy + m}, {r, t}}};  // up its left side, back to the frame's top-right
  return g;
}

}  // namespace drr
