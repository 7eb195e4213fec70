// The upscalers' compute passes (--upscale-shader compute, ComputeUpscale.h)
// against their pixel shaders: the same frames rendered both ways in this
// process, under validation, equal within one 8-bit step on interior pixels
// (a driver may round a compute shader's float arithmetic differently from a
// pixel shader's, and the compute shaders encode sRGB themselves where the
// pixel shaders' target does: llvmpipe's encoding is an approximation that
// differs from the exact curve by one step in some values);
// the original's filters ignore the option; a planted wrong compute shader
// is caught (the comparison really sees the compute path); without the
// compute shaders the pixel shaders run.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "SampleTestKit.h"
#include "ShaderLibrary.h"

namespace drr {
namespace {

using testkit::FreshRun;
using testkit::RenderFresh;

constexpr uint32_t kW = 256, kH = 144;
constexpr uint32_t kBorder = 2;  // the edge pixels' clamped taps are compared too, but not asserted

struct ComputeCase {
  const char* name;
  Filter filter;
  double secondaryPercent;  // 100: no secondary upscale
  int frames;               // TAAU: enough frames for the history to matter
  bool bgra = false;        // a BGRA8 sRGB back buffer (--headless-bgra), as many windows have
};

const ComputeCase kCases[] = {
    {"Nearest", Filter::UpscaleNearest, 100, 2},
    {"Bilinear", Filter::UpscaleBilinear, 100, 2},
    {"Directional", Filter::UpscaleDirectional, 100, 2},
    {"CatmullRom", Filter::UpscaleCatmullRom, 100, 2},
    {"Lanczos3", Filter::UpscaleLanczos3, 100, 2},
    {"GaussianUnsharp", Filter::UpscaleGaussianUnsharp, 100, 2},
    {"EdgeAdaptiveAndSharpen", Filter::UpscaleEdgeAdaptive, 100, 2},
    {"TemporalUpsample", Filter::TAAU, 100, 8},
    {"TemporalUpsampleFast", Filter::TAAUFast, 100, 8},
    {"CatmullRomThenSecondary", Filter::UpscaleCatmullRom, 83.33, 2},
    {"EdgeAdaptiveThenSecondary", Filter::UpscaleEdgeAdaptive, 75, 2},
    {"TemporalUpsampleThenSecondary", Filter::TAAU, 83.33, 8},
    // A 25 % secondary target under a 0.71 viewport: 2.84 viewport texels per
    // output pixel, more than the tiles have room for: the direct versions run.
    {"TemporalUpsampleDirect", Filter::TAAU, 25, 8},
    {"TemporalUpsampleFastDirect", Filter::TAAUFast, 25, 8},
    {"Lanczos3Direct", Filter::UpscaleLanczos3, 25, 2},
    {"EdgeAdaptiveDirect", Filter::UpscaleEdgeAdaptive, 25, 2},
    // The back buffer in BGRA order: the shader swaps red and blue for the
    // scratch whose bits are copied into it.
    {"TemporalUpsampleBgra", Filter::TAAU, 100, 8, true},
    {"CatmullRomThenSecondaryBgra", Filter::UpscaleCatmullRom, 83.33, 2, true},
};

void PrintTo(const ComputeCase& c, std::ostream* os) { *os << c.name; }

Options CaseOptions(const ComputeCase& c, UpscaleShader shader) {
  Options o = testkit::HeadlessOptions(kW, kH, 3.0);
  o.filter = c.filter;
  o.scaleX = o.scaleY = 0.71f;
  o.secondaryScreenPercentage = c.secondaryPercent;
  o.upscaleShader = shader;
  o.headlessBgra = c.bgra;
  return o;
}

class UpscaleCompute : public ::testing::TestWithParam<ComputeCase> {};

TEST_P(UpscaleCompute, EqualsThePixelShaderWithinOneStep) {
  const ComputeCase& c = GetParam();
  const FreshRun pixel = RenderFresh(CaseOptions(c, UpscaleShader::Pixel), c.frames);
  const FreshRun compute = RenderFresh(CaseOptions(c, UpscaleShader::Compute), c.frames);
  const testkit::Diff d = testkit::Compare(compute.image, pixel.image, kBorder);
  std::printf("[compute] %s: max %d, %llu interior pixels differ\n", c.name, d.maxAbs,
              static_cast<unsigned long long>(d.differing));
  EXPECT_LE(d.maxAbs, 1) << d.differing << " pixels differ";
  EXPECT_EQ(compute.passes, pixel.passes);  // the same passes, counted by the same names
}

INSTANTIATE_TEST_SUITE_P(Upscalers, UpscaleCompute, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// The original's filters stay pixel shaders: the option changes nothing.
TEST(UpscaleComputeOption, OriginalFiltersIgnoreIt) {
  for (Filter f : {Filter::Point, Filter::TAA}) {
    const ComputeCase c{"original", f, 100, 4};
    const Image pixel = RenderFresh(CaseOptions(c, UpscaleShader::Pixel), c.frames).image;
    const Image compute = RenderFresh(CaseOptions(c, UpscaleShader::Compute), c.frames).image;
    EXPECT_EQ(testkit::Compare(compute, pixel).maxAbs, 0) << GetFilterInfo(f).option;
  }
}

namespace fs = std::filesystem;

// A copy of the build's shader folder, which `change` edits, and the image
// of TAAU run with it in compute mode beside the image of the pixel shaders.
struct EditedShaders {
  Image pixel, compute;
};
EditedShaders RenderWithEditedShaders(const char* folder, const std::function<void(const fs::path&)>& change,
                                      double secondaryPercent = 100) {
  const fs::path from = ShaderLibrary::DefaultSpvDir("");
  const fs::path to = fs::path(testing::TempDir()) / folder;
  fs::remove_all(to);
  fs::copy(from, to);
  change(to);
  const ComputeCase c{folder, Filter::TAAU, secondaryPercent, 4};
  Options compute = CaseOptions(c, UpscaleShader::Compute);
  compute.shaderDir = to.string();
  EditedShaders r{RenderFresh(CaseOptions(c, UpscaleShader::Pixel), c.frames).image,
                  RenderFresh(compute, c.frames).image};
  fs::remove_all(to);
  return r;
}

// A shader folder whose compute TAAU is the nearest-texel compute upscaler:
// the comparison above must fail on it, so it does see the compute path.
TEST(UpscaleComputeOption, PlantedWrongComputeShaderIsCaught) {
  const EditedShaders r = RenderWithEditedShaders("drr_planted_compute_shaders", [](const fs::path& to) {
    fs::copy_file(to / "UpscaleSpatial_NearestCS.spv", to / "UpscaleTemporal_TemporalUpsampleCS.spv",
                  fs::copy_options::overwrite_existing);
  });
  EXPECT_GT(testkit::Compare(r.compute, r.pixel, kBorder).maxAbs, 1);
}

// The same at 2.84 viewport texels per output pixel with the direct version
// planted wrong: the comparison sees the version without the tile there.
TEST(UpscaleComputeOption, PlantedWrongDirectShaderIsCaught) {
  const EditedShaders r = RenderWithEditedShaders(
      "drr_planted_direct_shaders",
      [](const fs::path& to) {
        fs::copy_file(to / "UpscaleSpatial_NearestCS.spv", to / "UpscaleTemporal_TemporalUpsampleDirectCS.spv",
                      fs::copy_options::overwrite_existing);
      },
      25);
  EXPECT_GT(testkit::Compare(r.compute, r.pixel, kBorder).maxAbs, 1);
}

// Without its compute shaders the sample falls back to the pixel shaders
// (with a notice on stderr): the same image, exactly.
TEST(UpscaleComputeOption, MissingComputeShadersFallBackToThePixelShaders) {
  const EditedShaders r = RenderWithEditedShaders("drr_no_compute_shaders", [](const fs::path& to) {
    std::vector<fs::path> compute;
    for (const fs::directory_entry& e : fs::directory_iterator(to))
      if (e.path().filename().string().ends_with("CS.spv")) compute.push_back(e.path());
    for (const fs::path& p : compute) fs::remove(p);
  });
  EXPECT_EQ(testkit::Compare(r.compute, r.pixel).maxAbs, 0);
}

}  // namespace
}  // namespace drr
