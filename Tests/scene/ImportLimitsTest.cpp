// Import limits that grow with the input (ImportLimits.h): a small file gets
// seconds of CPU and wall time, a large one up to the caps; a truncated file
// of every format the import accepts ends with an error naming it, under the
// small limit; the largest valid model of assimp-testmodels still loads.
// Times are printed, never asserted: what is asserted is which limit applied.
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "imageio/ImageFile.h"
#include "scene/IsolatedImport.h"
#include "ScratchDir.h"

using namespace drr;
namespace fs = std::filesystem;

namespace {

const fs::path kModels = "/usr/share/assimp/models";
constexpr size_t kTruncatedBytes = 30;  // the size of the PLY header below

// A folder of its own for each file, so that no companion counts.
fs::path FreshDir(const std::string& name) {
  static int made = 0;
  fs::path d = drrtest::ProcessScratchDir() / std::to_string(made++) / name;
  fs::create_directories(d.parent_path());
  return d;
}

void WriteBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

std::string FirstBytes(const fs::path& p, size_t n) {
  std::ifstream f(p, std::ios::binary);
  std::string s(n, '\0');
  f.read(s.data(), std::streamsize(n));
  s.resize(size_t(f.gcount()));
  return s;
}

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// The model extensions Assimp imports, lower case, without the dot.
std::set<std::string> AssimpExtensions() {
  Assimp::Importer importer;
  std::string list;
  importer.GetExtensionList(list);  // "*.3ds;*.obj;..."
  std::set<std::string> out;
  size_t at = 0;
  while (at < list.size()) {
    size_t end = list.find(';', at);
    if (end == std::string::npos) end = list.size();
    std::string e = list.substr(at, end - at);
    if (e.rfind("*.", 0) == 0) e = e.substr(2);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (!e.empty()) out.insert(e);
    at = end + 1;
  }
  return out;
}

// The first file (in name order) of assimp-testmodels for each extension.
std::map<std::string, fs::path> OneModelPerExtension() {
  const std::set<std::string> extensions = AssimpExtensions();
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(kModels))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::map<std::string, fs::path> out;
  for (const auto& f : files) {
    std::string e = f.extension().string();
    if (e.size() < 2) continue;
    e = e.substr(1);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extensions.count(e)) out.emplace(e, f);
  }
  return out;
}

// One valid 8x8 image per texture format the loader lists (TextureLoader.h),
// made here; DDS by hand (an uncompressed RGBA8 header and texels).
std::vector<fs::path> OneImagePerFormat() {
  std::vector<fs::path> out;
  const std::vector<uint8_t> rgba(8 * 8 * 4, 200);
  const std::vector<float> rgbF(8 * 8 * 3, 0.5f);
  std::string err;
  for (const char* ext : {"png", "jpg", "tga", "bmp", "tif"}) {
    const fs::path p = FreshDir(std::string("image.") + ext);
    if (WriteImageFile(p.string(), 8, 8, 4, rgba.data(), &err)) out.push_back(p);
  }
  for (const char* ext : {"hdr", "exr"}) {
    const fs::path p = FreshDir(std::string("image.") + ext);
    if (WriteImageFileFloat(p.string(), 8, 8, 3, rgbF.data(), &err)) out.push_back(p);
  }
  std::vector<uint32_t> dds = {0x20534444u, 124, 0x100f, 8, 8, 32, 0, 1};  // magic, size, flags, h, w, pitch
  dds.resize(1 + 31, 0);
  dds[1 + 18] = 32, dds[1 + 19] = 0x41, dds[1 + 21] = 32;  // pixel format: size, RGB|alpha, 32 bits
  dds[1 + 22] = 0xff, dds[1 + 23] = 0xff00, dds[1 + 24] = 0xff0000, dds[1 + 25] = 0xff000000u;
  dds[1 + 26] = 0x1000;  // caps: texture
  dds.resize(dds.size() + 8 * 8, 0xffffffffu);
  const fs::path p = FreshDir("image.dds");
  WriteBytes(p, std::string(reinterpret_cast<const char*>(dds.data()), dds.size() * 4));
  out.push_back(p);
  return out;
}

struct Outcome {
  bool imported = false;
  std::string error;
  double seconds = 0;
};

// Imports path (a model, or a texture for the image formats) in the worker
// under the default limits, the ones a user gets.
Outcome ImportWithDefaults(const fs::path& path, bool texture) {
  Outcome o;
  const auto start = std::chrono::steady_clock::now();
  if (texture) {
    TextureData t;
    o.imported = ImportTextureIsolated(path.string(), TextureKind::Color, 16384, ImportLimits{}, &t, &o.error);
  } else {
    ModelData m;
    o.imported = ImportModelIsolated(path.string(), {}, ImportLimits{}, &m, &o.error);
  }
  o.seconds = Seconds(start);
  return o;
}

}  // namespace

TEST(ImportLimits, GrowWithTheInputUpToTheCaps) {
  const ImportLimits caps;
  const ImportLimits tiny = caps.ForInput(kTruncatedBytes);
  EXPECT_EQ(tiny.cpuSeconds, kImportCpuScale.baseSeconds);
  EXPECT_EQ(tiny.wallSeconds, kImportWallScale.baseSeconds);
  EXPECT_LE(tiny.cpuSeconds, 4u * kImportSanitizerSlowdown) << "a tiny file must end within seconds";
  const ImportLimits oneMiB = caps.ForInput(1 << 20);
  EXPECT_EQ(oneMiB.cpuSeconds, kImportCpuScale.baseSeconds + kImportCpuScale.secondsPerMiB);
  EXPECT_EQ(oneMiB.wallSeconds, kImportWallScale.baseSeconds + kImportWallScale.secondsPerMiB);
  const ImportLimits huge = caps.ForInput(uint64_t(1) << 50);
  EXPECT_EQ(huge.cpuSeconds, 60u);
  EXPECT_EQ(huge.wallSeconds, 120u);
  EXPECT_EQ(huge.memoryMiB, caps.memoryMiB);
  EXPECT_EQ(huge.replyMiB, caps.replyMiB);
  ImportLimits low;
  low.cpuSeconds = 1;
  low.wallSeconds = 4;
  EXPECT_EQ(low.ForInput(1 << 20).cpuSeconds, 1u) << "the caps bound the scaled limits";
  EXPECT_EQ(low.ForInput(1 << 20).wallSeconds, 4u);
}

