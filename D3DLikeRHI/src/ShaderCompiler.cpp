// Runtime HLSL -> SPIR-V through glslang's library, with exactly the options
// of the build-time rule in cmake/HLSL.cmake (HLSL input, Vulkan 1.3 target,
// hlsl_functionality1 semantics, HLSL cbuffer offsets, per-stage binding
// shifts of Bindings.h), so a reloaded shader binds like the built one.
#include "d3dl/ShaderCompiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>

namespace d3dl {
namespace {

bool ReadText(const std::filesystem::path& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  *out = ss.str();
  return true;
}

// Resolves #include "x" relative to the including file, then to the first
// source's folder. Keeps the loaded text alive until the result is released.
class FileIncluder : public glslang::TShader::Includer {
 public:
  explicit FileIncluder(std::filesystem::path rootDir) : rootDir_(std::move(rootDir)) {}

  IncludeResult* includeLocal(const char* headerName, const char* includerName,
                              size_t depth) override {
    std::filesystem::path includer(includerName ? includerName : "");
    std::filesystem::path candidates[] = {includer.parent_path() / headerName,
                                          rootDir_ / headerName};
    for (const auto& candidate : candidates) {
      auto text = std::make_unique<std::string>();
      if (ReadText(candidate, text.get())) {
        const char* data = text->data();
        size_t size = text->size();
        return new IncludeResult(candidate.string(), data, size, text.release());
      }
    }
    return nullptr;
  }

  IncludeResult* includeSystem(const char* headerName, const char* includerName,
                               size_t depth) override {
    return includeLocal(headerName, includerName, depth);
  }

  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

 private:
  std::filesystem::path rootDir_;
};

// glslang's process-wide tables: initialise once, keep for the process.
void EnsureGlslangInitialised() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

// glslang's language of each stage (hull = tessellation control, domain =
// tessellation evaluation).
EShLanguage LanguageOf(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::Vertex: return EShLangVertex;
    case ShaderStage::Pixel: return EShLangFragment;
    case ShaderStage::Hull: return EShLangTessControl;
    case ShaderStage::Domain: return EShLangTessEvaluation;
    case ShaderStage::Geometry: return EShLangGeometry;
    case ShaderStage::Compute: return EShLangCompute;
  }
  return EShLangVertex;
}

// Entry point, target environment and the binding formula's shifts, as
// cmake/HLSL.cmake passes them to glslangValidator.
void SetUpShader(const ShaderCompileDesc& desc, EShLanguage language, glslang::TShader* shader) {
  shader->setEntryPoint(desc.EntryPoint.c_str());
  shader->setSourceEntryPoint(desc.EntryPoint.c_str());
  shader->setEnvInput(glslang::EShSourceHlsl, language, glslang::EShClientVulkan, 100);
  shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
  // SPIR-V 1.3, as cmake/HLSL.cmake: glslang's HLSL storage buffers carry
  // BufferBlock, which SPIR-V 1.4+ rejects.
  shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  if (desc.KeepSemantics) shader->setEnvTargetHlslFunctionality1();

  const uint32_t stageBase = kStageBindingStride * static_cast<uint32_t>(desc.Stage);
  shader->setShiftBinding(glslang::EResUbo, stageBase + kConstantBufferBase);
  shader->setShiftBinding(glslang::EResTexture, stageBase + kTextureBase);
  shader->setShiftBinding(glslang::EResSampler, stageBase + kSamplerBase);
  // As --hlsl-iomap: t# and u# by register class (StructuredBuffer vs RWStructuredBuffer).
  shader->setHlslIoMapping(true);
  shader->setShiftBinding(glslang::EResUav, stageBase + kUnorderedAccessBase);
}

// The source text: desc.Source, else the file at desc.SourcePath.
bool ReadSource(const ShaderCompileDesc& desc, std::string* source) {
  *source = desc.Source;
  return !source->empty() || (!desc.SourcePath.empty() && ReadText(desc.SourcePath, source));
}

// Defines go into a preamble, as glslangValidator's -DNAME[=VALUE] does
// (an empty value defines the name as empty, not as 1).
std::string DefinesPreamble(const ShaderCompileDesc& desc) {
  std::string preamble;
  for (const auto& [name, value] : desc.Defines) {
    preamble += "#define " + name + (value.empty() ? std::string() : " " + value) + "\n";
  }
  return preamble;
}

// The linked program's SPIR-V, legalised as glslangValidator does (empty on
// failure); glslang's messages into *log.
void GenerateSpirv(glslang::TProgram& program, EShLanguage language, std::vector<uint32_t>* spirv, std::string* log) {
  glslang::SpvOptions options;
  options.validate = false;
  options.disableOptimizer = false;  // HLSL needs legalization, as glslangValidator runs it
  spv::SpvBuildLogger logger;
  spirv->clear();
  glslang::GlslangToSpv(*program.getIntermediate(language), *spirv, &logger, &options);
  *log = logger.getAllMessages();
}

}  // namespace

