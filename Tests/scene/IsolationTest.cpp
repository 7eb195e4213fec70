// The isolation layer (IsolatedImport.h): files that crash, hang or exhaust
// the decoders become errors naming the file, the parent's memory stays flat,
// replies are validated, each file is imported once, and 16-bit PNGs keep
// their stored values. Files that make Assimp misbehave are generated here
// from Debian's assimp-testmodels (skipped with a message when absent).
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/ImportWire.h"
#include "scene/IsolatedImport.h"
#include "scene/SceneDescription.h"
#include "ScratchDir.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {

const fs::path kModels = "/usr/share/assimp/models";

fs::path TempDir() {
  return drrtest::ProcessScratchDir();
}

void WriteFile(const fs::path& p, const std::vector<uint8_t>& bytes) {
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

std::vector<uint8_t> ReadBytes(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), {}};
}

// Short limits, so that a hang costs seconds.
ImportLimits TestLimits() {
  ImportLimits l;
  l.memoryMiB = 1024;
  l.cpuSeconds = 3;
  l.wallSeconds = 10;
  return l;
}

long PeakRssMiB() {
  rusage r{};
  getrusage(RUSAGE_SELF, &r);
  return r.ru_maxrss / 1024;
}

// A minimal PNG writer (stored deflate blocks), enough to make files whose
// header says what the test needs.
uint32_t Crc32(const uint8_t* p, size_t n, uint32_t c = 0xffffffffu) {
  for (size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return c;
}
void Be32(std::vector<uint8_t>* v, uint32_t x) {
  for (int s = 24; s >= 0; s -= 8) v->push_back(uint8_t(x >> s));
}
void Chunk(std::vector<uint8_t>* png, const char* type, const std::vector<uint8_t>& data) {
  Be32(png, uint32_t(data.size()));
  std::vector<uint8_t> body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  png->insert(png->end(), body.begin(), body.end());
  Be32(png, Crc32(body.data(), body.size()) ^ 0xffffffffu);
}
// raw: the filtered scanlines (filter byte 0 before each row).
std::vector<uint8_t> Png(uint32_t w, uint32_t h, uint8_t bitDepth, uint8_t colorType, const std::vector<uint8_t>& raw) {
  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<uint8_t> ihdr;
  Be32(&ihdr, w), Be32(&ihdr, h);
  ihdr.insert(ihdr.end(), {bitDepth, colorType, 0, 0, 0});
  Chunk(&png, "IHDR", ihdr);
  std::vector<uint8_t> z = {0x78, 0x01, 0x01, uint8_t(raw.size()), uint8_t(raw.size() >> 8),
                            uint8_t(~raw.size()), uint8_t(~(raw.size() >> 8))};
  z.insert(z.end(), raw.begin(), raw.end());
  uint32_t a = 1, b = 0;  // Adler-32
  for (uint8_t x : raw) a = (a + x) % 65521, b = (b + a) % 65521;
  Be32(&z, (b << 16) | a);
  Chunk(&png, "IDAT", z);
  Chunk(&png, "IEND", {});
  return png;
}

}  // namespace

TEST(Isolation, OutOfMemoryOffIsAnErrorNamingTheFile) {
  const fs::path f = kModels / "invalid/OutOfMemory.off";
  if (!fs::exists(f)) GTEST_SKIP() << f << " absent (Debian package assimp-testmodels)";
  ModelData m;
  std::string err;
  EXPECT_FALSE(ImportModelIsolated(f.string(), {}, TestLimits(), &m, &err));
  EXPECT_NE(err.find(f.string()), std::string::npos) << err;
  EXPECT_LT(PeakRssMiB(), 512) << "the parent must not hold the decoder's memory";
}

