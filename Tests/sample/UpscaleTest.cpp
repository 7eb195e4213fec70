// The upscalers of Docs/Upscaling.md in the whole sample, under validation:
// each spatial quality against a CPU evaluation of its kernel on the frame's
// own dynamic colour, and TAAU's convergence, camera cut (both with its pixel
// and its compute shader) and scale change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <tuple>

#include "SampleTestKit.h"
#include "analysis/ImageMetrics.h"
#include "imageio/Srgb.h"

namespace drr {
namespace {

using testkit::FreshRun;
using testkit::RenderAndCapture;
using testkit::RenderFresh;
using testkit::SampleTest;

constexpr uint32_t kW = 256, kH = 144;
constexpr double kTime = 3.0;  // a fixed animation time: the camera stands still

Options Base(Filter f, float scale) {
  Options o = testkit::HeadlessOptions(kW, kH, kTime);
  o.motionBlur = false;
  o.filter = f;
  o.scaleX = o.scaleY = scale;
  return o;
}

// The dynamic viewport of the captured scene colour (UNORM: linear values).
struct Source {
  const Image* img;
  int w, h;
  double At(int x, int y, int c) const {
    x = std::clamp(x, 0, w - 1);
    y = std::clamp(y, 0, h - 1);
    return img->RGBA8(uint32_t(x), uint32_t(y))[c] / 255.0;
  }
  double Bilinear(double px, double py, int c) const {  // texel centres at integers
    const double fx = std::floor(px), fy = std::floor(py), ax = px - fx, ay = py - fy;
    const int x = int(fx), y = int(fy);
    return (1 - ay) * ((1 - ax) * At(x, y, c) + ax * At(x + 1, y, c)) +
           ay * ((1 - ax) * At(x, y + 1, c) + ax * At(x + 1, y + 1, c));
  }
};

using Kernel = std::function<double(const Source&, double px, double py, int c)>;

double Lanczos3(double x) {
  x = std::abs(x);
  if (x < 1e-5) return 1.0;
  if (x >= 3.0) return 0.0;
  const double p = M_PI * x;
  return 3.0 * std::sin(p) * std::sin(p / 3.0) / (p * p);
}
double CatmullRom(double x) {
  x = std::abs(x);
  if (x < 1.0) return 1.5 * x * x * x - 2.5 * x * x + 1.0;
  if (x < 2.0) return -0.5 * x * x * x + 2.5 * x * x - 4.0 * x + 2.0;
  return 0.0;
}

// Separable kernels over texels base-r+1 .. base+r; `corners` false drops
// the four corner texels of the 4x4 (the 5-tap Catmull-Rom) and renormalises.
double Separable(const Source& s, double px, double py, int c, double (*k)(double), int r, bool corners) {
  const int bx = int(std::floor(px)), by = int(std::floor(py));
  double sum = 0, wsum = 0;
  for (int y = by - r + 1; y <= by + r; ++y)
    for (int x = bx - r + 1; x <= bx + r; ++x) {
      const bool corner = (x == bx - r + 1 || x == bx + r) && (y == by - r + 1 || y == by + r);
      if (corner && !corners) continue;
      const double w = k(px - x) * k(py - y);
      sum += w * s.At(x, y, c);
      wsum += w;
    }
  return sum / wsum;
}

double Gaussian(const Source& s, double px, double py, int c, double sigma) {
  const int bx = int(std::floor(px)), by = int(std::floor(py));
  double sum = 0, wsum = 0;
  for (int y = by - 2; y <= by + 3; ++y)
    for (int x = bx - 2; x <= bx + 3; ++x) {
      const double d2 = (px - x) * (px - x) + (py - y) * (py - y), w = std::exp(-d2 / (2 * sigma * sigma));
      sum += w * s.At(x, y, c);
      wsum += w;
    }
  return sum / wsum;
}

double Luma(const Source& s, double px, double py) {
  return 0.25 * s.Bilinear(px, py, 0) + 0.5 * s.Bilinear(px, py, 1) + 0.25 * s.Bilinear(px, py, 2);
}

double Directional(const Source& s, double px, double py, int c) {
  const double gx = Luma(s, px + 1, py) - Luma(s, px - 1, py), gy = Luma(s, px, py + 1) - Luma(s, px, py - 1);
  const double len = std::hypot(gx, gy);
  const double ax = len > 1.0 / 64.0 ? -gy / len : 0.0, ay = len > 1.0 / 64.0 ? gx / len : 0.0;
  const double centre = s.Bilinear(px, py, c);
  const double blur = 0.5 * centre + 0.25 * (s.Bilinear(px + 0.5 * ax, py + 0.5 * ay, c) +
                                             s.Bilinear(px - 0.5 * ax, py - 0.5 * ay, c));
  const double mean = 0.25 * (s.Bilinear(px - 1, py, c) + s.Bilinear(px + 1, py, c) + s.Bilinear(px, py - 1, c) +
                              s.Bilinear(px, py + 1, c));
  return std::max(blur + 0.5 * (centre - mean), 0.0);
}

struct SpatialCase {
  int quality;
  Kernel kernel;
  bool gradientSensitive;  // a decision on a luma gradient: pixels near its threshold may go either way
};

std::vector<SpatialCase> SpatialCases() {
  return {
      {0, [](const Source& s, double px, double py, int c) { return s.At(int(std::floor(px + 0.5)), int(std::floor(py + 0.5)), c); }, false},
      {1, [](const Source& s, double px, double py, int c) { return s.Bilinear(px, py, c); }, false},
      {2, Directional, true},
      {3, [](const Source& s, double px, double py, int c) { return Separable(s, px, py, c, CatmullRom, 2, false); }, false},
      {4, [](const Source& s, double px, double py, int c) { return Separable(s, px, py, c, Lanczos3, 3, true); }, false},
      {5, [](const Source& s, double px, double py, int c) {
         const double n = Gaussian(s, px, py, c, 0.6), w = Gaussian(s, px, py, c, 1.2);
         return std::max(n + 0.5 * (n - w), 0.0);
       }, false},
  };
}

class UpscaleTaau : public SampleTest {};
class UpscaleSpatial : public SampleTest, public ::testing::WithParamInterface<int> {};

// At scale 0.5 each output pixel centre maps to texel position (x + 0.5) / 2 -
// 0.5 of the viewport; the GPU's sRGB back buffer must hold the CPU kernel's
// linear result, encoded, within 2 LSB of the 8-bit linear scale (the
// hardware's bilinear weights and 8-bit filtered taps) plus the encoding's
// rounding, on every pixel 8 or more from the edges.
TEST_P(UpscaleSpatial, MatchesItsCpuKernelAtHalfScale) {
  const SpatialCase tc = SpatialCases()[GetParam()];
  Options o = Base(UpscaleQualityFilter(tc.quality), 0.5f);
  StartSample(o);
  const Image out = RenderAndCapture(sample, 3);
  const Image& scene = sample.CapturedSceneColor();
  ASSERT_EQ(out.width, kW);
  ASSERT_GE(scene.width, kW / 2);
  const Source src{&scene, int(kW / 2), int(kH / 2)};
  const double tol = 2.0 / 255.0;
  uint64_t bad = 0, checked = 0;
  double worst = 0;
  for (uint32_t y = 8; y + 8 < kH; ++y)
    for (uint32_t x = 8; x + 8 < kW; ++x) {
      const double px = (x + 0.5) * 0.5 - 0.5, py = (y + 0.5) * 0.5 - 0.5;
      for (int c = 0; c < 3; ++c) {
        const double ref = tc.kernel(src, px, py, c);
        const int gpu = out.RGBA8(x, y)[c];
        const int lo = int(std::floor(drr::LinearToSrgb(ref - tol) * 255.0 + 0.5)) - 1;
        const int hi = int(std::floor(drr::LinearToSrgb(ref + tol) * 255.0 + 0.5)) + 1;
        const double err = std::abs(gpu / 255.0 - drr::LinearToSrgb(ref));
        worst = std::max(worst, err);
        bad += gpu < lo || gpu > hi;
        ++checked;
      }
    }
  std::printf("[upscale] quality %d: %llu of %llu channel values outside, worst |sRGB diff| %.1f LSB\n",
              tc.quality, (unsigned long long)bad, (unsigned long long)checked, worst * 255.0);
  // The directional filter switches on a gradient threshold; a handful of
  // pixels sitting on it may take the other branch.
  EXPECT_LE(bad, tc.gradientSensitive ? checked / 1000 : 0u);
  EXPECT_EQ(sample.PassesRun().count(GetFilterInfo(o.filter).pass), 1u);
}

INSTANTIATE_TEST_SUITE_P(Qualities, UpscaleSpatial, ::testing::Range(0, kUpscaleQualities));

ImageF ToF(const Image& img) { return ImageFromRGBA8(img.pixels.data(), img.width, img.height, img.width * 4); }

// The 4x4 super-sampled reference (full-resolution path, no AA, no motion
// blur), box-filtered down: as the bench's.
ImageF Reference(int camera) {
  Options o = Base(Filter::Point, 1.0f);
  o.width = kW * 4;
  o.height = kH * 4;
  o.dynamicResolution = false;
  o.camera = camera;
  return Downsample(ToF(RenderFresh(o, 2).image), 4);
}

double Psnr(const Options& o, int frames, const ImageF& ref) {
  return CompareImages(ToF(RenderFresh(o, frames).image), ref).psnr;
}

// TAAU's two permutations (--filter taau and taau-fast), each with both
// implementations (--upscale-shader pixel and compute).
using TemporalCase = std::tuple<Filter, UpscaleShader>;
std::string TemporalCaseName(const ::testing::TestParamInfo<TemporalCase>& info) {
  std::string name = std::string(FilterOption(std::get<0>(info.param))) + "_" +
                     UpscaleShaderOption(std::get<1>(info.param));
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}
const auto kTemporalCases = ::testing::Combine(::testing::Values(Filter::TAAU, Filter::TAAUFast),
                                               ::testing::Values(UpscaleShader::Pixel, UpscaleShader::Compute));

// A still camera: after two jitter cycles TAAU at 0.5 has gathered about
// four samples per output pixel and comes within 0.5 dB of the native image
// (point, full resolution), the faster permutation within 1 dB (it trades
// the 3x3's diagonal samples, Docs/Upscaling.md), and both well above their
// own first (reset) frame.
double ConvergedWithinDb(Filter f) { return f == Filter::TAAUFast ? 1.0 : 0.5; }
class UpscaleTemporal : public ::testing::TestWithParam<TemporalCase> {};
TEST_P(UpscaleTemporal, StillCameraConvergesAtHalfScale) {
  const ImageF ref = Reference(1);
  Options native = Base(Filter::Point, 1.0f);
  native.dynamicResolution = false;
  const double psnrNative = Psnr(native, 2, ref);
  Options taau = Base(std::get<0>(GetParam()), 0.5f);
  taau.upscaleShader = std::get<1>(GetParam());
  const int n = 2 * int(kUpsampleJitterLength);
  const double psnrFirst = Psnr(taau, 1, ref), psnrN = Psnr(taau, n, ref);
  const double psnrSpatial = Psnr(Base(Filter::UpscaleCatmullRom, 0.5f), 2, ref);
  std::printf("[%s] still, scale 0.5: native %.2f dB, catmull-rom %.2f dB, frame 1 %.2f dB, frame %d %.2f dB\n",
              FilterOption(taau.filter), psnrNative, psnrSpatial, psnrFirst, n, psnrN);
  EXPECT_GE(psnrN, psnrNative - ConvergedWithinDb(taau.filter));
  EXPECT_GT(psnrN, psnrFirst + 1.0);
  EXPECT_GT(psnrN, psnrSpatial);
}
INSTANTIATE_TEST_SUITE_P(Shaders, UpscaleTemporal, kTemporalCases, TemporalCaseName);

// The frame after a camera cut is exactly the first frame of a TAAU run
// started on that camera: history and jitter restart.
class UpscaleTaauCut : public SampleTest, public ::testing::WithParamInterface<TemporalCase> {};
TEST_P(UpscaleTaauCut, CameraCutEqualsAResetFrame) {
  Options o = Base(std::get<0>(GetParam()), 0.5f);
  o.upscaleShader = std::get<1>(GetParam());
  o.camera = 1;
  StartSample(o);
  RenderAndCapture(sample, 9);
  Options cut = sample.Settings();
  cut.camera = 2;
  sample.ApplySettings(cut);
  const Image afterCut = RenderAndCapture(sample, 1);

  Options fresh = o;
  fresh.camera = 2;
  const Image reset = testkit::RenderFresh(fresh, 1).image;
  const testkit::Diff d = testkit::Compare(afterCut, reset);
  EXPECT_EQ(d.maxAbs, 0) << d.differing << " pixels differ";
}
INSTANTIATE_TEST_SUITE_P(Shaders, UpscaleTaauCut, kTemporalCases, TemporalCaseName);

// --filter taau-fast runs its own pass and shader in both implementations:
// after six frames its image differs from the full permutation's (the cross
// neighbourhood and the bilinear history).
class UpscaleTaauFast : public ::testing::TestWithParam<UpscaleShader> {};
TEST_P(UpscaleTaauFast, RunsItsOwnPermutation) {
  Image images[2];
  const Filter filters[2] = {Filter::TAAU, Filter::TAAUFast};
  for (int i = 0; i < 2; ++i) {
    Options o = Base(filters[i], 0.71f);
    o.upscaleShader = GetParam();
    o.camera = 1;
    FreshRun run = RenderFresh(o, 6);
    ASSERT_FALSE(run.image.pixels.empty()) << FilterOption(filters[i]);
    images[i] = std::move(run.image);
    EXPECT_EQ(run.passes.count(GetFilterInfo(filters[i]).pass), 1u) << FilterOption(filters[i]);
  }
  const testkit::Diff d = testkit::Compare(images[0], images[1]);
  std::printf("[taau-fast] %s, 6 frames at 0.71: %zu pixels differ from taau, at most %d steps\n",
              UpscaleShaderOption(GetParam()), size_t(d.differing), d.maxAbs);
  EXPECT_GT(d.differing, 0ull);
}
INSTANTIATE_TEST_SUITE_P(Shaders, UpscaleTaauFast, ::testing::Values(UpscaleShader::Pixel, UpscaleShader::Compute),
                         [](const auto& info) { return std::string(UpscaleShaderOption(info.param)); });

// A change of the dynamic scale keeps the output-resolution history: the
// frame after 0.5 -> 0.71 stays close to the converged one (no reset pop).
TEST_F(UpscaleTaau, ScaleChangeKeepsTheHistory) {
  StartSample(Base(Filter::TAAU, 0.5f));
  const Image before = RenderAndCapture(sample, 2 * int(kUpsampleJitterLength));
  Options up = sample.Settings();
  up.scaleX = up.scaleY = 0.71f;
  sample.ApplySettings(up);
  const Image after = RenderAndCapture(sample, 1);
  const double psnr = CompareImages(ToF(after), ToF(before)).psnr;
  std::printf("[taau] frame after 0.5 -> 0.71 against the converged frame: %.2f dB\n", psnr);
  EXPECT_GT(psnr, 35.0);
  EXPECT_EQ(sample.PassesRun().count("TemporalUpsample"), 1u);
}

}  // namespace
}  // namespace drr

