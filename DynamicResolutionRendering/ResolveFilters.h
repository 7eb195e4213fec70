// The resolve (scaling) filters of the original, as one table: the GUI and
// command-line names, the pixel shader that scales the dynamic viewport to the
// back buffer (and its fast variant when motion blur has left the velocity in
// the colour's alpha), the sampler it reads with, and whether it is temporal.
// To add a filter: a value here, a row in ResolveFilters.cpp, its entry point
// in Shaders/PostProcessDynamic.hlsl and a drr_shader() line in
// Shaders/CMakeLists.txt (Docs/Architecture.md).
#pragma once

namespace drr {

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
  Count
};

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