HRESULT CompileHLSL(const ShaderCompileDesc& desc, std::vector<uint32_t>* spirv,
                    std::string* errors) {
  std::string ignored;
  std::string& err = errors ? *errors : ignored;
  err.clear();
  if (!spirv) {
    err = "CompileHLSL: spirv output is null";
    return E_INVALIDARG;
  }
  if (desc.EntryPoint.empty()) {
    err = "CompileHLSL: empty entry point";
    return E_INVALIDARG;
  }

  std::string source;
  if (!ReadSource(desc, &source)) {
    err = "CompileHLSL: cannot read '" + desc.SourcePath + "'";
    return E_INVALIDARG;
  }
  const std::string preamble = DefinesPreamble(desc);

  EnsureGlslangInitialised();
  const EShLanguage language = LanguageOf(desc.Stage);
  glslang::TShader shader(language);
  const std::string name = desc.SourcePath.empty() ? "<memory>" : desc.SourcePath;
  const char* text = source.c_str();
  const char* names = name.c_str();
  const int length = static_cast<int>(source.size());
  shader.setStringsWithLengthsAndNames(&text, &length, &names, 1);
  shader.setPreamble(preamble.c_str());
  SetUpShader(desc, language, &shader);

  const auto messages =
      static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgReadHlsl |
                               EShMsgHlslOffsets);
  FileIncluder includer(std::filesystem::path(name).parent_path());
  if (!shader.parse(GetDefaultResources(), 100, false, messages, includer)) {
    err = name + ": " + shader.getInfoLog();
    return E_FAIL;
  }

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages) || !program.mapIO()) {
    err = name + ": " + program.getInfoLog();
    return E_FAIL;
  }

  std::string log;
  GenerateSpirv(program, language, spirv, &log);
  if (spirv->empty()) {
    err = name + ": SPIR-V generation failed: " + log;
    return E_FAIL;
  }
  err = log;  // warnings, if any
  return S_OK;
}

bool ShaderStageFromGlslangName(const std::string& name, ShaderStage* stage) {
  static const std::pair<const char*, ShaderStage> kNames[] = {
      {"vert", ShaderStage::Vertex}, {"frag", ShaderStage::Pixel},     {"tesc", ShaderStage::Hull},
      {"tese", ShaderStage::Domain}, {"geom", ShaderStage::Geometry}, {"comp", ShaderStage::Compute}};
  for (const auto& [n, s] : kNames)
    if (name == n) return *stage = s, true;
  return false;
}

HRESULT ReadSpirvFile(const std::string& path, std::vector<uint32_t>* spirv, std::string* error) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) {
    if (error) *error = "cannot open " + path;
    return E_FAIL;
  }
  const std::streamsize size = f.tellg();
  if (size <= 0 || size % 4 != 0) {
    if (error) *error = path + ": not a SPIR-V file (size " + std::to_string(size) + ")";
    return E_FAIL;
  }
  spirv->resize(size_t(size) / 4);
  f.seekg(0);
  f.read(reinterpret_cast<char*>(spirv->data()), size);
  if (!f) {
    if (error) *error = "cannot read " + path;
    return E_FAIL;
  }
  return S_OK;
}

}  // namespace d3dl
