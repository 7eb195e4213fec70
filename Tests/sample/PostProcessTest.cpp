// The resolve filters and post passes against the original's behaviour, and
// the post-processing fixes (each changes what it says and nothing else).
// Whole-sample renders on lavapipe under validation (D3DL_VALIDATION=sync
// from CTest); references are CPU computations of the original's formulas.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "DynamicResolutionRendering.h"
#include "SampleTestKit.h"
#include "imageio/Srgb.h"

using namespace drr;
using namespace drr::testkit;

namespace {

Options TinyOptions(uint32_t w = 160, uint32_t h = 90) {
  Options o;
  o.headless = true;
  o.width = w;
  o.height = h;
  o.control = ControlMode::Manual;
  o.gui = false;
  o.time = 1.0;  // the same scene every frame
  o.camera = 1;
  return o;
}

// Pixels of two sRGB back buffers that differ by more than the rounding of
// the 8-bit linear UNORM target behind them: a channel may differ by one sRGB
// level (the encoding's rounding) or by 2.5 linear levels (lavapipe filters
// UNORM8 in fixed point with 8-bit weights, and each sampler state takes its
// own path: up to 2.27 levels measured; the encoding spreads one linear level
// over up to ~10 sRGB levels in the darkest tones).
uint64_t PixelsBeyondLinearRounding(const Image& a, const Image& b) {
  if (a.pixels.size() != b.pixels.size()) return ~0ull;
  uint64_t beyond = 0;
  for (size_t p = 0; p < a.pixels.size(); p += 4) {
    bool ok = true;
    for (size_t c = p; c < p + 3; ++c) {
      const int srgb = std::abs(int(a.pixels[c]) - int(b.pixels[c]));
      const double linear = 255.0 * std::abs(double(drr::SrgbToLinear(a.pixels[c] / 255.0f)) -
                                             double(drr::SrgbToLinear(b.pixels[c] / 255.0f)));
      ok = ok && (srgb <= 1 || linear <= 2.5);
    }
    beyond += !ok;
  }
  return beyond;
}

class PostFixture : public SampleTest {
 protected:
  Image RenderWith(Options& o, int n = 2) {
    sample.ApplySettings(o);
    return RenderAndCapture(sample, n);
  }
};

}  // namespace

// ---------------------------------------------------------------------------
// 1. The original's point sampler is MIN_LINEAR_MAG_MIP_POINT read with an
// implicit LOD: super sampled at 2x (two texels per pixel) it minifies, so it
// filters linearly and Point gives exactly Bilinear's image.
TEST_F(PostFixture, PointEqualsBilinearWhenSuperSampledAtTwo) {
  Options o = TinyOptions();
  o.superSampling = true;
  o.scaleX = o.scaleY = 2.0f;
  o.motionBlur = false;
  o.filter = Filter::Point;
  StartSample(o);
  const Image point = RenderAndCapture(sample, 2);
  o.filter = Filter::Bilinear;
  const Image bilinear = RenderWith(o);
  const Diff d = Compare(point, bilinear);
  const uint64_t beyond = PixelsBeyondLinearRounding(point, bilinear);
  std::printf("[post] point vs bilinear, super sampled x2: %llu px differ (max %d sRGB levels), "
              "%llu beyond the rounding of the linear target\n",
              (unsigned long long)d.differing, d.maxAbs, (unsigned long long)beyond);
  // Both resolves filter the same texels with the same weights. The original's
  // UNORM targets hold linear 8-bit values, which lavapipe filters in fixed
  // point with different rounding per sampler state (PixelsBeyondLinearRounding).
  // With sRGB targets (--fix srgb-targets) lavapipe filters in float and the
  // two are identical to the bit (checked below).
  EXPECT_EQ(beyond, 0u);
  // At 1.5 the pixel footprint is 1.5 texels: still minified, still equal.
  o.scaleX = o.scaleY = 1.5f;
  o.filter = Filter::Point;
  const Image point15 = RenderWith(o);
  o.filter = Filter::Bilinear;
  EXPECT_EQ(PixelsBeyondLinearRounding(point15, RenderWith(o)), 0u);
  // Bit-identical with sRGB targets, where lavapipe filters in float.
  o.fixes.Set(Fix::SrgbTargets, true);
  o.scaleX = o.scaleY = 2.0f;
  o.filter = Filter::Point;
  const Image pointSrgb = RenderWith(o);
  o.filter = Filter::Bilinear;
  EXPECT_EQ(Compare(pointSrgb, RenderWith(o)).differing, 0u);
}

