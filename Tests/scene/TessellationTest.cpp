// Screen-space adaptive tessellation of the scene (Docs/Tessellation.md),
// under validation (the fixture fails on any message):
// - the Arena's primitives at half the dynamic viewport are at most 0.30 of
//   those at full size with tessellation, and exactly the same without;
// - at the default settings the primitives fall with the scale (the counts
//   that Docs/Tessellation.md's one-budget table reads);
// - a displaced plane of independent patches shows no background inside it
//   (no cracks), and the displacement did change the image;
// - velocity of a Phong-tessellated flat plane equals the untessellated
//   plane's under camera motion, and TAA jitter alone gives none on a
//   displaced one (previous positions go through the same tessellation).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "RenderTest.h"
#include "imageio/ImageFile.h"
#include "scene/Scene.h"
#include "ScratchDir.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {
const float kClear[4] = {1.f, 0.f, 1.f, 1.f};  // magenta: a crack shows it

class SceneTessellation : public drrtest::RenderTest {
 protected:
  void MakeTargets(uint32_t w, uint32_t h) {
    w_ = w;
    h_ = h;
    color_ = MakeRenderTarget(w, h, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);
    velocity_ = MakeRenderTarget(w, h, d3dl::DXGI_FORMAT_R16G16_FLOAT);
    d3dl::TEXTURE2D_DESC dd;
    dd.Width = w;
    dd.Height = h;
    dd.Format = d3dl::DXGI_FORMAT_D32_FLOAT;
    dd.BindFlags = d3dl::BIND_DEPTH_STENCIL;
    ASSERT_EQ(device()->CreateTexture2D(&dd, nullptr, depth_.ReleaseAndGetAddressOf()), d3dl::S_OK);
    ASSERT_EQ(device()->CreateDepthStencilView(depth_.Get(), nullptr, dsv_.ReleaseAndGetAddressOf()), d3dl::S_OK);
  }
  // Clears the targets and sets the dynamic viewport: scale x the target, top left.
  void Begin(float scale) {
    const float zero[4] = {};
    context()->ClearRenderTargetView(color_.rtv.Get(), kClear);
    context()->ClearRenderTargetView(velocity_.rtv.Get(), zero);
    context()->ClearDepthStencilView(dsv_.Get(), d3dl::CLEAR_DEPTH, 1.f, 0);
    d3dl::RenderTargetView* rtvs[2] = {color_.rtv.Get(), velocity_.rtv.Get()};
    context()->OMSetRenderTargets(2, rtvs, dsv_.Get());
    const d3dl::VIEWPORT vp{0, 0, float(w_) * scale, float(h_) * scale, 0, 1};
    context()->RSSetViewports(1, &vp);
  }
  // Renders with the statistics query around Scene::Render.
  d3dl::QUERY_DATA_PIPELINE_STATISTICS Render(Scene& scene, SceneRenderParams p, float scale) {
    d3dl::QUERY_DESC qd;
    qd.Query = d3dl::QUERY_PIPELINE_STATISTICS;
    d3dl::ComPtr<d3dl::Query> q;
    EXPECT_EQ(device()->CreateQuery(&qd, q.ReleaseAndGetAddressOf()), d3dl::S_OK);
    d3dl::QUERY_DATA_PIPELINE_STATISTICS s{};
    if (!q) return s;
    Begin(scale);
    p.tessellation.viewportHeight = float(h_) * scale;
    context()->Begin(q.Get());
    scene.Render(context(), p);
    context()->End(q.Get());
    d3dl::HRESULT hr;
    while ((hr = context()->GetData(q.Get(), &s, sizeof(s), 0)) == d3dl::S_FALSE) {
    }
    EXPECT_EQ(hr, d3dl::S_OK);
    return s;
  }
  uint32_t w_ = 0, h_ = 0;
  drrtest::RenderTarget color_, velocity_;
  d3dl::ComPtr<d3dl::Texture2D> depth_;
  d3dl::ComPtr<d3dl::DepthStencilView> dsv_;
};

SceneRenderParams ParamsFor(const CameraPose& pose, float aspect, bool tessellate) {
  SceneRenderParams p;
  p.view = pose.view;
  p.proj = glm::perspectiveRH_ZO(pose.fovY, aspect, pose.nearZ, pose.farZ);
  p.resetHistory = true;
  p.tessellation.enabled = tessellate;
  return p;
}

