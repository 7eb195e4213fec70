// The resolve (scaling) filters of the original, as one table: the GUI and
// command-line names, the pixel shader that scales the dynamic viewport to the
// back buffer (and its fast variant when motion blur has left the velocity in
// the colour's alpha), the sampler it reads with, and whether it is temporal.
// To add a filter: a row of kFilters here, its entry point in a shader file
// (Shaders/PostProcessDynamic.hlsl) and a drr_shader() line in
// Shaders/CMakeLists.txt (Docs/Architecture.md, "Where do I add").
#pragma once

#include <iterator>

namespace drr {

// What a filter does to the frame, which decides the passes and targets
// (FramePlan): Debug shows the whole dynamic RT (None); Spatial scales the
// viewport in one pass; SpatialSharpen adds a sharpening pass over an
// output-size target; TemporalAA is the original's TAA (two final targets,
// jitter); TemporalUpsample is TAAU (output-resolution history).
enum class FilterKind { Debug, Spatial, SpatialSharpen, TemporalAA, TemporalUpsample };

struct FilterInfo {
  const char* name;        // GUI ("Temporal AA")
  const char* option;      // command line ("taa")
  const char* shader;      // in Shaders/CMakeLists.txt
  const char* fastShader;  // with motion blur on (null: the same shader)
  const char* pass;        // in the report's passes_run
  const char* fastPass;
  bool linearSampler;      // s0 linear instead of point, as the original binds for Bilinear and Bicubic
  FilterKind kind;
  bool noisePerFrame = false;  // Noise: a new noise offset each frame (the original's two rand() calls)
};

namespace filter_row {
constexpr const char* kPoint = "PostProcessDynamic_ResolvePS";
// name, option, shader, fast shader, pass, fast pass, linear sampler, kind, noise per frame
constexpr FilterKind kDebug = FilterKind::Debug, kSpatial = FilterKind::Spatial,
                     kSharpen = FilterKind::SpatialSharpen, kTAA = FilterKind::TemporalAA,
                     kTAAU = FilterKind::TemporalUpsample;
// The table, in the order of the original's combo box; port additions after
// it. A row's index is its Filter value.
inline constexpr FilterInfo kFilters[] = {
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
    {"Temporal Upsample (fast)", "taau-fast", "UpscaleTemporal_TemporalUpsampleFastPS", nullptr,
     "TemporalUpsampleFast", "TemporalUpsampleFast", false, kTAAU},
};
}  // namespace filter_row
using filter_row::kFilters;

// In the order of the original's combo box; port additions after it.
enum class Filter : int {
  None = 0,  // debug: the raw dynamic RT
  Point,
  Bilinear,
  Bicubic,
  Noise,
  NoiseOffset,
  TAA,
  TAANoiseOffset,
  TAABasic,
  BicubicBSpline,  // port addition: a true cubic B-spline (the original's Bicubic is not one)
  // Port additions: the primary spatial upscale qualities of r.Upscale.Quality
  // 0..5 (Docs/Upscaling.md), in that order, then the temporal upsample.
  UpscaleNearest,
  UpscaleBilinear,
  UpscaleDirectional,
  UpscaleCatmullRom,
  UpscaleLanczos3,
  UpscaleGaussianUnsharp,
  TAAU,  // temporal upsample: output-resolution history (passes/TemporalUpsamplePass.cpp)
  UpscaleEdgeAdaptive,  // port design: edge-adaptive upscale + contrast-limited sharpening (two passes)
  // TAAU's faster permutation (the document names faster TAAU shaders for
  // r.PostProcessAAQuality 3 and 4): a cross neighbourhood and a bilinear
  // history (Docs/Upscaling.md).
  TAAUFast,
  // A row after these needs no name here: the table decides the count.
  Count = int(std::size(kFilters))
};
static_assert(int(Filter::TAAUFast) < int(Filter::Count));

const FilterInfo& GetFilterInfo(Filter f);
inline const char* FilterName(Filter f) { return GetFilterInfo(f).name; }
inline const char* FilterOption(Filter f) { return GetFilterInfo(f).option; }
inline FilterKind KindOf(Filter f) { return GetFilterInfo(f).kind; }
inline bool IsTAA(Filter f) { return KindOf(f) == FilterKind::TemporalAA; }

// r.Upscale.Quality: the engine's numbering 0..5 (its documentation's 1..6).
constexpr int kUpscaleQualities = 6;
inline Filter UpscaleQualityFilter(int quality) { return Filter(int(Filter::UpscaleNearest) + quality); }
// The temporal upsample keeps its own history at output resolution; it is
// not one of the original's TAA modes (IsTAA is false for it).
inline bool IsTemporalUpsample(Filter f) { return KindOf(f) == FilterKind::TemporalUpsample; }
// The edge-adaptive upscale writes an output-size target that its sharpening pass reads.
inline bool HasSharpenPass(Filter f) { return KindOf(f) == FilterKind::SpatialSharpen; }

// The document's table of primary screen percentages: what each range is
// for. The sample's scales run from 1 % to 200 % (with super sampling);
// outside the table's 50..200 % the range says so.
struct ScreenPercentageRange {
  double lowPercent, highPercent;  // [low, high)
  const char* use;
};
const ScreenPercentageRange& ScreenPercentageRangeOf(double scale);

}  // namespace drr
