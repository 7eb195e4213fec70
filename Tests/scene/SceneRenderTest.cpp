// GPU tests of the scene renderer (under validation; the fixture asserts zero
// messages): the small Arena from each static camera, matrix convention
// (glm column-major upload + mul(M, v)) and velocity / jitter behaviour.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "RenderTest.h"
#include "imageio/ImageFile.h"
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
    std::string error;
    ASSERT_TRUE(drr::WriteImageFile(file, uint32_t(img.width), uint32_t(img.height), 4, img.pixels.data(), &error))
        << error;
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

// ---------------------------------------------------------------------------
// The original's shading, culling and alpha test on small known models.
namespace {
// A w x 1 RGBA PNG.
void WritePng(const fs::path& file, const std::vector<uint8_t>& rgba) {
  std::string error;
  ASSERT_TRUE(drr::WriteImageFile(file.string(), uint32_t(rgba.size() / 4), 1, 4, rgba.data(), &error)) << error;
}

// A quad of half-size 1 centred at the origin, spanning u and v (its normal
// u x v), UVs 0..1 along u and v, with the material `mtl` of quad.mtl.
void WriteQuad(const fs::path& obj, glm::vec3 u, glm::vec3 v, const std::string& mtl) {
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  std::ofstream f(obj);
  if (!mtl.empty()) f << "mtllib quad.mtl\nusemtl " << mtl << "\n";
  for (glm::vec3 p : {-u - v, u - v, u + v, -u + v}) f << "v " << p.x << " " << p.y << " " << p.z << "\n";
  f << "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn " << n.x << " " << n.y << " " << n.z << "\n";
  f << "f 1/1/1 2/2/1 3/3/1 4/4/1\n";
}

// The original's PSMain for a white texture and a white specular map (no eye:
// no specular map, the original's black.png).
glm::vec3 OriginalShade(glm::vec3 n, glm::vec3 pos, std::optional<glm::vec3> eye) {
  const glm::vec3 toLight = -glm::vec3(0.89f, -0.45f, 0.089f);
  const glm::vec3 diffuse(1.58f, 1.36f, 0.74f), ambient(0.42f, 0.44f, 0.46f), specular(1.30f, 1.18f, 0.78f);
  const float intensity = glm::clamp(glm::dot(n, toLight), 0.f, 1.f);
  glm::vec3 c = glm::clamp(diffuse * intensity, 0.f, 1.f) + ambient;
  if (intensity > 0.f && eye) {
    const glm::vec3 r = glm::normalize(2.f * intensity * n - toLight);
    c += std::pow(glm::clamp(glm::dot(r, glm::normalize(*eye - pos)), 0.f, 1.f), 16.f) * specular;
  }
  return glm::clamp(c, 0.f, 1.f);
}
}  // namespace

