// Hostile SDKMESH and SDKMESH_ANIM files through the import worker:
// truncated, garbage and oversized counts each end with an error naming the
// file and what was wrong. The worker runs with a 5-second wall limit, so a
// reader that loops or stalls would fail with the limit's message instead.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "ArenaGenSdkMesh.h"
#include "scene/IsolatedImport.h"
#include "ScratchDir.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {

ImportLimits ShortLimits() {
  ImportLimits l;
  l.memoryMiB = 512;
  l.cpuSeconds = 5;
  l.wallSeconds = 5;
  l.replyMiB = 64;
  return l;
}

// Writes bytes to a temporary file named name and imports it; returns the error ("" on success).
std::string Import(const std::string& name, const std::vector<uint8_t>& bytes) {
  const fs::path file = drrtest::ProcessScratchDir() / name;
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  ModelLoadOptions opts;
  opts.animationsOnly = name.find("_anim") != std::string::npos;
  ModelData m;
  std::string error;
  const bool ok = ImportModelIsolated(file.string(), opts, ShortLimits(), &m, &error);
  EXPECT_TRUE(ok || error.find(file.string()) != std::string::npos) << "the error must name the file: " << error;
  fs::remove(file);
  return ok ? "" : error;
}

template <class T>
void Poke(std::vector<uint8_t>& b, size_t at, T v) {
  std::memcpy(b.data() + at, &v, sizeof(T));
}

void ExpectError(const std::string& error, const std::string& phrase) {
  EXPECT_NE(error.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << error;
}

}  // namespace

TEST(SdkMeshHostile, TruncatedMesh) {
  const std::vector<uint8_t> good = sdkgen::EncodeMesh(sdkgen::TestMesh());
  EXPECT_EQ(Import("good.sdkmesh", good), "");
  ExpectError(Import("short.sdkmesh", {good.begin(), good.begin() + 50}), "shorter than the 104-byte");
  ExpectError(Import("cut.sdkmesh", {good.begin(), good.begin() + good.size() / 2}), "do not fit");
  ExpectError(Import("cut_end.sdkmesh", {good.begin(), good.end() - 3}), "do not fit");
}

TEST(SdkMeshHostile, GarbageMesh) {
  std::vector<uint8_t> garbage(4096);
  for (size_t i = 0; i < garbage.size(); ++i) garbage[i] = uint8_t((i * 2654435761u) >> 13);
  ExpectError(Import("garbage.sdkmesh", garbage), "version");
  ExpectError(Import("empty.sdkmesh", {}), "shorter than");
}

TEST(SdkMeshHostile, OversizedCountsInMesh) {
  const std::vector<uint8_t> good = sdkgen::EncodeMesh(sdkgen::TestMesh());
  std::vector<uint8_t> b = good;
  Poke<uint32_t>(b, 36, 0xFFFFFFF0u);  // NumIndexBuffers
  ExpectError(Import("ibs.sdkmesh", b), "index buffer headers");
  b = good;
  Poke<uint64_t>(b, 104, uint64_t(1) << 60);  // vertex buffer 0: NumVertices
  ExpectError(Import("vertices.sdkmesh", b), "vertex buffer 0");
  b = good;
  const size_t subset0 = 104 + 3 * 288 + 3 * 32 + 3 * 224;
  Poke<uint64_t>(b, subset0 + 120, uint64_t(1) << 40);  // subset 0: IndexCount
  ExpectError(Import("subset.sdkmesh", b), "past the index buffer");
}

TEST(SdkMeshHostile, TruncatedGarbageAndOversizedAnim) {
  const std::vector<uint8_t> good = sdkgen::EncodeAnim(sdkgen::kTestFps, sdkgen::TestAnim());
  EXPECT_EQ(Import("good.sdkmesh_anim", good), "");
  ExpectError(Import("short.sdkmesh_anim", {good.begin(), good.begin() + 20}), "shorter than the 40-byte");
  ExpectError(Import("cut.sdkmesh_anim", {good.begin(), good.begin() + good.size() / 2}), "beyond");
  std::vector<uint8_t> garbage(2048, 0xA5);
  ExpectError(Import("garbage.sdkmesh_anim", garbage), "version");
  std::vector<uint8_t> b = good;
  Poke<uint32_t>(b, 16, 0x7FFFFFFFu);  // NumAnimationKeys
  ExpectError(Import("keys.sdkmesh_anim", b), "need more bytes");
  b = good;
  Poke<uint32_t>(b, 12, 0xFFFFFFFFu);  // NumFrames
  ExpectError(Import("frames.sdkmesh_anim", b), "frame records");
  b = good;
  Poke<uint32_t>(b, 16, 0u);
  ExpectError(Import("nokeys.sdkmesh_anim", b), "no animation keys");
}
