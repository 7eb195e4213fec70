// Bad input never crashes: NaN vertices, degenerate triangles, zero-size and
// unsupported textures, missing textures, huge counts, Assimp import errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/IsolatedImport.h"
#include "scene/ModelLoader.h"
#include "scene/TextureLoader.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {
fs::path TempDir() {
  fs::path d = fs::temp_directory_path() / ("drr_bad_input_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}
void WriteBinaryStl(const fs::path& p, const std::vector<std::array<float, 9>>& tris) {
  std::ofstream f(p, std::ios::binary);
  char header[80] = "drr test";
  f.write(header, 80);
  uint32_t n = uint32_t(tris.size());
  f.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    float normal[3] = {0, 0, 0};
    f.write(reinterpret_cast<const char*>(normal), 12);
    f.write(reinterpret_cast<const char*>(t.data()), 36);
    uint16_t attr = 0;
    f.write(reinterpret_cast<const char*>(&attr), 2);
  }
}
bool Contains(const std::vector<std::string>& v, const std::string& s) {
  for (const auto& x : v)
    if (x.find(s) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST(BadInput, NaNVerticesAreDroppedWithAMessage) {
  fs::path dir = TempDir();
  const float nan = std::nanf("");
  WriteBinaryStl(dir / "nan.stl", {{0, 0, 0, 1, 0, 0, 0, 1, 0},
                                   {nan, 0, 0, 1, 1, 0, 0, 1, 0},
                                   {2, 0, 0, 3, 0, 0, 2, 1, INFINITY},
                                   {5, 0, 0, 6, 0, 0, 5, 1, 0}});
  ModelData m;
  std::string err;
  ASSERT_TRUE(LoadModel((dir / "nan.stl").string(), {}, &m, &err)) << err;
  EXPECT_EQ(m.Triangles(), 2u);
  for (const auto& mesh : m.meshes)
    for (const auto& v : mesh.vertices) {
      EXPECT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
      EXPECT_TRUE(std::isfinite(v.normal.x) && std::isfinite(v.tangent.x) && std::isfinite(v.binormal.x));
    }
  EXPECT_TRUE(std::isfinite(m.meshes[0].sphereRadius));
  // Either Assimp's FindInvalidData or our repair removed them; when ours did, it says so.
  if (!m.warnings.empty()) {
    EXPECT_TRUE(Contains(m.warnings, "non-finite")) << m.warnings.front();
  }
  fs::remove_all(dir);
}

TEST(BadInput, RepairMeshDirectly) {
  MeshData mesh;
  mesh.name = "m";
  auto V = [](float x, float y, float z) {
    SceneVertex v{};
    v.position = {x, y, z};
    v.normal = {std::nanf(""), 0, 0};
    v.tangent = {std::nanf(""), 0, 0};
    v.texcoord = {INFINITY, 0};
    return v;
  };
  mesh.vertices = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(std::nanf(""), 0, 0), V(2, 2, 2), V(4, 4, 4)};
  mesh.indices = {0, 1, 2, /*NaN*/ 0, 3, 1, /*degenerate: repeated*/ 0, 0, 1, /*collinear*/ 0, 4, 5,
                  /*out of range*/ 0, 1, 99, 1};
  std::vector<std::string> msgs;
  ASSERT_TRUE(RepairMesh(&mesh, &msgs));
  EXPECT_EQ(mesh.indices.size(), 3u);
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_TRUE(Contains(msgs, "dropped 1 triangles with non-finite (NaN/Inf) vertex positions"));
  EXPECT_TRUE(Contains(msgs, "dropped 2 degenerate (zero-area) triangles"));
  EXPECT_TRUE(Contains(msgs, "dropped 1 triangles with out-of-range indices"));
  EXPECT_TRUE(Contains(msgs, "index count not a multiple of 3"));
  EXPECT_TRUE(Contains(msgs, "rebuilt 3 missing or non-finite normals"));
  EXPECT_TRUE(Contains(msgs, "non-finite texture coordinates"));
  for (const auto& v : mesh.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.f, 1e-5f);
    EXPECT_NEAR(std::fabs(v.normal.z), 1.f, 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal, v.tangent), 0.f, 1e-5f);
    EXPECT_EQ(v.texcoord, glm::vec2(0.f));
  }
  // Nothing valid left: reported as such.
  MeshData empty;
  empty.vertices = {V(0, 0, 0), V(0, 0, 0), V(0, 0, 0)};
  empty.indices = {0, 1, 2};
  EXPECT_FALSE(RepairMesh(&empty, &msgs));
}

