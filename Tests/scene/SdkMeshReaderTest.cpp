// The SDKMESH reader on the project's own files (tools/ArenaGenSdkMesh.h):
// every D3D9 vertex element type, both index sizes, subsets with their
// materials and primitive types, the frame hierarchy, texture names, the
// isolated import of the files drr_arenagen wrote, and the original's scene
// description form. The original's own media, when DRR_ORIGINAL_MEDIA names
// its folder.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "ArenaGenSdkMesh.h"
#include "scene/IsolatedImport.h"
#include "scene/SceneDescription.h"
#include "scene/SdkMesh.h"
#include "scene/SdkMeshModel.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {

sdkmesh::File ReadTestMesh() {
  sdkmesh::File f;
  std::string error;
  EXPECT_TRUE(sdkmesh::ReadMesh(sdkgen::EncodeMesh(sdkgen::TestMesh()), "/m/a/sdktest.sdkmesh", &f, &error)) << error;
  return f;
}

void ExpectVec4(const glm::vec4& got, const glm::vec4& want, const char* what) {
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], want[i], 1e-6f) << what << " component " << i;
}

const fs::path kSet = fs::path(DRR_ARENA_DIR) / "sdkmesh";

}  // namespace

TEST(SdkMeshReader, EveryVertexElementTypeDecodes) {
  const sdkmesh::File f = ReadTestMesh();
  ASSERT_EQ(f.vertexBuffers.size(), 3u);
  const sdkmesh::VertexBuffer& vb = f.vertexBuffers[2];
  ASSERT_EQ(vb.decl.size(), 17u);  // FLOAT1 .. FLOAT16_4, each once
  struct Want { uint8_t usage, index; glm::vec4 value; const char* what; };
  const Want wants[] = {
      {3, 0, {1.f, -1.f, 0.f, 1.f}, "DEC3N normal"},
      {5, 0, {16384.f / 32767.f, -1.f, 0.f, 1.f}, "SHORT2N texcoord"},
      {6, 0, {0.5f, -2.f, 1.f, 0.25f}, "FLOAT16_4 tangent"},
      {7, 0, {0.f, 0.f, 1.f, -1.f}, "FLOAT4 binormal"},
      {5, 1, {3.5f, 0.f, 0.f, 1.f}, "FLOAT1"},
      {5, 2, {-1.25f, 8.f, 0.f, 1.f}, "FLOAT2"},
      {5, 3, {1.f, 128.f / 255.f, 0.f, 64.f / 255.f}, "D3DCOLOR (stored B, G, R, A)"},
      {5, 4, {1.f, 2.f, 3.f, 4.f}, "UBYTE4"},
      {5, 5, {-7.f, 300.f, 0.f, 1.f}, "SHORT2"},
      {5, 6, {-1.f, 2.f, -3.f, 4.f}, "SHORT4"},
      {5, 7, {0.f, 0.2f, 0.4f, 1.f}, "UBYTE4N"},
      {10, 0, {1.f, -1.f, 0.f, 16384.f / 32767.f}, "SHORT4N"},
      {10, 1, {1.f, 0.f, 0.f, 1.f}, "USHORT2N"},
      {1, 0, {0.f, 1.f, 32768.f / 65535.f, 1.f / 65535.f}, "USHORT4N"},
      {2, 0, {1.f, 512.f, 1023.f, 1.f}, "UDEC3"},
      {4, 0, {-0.5f, 6.f, 0.f, 1.f}, "FLOAT16_2"},
  };
  for (const Want& w : wants) {
    const sdkmesh::VertexElement* e = vb.Find(w.usage, w.index);
    ASSERT_NE(e, nullptr) << w.what;
    for (uint64_t v = 0; v < vb.numVertices; ++v) ExpectVec4(f.Element(vb, *e, v), w.value, w.what);
  }
  ExpectVec4(f.Element(vb, *vb.Find(0, 0), 1), {0.f, 40.f, 0.f, 1.f}, "FLOAT3 position");
}

TEST(SdkMeshReader, SixteenAndThirtyTwoBitIndices) {
  const sdkmesh::File f = ReadTestMesh();
  ASSERT_EQ(f.indexBuffers.size(), 3u);
  EXPECT_EQ(f.indexBuffers[0].indexType, sdkmesh::k16Bit);
  EXPECT_EQ(f.indexBuffers[1].indexType, sdkmesh::k32Bit);
  EXPECT_EQ(f.Index(f.indexBuffers[0], 8), 2u);
  EXPECT_EQ(f.Index(f.indexBuffers[1], 6), 70000u);  // beyond 16 bits: read as 32-bit
}

