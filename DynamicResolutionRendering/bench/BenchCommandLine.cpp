// --bench's command line: its own options, the sample's options, and the
// sweep (views, filters, scales) that follows from them.
#include "bench/Bench.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace drr {
namespace {

const char* kBenchUsage =
    "DynamicResolutionRendering --bench [--quick] --out DIR [sample options]\n"
    "\n"
    "Renders every (camera view, filter, scale) after a warm-up and records image\n"
    "error (PSNR, SSIM, max error) against a 4x4 super-sampled reference, GPU time\n"
    "per pass (median and quartiles) and wall time. Writes results.csv,\n"
    "results.json, summary.md and plots (PNG) into DIR.\n"
    "Also measured: a 'fixed-function-blit' row per view and scale (a linear\n"
    "vkCmdBlitImage of the viewport region to a back-buffer-sized target: another\n"
    "driver path, not a floor; the bandwidth bound, bytes read + written / memory\n"
    "bandwidth, is the physical limit of the\n"
    "scale pass, with each filter's cost as a ratio to it and to point); claim rows\n"
    "on the first view at 0.71 (pixel-shader vs API clear, super sampling allowed at\n"
    "1.0, fast vs velocity-reading TAA) and motion blur at 0.71 vs native on the\n"
    "moving cinematic camera; ghosting ('ghost <filter>': point, taa, taa-basic,\n"
    "taa-noise-offset at 0.71, motion blur off) on the cinematic camera moving by a\n"
    "fixed step per frame: PSNR against the reference rendered at the captured\n"
    "frame's animation time, ghost fraction = pixels > 0.1 away from the same\n"
    "filter's still image of that time. summary.md judges the article's claims\n"
    "from these numbers.\n"
    "\n"
    "  --quick              short preset for CI: one static camera, point / bilinear /\n"
    "                       bicubic / TAA / TAAU at scales 0.3 0.5 0.71 1.0, 320x180,\n"
    "                       with the fixed-function-blit, claim and ghosting rows, and\n"
    "                       the moving camera at x1 (point, bilinear, taa, taau at\n"
    "                       0.5 and 1.0); interleaved timing 1 + 4 frames a turn\n"
    "  --out DIR            output folder (default: bench_out)\n"
    "  --bench-warmup N     frames rendered before measuring (default 8, quick 4)\n"
    "  --bench-warmup-ms T  and warm up for at least T ms (default 500, quick 0): GPU\n"
    "                       clocks drop while the CPU compares images, and a few\n"
    "                       frames do not bring them back\n"
    "  --bench-frames N     frames measured per configuration (default 24, quick 6)\n"
    "  --camera N           only this camera (a static view at its default time)\n"
    "  --filter F           only this filter\n"
    "  --scale S            only this scale\n"
    "  --filters LIST       these filters (comma-separated --filter names), still\n"
    "                       and moving; TAAU's still rows warm up for at least two\n"
    "                       jitter cycles (32 frames; not with --quick)\n"
    "  --scales LIST        these scales (comma-separated), still; moving: those\n"
    "                       at or below 1.0\n"
    "  --memory-bandwidth GBPS  device memory bandwidth for the bandwidth bound of the\n"
    "                       scale pass (default: measured host memcpy on CPU\n"
    "                       rasterisers, none on GPUs: give the device's figure)\n"
    "  --no-claims          skip the claim rows\n"
    "  --no-ghosting        skip the ghosting rows\n"
    "  --ghost-frames N     moving frames before the ghosting capture (default 24,\n"
    "                       quick 6); the camera steps 1/30 s per frame and the\n"
    "                       capture is at animation time 12 s\n"
    "  --flip-ppd PPD       FLIP's pixels per degree (default: the frame shown full-screen\n"
    "                       on FLIP's reference display, 0.7 m wide, 3840 pixels, seen\n"
    "                       from 0.7 m: 67.02 x width / 3840)\n"
    "  --timing-warmup-ms T each timed turn warms up for at least T ms (default 200,\n"
    "                       quick 0)\n"
"  --report-from DIR    rewrite the report into --out from DIR's results.csv/json\n"
    "                       (the same sweep options as that run), rendering nothing\n"
"  --timing-rounds N    interleaved timing: every configuration of a still view\n"
    "                       in turn, N rounds of 2 + 6 frames (default 4, quick 1; 0:\n"
    "                       the times of the sequential measurement)\n"
    "  --no-moving          skip the moving-camera sequences: the cinematic camera\n"
    "                       at speeds 0.5, 1 and 2 (quick: 1; 1 = 1/30 s of animation\n"
    "                       a frame), every filter at scales 0.4 0.55 0.71 0.85 1.0\n"
    "                       (quick: point, bilinear, taa, taau at 0.5 and 1.0) and native,\n"
    "                       no 2x targets, motion blur off; each frame against the\n"
    "                       reference of its animation time: PSNR, SSIM, FLIP, and\n"
    "                       instability (frame-to-frame change after reprojecting the\n"
    "                       previous frame with the reference's velocity, less the\n"
    "                       reference's own change); still rows: the change between\n"
    "                       consecutive frames (jitter instability)\n"
    "  --moving-frames N    frames compared per sequence (default 60, quick 4)\n"
    "  --moving-warmup N    frames before them (default 8, quick 2)\n"
    "  --moving-speed P     only this speed, in percent (100 = 1/30 s a frame)\n"
    "  --no-ablations       skip the ablation rows (symmetric jitter still and moving,\n"
    "                       fast TAA and native with motion blur on, moving; texture\n"
    "                       mip bias: TAA without its -0.5, TAAU without its\n"
    "                       automatic view bias, still and moving)\n"
    "  --sweep-motion-blur  the still sweep with motion blur on (default off: the\n"
    "                       reference has none, and TAA is then the velocity-reading one)\n"
    "  --width/--height, --scene, --no-motion-blur, --symmetric-taa, --no-ps-clear,\n"
    "  --renderer, --no-ssao, --no-local-lights, --shadow-scale, --shadow-law,\n"
    "  --validation         as for the sample (see DynamicResolutionRendering --help);\n"
    "                       --renderer deferred measures every row, the reference\n"
    "                       included, with the deferred renderer\n";

bool ParseInt(const std::string& s, int lo, int hi, int* out) {
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || !end || *end || v < lo || v > hi) return false;
  *out = int(v);
  return true;
}