TEST(Isolation, PngDeclaringHugeSizeIsAnErrorAndParentStaysSmall) {
  const fs::path f = TempDir() / "huge.png";
  WriteFile(f, Png(16384, 16384, 8, 6, std::vector<uint8_t>(64, 0)));  // 16384^2 RGBA claimed, 64 bytes given
  const long before = PeakRssMiB();
  TextureCache cache({}, IsolatedTextureLoader(TestLimits()));
  ModelData none;
  std::vector<std::string> warnings;
  auto t = cache.Get(none, f.string(), TextureKind::Color, &warnings);
  EXPECT_EQ(t->source, "<fallback white>");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find(f.string()), std::string::npos) << warnings[0];
  EXPECT_LT(PeakRssMiB() - before, 100) << "decoding 16384x16384 must not happen in this process";
}

TEST(Isolation, TruncatedBinaryPlyEndsAtTheCpuLimit) {
  const fs::path src = kModels / "PLY/cube_binary.ply";
  if (!fs::exists(src)) GTEST_SKIP() << src << " absent (Debian package assimp-testmodels)";
  std::vector<uint8_t> bytes = ReadBytes(src);
  bytes.resize(44);  // Assimp 5.2.5 loops for ever on this prefix
  const fs::path f = TempDir() / "truncated.ply";
  WriteFile(f, bytes);
  ModelData m;
  std::string err;
  EXPECT_FALSE(ImportModelIsolated(f.string(), {}, TestLimits(), &m, &err));
  EXPECT_NE(err.find(f.string()), std::string::npos) << err;
}

// Byte-flipped copies of FBX and binary PLY files: each is imported or
// rejected with a message naming it; none takes this process down.
TEST(Isolation, ByteFlippedModelsNeverKillTheCaller) {
  std::vector<fs::path> sources = {kModels / "FBX/box.fbx", kModels / "FBX/spider.fbx",
                                   kModels / "FBX/boxWithCompressedCTypeArray.FBX", kModels / "PLY/cube_binary.ply"};
  int made = 0, failed = 0;
  for (const auto& src : sources) {
    if (!fs::exists(src)) continue;
    const std::vector<uint8_t> orig = ReadBytes(src);
    for (int k = 1; k <= 6; ++k) {
      std::vector<uint8_t> bytes = orig;
      for (size_t i = (k * 7919u) % bytes.size(); i < bytes.size(); i += bytes.size() / (4 * k) + 1) bytes[i] ^= 0xff;
      const fs::path f = TempDir() / ("flipped" + std::to_string(made++) + src.extension().string());
      WriteFile(f, bytes);
      ModelData m;
      std::string err;
      if (!ImportModelIsolated(f.string(), {}, TestLimits(), &m, &err)) {
        ++failed;
        EXPECT_NE(err.find(f.string()), std::string::npos) << err;
      } else {
        EXPECT_EQ(ValidateModel(m, {}), "");
      }
    }
  }
  if (made == 0) GTEST_SKIP() << "assimp-testmodels absent";
  std::printf("%d byte-flipped files: %d rejected with an error, %d imported\n", made, failed, made - failed);
}

TEST(Isolation, ASceneListingOneModelManyTimesImportsItOnce) {
  const fs::path model = TempDir() / "tri.obj";
  std::ofstream(model) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::string text;
  for (int i = 0; i < 1000; ++i) text += "tri.obj NO_ANIM LIT\n";
  SceneDescription d;
  std::string err;
  ASSERT_TRUE(ParseSceneDescription(text, (TempDir() / "scene.txt").string(), {}, &d, &err)) << err;
  ASSERT_EQ(d.entries.size(), 1000u);
  ModelCache cache(TestLimits());
  for (const auto& e : d.entries) ASSERT_TRUE(cache.Get(e.meshFile, {}, &err)) << err;
  EXPECT_EQ(cache.Imports(), 1u);
}