TEST(SdkMeshReader, SubsetsMaterialsAndFrames) {
  const sdkmesh::File f = ReadTestMesh();
  ModelData m;
  std::string error;
  ASSERT_TRUE(SdkMeshToModel(f, {}, &m, &error)) << error;
  // plate/left, plate/right, pendulum/quad (a strip of 2 triangles), types/typed; the line list is skipped.
  ASSERT_EQ(m.meshes.size(), 4u);
  EXPECT_EQ(m.meshes[0].material, 0u);
  EXPECT_EQ(m.meshes[1].material, 1u);
  EXPECT_EQ(m.meshes[2].indices.size(), 6u);
  EXPECT_EQ(m.meshes[3].material, 2u);
  bool lineWarning = false;
  for (const auto& w : m.warnings) lineWarning |= w.find("LINE_LIST") != std::string::npos;
  EXPECT_TRUE(lineWarning);
  // The right quad's indices start again at 0 with VertexStart 4: its vertices are x in [0, 100].
  EXPECT_FLOAT_EQ(m.meshes[1].boundsMin.x, 0.f);
  EXPECT_FLOAT_EQ(m.meshes[1].boundsMax.x, 100.f);
  EXPECT_FLOAT_EQ(m.meshes[0].boundsMax.x, 0.f);
  // Texture names with Windows separators, relative to the mesh's folder.
  EXPECT_EQ(m.materials[0].diffuseTex, "/textures/floor_diffuse.png");
  EXPECT_EQ(m.materials[1].normalTex, "");
  EXPECT_EQ(m.materials[1].specularTex, "/m/a/sdk_missing_sm.dds");
  ASSERT_EQ(m.nodes.size(), 6u);
  EXPECT_EQ(m.nodes[4].name, "pendulum");
  EXPECT_EQ(m.nodes[4].parent, 2);
  EXPECT_EQ(m.nodes[4].meshes, std::vector<uint32_t>({2}));
  EXPECT_EQ(m.nodes[3].meshes, std::vector<uint32_t>({0, 1}));
  // Front faces: counter-clockwise seen from the side the normal points to (the original: clockwise).
  for (const MeshData& mesh : {m.meshes[0], m.meshes[1], m.meshes[2]}) {
    const glm::vec3 a = mesh.vertices[mesh.indices[0]].position, b = mesh.vertices[mesh.indices[1]].position,
                    c = mesh.vertices[mesh.indices[2]].position;
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), mesh.vertices[mesh.indices[0]].normal), 0.f) << mesh.name;
  }
  // The pendulum's 72-byte vertices as the original's input layout reads them: its "tangent" is
  // the second and third texture coordinate sets (0.25, 0.75, 0.5), made orthogonal to the normal.
  EXPECT_NEAR(m.meshes[2].vertices[0].tangent.y, 0.75f / std::sqrt(0.625f), 1e-5f);
  ModelLoadOptions declared;
  declared.sdkmeshDeclaredLayout = true;
  ModelData d;
  ASSERT_TRUE(SdkMeshToModel(f, declared, &d, &error)) << error;
  EXPECT_FLOAT_EQ(d.meshes[2].vertices[0].tangent.x, 1.f);  // its declared TANGENT
  // Mirrored z: the plate's normal stays +y, the pendulum's -z normal becomes +z.
  EXPECT_FLOAT_EQ(m.meshes[0].vertices[0].normal.y, 1.f);
  EXPECT_FLOAT_EQ(m.meshes[2].vertices[0].normal.z, 1.f);
}

TEST(SdkMeshReader, ImportsInTheWorkerFromTheGeneratedSet) {
  ModelData m;
  std::string error;
  ASSERT_TRUE(ImportModelIsolated((kSet / "media/sdktest.sdkmesh").string(), {}, ImportLimits{}, &m, &error)) << error;
  EXPECT_EQ(m.meshes.size(), 4u);
  ModelData anim;
  ModelLoadOptions ao;
  ao.animationsOnly = true;
  ASSERT_TRUE(ImportModelIsolated((kSet / "media/sdktest.sdkmesh_anim").string(), ao, ImportLimits{}, &anim, &error))
      << error;
  ASSERT_EQ(anim.animations.size(), 1u);
  EXPECT_DOUBLE_EQ(anim.animations[0].duration, double(sdkgen::kTestKeys) / sdkgen::kTestFps);
  EXPECT_EQ(AttachAnimations(&m, anim), 2);  // RootNode and pendulum; "ghost" names no frame
}

