#include "ResolveFilters.h"

#include <iterator>

namespace drr {

namespace {
constexpr const char* kPoint = "PostProcessDynamic_ResolvePS";
// name, option, shader, fast shader, pass, fast pass, linear sampler, kind, noise per frame
constexpr FilterKind kDebug = FilterKind::Debug, kSpatial = FilterKind::Spatial,
                     kSharpen = FilterKind::SpatialSharpen, kTAA = FilterKind::TemporalAA,
                     kTAAU = FilterKind::TemporalUpsample;
constexpr FilterInfo kFilters[] = {
    {"None (Debug)", "none", kPoint, nullptr, "ResolveNone", "ResolveNone", false, kDebug},
    {"Point", "point", kPoint, nullptr, "ResolvePoint", "ResolvePoint", false, kSpatial},
    {"Bilinear", "bilinear", kPoint, nullptr, "ResolveBilinear", "ResolveBilinear", true, kSpatial},
    {"Bicubic", "bicubic", "PostProcessDynamic_BicubicPS", nullptr, "ResolveBicubic", "ResolveBicubic", true, kSpatial},
    {"Noise", "noise", "PostProcessDynamic_NoisePS", nullptr, "ResolveNoise", "ResolveNoise", false, kSpatial, true},
    {"Noise Offset", "noise-offset", "PostProcessDynamic_NoiseOffsetPS", nullptr, "ResolveNoiseOffset",
     "ResolveNoiseOffset", false, kSpatial},
    {"Temporal AA", "taa", "PostProcessDynamic_TAAPS", "PostProcessDynamic_TAAFastPS", "ResolveTAA",
     "ResolveTAAFast", false, kTAA},
    {"TAA Noise Off.", "taa-noise-offset", "PostProcessDynamic_TAANoiseOffsetPS",
     "PostProcessDynamic_TAANoiseOffsetFastPS", "ResolveTAANoiseOffset", "ResolveTAANoiseOffsetFast", false, kTAA},
    {"TAA Basic", "taa-basic", "PostProcessDynamic_TAABasicPS", nullptr, "ResolveTAABasic", "ResolveTAABasic", false,
     kTAA},
    {"Bicubic B-spline", "bicubic-bspline", "PostProcessDynamic_BicubicBSplinePS", nullptr, "ResolveBicubicBSpline",
     "ResolveBicubicBSpline", false, kSpatial},
    {"Upscale 0: Nearest", "upscale-nearest", "UpscaleSpatial_NearestPS", nullptr, "UpscaleNearest",
     "UpscaleNearest", false, kSpatial},
    {"Upscale 1: Bilinear", "upscale-bilinear", "UpscaleSpatial_BilinearPS", nullptr, "UpscaleBilinear",
     "UpscaleBilinear", false, kSpatial},
    {"Upscale 2: Directional", "upscale-directional", "UpscaleSpatial_DirectionalPS", nullptr,
     "UpscaleDirectional", "UpscaleDirectional", false, kSpatial},
    {"Upscale 3: Catmull-Rom", "upscale-catmull-rom", "UpscaleSpatial_CatmullRomPS", nullptr, "UpscaleCatmullRom",
     "UpscaleCatmullRom", false, kSpatial},
    {"Upscale 4: Lanczos 3", "upscale-lanczos3", "UpscaleSpatial_Lanczos3PS", nullptr, "UpscaleLanczos3",
     "UpscaleLanczos3", false, kSpatial},
    {"Upscale 5: Gauss. unsharp", "upscale-gaussian-unsharp", "UpscaleSpatial_GaussianUnsharpPS", nullptr,
     "UpscaleGaussianUnsharp", "UpscaleGaussianUnsharp", false, kSpatial},
    {"Temporal Upsample", "taau", "UpscaleTemporal_TemporalUpsamplePS", nullptr, "TemporalUpsample",
     "TemporalUpsample", false, kTAAU},
    {"Edge-adaptive + sharpen", "upscale-edge-adaptive", "UpscaleSpatial_EdgeAdaptivePS", nullptr,
     "UpscaleEdgeAdaptive", "UpscaleEdgeAdaptive", false, kSharpen},
};
static_assert(std::size(kFilters) == size_t(Filter::Count));
constexpr FilterInfo kUnknown{"?", "?", kPoint, nullptr, "ResolvePoint", "ResolvePoint", false, kSpatial};
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