// ---------------------------------------------------------------------------
// 1b. TAA jitter: the original's pair (0,0) / (0.5,0.5) px translates the
// scene right and UP (+x, +y in clip space). Two consecutive frames of a
// still scene differ by that shift; estimated from the image gradients
// (B - A = -d . grad A, least squares), d in image coordinates (y down) has
// x and y of opposite signs, each about half a pixel.
TEST_F(PostFixture, TAAJitterMovesTheSceneRightAndUp) {
  Options o = TinyOptions(320, 180);
  o.motionBlur = false;  // the scene draws into the final targets, captured as scene colour
  o.filter = Filter::TAA;
  StartSample(o);
  RenderAndCapture(sample, 3);
  const Image a = sample.CapturedSceneColor();
  RenderAndCapture(sample, 1);
  const Image& b = sample.CapturedSceneColor();
  double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0;
  for (uint32_t y = 1; y + 1 < a.height; ++y)
    for (uint32_t x = 1; x + 1 < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double gx = (a.RGBA8(x + 1, y)[c] - a.RGBA8(x - 1, y)[c]) / 2.0;
        const double gy = (a.RGBA8(x, y + 1)[c] - a.RGBA8(x, y - 1)[c]) / 2.0;
        const double dt = double(b.RGBA8(x, y)[c]) - a.RGBA8(x, y)[c];
        sxx += gx * gx, sxy += gx * gy, syy += gy * gy, sx -= gx * dt, sy -= gy * dt;
      }
  const double det = sxx * syy - sxy * sxy;
  ASSERT_GT(det, 0.0);
  const double dx = (syy * sx - sxy * sy) / det, dy = (sxx * sy - sxy * sx) / det;
  std::printf("[post] TAA jitter between consecutive frames: (%.3f, %.3f) px (x right, y down)\n", dx, dy);
  EXPECT_GT(std::abs(dx), 0.25);
  EXPECT_LT(std::abs(dx), 0.75);
  EXPECT_GT(std::abs(dy), 0.25);
  EXPECT_LT(std::abs(dy), 0.75);
  EXPECT_LT(dx * dy, 0.0) << "the jittered frame must move right and up (or left and down)";
}

