#include "bench/Bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>
#include <unistd.h>

#include "DynamicResolutionRendering.h"
#include "analysis/ImageMetrics.h"
#include "analysis/Flip.h"
#include "analysis/TemporalStability.h"
#include "bench/BenchCommon.h"
#include "bench/BenchFixedBlit.h"
#include "bench/BenchReport.h"
#include "imageio/ImageFile.h"

namespace drr {
namespace {

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
  const Image first = Capture(sample);
  const Image second = Capture(sample);
  sample.Shutdown();
  if (first.Empty() || second.Empty()) {
    *error = "the reference frame could not be read back";
    return false;
  }
  *reference = Downsample(ToImage(first), plan.referenceFactor);
  // Rendering must be deterministic for the comparison to mean anything:
  // the same frame rendered twice has to be identical (PSNR = infinity).
  repeatRow->view = view.name;
  repeatRow->filter = kReferenceRepeat;
  repeatRow->scale = 1.0;
  repeatRow->error = CompareImages(Downsample(ToImage(second), plan.referenceFactor), *reference);
  return true;
}

// Fraction of pixels whose largest RGB difference exceeds `threshold`.
double FractionAbove(const ImageF& a, const ImageF& b, float threshold) {
  if (a.width != b.width || a.height != b.height || a.width == 0 || a.channels < 3 || b.channels < 3)
    return std::nan("");
  uint64_t above = 0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      float m = 0;
      for (uint32_t c = 0; c < 3; ++c) m = std::max(m, std::abs(a.At(x, y, c) - b.At(x, y, c)));
      if (m > threshold) ++above;
    }
  return double(above) / double(uint64_t(a.width) * a.height);
}

// One measured configuration of a running sample: apply, warm up, measure,
// capture. Returns the row (error against `reference`) and the image.
BenchRow Measure(Sample& sample, const BenchPlan& plan, const Options& settings,
                 const std::string& viewName, const std::string& filterName, double scale,
                 const ImageF& reference, int warmup, int frames, Image* imageOut = nullptr) {
  sample.ApplySettings(settings);
  const auto start = std::chrono::steady_clock::now();
  RenderFrames(sample, warmup);
  // Moving runs (warmup 0) count their frames exactly; static ones may add more.
  while (warmup > 0 && std::chrono::steady_clock::now() - start < std::chrono::milliseconds(plan.warmupMs))
    RenderFrames(sample, 1);
  const std::vector<FrameRecord> records = RenderFrames(sample, frames);
  BenchRow row;
  row.view = viewName;
  row.filter = filterName;
  row.scale = scale;
  FillGpuTimes({records}, &row);
  row.superSampling = settings.superSampling;
  const Image image = Capture(sample);
  const ImageF imageF = ToImage(image);
  row.error = CompareImages(imageF, reference);
  const FlipResult flip = ComputeFlip(reference, imageF, FlipPpd(plan));
  row.flip = flip.valid ? flip.mean : std::nan("");
  if (settings.dynamicResolution) {
    row.viewportW = sample.GetDynamicResolution().GetViewport().Width;
    row.viewportH = sample.GetDynamicResolution().GetViewport().Height;
  } else {
    row.viewportW = float(sample.BackBufferWidth());
    row.viewportH = float(sample.BackBufferHeight());
  }
  if (imageOut) *imageOut = image;
  return row;
}

// TAAU accumulates over its jitter sequence: a still row is measured after
// two whole cycles (the original's TAA settles in two frames); not in the
// quick preset, which checks completeness, not convergence.
int StillWarmup(const BenchPlan& plan, Filter filter) {
  if (!IsTemporalUpsample(filter) || plan.quick) return plan.warmupFrames;
  return std::max(plan.warmupFrames, int(2 * kUpsampleJitterLength));
}

// Jitter instability on a still camera: the mean over `pairs` pairs of
// consecutive frames (the first is `first`, the frame just captured) of the
// RMS change between them; the reference of a still view does not change.
constexpr int kStillInstabilityPairs = 2;
double StillInstability(Sample& sample, ImageF first, int pairs) {
  std::vector<double> change;
  for (int i = 0; i < pairs; ++i) {
    ImageF next = ToImage(Capture(sample));
    change.push_back(ReprojectedInstability(first, next, first, first, MotionField{}));
    first = std::move(next);
  }
  return BlockMeanCi(change, 1).mean;
}

