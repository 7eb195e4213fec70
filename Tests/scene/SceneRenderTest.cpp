// GPU tests of the scene renderer (under validation; the fixture asserts zero
// messages): the small Arena from each static camera, matrix convention
// (glm column-major upload + mul(M, v)) and velocity / jitter behaviour.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <OpenImageIO/imageio.h>
#include <glm/gtc/matrix_transform.hpp>

#include "RenderTest.h"
#include "scene/Scene.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {
struct Targets {
  drrtest::RenderTarget color, velocity;
  d3dl::ComPtr<d3dl::Texture2D> depth;
  d3dl::ComPtr<d3dl::DepthStencilView> dsv;
};

class SceneRender : public drrtest::RenderTest {
 protected:
  Targets Make(uint32_t w, uint32_t h) {
    Targets t;
    t.color = MakeRenderTarget(w, h, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB);
    t.velocity = MakeRenderTarget(w, h, d3dl::DXGI_FORMAT_R16G16_FLOAT);
    d3dl::TEXTURE2D_DESC dd;
    dd.Width = w;
    dd.Height = h;
    dd.Format = d3dl::DXGI_FORMAT_D32_FLOAT;
    dd.BindFlags = d3dl::BIND_DEPTH_STENCIL;
    EXPECT_EQ(device()->CreateTexture2D(&dd, nullptr, t.depth.GetAddressOf()), d3dl::S_OK);
    EXPECT_EQ(device()->CreateDepthStencilView(t.depth.Get(), nullptr, t.dsv.GetAddressOf()), d3dl::S_OK);
    return t;
  }
  void Begin(Targets& t, uint32_t w, uint32_t h) {
    const float clear[4] = {0.f, 0.1f, 0.1f, 1.f}, zero[4] = {};
    context()->ClearRenderTargetView(t.color.rtv.Get(), clear);
    context()->ClearRenderTargetView(t.velocity.rtv.Get(), zero);
    context()->ClearDepthStencilView(t.dsv.Get(), d3dl::CLEAR_DEPTH, 1.f, 0);
    d3dl::RenderTargetView* rtvs[2] = {t.color.rtv.Get(), t.velocity.rtv.Get()};
    context()->OMSetRenderTargets(2, rtvs, t.dsv.Get());
    SetViewport(w, h);
  }
  static void SavePng(const std::string& file, const drrtest::Image& img) {
    auto out = OIIO::ImageOutput::create(file);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(file, spec));
    out->write_image(OIIO::TypeDesc::UINT8, img.pixels.data());
    out->close();
  }
  static std::string ShaderDirForScene() { return ""; }  // the build's shader folder
};

glm::mat4 Proj(float aspect, const CameraPose& c) { return glm::perspectiveRH_ZO(c.fovY, aspect, c.nearZ, c.farZ); }
}  // namespace

TEST_F(SceneRender, ArenaFromEachStaticCamera) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_DIR "/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  EXPECT_TRUE(scene->Warnings().empty()) << scene->Warnings().front();
  ASSERT_EQ(scene->CameraCount(), 3);
  EXPECT_EQ(scene->CameraName(0), "camera_cinematic");  // CAMERA entries in file order, named by file
  const uint32_t W = 640, H = 360;
  Targets t = Make(W, H);
  scene->Update(1.0);
  for (int cam : {1, 2}) {
    CameraPose pose = scene->Camera(cam);
    SceneRenderParams p;
    p.view = pose.view;
    p.proj = Proj(float(W) / H, pose);
    p.resetHistory = true;
    Begin(t, W, H);
    scene->Render(context(), p);
    SceneStats st = scene->Stats();
    drrtest::Image img = ReadBack(t.color.texture.Get());
    drrtest::Image vel = ReadBack(t.velocity.texture.Get());
    double sum[3] = {0, 0, 0};
    size_t clearPx = 0, nanVel = 0;
    std::array<uint8_t, 4> first = img.RGBA8(0, 0);
    bool single = true;
    for (uint32_t y = 0; y < H; ++y)
      for (uint32_t x = 0; x < W; ++x) {
        auto c = img.RGBA8(x, y);
        for (int k = 0; k < 3; ++k) sum[k] += c[k];
        single &= c == first;
        clearPx += (c[0] == 0 && c[1] == 89 && c[2] == 89);  // 0.1 linear -> 89 sRGB
        float vx = vel.Float(x, y, 0), vy = vel.Float(x, y, 1);
        nanVel += !std::isfinite(vx) || !std::isfinite(vy) || std::fabs(vx) > 1e-3f || std::fabs(vy) > 1e-3f;
      }
    double n = double(W) * H;
    std::printf("camera %d (%s): mean colour (%.1f, %.1f, %.1f), clear pixels %.2f%%, %s\n", cam,
                scene->CameraName(cam).c_str(), sum[0] / n, sum[1] / n, sum[2] / n, 100.0 * clearPx / n,
                st.ToString().c_str());
    std::string png = std::string(DRR_SCENE_TEST_OUT) + "/arena_camera" + std::to_string(cam) + ".png";
    SavePng(png, img);
    EXPECT_FALSE(single);
    EXPECT_EQ(nanVel, 0u) << "velocity must be finite and ~0 with resetHistory and no motion";
    EXPECT_LT(clearPx, size_t(n * 0.01)) << "the sky dome should cover the background";
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(sum[k] / n, 20.0);
      EXPECT_LT(sum[k] / n, 235.0);
    }
    EXPECT_GT(st.drawsIssued, 10u);
    EXPECT_GE(st.shaderVariantsUsed, 3u);
    EXPECT_LE(st.shaderVariantsUsed, 4u);
    EXPECT_EQ(st.texturesLoaded, 15u);
  }
}