// ---------------------------------------------------------------------------
// 2. Bicubic: the original's formula on the CPU, from the final RT read back.
namespace {

using Rgb = std::array<float, 3>;

// The original's lookup: (h0, h1, g0, g1) of the cubic B-spline at x = i/128.
std::vector<std::array<float, 4>> OriginalCubicTable() {
  std::vector<std::array<float, 4>> t(128);
  for (int i = 0; i < 128; ++i) {
    const double x = i / 128.0;
    const double w0 = (1 - x) * (1 - x) * (1 - x) / 6, w1 = (3 * x * x * x - 6 * x * x + 4) / 6;
    const double w2 = (-3 * x * x * x + 3 * x * x + 3 * x + 1) / 6, w3 = x * x * x / 6;
    t[i] = {float(1 - w1 / (w0 + w1) + x), float(1 + w3 / (w2 + w3) - x), float(w0 + w1), float(w2 + w3)};
  }
  return t;
}

// A 1D linear-wrap read at normalised coordinate c.
std::array<float, 4> LookupLinearWrap(const std::vector<std::array<float, 4>>& t, double c) {
  const double p = c * double(t.size()) - 0.5;
  const double f = p - std::floor(p);
  const int n = int(t.size());
  const int i0 = ((int(std::floor(p)) % n) + n) % n, i1 = (i0 + 1) % n;
  std::array<float, 4> r;
  for (int k = 0; k < 4; ++k) r[k] = float(t[i0][k] * (1 - f) + t[i1][k] * f);
  return r;
}

// A bilinear, clamp-addressed read of an sRGB image in linear light.
Rgb BilinearClamp(const Image& img, double u, double v) {
  const double px = u * img.width - 0.5, py = v * img.height - 0.5;
  const int x0 = int(std::floor(px)), y0 = int(std::floor(py));
  const double fx = px - x0, fy = py - y0;
  auto texel = [&](int x, int y, int c) {
    x = std::clamp(x, 0, int(img.width) - 1);
    y = std::clamp(y, 0, int(img.height) - 1);
    const double stored = img.RGBA8(x, y)[c] / 255.0;  // linear in a UNORM target, encoded in an sRGB one
    return img.format == d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB ? double(drr::SrgbToLinear(float(stored))) : stored;
  };
  Rgb r;
  for (int c = 0; c < 3; ++c) {
    const double top = texel(x0, y0, c) * (1 - fx) + texel(x0 + 1, y0, c) * fx;
    const double bottom = texel(x0, y0 + 1, c) * (1 - fx) + texel(x0 + 1, y0 + 1, c) * fx;
    r[c] = float(top * (1 - fy) + bottom * fy);
  }
  return r;
}

Rgb Lerp(const Rgb& a, const Rgb& b, float t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

// The original's PSResolveCubic at back-buffer pixel (x, y).
Rgb OriginalBicubic(const Image& rt, const std::vector<std::array<float, 4>>& table, double u, double v) {
  const double sx = 1.0 / rt.width, sy = 1.0 / rt.height;
  auto hx = LookupLinearWrap(table, u * rt.width - 0.5);
  auto hy = LookupLinearWrap(table, v * rt.height - 0.5);
  const double x10 = u + 0.25 * hx[0] * sx, x00 = u - 0.25 * hx[1] * sx;
  const double yUp = v + 0.25 * hy[0] * sy, yDown = v - 0.25 * hy[1] * sy;
  const Rgb c00 = BilinearClamp(rt, x00, yDown), c01 = BilinearClamp(rt, x00, yUp);
  const Rgb c10 = BilinearClamp(rt, x10, yDown), c11 = BilinearClamp(rt, x10, yUp);
  return Lerp(Lerp(c00, c01, hy[2]), Lerp(c10, c11, hy[2]), hx[2]);
}

}  // namespace

TEST_F(PostFixture, BicubicIsTheOriginalsFormula) {
  Options o = TinyOptions();
  o.motionBlur = false;  // the scene draws straight into the final RT that the resolve reads
  o.filter = Filter::Bicubic;
  o.scaleX = o.scaleY = 0.5f;
  StartSample(o);
  const Image bb = RenderAndCapture(sample, 2);
  const Image& rt = sample.CapturedSceneColor();
  const DynamicResolution& dr = sample.GetDynamicResolution();
  ASSERT_EQ(rt.width, 160u);
  const auto table = OriginalCubicTable();
  int maxInterior = 0;
  uint64_t over1 = 0;
  for (uint32_t y = 1; y + 1 < bb.height; ++y)
    for (uint32_t x = 1; x + 1 < bb.width; ++x) {
      const double u = (x + 0.5) / bb.width * dr.GetRTScaleX(), v = (y + 0.5) / bb.height * dr.GetRTScaleY();
      const Rgb ref = OriginalBicubic(rt, table, u, v);
      for (int c = 0; c < 3; ++c) {
        // Within 2 levels of the sRGB back buffer, or of the linear UNORM
        // target the resolve filtered (lavapipe filters UNORM8 in fixed point;
        // one linear level is up to ~10 sRGB levels in the darkest tones).
        const int got = bb.RGBA8(x, y)[c];
        const int want = int(std::lround(drr::LinearToSrgb(std::clamp(ref[c], 0.f, 1.f)) * 255.0f));
        const double linear = 255.0 * std::abs(double(drr::SrgbToLinear(got / 255.0f)) - double(ref[c]));
        const int diff = std::min(std::abs(want - got), int(std::ceil(linear - 1e-9)));
        maxInterior = std::max(maxInterior, diff);
        over1 += diff > 1;
      }
    }
  std::printf("[post] bicubic vs CPU reference of the original's formula: max %d LSB, %llu channels > 1\n",
              maxInterior, (unsigned long long)over1);
  EXPECT_LE(maxInterior, 2);
  // And it is not the B-spline filter (the lookup's 1/4 scale and tap order differ).
  o.filter = Filter::BicubicBSpline;
  EXPECT_GT(Compare(bb, RenderWith(o)).differing, 100u);
}

// ---------------------------------------------------------------------------
// 3. Noise moves each frame (a new rand() offset); Noise Offset is static.
TEST_F(PostFixture, NoiseChangesEveryFrameNoiseOffsetDoesNot) {
  Options o = TinyOptions();
  o.scaleX = o.scaleY = 0.5f;  // noise strength 2 - 0.5 - 0.5 = 1
  o.filter = Filter::NoiseOffset;
  StartSample(o);
  const Image a = RenderAndCapture(sample, 2), b = RenderAndCapture(sample, 1);
  const Diff offset = Compare(a, b);
  o.filter = Filter::Noise;
  const Image c = RenderWith(o, 2), d = RenderAndCapture(sample, 1);
  const Diff noise = Compare(c, d);
  std::printf("[post] consecutive frames: noise offset %llu px differ, noise %llu px differ\n",
              (unsigned long long)offset.differing, (unsigned long long)noise.differing);
  EXPECT_EQ(offset.differing, 0u);
  EXPECT_GT(noise.differing, uint64_t(a.width) * a.height / 2);
  // Noise Offset does move pixels (it is not the point image).
  o.filter = Filter::Point;
  EXPECT_GT(Compare(a, RenderWith(o)).differing, 100u);
}

// ---------------------------------------------------------------------------
// 4. --no-ps-clear: the API clear covers the whole target, as
// ClearRenderTargetView does; the pixel-shader clear only the viewport.
TEST_F(PostFixture, ApiClearCoversTheWholeTarget) {
  Options o = TinyOptions();
  o.motionBlur = true;  // the scene colour target is then only cleared and drawn
  o.filter = Filter::Point;
  o.scaleX = o.scaleY = 0.5f;
  o.debugMarkerOutside = true;  // magenta outside the viewport before the clear
  o.psClear = false;
  StartSample(o);
  RenderAndCapture(sample, 2);
  // The clear colour's green, 0.1, as the scene colour target stores it:
  // linear in the original's UNORM target, encoded in an sRGB one.
  const bool srgbTarget = sample.CapturedSceneColor().format == d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
  const uint8_t clearG = uint8_t(std::lround((srgbTarget ? drr::LinearToSrgb(0.1f) : 0.1f) * 255.0f));
  auto countOutside = [&](const Image& img, auto pred) {
    uint64_t n = 0;
    for (uint32_t y = 0; y < img.height; ++y)
      for (uint32_t x = 0; x < img.width; ++x)
        if (x >= img.width / 2 || y >= img.height / 2) n += pred(img.RGBA8(x, y));
    return n;
  };
  const auto isClear = [&](std::array<uint8_t, 4> p) { return p[0] == 0 && p[1] == clearG && p[2] == clearG; };
  const Image& apiRT = sample.CapturedSceneColor();
  const uint64_t outside = uint64_t(apiRT.width) * apiRT.height * 3 / 4;
  EXPECT_EQ(countOutside(apiRT, isClear), outside);
  const Image& apiVelocity = sample.CapturedVelocity();
  ASSERT_FALSE(apiVelocity.Empty());
  EXPECT_EQ(apiVelocity.Float(apiVelocity.width - 1, apiVelocity.height - 1, 0), 0.0f);
  o.psClear = true;
  sample.ApplySettings(o);
  RenderAndCapture(sample, 2);
  EXPECT_EQ(countOutside(sample.CapturedSceneColor(), isClear), 0u);  // the marker stays
  EXPECT_NE(sample.CapturedVelocity().Float(apiVelocity.width - 1, apiVelocity.height - 1, 0), 0.0f);
}

// ---------------------------------------------------------------------------
// 5. The fixes of this area.
namespace {
bool AllBlack(const Image& img) {
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x)
      if (img.RGBA8(x, y)[0] || img.RGBA8(x, y)[1] || img.RGBA8(x, y)[2]) return false;
  return true;
}
}  // namespace

