#include "bench/Bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "DynamicResolutionRendering.h"
#include "analysis/ImageMetrics.h"
#include "bench/BenchReport.h"
#include "imageio/ImageFile.h"

namespace drr {
namespace {

const char* kBenchUsage =
    "DynamicResolutionRendering --bench [--quick] --out DIR [sample options]\n"
    "\n"
    "Renders every (camera view, filter, scale) after a warm-up and records image\n"
    "error (PSNR, SSIM, max error) against a 4x4 super-sampled reference, GPU time\n"
    "per pass (median and quartiles) and wall time. Writes results.csv,\n"
    "results.json, summary.md and plots (PNG) into DIR.\n"
    "\n"
    "  --quick              short preset for CI: one static camera, point / bilinear /\n"
    "                       bicubic / TAA at scales 0.3 0.5 0.71 1.0, 320x180\n"
    "  --out DIR            output folder (default: bench_out)\n"
    "  --bench-warmup N     frames rendered before measuring (default 8, quick 4)\n"
    "  --bench-frames N     frames measured per configuration (default 24, quick 6)\n"
    "  --camera N           only this camera (a static view at its default time)\n"
    "  --filter F           only this filter\n"
    "  --scale S            only this scale\n"
    "  --width/--height, --scene, --no-motion-blur, --symmetric-taa, --no-ps-clear,\n"
    "  --validation         as for the sample (see DynamicResolutionRendering --help)\n";

bool ParseInt(const std::string& s, int lo, int hi, int* out) {
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || !end || *end || v < lo || v > hi) return false;
  *out = int(v);
  return true;
}

double Percentile(std::vector<double> v, double p) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double pos = p * double(v.size() - 1);
  const size_t i = size_t(pos);
  const double f = pos - double(i);
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

Stat Summarise(const std::vector<double>& v) {
  return {Percentile(v, 0.5), Percentile(v, 0.25), Percentile(v, 0.75)};
}

ImageF ToImage(const ImageRGBA8& img) {
  return ImageFromRGBA8(img.pixels.data(), img.width, img.height, img.width * 4);
}

class Progress {
 public:
  explicit Progress(size_t total) : total_(total), tty_(isatty(2)) {}
  void Step(const std::string& what) {
    ++done_;
    const int width = 30;
    const int filled = int(width * done_ / std::max<size_t>(total_, 1));
    if (tty_) {
      std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu %-40.40s", filled,
                   "==============================", width - filled, "", done_, total_,
                   what.c_str());
      if (done_ == total_) std::fprintf(stderr, "\n");
    } else {
      std::fprintf(stderr, "bench %zu/%zu %s\n", done_, total_, what.c_str());
    }
    std::fflush(stderr);
  }

 private:
  size_t total_, done_ = 0;
  bool tty_;
};

// Renders `frames` frames and returns the records they produced.
std::vector<FrameRecord> RenderFrames(Sample& sample, int frames) {
  const size_t before = sample.Frames().size();
  for (int i = 0; i < frames; ++i) sample.RenderFrame();
  const auto& all = sample.Frames();
  return std::vector<FrameRecord>(all.begin() + std::ptrdiff_t(std::min(before, all.size())),
                                  all.end());
}

ImageRGBA8 Capture(Sample& sample) {
  sample.RequestCapture();
  sample.RenderFrame();
  return sample.CapturedBackBufferNoGui();
}

Options ViewOptions(const BenchPlan& plan, const BenchView& view) {
  Options o = plan.base;
  o.headless = true;
  o.gui = false;
  o.camera = view.camera;
  o.time = view.time;
  o.control = ControlMode::Manual;
  o.controlGiven = true;
  o.scaleGiven = true;
  o.vsync = false;
  o.screenshot.clear();
  o.report.clear();
  return o;
}

bool MakeReference(const BenchPlan& plan, const BenchView& view, ImageF* reference,
                   BenchRow* repeatRow, std::string* error) {
  Options o = ViewOptions(plan, view);
  o.width = plan.base.width * plan.referenceFactor;
  o.height = plan.base.height * plan.referenceFactor;
  o.dynamicResolution = false;
  o.motionBlur = false;
  o.filter = Filter::Point;
  Sample sample;
  if (sample.Init(o, error) != 0) return false;
  RenderFrames(sample, 2);
  const ImageRGBA8 first = Capture(sample);
  const ImageRGBA8 second = Capture(sample);
  sample.Shutdown();
  if (first.Empty() || second.Empty()) {
    *error = "the reference frame could not be read back";
    return false;
  }
  *reference = Downsample(ToImage(first), plan.referenceFactor);
  // Rendering must be deterministic for the comparison to mean anything:
  // the same frame rendered twice has to be identical (PSNR = infinity).
  repeatRow->view = view.name;
  repeatRow->filter = "reference-repeat";
  repeatRow->scale = 1.0;
  repeatRow->error = CompareImages(Downsample(ToImage(second), plan.referenceFactor), *reference);
  return true;
}

}  // namespace