TEST(BadInput, DegenerateTrianglesOnly) {
  fs::path dir = TempDir();
  std::ofstream(dir / "degenerate.obj") << "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 5 5 5\nf 1 2 3\nf 1 1 4\nf 2 2 2\n";
  ModelData m;
  std::string err;
  EXPECT_FALSE(LoadModel((dir / "degenerate.obj").string(), {}, &m, &err));
  EXPECT_NE(err.find("degenerate.obj"), std::string::npos) << err;
  std::ofstream(dir / "mixed.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 2 2\nf 1 2 3\nf 1 1 4\nf 1 4 4\n";
  ASSERT_TRUE(LoadModel((dir / "mixed.obj").string(), {}, &m, &err)) << err;
  EXPECT_EQ(m.Triangles(), 1u);
  fs::remove_all(dir);
}

TEST(BadInput, HugeCountsFailCleanly) {
  fs::path dir = TempDir();
  // A PLY header that promises 4 billion vertices with no data.
  std::ofstream(dir / "huge.ply") << "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n"
                                     "property float y\nproperty float z\nelement face 4000000000\n"
                                     "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n";
  ModelData m;
  std::string err;
  // Through the import worker, as the sample loads them: in process, Assimp's
  // allocation for the claimed counts is an abort under AddressSanitizer.
  EXPECT_FALSE(ImportModelIsolated((dir / "huge.ply").string(), {}, ImportLimits::FromEnvironment(), &m, &err));
  EXPECT_NE(err.find("huge.ply"), std::string::npos) << err;
  // A binary STL that claims more triangles than the file holds.
  {
    std::ofstream f(dir / "huge.stl", std::ios::binary);
    char header[80] = {};
    f.write(header, 80);
    uint32_t n = 0xfffffff0u;
    f.write(reinterpret_cast<const char*>(&n), 4);
  }
  EXPECT_FALSE(ImportModelIsolated((dir / "huge.stl").string(), {}, ImportLimits::FromEnvironment(), &m, &err));
  EXPECT_NE(err.find("huge.stl"), std::string::npos) << err;
  // Our own limits.
  WriteBinaryStl(dir / "ok.stl", {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 1, 0, 1, 1}});
  ModelLoadOptions small;
  small.maxTriangles = 1;
  EXPECT_FALSE(LoadModel((dir / "ok.stl").string(), small, &m, &err));
  EXPECT_NE(err.find("too large"), std::string::npos) << err;
  fs::remove_all(dir);
}

TEST(BadInput, ImportErrorsNameTheFile) {
  fs::path dir = TempDir();
  std::ofstream(dir / "garbage.fbx") << "this is not an FBX file at all";
  ModelData m;
  std::string err;
  EXPECT_FALSE(LoadModel((dir / "garbage.fbx").string(), {}, &m, &err));
  EXPECT_NE(err.find((dir / "garbage.fbx").string()), std::string::npos) << err;
  EXPECT_FALSE(LoadModel((dir / "absent.obj").string(), {}, &m, &err));
  EXPECT_NE(err.find("absent.obj: model file not found"), std::string::npos) << err;
  fs::remove_all(dir);
}

