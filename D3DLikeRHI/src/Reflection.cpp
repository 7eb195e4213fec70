// A small SPIR-V reflector: descriptor bindings (with uniform block sizes),
// vertex inputs with their HLSL semantics, fragment outputs.
#include <algorithm>
#include <cctype>
#include <unordered_map>

#include "Shaders.h"
#include "Spirv.h"

namespace d3dl::impl {

std::string ReadSpirvString(const uint32_t* w, size_t count) {
  std::string s;
  for (size_t i = 0; i < count; ++i)
    for (int b = 0; b < 4; ++b) {
      char c = static_cast<char>((w[i] >> (8 * b)) & 0xff);
      if (!c) return s;
      s.push_back(c);
    }
  return s;
}

void SplitSemanticIndex(std::string* semantic, uint32_t* index) {
  size_t p = semantic->size();
  while (p > 0 && std::isdigit(static_cast<unsigned char>((*semantic)[p - 1]))) --p;
  if (p == semantic->size()) return;
  *index = static_cast<uint32_t>(std::stoul(semantic->substr(p)));
  semantic->resize(p);
}

namespace {

struct TypeInfo {
  uint32_t op = 0;
  std::vector<uint32_t> args;  // operands after the result id
};
struct Var {
  uint32_t type, storage;
};

// The parts of a module the reflection reads, by result id.
class SpirvModule {
 public:
  bool Parse(const uint32_t* words, size_t n, std::string* error);
  void ReflectBindings(ShaderReflection* out);
  void ReflectInterface(ShaderReflection* out);
  std::string entry;
  uint32_t model = 0;
  bool haveEntry = false;
  std::vector<uint32_t> modes;  // execution modes of the entry point

 private:
  void Decorate(const uint32_t* a, uint32_t na);
  uint32_t SizeOf(uint32_t id);
  uint32_t StructSize(uint32_t id, const TypeInfo& t);
  bool BindingOf(uint32_t id, const Var& v, ReflectedBinding* b);
  template <class M>
  static typename M::mapped_type Get(const M& m, typename M::key_type k, typename M::mapped_type fallback) {
    auto it = m.find(k);
    return it == m.end() ? fallback : it->second;
  }

