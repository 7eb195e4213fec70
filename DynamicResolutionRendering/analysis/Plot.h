// Small PNG plots for the generated reports (error against time, frame time
// against scale): axes, ticks, labels, a legend, lines and markers. Text is
// drawn with Dear ImGui's built-in bitmap font, so no font files are needed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace drr {

struct PlotSeries {
  std::string name;
  std::vector<double> x, y;
  uint32_t color = 0;      // 0xRRGGBB; 0 = pick from the palette
  bool lines = true;
  bool markers = true;
  bool dashed = false;
  std::vector<std::string> labels;  // per point, drawn beside its marker (empty: none)
  float markerRadius = 3.5f;
  int labelDy = -14;  // label offset from the point, pixels down
};

struct PlotDesc {
  std::string title, xLabel, yLabel;
  std::vector<PlotSeries> series;
  uint32_t width = 960, height = 640;
};

// Writes the plot as an 8-bit RGB PNG (through OpenImageIO). Non-finite
// points are skipped. Returns false with a message on failure.
bool WritePlotPng(const PlotDesc& plot, const std::string& path, std::string* error);

// Indices of the points on the lower-left Pareto front (no other point has
// both a lower-or-equal x and a lower-or-equal y, one strictly), sorted by x.
std::vector<size_t> ParetoFront(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace drr