void WriteRgba(const fs::path& file, int size, const std::vector<uint8_t>& px) {
  std::string error;
  ASSERT_TRUE(drr::WriteImageFile(file.string(), uint32_t(size), uint32_t(size), 4, px.data(), &error)) << error;
}

// A square plane in y = 0 of n x n quads, each with its own four vertices
// (so every patch edge is shared by two independently evaluated patches),
// texture coordinates 0..1 over the whole plane; and a height map of
// independent random texels (the steepest relief).
void WritePlane(const fs::path& dir, int n, float size) {
  std::ofstream obj(dir / "plane.obj");
  obj << "mtllib plane.mtl\nusemtl Checker\nvn 0 1 0\n";
  std::ofstream(dir / "plane.mtl") << "newmtl Checker\nKd 1 1 1\nmap_Kd checker.png\n";
  int v = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
      for (const auto& c : corner) {
        obj << "v " << (c[0] * size / n - size / 2) << " 0 " << (size / 2 - c[1] * size / n) << "\n";
        obj << "vt " << float(c[0]) / n << " " << float(c[1]) / n << "\n";
      }
      obj << "f " << v + 1 << "/" << v + 1 << "/1 " << v + 2 << "/" << v + 2 << "/1 " << v + 3 << "/" << v + 3
          << "/1 " << v + 4 << "/" << v + 4 << "/1\n";
      v += 4;
    }
  const int T = 64;
  std::vector<uint8_t> height(T * T * 4, 255), checker(T * T * 4, 255);
  std::mt19937 rng(5);
  for (int k = 0; k < T * T; ++k) {
    height[k * 4] = height[k * 4 + 1] = height[k * 4 + 2] = uint8_t(rng() & 0xff);
    const bool dark = ((k % T) / 4 + (k / T) / 4) & 1;  // 4-texel squares: the displacement moves them on screen
    checker[k * 4] = checker[k * 4 + 1] = checker[k * 4 + 2] = dark ? 40 : 220;
  }
  WriteRgba(dir / "height.png", T, height);
  WriteRgba(dir / "checker.png", T, checker);
}

fs::path PlaneScene(const std::string& name, const std::string& rules) {
  const fs::path dir = drrtest::ProcessScratchDir() / name;
  fs::create_directories(dir);
  WritePlane(dir, 8, 100.f);
  std::ofstream(dir / "scene.txt") << "plane.obj NO_ANIM LIT " << rules << "\n";
  return dir / "scene.txt";
}

CameraPose Overhead(float height, float back) {
  CameraPose c;
  const glm::vec3 eye(0.f, height, back);
  c.view = glm::lookAtRH(eye, glm::vec3(0.f), glm::vec3(0, 1, 0));
  c.position = eye;
  c.nearZ = 1.f;
  c.farZ = 1000.f;
  return c;
}

bool IsClear(const std::array<uint8_t, 4>& c) { return c[0] == 255 && c[1] == 0 && c[2] == 255; }
}  // namespace

// The counts at the default settings (8 pixels per edge, max factor 16), on
// the static camera and on the cinematic one at 1 s, for Docs/Tessellation.md
// (scripts/tessellation-tables.py reads the "counts" lines). Without
// tessellation nothing depends on the scale; with it the primitives fall with it.
TEST_F(SceneTessellation, ArenaCountsAtTheDefaultSettings) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_DIR "/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  MakeTargets(320, 180);
  scene->Update(1.0);
  const SceneRenderParams defaults;
  for (int camera : {0, 1}) {  // the scene's cinematic camera, camera_static1
    for (bool tess : {false, true}) {
      SceneRenderParams p = ParamsFor(scene->Camera(camera), 320.f / 180.f, tess);
      ASSERT_EQ(p.tessellation.pixelsPerEdge, defaults.tessellation.pixelsPerEdge);
      uint64_t full = 0;
      for (float scale : {1.0f, 0.71f, 0.5f}) {
        const auto s = Render(*scene, p, scale);
        std::printf("counts camera %d tessellation %d px/edge %g max %g scale %.2f primitives %llu hs %llu ds %llu\n",
                    camera, int(tess), p.tessellation.pixelsPerEdge, p.tessellation.maxFactor, scale,
                    (unsigned long long)s.CInvocations, (unsigned long long)s.HSInvocations,
                    (unsigned long long)s.DSInvocations);
        if (scale == 1.0f) full = s.CInvocations;
        if (!tess) {
          EXPECT_EQ(s.CInvocations, full);
          EXPECT_EQ(s.HSInvocations, 0u);
        } else if (scale < 1.0f) {
          EXPECT_LT(s.CInvocations, full) << "the factors follow the dynamic viewport";
        }
      }
    }
  }
}

