// The sample's scene, cameras and frame against the original (in process,
// under validation): the default camera is the moving cinematic one, a pause
// keeps the last frame's velocity, and each fix of this area changes what it
// says and nothing else.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "DynamicResolutionRendering.h"
#include "SampleTestKit.h"

using namespace drr;
using namespace drr::testkit;

namespace {

Options SmallOptions() {
  return HeadlessOptions(160, 90, 3.0);
}

// Largest |velocity| (UV units) of a captured velocity target.
float MaxVelocity(const Image& v) {
  float m = 0.f;
  for (uint32_t y = 0; y < v.height; ++y)
    for (uint32_t x = 0; x < v.width; ++x) m = std::max({m, std::fabs(v.Float(x, y, 0)), std::fabs(v.Float(x, y, 1))});
  return m;
}

}  // namespace

// The original's camera list: 0 First Person, 1.. the CAMERA entries in file
// order; its default, 1, is the Arena's animated cinematic camera.
TEST(SceneFrame, DefaultCameraIsTheMovingCinematicCamera) {
  Sample s;
  if (!Start(s, SmallOptions())) return;
  EXPECT_EQ(s.GetCameras().Current(), 1);
  EXPECT_EQ(s.GetCameras().Name(0), "First Person");
  EXPECT_EQ(s.GetCameras().Name(1), "camera_cinematic");
  EXPECT_EQ(s.GetCameras().Count(), 4);
  const Image at3 = RenderAndCapture(s, 2);
  Options o = s.Settings();
  o.time = 10.0;
  s.ApplySettings(o);
  const Image at10 = RenderAndCapture(s, 2);
  const Diff d = Compare(at3, at10);
  std::printf("[camera] default camera, t=3 vs t=10: %llu of %u px differ\n", (unsigned long long)d.differing,
              at3.width * at3.height);
  EXPECT_GT(d.differing, uint64_t(at3.width) * at3.height / 2) << "the default camera must move over time";
  Finish(s);
}

// frustum-cull: fewer draws, the same pixels (culling is conservative).
TEST(SceneFrame, FrustumCullFixDrawsLessAndChangesNoPixel) {
  for (int camera : {1, 2}) {
    Options o = SmallOptions();
    o.camera = camera;
    Sample s;
    if (!Start(s, o)) return;
    const Image original = RenderAndCapture(s, 2);
    const SceneStats before = s.GetScene()->Stats();
    o.fixes.Set(Fix::FrustumCull, true);
    s.ApplySettings(o);
    const Image fixed = RenderAndCapture(s, 2);
    const SceneStats after = s.GetScene()->Stats();
    std::printf("[frustum-cull] camera %d: draws %u (culled %u) -> %u (culled %u)\n", camera, before.drawsIssued,
                before.drawsCulled, after.drawsIssued, after.drawsCulled);
    if (camera == 1) {
      EXPECT_LT(after.drawsIssued, before.drawsIssued);  // t=3: meshes beside the view
    }
    EXPECT_LE(after.drawsIssued, before.drawsIssued);
    EXPECT_EQ(after.drawsIssued + after.drawsCulled, before.drawsIssued + before.drawsCulled);
    EXPECT_EQ(Compare(original, fixed).differing, 0u);
    Finish(s);
  }
}

// camera-eye: specular lighting moves with the viewing camera; from the
// first-person camera (whose eye the original uses anyway) nothing changes.
TEST(SceneFrame, CameraEyeFixChangesSpecularOfSceneCamerasOnly) {
  for (int camera : {0, 2}) {
    Options o = SmallOptions();
    o.camera = camera;
    Sample s;
    if (!Start(s, o)) return;
    const Image original = RenderAndCapture(s, 2);
    o.fixes.Set(Fix::CameraEye, true);
    s.ApplySettings(o);
    const Diff d = Compare(original, RenderAndCapture(s, 2));
    std::printf("[camera-eye] camera %d: %llu px differ (max %d)\n", camera, (unsigned long long)d.differing, d.maxAbs);
    if (camera == 0) EXPECT_EQ(d.differing, 0u);
    else EXPECT_GT(d.differing, 0u);
    Finish(s);
  }
}

