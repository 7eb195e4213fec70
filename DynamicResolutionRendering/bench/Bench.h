// --bench: image error against run time, the measurement behind Docs/Results.md.
//
// For each camera view (static cameras, and fixed times on the cinematic
// path), each filter and each scale, the sample renders after a warm-up and
// records PSNR / SSIM / max error against a reference (the same frame at 4x4
// super sampling of the back buffer, box-filtered down, no jitter, no motion
// blur), GPU time per pass (median and quartiles over N frames) and wall time.
// It writes results.csv, results.json, summary.md and PNG plots into --out.
//
// Besides the sweep it records:
//  - "fixed-function-blit" rows per view and scale: a linear vkCmdBlitImage
//    (BlitExtension::BlitRegion) of the viewport region of the captured scene
//    colour to a back-buffer-sized target, timed with its own timestamp
//    queries: another driver path, not a floor. The physical bound of the
//    scale pass is the bandwidth bound (bytes read + written / memory
//    bandwidth), in summary.md with the bandwidth figure and its source;
//  - claim rows on the first view (pixel-shader vs API clear, super sampling,
//    fast vs velocity-reading TAA) and on the cinematic camera (motion blur
//    at 0.71 vs native), judged in summary.md's "Claims" section;
//  - ghosting rows ("ghost <filter>") on the moving cinematic camera: the
//    animation advances by a fixed step per frame (Options::fixedDt) so the
//    animation time of the captured frame is known exactly and the reference
//    is rendered at that time.
#pragma once

#include <string>
#include <vector>

#include "Options.h"

namespace drr {

struct BenchView {
  int camera = 1;
  double time = 0.0;  // animation time of the frame (fixed during the run)
  std::string name;   // "static 1", "cinematic t=12"
};

struct BenchPlan {
  bool quick = false;
  std::string outDir;
  std::string reportFrom;  // --report-from DIR: rewrite the report from DIR's results, render nothing
  std::vector<BenchView> views;
  std::vector<Filter> filters;
  std::vector<float> scales;
  int warmupFrames = 8;
  // Warm-up also lasts at least this long (static views): GPUs drop their
  // clocks while the CPU compares images between configurations.
  int warmupMs = 500;
  int measuredFrames = 24;
  // Interleaved timing of each static view's configurations (see
  // InterleaveTimes): rounds, and warm-up and measured frames per turn.
  int timingRounds = 4;
  int timingWarmup = 2;
  int timingFrames = 6;
  // Each turn of the interleaved timing (still and moving) warms up for at
  // least this long besides timingWarmup frames.
  int timingWarmupMs = 200;
  // FLIP's pixels per degree; 0: the frame full-screen on FLIP's reference
  // display (FlipFullScreenPpd of the back-buffer width).
  double flipPpd = 0;
  uint32_t referenceFactor = 4;
  bool claims = true;          // claim rows on the first view (and motion blur on the cinematic camera)
  bool ghosting = true;        // ghosting rows on the cinematic camera
  double ghostTime = 12.0;     // animation time of the captured ghosting frame (s)
  double ghostStep = 1.0 / 30.0;  // animation step per frame (Options::fixedDt)
  int ghostFrames = 24;        // frames rendered (moving) before the capture
  // Moving-camera sequences (BenchMoving.cpp): the cinematic camera at each
  // speed (1 = the animation's 1/30 s per frame), movingWarmup frames, then
  // movingFrames frames each compared with the reference rendered at the same
  // animation time; every movingFilters x movingScales, plus native.
  bool moving = true;
  std::vector<double> movingSpeeds;
  std::vector<Filter> movingFilters;
  std::vector<float> movingScales;
  int movingWarmup = 8;
  int movingFrames = 60;
  double movingStart = 8.0;  // animation time of the first warm-up frame (s)
  bool ablations = true;     // symmetric jitter (still and moving), fast TAA (moving)
  bool sweepMotionBlur = false;  // --sweep-motion-blur: the still sweep with motion blur on
  double memoryBandwidthGBs = 0;  // --memory-bandwidth; 0: measured on the host for CPU rasterisers
  Options base;  // size, scene, motion blur, symmetric TAA ... from the command line
};

// Builds the plan from the command line: --bench, --quick, --out DIR, plus
// the sample's own options; --camera, --filter and --scale narrow the sweep.
// Returns 0, or an exit code (2) with message set; message holds usage on --help.
int ParseBenchCommandLine(const std::vector<std::string>& args, BenchPlan* plan,
                          std::string* message);

// The pixels per degree FLIP uses in this plan.
double FlipPpd(const BenchPlan& plan);

// Runs the plan and writes the outputs. Returns the process exit code.
int RunBench(const BenchPlan& plan);

// Entry point used by main() when the arguments contain --bench.
int BenchMain(int argc, char** argv);

bool HasBenchFlag(int argc, char** argv);

}  // namespace drr