TEST(SdkMeshReader, DescriptionInTheOriginalsForm) {
  SceneDescription d;
  std::string error;
  ASSERT_TRUE(LoadSceneDescription((kSet / "scene_description.txt").string(), {}, &d, &error)) << error;
  ASSERT_EQ(d.entries.size(), 2u);
  EXPECT_EQ(d.entries[0].meshPath, "media/sdktest.sdkmesh");
  EXPECT_EQ(d.entries[0].animPath, "media/sdktest.sdkmesh_anim");
  EXPECT_EQ(d.entries[1].type, EntryType::Camera);
}

TEST(SdkMeshReader, MissingMeshNamesFileAndLine) {
  const std::string text = "media\\Arena\\arena.sdkmesh\r\nNO_ANIM\r\nLIT\r\n";
  SceneDescription d;
  std::string error;
  EXPECT_FALSE(ParseSceneDescription(text, (kSet / "scene_description.txt").string(), {}, &d, &error));
  EXPECT_NE(error.find("scene_description.txt:1:"), std::string::npos) << error;
  EXPECT_NE(error.find("arena.sdkmesh"), std::string::npos) << error;
}

TEST(SdkMeshReader, MissingTextureFallsBackWithOneWarning) {
  const sdkmesh::File f = ReadTestMesh();
  ModelData m;
  std::string error;
  ASSERT_TRUE(SdkMeshToModel(f, {}, &m, &error)) << error;
  TextureCache cache;
  std::vector<std::string> warnings;
  const auto a = cache.Get(m, m.materials[2].diffuseTex, TextureKind::Color, &warnings);
  const auto b = cache.Get(m, m.materials[2].diffuseTex, TextureKind::Color, &warnings);
  EXPECT_EQ(a, cache.Fallback(TextureKind::Color));
  EXPECT_EQ(a, b);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("sdk_missing.dds"), std::string::npos) << warnings[0];
}

// The original's media, when its folder is given: the bell, its animation,
// the cinematic camera and the decals load through the worker.
TEST(SdkMeshReader, OriginalMedia) {
  const char* dir = std::getenv("DRR_ORIGINAL_MEDIA");
  if (!dir || !*dir)
    GTEST_SKIP() << "skipped: set DRR_ORIGINAL_MEDIA to the original's 'Dynamic Resolution Rendering Update' folder "
                    "to load its media";
  const fs::path arena = fs::path(dir) / "media" / "Arena";
  std::string error;
  ModelData bell, anim, decals;
  ASSERT_TRUE(ImportModelIsolated((arena / "bell.sdkmesh").string(), {}, ImportLimits{}, &bell, &error)) << error;
  EXPECT_EQ(bell.meshes.size(), 2u);
  EXPECT_EQ(bell.Triangles(), (72u + 4278u) / 3u);
  ModelLoadOptions ao;
  ao.animationsOnly = true;
  ASSERT_TRUE(ImportModelIsolated((arena / "bell.sdkmesh_anim").string(), ao, ImportLimits{}, &anim, &error)) << error;
  EXPECT_EQ(AttachAnimations(&bell, anim), 4);
  std::vector<glm::mat4> g0, g1;
  bell.Evaluate(0.0, &g0);
  bell.Evaluate(1.5, &g1);
  EXPECT_GT(glm::length(glm::vec3(g0[2][1]) - glm::vec3(g1[2][1])), 0.1f);  // the bell swings
  ASSERT_TRUE(ImportModelIsolated((arena / "decals.sdkmesh").string(), {}, ImportLimits{}, &decals, &error)) << error;
  EXPECT_GE(decals.meshes.size(), 150u);
  // The cinematic camera flies: its last frame with a mesh moves between two times.
  ModelData camera, path;
  ASSERT_TRUE(ImportModelIsolated((arena / "CinematicCamera.sdkmesh").string(), {}, ImportLimits{}, &camera, &error))
      << error;
  ASSERT_TRUE(ImportModelIsolated((arena / "CinematicCamera.sdkmesh_anim").string(), ao, ImportLimits{}, &path, &error))
      << error;
  EXPECT_EQ(AttachAnimations(&camera, path), 2);
  camera.Evaluate(0.0, &g0);
  camera.Evaluate(1.5, &g1);
  const glm::vec3 eye0(g0.back()[3]), eye1(g1.back()[3]);
  std::printf("cinematic camera eye at 0 s (%.1f, %.1f, %.1f), at 1.5 s (%.1f, %.1f, %.1f)\n", eye0.x, eye0.y, eye0.z,
              eye1.x, eye1.y, eye1.z);
  EXPECT_GT(glm::length(eye1 - eye0), 10.f);
}