// The original zeroes None's final target after the scene drew into it:
// without motion blur None shows black. none-shows-rt zeroes it first.
TEST_F(PostFixture, FixNoneShowsRTChangesOnlyNoneWithoutMotionBlur) {
  Options o = TinyOptions();
  o.scaleX = o.scaleY = 0.5f;
  o.filter = Filter::None;
  o.motionBlur = false;
  StartSample(o);
  EXPECT_TRUE(AllBlack(RenderAndCapture(sample, 2))) << "the original's None without motion blur";
  o.fixes.Set(Fix::NoneShowsRT, true);
  const Image fixed = RenderWith(o);
  // The whole RT at ratio 1: the viewport (top-left quarter) holds the scene, the rest is zero.
  EXPECT_FALSE(AllBlack(fixed));
  uint64_t outsideLit = 0;
  for (uint32_t y = 0; y < fixed.height; ++y)
    for (uint32_t x = 0; x < fixed.width; ++x) {
      const auto p = fixed.RGBA8(x, y);
      if (x >= fixed.width / 2 || y >= fixed.height / 2) outsideLit += (p[0] | p[1] | p[2]) != 0;
    }
  EXPECT_EQ(outsideLit, 0u);
  // Nothing else: None with motion blur, and the other filters, are unchanged.
  for (auto [filter, mb] : {std::pair{Filter::None, true}, {Filter::Point, false}, {Filter::TAA, false}}) {
    o.filter = filter;
    o.motionBlur = mb;
    o.fixes = {};
    const Image before = RenderWith(o);
    o.fixes.Set(Fix::NoneShowsRT, true);
    EXPECT_EQ(Compare(before, RenderWith(o)).differing, 0u) << FilterOption(filter) << " mb " << mb;
  }
}

