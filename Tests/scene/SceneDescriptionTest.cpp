// Scene description parser: good files in both of the original's layouts and
// malformed ones; every error names file:line and what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "scene/SceneDescription.h"
#include "ScratchDir.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {
ParseOptions NoFileCheck() {
  ParseOptions o;
  o.checkFiles = false;
  return o;
}
bool Parse(const std::string& text, SceneDescription* d, std::string* err, ParseOptions o = NoFileCheck()) {
  return ParseSceneDescription(text, "/scenes/test.txt", o, d, err);
}
}  // namespace

TEST(SceneDescription, OneEntryPerLine) {
  SceneDescription d;
  std::string err;
  ASSERT_TRUE(Parse("arena.gltf NO_ANIM LIT\nbell.gltf bell.gltf LIT\nsky.gltf NO_ANIM UNLIT\n"
                    "decals.gltf NO_ANIM DECAL\ncam.gltf cam_anim.gltf CAMERA\n", &d, &err)) << err;
  ASSERT_EQ(d.entries.size(), 5u);
  EXPECT_EQ(d.entries[0].meshFile, "/scenes/arena.gltf");
  EXPECT_TRUE(d.entries[0].animFile.empty());
  EXPECT_EQ(d.entries[1].animFile, "/scenes/bell.gltf");
  EXPECT_EQ(d.entries[2].type, EntryType::Unlit);
  EXPECT_EQ(d.entries[3].type, EntryType::Decal);
  EXPECT_EQ(d.entries[4].type, EntryType::Camera);
  EXPECT_EQ(d.entries[4].line, 5);
  EXPECT_EQ(d.entries[4].name, "cam");
}

TEST(SceneDescription, OneTokenPerLineAndWindowsPaths) {
  SceneDescription d;
  std::string err;
  ASSERT_TRUE(Parse("Arena\\arena.sdkmesh\nNO_ANIM\nLIT\nArena\\cam.sdkmesh\nArena\\cam.sdkmesh_anim\nCAMERA\n", &d, &err))
      << err;
  ASSERT_EQ(d.entries.size(), 2u);
  EXPECT_EQ(d.entries[0].meshPath, "Arena/arena.sdkmesh");
  EXPECT_EQ(d.entries[1].animFile, "/scenes/Arena/cam.sdkmesh_anim");
  EXPECT_EQ(d.entries[1].line, 4);
}

TEST(SceneDescription, CommentsQuotesOptionsCrlfBom) {
  SceneDescription d;
  std::string err;
  std::string text = "\xEF\xBB\xBF# a comment\r\n\r\n\"my model.obj\" NO_ANIM lit name=Thing translate=1,2,3 scale=2 # tail\r\n"
                     "b.obj NO_ANIM UNLIT rotate=0,90,0 hidden=1 loop=2.5\r\n";
  ASSERT_TRUE(Parse(text, &d, &err)) << err;
  ASSERT_EQ(d.entries.size(), 2u);
  EXPECT_EQ(d.entries[0].meshPath, "my model.obj");
  EXPECT_EQ(d.entries[0].name, "Thing");
  EXPECT_EQ(d.entries[0].translate, glm::vec3(1, 2, 3));
  EXPECT_EQ(d.entries[0].scale, glm::vec3(2));
  EXPECT_EQ(d.entries[0].line, 3);
  EXPECT_TRUE(d.entries[1].hidden);
  EXPECT_DOUBLE_EQ(d.entries[1].loopSeconds, 2.5);
  glm::vec4 p = d.entries[1].Transform() * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(p.z, -1.f, 1e-5f);  // 90 degrees about Y takes +X to -Z
}

struct BadCase {
  const char* text;
  const char* expectInError;
};

