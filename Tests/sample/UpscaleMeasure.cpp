// The measurement behind Docs/Upscaling.md (not a check: skipped unless
// DRR_UPSCALE_MEASURE=1). On the Arena's cinematic camera, still (fixed time
// 12 s) and moving (1/30 s per frame, captured at 12 s), it prints PSNR
// against the 4x4 super-sampled reference of the captured time (as the
// bench's) and the GPU frame time as a ratio to point at the same scale and
// to native in the same run: each configuration's median over its frames,
// the smallest of kRounds interleaved rounds (other work on a shared CPU
// rasteriser only ever adds time). Motion blur off, as the bench's ghosting rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "SampleTestKit.h"
#include "analysis/ImageMetrics.h"

namespace drr {
namespace {

constexpr uint32_t kW = 640, kH = 360;
constexpr int kFrames = 32;
constexpr int kRounds = 3;
constexpr double kCapture = 12.0, kStep = 1.0 / 30.0;

ImageF ToF(const Image& img) { return ImageFromRGBA8(img.pixels.data(), img.width, img.height, img.width * 4); }

Options Base(bool moving) {
  Options o = testkit::HeadlessOptions(kW, kH, moving ? kCapture - (kFrames - 1) * kStep : kCapture);
  o.motionBlur = false;
  o.camera = 1;
  o.fixedDt = moving ? kStep : 0.0;
  return o;
}

struct Result {
  double psnr = 0, gpuMs = 0;
};

Result Measure(const Options& o, const ImageF& ref) {
  return testkit::RunFresh(o, kFrames, [&ref](Sample& s, Image&& img) {
    std::vector<double> ms;
    for (const FrameRecord& r : s.Frames())
      if (r.frame >= 8 && r.gpuFrameNew) ms.push_back(r.gpuFrame);
    std::sort(ms.begin(), ms.end());
    return Result{CompareImages(ToF(img), ref).psnr, ms.empty() ? 0.0 : ms[ms.size() / 2]};
  });
}

TEST(UpscaleMeasure, ArenaCinematic) {
  if (!std::getenv("DRR_UPSCALE_MEASURE")) GTEST_SKIP() << "set DRR_UPSCALE_MEASURE=1 to measure";
  Options ro = Base(false);
  ro.width = kW * 4;
  ro.height = kH * 4;
  ro.dynamicResolution = false;
  ro.filter = Filter::Point;
  const Image refImage = testkit::RenderFresh(ro, 2).image;
  ASSERT_FALSE(refImage.pixels.empty());
  const ImageF ref = Downsample(ToF(refImage), 4);
  struct Config {
    const char* name;
    Filter filter;
    float scale;
    bool dynamic;
  };
  const Config configs[] = {
      {"native (full path)", Filter::Point, 1.0f, false}, {"point", Filter::Point, 0.5f, true},
      {"catmull-rom", Filter::UpscaleCatmullRom, 0.5f, true}, {"taa", Filter::TAA, 0.5f, true},
      {"taau", Filter::TAAU, 0.5f, true},                    {"point", Filter::Point, 0.71f, true},
      {"catmull-rom", Filter::UpscaleCatmullRom, 0.71f, true}, {"taa", Filter::TAA, 0.71f, true},
      {"taau", Filter::TAAU, 0.71f, true},                   {"point", Filter::Point, 1.0f, true},
      {"taa", Filter::TAA, 1.0f, true},                      {"taau", Filter::TAAU, 1.0f, true},
  };
  // DRR_UPSCALE_ONLY=NAME: only that configuration (and point), moving only;
  // DRR_UPSCALE_ROUNDS=N: N timing rounds (images are the same in each).
  const char* only = std::getenv("DRR_UPSCALE_ONLY");
  const int rounds = std::getenv("DRR_UPSCALE_ROUNDS") ? std::max(1, std::atoi(std::getenv("DRR_UPSCALE_ROUNDS"))) : kRounds;
  for (bool moving : {false, true}) {
    if (only && !moving) continue;
    std::vector<Result> results(std::size(configs));
    for (int round = 0; round < rounds; ++round)
      for (size_t i = 0; i < std::size(configs); ++i) {
        const Config& c = configs[i];
        if (only && std::string(c.name) != only && c.filter != Filter::Point) continue;
        Options o = Base(moving);
        o.filter = c.filter;
        o.dynamicResolution = c.dynamic;
        o.scaleX = o.scaleY = c.scale;
        const Result r = Measure(o, ref);
        results[i].psnr = r.psnr;
        results[i].gpuMs = round == 0 ? r.gpuMs : std::min(results[i].gpuMs, r.gpuMs);
      }
    std::map<float, double> pointMs;
    double nativeMs = 0;
    for (size_t i = 0; i < std::size(configs); ++i) {
      if (!configs[i].dynamic) nativeMs = results[i].gpuMs;
      if (configs[i].filter == Filter::Point && configs[i].dynamic) pointMs[configs[i].scale] = results[i].gpuMs;
    }
    std::printf("\n%s camera, %ux%u, PSNR against the 4x4 reference, GPU frame ms (min of %d medians):\n",
                moving ? "moving" : "still", kW, kH, rounds);
    for (size_t i = 0; i < std::size(configs); ++i) {
      const Config& c = configs[i];
      if (only && std::string(c.name) != only && c.filter != Filter::Point) continue;
      const Result& r = results[i];
      const double point = pointMs.count(c.scale) ? pointMs[c.scale] : r.gpuMs;
      std::printf("  %-20s scale %.2f  PSNR %6.2f dB  GPU %7.3f ms  x%.2f of point  x%.2f of native\n", c.name,
                  c.scale, r.psnr, r.gpuMs, r.gpuMs / point, nativeMs > 0 ? r.gpuMs / nativeMs : 1.0);
    }
  }
}

}  // namespace
}  // namespace drr