namespace drr {
namespace {

// The scene colour of the first frame (for TAAU: jitter 0 of its sequence),
// validation-clean.
Image FirstSceneColour(const Options& o) {
  return testkit::RunFresh(o, 1, [](Sample& s, Image&&) { return s.CapturedSceneColor(); });
}

// TAAU's first scene colour with the automatic mip bias on or off.
Image TaauSceneColour(float scale, bool autoBias, double userBias) {
  Options o = Base(Filter::TAAU, scale);
  o.autoMipBias = autoBias;
  o.mipBias = userBias;
  return FirstSceneColour(o);
}

// The automatic view mip bias is log2(screen percentage) + the user's: a user
// bias of -log2(scale) cancels it exactly (the same image as without it),
// while the automatic bias alone, or half of it cancelled at 0.25, samples
// other (finer) mips.
TEST(UpscaleMipBias, FollowsLog2OfTheScale) {
  for (float scale : {0.5f, 0.25f}) {
    const double log2Scale = std::log2(double(scale));
    const Image unbiased = TaauSceneColour(scale, false, 0.0);
    const Image cancelled = TaauSceneColour(scale, true, -log2Scale);
    const Image automatic = TaauSceneColour(scale, true, 0.0);
    EXPECT_EQ(testkit::Compare(cancelled, unbiased).maxAbs, 0) << scale;
    EXPECT_GT(testkit::Compare(automatic, unbiased).differing, 100u) << "log2(" << scale << ") samples finer mips";
    if (scale == 0.25f) {
      const Image half = TaauSceneColour(scale, true, -0.5 * log2Scale);  // total bias -1
      EXPECT_GT(testkit::Compare(half, unbiased).differing, 100u);
      EXPECT_GT(testkit::Compare(half, automatic).differing, 100u);
    }
  }
}

}  // namespace
}  // namespace drr