// taa-velocity-pixels: the TAA weight S = 1 / (1 + |v_c|^2 + |v_p|^2) with v
// in viewport pixels instead of RT-size units. At ratio 1 both are the same;
// below it the velocities shrink by the ratio, S grows, and each pixel moves
// towards the plain average (TAA Basic, S = 1) and never away from it.
namespace {
Image RenderMoving(Filter filter, float scale, bool motionBlur, FixSet fixes) {
  Options o = TinyOptions();
  o.camera = 1;  // the cinematic camera moves: non-zero velocities
  o.time = -1.0;  // animated, each run from time 0 by fixed steps
  o.fixedDt = 1.0 / 15.0;
  o.filter = filter;
  o.scaleX = o.scaleY = scale;
  o.motionBlur = motionBlur;
  o.fixes = fixes;
  return RenderFresh(o, 5).image;
}
}  // namespace

TEST(PostFix, TaaVelocityPixelsMovesTAATowardsTheAverageBelowRatioOne) {
  FixSet fix;
  fix.Set(Fix::TaaVelocityPixels, true);
  for (bool mb : {false, true}) {
    const Image original = RenderMoving(Filter::TAA, 0.5f, mb, {});
    const Image fixed = RenderMoving(Filter::TAA, 0.5f, mb, fix);
    const Image b = RenderMoving(Filter::TAABasic, 0.5f, mb, {});
    ASSERT_FALSE(original.pixels.empty() || fixed.pixels.empty() || b.pixels.empty());
    const Diff changed = Compare(original, fixed);
    uint64_t away = 0;
    double toBasicOriginal = 0, toBasicFixed = 0;
    for (uint32_t y = 0; y < b.height; ++y)
      for (uint32_t x = 0; x < b.width; ++x)
        for (int c = 0; c < 3; ++c) {
          const int dO = std::abs(int(original.RGBA8(x, y)[c]) - int(b.RGBA8(x, y)[c]));
          const int dF = std::abs(int(fixed.RGBA8(x, y)[c]) - int(b.RGBA8(x, y)[c]));
          away += dF > dO + 1;
          toBasicOriginal += dO;
          toBasicFixed += dF;
        }
    std::printf("[post] taa-velocity-pixels at 0.5 (mb %d): %llu px changed; distance to the average %.0f -> %.0f\n",
                int(mb), (unsigned long long)changed.differing, toBasicOriginal, toBasicFixed);
    EXPECT_GT(changed.differing, 0u) << "mb " << mb;
    EXPECT_EQ(away, 0u) << "mb " << mb;
    EXPECT_LT(toBasicFixed, toBasicOriginal) << "mb " << mb;
    // Nothing else: at ratio 1 (RT pixels are viewport pixels) and for a
    // filter that reads no velocity the fix changes nothing.
    EXPECT_EQ(Compare(RenderMoving(Filter::TAA, 1.0f, mb, {}), RenderMoving(Filter::TAA, 1.0f, mb, fix))
                  .differing,
              0u);
    EXPECT_EQ(Compare(RenderMoving(Filter::Bilinear, 0.5f, mb, {}),
                      RenderMoving(Filter::Bilinear, 0.5f, mb, fix))
                  .differing,
              0u);
  }
}