// A quad in the upper-right of the view must land in the upper-right of the
// image (checks the column-major upload / mul(M, v) convention and +Y up),
// and camera motion gives velocity of the expected sign; jitter does not.
TEST_F(SceneRender, MatrixConventionVelocityAndJitter) {
  fs::path dir = fs::temp_directory_path() / ("drr_scene_quad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "quad.obj") << "v 1 0.5 0\nv 2 0.5 0\nv 2 1.5 0\nv 1 1.5 0\nvn 0 0 1\nvt 0 0\n"
                                     "f 1/1/1 2/1/1 3/1/1 4/1/1\n";
  std::string err;
  auto scene = Scene::Load(device(), (dir / "quad.obj").string(), {}, &err);
  ASSERT_TRUE(scene) << err;
  const uint32_t W = 128, H = 128;
  Targets t = Make(W, H);
  SceneRenderParams p;
  p.view = glm::lookAtRH(glm::vec3(0, 0, 5), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
  p.proj = glm::perspectiveRH_ZO(glm::radians(90.f), 1.f, 0.1f, 100.f);
  p.resetHistory = true;
  Begin(t, W, H);
  scene->Render(context(), p);
  drrtest::Image img = ReadBack(t.color.texture.Get());
  // Expected: x from 1/5 to 2/5 of NDC -> pixels 76.8..89.6; y from 0.1 to 0.3 up -> rows 44.8..57.6.
  int inside = 0, outside = 0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      auto c = img.RGBA8(x, y);
      bool drawn = !(c[0] == 0 && c[1] == 89 && c[2] == 89);
      bool expected = x >= 77 && x <= 89 && y >= 45 && y <= 57;
      bool border = x >= 76 && x <= 90 && y >= 44 && y <= 58;
      if (drawn && expected) ++inside;
      if (drawn && !border) ++outside;
    }
  EXPECT_GT(inside, 13 * 13 - 5);
  EXPECT_EQ(outside, 0);
  // Camera moves right by 0.1: the quad moves left on screen -> velocity.x < 0 (UV units), y ~ 0.
  p.resetHistory = false;
  p.view = glm::lookAtRH(glm::vec3(0.1f, 0, 5), glm::vec3(0.1f, 0, 0), glm::vec3(0, 1, 0));
  Begin(t, W, H);
  scene->Render(context(), p);
  drrtest::Image vel = ReadBack(t.velocity.texture.Get());
  float vx = vel.Float(83, 51, 0), vy = vel.Float(83, 51, 1);
  EXPECT_NEAR(vx, -0.1f / 5.f * 0.5f, 2e-3f);  // NDC shift 0.02 -> 0.01 in UV
  EXPECT_NEAR(vy, 0.f, 1e-3f);
  // Same camera again, with jitter: the jitter must not show in the velocity.
  p.jitterNdc = glm::vec2(0.013f, -0.021f);
  Begin(t, W, H);
  scene->Render(context(), p);
  vel = ReadBack(t.velocity.texture.Get());
  EXPECT_NEAR(vel.Float(83, 51, 0), 0.f, 1e-3f);
  EXPECT_NEAR(vel.Float(83, 51, 1), 0.f, 1e-3f);
  // Without the velocity output (RT1 unbound).
  p.writeVelocity = false;
  const float clear[4] = {0.f, 0.1f, 0.1f, 1.f};
  context()->ClearRenderTargetView(t.color.rtv.Get(), clear);
  context()->ClearDepthStencilView(t.dsv.Get(), d3dl::CLEAR_DEPTH, 1.f, 0);
  d3dl::RenderTargetView* rtv = t.color.rtv.Get();
  context()->OMSetRenderTargets(1, &rtv, t.dsv.Get());
  scene->Render(context(), p);
  img = ReadBack(t.color.texture.Get());
  auto c = img.RGBA8(83, 51);
  EXPECT_FALSE(c[0] == 0 && c[1] == 89 && c[2] == 89);
  EXPECT_EQ(scene->Stats().shaderVariantsUsed, 2u);
  // F4: recompile SceneShaders.hlsl at run time and draw with the new code.
  drr::ShaderLibrary lib;
  lib.Open(drr::ShaderLibrary::DefaultSpvDir({}), drr::ShaderLibrary::DefaultSourceDir());
  std::vector<uint32_t> spirv;
  bool compiled = false;
  ASSERT_TRUE(lib.Load("scene_ps_n0_s0_v0", true, &spirv, &err, &compiled)) << err;
  EXPECT_TRUE(compiled) << "the manifest should name SceneShaders.hlsl";
  ASSERT_TRUE(scene->ReloadShaders(lib, true, &err)) << err;
  context()->ClearRenderTargetView(t.color.rtv.Get(), clear);
  context()->ClearDepthStencilView(t.dsv.Get(), d3dl::CLEAR_DEPTH, 1.f, 0);
  scene->Render(context(), p);
  img = ReadBack(t.color.texture.Get());
  EXPECT_EQ(img.RGBA8(83, 51), c);
  fs::remove_all(dir);
}
