#include "bench/BenchReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>

#include "Options.h"
#include "analysis/Plot.h"
#include "bench/Bench.h"
#include "bench/BenchColumns.h"
#include "bench/BenchCommon.h"
#include "bench/BenchReportSections.h"

namespace drr {
namespace {

std::string Num(double v, int decimals = 4) { return FormatNumber(v, decimals); }



// Mean over views of a row value, for one filter and scale (NaN if none).
template <class Get>
double MeanOver(const std::vector<BenchRow>& rows, const std::string& filter, double scale,
                Get get) {
  double sum = 0;
  int n = 0;
  for (const auto& r : rows) {
    if (!r.moving && r.filter == filter && std::abs(r.scale - scale) < 1e-4) {
      const double v = get(r);
      if (std::isfinite(v)) {
        sum += v;
        ++n;
      }
    }
  }
  return n ? sum / n : std::nan("");
}

// Means over views for one filter and scale: PSNR, scale-pass and frame GPU medians.
double MeanPsnr(const BenchResults& res, const std::string& filter, double scale) {
  return MeanOver(res.rows, filter, scale, [](const BenchRow& r) { return r.error.psnr; });
}
double MeanScaleMs(const BenchResults& res, const std::string& filter, double scale) {
  return MeanOver(res.rows, filter, scale, [](const BenchRow& r) { return r.gpuScale.median; });
}
double MeanFrameMs(const BenchResults& res, const std::string& filter, double scale) {
  return MeanOver(res.rows, filter, scale, [](const BenchRow& r) { return r.gpuFrame.median; });
}

std::string Today() {
  std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y-%m-%d", std::gmtime(&t));
  return buf;
}

bool WriteCsv(const BenchResults& res, const std::string& path, std::string* error) {
  std::ofstream out(path);
  if (!out) {
    *error = "cannot write " + path;
    return false;
  }
  out << CsvHeader() << '\n';
  for (const auto& r : res.rows) out << CsvLine(r) << '\n';
  return bool(out);
}

bool WriteJson(const BenchResults& res, const std::string& path, std::string* error) {
  std::ofstream out(path);
  if (!out) {
    *error = "cannot write " + path;
    return false;
  }
  out << BenchJson(res, Today()).dump(2) << '\n';
  return bool(out);
}

bool WritePlots(const BenchResults& res, const std::string& dir, std::string* error) {
  const BenchPlan& plan = *res.plan;
  PlotDesc vsScale, vsFrame, fig11;
  vsScale.title = "Image error against scale-pass time (mean over views)";
  vsScale.xLabel = "scale pass GPU time, median (ms)";
  vsScale.yLabel = "PSNR against 4x4 SSAA reference (dB)";
  vsFrame.title = "Image error against frame time (mean over views)";
  vsFrame.xLabel = "frame GPU time, median (ms)";
  vsFrame.yLabel = "PSNR (dB)";
  fig11.title = "Frame time against resolution scale (article figure 11)";
  fig11.xLabel = "resolution scale (per axis)";
  fig11.yLabel = "frame GPU time, median (ms)";
  std::vector<double> allX, allY, allFX;
  for (Filter f : plan.filters) {
    const std::string name = FilterOption(f);
    PlotSeries a{name, {}, {}}, b{name, {}, {}}, c{name, {}, {}};
    a.lines = b.lines = false;
    for (float s : plan.scales) {
      const double psnr = MeanPsnr(res, name, s);
      const double scaleMs = MeanScaleMs(res, name, s);
      const double frameMs = MeanFrameMs(res, name, s);
      a.x.push_back(scaleMs), a.y.push_back(psnr);
      b.x.push_back(frameMs), b.y.push_back(psnr);
      c.x.push_back(s), c.y.push_back(frameMs);
      // The front is over error (lower is better): use -PSNR.
      allX.push_back(scaleMs), allY.push_back(-psnr), allFX.push_back(frameMs);
    }
    vsScale.series.push_back(a);
    vsFrame.series.push_back(b);
    fig11.series.push_back(c);
  }
  auto front = [](const std::vector<double>& x, const std::vector<double>& negPsnr) {
    PlotSeries s{"Pareto front", {}, {}, 0x000000, true, false, true};
    s.color = 0x111111;
    for (size_t i : ParetoFront(x, negPsnr)) {
      s.x.push_back(x[i]);
      s.y.push_back(-negPsnr[i]);
    }
    return s;
  };
  vsScale.series.push_back(front(allX, allY));
  vsFrame.series.push_back(front(allFX, allY));
  return WriteFrontPlots(res, dir, error) && WritePlotPng(vsScale, dir + "/error_vs_scale_time.png", error) &&
         WritePlotPng(vsFrame, dir + "/error_vs_frame_time.png", error) &&
         WritePlotPng(fig11, dir + "/frame_time_vs_scale.png", error);
}

}  // namespace

// Least time a scale pass can take: the viewport read and the back buffer
// written once, 4 bytes a pixel each, at the memory bandwidth (NaN: unknown).
double ScalePassBoundMs(const BenchResults& res, double viewportW, double viewportH) {
  const double bytes = 4.0 * (viewportW * viewportH + double(res.plan->base.width) * res.plan->base.height);
  return bytes / (res.bandwidthGBs * 1e9) * 1e3;
}

namespace {

// The bound at `scale`, from the fixed-function-blit row's viewport (NaN: none).
double BandwidthBoundMs(const BenchResults& res, double scale) {
  for (const BenchRow& r : res.rows)
    if (r.filter == kFixedBlit && std::abs(r.scale - scale) <= 1e-6) return ScalePassBoundMs(res, r.viewportW, r.viewportH);
  return std::nan("");
}

float CostScale(const BenchPlan& plan) {
  return std::find(plan.scales.begin(), plan.scales.end(), 0.71f) != plan.scales.end() ? 0.71f
                                                                                        : plan.scales.front();
}

const BenchRow* FindRow(const BenchResults& res, const std::string& filter) {
  for (const auto& r : res.rows)
    if (r.filter == filter) return &r;
  return nullptr;
}

double Median(const BenchRow* r, Stat BenchRow::*stat) { return r ? (r->*stat).median : std::nan(""); }
double Psnr(const BenchRow* r) { return r ? r->error.psnr : std::nan(""); }

// TAA modes after the history settled: the sweep's TAA rows are captured
// after the warm-up on a fixed animation time, so the two-frame history
// (current + previous final RT) holds two frames of the same scene.
void WriteTaaSettled(const BenchResults& res, std::ostringstream& md) {
  const BenchPlan& plan = *res.plan;
  std::vector<Filter> taa;
  for (Filter f : plan.filters)
    if (IsTAA(f)) taa.push_back(f);
  if (taa.empty()) return;
  md << "### TAA after the history settled (still camera, frozen animation time, " << plan.warmupFrames
     << " warm-up frames; PSNR dB, mean over views)\n\n| filter |";
  for (float s : plan.scales) md << ' ' << Num(s, 2) << " |";
  md << "\n| --- |";
  for (size_t i = 0; i < plan.scales.size(); ++i) md << " ---: |";
  md << '\n';
  for (Filter f : taa) {
    md << "| " << FilterOption(f) << " |";
    for (float s : plan.scales)
      md << ' ' << Num(MeanPsnr(res, FilterOption(f), s), 2) << " |";
    md << '\n';
  }
  md << "| point (for comparison) |";
  for (float s : plan.scales)
    md << ' ' << Num(MeanPsnr(res, "point", s), 2) << " |";
  md << "\n\n";
}

}  // namespace

void ClaimLine(std::ostringstream& md, const std::string& claim, const std::string& ours,
               const std::string& verdict) {
  md << "| " << claim << " | " << ours << " | " << verdict << " |\n";
}

namespace {

// Scale-pass cost of the filters relative to each other.
void ClaimScalePassRatios(const BenchResults& res, std::ostringstream& md) {
  const float cs = CostScale(*res.plan);
  const double p = MeanScaleMs(res, "point", cs), b = MeanScaleMs(res, "bilinear", cs),
               bc = MeanScaleMs(res, "bicubic", cs), t = MeanScaleMs(res, "taa", cs);
  std::ostringstream o;
  o << "at " << Num(cs, 2) << ": bilinear/point " << Num(b / p, 2) << ", bicubic/point " << Num(bc / p, 2)
    << ", bicubic/bilinear " << Num(bc / b, 2) << ", taa/point " << Num(t / p, 2);
  std::string v = "cannot measure (filters missing)";
  if (std::isfinite(bc / b)) v = (bc / b >= 8.75 / 2 && bc / b <= 8.75 * 2) ? "agree (within 2x of 8.75)" : "disagree (not within 2x of 8.75)";
  ClaimLine(md, "Bicubic costs ~7x bilinear (1/7 of its performance); bilinear = point", o.str(), v);
  // Per view, side by side: the mean over views hides how far apart they are.
  std::vector<double> perView;
  for (const BenchView& view : res.plan->views) {
    double tv = std::nan(""), pv = std::nan("");
    for (const BenchRow& r : res.rows) {
      if (r.moving || r.view != view.name || std::abs(r.scale - cs) > 1e-4) continue;
      if (r.filter == "taa") tv = r.gpuScale.median;
      if (r.filter == "point") pv = r.gpuScale.median;
    }
    if (std::isfinite(tv / pv)) perView.push_back(tv / pv);
  }
  std::sort(perView.begin(), perView.end());
  const double ratio = perView.empty() ? std::nan("") : perView[perView.size() / 2];
  std::ostringstream o2;
  o2 << "at " << Num(cs, 2) << ", " << (res.plan->sweepMotionBlur ? "fast TAA (motion blur on)" : "velocity-reading TAA (motion blur off)")
     << ": taa/point per view";
  for (double r : perView) o2 << ' ' << Num(r, 2);
  o2 << " (median " << Num(ratio, 2) << "; fast TAA, claim row: "
     << Num(Median(FindRow(res, "taa fast (motion blur on)"), &BenchRow::gpuScale) / p, 2) << ")";
  const double lo = 2.75 / 1.5, hi = 2.75 * 1.5;
  v = "cannot measure";
  if (std::isfinite(ratio)) {
    const bool allIn = perView.front() >= lo && perView.back() <= hi;
    const bool allOut = perView.back() < lo || perView.front() > hi;
    v = allIn ? "agree (every view within 1.5x of 2.75)" : allOut ? "disagree (every view outside 1.5x of 2.75)"
                                                                : "cannot decide (the views fall on both sides of 1.5x of 2.75)";
  }
  ClaimLine(md, "TAA (the velocity-reading one) costs 2.75x point", o2.str(), v);
}

// A time verdict only where the difference of two rows is larger than the
// spread of either row over its interleaved timing rounds: else the reason
// it cannot decide ("" when it can).
std::string InsideRoundSpread(double difference, const std::vector<double>& a, const std::vector<double>& b) {
  const double spread = std::max(RoundSpread(a), RoundSpread(b));
  if (!std::isfinite(RoundSpread(a)) || !std::isfinite(RoundSpread(b)))
    return "cannot decide (fewer than 2 timing rounds: no spread of repeated runs)";
  if (std::abs(difference) > spread) return "";
  return "cannot decide (the difference, " + Num(std::abs(difference), 3) + " ms, is inside the spread of repeated rounds, " +
         Num(spread, 3) + " ms)";
}

void ClaimPsClear(const BenchResults& res, std::ostringstream& md) {
  const BenchRow* api = FindRow(res, "point api-clear");
  const BenchRow* ps = FindRow(res, "point ps-clear");
  const double a = Median(api, &BenchRow::gpuClear), p = Median(ps, &BenchRow::gpuClear);
  std::ostringstream o;
  o << "clear: ps " << Num(p, 3) << " vs api " << Num(a, 3) << " (frame " << Num(Median(ps, &BenchRow::gpuFrame), 3)
    << " vs " << Num(Median(api, &BenchRow::gpuFrame), 3) << ")";
  const std::string noise = InsideRoundSpread(p - a, api ? api->roundClearMs : std::vector<double>{},
                                              ps ? ps->roundClearMs : std::vector<double>{});
  ClaimLine(md, "Pixel-shader clear of the viewport beats the API clear at 0.71x", o.str(),
            !(std::isfinite(a) && std::isfinite(p)) ? "cannot measure" : !noise.empty() ? noise : p < a ? "agree" : "disagree");
}

// Super sampling: is the extra cost mostly clears?
void ClaimSuperSampling(const BenchResults& res, std::ostringstream& md) {
  const double nan = std::nan("");
  auto pair = [&](const std::string& suffix, double* dFrame, double* dClear) {
    const BenchRow* no = FindRow(res, "point 1.0 no-ss" + suffix);
    const BenchRow* ss = FindRow(res, "point 1.0 ss-allowed" + suffix);
    *dFrame = Median(ss, &BenchRow::gpuFrame) - Median(no, &BenchRow::gpuFrame);
    *dClear = Median(ss, &BenchRow::gpuClear) - Median(no, &BenchRow::gpuClear);
  };
  double fApi = nan, cApi = nan, fPs = nan, cPs = nan;
  pair(" api-clear", &fApi, &cApi);
  pair("", &fPs, &cPs);
  std::ostringstream o;
  o << "2x RT allowed at scale 1.0, API clear: +" << Num(fApi, 3) << " frame, +" << Num(cApi, 3)
    << " clear; pixel-shader clear: +" << Num(fPs, 3) << " frame, +" << Num(cPs, 3) << " clear";
  std::string v = "cannot measure";
  if (std::isfinite(fApi) && std::isfinite(cApi)) {
    if (fApi <= 0.0) v = "cannot measure (no extra frame cost measured)";
    else v = cApi / fApi >= 0.5 ? "agree (clear is " + Num(100 * cApi / fApi, 0) + " % of the extra cost)"
                                 : "disagree (clear is " + Num(100 * cApi / fApi, 0) + " % of the extra cost)";
  }
  ClaimLine(md, "Super sampling (2x RT): the cost is mostly clearing the larger buffers", o.str(), v);
}

void ClaimFastTaa(const BenchResults& res, std::ostringstream& md) {
  const double fast = Median(FindRow(res, "taa fast (motion blur on)"), &BenchRow::gpuScale);
  const double vel = Median(FindRow(res, "taa velocity (motion blur off)"), &BenchRow::gpuScale);
  const double saving = 1.0 - fast / vel;
  std::ostringstream o;
  o << "scale pass: fast " << Num(fast, 3) << ", velocity-reading " << Num(vel, 3) << "; saving "
    << Num(100 * saving, 0) << " %";
  const BenchRow* fastRow = FindRow(res, "taa fast (motion blur on)");
  const BenchRow* velRow = FindRow(res, "taa velocity (motion blur off)");
  const std::string noise = InsideRoundSpread(fast - vel, fastRow ? fastRow->roundScaleMs : std::vector<double>{},
                                              velRow ? velRow->roundScaleMs : std::vector<double>{});
  ClaimLine(md, "Fast TAA (velocity in motion-blur alpha) ~40 % faster than the velocity-reading TAA", o.str(),
            !std::isfinite(saving) ? "cannot measure"
            : !noise.empty()       ? noise
            : std::abs(saving - 0.40) <= 0.15 ? "agree (within 15 points of 40 %)"
                                               : "disagree (not within 15 points of 40 %)");
}

// Motion blur at 0.71 close to native, and cheaper.
void ClaimMotionBlur(const BenchResults& res, std::ostringstream& md) {
  const BenchRow* n = FindRow(res, "motion-blur native");
  const BenchRow* s = FindRow(res, "motion-blur 0.71");
  std::ostringstream o;
  o << "PSNR vs reference: 0.71 (bilinear) " << Num(Psnr(s), 2) << ", native " << Num(Psnr(n), 2)
    << "; 0.71 vs native image " << Num(s ? s->psnrVsNative : std::nan(""), 2) << " dB; frame "
    << Num(Median(s, &BenchRow::gpuFrame), 3) << " vs " << Num(Median(n, &BenchRow::gpuFrame), 3);
  std::string v = "cannot measure";
  if (n && s && std::isfinite(Psnr(n)) && std::isfinite(Psnr(s))) {
    const bool close = Psnr(n) - Psnr(s) <= 2.0 || s->psnrVsNative >= 30.0;
    const bool shorter = Median(s, &BenchRow::gpuFrame) < Median(n, &BenchRow::gpuFrame);
    v = close && shorter ? "agree" : close ? "disagree (image close, frame not shorter)"
                                             : "disagree (image differs: > 2 dB and < 30 dB vs native)";
  }
  ClaimLine(md, "Motion blur at 0.71x: nearly the same image as native, shorter frame", o.str(), v);
}

// Figure 11: frame time grows with the scale.
void ClaimFrameTimeScaling(const BenchResults& res, std::ostringstream& md) {
  std::ostringstream o;
  bool mono = true;
  double prev = -1;
  for (float s : res.plan->scales) {
    const double f = MeanFrameMs(res, "point", s);
    o << Num(s, 2) << ": " << Num(f, 2) << "; ";
    if (std::isfinite(f)) {
      if (prev >= 0 && f < prev) mono = false;
      prev = f;
    }
  }
  ClaimLine(md, "Frame time scales with resolution (figure 11)", "point frame ms " + o.str(),
            prev < 0 ? "cannot measure" : mono ? "agree (monotonic)" : "disagree (not monotonic)");
}

void WriteClaims(const BenchResults& res, std::ostringstream& md) {
  const BenchPlan& plan = *res.plan;
  md << "### Claims (article-figures.md) against this run\n\n"
        "Claim rows run on the first view (`" << (plan.views.empty() ? std::string("-") : plan.views.front().name)
     << "`) at scale 0.71 unless named otherwise; motion blur on the moving cinematic camera. "
        "Timings are GPU medians (ms). Verdicts are computed from the numbers; on a CPU "
        "rasteriser (lavapipe) timings say little about a GPU.\n\n"
        "| claim | our numbers | verdict |\n| --- | --- | --- |\n";
  ClaimScalePassRatios(res, md);
  ClaimPsClear(res, md);
  ClaimSuperSampling(res, md);
  ClaimFastTaa(res, md);
  ClaimMotionBlur(res, md);
  ClaimTaaQuality(res, md);
  ClaimBicubicQuality(res, md);
  ClaimFrameTimeScaling(res, md);
  ClaimLine(md, "Power: halving the resolution cuts package power", "-", "cannot measure (no power counters)");
  ClaimLine(md, "Controller dS = k S (T - t)/T holds 30/60 FPS", "-", "not measured here (controller tests)");
  md << '\n';
}

void WriteGhosting(const BenchResults& res, std::ostringstream& md) {
  std::vector<const BenchRow*> rows;
  for (const auto& r : res.rows)
    if (r.filter.rfind("ghost ", 0) == 0) rows.push_back(&r);
  if (rows.empty()) return;
  const BenchPlan& plan = *res.plan;
  md << "### Ghosting on the moving cinematic camera\n\n"
     << "The cinematic camera (1) animated by " << Num(plan.ghostStep, 4) << " s per frame (`fixedDt`), "
     << plan.ghostFrames << " frames after switching the filter, captured at animation time "
     << Num(rows.front()->animTime, 4) << " s and compared with the reference rendered at that time; "
        "scale 0.71, motion blur off (the reference has none). PSNR/SSIM: against the reference. "
        "Ghost fraction = pixels whose largest RGB difference from the same filter's settled "
        "image of the same animation time (camera held still for as many frames) is above 0.1: "
        "what the motion adds, not the filter's spatial error.\n\n| filter | PSNR dB | SSIM | ghost fraction | frame ms |\n"
        "| --- | ---: | ---: | ---: | ---: |\n";
  const BenchRow* worst = nullptr;
  for (const BenchRow* r : rows) {
    md << "| " << r->filter.substr(6) << " | " << Num(r->error.psnr, 2) << " | " << Num(r->error.ssim, 4)
       << " | " << Num(r->ghostFraction, 4) << " | " << Num(r->gpuFrame.median, 3) << " |\n";
    if (!worst || r->ghostFraction > worst->ghostFraction) worst = r;
  }
  md << "\nMost ghosting: " << (worst ? worst->filter.substr(6) : std::string("-"))
     << (worst && worst->filter == "ghost taa-basic" ? " (as expected: plain average of two frames)\n\n"
                                                      : " (expected taa-basic)\n\n");
}

// The still PSNR table and the scale-pass cost table with the blit and the
// bandwidth bound.
void WritePsnrAndCost(const BenchResults& res, std::ostringstream& md) {
  const BenchPlan& plan = *res.plan;
  md << "### PSNR (dB, mean over views) by filter and scale\n\n| filter |";
  for (float s : plan.scales) md << ' ' << Num(s, 2) << " |";
  md << "\n| --- |";
  for (size_t i = 0; i < plan.scales.size(); ++i) md << " ---: |";
  md << '\n';
  for (Filter f : plan.filters) {
    md << "| " << FilterOption(f) << " |";
    for (float s : plan.scales)
      md << ' ' << Num(MeanPsnr(res, FilterOption(f), s), 2) << " |";
    md << '\n';
  }
  md << "| native (dynamic resolution off) | "
     << Num(MeanPsnr(res, "native", 1.0), 2)
     << " (at 1.0) |\n\n";

  md << "### Scale-pass cost (GPU ms, median, mean over views)\n\n"
        "`fixed-function-blit` is a linear `vkCmdBlitImage` (BlitExtension::BlitRegion) of the "
        "same viewport region of the scene colour to a back-buffer-sized target, timed with its "
        "own timestamp queries in the same run: another driver path for the same work, not a "
        "lower bound. `bandwidth bound` is the physical one: the bytes a scale pass must read "
        "(the viewport, 4 bytes a pixel) and write (the back buffer, 4 bytes a pixel) over the "
        "memory bandwidth.\n\n"
        "| filter | scale | ms | ratio to point | ratio to blit | ratio to bandwidth bound | article ratio to point (JP) |\n"
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  const float costScale = CostScale(plan);
  const double pointMs = MeanScaleMs(res, "point", costScale);
  const double blitMs = MeanScaleMs(res, kFixedBlit, costScale);
  const double boundMs = BandwidthBoundMs(res, costScale);
  auto costRow = [&](const std::string& name, double ms) {
    const double article = ArticleScaleRatio(name);
    md << "| " << name << " | " << Num(costScale, 2) << " | " << Num(ms, 3) << " | "
       << Num(pointMs > 0 ? ms / pointMs : std::nan(""), 2) << " | "
       << Num(blitMs > 0 ? ms / blitMs : std::nan(""), 2) << " | "
       << Num(boundMs > 0 ? ms / boundMs : std::nan(""), 1) << " | "
       << (article > 0 ? Num(article, 2) : std::string("-")) << " |\n";
  };
  costRow("bandwidth bound", boundMs);
  costRow(kFixedBlit, blitMs);
  for (Filter f : plan.filters) costRow(FilterOption(f), MeanScaleMs(res, FilterOption(f), costScale));
  md << "\nBandwidth: " << (std::isfinite(res.bandwidthGBs) ? Num(res.bandwidthGBs, 1) + " GB/s, " : std::string())
     << res.bandwidthSource << ".\n";
  md << "\nPSNR of the fixed-function blit itself (linear blit of the scene colour, no motion blur) by scale:";
  for (float s : plan.scales)
    md << ' ' << Num(s, 2) << ": " << Num(MeanPsnr(res, kFixedBlit, s), 2) << " dB;";
  md << "\n\n";
}

bool WriteSummary(const BenchResults& res, const std::string& path, std::string* error) {
  const BenchPlan& plan = *res.plan;
  std::ostringstream md;
  md << "## " << (plan.quick ? "Quick" : "Full") << " sweep on " << res.adapter << "\n\n"
     << "Driver " << res.driver << ", " << Today() << ", back buffer " << plan.base.width << "x"
     << plan.base.height << ", reference " << plan.referenceFactor << "x"
     << plan.referenceFactor << " super sampling, " << plan.warmupFrames << " warm-up frames (at least "
     << plan.warmupMs << " ms) + "
     << plan.measuredFrames << " measured frames per configuration, " << res.rows.size()
     << " configurations in " << Num(res.seconds, 1) << " s, " << res.validationMessages
     << " validation messages.\n\n";

  WritePsnrAndCost(res, md);
  WriteStillQuality(res, md);
  WriteMovingQuality(res, md);
  WriteAblations(res, md);
  WriteUpscaling(res, md);
  WriteIsoTables(res, md);
  WriteTaaSettled(res, md);
  WriteClaims(res, md);
  WriteGhosting(res, md);
  md << "\n### Frame and scene time against scale (point filter)\n\n"
        "| scale | frame ms | scene ms | wall ms |\n| ---: | ---: | ---: | ---: |\n";
  for (float s : plan.scales) {
    md << "| " << Num(s, 2) << " | "
       << Num(MeanFrameMs(res, "point", s), 3) << " | "
       << Num(MeanOver(res.rows, "point", s, [](const BenchRow& r) { return r.gpuScene.median; }), 3) << " | "
       << Num(MeanOver(res.rows, "point", s, [](const BenchRow& r) { return r.wall.median; }), 3) << " |\n";
  }
  md << "\nPlots: `front_still_flip.png`, `front_still_psnr.png`, `front_moving_flip.png`, `front_moving_psnr.png` "
        "(labelled Pareto fronts), `error_vs_scale_time.png`, `error_vs_frame_time.png`, "
        "`frame_time_vs_scale.png`. Raw data: `results.csv`, `results.json`.\n";

  std::ofstream out(path);
  out << md.str();
  if (!out) {
    *error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace

void BenchResults::Add(BenchRow row) {
  rows.push_back(std::move(row));
  if (partialDir.empty() || plan == nullptr) return;
  std::string error;
  if (!WriteCsv(*this, partialDir + "/results.csv", &error) || !WriteJson(*this, partialDir + "/results.json", &error))
    std::fprintf(stderr, "\nbench: %s (the partial results are not kept)\n", error.c_str());
}

std::string FlipName(const BenchResults& res) {
  return std::isfinite(res.flipPpd) ? "FLIP (" + Num(res.flipPpd, 2) + " ppd)" : std::string("FLIP (67 ppd, before the ppd field)");
}

double ArticleScaleRatio(const std::string& filter) {
  static const std::map<std::string, double> ratios = {
      {"point", 1.0}, {"bilinear", 1.0}, {"bicubic", 8.75},
      {"noise", 1.25}, {"noise-offset", 1.75}, {"taa", 2.75}};
  const auto it = ratios.find(filter);
  return it == ratios.end() ? 0.0 : it->second;
}

bool WriteBenchOutputs(const BenchResults& results, const std::string& outDir,
                       std::string* error) {
  return WriteCsv(results, outDir + "/results.csv", error) &&
         WriteJson(results, outDir + "/results.json", error) &&
         WritePlots(results, outDir, error) &&
         WriteSummary(results, outDir + "/summary.md", error);
}

}  // namespace drr