TEST(SceneDescription, MalformedFilesNameFileLineAndExpectation) {
  const BadCase cases[] = {
      {"a.obj NO_ANIM LIT\nb.obj NO_ANIM\n", "test.txt:2: entry 'b.obj' is missing its type (expected LIT, UNLIT, CAMERA or DECAL)"},
      {"a.obj\n", "test.txt:1: entry 'a.obj' is missing its animation path"},
      {"a.obj NO_ANIM SHINY\n", "test.txt:1: unknown type 'SHINY' (expected LIT, UNLIT, CAMERA or DECAL)"},
      {"a.obj LIT\n", "test.txt:1: found type 'LIT' where the animation path or NO_ANIM was expected"},
      {"LIT a.obj NO_ANIM\n", "test.txt:1: type 'LIT' where a mesh path was expected"},
      {"a.obj NO_ANIM LIT scale=abc\n", "test.txt:1: scale= expects"},
      {"a.obj NO_ANIM LIT colour=red\n", "test.txt:1: unknown option 'colour'"},
      {"\n\na.obj NO_ANIM LIT translate=1,2\n", "test.txt:3: translate= expects x,y,z"},
      {"\"a.obj NO_ANIM LIT\n", "test.txt:1: unterminated quoted path"},
      {"", "test.txt: no entries"},
      {"# only a comment\n\n", "test.txt: no entries"},
      // Tessellation (Docs/Tessellation.md)
      {"a.obj NO_ANIM LIT\nb.obj NO_ANIM LIT tessellate=smooth\n", "test.txt:2: tessellate= has unknown mode 'smooth'"},
      {"a.obj NO_ANIM LIT tessellate=:phong\n", "test.txt:1: tessellate= has an empty material name"},
      {"a.obj NO_ANIM LIT tessellate=\n", "test.txt:1: tessellate= needs a value"},
      {"a.obj NO_ANIM LIT tessellate=displace\n", "test.txt:1: tessellate=...displace needs displacement=<height map> and relief=<units>"},
      {"a.obj NO_ANIM LIT tessellate=displace displacement=h.png\n", "test.txt:1: tessellate=...displace needs"},
      {"a.obj NO_ANIM LIT tessellate=phong relief=3\n", "test.txt:1: displacement= and relief= act only with"},
      {"a.obj NO_ANIM LIT tessellate=displace displacement=h.png relief=-2\n", "test.txt:1: relief= expects a positive number"},
      {"a.obj NO_ANIM LIT tessellate=displace displacement=h.png relief=nan\n", "test.txt:1: relief= expects"},
  };
  for (const auto& c : cases) {
    SceneDescription d;
    std::string err;
    EXPECT_FALSE(Parse(c.text, &d, &err)) << c.text;
    EXPECT_NE(err.find(c.expectInError), std::string::npos) << "text: " << c.text << "\nerror: " << err;
  }
}

TEST(SceneDescription, BinaryGarbageIsRejectedWithLine) {
  std::mt19937 rng(7);
  std::string junk = "a.obj NO_ANIM LIT\n";
  for (int i = 0; i < 4096; ++i) junk.push_back(static_cast<char>(rng() & 0xff));
  SceneDescription d;
  std::string err;
  EXPECT_FALSE(Parse(junk, &d, &err));
  EXPECT_NE(err.find("test.txt:"), std::string::npos) << err;
  EXPECT_TRUE(err.find("binary data") != std::string::npos || err.find("line too long") != std::string::npos) << err;
  // An embedded NUL on line 2.
  EXPECT_FALSE(Parse(std::string("a.obj NO_ANIM LIT\nb.obj\0 NO_ANIM LIT\n", 38), &d, &err));
  EXPECT_NE(err.find("test.txt:2: unexpected binary data (byte 0x00"), std::string::npos) << err;
}

TEST(SceneDescription, VeryLongLine) {
  std::string text = "a.obj NO_ANIM LIT\n" + std::string(100000, 'x') + " NO_ANIM LIT\n";
  SceneDescription d;
  std::string err;
  EXPECT_FALSE(Parse(text, &d, &err));
  EXPECT_NE(err.find("test.txt:2: line too long (100012 characters, at most 4096 expected)"), std::string::npos) << err;
}

