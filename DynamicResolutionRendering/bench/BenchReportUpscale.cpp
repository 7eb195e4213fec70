// summary.md's upscaling section: the port's upscalers (Docs/Upscaling.md)
// beside native and the original's filters, from the sweep's rows: TAAU at
// the scales from 0.5 to 0.71, still and moving, against native and the
// original's TAA, with its cost ratios to point and to the bandwidth bound;
// and every upscaler at the cost scale.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "Options.h"
#include "bench/Bench.h"
#include "bench/BenchReportSections.h"

namespace drr {
namespace {

// The goal set for TAAU: at 0.71, moving, within this of native's PSNR
// at under this fraction of native's frame time.
constexpr double kGoalScale = 0.71, kGoalDb = 0.5, kGoalTime = 0.6;

// Scale-pass median and viewport of one row kind: the mean over the still
// views, or the moving sequence at `speed` (speed 0: still).
struct PassCost {
  double scaleMs = NAN, viewportW = NAN, viewportH = NAN;
};
PassCost CostOf(const BenchResults& res, double speed, const std::string& filter, double scale) {
  PassCost c;
  double sum = 0;
  int n = 0;
  for (const BenchRow& r : res.rows) {
    if (r.filter != filter || !SameScale(r.scale, scale) || r.moving != (speed > 0) || (speed > 0 && !SameScale(r.speed, speed)) ||
        !std::isfinite(r.gpuScale.median))
      continue;
    sum += r.gpuScale.median, ++n;
    c.viewportW = r.viewportW, c.viewportH = r.viewportH;
  }
  if (n) c.scaleMs = sum / n;
  return c;
}

bool InPlan(const std::vector<Filter>& filters, Filter f) {
  for (Filter g : filters)
    if (g == f) return true;
  return false;
}

// One line per scale in [0.5, 0.71]: TAAU against native, the original's TAA
// and point at that scale; frame and scale-pass ratios.
void WriteTaauRows(const BenchResults& res, double speed, const std::vector<float>& scales, std::ostringstream& md) {
  const bool moving = speed > 0;
  auto point = [&](const std::string& f, double s) {
    return moving ? MovingPoint(res, speed, f, s) : StillPoint(res, f, s);
  };
  const QualityPoint native = point("native", 1.0);
  for (float s : scales) {
    if (s < 0.5f - 1e-4f || s > 0.71f + 1e-4f) continue;
    const QualityPoint taau = point("taau", s), taa = point("taa", s), pt = point("point", s);
    const PassCost c = CostOf(res, speed, "taau", s), cp = CostOf(res, speed, "point", s);
    const double bound = ScalePassBoundMs(res, c.viewportW, c.viewportH);
    md << "| " << (moving ? "moving x" + FormatCell(speed, 2) : std::string("still")) << " | " << FormatCell(s, 2) << " | " << FormatCell(taau.psnr, 2)
       << " / " << FormatCell(taau.flip, 4) << " | " << FormatCell(taau.psnr - native.psnr, 2) << " | " << FormatCell(taau.psnr - taa.psnr, 2) << " | "
       << FormatCell(taau.psnr - pt.psnr, 2) << " | " << FormatCell(taau.frameMs / native.frameMs, 2) << " | "
       << FormatCell(c.scaleMs / cp.scaleMs, 2) << " | " << FormatCell(c.scaleMs / bound, 1) << " |\n";
  }
}

void WriteGoal(const BenchResults& res, double speed, std::ostringstream& md) {
  const QualityPoint taau = MovingPoint(res, speed, "taau", kGoalScale), native = MovingPoint(res, speed, "native", 1.0);
  if (!std::isfinite(taau.psnr) || !std::isfinite(native.psnr)) {
    md << "Goal (TAAU at 0.71 within " << FormatCell(kGoalDb, 1) << " dB of native on the moving camera, at under "
       << FormatCell(100 * kGoalTime, 0) << " % of native's frame time): not measured in this run (no moving taau 0.71 row).\n\n";
    return;
  }
  const double gap = native.psnr - taau.psnr, time = taau.frameMs / native.frameMs;
  const bool quality = gap <= kGoalDb, cost = time < kGoalTime;
  md << "Goal (TAAU at 0.71 within " << FormatCell(kGoalDb, 1) << " dB of native on the moving camera x" << FormatCell(speed, 2)
     << ", at under " << FormatCell(100 * kGoalTime, 0) << " % of native's frame time): image "
     << (quality ? "met" : "not met, by " + FormatCell(gap - kGoalDb, 2) + " dB") << " (" << FormatCell(taau.psnr, 2) << " against "
     << FormatCell(native.psnr, 2) << " dB); time " << (cost ? "met" : "not met") << " (" << FormatCell(100 * time, 0)
     << " % of native's frame on this machine).\n\n";
}

// Each port upscaler (and the original's bilinear and TAA beside them) at
// the cost scale: still and moving image, scale pass against point.
void WriteUpscalerTable(const BenchResults& res, double speed, float scale, std::ostringstream& md) {
  const BenchPlan& plan = *res.plan;
  md << "| filter | still PSNR / " << FlipName(res) << " | moving PSNR / FLIP / instability | still scale pass x point | x bandwidth bound |\n"
        "| --- | ---: | ---: | ---: | ---: |\n";
  for (Filter f : plan.filters) {
    if (int(f) < int(Filter::UpscaleNearest) && f != Filter::Bilinear && f != Filter::TAA) continue;
    const QualityPoint st = StillPoint(res, FilterOption(f), scale);
    const QualityPoint mv = MovingPoint(res, speed, FilterOption(f), scale);
    const PassCost c = CostOf(res, 0, FilterOption(f), scale), cp = CostOf(res, 0, "point", scale);
    md << "| " << FilterOption(f) << " | " << FormatCell(st.psnr, 2) << " / " << FormatCell(st.flip, 4) << " | " << FormatCell(mv.psnr, 2) << " / "
       << FormatCell(mv.flip, 4) << " / " << FormatCell(1000 * mv.instability, 1) << " | " << FormatCell(c.scaleMs / cp.scaleMs, 2) << " | "
       << FormatCell(c.scaleMs / ScalePassBoundMs(res, c.viewportW, c.viewportH), 1) << " |\n";
  }
  md << '\n';
}

}  // namespace

void WriteUpscaling(const BenchResults& res, std::ostringstream& md) {
  const BenchPlan& plan = *res.plan;
  if (!InPlan(plan.filters, Filter::TAAU) && !InPlan(plan.movingFilters, Filter::TAAU)) return;
  const double speed = ReportSpeed(res);
  md << "### Upscaling (port): TAAU against native and the original's TAA\n\n"
        "TAAU (`--filter taau`, Docs/Upscaling.md) at the scales from 0.5 to 0.71: PSNR / FLIP, its PSNR minus "
        "native's, the original's TAA's and point's at the same scale (dB), its frame time over native's, its "
        "scale pass (the upsample) over point's at the same scale and over the bandwidth bound of a scale pass. "
        "Still: mean over views (TAAU warmed up for two jitter cycles); moving: the sequence's mean over frames. "
        "Times are medians of the rows' own frames.\n\n"
        "| camera | scale | taau PSNR / FLIP | - native | - taa | - point | frame x native | scale pass x point "
        "| x bandwidth bound |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  WriteTaauRows(res, 0, plan.scales, md);
  if (std::isfinite(speed)) WriteTaauRows(res, speed, plan.movingScales, md);
  md << '\n';
  if (std::isfinite(speed)) WriteGoal(res, speed, md);
  md << "Every upscaler at " << FormatCell(kGoalScale, 2) << " (moving x" << FormatCell(speed, 2) << "; `-`: not in this run's moving sweep):\n\n";
  WriteUpscalerTable(res, speed, float(kGoalScale), md);
}

}  // namespace drr
