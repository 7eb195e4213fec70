// The generator's SDKMESH set (tools/ArenaGenSdkMesh.h) drawn through the
// scene renderer under validation: its description in the original's form
// loads, the CAMERA entry gives the camera, missing textures are named once
// each, front faces survive culling (the plate and the pendulum face the
// camera), and the animation moves the picture.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "ArenaGenSdkMesh.h"
#include "RenderTest.h"
#include "imageio/ImageFile.h"
#include "scene/Scene.h"

using namespace drr;

namespace {

class SdkMeshRender : public drrtest::RenderTest {
 protected:
  // Renders the scene at time t from its first camera; returns the colour image.
  drrtest::Image RenderAt(Scene& scene, double t, uint32_t w, uint32_t h) {
    drrtest::RenderTarget color = MakeRenderTarget(w, h, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB);
    drrtest::RenderTarget velocity = MakeRenderTarget(w, h, d3dl::DXGI_FORMAT_R16G16_FLOAT);
    const drrtest::DepthTarget depth = MakeDepthTarget(w, h);
    const float clear[4] = {0.f, 0.f, 0.f, 1.f}, zero[4] = {};
    context()->ClearRenderTargetView(color.rtv.Get(), clear);
    context()->ClearRenderTargetView(velocity.rtv.Get(), zero);
    context()->ClearDepthStencilView(depth.dsv.Get(), d3dl::CLEAR_DEPTH, 1.f, 0);
    d3dl::RenderTargetView* rtvs[2] = {color.rtv.Get(), velocity.rtv.Get()};
    context()->OMSetRenderTargets(2, rtvs, depth.dsv.Get());
    SetViewport(w, h);
    scene.Update(t);
    const CameraPose pose = scene.Camera(0);
    SceneRenderParams p;
    p.view = pose.view;
    p.proj = glm::perspectiveRH_ZO(pose.fovY, float(w) / float(h), pose.nearZ, pose.farZ);
    p.resetHistory = true;
    scene.Render(context(), p);
    return ReadBack(color.texture.Get());
  }
};

size_t DrawnPixels(const drrtest::Image& img) {
  size_t n = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const auto c = img.RGBA8(x, y);
      n += c[0] || c[1] || c[2];
    }
  return n;
}

void SavePng(const std::string& file, const drrtest::Image& img) {
  std::string error;
  ASSERT_TRUE(drr::WriteImageFile(file, uint32_t(img.width), uint32_t(img.height), 4, img.pixels.data(), &error))
      << error;
}

}  // namespace

TEST_F(SdkMeshRender, GeneratedSetDrawsAndMoves) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_DIR "/sdkmesh/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  ASSERT_EQ(scene->CameraCount(), 1);
  EXPECT_EQ(scene->CameraName(0), "sdkcam");
  size_t missingDiffuse = 0;
  for (const std::string& w : scene->Warnings()) missingDiffuse += w.find("sdk_missing.dds") != std::string::npos;
  EXPECT_EQ(missingDiffuse, 1u);
  // The camera frame's scale of 10 moves the clip planes as the original's inverted world matrix does.
  EXPECT_FLOAT_EQ(scene->Camera(0).nearZ, 200.f);
  const uint32_t W = 320, H = 180;
  const drrtest::Image still = RenderAt(*scene, 0.0, W, H);
  const drrtest::Image later = RenderAt(*scene, 1.0, W, H);
  SavePng(std::string(DRR_SCENE_TEST_OUT) + "/sdkmesh_t0.png", still);
  SavePng(std::string(DRR_SCENE_TEST_OUT) + "/sdkmesh_t1.png", later);
  // With the winding reversed the plate, the pendulum and the triangle would all be culled.
  EXPECT_GT(DrawnPixels(still), size_t(W * H / 200)) << "front faces must face the camera";
  size_t differing = 0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) differing += still.RGBA8(x, y) != later.RGBA8(x, y);
  EXPECT_GT(differing, size_t(W * H / 100)) << "the pendulum swings and the camera moves";
}
