// --preset gles2 renders the OpenGL ES 2.0 article's system under validation:
// the back buffer is the native-size target's viewport (w f, h f) sampled
// bilinearly with texture coordinates running to (f, f), not clamped inside the
// viewport, through a clamp-to-edge sampler over the whole target; no velocity
// target is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

// The article's full-screen quad on the CPU: pixel (x, y) of a w x h back
// buffer reads uv = (x + 0.5) / w * f bilinearly, with no clamp to the used part.
Image ArticleQuad(const Image& rt, uint32_t w, uint32_t h, double f) {
  Image out;
  out.width = w;
  out.height = h;
  out.pixels.assign(size_t(w) * h * 4, 255);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const double tx = (x + 0.5) / w * f * rt.width - 0.5, ty = (y + 0.5) / h * f * rt.height - 0.5;
      const int x0 = int(std::floor(tx)), y0 = int(std::floor(ty));
      const double ax = tx - x0, ay = ty - y0;
      for (int c = 0; c < 3; ++c) {
        const double top = (1 - ax) * Texel(rt, x0, y0, c) + ax * Texel(rt, x0 + 1, y0, c);
        const double bottom = (1 - ax) * Texel(rt, x0, y0 + 1, c) + ax * Texel(rt, x0 + 1, y0 + 1, c);
        out.pixels[(size_t(y) * w + x) * 4 + c] = uint8_t(std::lround(EncodeSrgb((1 - ay) * top + ay * bottom) * 255));
      }
    }
  return out;
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

}  // namespace

// At 0.5 the last row and column of the back buffer read a quarter of the
// texel past the viewport (the article's quad is not clamped): the CPU model
// of the article, clear colour outside the viewport included, gives the frame.
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
    const Diff all = Compare(ArticleQuad(rt, bb.width, bb.height, f), bb);
    std::printf("[image] gles2 at %s vs the article's quad on the CPU: max diff %d, %llu px differ\n", scale,
                all.maxAbs, (unsigned long long)all.differing);
    EXPECT_LE(all.maxAbs, 2) << scale;
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
