// The generated Arena (small) loads through the same Assimp / OpenImageIO path
// as any model: expected entries, textures, cameras; animation and the
// cinematic camera path are finite and smooth over a whole loop at 60 Hz.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_access.hpp>

#include "scene/ModelLoader.h"
#include "scene/SceneDescription.h"

using namespace drr;

namespace {
const std::string kArena = DRR_ARENA_DIR "/scene_description.txt";

struct Loaded {
  SceneDescription desc;
  std::vector<ModelData> models;
};
const Loaded& Arena() {
  static Loaded l = [] {
    Loaded r;
    std::string err;
    EXPECT_TRUE(LoadSceneDescription(kArena, {}, &r.desc, &err)) << err;
    for (const auto& e : r.desc.entries) {
      ModelData m;
      EXPECT_TRUE(LoadModel(e.meshFile, {}, &m, &err)) << err;
      r.models.push_back(std::move(m));
    }
    return r;
  }();
  return l;
}
float AngleBetween(const glm::mat3& a, const glm::mat3& b) {
  glm::quat qa = glm::quat_cast(a), qb = glm::quat_cast(b);
  float d = std::min(1.f, std::fabs(glm::dot(glm::normalize(qa), glm::normalize(qb))));
  return 2.f * std::acos(d);
}
}  // namespace

TEST(Arena, EntriesInTheOriginalsForm) {
  const auto& a = Arena();
  ASSERT_EQ(a.desc.entries.size(), 7u);
  int lit = 0, unlit = 0, cam = 0, decal = 0, anim = 0;
  for (const auto& e : a.desc.entries) {
    lit += e.type == EntryType::Lit;
    unlit += e.type == EntryType::Unlit;
    cam += e.type == EntryType::Camera;
    decal += e.type == EntryType::Decal;
    anim += !e.animFile.empty();
  }
  EXPECT_EQ(lit, 2);
  EXPECT_EQ(unlit, 1);
  EXPECT_EQ(cam, 3);
  EXPECT_EQ(decal, 1);
  EXPECT_EQ(anim, 2);  // bell and cinematic camera
}

TEST(Arena, ModelsTexturesAndCounts) {
  const auto& a = Arena();
  ASSERT_EQ(a.models.size(), 7u);
  uint64_t tris = 0;
  int cameras = 0, animations = 0;
  TextureCache cache;
  std::vector<std::string> warnings;
  for (const auto& m : a.models) {
    tris += m.Triangles();
    cameras += int(m.cameras.size());
    animations += int(m.animations.size());
    EXPECT_TRUE(m.warnings.empty()) << m.file << ": " << m.warnings.front();
    for (const auto& mat : m.materials) {
      if (!mat.diffuseTex.empty()) cache.Get(m, mat.diffuseTex, TextureKind::Color, &warnings);
      if (!mat.normalTex.empty()) cache.Get(m, mat.normalTex, TextureKind::Normal, &warnings);
      if (!mat.specularTex.empty()) cache.Get(m, mat.specularTex, TextureKind::Specular, &warnings);
    }
    for (const auto& mesh : m.meshes) EXPECT_TRUE(mesh.Use16BitIndices());
  }
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_GT(tris, 40000u);
  EXPECT_LT(tris, 70000u);  // "small": about 50k
  EXPECT_EQ(cameras, 3);
  EXPECT_EQ(animations, 2);
  EXPECT_EQ(cache.LoadedCount(), 15u);  // 5 materials x (d, n, s) minus 2 + sky + decal ...
  const auto& arena = a.models[0];
  glm::vec3 mn, mx;
  arena.Bounds(&mn, &mx);
  EXPECT_GT(mx.x - mn.x, 3000.f);  // a few thousand units across
  EXPECT_LT(mx.x - mn.x, 10000.f);
  // Materials: the lit arena uses normal + specular maps, rock only normal, bronze only specular.
  int withBoth = 0, normalOnly = 0, specOnly = 0;
  for (const auto& m : a.models)
    for (const auto& mat : m.materials) {
      withBoth += !mat.normalTex.empty() && !mat.specularTex.empty();
      normalOnly += !mat.normalTex.empty() && mat.specularTex.empty();
      specOnly += mat.normalTex.empty() && !mat.specularTex.empty();
    }
  EXPECT_EQ(withBoth, 3);
  EXPECT_EQ(normalOnly, 1);
  EXPECT_EQ(specOnly, 1);
  EXPECT_TRUE(a.models[3].materials[0].alphaBlend);  // decals
}

