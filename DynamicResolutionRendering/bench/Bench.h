// --bench: image error against run time, the measurement behind Docs/Results.md.
//
// For each camera view (static cameras, and fixed times on the cinematic
// path), each filter and each scale, the sample renders after a warm-up and
// records PSNR / SSIM / max error against a reference (the same frame at 4x4
// super sampling of the back buffer, box-filtered down, no jitter, no motion
// blur), GPU time per pass (median and quartiles over N frames) and wall time.
// It writes results.csv, results.json, summary.md and PNG plots into --out.
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
  std::vector<BenchView> views;
  std::vector<Filter> filters;
  std::vector<float> scales;
  int warmupFrames = 8;
  int measuredFrames = 24;
  uint32_t referenceFactor = 4;
  Options base;  // size, scene, motion blur, symmetric TAA ... from the command line
};

// Builds the plan from the command line: --bench, --quick, --out DIR, plus
// the sample's own options; --camera, --filter and --scale narrow the sweep.
// Returns 0, or an exit code (2) with message set; message holds usage on --help.
int ParseBenchCommandLine(const std::vector<std::string>& args, BenchPlan* plan,
                          std::string* message);

// Runs the plan and writes the outputs. Returns the process exit code.
int RunBench(const BenchPlan& plan);

// Entry point used by main() when the arguments contain --bench.
int BenchMain(int argc, char** argv);

bool HasBenchFlag(int argc, char** argv);

}  // namespace drr