// What the measurements of one view share; AddRow measures one configuration
// with the plan's warm-up and frame counts and records it.
struct ViewRun {
  const BenchPlan& plan;
  const BenchView& view;
  const ImageF& reference;
  Sample& sample;
  BenchResults* results;
  Progress* progress;

  // Rows whose times the interleaved pass measures: settings and row index.
  std::vector<std::pair<Options, size_t>> timed = {};

  void AddRow(const Options& settings, const std::string& filterName, double scale) {
    Image image;
    BenchRow row = Measure(sample, plan, settings, view.name, filterName, scale, reference,
                           StillWarmup(plan, settings.filter), plan.measuredFrames, &image);
    row.instability = StillInstability(sample, ToImage(image), kStillInstabilityPairs);
    results->Add(row);
    timed.emplace_back(settings, results->rows.size() - 1);
    progress->Step(view.name + " " + filterName + " " + Num2(scale));
  }
};

// Side-by-side timing: every timed configuration of the view in turn (each
// round starting one configuration later, each turn warmed up by frames and
// by time), for plan.timingRounds rounds of a few frames each, so a change of load on the
// machine spreads over all of them instead of falling on some rows. The rows'
// GPU and wall times are replaced by these.
void InterleaveTimes(ViewRun& run) {
  const BenchPlan& plan = run.plan;
  if (plan.timingRounds <= 0) return;
  std::vector<std::vector<std::vector<FrameRecord>>> rounds(run.timed.size());
  for (int r = 0; r < plan.timingRounds; ++r)
    for (size_t turn = 0; turn < run.timed.size(); ++turn) {
      const size_t i = (turn + size_t(r)) % run.timed.size();  // each round starts one later
      run.sample.ApplySettings(run.timed[i].first);
      RenderFrames(run.sample, plan.timingWarmup);
      WarmUpFor(run.sample, plan.timingWarmupMs);
      rounds[i].push_back(RenderFrames(run.sample, plan.timingFrames));
    }
  for (size_t i = 0; i < run.timed.size(); ++i) FillGpuTimes(rounds[i], &run.results->rows[run.timed[i].second]);
  run.progress->Step(run.view.name + " interleaved timing");
}



// Claim rows on the first view (article-figures.md): clears, super sampling,
// fast vs velocity-reading TAA. Scale 0.71 unless the name says otherwise.
void MeasureClaims(ViewRun& view, const Options& o) {
  auto run = [&](const std::string& name, double scale, auto&& edit) {
    Options s = o;
    s.dynamicResolution = true;
    s.filter = Filter::Point;
    s.scaleX = s.scaleY = float(scale);
    edit(s);
    view.AddRow(s, name, scale);
  };
  run("point api-clear", 0.71, [](Options& s) { s.psClear = false; s.superSampling = false; });
  run("point ps-clear", 0.71, [](Options& s) { s.psClear = true; s.superSampling = false; });
  run("point 1.0 no-ss", 1.0, [](Options& s) { s.superSampling = false; });
  run("point 1.0 ss-allowed", 1.0, [](Options& s) { s.superSampling = true; });
  run("point 1.0 no-ss api-clear", 1.0, [](Options& s) { s.superSampling = false; s.psClear = false; });
  run("point 1.0 ss-allowed api-clear", 1.0, [](Options& s) { s.superSampling = true; s.psClear = false; });
  run("taa fast (motion blur on)", 0.71, [](Options& s) { s.filter = Filter::TAA; s.motionBlur = true; s.superSampling = false; });
  run("taa velocity (motion blur off)", 0.71, [](Options& s) { s.filter = Filter::TAA; s.motionBlur = false; s.superSampling = false; });
}

// Moving cinematic camera: ghosting per filter and the motion-blur claim.
// The animation advances by plan.ghostStep per frame (Options::fixedDt): the
// sample sets animation time = max(time, 0) + frameCount * fixedDt, so with
// time = ghostTime - (frameCount at capture) * fixedDt the captured frame is
// at ghostTime exactly, and the reference is rendered there.
struct GhostRun {
  const BenchPlan& plan;
  Sample& sample;
  const ImageF& reference;
  std::string viewName;
  Progress* progress;
  bool exact = true;  // every capture at plan.ghostTime