// What the command line said beyond the plan's own fields: which sweep axes
// it narrowed, the counts it set (-1 = the preset's), the sample's options.
struct BenchArgs {
  bool cameraGiven = false, filterGiven = false, scaleGiven = false, sizeGiven = false;
  int warmup = -1, warmupMs = -1, timingWarmupMs = -1, frames = -1, ghostFrames = -1;
  int movingFrames = -1, movingWarmup = -1, movingSpeedPercent = 0, timingRounds = -1;
  std::vector<std::string> sampleArgs;
  std::vector<Filter> filterList;  // --filters
  std::vector<float> scaleList;    // --scales
};

// The value after args[*i] (moving *i onto it); false with the usage in
// *message when there is none.
bool TakeValue(const std::vector<std::string>& args, size_t* i, std::string* out, std::string* message) {
  if (*i + 1 >= args.size()) {
    *message = args[*i] + ": missing value\n\n" + kBenchUsage;
    return false;
  }
  *out = args[++*i];
  return true;
}

// The integer in [lo, hi] after args[*i].
bool TakeInt(const std::vector<std::string>& args, size_t* i, int lo, int hi, int* out, std::string* message) {
  const std::string name = args[*i];
  std::string v;
  if (!TakeValue(args, i, &v, message)) return false;
  if (!ParseInt(v, lo, hi, out)) {
    *message = name + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + v + "'";
    return false;
  }
  return true;
}

// The comma-separated items after args[*i], each read by `parse`; false
// with a message naming the item it could not read.
template <typename T, typename Parse>
bool TakeList(const std::vector<std::string>& args, size_t* i, std::vector<T>* out, Parse parse, const char* expected,
              std::string* message) {
  const std::string name = args[*i];
  std::string v;
  if (!TakeValue(args, i, &v, message)) return false;
  out->clear();
  for (size_t at = 0; at <= v.size();) {
    const size_t comma = std::min(v.find(',', at), v.size());
    const std::string item = v.substr(at, comma - at);
    T value{};
    if (!parse(item, &value)) {
      *message = name + ": '" + item + "' in '" + v + "' is not " + expected;
      return false;
    }
    out->push_back(value);
    at = comma + 1;
  }
  return true;
}

bool ParseFilterName(const std::string& s, Filter* out) {
  for (int f = int(Filter::None); f < int(Filter::Count); ++f)
    if (s == FilterOption(Filter(f))) return *out = Filter(f), true;
  return false;
}

