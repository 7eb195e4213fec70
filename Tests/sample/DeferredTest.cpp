// The deferred renderer (Docs/Deferred.md) in the whole sample, under
// validation: the same view as the forward path where the lighting models
// agree, the G-buffer's targets and formats from the render-target table (and
// none with forward), SSAO that only darkens, scene lights that only add, a
// spot shadow that only removes light, and the shadow maps' dynamic scale.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "SampleTestKit.h"
#include "analysis/ImageMetrics.h"
#include "ScratchDir.h"

namespace drr {
namespace {

using testkit::RenderFresh;
using testkit::SampleTest;

constexpr uint32_t kW = 256, kH = 144;
constexpr double kTime = 3.0;  // a fixed animation time: the camera stands still
constexpr int kFrames = 3;
// Deferred against forward with the directional light alone: the G-buffer
// keeps the material in 8-bit sRGB and the normal in 10 bits where the
// forward shader keeps floats, and the lighting pass rebuilds the position
// from depth; everything else is the same formula.
constexpr double kMinPsnrDb = 45.0;  // measured 49.0 dB at scale 1, 48.4 dB at 0.5 (lavapipe, 256x144)

Options Base(Renderer r, float scale) {
  Options o = testkit::HeadlessOptions(kW, kH, kTime);
  o.motionBlur = false;
  o.filter = Filter::Point;  // no history: each image is one frame's
  o.scaleX = o.scaleY = scale;
  o.renderer = r;
  return o;
}

ImageF ToFloat(const Image& i) { return ImageFromRGBA8(i.pixels.data(), i.width, i.height, i.width * 4); }

// Channels of b above / below a by more than one step (8-bit, RGB), and the summed difference.
struct Change {
  uint64_t brighter = 0, darker = 0;
  double sum = 0.0;
};
Change Compare(const Image& a, const Image& b) {
  Change c;
  for (size_t p = 0; p + 3 < a.pixels.size() && p + 3 < b.pixels.size(); p += 4)
    for (int k = 0; k < 3; ++k) {
      const int d = int(b.pixels[p + k]) - int(a.pixels[p + k]);
      c.brighter += d > 1;
      c.darker += d < -1;
      c.sum += d;
    }
  return c;
}

class DeferredTest : public SampleTest {
 protected:
  static Image Render(const Options& o) { return RenderFresh(o, kFrames).image; }
  // The Arena's description with light lines appended (the model paths made absolute).
  static std::string LitScene(const std::string& lights) {
    const std::filesystem::path& dir = drrtest::ProcessScratchDir();
    const std::string a = std::string(DRR_TEST_ARENA_DIR) + "/";
    const std::filesystem::path file = dir / ("lit_" + std::to_string(std::hash<std::string>{}(lights)) + ".txt");
    std::ofstream(file) << a << "arena.gltf NO_ANIM LIT\n"
                        << a << "bell.gltf " << a << "bell.gltf LIT\n"
                        << a << "sky.gltf NO_ANIM UNLIT\n"
                        << a << "decals.gltf NO_ANIM DECAL\n"
                        << a << "camera_cinematic.gltf " << a << "camera_cinematic.gltf CAMERA\n"
                        << lights;
    return file.string();
  }
};

// What-it-must-show 4: the same view within kMinPsnrDb where the lighting
// models agree (directional light only, SSAO and scene lights off), at full
// scale and at half scale (the G-buffer read through the RT ratio).
TEST_F(DeferredTest, MatchesForwardWithTheDirectionalLightOnly) {
  for (float scale : {1.0f, 0.5f}) {
    const Image forward = Render(Base(Renderer::Forward, scale));
    Options d = Base(Renderer::Deferred, scale);
    d.ssao = false;
    d.localLights = false;
    const Image deferred = Render(d);
    ASSERT_FALSE(forward.Empty());
    const ImageError e = CompareImages(ToFloat(forward), ToFloat(deferred));
    ASSERT_TRUE(e.valid);
    std::printf("scale %.2f: deferred vs forward PSNR %.2f dB, SSIM %.4f, max error %.3f\n", scale, e.psnr, e.ssim,
                e.maxAbsError);
    EXPECT_GE(e.psnr, kMinPsnrDb) << "scale " << scale;
  }
}

// The render-target table decides: no G-buffer with forward; with deferred
// the seed's formats, the AO target only with SSAO, depth typeless.
TEST_F(DeferredTest, GBufferTargetsExistOnlyWhenDeferred) {
  const RT gbuffer[] = {RT::GBufferDiffuse, RT::GBufferSpecular, RT::GBufferNormal, RT::GBufferAO};
  StartSample(Base(Renderer::Forward, 0.5f));
  ASSERT_TRUE(sample.RenderFrame());
  for (RT rt : gbuffer) EXPECT_FALSE(sample.Targets()[rt].Valid()) << RenderTargetSet::Name(rt);
  EXPECT_EQ(sample.Targets()[RT::DepthDynamic].format, d3dl::DXGI_FORMAT_D32_FLOAT);
  EXPECT_EQ(sample.PassesRun().count("GBuffer"), 0u);
  const uint64_t forwardBytes = sample.RenderTargetBytes();
  Options o = Base(Renderer::Deferred, 0.5f);
  sample.ApplySettings(o);
  ASSERT_TRUE(sample.RenderFrame());
  const d3dl::DXGI_FORMAT formats[] = {d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB,
                                       d3dl::DXGI_FORMAT_R10G10B10A2_UNORM, d3dl::DXGI_FORMAT_R8_UNORM};
  for (int i = 0; i < 4; ++i) {
    const RenderTarget& t = sample.Targets()[gbuffer[i]];
    EXPECT_TRUE(t.Valid()) << RenderTargetSet::Name(gbuffer[i]);
    EXPECT_EQ(t.format, formats[i]) << RenderTargetSet::Name(gbuffer[i]);
    EXPECT_EQ(t.width, sample.GetDynamicResolution().GetDynamicBufferWidth());  // the oversized RT
  }
  EXPECT_EQ(sample.Targets()[RT::DepthDynamic].format, d3dl::DXGI_FORMAT_R32_TYPELESS);
  EXPECT_GT(sample.RenderTargetBytes(), forwardBytes);
  for (const char* pass : {"GBuffer", "SSAO", "Lighting"}) EXPECT_EQ(sample.PassesRun().count(pass), 1u) << pass;
  o.ssao = false;
  sample.ApplySettings(o);
  ASSERT_TRUE(sample.RenderFrame());
  EXPECT_FALSE(sample.Targets()[RT::GBufferAO].Valid());
  EXPECT_EQ(sample.PassesRun().at("SSAO"), 1u);  // not run again
}

// The AO target only scales the ambient term down.
TEST_F(DeferredTest, AmbientOcclusionOnlyDarkens) {
  Options o = Base(Renderer::Deferred, 1.0f);
  o.ssao = false;
  const Image off = Render(o);
  o.ssao = true;
  const Image on = Render(o);
  const Change c = Compare(off, on);
  EXPECT_EQ(c.brighter, 0u);
  EXPECT_GT(c.darker, uint64_t(kW * kH) / 100) << "SSAO darkened under 1 % of the channels";
}

// Point and spot lights add light and never remove any; a spot's shadow
// (slice of the shadow-map array) removes some of its light and adds none.
TEST_F(DeferredTest, SceneLightsAddAndSpotShadowsRemove) {
  const std::string spot = "LIGHT SPOT position=0,1500,200 direction=0,-1,0 color=3,3,3 radius=3000 angle=30";
  Options o = Base(Renderer::Deferred, 1.0f);
  o.ssao = false;
  o.scene = LitScene("");
  const Image none = Render(o);
  o.scene = LitScene("LIGHT POINT position=0,120,600 color=0,0,3 radius=1500\n" + spot + " shadow=0\n");
  const Image lit = Render(o);
  o.scene = LitScene("LIGHT POINT position=0,120,600 color=0,0,3 radius=1500\n" + spot + " shadow=1\n");
  const Image shadowed = Render(o);
  const Change added = Compare(none, lit), removed = Compare(lit, shadowed);
  EXPECT_EQ(added.darker, 0u);
  EXPECT_GT(added.brighter, uint64_t(kW * kH) / 50);
  EXPECT_EQ(removed.brighter, 0u);
  EXPECT_GT(removed.darker, uint64_t(kW * kH) / 200) << "the bell and columns cast no shadow";
}

// The shadow maps' own dynamic scale: the fixed law keeps the option, the main
// law follows the resolution scale; the used viewport is what the lighting reads.
TEST_F(DeferredTest, ShadowMapScaleFollowsItsLaw) {
  Options o = Base(Renderer::Deferred, 0.5f);
  o.ssao = false;
  o.shadowMapSize = 256;
  o.shadowScale = 0.75;
  o.scene = LitScene("LIGHT SPOT position=0,1500,200 direction=0,-1,0 color=3,3,3 radius=3000 angle=30 shadow=1\n");
  o.shadowLaw = ShadowLaw::Fixed;
  StartSample(o);
  ASSERT_TRUE(sample.RenderFrame());
  EXPECT_FLOAT_EQ(sample.Deferred().ShadowScaleUsed(), 0.75f);
  EXPECT_EQ(sample.Deferred().ShadowSlices(), 1u);
  EXPECT_GT(sample.Deferred().ShadowMapDraws(), 0u);
  // The table's row: one slice of --shadow-map-size squared.
  const RenderTarget& maps = sample.Targets()[RT::SpotShadowMaps];
  EXPECT_EQ(maps.slices, 1u);
  EXPECT_EQ(maps.width, 256u);
  EXPECT_EQ(maps.Bytes(), 256u * 256u * 4u);
  o.shadowLaw = ShadowLaw::Main;
  sample.ApplySettings(o);
  ASSERT_TRUE(sample.RenderFrame());
  EXPECT_FLOAT_EQ(sample.Deferred().ShadowScaleUsed(), std::floor(0.75f * 0.5f * 256.0f) / 256.0f);
  // Without the local lights the 1x1 placeholder replaces the maps alone.
  const d3dl::Texture2D* kept = sample.Targets()[RT::FinalDynamic0].texture.Get();
  ASSERT_NE(kept, nullptr);
  o.localLights = false;
  sample.ApplySettings(o);
  ASSERT_TRUE(sample.RenderFrame());
  EXPECT_EQ(maps.width, 1u);
  EXPECT_EQ(maps.slices, 1u);
  EXPECT_EQ(sample.Targets()[RT::FinalDynamic0].texture.Get(), kept) << "an unrelated target was re-created";
}

// Every target mode of the table with the deferred scene: full resolution
// (the G-buffer at the dynamic RT's size, read through back buffer / RT),
// motion blur, TAA (velocity into the G-buffer's fourth target), super
// sampling (the viewport beyond the back buffer), TAAU (depth shared with its
// reader). Validation-clean, and the same picture as forward in each.
TEST_F(DeferredTest, EveryTargetModeMatchesForward) {
  struct Mode {
    const char* name;
    bool dynamic, motionBlur, superSampling;
    Filter filter;
    float scale;
  };
  const Mode modes[] = {{"full", false, false, false, Filter::Point, 1.0f},
                        {"full + motion blur", false, true, false, Filter::Point, 1.0f},
                        {"dynamic + motion blur + TAA", true, true, false, Filter::TAA, 0.71f},
                        {"TAA, velocity targets", true, false, false, Filter::TAA, 0.6f},
                        {"super sampling", true, false, true, Filter::Bilinear, 1.5f},
                        {"TAAU", true, false, false, Filter::TAAU, 0.5f}};
  for (const Mode& m : modes) {
    Options o = Base(Renderer::Forward, m.scale);
    o.width = kW / 2;  // twelve samples: kept small
    o.height = kH / 2;
    o.dynamicResolution = m.dynamic;
    o.motionBlur = m.motionBlur;
    o.superSampling = m.superSampling;
    o.filter = m.filter;
    const Image forward = Render(o);
    o.renderer = Renderer::Deferred;
    o.ssao = false;
    o.localLights = false;
    const Image deferred = Render(o);
    const ImageError e = CompareImages(ToFloat(forward), ToFloat(deferred));
    ASSERT_TRUE(e.valid) << m.name;
    std::printf("%s: deferred vs forward PSNR %.2f dB\n", m.name, e.psnr);
    EXPECT_GE(e.psnr, 40.0) << m.name;
  }
}

TEST(ShadowMapScale, LawsAndLimits) {
  EXPECT_FLOAT_EQ(ShadowMapScale(ShadowLaw::Fixed, 0.5f, 0.3f), 0.5f);
  EXPECT_FLOAT_EQ(ShadowMapScale(ShadowLaw::Main, 0.5f, 0.5f), 0.25f);
  EXPECT_FLOAT_EQ(ShadowMapScale(ShadowLaw::Main, 1.0f, 2.0f), 1.0f);  // super sampling: capped at the map
  EXPECT_FLOAT_EQ(ShadowMapScale(ShadowLaw::Main, 0.25f, 0.3f), kMinShadowScale);
  EXPECT_FLOAT_EQ(ShadowMapScale(ShadowLaw::Main, 1.0f, std::nanf("")), 1.0f);
}

}  // namespace
}  // namespace drr
