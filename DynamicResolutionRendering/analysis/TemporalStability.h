// Temporal instability separated from error: the previous frame is moved to
// where its content lies in the current frame (reprojected with the screen
// motion of the reference: its velocity target) before the two are
// differenced, and the reference's own change over the same step is taken
// away. A renderer whose error moves with the scene (blur, a constant
// offset) scores 0; one whose image changes on its own (jitter, crawling
// edges, flicker) does not. On a still camera (no motion) the measure is the
// frame-to-frame change of the test against the reference's (zero when the
// reference is a single still image): the jitter instability. CPU only.
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/ImageMetrics.h"

namespace drr {

// Screen motion of each pixel from the previous frame to this one, in pixels
// (x right, y down): the content at pixel p was at p - motion(p). Empty: no
// motion (a still camera).
struct MotionField {
  uint32_t width = 0, height = 0;
  std::vector<float> dx, dy;  // row-major
  bool Empty() const { return width == 0 || height == 0; }
};

// A motion field from a velocity target holding the UV change of each pixel
// (current minus previous, x right, y down), 2 floats a pixel.
MotionField MotionFromUvVelocity(const std::vector<float>& uv, uint32_t width, uint32_t height);

// `previous` sampled (bilinear) at p - motion(p) for every pixel p; `valid`
// (when given) says which pixels had their source inside the image.
ImageF Reproject(const ImageF& previous, const MotionField& motion, std::vector<uint8_t>* valid = nullptr);

// RMS over the RGB channels of the pixels with a valid source of
//   (test - R(testPrev)) - (reference - R(referencePrev)),
// R the reprojection by `motion` (the identity when it is empty). NaN when
// sizes differ, the motion field does not match, no pixel is valid or a value
// is not finite.
double ReprojectedInstability(const ImageF& testPrev, const ImageF& test, const ImageF& referencePrev,
                              const ImageF& reference, const MotionField& motion);

}  // namespace drr
