// What the still sweep (Bench.cpp) and the moving sequences (BenchMoving.cpp)
// share: rendering and capturing frames of a running sample, the options of a
// view, statistics of timings and of per-frame image errors, progress output.
#pragma once

#include <string>
#include <vector>

#include "DynamicResolutionRendering.h"
#include "analysis/ImageMetrics.h"
#include "bench/Bench.h"
#include "bench/BenchReport.h"

namespace drr {

std::string Num2(double v);
Stat Summarise(const std::vector<double>& v);
ImageF ToImage(const Image& img);

// Mean of per-frame values and the half-width of its 95 % confidence
// interval from the means of `blocks` consecutive blocks (Student t): frames
// in a sequence are correlated, block means much less. NaN with < 2 blocks.
struct MeanCi {
  double mean, halfWidth;
};
MeanCi BlockMeanCi(const std::vector<double>& perFrame, int blocks);
// The paired difference a[i] - b[i] (pairs where both are finite): its mean
// and the 95 % interval from the means of `blocks` consecutive blocks of
// pairs (blocks = pairs: per pair, as for views). The pairs must be matched:
// the same frame of two sequences of the same animation times, or the same view.
MeanCi PairedDifferenceCi(const std::vector<double>& a, const std::vector<double>& b, int blocks);
// Where the interval lies against `threshold`: +1 wholly above, -1 wholly
// below, 0 it spans the threshold (or is unknown): cannot decide.
int SideOf(const MeanCi& d, double threshold);
// The two-sided 95 % Student t quantile for `dof` degrees of freedom.
double StudentT95(int dof);

// Renders `frames` frames and returns the records they produced.
std::vector<FrameRecord> RenderFrames(Sample& sample, int frames);
// Renders frames until `ms` milliseconds have passed (none for ms <= 0): a
// warm-up by time, since GPU clocks fall while the CPU computes metrics.
void WarmUpFor(Sample& sample, int ms);
// Renders one frame and returns its back buffer (without GUI).
Image Capture(Sample& sample);
// The sample's options for one view: headless, manual control, no GUI, the
// view's camera and fixed animation time.
Options ViewOptions(const BenchPlan& plan, const BenchView& view);
// GPU statistics of the records: only results that arrived during them and
// belong to one of them; gpuSamples counts the distinct results.
// `rounds`: runs of consecutive frames (the delay check is per run).
void FillGpuTimes(const std::vector<std::vector<FrameRecord>>& rounds, BenchRow* row);

// Largest minus smallest of the finite per-round medians (NaN with fewer than 2).
double RoundSpread(const std::vector<double>& perRound);

class Progress {
 public:
  explicit Progress(size_t total);
  void Step(const std::string& what);

 private:
  size_t total_, done_ = 0;
  bool tty_;
};

// The texture mip bias ablation's configurations (still and moving): a
// row name and the edit of the sweep's options that makes it.
struct MipBiasAblation {
  const char* name;
  void (*edit)(Options&);
};
std::vector<MipBiasAblation> MipBiasAblations(const BenchPlan& plan);

// The moving-camera sequences and the ablations on them (BenchMoving.cpp).
bool MeasureMovingSequences(const BenchPlan& plan, BenchResults* results, Progress* progress,
                            std::string* error);
size_t MovingProgressSteps(const BenchPlan& plan);

// Reads a finished run's rows and header back (BenchReload.cpp).
bool ReloadBenchResults(const std::string& dir, BenchResults* res, std::string* error);

}  // namespace drr
