// FLIP (Andersson et al. 2020, "FLIP: A Difference Evaluator for Alternating
// Images"), the LDR variant, written from the paper's description: a
// perceptual error in [0, 1] per pixel for a viewer who flips between the two
// images. Colour: sRGB -> linear -> XYZ -> YyCxCz (linearised opponent
// space), each channel filtered with its contrast-sensitivity Gaussian(s),
// back to linear RGB (clamped), to L*a*b*, Hunt-adjusted (a, b scaled by
// 0.01 L), HyAB distance, raised to 0.7 and mapped to [0, 1] with the largest
// distance (Hunt-adjusted green against blue). Features: edges (first
// derivative of a Gaussian) and points (second derivative) of the luminance,
// the larger difference of the two, to the power 0.5. Per pixel:
// error = colour ^ (1 - feature). CPU only.
#pragma once

#include <array>

#include "analysis/ImageMetrics.h"

namespace drr {

// Pixels per degree of a viewer at `distanceM` from a display `widthM` wide
// with `widthPixels` columns; the paper's default (0.7 m, 0.7 m, 3840) is ~67.
double FlipPixelsPerDegree(double distanceM, double widthM, double widthPixels);
inline constexpr double kFlipDefaultPpd = 67.0;
// FLIP's reference display: 0.7 m wide, 3840 pixels across, seen from 0.7 m.
inline constexpr double kFlipDisplayWidthM = 0.7, kFlipDisplayPixels = 3840, kFlipDisplayDistanceM = 0.7;
// A frame `widthPixels` wide shown full-screen on that display (its pixels
// stretched to the display's width): 67.02 x widthPixels / 3840.
double FlipFullScreenPpd(double widthPixels);

// Radius in pixels of the contrast-sensitivity filters (3 standard deviations
// of the widest Gaussian) and of the feature detectors (3 sigma, sigma =
// 0.5 * 0.082 degrees * ppd).
int FlipCsfRadius(double ppd);
int FlipFeatureRadius(double ppd);

// Display-encoded sRGB in [0, 1] to CIE L*a*b* (D65), and the Hunt adjustment.
std::array<double, 3> FlipSrgbToLab(const std::array<double, 3>& srgb);
std::array<double, 3> FlipHunt(const std::array<double, 3>& lab);
// HyAB distance: |dL| + Euclidean distance of (a, b).
double FlipHyAB(const std::array<double, 3>& lab1, const std::array<double, 3>& lab2);
// The largest colour distance: HyAB of Hunt-adjusted green and blue, ^ 0.7.
double FlipMaxColorDistance();
// A colour distance (HyAB of Hunt-adjusted colours) mapped to [0, 1].
double FlipColorError(double hyab);

struct FlipResult {
  double mean = 0.0;  // mean per-pixel error, [0, 1]
  bool valid = false; // false when the sizes differ or an input is not RGB
  ImageF map;         // per-pixel error (one channel), filled when asked for
};

// FLIP of `test` against `reference` (display-encoded RGB(A), alpha ignored).
FlipResult ComputeFlip(const ImageF& reference, const ImageF& test, double ppd = kFlipDefaultPpd,
                       bool keepMap = false);

}  // namespace drr