  // plan.ghostFrames moving frames of `s`, then the capture at ghostTime.
  BenchRow Run(const std::string& name, Options s, Image* image) {
    const int n = plan.ghostFrames;
    s.camera = 1;  // cinematic
    s.fixedDt = plan.ghostStep;
    const int64_t captureFrame = sample.FrameCount() + n;  // n frames, then the capture
    s.time = plan.ghostTime - double(captureFrame) * plan.ghostStep;
    BenchRow row = Measure(sample, plan, s, viewName, name, s.scaleX, reference, 0, n, image);
    row.animTime = std::max(s.time, 0.0) + double(captureFrame) * s.fixedDt;
    exact = exact && std::abs(row.animTime - plan.ghostTime) < 1e-9;
    progress->Step(viewName + " " + name);
    return row;
  }
};

void MeasureGhosting(GhostRun& run, const Options& o, BenchResults* results) {
  const int n = run.plan.ghostFrames;
  for (Filter f : {Filter::Point, Filter::TAA, Filter::TAABasic, Filter::TAANoiseOffset}) {
    Options s = o;
    s.dynamicResolution = true;
    s.motionBlur = false;  // isolates the history: the reference has no motion blur
    s.filter = f;
    s.scaleX = s.scaleY = 0.71f;
    Image image, still;
    BenchRow row = run.Run(std::string("ghost ") + FilterOption(f), s, &image);
    // The same filter settled on the same animation time (camera held
    // still): the difference is what the motion adds (ghost trails), not
    // the filter's spatial error.
    Options h = s;
    h.fixedDt = 0.0;
    h.time = run.plan.ghostTime;
    // An even number of frames between the two captures keeps the TAA
    // jitter phase (the final RT index flips every frame) the same.
    const int stillFrames = n + ((n + 1) % 2);
    Measure(run.sample, run.plan, h, run.viewName, "still", 0.71, run.reference, 0, stillFrames, &still);
    run.progress->Step(run.viewName + " still " + FilterOption(f));
    row.ghostFraction = FractionAbove(ToImage(image), ToImage(still), 0.1f);
    results->Add(row);
  }
}

void MeasureMotionBlurClaim(GhostRun& run, Options s, BenchResults* results) {
  s.dynamicResolution = false;
  s.motionBlur = true;
  s.filter = Filter::Point;
  Image nativeImage, scaledImage;
  BenchRow native = run.Run("motion-blur native", s, &nativeImage);
  s.dynamicResolution = true;
  s.filter = Filter::Bilinear;
  s.scaleX = s.scaleY = 0.71f;
  BenchRow scaled = run.Run("motion-blur 0.71", s, &scaledImage);
  scaled.psnrVsNative = CompareImages(ToImage(scaledImage), ToImage(nativeImage)).psnr;
  results->Add(native);
  results->Add(scaled);
}

bool MeasureMoving(const BenchPlan& plan, BenchResults* results, Progress* progress, std::string* error) {
  const BenchView refView{1, plan.ghostTime, "cinematic moving t=" + Num2(plan.ghostTime)};
  ImageF reference;
  BenchRow repeat;
  if (!MakeReference(plan, refView, &reference, &repeat, error)) return false;
  progress->Step(refView.name + " reference");
  Options o = ViewOptions(plan, refView);
  o.superSampling = false;
  Sample sample;
  if (sample.Init(o, error) != 0) return false;
  GhostRun run{plan, sample, reference, refView.name, progress};
  if (plan.ghosting) MeasureGhosting(run, o, results);
  if (plan.claims) MeasureMotionBlurClaim(run, o, results);
  results->validationMessages += sample.ValidationMessages();
  sample.Shutdown();
  if (!run.exact) {
    *error = "the moving camera's captured frame is not at the reference time (ghostTime too small "
             "for the frames rendered before it?)";
    return false;
  }
  return true;
}

// The fixed-function blit of one scale, from the scene colour of the row just
// measured: same source region, same back-buffer size, linear filter.
bool AddFixedBlitRow(ViewRun& run, FixedFunctionBlit& blit, float scale, std::string* error) {
  const Image scene = run.sample.CapturedSceneColor();
  const BenchRow& last = run.results->rows.back();
  BenchRow row;
  row.view = run.view.name;
  row.filter = kFixedBlit;
  row.scale = scale;
  row.viewportW = last.viewportW;
  row.viewportH = last.viewportH;
  std::vector<double> ms;
  Image image;
  if (!blit.Run(scene, uint32_t(last.viewportW), uint32_t(last.viewportH), run.sample.BackBufferWidth(),
                run.sample.BackBufferHeight(), run.plan.measuredFrames, &ms, &image, error))
    return false;
  row.gpuScale = Summarise(ms);
  row.gpuSamples = int(ms.size());
  row.error = CompareImages(ToImage(image), run.reference);
  run.results->Add(row);
  run.progress->Step(run.view.name + " " + kFixedBlit + " " + Num2(scale));
  return true;
}

