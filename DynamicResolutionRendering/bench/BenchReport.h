// Outputs of --bench: results.csv, results.json, summary.md and the plots.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "analysis/ImageMetrics.h"

namespace drr {

struct BenchPlan;

struct Stat {
  // NaN when nothing was measured (e.g. the reference-repeat row).
  double median = std::numeric_limits<double>::quiet_NaN();
  double p25 = std::numeric_limits<double>::quiet_NaN();
  double p75 = std::numeric_limits<double>::quiet_NaN();
};

struct BenchRow {
  std::string view, filter;  // filter: a --filter value, "native", "reference-repeat" or an extra
  double scale = 1.0;
  float viewportW = 0, viewportH = 0;
  ImageError error;
  Stat gpuFrame, gpuClear, gpuScene, gpuPost, gpuScale, wall;  // milliseconds
  int gpuSamples = 0;  // distinct GPU results behind the gpu* statistics
  // Ghosting / moving-camera rows: animation time of the captured frame, the
  // fraction of pixels whose largest RGB difference from the same filter's
  // settled image of that animation time (camera held still) is above 0.1
  // (ghost trails: what the motion adds), and the PSNR against the native image of the
  // same frame (motion-blur claim). NaN where not measured.
  double animTime = std::numeric_limits<double>::quiet_NaN();
  double ghostFraction = std::numeric_limits<double>::quiet_NaN();
  double psnrVsNative = std::numeric_limits<double>::quiet_NaN();
  // Still (one frozen animation time) or moving (a sequence on the cinematic
  // camera at `speed`, image numbers the mean over qualityFrames frames).
  bool moving = false;
  double speed = 0.0;
  int qualityFrames = 1;       // distinct frames behind the image numbers
  bool superSampling = false;  // 2x render targets allowed in this row
  // FLIP (mean per-pixel, LDR, at BenchResults::flipPpd; lower is better);
  // moving rows: mean over frames, with the 95 % interval half-widths of
  // PSNR and FLIP over blocks of frames. Instability (TemporalStability.h):
  // moving rows, the mean over frame pairs of ReprojectedInstability with the
  // reference's velocity; still rows, the mean RMS change between consecutive
  // frames of a still camera (jitter instability). flicker: the former
  // measure, the error image's frame-to-frame change WITHOUT motion
  // compensation (it follows the error's size; kept in the data only).
  double flip = std::numeric_limits<double>::quiet_NaN();
  double flipCi = std::numeric_limits<double>::quiet_NaN();
  double psnrCi = std::numeric_limits<double>::quiet_NaN();
  double flicker = std::numeric_limits<double>::quiet_NaN();
  double instability = std::numeric_limits<double>::quiet_NaN();
  // Moving rows: the per-frame values behind the means (results.json only),
  // instability from the second frame on. Empty on still rows (one per view).
  std::vector<double> framePsnr, frameFlip, frameInstability;
  // Interleaved timing: the median of each round (results.json only), so a
  // time verdict can be held against the spread of repeated rounds.
  std::vector<double> roundFrameMs, roundClearMs, roundScaleMs;
};

// Filter names of the rows that are not part of the filter x scale sweep.
// The fixed-function blit: another driver path for the scale pass (a linear
// vkCmdBlitImage), not a lower bound; the bandwidth bound is the physical one.
inline constexpr const char* kFixedBlit = "fixed-function-blit";
inline constexpr const char* kReferenceRepeat = "reference-repeat";
// Ablation rows: TAA with the symmetric jitter pair; the fast TAA (velocity
// from the motion-blur alpha, motion blur on) and native with motion blur on.
inline constexpr const char* kTaaSymmetric = "taa symmetric-jitter";
inline constexpr const char* kTaaFast = "taa fast (motion blur on)";
inline constexpr const char* kNativeMotionBlur = "native (motion blur on)";
// Texture mip bias ablation (still and moving): the original's TAA without
// its sampler's MipLODBias -0.5, TAAU without its automatic view mip bias.
inline constexpr const char* kTaaNoMipBias = "taa mip-bias 0";
inline constexpr const char* kTaauNoMipBias = "taau no-auto-mip-bias";

struct BenchResults {
  const BenchPlan* plan = nullptr;
  std::string adapter, driver;
  std::vector<BenchRow> rows;
  bool softwareAdapter = false;  // a CPU rasteriser: its device memory is host memory
  double seconds = 0;
  uint64_t validationMessages = 0;
  // Memory bandwidth behind the bandwidth bound of the scale pass (GB/s, NaN:
  // unknown), and where the figure comes from.
  double bandwidthGBs = std::numeric_limits<double>::quiet_NaN();
  std::string bandwidthSource;
  double flipPpd = std::numeric_limits<double>::quiet_NaN();  // FLIP's pixels per degree in this run
  std::string flipDisplay;  // how flipPpd was chosen
  // When set, results.csv and results.json are rewritten into this folder as
  // each row is added (Add), so an interrupted run keeps what it measured.
  std::string partialDir;
  bool complete = false;  // every planned row measured
  void Add(BenchRow row);
};

// The article's scale-pass cost ratios to point filtering at 0.71x (Japanese
// translation of the article's figures). 0 = not given.
double ArticleScaleRatio(const std::string& filter);

bool WriteBenchOutputs(const BenchResults& results, const std::string& outDir,
                       std::string* error);

}  // namespace drr