// uv-inset: resolves clamp their UVs half a texel inside the viewport. It can
// only change pixels whose reads reach past the viewport's edges (right and
// bottom; Noise Offset's jitter also reaches before the first texel, and the
// clamp changes its implicit LOD there): the interior of the back buffer
// stays the same, and nothing of the marker written outside the viewport
// reaches the screen.
TEST_F(PostFixture, FixUvInsetChangesOnlyTheViewportEdge) {
  Options o = TinyOptions();
  o.scaleX = o.scaleY = 0.5f;
  o.motionBlur = false;
  o.debugMarkerOutside = true;
  o.filter = Filter::Bilinear;
  StartSample(o);
  for (Filter f : {Filter::Point, Filter::Bilinear, Filter::Bicubic, Filter::NoiseOffset}) {
    o.filter = f;
    o.fixes = {};
    const Image original = RenderWith(o);
    o.fixes.Set(Fix::UvInset, true);
    const Image fixed = RenderWith(o);
    // Bicubic's taps reach 1.5 texels (3 back-buffer pixels at 0.5) past the sample.
    const Diff inner = Compare(original, fixed, 4);
    uint64_t magenta = 0;
    for (uint32_t y = 0; y < fixed.height; ++y)
      for (uint32_t x = 0; x < fixed.width; ++x) {
        const auto p = fixed.RGBA8(x, y);
        magenta += p[0] > 200 && p[2] > 200 && p[1] < 60;
      }
    std::printf("[post] uv-inset %s: %llu px changed, %llu of them inside; magenta with the fix %llu\n",
                FilterOption(f), (unsigned long long)Compare(original, fixed).differing,
                (unsigned long long)inner.differing, (unsigned long long)magenta);
    EXPECT_EQ(inner.differing, 0u) << FilterOption(f);
    EXPECT_EQ(magenta, 0u) << FilterOption(f);
    if (f == Filter::Bilinear) {
      EXPECT_GT(Compare(original, fixed).differing, 0u);
    }
  }
}
