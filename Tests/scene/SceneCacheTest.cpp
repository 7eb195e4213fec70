// A scene description that lists one model many times imports it once and
// uploads its geometry once (under validation; the fixture asserts zero messages).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "RenderTest.h"
#include "scene/Scene.h"

using namespace drr;
namespace fs = std::filesystem;

class SceneCache : public drrtest::RenderTest {};

TEST_F(SceneCache, OneUploadPerDistinctModelFile) {
  const fs::path dir = fs::path(DRR_SCENE_TEST_OUT) / "scene_cache";
  fs::create_directories(dir);
  std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n";
  std::ofstream one(dir / "one.txt"), many(dir / "many.txt");
  one << "tri.obj NO_ANIM LIT\n";
  for (int i = 0; i < 1000; ++i) many << "tri.obj NO_ANIM LIT\n";
  one.close(), many.close();
  std::string err;
  auto a = Scene::Load(device(), (dir / "one.txt").string(), {}, &err);
  ASSERT_TRUE(a) << err;
  auto b = Scene::Load(device(), (dir / "many.txt").string(), {}, &err);
  ASSERT_TRUE(b) << err;
  EXPECT_GT(a->Stats().vertexBytes, 0u);
  EXPECT_EQ(b->Stats().vertexBytes, a->Stats().vertexBytes);
  EXPECT_EQ(b->Stats().indexBytes, a->Stats().indexBytes);
  EXPECT_EQ(b->Stats().triangles, 1000 * a->Stats().triangles);  // of the whole scene, as before
}
