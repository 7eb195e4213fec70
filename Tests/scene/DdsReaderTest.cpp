// The DDS reader and the CPU BC decoder on the Arena generator's DDS set
// (tools/ArenaGenDds.h): headers, formats, mip sizes and offsets, colour
// spaces by texture kind, the isolated import path, and hand-made blocks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "scene/DdsBlocks.h"
#include "scene/DdsReader.h"
#include "scene/IsolatedImport.h"

using namespace drr;
using namespace d3dl;
namespace fs = std::filesystem;

namespace {

std::string ArenaDds(const char* name) { return (fs::path(DRR_ARENA_DIR) / "dds" / name).string(); }

uint64_t FileSize(const std::string& path) { return fs::file_size(path); }

DdsImage Read(const char* name) {
  DdsImage img;
  std::string err;
  EXPECT_TRUE(ReadDdsFile(ArenaDds(name), 16384, &img, &err)) << err;
  return img;
}

// Mip i of a w x h texture has sides max(1, w >> i) and exactly the bytes its format needs.
void ExpectChain(const DdsImage& img, uint32_t w, uint32_t h, size_t mips) {
  ASSERT_EQ(img.mips.size(), mips);
  for (size_t i = 0; i < mips; ++i) {
    EXPECT_EQ(img.mips[i].width, std::max(1u, w >> i)) << i;
    EXPECT_EQ(img.mips[i].height, std::max(1u, h >> i)) << i;
    EXPECT_EQ(img.mips[i].rgba.size(), TextureMipBytes(img.format, img.mips[i].width, img.mips[i].height)) << i;
  }
}

uint64_t DataBytes(const DdsImage& img) {
  uint64_t b = 0;
  for (const auto& m : img.mips) b += m.rgba.size();
  return b;
}

}  // namespace

TEST(DdsReader, Bc1FullChainFromTheDx9Header) {
  DdsImage img = Read("bc1_mips.dds");
  EXPECT_EQ(img.format, DXGI_FORMAT_BC1_UNORM);
  EXPECT_EQ(img.pixelFormat, "DXT1");
  ExpectChain(img, 64, 32, 7);
  EXPECT_EQ(img.mips[0].rgba.size(), 16u * 8u * 8u);  // 16x8 blocks of 8 bytes
  EXPECT_EQ(img.mips[6].rgba.size(), 8u);             // 1x1: one whole block
  EXPECT_EQ(DataBytes(img) + 128, FileSize(ArenaDds("bc1_mips.dds")));
}

TEST(DdsReader, Bc3FullChainWithAlpha) {
  DdsImage img = Read("bc3_mips.dds");
  EXPECT_EQ(img.format, DXGI_FORMAT_BC3_UNORM);
  ExpectChain(img, 32, 32, 6);
  EXPECT_EQ(img.mips[0].rgba.size(), 8u * 8u * 16u);
  EXPECT_EQ(DataBytes(img) + 128, FileSize(ArenaDds("bc3_mips.dds")));
  TextureData t;
  std::string err;
  ASSERT_TRUE(LoadTextureFile(ArenaDds("bc3_mips.dds"), TextureKind::Color, {}, &t, &err)) << err;
  EXPECT_TRUE(t.hasAlpha);
}

TEST(DdsReader, Dx10HeaderMovesTheDataBy20Bytes) {
  DdsImage img = Read("bc1_dx10.dds");
  EXPECT_EQ(img.format, DXGI_FORMAT_BC1_UNORM);
  EXPECT_EQ(img.pixelFormat, "DX10 BC1_UNORM");
  ExpectChain(img, 16, 16, 5);
  EXPECT_EQ(DataBytes(img) + 148, FileSize(ArenaDds("bc1_dx10.dds")));
}