// Native (dynamic resolution off, the full-resolution path of the original),
// then every filter at every scale up to 1.0 with 2x targets not allowed (as
// the original runs below 1.0), the fixed-function blit after the first filter
// (point in the default plans); then the scales above 1.0 as super-sampling
// rows of their own (2x targets allowed).
bool MeasureSweep(ViewRun& run, const Options& o, std::string* error) {
  Options native = o;
  native.dynamicResolution = false;
  native.superSampling = false;
  native.filter = Filter::Point;
  run.AddRow(native, "native", 1.0);
  FixedFunctionBlit blit(run.sample.GetDevice());
  const BenchPlan& plan = run.plan;
  for (bool superSampled : {false, true}) {
    for (size_t fi = 0; fi < plan.filters.size(); ++fi) {
      for (float scale : plan.scales) {
        if ((scale > 1.0f) != superSampled) continue;
        Options s = o;
        s.dynamicResolution = true;
        s.superSampling = superSampled;
        s.filter = plan.filters[fi];
        s.scaleX = s.scaleY = scale;
        run.AddRow(s, FilterOption(plan.filters[fi]), scale);
        if (fi == 0 && !AddFixedBlitRow(run, blit, scale, error)) return false;
      }
    }
  }
  return true;
}

// Jitter ablation on the first view: the symmetric pair (-0.25/+0.25 px)
// against the original's asymmetric one (0/0.5 px, the sweep's taa rows);
// texture mip bias: TAA at 0.71 with the plain sampler, TAAU at 0.5 and
// 0.71 without its automatic bias (against the sweep's taa and taau rows).
void MeasureStillAblations(ViewRun& run, const Options& o) {
  for (const MipBiasAblation& a : MipBiasAblations(run.plan)) {
    Options s = o;
    s.dynamicResolution = true;
    s.superSampling = false;
    a.edit(s);
    run.AddRow(s, a.name, s.scaleX);
  }
  for (float scale : {0.5f, 0.71f, 1.0f}) {
    Options s = o;
    s.dynamicResolution = true;
    s.superSampling = false;
    s.filter = Filter::TAA;
    s.symmetricTAA = true;
    s.scaleX = s.scaleY = scale;
    run.AddRow(s, kTaaSymmetric, scale);
  }
}

// One static view: reference, native, the sweep, and the claim rows when it
// is the first view. Says on stderr what failed.
bool MeasureView(const BenchPlan& plan, const BenchView& view, bool firstView, BenchResults* results,
                 Progress* progress) {
  std::string error;
  ImageF reference;
  BenchRow repeat;
  if (!MakeReference(plan, view, &reference, &repeat, &error)) {
    std::fprintf(stderr, "\nbench: reference for %s failed: %s\n", view.name.c_str(),
                 error.c_str());
    return false;
  }
  results->Add(repeat);
  progress->Step(view.name + " reference");

  Options o = ViewOptions(plan, view);
  o.superSampling = false;
  // The reference has no motion blur; without it the TAA rows are the
  // velocity-reading TAA (the article's cost figure), not the fast one.
  o.motionBlur = plan.sweepMotionBlur;
  Sample sample;
  if (sample.Init(o, &error) != 0) {
    std::fprintf(stderr, "\nbench: %s\n", error.c_str());
    return false;
  }
  if (results->adapter.empty()) {
    d3dl::ADAPTER_DESC adapter;
    sample.GetDevice()->GetAdapterDesc(&adapter);
    results->adapter = adapter.Description;
    results->driver = adapter.Driver;
    results->softwareAdapter = adapter.IsSoftware;
  }
  ViewRun run{plan, view, reference, sample, results, progress};
  if (!MeasureSweep(run, o, &error)) {
    std::fprintf(stderr, "\nbench: %s\n", error.c_str());
    return false;
  }
  if (firstView && plan.ablations) MeasureStillAblations(run, o);
  if (firstView && plan.claims) MeasureClaims(run, o);
  InterleaveTimes(run);
  results->validationMessages += sample.ValidationMessages();
  sample.Shutdown();
  return true;
}