TEST_F(SceneRender, ShadingMatchesTheOriginalFormulas) {
  fs::path dir = fs::temp_directory_path() / ("drr_scene_shade_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  WritePng(dir / "white.png", std::vector<uint8_t>(16, 255));
  std::ofstream(dir / "quad.mtl") << "newmtl lit\nKd 1 1 1\nmap_Kd white.png\nmap_Ks white.png\n"
                                  << "newmtl plain\nKd 1 1 1\nmap_Kd white.png\n";
  // Facing the light only a little (N.L = 0.199): no channel saturates.
  const glm::vec3 n(0.f, 0.6f, 0.8f), u(1.f, 0.f, 0.f), v = glm::cross(n, u);
  WriteQuad(dir / "lit.obj", u, v, "lit");
  WriteQuad(dir / "plain.obj", u, v, "plain");
  // The specular eye (the original's first-person eye) where R.V = 0.9 at the centre.
  const glm::vec3 toLight = -glm::vec3(0.89f, -0.45f, 0.089f);
  const glm::vec3 r = glm::normalize(2.f * glm::dot(n, toLight) * n - toLight);
  const glm::vec3 side = glm::normalize(glm::cross(r, glm::vec3(0, 1, 0)));
  const glm::vec3 eye = 10.f * (0.9f * r + std::sqrt(1.f - 0.81f) * side);
  const uint32_t W = 64, H = 64;
  Targets t = Make(W, H);
  t.color = MakeRenderTarget(W, H, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);  // linear values, as the original's targets
  SceneRenderParams p;
  p.view = glm::lookAtRH(5.f * n, glm::vec3(0.f), glm::vec3(0, 1, 0));
  p.proj = glm::perspectiveRH_ZO(glm::radians(60.f), 1.f, 0.1f, 100.f);
  p.shadingEye = eye;
  const glm::mat4 invViewProj = glm::inverse(p.proj * p.view);
  for (const char* model : {"lit.obj", "plain.obj"}) {
    std::string err;
    auto scene = Scene::Load(device(), (dir / model).string(), {}, &err);
    ASSERT_TRUE(scene) << err;
    Begin(t, W, H);
    scene->Render(context(), p);
    drrtest::Image img = ReadBack(t.color.texture.Get());
    int checked = 0, worst = 0;
    for (uint32_t y = 8; y < H - 8; ++y)
      for (uint32_t x = 8; x < W - 8; ++x) {
        // The pixel centre's point on the quad's plane.
        const glm::vec2 ndc((x + 0.5f) / W * 2.f - 1.f, 1.f - (y + 0.5f) / H * 2.f);
        glm::vec4 a = invViewProj * glm::vec4(ndc, 0.f, 1.f), b = invViewProj * glm::vec4(ndc, 1.f, 1.f);
        const glm::vec3 from = glm::vec3(a) / a.w, dir3 = glm::vec3(b) / b.w - from;
        const glm::vec3 pos = from - dir3 * (glm::dot(n, from) / glm::dot(n, dir3));
        if (std::fabs(glm::dot(pos, u)) > 0.9f || std::fabs(glm::dot(pos, v)) > 0.9f) continue;
        const bool lit = std::string(model) == "lit.obj";
        // Without a specular map the original reads black: no specular term.
        const glm::vec3 want = lit ? OriginalShade(n, pos, eye) : OriginalShade(n, pos, std::nullopt);
        const auto got = img.RGBA8(x, y);
        if (x == W / 2 && y == H / 2)
          std::printf("%s centre: got %d %d %d, formula %.1f %.1f %.1f\n", model, got[0], got[1], got[2],
                      want.x * 255, want.y * 255, want.z * 255);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(got[c]) - int(std::lround(want[c] * 255.f))));
        EXPECT_EQ(got[3], 255) << "the original's alpha saturates to 1 on lit surfaces";
        ++checked;
      }
    std::printf("%s: %d pixels against the CPU formula, largest difference %d/255\n", model, checked, worst);
    EXPECT_GT(checked, 300);
    EXPECT_LE(worst, 2);
  }
  fs::remove_all(dir);
}