// FLIP's pixels per degree: a number from 1 to 1000.
bool TakePpd(const std::vector<std::string>& args, size_t* i, double* out, std::string* message) {
  std::string v;
  if (!TakeValue(args, i, &v, message)) return false;
  char* end = nullptr;
  const double ppd = std::strtod(v.c_str(), &end);
  if (v.empty() || !end || *end || !(ppd >= 1 && ppd <= 1000)) {
    *message = "--flip-ppd: '" + v + "' is not a number from 1 to 1000";
    return false;
  }
  return *out = ppd, true;
}

bool ParseScale(const std::string& s, float* out) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || !end || *end || !(v >= 0.1 && v <= 2.0)) return false;
  return *out = float(v), true;
}

// Reads the bench's own options into plan and parsed, and passes the others
// on in parsed->sampleArgs. Returns 0, 1 (help) or 2 (error, *message set).
int ParseBenchArgs(const std::vector<std::string>& args, BenchPlan* plan, BenchArgs* parsed, std::string* message) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--bench") continue;
    if (a == "--help" || a == "-h") {
      *message = kBenchUsage;
      return 1;
    }
    bool ok = true;
    if (a == "--quick") plan->quick = true;
    else if (a == "--out") ok = TakeValue(args, &i, &plan->outDir, message);
    else if (a == "--no-claims") plan->claims = false;
    else if (a == "--no-ghosting") plan->ghosting = false;
    else if (a == "--no-moving") plan->moving = false;
    else if (a == "--timing-rounds") ok = TakeInt(args, &i, 0, 1000, &parsed->timingRounds, message);
    else if (a == "--report-from") ok = TakeValue(args, &i, &plan->reportFrom, message);
    else if (a == "--no-ablations") plan->ablations = false;
    else if (a == "--sweep-motion-blur") plan->sweepMotionBlur = true;
    else if (a == "--moving-frames") ok = TakeInt(args, &i, 2, 10000, &parsed->movingFrames, message);
    else if (a == "--moving-warmup") ok = TakeInt(args, &i, 0, 10000, &parsed->movingWarmup, message);
    else if (a == "--moving-speed") {
      int percent = 0;
      ok = TakeInt(args, &i, 1, 1000, &percent, message);
      parsed->movingSpeedPercent = percent;
    }
    else if (a == "--filters") ok = TakeList(args, &i, &parsed->filterList, ParseFilterName, "a --filter name", message);
    else if (a == "--scales") ok = TakeList(args, &i, &parsed->scaleList, ParseScale, "a scale from 0.1 to 2", message);
    else if (a == "--ghost-frames") ok = TakeInt(args, &i, 2, 300, &parsed->ghostFrames, message);
    else if (a == "--bench-warmup-ms") ok = TakeInt(args, &i, 0, 60000, &parsed->warmupMs, message);
    else if (a == "--bench-warmup") ok = TakeInt(args, &i, 0, 10000, &parsed->warmup, message);
    else if (a == "--bench-frames") ok = TakeInt(args, &i, 1, 10000, &parsed->frames, message);
    else if (a == "--flip-ppd") ok = TakePpd(args, &i, &plan->flipPpd, message);
    else if (a == "--timing-warmup-ms") ok = TakeInt(args, &i, 0, 60000, &parsed->timingWarmupMs, message);
    else if (a == "--memory-bandwidth") {
      int gbs = 0;
      ok = TakeInt(args, &i, 1, 100000, &gbs, message);
      plan->memoryBandwidthGBs = gbs;
    }
    else {
      parsed->cameraGiven |= a == "--camera";
      parsed->filterGiven |= a == "--filter";
      parsed->scaleGiven |= a == "--scale" || a == "--scale-x" || a == "--scale-y";
      parsed->sizeGiven |= a == "--width" || a == "--height";
      parsed->sampleArgs.push_back(a);
    }
    if (!ok) return 2;
  }
  return 0;
}