namespace drr {
namespace {

// Mean absolute horizontal + vertical difference of neighbours (sRGB values):
// how much high-frequency detail an image keeps.
double Detail(const ImageF& img) {
  double sum = 0;
  for (uint32_t y = 1; y < img.height; ++y)
    for (uint32_t x = 1; x < img.width; ++x)
      for (uint32_t c = 0; c < 3; ++c)
        sum += std::abs(img.At(x, y, c) - img.At(x - 1, y, c)) + std::abs(img.At(x, y, c) - img.At(x, y - 1, c));
  return sum / (double(img.width) * img.height * 3);
}

// The edge-adaptive upscale and its sharpening pass both run; at 0.5 the pair
// keeps more detail than the bilinear upscale and is closer to the 4x4
// reference than the nearest-texel one.
TEST(UpscaleEdgeAdaptive, RunsBothPassesSharperThanBilinear) {
  const ImageF ref = Reference(1);
  Options o = Base(Filter::UpscaleEdgeAdaptive, 0.5f);
  const testkit::FreshRun run = testkit::RenderFresh(o, 2);
  ASSERT_FALSE(run.image.pixels.empty());
  const Image& img = run.image;
  EXPECT_EQ(run.passes.count("UpscaleEdgeAdaptive"), 1u);
  EXPECT_EQ(run.passes.count("Sharpen"), 1u);
  const double edge = CompareImages(ToF(img), ref).psnr;
  const double nearest = Psnr(Base(Filter::UpscaleNearest, 0.5f), 2, ref);
  const ImageF bilinear = ToF(testkit::RenderFresh(Base(Filter::UpscaleBilinear, 0.5f), 2).image);
  std::printf("[edge-adaptive] scale 0.5: %.2f dB (nearest %.2f dB, bilinear %.2f dB); detail %.4f, bilinear %.4f\n",
              edge, nearest, CompareImages(bilinear, ref).psnr, Detail(ToF(img)), Detail(bilinear));
  EXPECT_GT(edge, nearest);
  EXPECT_GT(Detail(ToF(img)), Detail(bilinear));
}

}  // namespace
}  // namespace drr