// The original culls only meshes whose box centre is behind the eye; a mesh
// in front of the eye but outside the frustum is drawn. The frustum-cull fix
// culls it.
TEST_F(SceneRender, CullingAsTheOriginal) {
  fs::path dir = fs::temp_directory_path() / ("drr_scene_cull_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  WriteQuad(dir / "quad.obj", glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), "");
  std::string err;
  auto scene = Scene::Load(device(), (dir / "quad.obj").string(), {}, &err);
  ASSERT_TRUE(scene) << err;
  const uint32_t W = 64, H = 64;
  Targets t = Make(W, H);
  struct Case {
    const char* what;
    glm::vec3 eye;
    uint32_t drawnOriginal, drawnFrustum;
  } cases[] = {{"in view", {0, 0, 5}, 1, 1},
               {"in front, outside the frustum", {50, 0, 5}, 1, 0},
               {"wholly behind the eye", {0, 0, -5}, 0, 0}};
  for (const Case& c : cases)
    for (bool frustum : {false, true}) {
      SceneRenderParams p;
      p.view = glm::lookAtRH(c.eye, c.eye + glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
      p.proj = glm::perspectiveRH_ZO(glm::radians(45.f), 1.f, 0.1f, 100.f);
      p.frustumCulling = frustum;
      Begin(t, W, H);
      scene->Render(context(), p);
      const SceneStats st = scene->Stats();
      EXPECT_EQ(st.drawsIssued, frustum ? c.drawnFrustum : c.drawnOriginal) << c.what << " frustum " << frustum;
      EXPECT_EQ(st.drawsIssued + st.drawsCulled, 1u) << c.what;
    }
  fs::remove_all(dir);
}

// The original discards pixels whose diffuse texel has alpha exactly 0.
TEST_F(SceneRender, AlphaTestDiscardsTransparentTexels) {
  fs::path dir = fs::temp_directory_path() / ("drr_scene_alpha_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::vector<uint8_t> texels;
  for (int i = 0; i < 8; ++i) texels.insert(texels.end(), {255, 255, 255, uint8_t(i < 4 ? 0 : 255)});
  WritePng(dir / "half.png", texels);
  std::ofstream(dir / "quad.mtl") << "newmtl half\nmap_Kd half.png\n";
  WriteQuad(dir / "quad.obj", glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), "half");
  std::string err;
  auto scene = Scene::Load(device(), (dir / "quad.obj").string(), {}, &err);
  ASSERT_TRUE(scene) << err;
  const uint32_t W = 64, H = 64;
  Targets t = Make(W, H);
  SceneRenderParams p;
  p.view = glm::lookAtRH(glm::vec3(0, 0, 2.5f), glm::vec3(0.f), glm::vec3(0, 1, 0));
  p.proj = glm::perspectiveRH_ZO(glm::radians(60.f), 1.f, 0.1f, 100.f);
  Begin(t, W, H);
  scene->Render(context(), p);
  drrtest::Image img = ReadBack(t.color.texture.Get());
  // The quad spans pixels ~12..52; u = 0.25 (alpha 0) near x = 22, u = 0.75 near x = 42.
  auto isClear = [](std::array<uint8_t, 4> c) { return c[0] == 0 && c[1] == 89 && c[2] == 89; };
  EXPECT_TRUE(isClear(img.RGBA8(22, 32))) << "a texel of alpha 0 must be discarded";
  EXPECT_FALSE(isClear(img.RGBA8(42, 32))) << "an opaque texel is drawn";
  fs::remove_all(dir);
}

// A DECAL entry co-planar with a LIT one: drawn (depth LESS_EQUAL), blended by
// its alpha, and its alpha written as the source's, as the original's states.
TEST_F(SceneRender, DecalsBlendAsTheOriginal) {
  fs::path dir = fs::temp_directory_path() / ("drr_scene_decal_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  WritePng(dir / "white.png", std::vector<uint8_t>(16, 255));
  WritePng(dir / "red.png", {255, 0, 0, 128, 255, 0, 0, 128, 255, 0, 0, 128, 255, 0, 0, 128});
  std::ofstream(dir / "quad.mtl") << "newmtl white\nKd 1 1 1\nmap_Kd white.png\nnewmtl red\nKd 1 1 1\nmap_Kd red.png\n";
  // Facing +z, away from the light (N.L < 0): ambient only, and the alpha stays the texture's.
  WriteQuad(dir / "floor.obj", glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), "white");
  WriteQuad(dir / "decal.obj", glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), "red");
  std::ofstream(dir / "scene.txt") << "floor.obj NO_ANIM LIT\ndecal.obj NO_ANIM DECAL\n";
  std::string err;
  auto scene = Scene::Load(device(), (dir / "scene.txt").string(), {}, &err);
  ASSERT_TRUE(scene) << err;
  const uint32_t W = 32, H = 32;
  Targets t = Make(W, H);
  t.color = MakeRenderTarget(W, H, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);
  SceneRenderParams p;
  p.view = glm::lookAtRH(glm::vec3(0, 0, 2.5f), glm::vec3(0.f), glm::vec3(0, 1, 0));
  p.proj = glm::perspectiveRH_ZO(glm::radians(60.f), 1.f, 0.1f, 100.f);
  Begin(t, W, H);
  scene->Render(context(), p);
  const auto got = ReadBack(t.color.texture.Get()).RGBA8(W / 2, H / 2);
  const float a = 128.f / 255.f;
  const glm::vec3 ambient(0.42f, 0.44f, 0.46f);
  const glm::vec3 want = a * ambient * glm::vec3(1, 0, 0) + (1.f - a) * ambient;
  std::printf("decal over floor: got %d %d %d %d, expected %.1f %.1f %.1f %.1f\n", got[0], got[1], got[2], got[3],
              want.x * 255, want.y * 255, want.z * 255, a * 255);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c] * 255.f, 1.01f) << "channel " << c;
  EXPECT_EQ(got[3], 128) << "the decal's alpha is written (ONE, ZERO)";
  fs::remove_all(dir);
}
