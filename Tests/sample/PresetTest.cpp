// --preset gles2 renders the OpenGL ES 2.0 article's system under validation:
// the back buffer is the native-size target's viewport (w f, h f) sampled
// bilinearly with texture coordinates running to (f, f), not clamped inside the
// viewport, through a clamp-to-edge sampler over the whole target; no velocity
// target is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "DynamicResolutionRendering.h"
#include "SampleTestKit.h"

using namespace drr;
using namespace drr::testkit;

namespace {

double EncodeSrgb(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// The target's 8-bit value (linear, as the original's UNORM targets hold it)
// at a texel, clamped to the whole target (GL_CLAMP_TO_EDGE).
double Texel(const Image& rt, int x, int y, int c) {
  x = std::clamp(x, 0, int(rt.width) - 1);
  y = std::clamp(y, 0, int(rt.height) - 1);
  return rt.pixels[(size_t(y) * rt.width + x) * 4 + c] / 255.0;
}

// The article's full-screen quad on the CPU, in linear light: pixel (x, y) of
// a w x h back buffer reads uv = (x + 0.5) / w * f bilinearly, with no clamp
// to the used part; clampToViewport models the uv-inset fix instead (taps
// clamped to the viewport's texel centres). RGB per pixel.
std::vector<double> ArticleQuad(const Image& rt, uint32_t w, uint32_t h, double f, bool clampToViewport) {
  std::vector<double> out(size_t(w) * h * 3);
  const double lastX = f * rt.width - 1, lastY = f * rt.height - 1;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      double tx = (x + 0.5) / w * f * rt.width - 0.5, ty = (y + 0.5) / h * f * rt.height - 0.5;
      if (clampToViewport) tx = std::clamp(tx, 0.0, lastX), ty = std::clamp(ty, 0.0, lastY);
      const int x0 = int(std::floor(tx)), y0 = int(std::floor(ty));
      const double ax = tx - x0, ay = ty - y0;
      for (int c = 0; c < 3; ++c) {
        const double top = (1 - ax) * Texel(rt, x0, y0, c) + ax * Texel(rt, x0 + 1, y0, c);
        const double bottom = (1 - ax) * Texel(rt, x0, y0 + 1, c) + ax * Texel(rt, x0 + 1, y0 + 1, c);
        out[(size_t(y) * w + x) * 3 + c] = (1 - ay) * top + ay * bottom;
      }
    }
  return out;
}

// Channels of the sRGB back buffer outside the encoding of the model's linear
// value give or take `slack` (the sampler's fixed-point weights; sRGB's steep
// dark end turns a small linear difference into several 8-bit steps).
uint64_t Mismatches(const std::vector<double>& model, const Image& bb, double slack) {
  uint64_t n = 0;
  for (size_t p = 0; p < size_t(bb.width) * bb.height; ++p)
    for (int c = 0; c < 3; ++c) {
      const double v = model[p * 3 + c];
      const long lo = std::lround(EncodeSrgb(v - slack) * 255), hi = std::lround(EncodeSrgb(v + slack) * 255);
      const int got = bb.pixels[p * 4 + c];
      n += got < lo || got > hi;
    }
  return n;
}

Options Gles2Options(const char* scale) {
  Options o;
  std::string message;
  EXPECT_EQ(ParseCommandLine({"--headless", "--no-gui", "--quiet", "--width", "320", "--height", "176", "--time", "1",
                              "--camera", "2", "--preset", "gles2", "--scale", scale},
                             &o, &message),
            ParseStatus::Ok)
      << message;
  return o;
}

using PresetFixture = SampleTest;
constexpr double kSlack = 1.5 / 255;

}  // namespace

// At 0.5 and 0.25 the last rows and columns of the back buffer read into the
// texels past the viewport (the article's quad is not clamped): the CPU model
// of the article, clear colour outside the viewport included, gives the frame,
// and a model clamped to the viewport (the uv-inset fix) does not.
TEST_F(PresetFixture, Gles2IsTheArticlesBilinearQuadToF) {
  for (const char* scale : {"0.5", "0.25"}) {
    const Options o = Gles2Options(scale);
    if (std::string(scale) == "0.5") StartSample(o);
    else sample.ApplySettings(o);
    const Image bb = RenderAndCapture(sample, 3);
    const Image& rt = sample.CapturedSceneColor();
    const DynamicResolution& dr = sample.GetDynamicResolution();
    const double f = std::atof(scale);
    ASSERT_EQ(rt.width, 320u);  // the target at native size
    ASSERT_EQ(dr.GetViewportWidth(), uint32_t(320 * f));
    ASSERT_EQ(dr.GetViewportHeight(), uint32_t(176 * f));
    const uint64_t article = Mismatches(ArticleQuad(rt, bb.width, bb.height, f, false), bb, kSlack);
    const uint64_t clamped = Mismatches(ArticleQuad(rt, bb.width, bb.height, f, true), bb, kSlack);
    std::printf("[image] gles2 at %s: channels off the article's quad %llu, off a clamped quad %llu\n", scale,
                (unsigned long long)article, (unsigned long long)clamped);
    EXPECT_EQ(article, 0u) << scale;
    EXPECT_GT(clamped, 0u) << scale << ": the edge does not show the texels past the viewport";
  }
}

// The preset's passes: no motion blur, no TAA, no velocity target.
TEST_F(PresetFixture, Gles2WritesNoVelocityTarget) {
  const Options o = Gles2Options("0.75");
  EXPECT_EQ(o.filter, Filter::Bilinear);
  EXPECT_FALSE(o.motionBlur);
  EXPECT_FALSE(o.psClear);
  StartSample(o);
  RenderAndCapture(sample, 2);
  EXPECT_EQ(sample.GetDynamicResolution().GetViewportWidth(), 240u);
  EXPECT_EQ(sample.GetDynamicResolution().GetViewportHeight(), 132u);
  EXPECT_TRUE(sample.CapturedVelocity().pixels.empty()) << "a velocity target was written";
  const auto& passes = sample.PassesRun();
  EXPECT_TRUE(passes.count("ClearAPI")) << "glClear of the whole target";
  EXPECT_FALSE(passes.count("ClearPS"));
  EXPECT_FALSE(passes.count("MotionBlurDynamic"));
}
