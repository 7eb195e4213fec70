// The one place that turns a shader's name into SPIR-V. The build compiles
// every shader of the sample listed in Shaders/CMakeLists.txt and writes that
// list, with each shader's source, entry point, stage and defines, next to the
// .spv files (shaders.txt). Load(name) reads <name>.spv; Load(name, true)
// recompiles the HLSL source with the same entry and defines (F4).
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "d3dl/D3DLike.h"

namespace drr {

// The fields of one line of a build manifest ("a|b||c" -> a, b, "", c).
std::vector<std::string> SplitFields(const std::string& line, char separator);

class ShaderLibrary {
 public:
  // spvDir holds the .spv files and shaders.txt; sourceDir the HLSL. A folder
  // without shaders.txt still loads .spv files, but cannot recompile.
  void Open(const std::string& spvDir, const std::string& sourceDir);
  const std::string& SpvDir() const { return m_SpvDir; }
  const std::string& SourceDir() const { return m_SourceDir; }

  // SPIR-V of `name`; fromSource compiles its HLSL when the manifest knows it
  // and the source file exists (then *compiled is set).
  bool Load(const std::string& name, bool fromSource, std::vector<uint32_t>* code, std::string* error,
            bool* compiled = nullptr) const;
  // Whether the build made `name`: listed in shaders.txt, or its .spv is there.
  bool Has(const std::string& name) const;
  bool CreateVertexShader(d3dl::Device* device, const std::string& name, bool fromSource,
                          d3dl::VertexShader** shader, std::vector<uint32_t>* code, std::string* error,
                          bool* compiled = nullptr) const;
  bool CreatePixelShader(d3dl::Device* device, const std::string& name, bool fromSource,
                         d3dl::PixelShader** shader, std::string* error, bool* compiled = nullptr) const;

  // $DRR_SHADER_SOURCE_DIR, else the build's Shaders folder.
  static std::string DefaultSourceDir();
  // --shader-dir, else $DRR_SHADER_DIR, else the build's shader output folder.
  static std::string DefaultSpvDir(const std::string& option);

 private:
  struct Entry {
    std::string source, entry, stage;
    std::vector<std::string> defines;  // NAME or NAME=VALUE
  };
  std::string m_SpvDir, m_SourceDir;
  std::map<std::string, Entry> m_Entries;
};

// One pass's shaders by name, created all or none: a reload (F4) keeps the
// old set on any error. compiled counts those compiled from HLSL.
struct ShaderLoad {
  struct Vertex {
    const char* name;
    d3dl::ComPtr<d3dl::VertexShader>* shader;
    std::vector<uint32_t>* code = nullptr;  // the SPIR-V, for an input layout
  };
  struct Pixel {
    const char* name;
    d3dl::ComPtr<d3dl::PixelShader>* shader;
  };
  d3dl::Device* device = nullptr;
  const ShaderLibrary* library = nullptr;
  bool fromSource = false;
  std::string* error = nullptr;
  size_t compiled = 0;
  bool Load(std::initializer_list<Vertex> vertex, std::initializer_list<Pixel> pixel);
};

}  // namespace drr