// camera-cut: the original's first frame after a camera change has the
// velocity of the jump between the cameras; the fix starts from zero. The
// frame after is the same either way.
TEST(SceneFrame, CameraCutFixRestartsVelocityForOneFrame) {
  Image afterCut[2];
  for (bool fix : {false, true}) {
    Options o = SmallOptions();
    o.camera = 2;
    o.motionBlur = true;          // the velocity target is captured
    o.filter = Filter::Bilinear;  // no TAA history: the frame after the cut depends on that frame only
    o.fixes.Set(Fix::CameraCut, fix);
    Sample s;
    if (!Start(s, o)) return;
    RenderAndCapture(s, 3);
    o.camera = 3;
    s.ApplySettings(o);
    RenderAndCapture(s, 1);
    const float cutVelocity = MaxVelocity(s.CapturedVelocity());
    afterCut[fix] = RenderAndCapture(s, 1);
    const float nextVelocity = MaxVelocity(s.CapturedVelocity());
    std::printf("[camera-cut] fix %d: largest velocity on the cut %.4f, next frame %.4f\n", int(fix), cutVelocity,
                nextVelocity);
    if (fix) EXPECT_EQ(cutVelocity, 0.f);
    else EXPECT_GT(cutVelocity, 0.05f);
    EXPECT_EQ(nextVelocity, 0.f);  // time is fixed: nothing moves
    Finish(s);
  }
  EXPECT_EQ(Compare(afterCut[0], afterCut[1]).differing, 0u);
}

// taa-flip: with dynamic resolution off the original still flips its targets
// for TAA Basic, so a paused scene alternates between its last two frames; the
// fix holds it. With dynamic resolution on the fix changes nothing.
TEST(SceneFrame, TaaFlipFixStopsThePausedFlickerWithDynamicResolutionOff) {
  Image last[2][2];  // [dynamic][fix]
  for (bool dynamic : {false, true})
    for (bool fix : {false, true}) {
      Options o = SmallOptions();
      o.time = 2.0;
      o.fixedDt = 1.0 / 15.0;  // the cinematic camera moves until paused
      o.filter = Filter::TAABasic;
      o.dynamicResolution = dynamic;
      o.fixes.Set(Fix::TaaFlip, fix);
      Sample s;
      if (!Start(s, o)) return;
      RenderAndCapture(s, 4);
      o.pause = true;
      s.ApplySettings(o);
      const Image a = RenderAndCapture(s, 2), b = RenderAndCapture(s, 1);
      last[dynamic][fix] = b;
      const Diff d = Compare(a, b);
      std::printf("[taa-flip] dynamic %d fix %d: consecutive paused frames differ in %llu px\n", int(dynamic),
                  int(fix), (unsigned long long)d.differing);
      if (!dynamic && !fix) EXPECT_GT(d.differing, 0u);
      else EXPECT_EQ(d.differing, 0u);
      Finish(s);
    }
  EXPECT_EQ(Compare(last[1][0], last[1][1]).differing, 0u);
}

// srgb-targets: the colour targets become sRGB (same size), the image changes
// only by 8-bit quantisation.
TEST(SceneFrame, SrgbTargetsFixChangesOnlyTheColourFormat) {
  Image frame[2];
  uint64_t bytes[2] = {};
  for (bool fix : {false, true}) {
    Options o = SmallOptions();
    o.camera = 2;
    o.fixes.Set(Fix::SrgbTargets, fix);
    Sample s;
    if (!Start(s, o)) return;
    frame[fix] = RenderAndCapture(s, 2);
    EXPECT_EQ(s.CapturedSceneColor().format,
              fix ? d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB : d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);
    bytes[fix] = s.RenderTargetBytes();
    Finish(s);
  }
  const Diff d = Compare(frame[0], frame[1]);
  std::printf("[srgb-targets] %llu px differ (max %d)\n", (unsigned long long)d.differing, d.maxAbs);
  EXPECT_EQ(bytes[0], bytes[1]);
  EXPECT_GT(d.differing, 0u);
  EXPECT_LE(d.maxAbs, 16) << "only the quantisation of dark tones may differ";
}

// The original's pause: the matrices freeze with the frame before the pause,
// so the velocity (and the motion blur) stays, and the image is still.
TEST(SceneFrame, PauseFreezesTheFrameWithItsVelocity) {
  Options o = SmallOptions();
  o.fixedDt = 1.0 / 15.0;
  o.motionBlur = true;
  Sample s;
  if (!Start(s, o)) return;
  RenderAndCapture(s, 3);
  const float moving = MaxVelocity(s.CapturedVelocity());
  o.pause = true;
  s.ApplySettings(o);
  const Image a = RenderAndCapture(s, 1);
  const float paused = MaxVelocity(s.CapturedVelocity());
  const Image b = RenderAndCapture(s, 1);
  std::printf("[pause] largest velocity moving %.4f, paused %.4f\n", moving, paused);
  EXPECT_GT(paused, 0.f);
  EXPECT_NEAR(paused, moving, moving * 0.5f);
  EXPECT_EQ(Compare(a, b).differing, 0u);
  Finish(s);
}