TEST(ImportLimits, CompanionFilesCountAndOthersDoNot) {
  const fs::path gltf = FreshDir("scene.gltf");
  WriteBytes(gltf, std::string(100, ' '));
  WriteBytes(gltf.parent_path() / "scene.bin", std::string(3 << 20, '\0'));
  WriteBytes(gltf.parent_path() / "scene_textures.png", std::string(1000, '\0'));
  WriteBytes(gltf.parent_path() / "other.bin", std::string(5 << 20, '\0'));
  EXPECT_EQ(ImportInputBytes(gltf.string()), 100u + (3u << 20) + 1000u);
  ImportLimits uncapped;  // caps above the scaled value, also in the sanitizer build's longer scale
  uncapped.cpuSeconds = 1000;
  EXPECT_EQ(ImportLimitsForFile(uncapped, gltf.string()).cpuSeconds,
            kImportCpuScale.baseSeconds + 3 * kImportCpuScale.secondsPerMiB);
  EXPECT_EQ(ImportInputBytes((gltf.parent_path() / "absent.obj").string()), 0u);
}

// The 30-byte header that made Assimp 5.2 loop until the fixed 60-second
// limit: "ply", a format line, and a comment line with nothing after the
// keyword (without its last line break, 29 bytes, it loops as well).
TEST(ImportLimits, TruncatedPlyHeaderEndsWithAnErrorAtTheSmallLimit) {
  const fs::path ply = FreshDir("truncated.ply");
  const std::string header = "ply\nformat ascii 1.0\ncomment \n";
  ASSERT_EQ(header.size(), kTruncatedBytes);
  WriteBytes(ply, header);
  const ImportLimits limits = ImportLimitsForFile(ImportLimits{}, ply.string());
  EXPECT_EQ(limits.cpuSeconds, kImportCpuScale.baseSeconds);
  EXPECT_EQ(limits.wallSeconds, kImportWallScale.baseSeconds);
  const Outcome o = ImportWithDefaults(ply, false);
  EXPECT_FALSE(o.imported);
  EXPECT_NE(o.error.find(ply.string()), std::string::npos) << o.error;
  std::printf("30-byte PLY header: error after %.2f s (limits %u s CPU, %u s wall): %s\n", o.seconds,
              limits.cpuSeconds, limits.wallSeconds, o.error.c_str());
}

// The first 30 bytes of a file of each format: an error naming the file.
TEST(ImportLimits, TruncatedFileOfEveryFormatEndsWithAnError) {
  if (!fs::exists(kModels)) GTEST_SKIP() << kModels << " absent (Debian package assimp-testmodels)";
  std::vector<std::pair<fs::path, bool>> sources;  // (file, is a texture)
  for (const auto& [ext, path] : OneModelPerExtension()) sources.emplace_back(path, false);
  for (const fs::path& p : OneImagePerFormat()) sources.emplace_back(p, true);
  double slowest = 0;
  std::string slowestFile;
  int atCpuLimit = 0;
  for (const auto& [source, texture] : sources) {
    const fs::path cut = FreshDir("truncated" + source.extension().string());
    WriteBytes(cut, FirstBytes(source, kTruncatedBytes));
    EXPECT_EQ(ImportLimitsForFile(ImportLimits{}, cut.string()).cpuSeconds, kImportCpuScale.baseSeconds);
    const Outcome o = ImportWithDefaults(cut, texture);
    EXPECT_FALSE(o.imported) << source << " truncated to " << kTruncatedBytes << " bytes was imported";
    EXPECT_NE(o.error.find(cut.string()), std::string::npos) << source << ": " << o.error;
    if (o.seconds > slowest) slowest = o.seconds, slowestFile = source.string() + ": " + o.error;
    atCpuLimit += o.error.find("s of CPU time") != std::string::npos;
  }
  std::printf("%zu formats truncated to %zu bytes, each an error (%d at the CPU-time limit); slowest %.2f s (%s)\n",
              sources.size(), kTruncatedBytes, atCpuLimit, slowest, slowestFile.c_str());
}

// The largest file of assimp-testmodels (4 MB of IFC), a valid model,
// still imports under the default limits scaled to its size.
TEST(ImportLimits, LargestValidTestModelStillLoads) {
  const fs::path model = kModels / "IFC/AC14-FZK-Haus.ifc";
  if (!fs::exists(model)) GTEST_SKIP() << model << " absent (Debian package assimp-testmodels)";
  const ImportLimits limits = ImportLimitsForFile(ImportLimits{}, model.string());
  const Outcome o = ImportWithDefaults(model, false);
  EXPECT_TRUE(o.imported) << o.error;
  std::printf("%s (%ju bytes): imported in %.2f s (limits %u s CPU, %u s wall)\n", model.c_str(),
              uintmax_t(fs::file_size(model)), o.seconds, limits.cpuSeconds, limits.wallSeconds);
}