TEST_F(SceneTessellation, ArenaPrimitivesFollowTheDynamicViewport) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_DIR "/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  EXPECT_TRUE(scene->Warnings().empty()) << scene->Warnings().front();
  MakeTargets(320, 180);
  scene->Update(1.0);
  const CameraPose pose = scene->Camera(1);  // camera_static1, over the floor towards the bell
  for (bool tess : {false, true}) {
    SceneRenderParams p = ParamsFor(pose, 320.f / 180.f, tess);
    p.tessellation.pixelsPerEdge = 1.f;
    p.tessellation.maxFactor = 64.f;
    const auto full = Render(*scene, p, 1.f);
    const SceneStats st = scene->Stats();
    const auto half = Render(*scene, p, 0.5f);
    const double ratio = double(half.CInvocations) / double(full.CInvocations);
    std::printf("tessellation %s: primitives %llu at scale 1.0, %llu at 0.5 (ratio %.3f); DS invocations %llu / %llu; %s\n",
                tess ? "on" : "off", (unsigned long long)full.CInvocations, (unsigned long long)half.CInvocations, ratio,
                (unsigned long long)full.DSInvocations, (unsigned long long)half.DSInvocations, st.ToString().c_str());
    if (!tess) {
      EXPECT_EQ(half.CInvocations, full.CInvocations) << "without tessellation the geometry does not follow the scale";
      EXPECT_EQ(full.HSInvocations, 0u);
      EXPECT_EQ(st.tessellatedDraws, 0u);
    } else {
      EXPECT_GT(st.tessellatedDraws, 0u);
      EXPECT_GT(full.DSInvocations, 0u);
      EXPECT_LE(ratio, 0.30);
      // Half the viewport is the same work as twice the pixels per edge: the
      // factors follow the dynamic viewport, not the render target.
      p.tessellation.pixelsPerEdge = 2.f;
      EXPECT_EQ(Render(*scene, p, 1.f).CInvocations, half.CInvocations);
    }
  }
}

TEST_F(SceneTessellation, DisplacedPlaneHasNoCracks) {
  std::string err;
  auto scene = Scene::Load(device(), PlaneScene("cracks", "tessellate=displace displacement=height.png relief=6").string(),
                           {}, &err);
  ASSERT_TRUE(scene) << err;
  MakeTargets(256, 256);
  const CameraPose pose = Overhead(70.f, 45.f);
  SceneRenderParams p = ParamsFor(pose, 1.f, false);
  Render(*scene, p, 1.f);
  const drrtest::Image flat = ReadBack(color_.texture.Get());
  p.tessellation.enabled = true;
  p.tessellation.pixelsPerEdge = 3.f;
  p.tessellation.maxFactor = 24.f;
  const auto stats = Render(*scene, p, 1.f);
  const drrtest::Image img = ReadBack(color_.texture.Get());
  EXPECT_EQ(stats.HSInvocations, 128u) << "8 x 8 quads, two patches each";
  EXPECT_GT(stats.CInvocations, 128u * 20) << "the patches were subdivided";
  // The plane's inside on screen: where its inset corners project.
  const glm::mat4 vp = p.proj * p.view;
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (float x : {-44.f, 44.f})
    for (float z : {-44.f, 44.f}) {
      const glm::vec4 c = vp * glm::vec4(x, -6.f, z, 1.f);
      const glm::vec2 s((c.x / c.w * 0.5f + 0.5f) * 256.f, (0.5f - c.y / c.w * 0.5f) * 256.f);
      lo = glm::min(lo, s);
      hi = glm::max(hi, s);
    }
  size_t inside = 0, background = 0, changed = 0;
  for (uint32_t y = 0; y < 256; ++y)
    for (uint32_t x = 0; x < 256; ++x) {
      changed += img.RGBA8(x, y) != flat.RGBA8(x, y);
      // A trapezoid in perspective: take the box of the inset corners at the
      // far edge's width, which lies inside the plane for every row.
      if (x < lo.x + 0.25f * (hi.x - lo.x) || x > hi.x - 0.25f * (hi.x - lo.x) || y < lo.y || y > hi.y) continue;
      ++inside;
      background += IsClear(img.RGBA8(x, y));
      EXPECT_FALSE(IsClear(flat.RGBA8(x, y))) << "the flat plane covers " << x << "," << y;
    }
  std::printf("inside %zu pixels, background %zu, changed by displacement %zu\n", inside, background, changed);
  EXPECT_GT(inside, 256u * 256u / 10);
  EXPECT_EQ(background, 0u) << "background inside the displaced plane: a crack";
  EXPECT_GT(changed, inside / 4) << "the displacement should show";
}

