// PlanFrame on the CPU for every mode of scripts/mode-matrix.sh: the render
// targets the frame needs and the passes it records. The expected lists are
// what the sample allocated and counted (its report's render_targets and
// passes_run) for the same command lines before the frame plan existed, so a
// difference is a change of behaviour; the deferred modes' shadow-map array (a
// 1x1 placeholder: the Arena has no shadowed spot) and the zoom box's copy
// are rows of the table too.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "FramePlan.h"
#include "Options.h"

using namespace drr;

namespace {
struct Mode {
  const char* name;
  const char* args;  // on top of the matrix's common options
  std::vector<std::string> targets, passes;
};

// name, options, targets (RenderTargetSet::Name), passes (sorted)
const Mode kModes[] = {
    {"none", "--filter none",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearFinalNone", "ClearPS", "MotionBlurDynamic", "ResolveNone", "Scene"}},
    {"point", "--filter point",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "ResolvePoint", "Scene"}},
    {"bilinear", "--filter bilinear",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveBilinear", "Scene"}},
    {"bicubic", "--filter bicubic",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveBicubic", "Scene"}},
    {"noise", "--filter noise",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveNoise", "Scene"}},
    {"noise-offset", "--filter noise-offset",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveNoiseOffset", "Scene"}},
    {"taa", "--filter taa",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveTAAFast", "Scene"}},
    {"taa-noise-offset", "--filter taa-noise-offset",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveTAANoiseOffsetFast", "Scene"}},
    {"taa-basic", "--filter taa-basic",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveTAABasic", "Scene"}},
    {"bicubic-bspline", "--filter bicubic-bspline",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveBicubicBSpline", "Scene"}},
    {"upscale-q0", "--upscale-quality 0",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "UpscaleNearest"}},
    {"upscale-q1", "--upscale-quality 1",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "UpscaleBilinear"}},
    {"upscale-q2", "--upscale-quality 2",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "UpscaleDirectional"}},
    {"upscale-q3", "--upscale-quality 3",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "UpscaleCatmullRom"}},
    {"upscale-q4", "--upscale-quality 4",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "UpscaleLanczos3"}},
    {"upscale-q5", "--upscale-quality 5",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "UpscaleGaussianUnsharp"}},
    {"taau", "--temporal-upsampling",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale history[0]", "upscale history[1]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "TemporalUpsample"}},
    {"edge-adaptive", "--filter upscale-edge-adaptive",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale sharpen input"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "Sharpen", "UpscaleEdgeAdaptive"}},
    {"taau-fast", "--filter taau-fast",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale history[0]", "upscale history[1]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "TemporalUpsampleFast"}},
    {"none-nomb", "--filter none --no-motion-blur",
     {"g_DepthDynamic", "g_FinalRTDynamic[0]"},
     {"ClearFinalNone", "ClearPS", "ResolveNone", "Scene"}},
    {"bicubic-nomb", "--filter bicubic --no-motion-blur",
     {"g_DepthDynamic", "g_FinalRTDynamic[0]"},
     {"ClearPS", "ResolveBicubic", "Scene"}},
    {"taa-nomb", "--filter taa --no-motion-blur",
     {"g_DepthDynamic", "g_VelocityDynamic[0]", "g_VelocityDynamic[1]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "ResolveTAA", "Scene"}},
    {"taa-noise-offset-nomb", "--filter taa-noise-offset --no-motion-blur",
     {"g_DepthDynamic", "g_VelocityDynamic[0]", "g_VelocityDynamic[1]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "ResolveTAANoiseOffset", "Scene"}},
    {"taau-nomb", "--filter taau --no-motion-blur",
     {"g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale history[0]", "upscale history[1]"},
     {"ClearPS", "Scene", "TemporalUpsample"}},
    {"taa-apiclear", "--filter taa --no-ps-clear",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearAPI", "MotionBlurDynamic", "ResolveTAAFast", "Scene"}},
    {"bilinear-apiclear-nomb", "--filter bilinear --no-ps-clear --no-motion-blur",
     {"g_DepthDynamic", "g_FinalRTDynamic[0]"},
     {"ClearAPI", "ResolveBilinear", "Scene"}},
    {"ss-bicubic", "--supersampling --scale 1.4 --filter bicubic",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveBicubic", "Scene"}},
    {"ss-taa", "--supersampling --scale 1.3 --filter taa",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveTAAFast", "Scene"}},
    {"zoom-bilinear", "--filter bilinear --zoom",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "zoom_box_copy"},
     {"ClearPS", "MotionBlurDynamic", "ResolveBilinear", "Scene", "ZoomBox"}},
    {"zoom-taau", "--filter taau --zoom",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale history[0]", "upscale history[1]", "zoom_box_copy"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "TemporalUpsample", "ZoomBox"}},
    {"deferred-taa", "--renderer deferred --filter taa",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]", "g_GBufferDiffuse", "g_GBufferSpecular", "g_GBufferNormal", "g_GBufferAO", "g_SpotShadowMaps"},
     {"ClearPS", "GBuffer", "Lighting", "MotionBlurDynamic", "ResolveTAAFast", "SSAO"}},
    {"deferred-bilinear-nossao", "--renderer deferred --no-ssao --filter bilinear",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_GBufferDiffuse", "g_GBufferSpecular", "g_GBufferNormal", "g_SpotShadowMaps"},
     {"ClearPS", "GBuffer", "Lighting", "MotionBlurDynamic", "ResolveBilinear"}},
    {"deferred-taau", "--renderer deferred --filter taau",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale history[0]", "upscale history[1]", "g_GBufferDiffuse", "g_GBufferSpecular", "g_GBufferNormal", "g_GBufferAO", "g_SpotShadowMaps"},
     {"ClearPS", "GBuffer", "Lighting", "MotionBlurDynamic", "SSAO", "TemporalUpsample"}},
    {"deferred-full", "--renderer deferred --no-dynamic-resolution",
     {"g_ColorFull", "g_VelocityFull", "g_DepthFull", "g_GBufferDiffuse", "g_GBufferSpecular", "g_GBufferNormal", "g_GBufferAO", "g_SpotShadowMaps"},
     {"ClearPS", "GBuffer", "Lighting", "MotionBlurFull", "SSAO"}},
    {"tessellation", "--tessellation --filter taa",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveTAAFast", "Scene"}},
    {"fix-all-taa", "--fix all --filter taa",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveTAAFast", "Scene"}},
    {"fix-all-none", "--fix all --filter none",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearFinalNone", "ClearPS", "MotionBlurDynamic", "ResolveNone", "Scene"}},
    {"fix-all-taa-basic-full", "--fix all --no-dynamic-resolution --filter taa-basic",
     {"g_ColorFull", "g_VelocityFull", "g_DepthFull"},
     {"ClearPS", "MotionBlurFull", "Scene"}},
    {"secondary75-catmull", "--secondary-screen-percentage 75 --upscale-quality 3",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale output"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "SecondaryUpscale", "UpscaleCatmullRom"}},
    {"secondary60-taau", "--secondary-screen-percentage 60 --filter taau",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale history[0]", "upscale history[1]"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "SecondaryUpscale", "TemporalUpsample"}},
    {"secondary75-edge", "--secondary-screen-percentage 75 --filter upscale-edge-adaptive",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "upscale output", "upscale sharpen input"},
     {"ClearPS", "MotionBlurDynamic", "Scene", "SecondaryUpscale", "Sharpen", "UpscaleEdgeAdaptive"}},
    {"full-mb", "--no-dynamic-resolution",
     {"g_ColorFull", "g_VelocityFull", "g_DepthFull"},
     {"ClearPS", "MotionBlurFull", "Scene"}},
    {"full-nomb", "--no-dynamic-resolution --no-motion-blur",
     {"g_DepthFull"},
     {"ClearPS", "Scene"}},
    {"full-taa-basic", "--no-dynamic-resolution --filter taa-basic",
     {"g_ColorFull", "g_VelocityFull", "g_DepthFull"},
     {"ClearPS", "MotionBlurFull", "Scene"}},
    {"full-apiclear", "--no-dynamic-resolution --no-ps-clear",
     {"g_ColorFull", "g_VelocityFull", "g_DepthFull"},
     {"ClearAPI", "MotionBlurFull", "Scene"}},
    {"taa-paused", "--filter taa --pause",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveTAAFast", "Scene"}},
    {"taa-symmetric", "--filter taa --symmetric-taa",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]"},
     {"ClearPS", "MotionBlurDynamic", "ResolveTAAFast", "Scene"}},
    // MarkOutside: a test aid the plan lists but passes_run does not count.
    {"marker-bilinear", "--filter bilinear --debug-marker-outside",
     {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]", "g_FinalRTDynamic[0]"},
     {"ClearPS", "MarkOutside", "MotionBlurDynamic", "ResolveBilinear", "Scene"}},
};

Options Parse(const char* extra) {
  std::vector<std::string> args = {"--headless", "--width", "320", "--height", "180", "--frames", "20", "--time", "5",
                                   "--fixed-dt", "0.02", "--control", "manual", "--scale", "0.71", "--no-gui"};
  std::istringstream words(extra);
  for (std::string w; words >> w;) args.push_back(w);
  Options o;
  std::string message;
  EXPECT_EQ(ParseCommandLine(args, &o, &message), ParseStatus::Ok) << extra << ": " << message;
  return o;
}

FrameInputs MatrixInputs() {
  FrameInputs in;
  in.backBufferW = 320;
  in.backBufferH = 180;
  return in;  // the Arena has no shadowed spot light; no GUI
}
}  // namespace

class FramePlanModes : public ::testing::TestWithParam<Mode> {};

TEST_P(FramePlanModes, TargetsAndPassesAsTheSampleRan) {
  const Mode& m = GetParam();
  const FramePlan plan = PlanFrame(Parse(m.args), MatrixInputs());
  std::vector<std::string> targets;
  for (RT rt : plan.NeededTargets()) targets.push_back(RenderTargetSet::Name(rt));
  EXPECT_EQ(targets, m.targets) << m.name;
  std::vector<std::string> passes = plan.PassNames();
  std::sort(passes.begin(), passes.end());
  EXPECT_EQ(passes, m.passes) << m.name;
  // Each pass once a frame.
  EXPECT_EQ(std::adjacent_find(passes.begin(), passes.end()), passes.end()) << m.name;
}

INSTANTIATE_TEST_SUITE_P(Matrix, FramePlanModes, ::testing::ValuesIn(kModes),
                         [](const ::testing::TestParamInfo<Mode>& info) {
                           std::string n = info.param.name;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

// The shadow maps exist exactly in the deferred modes, the zoom box's copy in
// the zoom modes.
TEST_P(FramePlanModes, ShadowMapsWhenDeferredAndZoomCopyWhenZoomed) {
  const Mode& m = GetParam();
  const FramePlan plan = PlanFrame(Parse(m.args), MatrixInputs());
  const std::string args = m.args;
  EXPECT_EQ(RenderTargetSet::Needed(RT::SpotShadowMaps, plan.targets), args.find("--renderer deferred") != std::string::npos)
      << m.name;
  EXPECT_EQ(RenderTargetSet::Needed(RT::ZoomBoxCopy, plan.targets), args.find("--zoom") != std::string::npos) << m.name;
}

// A slice per shadowed spot at --shadow-map-size when the shadow maps are
// drawn; the 1x1 one-slice placeholder when they are not; nothing forward.
// The zoom box's copy: the back buffer's size and format.
TEST(FramePlan, ShadowMapAndZoomCopyRowsSizes) {
  FrameInputs in = MatrixInputs();
  in.shadowedLights = 3;
  in.backBufferFormat = d3dl::DXGI_FORMAT_B8G8R8A8_UNORM;
  uint32_t w = 0, h = 0;
  const RenderTargetPlan drawn = PlanFrame(Parse("--renderer deferred --shadow-map-size 512 --zoom"), in).targets;
  EXPECT_EQ(drawn.shadowSlices, 3u);
  drawn.Size(RenderTargetSet::Row(RT::SpotShadowMaps).size, 7, 7, &w, &h);
  EXPECT_EQ(w, 512u);
  EXPECT_EQ(h, 512u);
  EXPECT_EQ(RenderTargetSet::Format(RT::SpotShadowMaps, drawn), d3dl::DXGI_FORMAT_R32_TYPELESS);
  drawn.Size(RenderTargetSet::Row(RT::ZoomBoxCopy).size, 7, 7, &w, &h);
  EXPECT_EQ(w, 320u);
  EXPECT_EQ(h, 180u);
  EXPECT_EQ(RenderTargetSet::Format(RT::ZoomBoxCopy, drawn), d3dl::DXGI_FORMAT_B8G8R8A8_UNORM);
  const RenderTargetPlan unlit = PlanFrame(Parse("--renderer deferred --shadow-map-size 512 --no-local-lights"), in).targets;
  EXPECT_EQ(unlit.shadowSlices, 1u);
  EXPECT_EQ(unlit.shadowMapSize, 1u);
  EXPECT_FALSE(RenderTargetSet::Needed(RT::ZoomBoxCopy, unlit));
  const RenderTargetPlan forward = PlanFrame(Parse("--shadow-map-size 512"), in).targets;
  EXPECT_FALSE(RenderTargetSet::Needed(RT::SpotShadowMaps, forward));
  // The zoom box and the shadow maps alone change nothing else (Sample::UpdateTargets).
  EXPECT_TRUE(drawn.SameButRewrittenEachFrame(unlit));
  EXPECT_FALSE(drawn.SameButRewrittenEachFrame(forward));
}

TEST(FramePlan, PassOrderOfTheDeferredTemporalUpsampleWithZoomAndGui) {
  Options o = Parse("--renderer deferred --filter taau --secondary-screen-percentage 60 --zoom");
  FrameInputs in = MatrixInputs();
  in.shadowedLights = 2;
  in.guiDrawn = true;
  const FramePlan plan = PlanFrame(o, in);
  const std::vector<std::string> expected = {"ClearPS", "ShadowMaps", "GBuffer", "SSAO", "Lighting",
                                             "MotionBlurDynamic", "TemporalUpsample", "SecondaryUpscale",
                                             "ZoomBox", "GUI"};
  EXPECT_EQ(plan.PassNames(), expected);
  EXPECT_TRUE(plan.TAAU());
  EXPECT_TRUE(plan.secondary);
  EXPECT_FALSE(plan.flipsTargets);
}

TEST(FramePlan, NoneClearsItsFinalTargetBeforeTheSceneOnlyWithTheFix) {
  const FramePlan original = PlanFrame(Parse("--filter none"), MatrixInputs());
  const FramePlan fixed = PlanFrame(Parse("--filter none --fix none-shows-rt"), MatrixInputs());
  EXPECT_EQ(original.PassNames(), (std::vector<std::string>{"ClearPS", "Scene", "ClearFinalNone", "MotionBlurDynamic",
                                                       "ResolveNone"}));
  EXPECT_EQ(fixed.PassNames(), (std::vector<std::string>{"ClearFinalNone", "ClearPS", "Scene", "MotionBlurDynamic",
                                                    "ResolveNone"}));
}

TEST(FramePlan, TheOriginalsFlipQuirkAndItsFix) {
  // TAA Basic flips the final pair with dynamic resolution off (operator
  // precedence in the original); the taa-flip fix flips only when TAA runs.
  EXPECT_TRUE(PlanFrame(Parse("--no-dynamic-resolution --filter taa-basic"), MatrixInputs()).flipsTargets);
  EXPECT_FALSE(PlanFrame(Parse("--no-dynamic-resolution --filter taa-basic --fix taa-flip"), MatrixInputs()).flipsTargets);
  EXPECT_FALSE(PlanFrame(Parse("--no-dynamic-resolution --filter taa"), MatrixInputs()).flipsTargets);
  EXPECT_TRUE(PlanFrame(Parse("--filter taa"), MatrixInputs()).flipsTargets);
  EXPECT_FALSE(PlanFrame(Parse("--filter taau"), MatrixInputs()).flipsTargets);
}

// The temporal state a plan leaves is the next plan's input (TemporalHistory):
// TAA writes the other final target each frame and reads the last one once
// the history holds a frame.
TEST(FramePlan, TAAHistoryAlternatesAndReadsTheLastFrameOnceValid) {
  FrameInputs in = MatrixInputs();
  const Options o = Parse("--filter taa");
  const FramePlan first = PlanFrame(o, in);
  EXPECT_EQ(first.setup.cur, 1);
  EXPECT_EQ(first.setup.prev, 1);  // nothing to read yet
  EXPECT_TRUE(first.history.valid);
  in.history = first.history;
  const FramePlan second = PlanFrame(o, in);
  EXPECT_EQ(second.setup.cur, 0);
  EXPECT_EQ(second.setup.prev, 1);
  EXPECT_EQ(second.scene.target, 0);
  // The jitter pair alternates with the target written.
  EXPECT_NE(second.setup.dc.jitterCurr[0], second.setup.dc.jitterPrev[0]);
}

// TAAU: the history pair alternates from the second frame, the Halton index
// advances each frame and holds while paused.
TEST(FramePlan, TAAUHistoryAndJitterIndex) {
  FrameInputs in = MatrixInputs();
  const FramePlan first = PlanFrame(Parse("--filter taau"), in);
  EXPECT_FALSE(first.setup.historyValid);
  EXPECT_EQ(first.history.jitterIndex, 1u);
  in.history = first.history;
  const FramePlan second = PlanFrame(Parse("--filter taau"), in);
  EXPECT_TRUE(second.setup.historyValid);
  EXPECT_EQ(second.setup.historyCur, 1 - first.setup.historyCur);
  EXPECT_EQ(second.history.jitterIndex, 2u);
  in.history = second.history;
  const FramePlan paused = PlanFrame(Parse("--filter taau --pause"), in);
  EXPECT_EQ(paused.history.jitterIndex, 2u);
  EXPECT_EQ(paused.setup.uc.jitterPx[0], second.setup.uc.jitterPx[0]);
}

// Nothing temporal: the final target 0 every frame, no jitter.
TEST(FramePlan, SpatialFiltersKeepTargetZeroWithoutJitter) {
  FrameInputs in = MatrixInputs();
  const FramePlan first = PlanFrame(Parse("--filter bicubic"), in);
  in.history = first.history;
  const FramePlan second = PlanFrame(Parse("--filter bicubic"), in);
  EXPECT_EQ(second.setup.cur, 0);
  EXPECT_FALSE(second.history.valid);
  EXPECT_EQ(second.scene.jitterNdc, glm::vec2(0.0f));
}
