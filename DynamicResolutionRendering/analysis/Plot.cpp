#include "analysis/Plot.h"
#include "imageio/ImageFile.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace drr {
namespace {

// Eighteen colours: a front of the bench has up to 17 filters, each a series.
constexpr uint32_t kPalette[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b,
                                 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf, 0x000080, 0x808000,
                                 0xff00ff, 0x8b0000, 0x006400, 0x4b0082, 0xdaa520, 0x404040};

class Canvas {
 public:
  Canvas(uint32_t w, uint32_t h) : w_(w), h_(h), rgb_(size_t(w) * h * 3, 255) {
    atlas_.AddFontDefault();
    atlas_.GetTexDataAsAlpha8(&glyphs_, &atlasW_, &atlasH_);
    font_ = atlas_.Fonts[0];
  }

  void Blend(int x, int y, uint32_t color, float alpha) {
    if (x < 0 || y < 0 || x >= int(w_) || y >= int(h_) || alpha <= 0.0f) return;
    uint8_t* p = &rgb_[(size_t(y) * w_ + x) * 3];
    const uint8_t c[3] = {uint8_t(color >> 16), uint8_t(color >> 8), uint8_t(color)};
    for (int i = 0; i < 3; ++i) p[i] = uint8_t(std::lround(p[i] + (c[i] - p[i]) * std::min(alpha, 1.0f)));
  }

  // Anti-aliased by coverage sampling along the segment, width in pixels.
  void Line(double x0, double y0, double x1, double y1, uint32_t color, float width = 1.5f,
            bool dashed = false) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    const int steps = std::max(1, int(len * 2));
    for (int s = 0; s <= steps; ++s) {
      const double t = double(s) / steps;
      if (dashed && std::fmod(t * len, 12.0) > 7.0) continue;
      Dot(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, width * 0.5f, color);
    }
  }

  void Dot(double cx, double cy, float radius, uint32_t color) {
    for (int y = int(cy - radius - 1); y <= int(cy + radius + 1); ++y) {
      for (int x = int(cx - radius - 1); x <= int(cx + radius + 1); ++x) {
        const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
        Blend(x, y, color, float(std::clamp(radius + 0.5 - d, 0.0, 1.0)));
      }
    }
  }

  void Rect(int x0, int y0, int x1, int y1, uint32_t color) {
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) Blend(x, y, color, 1.0f);
  }

  int TextWidth(const std::string& s) const {
    float w = 0;
    for (char ch : s) {
      if (const ImFontGlyph* g = font_->FindGlyph(ImWchar(uint8_t(ch)))) w += g->AdvanceX;
    }
    return int(w);
  }

  // Draws text with its top-left at (x, y); vertical = rotated 90° counter-clockwise.
  void Text(int x, int y, const std::string& s, uint32_t color, bool vertical = false) {
    float pen = 0;
    for (char ch : s) {
      const ImFontGlyph* g = font_->FindGlyph(ImWchar(uint8_t(ch)));
      if (!g) continue;
      const int gw = int(std::lround((g->U1 - g->U0) * atlasW_));
      const int gh = int(std::lround((g->V1 - g->V0) * atlasH_));
      const int u0 = int(std::lround(g->U0 * atlasW_)), v0 = int(std::lround(g->V0 * atlasH_));
      for (int j = 0; j < gh; ++j) {
        for (int i = 0; i < gw; ++i) {
          const float a = glyphs_[size_t(v0 + j) * atlasW_ + u0 + i] / 255.0f;
          const int gx = int(pen + g->X0) + i, gy = int(g->Y0) + j;
          if (vertical) Blend(x + gy, y - gx, color, a);
          else Blend(x + gx, y + gy, color, a);
        }
      }
      pen += g->AdvanceX;
    }
  }

  bool Save(const std::string& path, std::string* error) const {
    return WriteImageFile(path, w_, h_, 3, rgb_.data(), error);
  }

 private:
  uint32_t w_, h_;
  std::vector<uint8_t> rgb_;
  ImFontAtlas atlas_;
  unsigned char* glyphs_ = nullptr;
  int atlasW_ = 0, atlasH_ = 0;
  ImFont* font_ = nullptr;
};

// "Nice" tick step covering [lo, hi] with about n ticks.
double NiceStep(double lo, double hi, int n) {
  const double raw = (hi - lo) / std::max(n, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * mag >= raw) return m * mag;
  }
  return 10.0 * mag;
}

