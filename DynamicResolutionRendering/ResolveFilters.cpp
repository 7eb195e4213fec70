#include "ResolveFilters.h"

#include <iterator>

namespace drr {

namespace {
constexpr const char* kPoint = "PostProcessDynamic_ResolvePS";
// name, option, shader, fast shader, pass, fast pass, linear sampler, temporal
constexpr FilterInfo kFilters[] = {
    {"None (Debug)", "none", kPoint, nullptr, "ResolveNone", "ResolveNone", false, false},
    {"Point", "point", kPoint, nullptr, "ResolvePoint", "ResolvePoint", false, false},
    {"Bilinear", "bilinear", kPoint, nullptr, "ResolveBilinear", "ResolveBilinear", true, false},
    {"Bicubic", "bicubic", "PostProcessDynamic_BicubicPS", nullptr, "ResolveBicubic", "ResolveBicubic", true, false},
    {"Noise", "noise", "PostProcessDynamic_NoisePS", nullptr, "ResolveNoise", "ResolveNoise", false, false},
    {"Noise Offset", "noise-offset", "PostProcessDynamic_NoiseOffsetPS", nullptr, "ResolveNoiseOffset",
     "ResolveNoiseOffset", false, false},
    {"Temporal AA", "taa", "PostProcessDynamic_TAAPS", "PostProcessDynamic_TAAFastPS", "ResolveTAA",
     "ResolveTAAFast", false, true},
    {"TAA Noise Off.", "taa-noise-offset", "PostProcessDynamic_TAANoiseOffsetPS",
     "PostProcessDynamic_TAANoiseOffsetFastPS", "ResolveTAANoiseOffset", "ResolveTAANoiseOffsetFast", false, true},
    {"TAA Basic", "taa-basic", "PostProcessDynamic_TAABasicPS", nullptr, "ResolveTAABasic", "ResolveTAABasic", false,
     true},
    {"Bicubic B-spline", "bicubic-bspline", "PostProcessDynamic_BicubicBSplinePS", nullptr, "ResolveBicubicBSpline",
     "ResolveBicubicBSpline", false, false},
    {"Upscale 0: Nearest", "upscale-nearest", "UpscaleSpatial_NearestPS", nullptr, "UpscaleNearest",
     "UpscaleNearest", false, false},
    {"Upscale 1: Bilinear", "upscale-bilinear", "UpscaleSpatial_BilinearPS", nullptr, "UpscaleBilinear",
     "UpscaleBilinear", false, false},
    {"Upscale 2: Directional", "upscale-directional", "UpscaleSpatial_DirectionalPS", nullptr,
     "UpscaleDirectional", "UpscaleDirectional", false, false},
    {"Upscale 3: Catmull-Rom", "upscale-catmull-rom", "UpscaleSpatial_CatmullRomPS", nullptr, "UpscaleCatmullRom",
     "UpscaleCatmullRom", false, false},
    {"Upscale 4: Lanczos 3", "upscale-lanczos3", "UpscaleSpatial_Lanczos3PS", nullptr, "UpscaleLanczos3",
     "UpscaleLanczos3", false, false},
    {"Upscale 5: Gauss. unsharp", "upscale-gaussian-unsharp", "UpscaleSpatial_GaussianUnsharpPS", nullptr,
     "UpscaleGaussianUnsharp", "UpscaleGaussianUnsharp", false, false},
    {"Temporal Upsample", "taau", "UpscaleTemporal_TemporalUpsamplePS", nullptr, "TemporalUpsample",
     "TemporalUpsample", false, false},
    {"Edge-adaptive + sharpen", "upscale-edge-adaptive", "UpscaleSpatial_EdgeAdaptivePS", nullptr,
     "UpscaleEdgeAdaptive", "UpscaleEdgeAdaptive", false, false},
};
static_assert(std::size(kFilters) == size_t(Filter::Count));
constexpr FilterInfo kUnknown{"?", "?", kPoint, nullptr, "ResolvePoint", "ResolvePoint", false, false};
}  // namespace

const FilterInfo& GetFilterInfo(Filter f) {
  const auto i = static_cast<size_t>(f);
  return i < std::size(kFilters) ? kFilters[i] : kUnknown;
}

namespace {
constexpr ScreenPercentageRange kRanges[] = {
    {0.0, 50.0, "below the document's table: detail is lost faster than TAAU can recover it"},
    {50.0, 71.0, "the cheapest range: TAAU targeting 4K on desktops and consoles"},
    {71.0, 100.0, "rendering at ordinary DPI on desktops and consoles"},
    {100.0, 200.01, "super sampling, as far as render-target memory allows"},
};
}  // namespace

const ScreenPercentageRange& ScreenPercentageRangeOf(double scale) {
  const double percent = scale * 100.0;
  for (const ScreenPercentageRange& r : kRanges)
    if (percent < r.highPercent) return r;
  return kRanges[std::size(kRanges) - 1];
}

}  // namespace drr
