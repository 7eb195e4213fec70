// Outputs of --bench: results.csv, results.json, summary.md and the plots.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/ImageMetrics.h"

namespace drr {

struct BenchPlan;

struct Stat {
  double median = 0, p25 = 0, p75 = 0;  // NaN when nothing was measured
};

struct BenchRow {
  std::string view, filter;  // filter: a --filter value, "native", "reference-repeat" or an extra
  double scale = 1.0;
  float viewportW = 0, viewportH = 0;
  ImageError error;
  Stat gpuFrame, gpuClear, gpuScene, gpuPost, gpuScale, wall;  // milliseconds
};

struct BenchResults {
  const BenchPlan* plan = nullptr;
  std::string adapter, driver;
  std::vector<BenchRow> rows;
  double seconds = 0;
  uint64_t validationMessages = 0;
};

// The article's scale-pass cost ratios to point filtering at 0.71x (Japanese
// translation; see shared/reference/article-figures.md). 0 = not given.
double ArticleScaleRatio(const std::string& filter);

bool WriteBenchOutputs(const BenchResults& results, const std::string& outDir,
                       std::string* error);

}  // namespace drr