std::string Format(double v, double step) {
  char buf[32];
  // Enough decimals for the step itself (0.025 needs 3, 0.5 needs 1).
  int decimals = 0;
  while (decimals < 6 && std::abs(step * std::pow(10.0, decimals) -
                                  std::round(step * std::pow(10.0, decimals))) > 1e-6) {
    ++decimals;
  }
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

// The plot area in pixels and the data range drawn in it, rounded out to
// whole tick steps (xs, ys).
struct Axes {
  int left, right, top, bottom;
  double x0, x1, y0, y1, xs, ys;
  double Px(double v) const { return left + (v - x0) / (x1 - x0) * (right - left); }
  double Py(double v) const { return bottom - (v - y0) / (y1 - y0) * (bottom - top); }
};

Axes FitAxes(const PlotDesc& plot, uint32_t w, uint32_t h) {
  Axes a{80, int(w) - 200, 40, int(h) - 60, 0, 0, 0, 0, 0, 0};
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : plot.series) {
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 - x0 < 1e-12) x0 -= 0.5, x1 += 0.5;
  if (y1 - y0 < 1e-12) y0 -= 0.5, y1 += 0.5;
  a.xs = NiceStep(x0, x1, 8), a.ys = NiceStep(y0, y1, 6);
  a.x0 = std::floor(x0 / a.xs) * a.xs, a.x1 = std::ceil(x1 / a.xs) * a.xs;
  a.y0 = std::floor(y0 / a.ys) * a.ys, a.y1 = std::ceil(y1 / a.ys) * a.ys;
  return a;
}

// Grid, ticks and their labels, the axes, the title and the axis labels.
void DrawFrame(Canvas& canvas, const Axes& a, const PlotDesc& plot) {
  const int left = a.left, right = a.right, top = a.top, bottom = a.bottom;
  for (double v = a.x0; v <= a.x1 + a.xs * 0.5; v += a.xs) {
    canvas.Line(a.Px(v), top, a.Px(v), bottom, 0xe6e6e6, 1.0f);
    const std::string t = Format(v, a.xs);
    canvas.Text(int(a.Px(v)) - canvas.TextWidth(t) / 2, bottom + 6, t, 0x333333);
  }
  for (double v = a.y0; v <= a.y1 + a.ys * 0.5; v += a.ys) {
    canvas.Line(left, a.Py(v), right, a.Py(v), 0xe6e6e6, 1.0f);
    const std::string t = Format(v, a.ys);
    canvas.Text(left - 8 - canvas.TextWidth(t), int(a.Py(v)) - 6, t, 0x333333);
  }
  canvas.Line(left, bottom, right, bottom, 0x333333, 1.2f);
  canvas.Line(left, top, left, bottom, 0x333333, 1.2f);
  canvas.Text((left + right - canvas.TextWidth(plot.title)) / 2, 12, plot.title, 0x000000);
  canvas.Text((left + right - canvas.TextWidth(plot.xLabel)) / 2, bottom + 28, plot.xLabel, 0x000000);
  canvas.Text(16, (top + bottom + canvas.TextWidth(plot.yLabel)) / 2, plot.yLabel, 0x000000, true);
}

// Each series (a gap at every non-finite point) and its legend entry.
void DrawSeries(Canvas& canvas, const Axes& a, const PlotDesc& plot) {
  int legendY = a.top;
  for (size_t k = 0; k < plot.series.size(); ++k) {
    const auto& s = plot.series[k];
    const uint32_t color = s.color ? s.color : kPalette[k % std::size(kPalette)];
    bool havePrev = false;
    double lx = 0, ly = 0;
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        havePrev = false;
        continue;
      }
      const double cx = a.Px(s.x[i]), cy = a.Py(s.y[i]);
      if (s.lines && havePrev) canvas.Line(lx, ly, cx, cy, color, 2.0f, s.dashed);
      if (s.markers) canvas.Dot(cx, cy, s.markerRadius, color);
      if (i < s.labels.size() && !s.labels[i].empty()) canvas.Text(int(cx) + 5, int(cy) + s.labelDy, s.labels[i], color);
      lx = cx, ly = cy, havePrev = true;
    }
    canvas.Line(a.right + 16, legendY + 7, a.right + 40, legendY + 7, color, 2.0f, s.dashed);
    if (s.markers) canvas.Dot(a.right + 28, legendY + 7, 3.5f, color);
    canvas.Text(a.right + 46, legendY, s.name, 0x000000);
    legendY += 18;
  }
}

}  // namespace

std::vector<size_t> ParetoFront(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<size_t> order;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (std::isfinite(x[i]) && std::isfinite(y[i])) order.push_back(i);
  }
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return x[a] != x[b] ? x[a] < x[b] : y[a] < y[b]; });
  std::vector<size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i : order) {
    if (y[i] < best) {
      front.push_back(i);
      best = y[i];
    }
  }
  return front;
}

bool WritePlotPng(const PlotDesc& plot, const std::string& path, std::string* error) {
  const uint32_t w = std::max(plot.width, 320u), h = std::max(plot.height, 240u);
  Canvas canvas(w, h);
  const Axes axes = FitAxes(plot, w, h);
  DrawFrame(canvas, axes, plot);
  DrawSeries(canvas, axes, plot);
  return canvas.Save(path, error);
}

}  // namespace drr