TEST(Isolation, SixteenBitGreyMatchesEightBit) {
  const fs::path dir = TempDir();
  // 2x2 grey: 8-bit 0x80, and 16-bit 0x8080 (the same value, 128.5/255).
  WriteFile(dir / "grey8.png", Png(2, 2, 8, 0, {0, 0x80, 0x80, 0, 0x80, 0x80}));
  WriteFile(dir / "grey16.png", Png(2, 2, 16, 0, {0, 0x80, 0x80, 0x80, 0x80, 0, 0x80, 0x80, 0x80, 0x80}));
  for (bool isolated : {false, true}) {
    TextureData t8, t16;
    std::string err;
    auto load = [&](const char* name, TextureData* t) {
      return isolated ? ImportTextureIsolated((dir / name).string(), TextureKind::Color, 16384, TestLimits(), t, &err)
                      : LoadTextureFile((dir / name).string(), TextureKind::Color, {}, t, &err);
    };
    ASSERT_TRUE(load("grey8.png", &t8)) << err;
    ASSERT_TRUE(load("grey16.png", &t16)) << err;
    EXPECT_EQ(int(t8.mips[0].rgba[0]), 0x80);
    EXPECT_EQ(int(t16.mips[0].rgba[0]), 0x80) << (isolated ? "isolated" : "in process");
  }
}

TEST(Isolation, MissingWorkerIsAClearError) {
  setenv("DRR_IMPORT_WORKER", "/nonexistent/drr_import_worker", 1);
  ModelData m;
  std::string err;
  EXPECT_FALSE(ImportModelIsolated("/any/model.obj", {}, TestLimits(), &m, &err));
  unsetenv("DRR_IMPORT_WORKER");
  EXPECT_NE(err.find("/any/model.obj"), std::string::npos) << err;
}

TEST(ImportWire, ModelRoundTripsAndBadDataIsRejected) {
  ModelData m;
  m.file = "x.obj";
  MeshData mesh;
  mesh.vertices.resize(3);
  for (auto& v : mesh.vertices) v = SceneVertex{{1, 2, 3}, {0, 1, 0}, {0, 0}, {1, 0, 0}, {0, 0, 1}};
  mesh.indices = {0, 1, 2};
  m.meshes.push_back(mesh);
  m.materials.emplace_back();
  m.nodes.push_back(NodeData{"root", -1, glm::mat4(1.f), {}, glm::vec3(1.f), {}, {0}});
  std::vector<uint8_t> wire;
  WireWriteModel(m, &wire);
  ModelData back;
  std::string err;
  ASSERT_TRUE(WireReadModel(wire, {}, &back, &err)) << err;
  EXPECT_EQ(back.meshes[0].indices, mesh.indices);

  m.meshes[0].indices[2] = 3;  // out of range
  wire.clear();
  WireWriteModel(m, &wire);
  EXPECT_FALSE(WireReadModel(wire, {}, &back, &err));
  EXPECT_NE(err.find("out of range"), std::string::npos) << err;

  m.meshes[0].indices[2] = 2;
  m.meshes[0].vertices[1].position.x = std::nanf("");
  wire.clear();
  WireWriteModel(m, &wire);
  EXPECT_FALSE(WireReadModel(wire, {}, &back, &err));
  EXPECT_NE(err.find("non-finite"), std::string::npos) << err;

  // Every truncation of a reply is rejected without allocating its claims.
  m.meshes[0].vertices[1].position.x = 0.f;
  wire.clear();
  WireWriteModel(m, &wire);
  for (size_t n = 0; n < wire.size(); ++n) {
    std::vector<uint8_t> cut(wire.begin(), wire.begin() + long(n));
    EXPECT_FALSE(WireReadModel(cut, {}, &back, &err)) << n;
  }
  // A count claiming 2^60 vertices.
  std::vector<uint8_t> lie = wire;
  const size_t countAt = 4 + 4 + 1 + 8 + m.file.size() + 8 + 8 + m.meshes[0].name.size();
  uint64_t huge = 1ull << 60;
  std::memcpy(lie.data() + countAt, &huge, 8);
  EXPECT_FALSE(WireReadModel(lie, {}, &back, &err));
}