// Walks a loop at 60 Hz (and across the wrap-around) and bounds the per-frame change.
static void CheckSmoothLoop(const ModelData& m, int node, float maxStep, float maxAngleDeg, float* maxSeenStep,
                            float* maxSeenAngle) {
  const double period = m.AnimationDuration();
  ASSERT_GT(period, 0.0);
  const int frames = int(std::ceil(period * 60.0)) + 60;  // one loop plus one second past the wrap
  std::vector<glm::mat4> g, prev;
  *maxSeenStep = 0;
  *maxSeenAngle = 0;
  for (int f = 0; f <= frames; ++f) {
    m.Evaluate(f / 60.0, &g);
    const glm::mat4& w = g[node];
    for (int k = 0; k < 16; ++k) ASSERT_TRUE(std::isfinite(w[k / 4][k % 4])) << "frame " << f;
    if (!prev.empty()) {
      float step = glm::length(glm::vec3(w[3]) - glm::vec3(prev[node][3]));
      float ang = glm::degrees(AngleBetween(glm::mat3(w), glm::mat3(prev[node])));
      *maxSeenStep = std::max(*maxSeenStep, step);
      *maxSeenAngle = std::max(*maxSeenAngle, ang);
      EXPECT_LE(step, maxStep) << "frame " << f << " t=" << f / 60.0;
      EXPECT_LE(ang, maxAngleDeg) << "frame " << f << " t=" << f / 60.0;
    }
    prev = g;
  }
}

TEST(Arena, CinematicCameraPathIsSmoothAndLoops) {
  const auto& m = Arena().models[4];
  ASSERT_EQ(m.cameras.size(), 1u);
  int node = m.cameras[0].node;
  ASSERT_GE(node, 0);
  EXPECT_NEAR(m.AnimationDuration(), 48.0, 1e-3);
  float step, ang;
  CheckSmoothLoop(m, node, 12.f, 1.5f, &step, &ang);
  std::printf("cinematic camera: max step %.2f units, max rotation %.3f deg per 1/60 s\n", step, ang);
  // Wrap-around: the pose at the loop end equals the start.
  std::vector<glm::mat4> a, b;
  m.Evaluate(0.0, &a);
  m.Evaluate(m.AnimationDuration() - 1e-6, &b);
  EXPECT_LT(glm::length(glm::vec3(a[node][3]) - glm::vec3(b[node][3])), 0.1f);
}

TEST(Arena, BellSwingIsSmoothAndLoops) {
  const auto& m = Arena().models[1];
  int pivot = m.FindNode("BellPivot");
  ASSERT_GE(pivot, 0);
  EXPECT_NEAR(m.AnimationDuration(), 4.0, 1e-3);
  float step, ang;
  CheckSmoothLoop(m, m.FindNode("BellMesh"), 1.f, 2.f, &step, &ang);
  std::printf("bell: max rotation %.3f deg per 1/60 s\n", ang);
  // It does swing: compare t=0 and a quarter period.
  std::vector<glm::mat4> a, b;
  m.Evaluate(0.0, &a);
  m.Evaluate(1.0, &b);
  EXPECT_GT(glm::degrees(AngleBetween(glm::mat3(a[pivot]), glm::mat3(b[pivot]))), 20.f);
}

TEST(Arena, StaticCamerasLookAtTheArena) {
  for (int i : {5, 6}) {
    const auto& m = Arena().models[i];
    ASSERT_EQ(m.cameras.size(), 1u);
    std::vector<glm::mat4> g;
    m.Evaluate(0.0, &g);
    glm::mat4 w = g[m.cameras[0].node];
    glm::vec3 pos = glm::vec3(w * glm::vec4(m.cameras[0].position, 1));
    glm::vec3 fwd = glm::normalize(glm::vec3(w * glm::vec4(m.cameras[0].lookAt, 0)));
    EXPECT_LT(glm::dot(glm::normalize(-pos), fwd), 1.01f);
    EXPECT_GT(glm::dot(glm::normalize(glm::vec3(0, 300, 0) - pos), fwd), 0.9f)
        << "camera " << i << " at " << pos.x << "," << pos.y << "," << pos.z << " forward " << fwd.x << "," << fwd.y << "," << fwd.z;
    EXPECT_NEAR(glm::degrees(m.cameras[0].fovY), 45.f, 0.5f);
  }
}

