// Sections of summary.md on still and moving quality, ablations, iso tables
// and the labelled fronts (BenchReportMoving.cpp), and the points they and
// the claims read.
#pragma once

#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "bench/BenchReport.h"

namespace drr {

// One filter at one scale: still (mean over views, interval over views) or
// moving (one sequence: mean over frames, interval over blocks of frames).
struct QualityPoint {
  std::string filter;
  double scale = 1.0;
  double psnr = std::numeric_limits<double>::quiet_NaN(), psnrCi = std::numeric_limits<double>::quiet_NaN();
  double flip = std::numeric_limits<double>::quiet_NaN(), flipCi = std::numeric_limits<double>::quiet_NaN();
  double instability = std::numeric_limits<double>::quiet_NaN();  // TemporalStability.h
  double frameMs = std::numeric_limits<double>::quiet_NaN();
  int samples = 0;     // views (still) or frames (moving) behind the image numbers
  int gpuSamples = 0;  // distinct GPU results (still: the fewest of the views)
};

QualityPoint StillPoint(const BenchResults& res, const std::string& filter, double scale);
QualityPoint MovingPoint(const BenchResults& res, double speed, const std::string& filter, double scale);
std::vector<double> MovingSpeeds(const BenchResults& res);
double ReportSpeed(const BenchResults& res);  // 1 if measured, else the first speed; NaN: none

// "FLIP (5.59 ppd)": the metric's name with the pixels per degree of the run.
std::string FlipName(const BenchResults& res);
// A table cell: v with `decimals` decimals, "-" for NaN.
std::string FormatCell(double v, int decimals);
// Two scales of the plan are the same scale (they come from parsed decimals).
inline bool SameScale(double a, double b) { return a - b < 1e-4 && b - a < 1e-4; }

void WriteStillQuality(const BenchResults& res, std::ostringstream& md);
void WriteMovingQuality(const BenchResults& res, std::ostringstream& md);
void WriteAblations(const BenchResults& res, std::ostringstream& md);
void WriteIsoTables(const BenchResults& res, std::ostringstream& md);
bool WriteFrontPlots(const BenchResults& res, const std::string& dir, std::string* error);

// One row of the claims table (BenchReport.cpp).
void ClaimLine(std::ostringstream& md, const std::string& claim, const std::string& ours, const std::string& verdict);
// The image-quality claims judged on paired intervals (BenchReportPaired.cpp):
// TAA at 0.71 against native, TAA at 1.0 against native, bicubic against bilinear.
void ClaimTaaQuality(const BenchResults& res, std::ostringstream& md);
void ClaimBicubicQuality(const BenchResults& res, std::ostringstream& md);

// The scale pass's bandwidth bound in ms (BenchReport.cpp): the viewport
// read and the back buffer written once, 4 bytes a pixel each.
double ScalePassBoundMs(const BenchResults& res, double viewportW, double viewportH);
// The port's upscalers against native and the original's TAA: TAAU at 0.5
// and 0.71 still and moving, its cost ratios, the mip bias ablation
// (BenchReportUpscale.cpp).
void WriteUpscaling(const BenchResults& res, std::ostringstream& md);

}  // namespace drr
