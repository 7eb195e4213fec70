// Replays every build-time HLSL compile (build/shader_manifest.txt) through
// d3dl::CompileHLSL and requires byte-identical SPIR-V, so a shader reloaded
// at run time binds and behaves exactly like the one built with the project.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "RenderTest.h"
#include "ShaderLibrary.h"
#include "d3dl/ShaderCompiler.h"

namespace {

struct ManifestEntry {
  std::string source, entry, stage, output, flags;
  std::vector<std::pair<std::string, std::string>> defines;
};

std::vector<ManifestEntry> ReadManifest() {
  std::vector<ManifestEntry> entries;
  std::ifstream in(DRR_SHADER_MANIFEST);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = drr::SplitFields(line, '|');
    if (f.size() != 6) continue;
    ManifestEntry e{f[0], f[1], f[2], f[4], f[5], {}};
    for (const auto& d : drr::SplitFields(f[3], ',')) {
      if (d.empty()) continue;
      const auto eq = d.find('=');
      e.defines.emplace_back(d.substr(0, eq), eq == std::string::npos ? "" : d.substr(eq + 1));
    }
    entries.push_back(std::move(e));
  }
  return entries;
}

TEST(RuntimeCompiler, MatchesEveryBuildTimeShader) {
  const auto entries = ReadManifest();
  ASSERT_FALSE(entries.empty()) << "no shaders in " << DRR_SHADER_MANIFEST;
  for (const auto& e : entries) {
    SCOPED_TRACE(e.source + " " + e.entry + " (" + e.stage + ")");
    d3dl::ShaderCompileDesc desc;
    desc.SourcePath = e.source;
    desc.EntryPoint = e.entry;
    ASSERT_TRUE(d3dl::ShaderStageFromGlslangName(e.stage, &desc.Stage)) << e.stage;
    desc.Defines = e.defines;
    desc.KeepSemantics = e.flags.find("no-semantics") == std::string::npos;
    std::vector<uint32_t> spirv;
    std::string errors;
    ASSERT_EQ(d3dl::CompileHLSL(desc, &spirv, &errors), d3dl::S_OK) << errors;
    const auto built = drrtest::RenderTest::LoadSpirv(e.output);  // absolute path
    ASSERT_FALSE(built.empty()) << "missing " << e.output;
    EXPECT_EQ(spirv, built) << "runtime SPIR-V differs from " << e.output;
  }
}

TEST(RuntimeCompiler, ReportsErrorsWithTheFileName) {
  d3dl::ShaderCompileDesc desc;
  desc.SourcePath = "broken.hlsl";
  desc.Source = "float4 PSMain() : SV_Target { return undefined_symbol; }\n";
  desc.EntryPoint = "PSMain";
  desc.Stage = d3dl::ShaderStage::Pixel;
  std::vector<uint32_t> spirv;
  std::string errors;
  EXPECT_EQ(d3dl::CompileHLSL(desc, &spirv, &errors), d3dl::E_FAIL);
  EXPECT_NE(errors.find("broken.hlsl"), std::string::npos) << errors;
  EXPECT_NE(errors.find("undefined_symbol"), std::string::npos) << errors;
}

TEST(RuntimeCompiler, RejectsMissingFileAndBadArguments) {
  d3dl::ShaderCompileDesc desc;
  desc.SourcePath = "/nonexistent/dir/shader.hlsl";
  desc.EntryPoint = "main";
  std::vector<uint32_t> spirv;
  std::string errors;
  EXPECT_EQ(d3dl::CompileHLSL(desc, &spirv, &errors), d3dl::E_INVALIDARG);
  EXPECT_NE(errors.find("/nonexistent/dir/shader.hlsl"), std::string::npos) << errors;
  EXPECT_EQ(d3dl::CompileHLSL(desc, nullptr, &errors), d3dl::E_INVALIDARG);
  desc.Source = "float4 PSMain() : SV_Target { return 0; }";
  desc.EntryPoint = "";
  EXPECT_EQ(d3dl::CompileHLSL(desc, &spirv, &errors), d3dl::E_INVALIDARG);
}

TEST(RuntimeCompiler, AppliesTheBindingFormula) {
  // A pixel shader's b1 / t2 / s3 / u1 must land on 72 + 0 + 1, 72 + 16 + 2, 72 + 48 + 3, 72 + 64 + 1.
  d3dl::ShaderCompileDesc desc;
  desc.SourcePath = "formula.hlsl";
  desc.Source =
      "cbuffer C : register(b1) { float4 k; };\n"
      "Texture2D t : register(t2);\nSamplerState s : register(s3);\n"
      "RWTexture2D<float4> u : register(u1);\n"
      "float4 PSMain(float4 p : SV_Position) : SV_Target { u[uint2(p.xy)] = k; return t.Sample(s, p.xy) * k; }\n";
  desc.EntryPoint = "PSMain";
  desc.Stage = d3dl::ShaderStage::Pixel;
  std::vector<uint32_t> spirv;
  std::string errors;
  ASSERT_EQ(d3dl::CompileHLSL(desc, &spirv, &errors), d3dl::S_OK) << errors;
  // Collect OpDecorate <id> Binding <n> (opcode 71, decoration 33).
  std::vector<uint32_t> bindings;
  for (size_t i = 5; i < spirv.size();) {
    const uint32_t count = spirv[i] >> 16, opcode = spirv[i] & 0xffff;
    if (count == 0) break;
    if (opcode == 71 && count == 4 && spirv[i + 2] == 33) bindings.push_back(spirv[i + 3]);
    i += count;
  }
  std::sort(bindings.begin(), bindings.end());
  const std::vector<uint32_t> expected = {
      d3dl::VulkanBinding(d3dl::ShaderStage::Pixel, d3dl::RegisterClass::ConstantBuffer, 1),
      d3dl::VulkanBinding(d3dl::ShaderStage::Pixel, d3dl::RegisterClass::Texture, 2),
      d3dl::VulkanBinding(d3dl::ShaderStage::Pixel, d3dl::RegisterClass::Sampler, 3),
      d3dl::VulkanBinding(d3dl::ShaderStage::Pixel, d3dl::RegisterClass::UnorderedAccess, 1)};
  EXPECT_EQ(bindings, expected);
  EXPECT_EQ(expected, (std::vector<uint32_t>{73, 90, 123, 137}));
}

}  // namespace