TEST(DdsReader, PlainRgbaMasks) {
  DdsImage img = Read("rgba8.dds");
  EXPECT_EQ(img.format, DXGI_FORMAT_R8G8B8A8_UNORM);
  ExpectChain(img, 16, 8, 1);
  std::ifstream f(ArenaDds("rgba8.dds"), std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_EQ(img.mips[0].rgba, std::vector<uint8_t>(bytes.begin() + 128, bytes.end()));
}

TEST(DdsTexture, DiffuseMapsTakeTheSrgbFormLikeTheOriginal) {
  TextureData c, n, s, plain;
  std::string err;
  ASSERT_TRUE(LoadTextureFile(ArenaDds("bc1_mips.dds"), TextureKind::Color, {}, &c, &err)) << err;
  ASSERT_TRUE(LoadTextureFile(ArenaDds("bc1_mips.dds"), TextureKind::Normal, {}, &n, &err)) << err;
  ASSERT_TRUE(LoadTextureFile(ArenaDds("bc3_mips.dds"), TextureKind::Specular, {}, &s, &err)) << err;
  ASSERT_TRUE(LoadTextureFile(ArenaDds("rgba8.dds"), TextureKind::Color, {}, &plain, &err)) << err;
  EXPECT_EQ(c.format, DXGI_FORMAT_BC1_UNORM_SRGB);
  EXPECT_EQ(n.format, DXGI_FORMAT_BC1_UNORM);
  EXPECT_EQ(s.format, DXGI_FORMAT_BC3_UNORM);
  EXPECT_EQ(plain.format, DXGI_FORMAT_R8G8B8A8_UNORM_SRGB);
  EXPECT_TRUE(c.mipsFromFile);
  EXPECT_EQ(c.mips.size(), 7u);
  EXPECT_EQ(c.mips[0].rgba.size() * 8, 64u * 32u * 4u);  // BC1: 4 bits a texel against RGBA8's 32
  EXPECT_EQ(c.Bytes(), 1024u + 256 + 64 + 16 + 8 + 8 + 8);  // mips below 4x4 take a whole block
  EXPECT_EQ(c.BytesAsRgba8(), 4u * (2048 + 512 + 128 + 32 + 8 + 2 + 1));
  EXPECT_EQ(plain.mips.size(), 5u);            // one mip in the file: the chain is built, 16x8 .. 1x1
  GenerateMipChain(&c);
  EXPECT_EQ(c.mips.size(), 7u);
  EXPECT_EQ(c.mips[0].rgba.size(), 16u * 8u * 8u);
}

TEST(DdsTexture, TheImportWorkerHandsOverEveryMipUnchanged) {
  TextureData local, isolated;
  std::string err;
  ASSERT_TRUE(LoadTextureFile(ArenaDds("bc3_mips.dds"), TextureKind::Color, {}, &local, &err)) << err;
  ASSERT_TRUE(IsolatedTextureLoader()(ArenaDds("bc3_mips.dds"), TextureKind::Color, {}, &isolated, &err)) << err;
  EXPECT_EQ(isolated.format, local.format);
  ASSERT_EQ(isolated.mips.size(), local.mips.size());
  for (size_t i = 0; i < local.mips.size(); ++i) EXPECT_EQ(isolated.mips[i].rgba, local.mips[i].rgba) << i;
  EXPECT_TRUE(isolated.hasAlpha);
}

TEST(BcDecoder, Bc1FourAndThreeColourBlocks) {
  // c0 red, c1 blue; all indices 2: two thirds red, one third blue.
  const uint8_t four[8] = {0x00, 0xF8, 0x1F, 0x00, 0xAA, 0xAA, 0xAA, 0xAA};
  std::vector<uint8_t> rgba;
  ASSERT_TRUE(DecodeBcMip(DXGI_FORMAT_BC1_UNORM, four, 4, 4, &rgba));
  EXPECT_EQ(std::vector<uint8_t>(rgba.begin(), rgba.begin() + 4), (std::vector<uint8_t>{170, 0, 85, 255}));
  // c0 <= c1: three colours and transparent black at index 3.
  const uint8_t three[8] = {0x1F, 0x00, 0x00, 0xF8, 0xFF, 0xFF, 0xFF, 0xFF};
  ASSERT_TRUE(DecodeBcMip(DXGI_FORMAT_BC1_UNORM, three, 2, 2, &rgba));
  ASSERT_EQ(rgba.size(), 16u);
  EXPECT_EQ(std::vector<uint8_t>(rgba.begin(), rgba.begin() + 4), (std::vector<uint8_t>{0, 0, 0, 0}));
}

TEST(BcDecoder, Bc3AlphaAndBc4Bc5Channels) {
  // Alpha endpoints 255 and 0 (eight values), every index 2: (6 * 255 + 0) / 7 = 219 rounded.
  uint8_t bc3[16] = {255, 0, 0x92, 0x24, 0x49, 0x92, 0x24, 0x49, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0, 0, 0};
  std::vector<uint8_t> rgba;
  ASSERT_TRUE(DecodeBcMip(DXGI_FORMAT_BC3_UNORM, bc3, 4, 4, &rgba));
  for (size_t i = 3; i < rgba.size(); i += 4) EXPECT_EQ(rgba[i], 219) << i;
  ASSERT_TRUE(DecodeBcMip(DXGI_FORMAT_BC4_UNORM, bc3, 4, 4, &rgba));
  EXPECT_EQ(std::vector<uint8_t>(rgba.begin(), rgba.begin() + 4), (std::vector<uint8_t>{219, 0, 0, 255}));
  ASSERT_TRUE(DecodeBcMip(DXGI_FORMAT_BC5_UNORM, bc3, 4, 4, &rgba));
  EXPECT_EQ(rgba[1], 255);  // the second half's endpoints 0xFF 0xFF: every value 255
  EXPECT_FALSE(DecodeBcMip(DXGI_FORMAT_BC4_SNORM, bc3, 4, 4, &rgba));
}

TEST(BcDecoder, FallbackExpandsToRgba8InTheSameColourSpace) {
  TextureData c;
  std::string err;
  ASSERT_TRUE(LoadTextureFile(ArenaDds("bc1_mips.dds"), TextureKind::Color, {}, &c, &err)) << err;
  auto shared = std::make_shared<const TextureData>(c);
  EXPECT_EQ(TextureForDevice(shared, true, &err).get(), shared.get());
  auto expanded = TextureForDevice(shared, false, &err);
  ASSERT_TRUE(expanded) << err;
  EXPECT_EQ(expanded->format, DXGI_FORMAT_R8G8B8A8_UNORM_SRGB);
  ASSERT_EQ(expanded->mips.size(), 7u);
  EXPECT_EQ(expanded->Bytes(), c.BytesAsRgba8());
  setenv("DRR_BC_DECODE", "cpu", 1);
  EXPECT_NE(TextureForDevice(shared, true, &err).get(), shared.get());
  unsetenv("DRR_BC_DECODE");
}

// With DRR_ORIGINAL_MEDIA naming the original's "Dynamic Resolution Rendering
// Update" folder: every .dds under media/ loads, and the bytes its textures
// take on the GPU (BC data as it is) are printed against the same textures
// expanded to RGBA8. Skipped, saying so, without that folder.
TEST(DdsOriginalMedia, EveryFileLoadsAndStaysCompressed) {
  const char* root = std::getenv("DRR_ORIGINAL_MEDIA");
  if (!root || !fs::is_directory(fs::path(root) / "media"))
    GTEST_SKIP() << "DRR_ORIGINAL_MEDIA does not name the original's folder: the original's DDS media was not tested";
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(root) / "media"))
    if (e.is_regular_file() && e.path().extension() == ".dds") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  uint64_t gpu = 0, rgba8 = 0;
  size_t loaded = 0;
  for (const auto& f : files) {
    TextureData t;
    std::string err;
    if (fs::file_size(f) == 0) {
      std::printf("  %-40s empty in this copy (not counted)\n", f.filename().string().c_str());
      continue;
    }
    ASSERT_TRUE(LoadTextureFile(f.string(), TextureKind::Color, {}, &t, &err)) << err;
    std::printf("  %-40s %-16s %5ux%-5u %2zu mips %9llu bytes (RGBA8 %9llu)\n", f.filename().string().c_str(),
                TextureFormatName(t.format), t.Width(), t.Height(), t.mips.size(), (unsigned long long)t.Bytes(),
                (unsigned long long)t.BytesAsRgba8());
    gpu += t.Bytes(), rgba8 += t.BytesAsRgba8(), ++loaded;
  }
  std::printf("%zu DDS files: %llu bytes on the GPU as loaded, %llu bytes expanded to RGBA8 (%.2fx)\n", loaded,
              (unsigned long long)gpu, (unsigned long long)rgba8, gpu ? double(rgba8) / double(gpu) : 0.0);
  EXPECT_GT(loaded, 0u);
  EXPECT_LT(gpu, rgba8);
}