TEST(SceneDescription, BadPathsAreReportedWithTheResolvedLocation) {
  fs::path dir = drrtest::ProcessScratchDir() / "desc_test";
  fs::create_directories(dir);
  { std::ofstream(dir / "exists.obj") << "v 0 0 0\n"; }
  std::ofstream(dir / "scene.txt") << "exists.obj NO_ANIM LIT\n\nmissing.obj NO_ANIM LIT\n";
  SceneDescription d;
  std::string err;
  EXPECT_FALSE(LoadSceneDescription((dir / "scene.txt").string(), {}, &d, &err));
  EXPECT_NE(err.find("scene.txt:3: mesh file 'missing.obj' not found (looked for " + (dir / "missing.obj").string()),
            std::string::npos)
      << err;
  std::ofstream(dir / "scene2.txt") << "exists.obj\nnope.anim\nLIT\n";
  EXPECT_FALSE(LoadSceneDescription((dir / "scene2.txt").string(), {}, &d, &err));
  EXPECT_NE(err.find("scene2.txt:2: animation file 'nope.anim' not found"), std::string::npos) << err;
  EXPECT_FALSE(LoadSceneDescription((dir / "no_such_scene.txt").string(), {}, &d, &err));
  EXPECT_NE(err.find("no_such_scene.txt: cannot open scene description"), std::string::npos) << err;
  fs::remove_all(dir);
}

// Deferred shading's LIGHT entries (Docs/Deferred.md): between model entries,
// any case, spot directions normalised, defaults for the optional values.
TEST(SceneDescription, LightEntries) {
  SceneDescription d;
  std::string err;
  ASSERT_TRUE(Parse("arena.gltf NO_ANIM LIT\n"
                    "LIGHT POINT position=1,2,3 color=3,0.5,0.25 radius=900\n"
                    "light spot position=0,10,0 direction=0,-2,0 radius=30 angle=25 shadow=1\n"
                    "bell.gltf NO_ANIM LIT\n\"LIGHT\" NO_ANIM LIT\n",
                    &d, &err))
      << err;
  ASSERT_EQ(d.entries.size(), 3u);
  EXPECT_EQ(d.entries[2].meshPath, "LIGHT");  // quoted: a model file's name
  ASSERT_EQ(d.lights.size(), 2u);
  EXPECT_EQ(d.lights[0].type, LightType::Point);
  EXPECT_EQ(d.lights[0].position, glm::vec3(1, 2, 3));
  EXPECT_EQ(d.lights[0].color, glm::vec3(3, 0.5f, 0.25f));
  EXPECT_EQ(d.lights[0].radius, 900.f);
  EXPECT_EQ(d.lights[0].line, 2);
  EXPECT_EQ(d.lights[1].type, LightType::Spot);
  EXPECT_EQ(d.lights[1].direction, glm::vec3(0, -1, 0));
  EXPECT_EQ(d.lights[1].color, glm::vec3(1));
  EXPECT_EQ(d.lights[1].angleDeg, 25.f);
  EXPECT_TRUE(d.lights[1].shadow);
}