  std::unordered_map<uint32_t, TypeInfo> types_;
  std::unordered_map<uint32_t, uint64_t> constants_;
  std::unordered_map<uint32_t, Var> vars_;
  std::unordered_map<uint32_t, uint32_t> binding_, set_, location_, arrayStride_;
  std::unordered_map<uint32_t, std::string> semantic_, names_;
  std::unordered_map<uint32_t, bool> builtin_, block_;
  std::unordered_map<uint64_t, uint32_t> memberOffset_, memberMatrixStride_;  // (struct<<32)|member
  std::vector<uint32_t> interface_;
};

void SpirvModule::Decorate(const uint32_t* a, uint32_t na) {
  const uint32_t t = a[0], d = a[1];
  if (d == spirv::DecBinding && na >= 3) binding_[t] = a[2];
  if (d == spirv::DecDescriptorSet && na >= 3) set_[t] = a[2];
  if (d == spirv::DecLocation && na >= 3) location_[t] = a[2];
  if (d == spirv::DecBuiltIn) builtin_[t] = true;
  if (d == spirv::DecBlock) block_[t] = true;
  if (d == spirv::DecBufferBlock) block_[t] = false;
  if (d == spirv::DecArrayStride && na >= 3) arrayStride_[t] = a[2];
}

bool SpirvModule::Parse(const uint32_t* words, size_t n, std::string* error) {
  using namespace spirv;
  for (size_t i = 5; i < n;) {
    const uint32_t op = words[i] & 0xffff, wc = words[i] >> 16;
    if (wc == 0 || i + wc > n) {
      *error = "malformed SPIR-V instruction stream";
      return false;
    }
    const uint32_t* a = words + i + 1;
    const uint32_t na = wc - 1;
    if (op == OpName && na >= 2) names_[a[0]] = ReadSpirvString(a + 1, na - 1);
    if (op == OpEntryPoint && !haveEntry && na >= 3) {
      haveEntry = true;
      model = a[0];
      entry = ReadSpirvString(a + 2, na - 2);
      for (size_t k = 2 + entry.size() / 4 + 1; k < na; ++k) interface_.push_back(a[k]);
    }
    if (op == OpExecutionMode && na >= 2) modes.push_back(a[1]);
    if (op == OpDecorate && na >= 2) Decorate(a, na);
    if (op == OpMemberDecorate && na >= 4) {
      const uint64_t k = (uint64_t(a[0]) << 32) | a[1];
      if (a[2] == DecOffset) memberOffset_[k] = a[3];
      if (a[2] == DecMatrixStride) memberMatrixStride_[k] = a[3];
    }
    if (op == OpDecorateString && na >= 3 && a[1] == DecUserSemantic) semantic_[a[0]] = ReadSpirvString(a + 2, na - 2);
    if (IsTypeOp(op) && na >= 1)
      types_[a[0]] = TypeInfo{op, std::vector<uint32_t>(a + 1, a + na)};
    if (op == OpConstant && na >= 3) constants_[a[1]] = a[2];
    if (op == OpVariable && na >= 3) vars_[a[1]] = Var{a[0], a[2]};
    i += wc;
  }
  return true;
}

// Size in bytes of a type inside a uniform block (std140-like HLSL offsets).
uint32_t SpirvModule::SizeOf(uint32_t id) {
  using namespace spirv;
  auto it = types_.find(id);
  if (it == types_.end()) return 0;
  const TypeInfo& t = it->second;
  switch (t.op) {
    case OpTypeInt: case OpTypeFloat: return t.args.empty() ? 4 : t.args[0] / 8;
    case OpTypeVector: return SizeOf(t.args[0]) * t.args[1];
    case OpTypeMatrix: return SizeOf(t.args[0]) * t.args[1];
    case OpTypeArray: {
      const uint64_t len = Get(constants_, t.args[1], uint64_t(1));
      const uint32_t stride = arrayStride_.count(id) ? arrayStride_[id] : SizeOf(t.args[0]);
      return static_cast<uint32_t>(len * stride);
    }
    case OpTypeStruct: return StructSize(id, t);
    default: return 0;
  }
}

uint32_t SpirvModule::StructSize(uint32_t id, const TypeInfo& t) {
  uint32_t end = 0;
  for (uint32_t m = 0; m < t.args.size(); ++m) {
    const uint64_t k = (uint64_t(id) << 32) | m;
    const uint32_t off = Get(memberOffset_, k, 0u);
    uint32_t sz = SizeOf(t.args[m]);
    auto mt = types_.find(t.args[m]);
    if (mt != types_.end() && mt->second.op == spirv::OpTypeMatrix && memberMatrixStride_.count(k))
      sz = memberMatrixStride_[k] * mt->second.args[1];
    end = std::max(end, off + sz);
  }
  return end;
}

// The binding a resource variable declares; false when it is not one.
bool SpirvModule::BindingOf(uint32_t id, const Var& v, ReflectedBinding* b) {
  using namespace spirv;
  auto pt = types_.find(v.type);
  if (pt == types_.end() || pt->second.op != OpTypePointer) return false;
  if (v.storage != StorageUniformConstant && v.storage != StorageUniform && v.storage != StorageStorageBuffer)
    return false;
  uint32_t tid = pt->second.args.size() >= 2 ? pt->second.args[1] : 0;
  while (types_.count(tid) && (types_[tid].op == OpTypeArray || types_[tid].op == OpTypeRuntimeArray))
    tid = types_[tid].args[0];
  auto t = types_.find(tid);
  if (t == types_.end()) return false;
  b->set = Get(set_, id, 0u);
  b->binding = Get(binding_, id, 0u);
  b->name = Get(names_, id, std::string());
  if (b->name.empty()) b->name = Get(names_, tid, std::string());
  const std::vector<uint32_t>& args = t->second.args;
  switch (t->second.op) {
    case OpTypeStruct:
      if (v.storage == StorageUniform && Get(block_, tid, false)) {
        b->type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
        b->blockSize = SizeOf(tid);
      } else {
        b->type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      }
      return true;
    case OpTypeImage: {
      const uint32_t dim = args.size() > 1 ? args[1] : 1;
      const uint32_t sampled = args.size() > 5 ? args[5] : 1;
      b->type = dim == 5 ? (sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER)
                         : (sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
      b->image1D = dim == 0;
      const bool arrayed = args.size() > 3 && args[3], ms = args.size() > 4 && args[4];
      b->viewType = dim == 0   ? (arrayed ? VK_IMAGE_VIEW_TYPE_1D_ARRAY : VK_IMAGE_VIEW_TYPE_1D)
                    : dim == 3 ? (arrayed ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_CUBE)
                               : (arrayed ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D);
      b->multisampled = ms;
      if (dim == 2) b->type = VK_DESCRIPTOR_TYPE_MAX_ENUM;  // 3D (no Texture3D); cube (3) is a TEXTURECUBE view
      return true;
    }
    case OpTypeSampler: b->type = VK_DESCRIPTOR_TYPE_SAMPLER; return true;
    case OpTypeSampledImage: b->type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER; return true;
    default: return false;
  }
}

void SpirvModule::ReflectBindings(ShaderReflection* out) {
  for (auto& [id, v] : vars_) {
    ReflectedBinding b;
    if (BindingOf(id, v, &b)) out->bindings.push_back(b);
  }
  std::sort(out->bindings.begin(), out->bindings.end(),
            [](const ReflectedBinding& x, const ReflectedBinding& y) { return x.binding < y.binding; });
}

// Vertex inputs with their semantics; fragment output locations.
void SpirvModule::ReflectInterface(ShaderReflection* out) {
  for (uint32_t id : interface_) {
    auto v = vars_.find(id);
    if (v == vars_.end() || builtin_.count(id) || !location_.count(id)) continue;
    if (v->second.storage == spirv::StorageInput && out->stage == ShaderStage::Vertex) {
      ReflectedInput in;
      in.location = location_[id];
      in.semantic = semantic_.count(id) ? ToUpper(semantic_[id].c_str()) : "";
      SplitSemanticIndex(&in.semantic, &in.index);
      out->inputs.push_back(in);
    } else if (v->second.storage == spirv::StorageOutput && out->stage == ShaderStage::Pixel) {
      if (location_[id] < 32) out->outputLocations |= 1u << location_[id];
    }
  }
  std::sort(out->inputs.begin(), out->inputs.end(),
            [](const ReflectedInput& x, const ReflectedInput& y) { return x.location < y.location; });
}

bool StageOfModel(uint32_t model, ShaderStage* stage) {
  switch (model) {
    case spirv::ModelVertex: *stage = ShaderStage::Vertex; return true;
    case spirv::ModelTessellationControl: *stage = ShaderStage::Hull; return true;
    case spirv::ModelTessellationEvaluation: *stage = ShaderStage::Domain; return true;
    case spirv::ModelGeometry: *stage = ShaderStage::Geometry; return true;
    case spirv::ModelFragment: *stage = ShaderStage::Pixel; return true;
    case spirv::ModelGLCompute: *stage = ShaderStage::Compute; return true;
    default: return false;
  }
}

// The primitive classes (0 points, 1 lines, 2 triangles) of the execution
// modes: a geometry shader's input, or the tessellation domain.
void ReflectPrimitives(const std::vector<uint32_t>& modes, ShaderReflection* out) {
  using namespace spirv;
  const bool geometry = out->stage == ShaderStage::Geometry;
  const bool tessellation = out->stage == ShaderStage::Hull || out->stage == ShaderStage::Domain;
  for (uint32_t mode : modes) {
    if (geometry) {
      if (mode == ModeInputPoints) out->geometryInput = 0;
      if (mode == ModeInputLines || mode == ModeInputLinesAdjacency) out->geometryInput = 1;
      if (mode == ModeTriangles || mode == ModeInputTrianglesAdjacency) out->geometryInput = 2;
      if (mode == ModeInputLinesAdjacency || mode == ModeInputTrianglesAdjacency) out->geometryAdjacency = true;
    } else if (tessellation) {
      if (mode == ModeIsolines) out->tessellationDomain = 1;
      if (mode == ModeTriangles || mode == ModeQuads) out->tessellationDomain = 2;
      if (mode == ModePointMode) out->tessellationPointMode = true;
    }
  }
}

}  // namespace

bool ReflectSpirv(const uint32_t* words, size_t n, ShaderReflection* out, std::string* error) {
  if (!words || n < 5 || words[0] != 0x07230203u) {
    *error = "bytecode is not SPIR-V (bad magic number or too short)";
    return false;
  }
  SpirvModule m;
  if (!m.Parse(words, n, error)) return false;
  if (!m.haveEntry) {
    *error = "SPIR-V module has no entry point";
    return false;
  }
  out->entry = m.entry;
  if (!StageOfModel(m.model, &out->stage)) {
    *error = "unsupported execution model " + std::to_string(m.model) +
             " (only vertex, hull, domain, geometry, pixel and compute shaders)";
    return false;
  }
  ReflectPrimitives(m.modes, out);
  m.ReflectBindings(out);
  m.ReflectInterface(out);
  return true;
}

}  // namespace d3dl::impl