bool HasBenchFlag(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--bench") == 0) return true;
  }
  return false;
}

int ParseBenchCommandLine(const std::vector<std::string>& args, BenchPlan* plan,
                          std::string* message) {
  std::vector<std::string> rest;
  bool cameraGiven = false, filterGiven = false, scaleGiven = false, sizeGiven = false;
  int warmup = -1, frames = -1;
  plan->outDir = "bench_out";
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* name, std::string* out) {
      if (i + 1 >= args.size()) {
        *message = std::string(name) + ": missing value\n\n" + kBenchUsage;
        return false;
      }
      *out = args[++i];
      return true;
    };
    std::string v;
    if (a == "--bench") continue;
    if (a == "--help" || a == "-h") {
      *message = kBenchUsage;
      return 1;
    }
    if (a == "--quick") {
      plan->quick = true;
    } else if (a == "--out") {
      if (!value("--out", &plan->outDir)) return 2;
    } else if (a == "--bench-warmup" || a == "--bench-frames") {
      if (!value(a.c_str(), &v)) return 2;
      int n = 0;
      if (!ParseInt(v, a == "--bench-warmup" ? 0 : 1, 10000, &n)) {
        *message = a + ": expected an integer in [" + (a == "--bench-warmup" ? "0" : "1") +
                   ", 10000], got '" + v + "'";
        return 2;
      }
      (a == "--bench-warmup" ? warmup : frames) = n;
    } else {
      cameraGiven |= a == "--camera";
      filterGiven |= a == "--filter";
      scaleGiven |= a == "--scale" || a == "--scale-x" || a == "--scale-y";
      sizeGiven |= a == "--width" || a == "--height";
      rest.push_back(a);
    }
  }
  std::string parseMessage;
  const ParseStatus status = ParseCommandLine(rest, &plan->base, &parseMessage);
  if (status == ParseStatus::Error) {
    *message = parseMessage;
    return 2;
  }
  if (status == ParseStatus::Help) {
    *message = kBenchUsage;
    return 1;
  }
  if (plan->outDir.empty()) {
    *message = "--out: the output folder must not be empty";
    return 2;
  }
  if (plan->quick && !sizeGiven) {
    plan->base.width = 320;
    plan->base.height = 180;
  }
  plan->warmupFrames = warmup >= 0 ? warmup : (plan->quick ? 4 : 8);
  plan->measuredFrames = frames >= 0 ? frames : (plan->quick ? 6 : 24);

  if (cameraGiven) {
    plan->views = {{plan->base.camera, plan->base.time >= 0 ? plan->base.time : 0.0,
                    "camera " + std::to_string(plan->base.camera)}};
  } else if (plan->quick) {
    plan->views = {{1, 0.0, "static 1"}};
  } else {
    plan->views = {{1, 0.0, "static 1"},
                   {2, 0.0, "static 2"},
                   {0, 4.0, "cinematic t=4"},
                   {0, 12.0, "cinematic t=12"}};
  }
  if (filterGiven) {
    plan->filters = {plan->base.filter};
  } else if (plan->quick) {
    plan->filters = {Filter::Point, Filter::Bilinear, Filter::Bicubic, Filter::TAA};
  } else {
    for (int f = int(Filter::Point); f < int(Filter::Count); ++f) plan->filters.push_back(Filter(f));
  }
  if (scaleGiven) {
    plan->scales = {plan->base.scaleX};
  } else if (plan->quick) {
    plan->scales = {0.3f, 0.5f, 0.71f, 1.0f};
  } else {
    plan->scales = {0.3f, 0.4f, 0.5f, 0.6f, 0.71f, 0.8f, 0.9f, 1.0f, 1.25f, 1.5f, 2.0f};
  }
  return 0;
}

