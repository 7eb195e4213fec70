// summary.md sections on still and moving quality (PSNR with intervals, FLIP,
// instability), the ablations, iso-time and iso-quality tables, and the labelled
// Pareto fronts (still and moving).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "Options.h"
#include "analysis/Plot.h"
#include "bench/Bench.h"
#include "bench/BenchCommon.h"
#include "bench/BenchReportSections.h"

namespace drr {

std::string FormatCell(double v, int decimals) {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

QualityPoint StillPoint(const BenchResults& res, const std::string& filter, double scale) {
  std::vector<double> psnr, flip, frame, instability;
  QualityPoint q{filter, scale};
  for (const BenchRow& r : res.rows) {
    if (r.moving || r.filter != filter || !SameScale(r.scale, scale) || !std::isfinite(r.error.psnr)) continue;
    psnr.push_back(r.error.psnr);
    flip.push_back(r.flip);
    instability.push_back(r.instability);
    frame.push_back(r.gpuFrame.median);
    q.gpuSamples = q.gpuSamples == 0 ? r.gpuSamples : std::min(q.gpuSamples, r.gpuSamples);
  }
  // Over views: each view one block.
  const MeanCi p = BlockMeanCi(psnr, int(psnr.size())), f = BlockMeanCi(flip, int(flip.size()));
  q.psnr = p.mean, q.psnrCi = p.halfWidth, q.flip = f.mean, q.flipCi = f.halfWidth;
  q.frameMs = BlockMeanCi(frame, 1).mean;
  q.instability = BlockMeanCi(instability, 1).mean;
  q.samples = int(psnr.size());
  return q;
}

QualityPoint MovingPoint(const BenchResults& res, double speed, const std::string& filter, double scale) {
  QualityPoint q{filter, scale};
  for (const BenchRow& r : res.rows) {
    if (!r.moving || !SameScale(r.speed, speed) || r.filter != filter || !SameScale(r.scale, scale)) continue;
    q.psnr = r.error.psnr, q.psnrCi = r.psnrCi, q.flip = r.flip, q.flipCi = r.flipCi, q.instability = r.instability;
    q.frameMs = r.gpuFrame.median, q.samples = r.qualityFrames, q.gpuSamples = r.gpuSamples;
  }
  return q;
}

std::vector<double> MovingSpeeds(const BenchResults& res) {
  std::vector<double> s;
  for (const BenchRow& r : res.rows)
    if (r.moving && std::none_of(s.begin(), s.end(), [&](double x) { return SameScale(x, r.speed); })) s.push_back(r.speed);
  return s;
}

double ReportSpeed(const BenchResults& res) {
  const std::vector<double> s = MovingSpeeds(res);
  for (double x : s)
    if (SameScale(x, 1.0)) return x;
  return s.empty() ? std::nan("") : s.front();
}

// Every sweep point of one kind (still: the plan's filters and scales up to
// 1.0; moving: the moving filters and scales at `speed`), native first.
std::vector<QualityPoint> SweepPoints(const BenchResults& res, bool moving, double speed) {
  const BenchPlan& plan = *res.plan;
  std::vector<QualityPoint> pts;
  pts.push_back(moving ? MovingPoint(res, speed, "native", 1.0) : StillPoint(res, "native", 1.0));
  const auto& filters = moving ? plan.movingFilters : plan.filters;
  for (Filter f : filters)
    for (float s : moving ? plan.movingScales : plan.scales) {
      if (s > 1.0f) continue;
      QualityPoint q = moving ? MovingPoint(res, speed, FilterOption(f), s) : StillPoint(res, FilterOption(f), s);
      if (std::isfinite(q.psnr)) pts.push_back(q);
    }
  return pts;
}

void WriteStillQuality(const BenchResults& res, std::ostringstream& md) {
  const BenchPlan& plan = *res.plan;
  md << "### Still camera: PSNR (dB) and " << FlipName(res) << " by filter and scale\n\n"
        "Each view a frozen animation time; mean over the " << plan.views.size()
     << " view(s), with the 95 % interval over views (Student t; one view: none). Rows at or below 1.0 "
        "without 2x targets; scales above 1.0 are super-sampling rows (2x targets allowed). "
        "Cell: PSNR ± interval / FLIP (lower is better) / jitter instability (RMS change between consecutive frames, x1000).\n\n| filter |";
  for (float s : plan.scales) md << ' ' << FormatCell(s, 2) << (s > 1.0f ? " (2x)" : "") << " |";
  md << "\n| --- |";
  for (size_t i = 0; i < plan.scales.size(); ++i) md << " ---: |";
  md << '\n';
  auto cell = [&](const QualityPoint& q) {
    md << ' ' << FormatCell(q.psnr, 2) << (std::isfinite(q.psnrCi) ? " ± " + FormatCell(q.psnrCi, 2) : "") << " / " << FormatCell(q.flip, 4) << " / "
       << FormatCell(1000 * q.instability, 1) << " |";
  };
  for (Filter f : plan.filters) {
    md << "| " << FilterOption(f) << " |";
    for (float s : plan.scales) cell(StillPoint(res, FilterOption(f), s));
    md << '\n';
  }
  md << "| native |";
  cell(StillPoint(res, "native", 1.0));
  md << " (dynamic resolution off)";
  for (size_t i = 1; i < plan.scales.size(); ++i) md << " |";
  md << "\n\n";
}

void WriteMovingQuality(const BenchResults& res, std::ostringstream& md) {
  const BenchPlan& plan = *res.plan;
  for (double speed : MovingSpeeds(res)) {
    md << "### Moving camera x" << FormatCell(speed, 2) << ": PSNR (dB), " << FlipName(res) << ", instability\n\n"
       << "The cinematic camera moving at " << FormatCell(speed, 2) << " x its animation speed (" << FormatCell(speed / 30.0, 4)
       << " s of animation a frame), " << plan.movingWarmup << " warm-up frames then " << plan.movingFrames
       << " frames, each against the reference of its own animation time; motion blur off, no 2x targets. "
          "Cell: mean PSNR over frames ± 95 % interval (over 6 blocks of frames) / mean FLIP / instability "
          "(RMS of the frame-to-frame change after reprojecting the previous frame with the reference's "
          "velocity, less the reference's own change, x1000; 0 for an image that moves with the scene, "
          "lower is better).\n\n| filter |";
    for (float s : plan.movingScales) md << ' ' << FormatCell(s, 2) << " |";
    md << "\n| --- |";
    for (size_t i = 0; i < plan.movingScales.size(); ++i) md << " ---: |";
    md << '\n';
    auto cell = [&](const QualityPoint& q) {
      md << ' ' << FormatCell(q.psnr, 2) << " ± " << FormatCell(q.psnrCi, 2) << " / " << FormatCell(q.flip, 4) << " / " << FormatCell(1000 * q.instability, 1) << " |";
    };
    for (Filter f : plan.movingFilters) {
      md << "| " << FilterOption(f) << " |";
      for (float s : plan.movingScales) cell(MovingPoint(res, speed, FilterOption(f), s));
      md << '\n';
    }
    md << "| native |";
    cell(MovingPoint(res, speed, "native", 1.0));
    for (size_t i = 1; i < plan.movingScales.size(); ++i) md << " |";
    md << "\n\n";
  }
}

void WriteAblations(const BenchResults& res, std::ostringstream& md) {
  md << "### Ablations\n\n| what | camera | scale | PSNR dB | " << FlipName(res)
     << " | instability x1000 | frame ms | scale-pass ms | frames / GPU samples |\n"
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
  const std::string firstView = res.plan->views.empty() ? "" : res.plan->views.front().name;
  const double speed = ReportSpeed(res);
  for (const BenchRow& r : res.rows) {
    const bool mipBias = r.filter == kTaaNoMipBias || r.filter == kTaauNoMipBias ||
                         (r.filter == "taau" && (SameScale(r.scale, 0.5) || SameScale(r.scale, 0.71)));
    const bool still = !r.moving && r.view == firstView &&
                       (r.filter == kTaaSymmetric || mipBias || (r.filter == "taa" && (SameScale(r.scale, 0.5) || SameScale(r.scale, 0.71) || SameScale(r.scale, 1.0))));
    const bool moving = r.moving && SameScale(r.speed, speed) &&
                        (r.filter == kTaaSymmetric || r.filter == kTaaFast || r.filter == kNativeMotionBlur || r.filter == "native" || mipBias ||
                         (r.filter == "taa" && (SameScale(r.scale, 0.71) || SameScale(r.scale, 1.0))));
    if (!still && !moving) continue;
    const std::string what = r.filter == "taa" ? "taa (asymmetric jitter, velocity-reading)" : r.filter;
    md << "| " << what << " | " << (r.moving ? "moving x" + FormatCell(r.speed, 2) : "still, " + r.view) << " | " << FormatCell(r.scale, 2)
       << " | " << FormatCell(r.error.psnr, 2) << (std::isfinite(r.psnrCi) ? " ± " + FormatCell(r.psnrCi, 2) : "") << " | " << FormatCell(r.flip, 4)
       << " | " << FormatCell(1000 * r.instability, 1) << " | " << FormatCell(r.gpuFrame.median, 3) << " | " << FormatCell(r.gpuScale.median, 3) << " | "
       << r.qualityFrames << " / " << r.gpuSamples << " |\n";
  }
  md << "\nTexture mip bias: `taa` samples the scene's textures with the original's MipLODBias -0.5, `" << kTaaNoMipBias
     << "` with the plain sampler (`--no-taa-mip-bias`); `taau` adds log2(scale) to the bias (-1 at 0.5, -0.49 at "
        "0.71), `" << kTaauNoMipBias << "` does not (`--no-auto-mip-bias`). Compare each with the row of the same "
        "filter, camera and scale.\n\n";
}

// The best FLIP within each frame-time budget, and the cheapest frame
// reaching each FLIP target, from the sweep points of one kind.
void WriteIso(const std::vector<QualityPoint>& pts, const std::string& kind, std::ostringstream& md) {
  const QualityPoint& native = pts.front();
  md << "#### " << kind << "\n\n| budget (x native frame) | ms | best point | frame ms | PSNR dB | FLIP |\n"
        "| ---: | ---: | --- | ---: | ---: | ---: |\n";
  for (double k : {0.4, 0.6, 0.8, 1.0}) {
    const double budget = k * native.frameMs;
    const QualityPoint* best = nullptr;
    for (const QualityPoint& q : pts)
      if (q.frameMs <= budget && std::isfinite(q.flip) && (!best || q.flip < best->flip)) best = &q;
    md << "| " << FormatCell(k, 1) << " | " << FormatCell(budget, 2) << " | "
       << (best ? best->filter + " " + FormatCell(best->scale, 2) : std::string("none")) << " | " << FormatCell(best ? best->frameMs : NAN, 2)
       << " | " << FormatCell(best ? best->psnr : NAN, 2) << " | " << FormatCell(best ? best->flip : NAN, 4) << " |\n";
  }
  md << "\n| FLIP target (x native FLIP) | FLIP | cheapest point | frame ms (x native) | PSNR dB | FLIP |\n"
        "| ---: | ---: | --- | ---: | ---: | ---: |\n";
  for (double k : {1.0, 1.1, 1.25, 1.5}) {
    const double target = k * native.flip;
    const QualityPoint* best = nullptr;
    for (const QualityPoint& q : pts)
      if (q.flip <= target && std::isfinite(q.frameMs) && (!best || q.frameMs < best->frameMs)) best = &q;
    md << "| " << FormatCell(k, 2) << " | " << FormatCell(target, 4) << " | "
       << (best ? best->filter + " " + FormatCell(best->scale, 2) : std::string("none")) << " | "
       << FormatCell(best ? best->frameMs : NAN, 2) << " (" << FormatCell(best ? best->frameMs / native.frameMs : NAN, 2) << ") | "
       << FormatCell(best ? best->psnr : NAN, 2) << " | " << FormatCell(best ? best->flip : NAN, 4) << " |\n";
  }
  md << '\n';
}

void WriteIsoTables(const BenchResults& res, std::ostringstream& md) {
  md << "### Iso-time and iso-quality (frame GPU time median; " << FlipName(res) << ")\n\n"
        "Times are medians of the rows' own frames; on a loaded machine they move between rows, so read them "
        "as ratios within this run. Native = dynamic resolution off.\n\n";
  WriteIso(SweepPoints(res, false, 0), "Still camera (mean over views)", md);
  const double speed = ReportSpeed(res);
  if (std::isfinite(speed)) WriteIso(SweepPoints(res, true, speed), "Moving camera x" + FormatCell(speed, 2), md);
}

namespace {

// A labelled Pareto front: each filter a series of points labelled with
// their scale, the front through them labelled "filter scale", native big.
bool WriteFront(const std::vector<QualityPoint>& pts, bool flip, const std::string& title, const std::string& path,
                std::string* error) {
  PlotDesc plot;
  plot.title = title;
  plot.xLabel = "frame GPU time, median (ms)";
  plot.yLabel = flip ? "FLIP, mean (lower is better)" : "PSNR against the 4x4 reference (dB)";
  plot.width = 1200, plot.height = 800;
  std::vector<double> xs, ys;
  std::vector<std::string> names;
  for (size_t i = 1; i < pts.size(); ++i) {
    const QualityPoint& q = pts[i];
    auto it = std::find_if(plot.series.begin(), plot.series.end(), [&](const PlotSeries& s) { return s.name == q.filter; });
    if (it == plot.series.end()) {
      plot.series.push_back(PlotSeries{q.filter, {}, {}, 0, false, true});
      it = plot.series.end() - 1;
    }
    it->x.push_back(q.frameMs);
    it->y.push_back(flip ? q.flip : q.psnr);
    it->labels.push_back(FormatCell(q.scale, 2));
  }
  for (const QualityPoint& q : pts) {
    xs.push_back(q.frameMs);
    ys.push_back(flip ? q.flip : -q.psnr);
    names.push_back(q.filter + " " + (q.filter == "native" ? std::string() : FormatCell(q.scale, 2)));
  }
  PlotSeries front{"Pareto front", {}, {}, 0x111111, true, false, true};
  front.labelDy = 2;  // below the point: its scale label is above
  for (size_t i : ParetoFront(xs, ys)) {
    front.x.push_back(xs[i]);
    front.y.push_back(flip ? ys[i] : -ys[i]);
    front.labels.push_back(names[i]);
  }
  plot.series.push_back(front);
  PlotSeries native{"native", {pts.front().frameMs}, {flip ? pts.front().flip : pts.front().psnr},
                    0x010101, false, true};  // black: the palette has red
  native.markerRadius = 8.0f;
  native.labels = {"native (dyn. res. off)"};
  plot.series.push_back(native);
  return WritePlotPng(plot, path, error);
}

}  // namespace

bool WriteFrontPlots(const BenchResults& res, const std::string& dir, std::string* error) {
  const std::vector<QualityPoint> still = SweepPoints(res, false, 0);
  if (!WriteFront(still, true, "Still camera: FLIP against frame time (mean over views)", dir + "/front_still_flip.png", error) ||
      !WriteFront(still, false, "Still camera: PSNR against frame time (mean over views)", dir + "/front_still_psnr.png", error))
    return false;
  const double speed = ReportSpeed(res);
  if (!std::isfinite(speed)) return true;
  const std::vector<QualityPoint> moving = SweepPoints(res, true, speed);
  return WriteFront(moving, true, "Moving camera x" + FormatCell(speed, 2) + ": FLIP against frame time (mean over frames)",
                    dir + "/front_moving_flip.png", error) &&
         WriteFront(moving, false, "Moving camera x" + FormatCell(speed, 2) + ": PSNR against frame time (mean over frames)",
                    dir + "/front_moving_psnr.png", error);
}

}  // namespace drr
