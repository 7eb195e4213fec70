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

namespace drr {
namespace {

std::string Num(double v, int decimals = 4) {
  if (std::isnan(v)) return "";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

// JSON has no infinity: identical images report "psnr": null with "identical": true.
std::string JsonNum(double v, int decimals = 6) {
  return std::isfinite(v) ? Num(v, decimals) : "null";
}

std::string JsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + "\"";
}

// Mean over views of a row value, for one filter and scale (NaN if none).
template <class Get>
double MeanOver(const std::vector<BenchRow>& rows, const std::string& filter, double scale,
                Get get) {
  double sum = 0;
  int n = 0;
  for (const auto& r : rows) {
    if (r.filter == filter && std::abs(r.scale - scale) < 1e-4) {
      const double v = get(r);
      if (std::isfinite(v)) {
        sum += v;
        ++n;
      }
    }
  }
  return n ? sum / n : std::nan("");
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
  out << "view,filter,scale,viewport_w,viewport_h,psnr_db,ssim,max_abs_error,mse,valid,"
         "gpu_frame_ms,gpu_frame_p25,gpu_frame_p75,gpu_clear_ms,gpu_scene_ms,gpu_post_ms,"
         "gpu_scale_ms,gpu_scale_p25,gpu_scale_p75,wall_ms,wall_p25,wall_p75\n";
  for (const auto& r : res.rows) {
    out << '"' << r.view << "\"," << r.filter << ',' << Num(r.scale, 3) << ',' << r.viewportW
        << ',' << r.viewportH << ',' << Num(r.error.psnr, 3) << ',' << Num(r.error.ssim, 5)
        << ',' << Num(r.error.maxAbsError, 5) << ',' << Num(r.error.mse, 8) << ','
        << (r.error.valid ? 1 : 0) << ',' << Num(r.gpuFrame.median) << ','
        << Num(r.gpuFrame.p25) << ',' << Num(r.gpuFrame.p75) << ',' << Num(r.gpuClear.median)
        << ',' << Num(r.gpuScene.median) << ',' << Num(r.gpuPost.median) << ','
        << Num(r.gpuScale.median) << ',' << Num(r.gpuScale.p25) << ',' << Num(r.gpuScale.p75)
        << ',' << Num(r.wall.median) << ',' << Num(r.wall.p25) << ',' << Num(r.wall.p75) << '\n';
  }
  return bool(out);
}

std::string StatJson(const Stat& s) {
  return "{\"median\": " + JsonNum(s.median) + ", \"p25\": " + JsonNum(s.p25) +
         ", \"p75\": " + JsonNum(s.p75) + "}";
}

bool WriteJson(const BenchResults& res, const std::string& path, std::string* error) {
  std::ofstream out(path);
  if (!out) {
    *error = "cannot write " + path;
    return false;
  }
  const BenchPlan& plan = *res.plan;
  out << "{\n  \"adapter\": " << JsonString(res.adapter) << ",\n  \"driver\": "
      << JsonString(res.driver) << ",\n  \"date\": " << JsonString(Today())
      << ",\n  \"quick\": " << (plan.quick ? "true" : "false") << ",\n  \"width\": "
      << plan.base.width << ",\n  \"height\": " << plan.base.height
      << ",\n  \"reference_factor\": " << plan.referenceFactor
      << ",\n  \"warmup_frames\": " << plan.warmupFrames
      << ",\n  \"measured_frames\": " << plan.measuredFrames << ",\n  \"seconds\": "
      << Num(res.seconds, 2) << ",\n  \"validation_messages\": " << res.validationMessages
      << ",\n  \"options\": " << OptionsToJson(plan.base) << ",\n  \"rows\": [\n";
  for (size_t i = 0; i < res.rows.size(); ++i) {
    const auto& r = res.rows[i];
    out << "    {\"view\": " << JsonString(r.view) << ", \"filter\": " << JsonString(r.filter)
        << ", \"scale\": " << Num(r.scale, 3) << ", \"viewport\": [" << r.viewportW << ", "
        << r.viewportH << "], \"valid\": " << (r.error.valid ? "true" : "false")
        << ", \"identical\": " << (r.error.valid && r.error.mse == 0 ? "true" : "false")
        << ", \"psnr_db\": " << JsonNum(r.error.psnr) << ", \"ssim\": " << JsonNum(r.error.ssim)
        << ", \"max_abs_error\": " << JsonNum(r.error.maxAbsError)
        << ", \"gpu_ms\": {\"frame\": " << StatJson(r.gpuFrame)
        << ", \"clear\": " << StatJson(r.gpuClear) << ", \"scene\": " << StatJson(r.gpuScene)
        << ", \"post\": " << StatJson(r.gpuPost) << ", \"scale\": " << StatJson(r.gpuScale)
        << "}, \"wall_ms\": " << StatJson(r.wall) << "}" << (i + 1 < res.rows.size() ? "," : "")
        << "\n";
  }
  out << "  ]\n}\n";
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
      const double psnr = MeanOver(res.rows, name, s, [](const BenchRow& r) { return r.error.psnr; });
      const double scaleMs = MeanOver(res.rows, name, s, [](const BenchRow& r) { return r.gpuScale.median; });
      const double frameMs = MeanOver(res.rows, name, s, [](const BenchRow& r) { return r.gpuFrame.median; });
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
  return WritePlotPng(vsScale, dir + "/error_vs_scale_time.png", error) &&
         WritePlotPng(vsFrame, dir + "/error_vs_frame_time.png", error) &&
         WritePlotPng(fig11, dir + "/frame_time_vs_scale.png", error);
}

bool WriteSummary(const BenchResults& res, const std::string& path, std::string* error) {
  const BenchPlan& plan = *res.plan;
  std::ostringstream md;
  md << "## " << (plan.quick ? "Quick" : "Full") << " sweep on " << res.adapter << "\n\n"
     << "Driver " << res.driver << ", " << Today() << ", back buffer " << plan.base.width << "x"
     << plan.base.height << ", reference " << plan.referenceFactor << "x"
     << plan.referenceFactor << " super sampling, " << plan.warmupFrames << " warm-up + "
     << plan.measuredFrames << " measured frames per configuration, " << res.rows.size()
     << " configurations in " << Num(res.seconds, 1) << " s, " << res.validationMessages
     << " validation messages.\n\n";

  md << "### PSNR (dB, mean over views) by filter and scale\n\n| filter |";
  for (float s : plan.scales) md << ' ' << Num(s, 2) << " |";
  md << "\n| --- |";
  for (size_t i = 0; i < plan.scales.size(); ++i) md << " ---: |";
  md << '\n';
  for (Filter f : plan.filters) {
    md << "| " << FilterOption(f) << " |";
    for (float s : plan.scales)
      md << ' ' << Num(MeanOver(res.rows, FilterOption(f), s, [](const BenchRow& r) { return r.error.psnr; }), 2) << " |";
    md << '\n';
  }
  md << "| native (dynamic resolution off) | "
     << Num(MeanOver(res.rows, "native", 1.0, [](const BenchRow& r) { return r.error.psnr; }), 2)
     << " (at 1.0) |\n\n";

  md << "### Scale-pass cost (GPU ms, median, mean over views)\n\n"
        "| filter | scale | ms | ratio to point | article ratio (JP) |\n"
        "| --- | ---: | ---: | ---: | ---: |\n";
  const float costScale = std::find(plan.scales.begin(), plan.scales.end(), 0.71f) != plan.scales.end()
                              ? 0.71f : plan.scales.front();
  const double pointMs = MeanOver(res.rows, "point", costScale, [](const BenchRow& r) { return r.gpuScale.median; });
  for (Filter f : plan.filters) {
    const double ms = MeanOver(res.rows, FilterOption(f), costScale, [](const BenchRow& r) { return r.gpuScale.median; });
    const double article = ArticleScaleRatio(FilterOption(f));
    md << "| " << FilterOption(f) << " | " << Num(costScale, 2) << " | " << Num(ms, 3) << " | "
       << Num(pointMs > 0 ? ms / pointMs : std::nan(""), 2) << " | "
       << (article > 0 ? Num(article, 2) : std::string("-")) << " |\n";
  }

  md << "\n### Frame and scene time against scale (point filter)\n\n"
        "| scale | frame ms | scene ms | wall ms |\n| ---: | ---: | ---: | ---: |\n";
  for (float s : plan.scales) {
    md << "| " << Num(s, 2) << " | "
       << Num(MeanOver(res.rows, "point", s, [](const BenchRow& r) { return r.gpuFrame.median; }), 3) << " | "
       << Num(MeanOver(res.rows, "point", s, [](const BenchRow& r) { return r.gpuScene.median; }), 3) << " | "
       << Num(MeanOver(res.rows, "point", s, [](const BenchRow& r) { return r.wall.median; }), 3) << " |\n";
  }
  md << "\nPlots: `error_vs_scale_time.png`, `error_vs_frame_time.png`, "
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