int RunBench(const BenchPlan& plan) {
  std::error_code ec;
  std::filesystem::create_directories(plan.outDir, ec);
  if (ec) {
    std::fprintf(stderr, "bench: cannot create '%s': %s\n", plan.outDir.c_str(),
                 ec.message().c_str());
    return 1;
  }
  BenchResults results;
  results.plan = &plan;
  const size_t perView = 2 + plan.filters.size() * plan.scales.size();  // + reference, native
  Progress progress(plan.views.size() * perView);
  const auto started = std::chrono::steady_clock::now();

  for (const BenchView& view : plan.views) {
    std::string error;
    ImageF reference;
    BenchRow repeat;
    if (!MakeReference(plan, view, &reference, &repeat, &error)) {
      std::fprintf(stderr, "\nbench: reference for %s failed: %s\n", view.name.c_str(),
                   error.c_str());
      return 1;
    }
    results.rows.push_back(repeat);
    progress.Step(view.name + " reference");

    Options o = ViewOptions(plan, view);
    o.superSampling = std::any_of(plan.scales.begin(), plan.scales.end(),
                                  [](float s) { return s > 1.0f; });
    Sample sample;
    if (sample.Init(o, &error) != 0) {
      std::fprintf(stderr, "\nbench: %s\n", error.c_str());
      return 1;
    }
    if (results.adapter.empty()) {
      d3dl::ADAPTER_DESC adapter;
      sample.GetDevice()->GetAdapterDesc(&adapter);
      results.adapter = adapter.Description;
      results.driver = adapter.Driver;
    }

    auto measure = [&](const Options& settings, const std::string& filterName, double scale) {
      sample.ApplySettings(settings);
      RenderFrames(sample, plan.warmupFrames);
      const std::vector<FrameRecord> frames = RenderFrames(sample, plan.measuredFrames);
      BenchRow row;
      row.view = view.name;
      row.filter = filterName;
      row.scale = scale;
      std::vector<double> f, c, s, p, sc, wall;
      for (const FrameRecord& r : frames) {
        f.push_back(r.gpuFrame);
        c.push_back(r.gpuClear);
        s.push_back(r.gpuScene);
        p.push_back(r.gpuPostP);
        sc.push_back(r.gpuScale);
        wall.push_back(r.cpuFrameMs);
      }
      row.gpuFrame = Summarise(f);
      row.gpuClear = Summarise(c);
      row.gpuScene = Summarise(s);
      row.gpuPost = Summarise(p);
      row.gpuScale = Summarise(sc);
      row.wall = Summarise(wall);
      const ImageRGBA8 image = Capture(sample);
      row.error = CompareImages(ToImage(image), reference);
      row.viewportW = sample.GetDynamicResolution().GetViewport().Width;
      row.viewportH = sample.GetDynamicResolution().GetViewport().Height;
      results.rows.push_back(row);
      progress.Step(view.name + " " + filterName + " " + std::to_string(scale).substr(0, 4));
    };

    // Native: dynamic resolution off, the full-resolution path of the original.
    Options native = o;
    native.dynamicResolution = false;
    native.filter = Filter::Point;
    measure(native, "native", 1.0);

    for (Filter filter : plan.filters) {
      for (float scale : plan.scales) {
        Options s = o;
        s.dynamicResolution = true;
        s.filter = filter;
        s.scaleX = s.scaleY = scale;
        measure(s, FilterOption(filter), scale);
      }
    }
    results.validationMessages += sample.ValidationMessages();
    sample.Shutdown();
  }
  results.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::string error;
  if (!WriteBenchOutputs(results, plan.outDir, &error)) {
    std::fprintf(stderr, "bench: %s\n", error.c_str());
    return 1;
  }
  std::printf("bench: %zu configurations in %.1f s on %s; results in %s\n", results.rows.size(),
              results.seconds, results.adapter.c_str(), plan.outDir.c_str());
  if (plan.base.validation && results.validationMessages > 0) {
    std::fprintf(stderr, "bench: %llu validation messages\n",
                 static_cast<unsigned long long>(results.validationMessages));
    return 3;
  }
  return 0;
}

int BenchMain(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  BenchPlan plan;
  std::string message;
  const int rc = ParseBenchCommandLine(args, &plan, &message);
  if (rc == 1) {
    std::printf("%s", message.c_str());
    return 0;
  }
  if (rc != 0) {
    std::fprintf(stderr, "error: %s\n", message.c_str());
    return rc;
  }
  return RunBench(plan);
}

}  // namespace drr
