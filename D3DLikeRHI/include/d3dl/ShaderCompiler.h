// Runtime HLSL -> SPIR-V compilation (glslang's HLSL front end, in process),
// with the same options and binding shifts as the build-time compile, for
// "reload shaders" and for tests.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "d3dl/Bindings.h"
#include "d3dl/Types.h"

namespace d3dl {

struct ShaderCompileDesc {
  std::string SourcePath;   // used for #include resolution and messages
  std::string Source;       // if empty, read from SourcePath
  std::string EntryPoint = "main";
  ShaderStage Stage = ShaderStage::Vertex;
  std::vector<std::pair<std::string, std::string>> Defines;
  // Keep HLSL semantic strings (SPV_GOOGLE_hlsl_functionality1), which
  // CreateInputLayout matches against; off = d3dl_compile_hlsl's NO_SEMANTICS.
  bool KeepSemantics = true;
};

// Returns S_OK and fills spirv, or E_FAIL with the compiler's messages in errors.
HRESULT CompileHLSL(const ShaderCompileDesc& desc, std::vector<uint32_t>* spirv,
                    std::string* errors);

// The stage of glslang's stage name (-S vert|frag|tesc|tese|geom|comp, as
// cmake/HLSL.cmake's STAGE): false for another name.
bool ShaderStageFromGlslangName(const std::string& name, ShaderStage* stage);

// Reads a compiled SPIR-V file: S_OK, or E_FAIL with the path and the reason
// (cannot open, or a size that is not a whole number of 32-bit words).
HRESULT ReadSpirvFile(const std::string& path, std::vector<uint32_t>* spirv, std::string* error);

}  // namespace d3dl