TEST(SceneDescription, BadLightsNameTheLineAndTheValue) {
  const std::string ok = "position=0,0,0 radius=1";
  const struct {
    std::string text, expect;
  } cases[] = {
      {"LIGHT\n", "test.txt:2: LIGHT needs its kind: found '', expected POINT or SPOT"},
      {"LIGHT AREA " + ok, "test.txt:2: LIGHT needs its kind: found 'AREA'"},
      {"LIGHT POINT radius=1", "test.txt:2: LIGHT POINT needs position= and radius="},
      {"LIGHT SPOT " + ok, "LIGHT SPOT needs position=, direction= and radius="},
      {"LIGHT POINT " + ok + "\n  radius=0", "test.txt:3: radius= expects a number in (0, 1e7]"},
      {"LIGHT POINT " + ok + " radius=nan", "radius= expects a number in (0, 1e7]"},
      {"LIGHT POINT " + ok + " color=1,2", "color= expects r,g,b, each in [0, 64]"},
      {"LIGHT POINT " + ok + " color=1,-2,3", "color= expects r,g,b, each in [0, 64]"},
      {"LIGHT POINT " + ok + " angle=30", "unknown light option 'angle' (expected position=, color=, radius=)"},
      {"LIGHT SPOT " + ok + " direction=0,0,0", "direction= expects x,y,z, not all zero"},
      {"LIGHT SPOT " + ok + " direction=0,1,0 angle=90", "angle= expects degrees in (0, 89]"},
      {"LIGHT SPOT " + ok + " direction=0,1,0 shadow=yes", "shadow= expects 0 or 1"},
  };
  for (const auto& c : cases) {
    SceneDescription d;
    std::string err;
    EXPECT_FALSE(Parse("arena.gltf NO_ANIM LIT\n" + c.text, &d, &err)) << c.text;
    EXPECT_NE(err.find(c.expect), std::string::npos) << "text: " << c.text << "\nerror: " << err;
  }
}

TEST(SceneDescription, LightLimits) {
  std::string text = "arena.gltf NO_ANIM LIT\n";
  for (size_t i = 0; i < kMaxShadowedSpots + 1; ++i)
    text += "LIGHT SPOT position=0,0,0 direction=0,-1,0 radius=1 shadow=1\n";
  SceneDescription d;
  std::string err;
  EXPECT_FALSE(Parse(text, &d, &err));
  EXPECT_NE(err.find("test.txt:6: too many spot lights with shadow=1 (at most 4)"), std::string::npos) << err;
  text = "arena.gltf NO_ANIM LIT\n";
  for (size_t i = 0; i < kMaxSceneLights + 1; ++i) text += "LIGHT POINT position=0,0,0 radius=1\n";
  EXPECT_FALSE(Parse(text, &d, &err));
  EXPECT_NE(err.find("test.txt:34: too many lights (at most 32)"), std::string::npos) << err;
}

TEST(SceneDescription, TessellationRulesPerMaterial) {
  SceneDescription d;
  std::string err;
  ASSERT_TRUE(Parse("arena.gltf NO_ANIM LIT tessellate=Floor:displace,Rock:phong displacement=textures/h.png relief=12\n"
                    "bell.gltf bell.gltf LIT tessellate=phong\nsky.gltf NO_ANIM UNLIT\n",
                    &d, &err))
      << err;
  ASSERT_EQ(d.entries.size(), 3u);
  const SceneEntry& arena = d.entries[0];
  EXPECT_EQ(arena.TessModeOf("Floor"), TessMode::Displace);
  EXPECT_EQ(arena.TessModeOf("Rock"), TessMode::Phong);
  EXPECT_EQ(arena.TessModeOf("Brick"), TessMode::None);
  EXPECT_FLOAT_EQ(arena.relief, 12.f);
  EXPECT_EQ(arena.displacementFile, "/scenes/textures/h.png");
  EXPECT_EQ(d.entries[1].TessModeOf("Bronze"), TessMode::Phong);
  EXPECT_EQ(d.entries[2].TessModeOf("Sky"), TessMode::None);
}

TEST(SceneDescription, MissingDisplacementMapNamesFileAndLine) {
  fs::path dir = drrtest::ProcessScratchDir() / "desc_tess";
  fs::create_directories(dir);
  std::ofstream(dir / "a.obj") << "v 0 0 0\n";
  SceneDescription d;
  std::string err;
  ParseOptions o;
  EXPECT_FALSE(ParseSceneDescription("a.obj NO_ANIM LIT\na.obj NO_ANIM LIT tessellate=displace displacement=none.png relief=1\n",
                                     (dir / "s.txt").string(), o, &d, &err));
  EXPECT_NE(err.find("s.txt:2: displacement map 'none.png' not found"), std::string::npos) << err;
  fs::remove_all(dir);
}