// Progress steps: per view the reference, native, the sweep and one
// fixed-function-blit row per scale; claims on the first view; the moving camera
// (reference, ghosting with its still captures, motion blur).
size_t ProgressSteps(const BenchPlan& plan) {
  const size_t perView = 2 + plan.filters.size() * plan.scales.size() + plan.scales.size();
  const size_t moving = (plan.ghosting || plan.claims ? 1 : 0) + (plan.ghosting ? 8 : 0) + (plan.claims ? 2 : 0);
  return plan.views.size() * (perView + (plan.timingRounds > 0 ? 1 : 0)) + (plan.claims ? 8 : 0) +
         (plan.ablations ? 3 + MipBiasAblations(plan).size() : 0) + moving +
         MovingProgressSteps(plan);
}

// Host memory bandwidth: the best of five 256 MiB memcpy copies, counting the
// bytes read and written. For a CPU rasteriser this is its device memory.
double MeasureHostCopyGBs() {
  constexpr size_t kBytes = size_t(256) << 20;
  std::vector<char> a(kBytes, 1), b(kBytes, 2);
  double best = 0;
  for (int i = 0; i < 5; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    std::memcpy(b.data(), a.data(), kBytes);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (s > 0) best = std::max(best, 2.0 * double(kBytes) / s / 1e9);
    std::swap(a, b);
  }
  return best;
}

void ChooseBandwidth(const BenchPlan& plan, BenchResults* results) {
  if (plan.memoryBandwidthGBs > 0) {
    results->bandwidthGBs = plan.memoryBandwidthGBs;
    results->bandwidthSource = "given (--memory-bandwidth)";
  } else if (results->softwareAdapter) {
    results->bandwidthGBs = MeasureHostCopyGBs();
    results->bandwidthSource = "measured: host memcpy, 256 MiB, best of 5, read + written";
  } else {
    results->bandwidthSource = "unknown: give the device's figure with --memory-bandwidth";
  }
}

// --report-from: the report of a finished run, rendering nothing.
int RewriteReport(const BenchPlan& plan) {
  BenchResults results;
  results.plan = &plan;
  std::string error;
  if (!ReloadBenchResults(plan.reportFrom, &results, &error) || !WriteBenchOutputs(results, plan.outDir, &error)) {
    std::fprintf(stderr, "bench: %s\n", error.c_str());
    return 1;
  }
  std::printf("bench: report of %zu rows rewritten into %s\n", results.rows.size(), plan.outDir.c_str());
  return 0;
}

}  // namespace

int RunBench(const BenchPlan& plan) {
  std::error_code ec;
  std::filesystem::create_directories(plan.outDir, ec);
  if (ec) {
    std::fprintf(stderr, "bench: cannot create '%s': %s\n", plan.outDir.c_str(),
                 ec.message().c_str());
    return 1;
  }
  if (!plan.reportFrom.empty()) return RewriteReport(plan);
  BenchResults results;
  results.plan = &plan;
  results.flipPpd = FlipPpd(plan);
  results.flipDisplay = plan.flipPpd > 0 ? "given (--flip-ppd)"
                                         : "the frame full-screen on a 0.7 m wide, 3840-pixel display seen from 0.7 m";
  results.partialDir = plan.outDir;
  Progress progress(ProgressSteps(plan));
  const auto started = std::chrono::steady_clock::now();

  for (size_t vi = 0; vi < plan.views.size(); ++vi)
    if (!MeasureView(plan, plan.views[vi], vi == 0, &results, &progress)) return 1;
  if (plan.ghosting || plan.claims) {
    std::string error;
    if (!MeasureMoving(plan, &results, &progress, &error)) {
      std::fprintf(stderr, "\nbench: moving camera: %s\n", error.c_str());
      return 1;
    }
  }
  if (plan.moving) {
    std::string error;
    if (!MeasureMovingSequences(plan, &results, &progress, &error)) {
      std::fprintf(stderr, "\nbench: moving sequences: %s\n", error.c_str());
      return 1;
    }
  }
  ChooseBandwidth(plan, &results);
  results.complete = true;
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

double FlipPpd(const BenchPlan& plan) {
  return plan.flipPpd > 0 ? plan.flipPpd : FlipFullScreenPpd(plan.base.width);
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