namespace drr {
namespace {

// The secondary screen percentage at 50 % with the primary at 0.5 of the
// back buffer: the primary (nearest texel) copies the 128x72 viewport 1:1
// into the 128x72 output target, the secondary Catmull-Rom scales it to the
// 256x144 back buffer; every interior pixel must hold a CPU Catmull-Rom of
// the scene colour, as the quality-3 test checks it. A secondary sized
// otherwise, or a second scale factor applied anywhere, moves the samples.
TEST_F(UpscaleTaau, SecondaryUpscaleIsItsCatmullRomOfTheOutputTarget) {
  Options o = Base(Filter::UpscaleNearest, 0.5f);
  o.secondaryScreenPercentage = 50.0;
  StartSample(o);
  const Image out = RenderAndCapture(sample, 3);
  const Image& scene = sample.CapturedSceneColor();
  ASSERT_EQ(out.width, kW);
  ASSERT_EQ(out.height, kH);
  EXPECT_EQ(sample.GetDynamicResolution().GetViewport().Width, float(kW / 2));
  EXPECT_EQ(sample.PassesRun().count("SecondaryUpscale"), 1u);
  const Source src{&scene, int(kW / 2), int(kH / 2)};
  const double tol = 2.0 / 255.0;
  uint64_t bad = 0, checked = 0;
  for (uint32_t y = 8; y + 8 < kH; ++y)
    for (uint32_t x = 8; x + 8 < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        const double ref = Separable(src, (x + 0.5) * 0.5 - 0.5, (y + 0.5) * 0.5 - 0.5, c, CatmullRom, 2, false);
        const int gpu = out.RGBA8(x, y)[c];
        const int lo = int(std::floor(drr::LinearToSrgb(ref - tol) * 255.0 + 0.5)) - 1;
        const int hi = int(std::floor(drr::LinearToSrgb(ref + tol) * 255.0 + 0.5)) + 1;
        bad += gpu < lo || gpu > hi;
        ++checked;
      }
  std::printf("[secondary] 50 %%: %llu of %llu channel values outside the CPU Catmull-Rom\n", (unsigned long long)bad,
              (unsigned long long)checked);
  EXPECT_EQ(bad, 0u);
}

// The scene colour of TAAU's first frame with the automatic bias on or off
// and the materials in `optOut` sampled without it.
Image TaauSceneColourOptOut(bool autoBias, const std::string& optOut) {
  Options o = Base(Filter::TAAU, 0.5f);
  o.autoMipBias = autoBias;
  o.mipBiasOptOut = optOut;
  return FirstSceneColour(o);
}

// Per-material opt-out: with the Arena's floor opted out, every pixel the
// bias changes shows either the unbiased texel (the floor) or the biased one
// (every other material), both in large numbers, except where a decal (the
// blended "Decals" material, biased) lies over the floor: those pixels must
// be the decal's (opting the decals out changes them). A name that is no
// material changes nothing. Pixels of the dynamic viewport (scale 0.5).
TEST(UpscaleMipBias, OptOutKeepsTheNamedMaterialUnbiased) {
  const Image plain = TaauSceneColourOptOut(false, "");
  const Image biased = TaauSceneColourOptOut(true, "");
  const Image floorOut = TaauSceneColourOptOut(true, "Floor");
  const Image decalsOut = TaauSceneColourOptOut(true, "Decals");
  EXPECT_EQ(testkit::Compare(TaauSceneColourOptOut(true, "NoSuchMaterial"), biased).maxAbs, 0);
  // The loop below reads the top-left quarter of all four: a run that did not
  // start returned an empty image.
  for (const Image* im : {&plain, &biased, &floorOut, &decalsOut})
    ASSERT_TRUE(im->width >= kW / 2 && im->height >= kH / 2 && im->pixels.size() >= size_t(im->width) * im->height * 4)
        << im->width << "x" << im->height;
  uint64_t changed = 0, keptPlain = 0, keptBiased = 0, decal = 0, neither = 0;
  for (uint32_t y = 0; y < kH / 2; ++y)
    for (uint32_t x = 0; x < kW / 2; ++x) {
      auto same = [&](const Image& a, const Image& b) {
        const auto pa = a.RGBA8(x, y), pb = b.RGBA8(x, y);
        return pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2];
      };
      if (same(plain, biased)) continue;
      ++changed;
      if (same(floorOut, plain)) ++keptPlain;
      else if (same(floorOut, biased)) ++keptBiased;
      else if (!same(decalsOut, biased)) ++decal;
      else ++neither;
    }
  std::printf("[mip bias] %llu pixels changed by the bias; floor opted out: %llu unbiased, %llu biased, %llu decal "
              "over the floor, %llu other\n",
              (unsigned long long)changed, (unsigned long long)keptPlain, (unsigned long long)keptBiased,
              (unsigned long long)decal, (unsigned long long)neither);
  EXPECT_GT(keptPlain, 100u);
  EXPECT_GT(keptBiased, 100u);
  // 0.1 % allowed: 2 of 7 816 pixels here fall in no class (not traced).
  EXPECT_LE(neither, changed / 1000);
}

}  // namespace
}  // namespace drr
