// Hostile DDS files: truncated, garbage, oversized counts and sizes, and
// layouts the reader does not support. Each must end with an error that names
// the file and the offending value, in process and through the import worker,
// without allocating what the header claims.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include <unistd.h>

#include "scene/DdsFormat.h"
#include "scene/DdsReader.h"
#include "scene/IsolatedImport.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {

std::vector<uint8_t> ArenaBytes(const char* name) {
  std::ifstream f(fs::path(DRR_ARENA_DIR) / "dds" / name, std::ios::binary);
  return std::vector<uint8_t>((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

void Set32(std::vector<uint8_t>* b, size_t offset, uint32_t v) { std::memcpy(b->data() + offset, &v, 4); }

class DdsHostile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drr_dds_hostile_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Writes `bytes` as `name` and expects both loaders to fail with an error
  // naming the file and containing `expected`.
  void ExpectRejected(const std::string& name, const std::vector<uint8_t>& bytes, const std::string& expected) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    TextureData t;
    std::string local, isolated;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_FALSE(LoadTextureFile(path, TextureKind::Color, {}, &t, &local));
    EXPECT_EQ(local.rfind(path, 0), 0u) << local;
    EXPECT_NE(local.find(expected), std::string::npos) << local;
    EXPECT_FALSE(IsolatedTextureLoader()(path, TextureKind::Color, {}, &t, &isolated));
    EXPECT_NE(isolated.find(path), std::string::npos) << isolated;
    EXPECT_NE(isolated.find(expected), std::string::npos) << isolated;
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    std::printf("  %-12s rejected in %.2f s (in process and through the worker): %s\n", name.c_str(), took.count(),
                local.c_str());
  }
  fs::path dir_;
};

}  // namespace

TEST_F(DdsHostile, TruncatedFiles) {
  const auto good = ArenaBytes("bc1_mips.dds");
  ASSERT_GT(good.size(), 200u);
  ExpectRejected("empty.dds", {}, "texture has zero size");
  ExpectRejected("header.dds", std::vector<uint8_t>(good.begin(), good.begin() + 100), "truncated DDS file (100 bytes");
  ExpectRejected("mip0.dds", std::vector<uint8_t>(good.begin(), good.begin() + 200),
                 "mip 0 (64x32, 1024 bytes at offset 128)");
  ExpectRejected("lastmip.dds", std::vector<uint8_t>(good.begin(), good.end() - 1), "mip 6 (1x1, 8 bytes");
  const auto dx10 = ArenaBytes("bc1_dx10.dds");
  ExpectRejected("dx10.dds", std::vector<uint8_t>(dx10.begin(), dx10.begin() + 140), "the DX10 header needs 148");
}

TEST_F(DdsHostile, Garbage) {
  std::mt19937 rng(7);
  std::vector<uint8_t> noise(4096);
  for (auto& b : noise) b = uint8_t(rng());
  ExpectRejected("noise.dds", noise, "not a DDS file");
  std::memcpy(noise.data(), "DDS ", 4);
  Set32(&noise, dds::kOffSize, dds::kHeaderSize);
  Set32(&noise, dds::kOffPixelFormat, dds::kPixelFormatSize);
  Set32(&noise, dds::kOffCaps2, 0);
  Set32(&noise, dds::kOffPixelFormat + dds::kPfFlags, dds::kPfFourCCFlag);
  Set32(&noise, dds::kOffPixelFormat + dds::kPfFourCC, dds::FourCC('Z', 'Z', 'Z', 'Z'));
  ExpectRejected("fourcc.dds", noise, "unsupported DDS pixel format (flags 0x4, FourCC 'ZZZZ'");
}

TEST_F(DdsHostile, OversizedCountsAndSizes) {
  auto bytes = ArenaBytes("bc1_mips.dds");
  Set32(&bytes, dds::kOffMipCount, 0xFFFFFFFFu);
  ExpectRejected("mips.dds", bytes, "mip count 4294967295 exceeds the 7 levels of a 64x32 texture");
  bytes = ArenaBytes("bc1_mips.dds");
  Set32(&bytes, dds::kOffWidth, 0xFFFFFFFFu);
  ExpectRejected("width.dds", bytes, "DDS size 4294967295x32 is out of range");
  // The largest accepted size with the data of a small file: rejected at the
  // first mip's bounds check, before any allocation of its 128 MiB.
  bytes = ArenaBytes("bc1_mips.dds");
  Set32(&bytes, dds::kOffWidth, 16384), Set32(&bytes, dds::kOffHeight, 16384), Set32(&bytes, dds::kOffMipCount, 15);
  ExpectRejected("huge.dds", bytes, "mip 0 (16384x16384, 134217728 bytes at offset 128) runs past the end");
  bytes = ArenaBytes("bc1_mips.dds");
  Set32(&bytes, dds::kOffWidth, 66);
  ExpectRejected("odd.dds", bytes, "66x32 is not a multiple of 4");
}

TEST_F(DdsHostile, UnsupportedLayouts) {
  auto bytes = ArenaBytes("bc1_mips.dds");
  Set32(&bytes, dds::kOffCaps2, 0xFE00);  // a cube map with all six faces
  ExpectRejected("cube.dds", bytes, "cube maps and volume textures are not supported (caps2 0xfe00)");
  bytes = ArenaBytes("bc1_dx10.dds");
  Set32(&bytes, dds::kDataOffset + dds::kDx10ArraySize, 6);
  ExpectRejected("array.dds", bytes, "array size 6); only single 2D textures are supported");
  bytes = ArenaBytes("bc1_dx10.dds");
  Set32(&bytes, dds::kDataOffset + dds::kDx10Format, 2);  // R32G32B32A32_FLOAT
  ExpectRejected("float.dds", bytes, "DX10 header names DXGI format 2, which is not supported");
}

// A valid file followed by a gigabyte (sparse) of trailing bytes loads: the
// reader takes the headers, then only the bytes of the mips they describe.
TEST_F(DdsHostile, TrailingBytesAreNotRead) {
  const auto good = ArenaBytes("bc1_mips.dds");
  const std::string path = (dir_ / "trailing.dds").string();
  {
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(good.data()), std::streamsize(good.size()));
    f.seekp(std::streamoff(1) << 30);
    f.put('x');
  }
  ASSERT_GT(fs::file_size(path), uint64_t(1) << 30);
  DdsImage img;
  std::string err;
  ASSERT_TRUE(ReadDdsFile(path, 16384, &img, &err)) << err;
  ASSERT_EQ(img.mips.size(), 7u);
  EXPECT_EQ(img.mips[6].rgba, std::vector<uint8_t>(good.end() - 8, good.end()));
  TextureData t;
  EXPECT_TRUE(IsolatedTextureLoader()(path, TextureKind::Color, {}, &t, &err)) << err;
}