TEST(BadInput, ZeroSizeAndUnsupportedTextures) {
  fs::path dir = TempDir();
  TextureData t;
  std::string err;
  std::ofstream(dir / "empty.png").close();
  EXPECT_FALSE(LoadTextureFile((dir / "empty.png").string(), TextureKind::Color, {}, &t, &err));
  EXPECT_NE(err.find("empty.png: texture has zero size"), std::string::npos) << err;
  EXPECT_FALSE(MakeTextureRGBA8(nullptr, 0, 0, "zero", TextureKind::Color, {}, &t, &err));
  EXPECT_NE(err.find("zero: texture has zero size (0x0)"), std::string::npos) << err;
  std::ofstream(dir / "fake.png") << "definitely not a PNG image";
  EXPECT_FALSE(LoadTextureFile((dir / "fake.png").string(), TextureKind::Color, {}, &t, &err));
  EXPECT_NE(err.find("fake.png: "), std::string::npos) << err;
  std::ofstream(dir / "tex.xyz123") << "unknown format";
  EXPECT_FALSE(LoadTextureFile((dir / "tex.xyz123").string(), TextureKind::Normal, {}, &t, &err));
  EXPECT_NE(err.find("tex.xyz123: unsupported texture format"), std::string::npos) << err;
  TextureLoadOptions tiny;
  tiny.maxDimension = 1;
  std::vector<uint8_t> px(4 * 4 * 4, 255);
  EXPECT_FALSE(MakeTextureRGBA8(px.data(), 4, 4, "big", TextureKind::Color, tiny, &t, &err));
  EXPECT_NE(err.find("too large"), std::string::npos);
  fs::remove_all(dir);
}

TEST(BadInput, MissingTexturesFallBackWithExactlyOneWarning) {
  ModelData model;
  model.file = "/nowhere/model.obj";
  TextureCache cache;
  std::vector<std::string> warnings;
  auto a = cache.Get(model, "/nowhere/missing.png", TextureKind::Color, &warnings);
  auto b = cache.Get(model, "/nowhere/missing.png", TextureKind::Color, &warnings);
  auto c = cache.Get(model, "/nowhere/missing.png", TextureKind::Specular, &warnings);
  auto n = cache.Get(model, "/nowhere/missing_n.png", TextureKind::Normal, &warnings);
  auto e = cache.Get(model, "*3", TextureKind::Color, &warnings);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_NE(warnings[0].find("/nowhere/missing.png"), std::string::npos);
  EXPECT_NE(warnings[0].find("white"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("flat normal"), std::string::npos) << warnings[1];
  EXPECT_EQ(a->mips[0].rgba, (std::vector<uint8_t>{255, 255, 255, 255}));
  EXPECT_EQ(c->mips[0].rgba, (std::vector<uint8_t>{0, 0, 0, 255}));
  EXPECT_EQ(n->mips[0].rgba, (std::vector<uint8_t>{128, 128, 255, 255}));
  EXPECT_EQ(n->format, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);
  EXPECT_EQ(a->format, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(e->mips[0].rgba, a->mips[0].rgba);
  EXPECT_EQ(cache.LoadedCount(), 0u);
}

TEST(Textures, MipChainIsCompleteAndFilteredInLinearLight) {
  // 4x2 checker of black and white: the 1x1 mip of the sRGB texture is linear 0.5 -> sRGB ~188.
  std::vector<uint8_t> px;
  for (int i = 0; i < 8; ++i) {
    uint8_t v = (i % 2) ? 255 : 0;
    px.insert(px.end(), {v, v, v, 255});
  }
  TextureData t;
  std::string err;
  ASSERT_TRUE(MakeTextureRGBA8(px.data(), 4, 2, "checker", TextureKind::Color, {}, &t, &err)) << err;
  ASSERT_EQ(t.mips.size(), 3u);  // 4x2, 2x1, 1x1
  EXPECT_EQ(t.mips[1].width, 2u);
  EXPECT_EQ(t.mips[1].height, 1u);
  EXPECT_EQ(t.mips[2].width, 1u);
  EXPECT_NEAR(int(t.mips[2].rgba[0]), 188, 1);
  ASSERT_TRUE(MakeTextureRGBA8(px.data(), 4, 2, "checker", TextureKind::Specular, {}, &t, &err));
  EXPECT_NEAR(int(t.mips[2].rgba[0]), 128, 1);
  // Normal maps are renormalised.
  std::vector<uint8_t> nm = {255, 128, 128, 255, 0, 128, 128, 255};
  ASSERT_TRUE(MakeTextureRGBA8(nm.data(), 2, 1, "n", TextureKind::Normal, {}, &t, &err));
  EXPECT_EQ(t.mips[1].rgba[2], 255);  // (1,0,0)+(-1,0,0) averages to nothing -> flat normal
}