// Views, filters and scales: the one given on the command line, else the
// quick or the full preset.
void ChooseSweep(const BenchArgs& parsed, BenchPlan* plan) {
  if (parsed.cameraGiven) {
    plan->views = {{plan->base.camera, plan->base.time >= 0 ? plan->base.time : 0.0,
                    "camera " + std::to_string(plan->base.camera)}};
  } else if (plan->quick) {
    plan->views = {{2, 0.0, "static 1"}};
  } else {
    // Camera indices as the original's list: 0 first person, 1 cinematic, 2 and 3 static.
    plan->views = {{2, 0.0, "static 1"},
                   {3, 0.0, "static 2"},
                   {1, 4.0, "cinematic t=4"},
                   {1, 12.0, "cinematic t=12"}};
  }
  if (!parsed.filterList.empty()) {
    plan->filters = parsed.filterList;
  } else if (parsed.filterGiven) {
    plan->filters = {plan->base.filter};
  } else if (plan->quick) {
    plan->filters = {Filter::Point, Filter::Bilinear, Filter::Bicubic, Filter::TAA, Filter::TAAU};
  } else {
    for (int f = int(Filter::Point); f < int(Filter::Count); ++f) plan->filters.push_back(Filter(f));
  }
  if (!parsed.scaleList.empty()) {
    plan->scales = parsed.scaleList;
  } else if (parsed.scaleGiven) {
    plan->scales = {plan->base.scaleX};
  } else if (plan->quick) {
    plan->scales = {0.3f, 0.5f, 0.71f, 1.0f};
  } else {
    plan->scales = {0.3f, 0.4f, 0.5f, 0.6f, 0.71f, 0.8f, 0.9f, 1.0f, 1.25f, 1.5f, 2.0f};
  }
}

// The moving sequences: speeds, filters and scales (at or below 1.0: the
// sequences never allow 2x targets), and their frame counts.
void ChooseMoving(const BenchArgs& parsed, BenchPlan* plan) {
  if (parsed.movingSpeedPercent > 0) plan->movingSpeeds = {parsed.movingSpeedPercent / 100.0};
  else if (plan->quick) plan->movingSpeeds = {1.0};
  else plan->movingSpeeds = {0.5, 1.0, 2.0};
  if (!parsed.filterList.empty()) plan->movingFilters = parsed.filterList;
  else if (parsed.filterGiven) plan->movingFilters = {plan->base.filter};
  else if (plan->quick) plan->movingFilters = {Filter::Point, Filter::Bilinear, Filter::TAA, Filter::TAAU};
  else plan->movingFilters = plan->filters;
  plan->movingScales.clear();
  if (!parsed.scaleList.empty()) {
    for (float s : parsed.scaleList)
      if (s <= 1.0f) plan->movingScales.push_back(s);
  } else if (parsed.scaleGiven) {
    if (plan->base.scaleX <= 1.0f) plan->movingScales = {plan->base.scaleX};
  } else if (plan->quick) {
    plan->movingScales = {0.5f, 1.0f};
  } else {
    plan->movingScales = {0.4f, 0.55f, 0.71f, 0.85f, 1.0f};
  }
  plan->movingFrames = parsed.movingFrames >= 0 ? parsed.movingFrames : (plan->quick ? 4 : 60);
  plan->movingWarmup = parsed.movingWarmup >= 0 ? parsed.movingWarmup : (plan->quick ? 2 : 8);
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
  BenchArgs parsed;
  plan->outDir = "bench_out";
  if (const int rc = ParseBenchArgs(args, plan, &parsed, message); rc != 0) return rc;
  std::string parseMessage;
  const ParseStatus status = ParseCommandLine(parsed.sampleArgs, &plan->base, &parseMessage);
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
  if (plan->quick && !parsed.sizeGiven) {
    plan->base.width = 320;
    plan->base.height = 180;
  }
  plan->warmupFrames = parsed.warmup >= 0 ? parsed.warmup : (plan->quick ? 4 : 8);
  plan->warmupMs = parsed.warmupMs >= 0 ? parsed.warmupMs : (plan->quick ? 0 : 500);
  plan->timingWarmupMs = parsed.timingWarmupMs >= 0 ? parsed.timingWarmupMs : (plan->quick ? 0 : 200);
  plan->measuredFrames = parsed.frames >= 0 ? parsed.frames : (plan->quick ? 6 : 24);
  plan->ghostFrames = parsed.ghostFrames >= 0 ? parsed.ghostFrames : (plan->quick ? 6 : 24);
  ChooseSweep(parsed, plan);
  ChooseMoving(parsed, plan);
  plan->timingRounds = parsed.timingRounds >= 0 ? parsed.timingRounds : (plan->quick ? 1 : 4);
  if (plan->quick) plan->timingWarmup = 1, plan->timingFrames = 4;
  return 0;
}

}  // namespace drr
