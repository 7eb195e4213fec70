#include "ShaderLibrary.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "d3dl/ShaderCompiler.h"

#ifndef DRR_DEFAULT_SHADER_DIR
#define DRR_DEFAULT_SHADER_DIR "shaders"
#endif

namespace drr {

std::vector<std::string> SplitFields(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!s.empty() && s.back() == sep) parts.emplace_back();
  return parts;
}

void ShaderLibrary::Open(const std::string& spvDir, const std::string& sourceDir) {
  m_SpvDir = spvDir;
  m_SourceDir = sourceDir;
  m_Entries.clear();
  // name|source|entry|stage|DEF=1,DEF2 (written by Shaders/CMakeLists.txt)
  std::ifstream in(spvDir + "/shaders.txt");
  std::string line;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = SplitFields(line, '|');
    if (f.size() != 5 || f[0].empty()) continue;
    Entry e{f[1], f[2], f[3], {}};
    if (!f[4].empty()) e.defines = SplitFields(f[4], ',');
    m_Entries[f[0]] = std::move(e);
  }
}

bool ShaderLibrary::Load(const std::string& name, bool fromSource, std::vector<uint32_t>* code,
                         std::string* error, bool* compiled) const {
  if (compiled) *compiled = false;
  const auto it = m_Entries.find(name);
  std::error_code ec;
  if (fromSource && it != m_Entries.end() && std::filesystem::exists(m_SourceDir + "/" + it->second.source, ec)) {
    const Entry& e = it->second;
    d3dl::ShaderCompileDesc d;
    d.SourcePath = m_SourceDir + "/" + e.source;
    d.EntryPoint = e.entry;
    if (!d3dl::ShaderStageFromGlslangName(e.stage, &d.Stage)) {  // vert, frag, tesc, tese (scene tessellation)
      *error = e.source + " (" + e.entry + "): unknown stage '" + e.stage + "' in shaders.txt";
      return false;
    }
    for (const std::string& def : e.defines) {
      const size_t eq = def.find('=');
      d.Defines.emplace_back(def.substr(0, eq), eq == std::string::npos ? "1" : def.substr(eq + 1));
    }
    std::string errs;
    if (d3dl::FAILED(d3dl::CompileHLSL(d, code, &errs))) {
      *error = e.source + " (" + e.entry + (e.defines.empty() ? "" : ", " + SplitFields(e.defines[0], '=')[0]) +
               ") did not compile:\n" + errs;
      return false;
    }
    if (compiled) *compiled = true;
    return true;
  }
  return d3dl::SUCCEEDED(d3dl::ReadSpirvFile(m_SpvDir + "/" + name + ".spv", code, error));
}

bool ShaderLibrary::Has(const std::string& name) const {
  std::error_code ec;
  return m_Entries.count(name) != 0 || std::filesystem::exists(m_SpvDir + "/" + name + ".spv", ec);
}

bool ShaderLibrary::CreateVertexShader(d3dl::Device* device, const std::string& name, bool fromSource,
                                       d3dl::VertexShader** shader, std::vector<uint32_t>* code,
                                       std::string* error, bool* compiled) const {
  std::vector<uint32_t> words;
  if (!Load(name, fromSource, &words, error, compiled)) return false;
  if (d3dl::FAILED(device->CreateVertexShader(words.data(), words.size() * 4, shader))) {
    *error = "CreateVertexShader(" + name + ") failed";
    return false;
  }
  if (code) *code = std::move(words);
  return true;
}

bool ShaderLibrary::CreatePixelShader(d3dl::Device* device, const std::string& name, bool fromSource,
                                      d3dl::PixelShader** shader, std::string* error, bool* compiled) const {
  std::vector<uint32_t> words;
  if (!Load(name, fromSource, &words, error, compiled)) return false;
  if (d3dl::FAILED(device->CreatePixelShader(words.data(), words.size() * 4, shader))) {
    *error = "CreatePixelShader(" + name + ") failed";
    return false;
  }
  return true;
}

std::string ShaderLibrary::DefaultSourceDir() {
  const char* env = std::getenv("DRR_SHADER_SOURCE_DIR");
  if (env && *env) return env;
#ifdef DRR_SHADER_SOURCE_DIR
  return DRR_SHADER_SOURCE_DIR;  // set by the build
#else
  return (std::filesystem::path(__FILE__).parent_path().parent_path() / "Shaders").string();
#endif
}

std::string ShaderLibrary::DefaultSpvDir(const std::string& option) {
  if (!option.empty()) return option;
  const char* env = std::getenv("DRR_SHADER_DIR");
  return env && *env ? env : DRR_DEFAULT_SHADER_DIR;
}

bool ShaderLoad::Load(std::initializer_list<Vertex> vertex, std::initializer_list<Pixel> pixel) {
  std::vector<d3dl::ComPtr<d3dl::VertexShader>> vs(vertex.size());
  std::vector<d3dl::ComPtr<d3dl::PixelShader>> ps(pixel.size());
  std::vector<std::vector<uint32_t>> code(vertex.size());
  size_t n = 0, i = 0;
  for (const Vertex& v : vertex) {
    bool c = false;
    if (!library->CreateVertexShader(device, v.name, fromSource, vs[i].GetAddressOf(), &code[i], error, &c)) return false;
    n += c;
    ++i;
  }
  i = 0;
  for (const Pixel& p : pixel) {
    bool c = false;
    if (!library->CreatePixelShader(device, p.name, fromSource, ps[i++].GetAddressOf(), error, &c)) return false;
    n += c;
  }
  i = 0;
  for (const Vertex& v : vertex) {
    *v.shader = vs[i];
    if (v.code) *v.code = std::move(code[i]);
    ++i;
  }
  i = 0;
  for (const Pixel& p : pixel) *p.shader = ps[i++];
  compiled += n;
  return true;
}

}  // namespace drr