TEST_F(SceneTessellation, VelocityGoesThroughTheSameTessellation) {
  std::string err;
  auto phong = Scene::Load(device(), PlaneScene("phong", "tessellate=phong").string(), {}, &err);
  ASSERT_TRUE(phong) << err;
  MakeTargets(128, 128);
  const CameraPose a = Overhead(70.f, 45.f), b = Overhead(68.f, 50.f);
  // Two frames: camera a then b; the second frame's velocity is compared.
  auto velocityOf = [&](Scene& scene, bool tess, glm::vec2 jitter0, glm::vec2 jitter1, const CameraPose& second) {
    SceneRenderParams p = ParamsFor(a, 1.f, tess);
    p.tessellation.pixelsPerEdge = 3.f;
    p.jitterNdc = jitter0;
    Render(scene, p, 1.f);
    p.view = second.view;
    p.resetHistory = false;
    p.jitterNdc = jitter1;
    Render(scene, p, 1.f);
    return ReadBack(velocity_.texture.Get());
  };
  const drrtest::Image plain = velocityOf(*phong, false, {}, {}, b);
  const drrtest::Image tessellated = velocityOf(*phong, true, {}, {}, b);
  size_t moving = 0;
  float worst = 0.f;
  for (uint32_t y = 8; y < 120; ++y)
    for (uint32_t x = 8; x < 120; ++x) {
      const glm::vec2 v0(plain.Float(x, y, 0), plain.Float(x, y, 1)), v1(tessellated.Float(x, y, 0), tessellated.Float(x, y, 1));
      if (glm::length(v0) == 0.f || glm::length(v1) == 0.f) continue;  // off the plane in one of them
      ++moving;
      worst = std::max(worst, glm::length(v0 - v1));
    }
  std::printf("velocity: %zu moving pixels, largest difference %.2e\n", moving, worst);
  EXPECT_GT(moving, 128u * 128u / 4);
  EXPECT_LT(worst, 2e-3f) << "the tessellated plane's velocity differs from the plain one's";

  auto displaced = Scene::Load(device(), PlaneScene("jitter", "tessellate=displace displacement=height.png relief=6").string(),
                               {}, &err);
  ASSERT_TRUE(displaced) << err;
  const drrtest::Image still = velocityOf(*displaced, true, {0.f, 0.f}, {1.f / 128, -1.f / 128}, a);
  float largest = 0.f;
  for (uint32_t y = 0; y < 128; ++y)
    for (uint32_t x = 0; x < 128; ++x)
      largest = std::max(largest, glm::length(glm::vec2(still.Float(x, y, 0), still.Float(x, y, 1))));
  EXPECT_LT(largest, 1e-4f) << "jitter alone must not show as velocity on a displaced surface";
}

// The hull shader culls patches facing away (factor 0), but not those near
// the silhouette: seen from below the plane draws nothing; seen from just
// below its edge, at a grazing angle, it keeps its subdivided patches.
TEST_F(SceneTessellation, BackFacingPatchesAreCulledSilhouettesKept) {
  std::string err;
  auto scene = Scene::Load(device(), PlaneScene("cull", "tessellate=phong").string(), {}, &err);
  ASSERT_TRUE(scene) << err;
  MakeTargets(128, 128);
  SceneRenderParams p = ParamsFor(Overhead(-70.f, 45.f), 1.f, false);
  p.tessellation.pixelsPerEdge = 2.f;
  EXPECT_EQ(Render(*scene, p, 1.f).CInvocations, 128u) << "untessellated: the clipper sees every triangle";
  p.tessellation.enabled = true;
  const auto below = Render(*scene, p, 1.f);
  EXPECT_EQ(below.HSInvocations, 128u);
  EXPECT_EQ(below.CInvocations, 0u) << "every patch faces away";
  const CameraPose grazing = Overhead(-4.f, 120.f);  // about 2 degrees below the plane
  p.view = grazing.view;
  const auto edge = Render(*scene, p, 1.f);
  std::printf("grazing from below: %llu primitives from 128 patches\n", (unsigned long long)edge.CInvocations);
  EXPECT_GT(edge.CInvocations, 128u) << "patches at the silhouette keep their factors";
}
