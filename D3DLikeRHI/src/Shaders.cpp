// Shader modules, a small SPIR-V reflector (descriptor bindings, vertex
// inputs with their HLSL semantics, fragment outputs) and input layouts.
#include <cctype>
#include <cstdio>
#include <functional>

#include "Context.h"

namespace d3dl::impl {
namespace {

enum : uint32_t {
  OpName = 5, OpEntryPoint = 15, OpTypeInt = 21, OpTypeFloat = 22, OpTypeVector = 23,
  OpTypeMatrix = 24, OpTypeImage = 25, OpTypeSampler = 26, OpTypeSampledImage = 27,
  OpTypeArray = 28, OpTypeRuntimeArray = 29, OpTypeStruct = 30, OpTypePointer = 32,
  OpConstant = 43, OpVariable = 59, OpDecorate = 71, OpMemberDecorate = 72,
  OpDecorateString = 5632,
};
enum : uint32_t {
  DecBlock = 2, DecBufferBlock = 3, DecArrayStride = 6, DecMatrixStride = 7, DecBuiltIn = 11,
  DecLocation = 30, DecBinding = 33, DecDescriptorSet = 34, DecOffset = 35,
  DecUserSemantic = 5635,
};
enum : uint32_t { StorageUniformConstant = 0, StorageInput = 1, StorageUniform = 2, StorageOutput = 3 };

std::string ReadString(const uint32_t* w, size_t count) {
  std::string s;
  for (size_t i = 0; i < count; ++i)
    for (int b = 0; b < 4; ++b) {
      char c = static_cast<char>((w[i] >> (8 * b)) & 0xff);
      if (!c) return s;
      s.push_back(c);
    }
  return s;
}

struct TypeInfo {
  uint32_t op = 0;
  std::vector<uint32_t> args;  // operands after the result id
};

}  // namespace

bool ReflectSpirv(const uint32_t* words, size_t n, ShaderReflection* out, std::string* error) {
  if (!words || n < 5 || words[0] != 0x07230203u) {
    *error = "bytecode is not SPIR-V (bad magic number or too short)";
    return false;
  }
  std::unordered_map<uint32_t, TypeInfo> types;
  std::unordered_map<uint32_t, uint64_t> constants;
  struct Var {
    uint32_t type, storage;
  };
  std::unordered_map<uint32_t, Var> vars;
  std::unordered_map<uint32_t, uint32_t> binding, set, location, arrayStride;
  std::unordered_map<uint32_t, std::string> semantic, names;
  std::unordered_map<uint32_t, bool> builtin, block;
  std::unordered_map<uint64_t, uint32_t> memberOffset, memberMatrixStride;  // (struct<<32)|member
  std::vector<uint32_t> interface;
  bool haveEntry = false;
  uint32_t model = 0;

  for (size_t i = 5; i < n;) {
    uint32_t op = words[i] & 0xffff, wc = words[i] >> 16;
    if (wc == 0 || i + wc > n) {
      *error = "malformed SPIR-V instruction stream";
      return false;
    }
    const uint32_t* a = words + i + 1;
    uint32_t na = wc - 1;
    switch (op) {
      case OpName:
        if (na >= 2) names[a[0]] = ReadString(a + 1, na - 1);
        break;
      case OpEntryPoint:
        if (!haveEntry && na >= 3) {
          haveEntry = true;
          model = a[0];
          out->entry = ReadString(a + 2, na - 2);
          size_t strWords = out->entry.size() / 4 + 1;
          for (size_t k = 2 + strWords; k < na; ++k) interface.push_back(a[k]);
        }
        break;
      case OpDecorate:
        if (na >= 2) {
          uint32_t t = a[0], d = a[1];
          if (d == DecBinding && na >= 3) binding[t] = a[2];
          if (d == DecDescriptorSet && na >= 3) set[t] = a[2];
          if (d == DecLocation && na >= 3) location[t] = a[2];
          if (d == DecBuiltIn) builtin[t] = true;
          if (d == DecBlock) block[t] = true;
          if (d == DecBufferBlock) block[t] = false;
          if (d == DecArrayStride && na >= 3) arrayStride[t] = a[2];
        }
        break;
      case OpMemberDecorate:
        if (na >= 4) {
          uint64_t k = (uint64_t(a[0]) << 32) | a[1];
          if (a[2] == DecOffset) memberOffset[k] = a[3];
          if (a[2] == DecMatrixStride) memberMatrixStride[k] = a[3];
        }
        break;
      case OpDecorateString:
        if (na >= 3 && a[1] == DecUserSemantic) semantic[a[0]] = ReadString(a + 2, na - 2);
        break;
      case OpTypeInt: case OpTypeFloat: case OpTypeVector: case OpTypeMatrix: case OpTypeImage:
      case OpTypeSampler: case OpTypeSampledImage: case OpTypeArray: case OpTypeRuntimeArray:
      case OpTypeStruct: case OpTypePointer:
        if (na >= 1) types[a[0]] = TypeInfo{op, std::vector<uint32_t>(a + 1, a + na)};
        break;
      case OpConstant:
        if (na >= 3) constants[a[1]] = a[2];
        break;
      case OpVariable:
        if (na >= 3) vars[a[1]] = Var{a[0], a[2]};
        break;
      default:
        break;
    }
    i += wc;
  }
  if (!haveEntry) {
    *error = "SPIR-V module has no entry point";
    return false;
  }
  if (model == 0) out->stage = VK_SHADER_STAGE_VERTEX_BIT;
  else if (model == 4) out->stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  else {
    *error = "unsupported execution model " + std::to_string(model) + " (only vertex and pixel shaders)";
    return false;
  }

  // Size in bytes of a type inside a uniform block (std140-like HLSL offsets).
  std::function<uint32_t(uint32_t)> sizeOf = [&](uint32_t id) -> uint32_t {
    auto it = types.find(id);
    if (it == types.end()) return 0;
    const TypeInfo& t = it->second;
    switch (t.op) {
      case OpTypeInt: case OpTypeFloat: return t.args.empty() ? 4 : t.args[0] / 8;
      case OpTypeVector: return sizeOf(t.args[0]) * t.args[1];
      case OpTypeMatrix: return sizeOf(t.args[0]) * t.args[1];
      case OpTypeArray: {
        uint64_t len = constants.count(t.args[1]) ? constants[t.args[1]] : 1;
        uint32_t stride = arrayStride.count(id) ? arrayStride[id] : sizeOf(t.args[0]);
        return static_cast<uint32_t>(len * stride);
      }
      case OpTypeStruct: {
        uint32_t end = 0;
        for (uint32_t m = 0; m < t.args.size(); ++m) {
          uint64_t k = (uint64_t(id) << 32) | m;
          uint32_t off = memberOffset.count(k) ? memberOffset[k] : 0;
          uint32_t sz = sizeOf(t.args[m]);
          auto mt = types.find(t.args[m]);
          if (mt != types.end() && mt->second.op == OpTypeMatrix && memberMatrixStride.count(k))
            sz = memberMatrixStride[k] * mt->second.args[1];
          end = std::max(end, off + sz);
        }
        return end;
      }
      default: return 0;
    }
  };

  for (auto& [id, v] : vars) {
    auto pt = types.find(v.type);
    if (pt == types.end() || pt->second.op != OpTypePointer) continue;
    uint32_t pointee = pt->second.args.size() >= 2 ? pt->second.args[1] : 0;
    if (v.storage == StorageUniformConstant || v.storage == StorageUniform || v.storage == 12) {
      ReflectedBinding b;
      b.set = set.count(id) ? set[id] : 0;
      b.binding = binding.count(id) ? binding[id] : 0;
      b.name = names.count(id) ? names[id] : "";
      uint32_t tid = pointee;
      while (types.count(tid) && (types[tid].op == OpTypeArray || types[tid].op == OpTypeRuntimeArray))
        tid = types[tid].args[0];
      auto t = types.find(tid);
      if (t == types.end()) continue;
      if (b.name.empty() && names.count(tid)) b.name = names[tid];
      switch (t->second.op) {
        case OpTypeStruct:
          if (v.storage == StorageUniform && block.count(tid) && block[tid]) {
            b.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
            b.blockSize = sizeOf(tid);
          } else {
            b.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
          }
          break;
        case OpTypeImage: {
          uint32_t dim = t->second.args.size() > 1 ? t->second.args[1] : 1;
          uint32_t sampled = t->second.args.size() > 5 ? t->second.args[5] : 1;
          b.type = dim == 5 ? (sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                            : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER)
                            : (sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                                            : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
          b.image1D = dim == 0;
          if (dim != 0 && dim != 1 && dim != 5) b.type = VK_DESCRIPTOR_TYPE_MAX_ENUM;  // 3D/cube
          break;
        }
        case OpTypeSampler: b.type = VK_DESCRIPTOR_TYPE_SAMPLER; break;
        case OpTypeSampledImage: b.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER; break;
        default: continue;
      }
      out->bindings.push_back(b);
    }
  }
  std::sort(out->bindings.begin(), out->bindings.end(),
            [](const ReflectedBinding& x, const ReflectedBinding& y) { return x.binding < y.binding; });

  for (uint32_t id : interface) {
    auto v = vars.find(id);
    if (v == vars.end() || builtin.count(id) || !location.count(id)) continue;
    if (v->second.storage == StorageInput && out->stage == VK_SHADER_STAGE_VERTEX_BIT) {
      ReflectedInput in;
      in.location = location[id];
      std::string sem = semantic.count(id) ? ToUpper(semantic[id].c_str()) : "";
      size_t p = sem.size();
      while (p > 0 && std::isdigit(static_cast<unsigned char>(sem[p - 1]))) --p;
      in.index = p < sem.size() ? static_cast<uint32_t>(std::stoul(sem.substr(p))) : 0;
      in.semantic = sem.substr(0, p);
      out->inputs.push_back(in);
    } else if (v->second.storage == StorageOutput && out->stage == VK_SHADER_STAGE_FRAGMENT_BIT) {
      if (location[id] < 32) out->outputLocations |= 1u << location[id];
    }
  }
  std::sort(out->inputs.begin(), out->inputs.end(),
            [](const ReflectedInput& x, const ReflectedInput& y) { return x.location < y.location; });
  return true;
}

// glslang's -fhlsl_functionality1 adds SPV_GOOGLE_hlsl_functionality1 /
// SPV_GOOGLE_user_type and their decorations (the HLSL semantics reflected
// above). Drivers without VK_GOOGLE_hlsl_functionality1 must not see them, so
// the module is created from a copy without those instructions.
static std::vector<uint32_t> StripGoogleDecorations(const std::vector<uint32_t>& in) {
  std::vector<uint32_t> out(in.begin(), in.begin() + 5);
  for (size_t i = 5; i < in.size();) {
    uint32_t op = in[i] & 0xffff, wc = in[i] >> 16;
    if (wc == 0 || i + wc > in.size()) return in;
    bool drop = false;
    if (op == 10 /*OpExtension*/) {
      std::string name = ReadString(&in[i + 1], wc - 1);
      drop = name == "SPV_GOOGLE_hlsl_functionality1" || name == "SPV_GOOGLE_user_type" ||
             name == "SPV_GOOGLE_decorate_string";
    } else if (op == OpDecorateString && wc >= 3) {
      drop = in[i + 2] == DecUserSemantic || in[i + 2] == 5636 /*UserTypeGOOGLE*/;
    } else if (op == 5633 /*OpMemberDecorateString*/ && wc >= 4) {
      drop = in[i + 3] == DecUserSemantic || in[i + 3] == 5636;
    } else if (op == 332 /*OpDecorateId*/ && wc >= 3) {
      drop = in[i + 2] == 5634 /*HlslCounterBufferGOOGLE*/;
    }
    if (!drop) out.insert(out.end(), in.begin() + i, in.begin() + i + wc);
    i += wc;
  }
  return out;
}

// Checks that every binding follows the formula of Bindings.h for the stage.
static bool CheckBindings(const ShaderReflection& r, ShaderStage stage, std::string* error) {
  const uint32_t base = kStageBindingStride * static_cast<uint32_t>(stage);
  for (const auto& b : r.bindings) {
    char buf[256];
    if (b.set != 0) {
      std::snprintf(buf, sizeof(buf), "'%s' uses descriptor set %u (only set 0 is used)", b.name.c_str(), b.set);
      *error = buf;
      return false;
    }
    RegisterClass cls;
    switch (b.type) {
      case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC: cls = RegisterClass::ConstantBuffer; break;
      case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: cls = RegisterClass::Texture; break;
      case VK_DESCRIPTOR_TYPE_SAMPLER: cls = RegisterClass::Sampler; break;
      default:
        std::snprintf(buf, sizeof(buf), "'%s' (binding %u) is a resource kind D3DLikeRHI does not bind (only cbuffer, Texture1D/2D, SamplerState)", b.name.c_str(), b.binding);
        *error = buf;
        return false;
    }
    uint32_t lo = base + RegisterClassBase(cls), hi = lo + RegisterSlotCount(cls);
    if (b.binding < lo || b.binding >= hi) {
      std::snprintf(buf, sizeof(buf), "'%s' has binding %u, outside [%u, %u) required by the binding formula for this stage; compile with the shifts of cmake/HLSL.cmake", b.name.c_str(), b.binding, lo, hi);
      *error = buf;
      return false;
    }
  }
  return true;
}

template <class Iface>
ShaderImpl<Iface>::~ShaderImpl() {
  this->dev_->pipelines().ForgetShader(this->uid());
  this->dev_->Defer(VK_OBJECT_TYPE_SHADER_MODULE, reinterpret_cast<uint64_t>(module));
}
template <class Iface>
void ShaderImpl<Iface>::OnDebugName() {
  this->dev_->SetName(VK_OBJECT_TYPE_SHADER_MODULE, reinterpret_cast<uint64_t>(module), this->name_);
}
template class ShaderImpl<VertexShader>;
template class ShaderImpl<PixelShader>;

template <class Impl, class Iface>
static HRESULT CreateShader(DeviceImpl* dev, const char* fn, ShaderStage stage, const void* code,
                            size_t len, Iface** out) {
  if (out) *out = nullptr;
  if (!code || !out) {
    dev->Log(LogLevel::Error, "%s: %s is null", fn, code ? "ppShader" : "pShaderBytecode");
    return E_INVALIDARG;
  }
  if (len < 20 || len % 4 != 0) {
    dev->Log(LogLevel::Error, "%s: bytecode length %zu is not SPIR-V (a multiple of 4, at least 20)", fn, len);
    return E_INVALIDARG;
  }
  std::vector<uint32_t> words(len / 4);
  std::memcpy(words.data(), code, len);
  ShaderReflection refl;
  std::string err;
  if (!ReflectSpirv(words.data(), words.size(), &refl, &err)) {
    dev->Log(LogLevel::Error, "%s: %s", fn, err.c_str());
    return E_INVALIDARG;
  }
  VkShaderStageFlagBits want = stage == ShaderStage::Vertex ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
  if (refl.stage != want) {
    dev->Log(LogLevel::Error, "%s: the SPIR-V entry point '%s' is a %s shader", fn, refl.entry.c_str(),
             refl.stage == VK_SHADER_STAGE_VERTEX_BIT ? "vertex" : "pixel");
    return E_INVALIDARG;
  }
  if (!CheckBindings(refl, stage, &err)) {
    dev->Log(LogLevel::Error, "%s: %s", fn, err.c_str());
    return E_INVALIDARG;
  }
  std::vector<uint32_t> stripped = StripGoogleDecorations(words);
  VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  ci.codeSize = stripped.size() * 4;
  ci.pCode = stripped.data();
  auto* s = new Impl(dev);
  if (vkCreateShaderModule(dev->vk(), &ci, nullptr, &s->module) != VK_SUCCESS) {
    dev->Log(LogLevel::Error, "%s: vkCreateShaderModule failed", fn);
    s->Release();
    return E_INVALIDARG;
  }
  s->refl = std::move(refl);
  *out = s;
  return S_OK;
}

HRESULT DeviceImpl::CreateVertexShader(const void* code, size_t len, VertexShader** out) {
  return CreateShader<VertexShaderImpl>(this, "CreateVertexShader", ShaderStage::Vertex, code, len, out);
}
HRESULT DeviceImpl::CreatePixelShader(const void* code, size_t len, PixelShader** out) {
  return CreateShader<PixelShaderImpl>(this, "CreatePixelShader", ShaderStage::Pixel, code, len, out);
}

HRESULT DeviceImpl::CreateInputLayout(const INPUT_ELEMENT_DESC* elements, UINT num, const void* code,
                                      size_t len, InputLayout** out) {
  const char* fn = "CreateInputLayout";
  if (out) *out = nullptr;
  if (!out || (!elements && num) || !code) {
    Log(LogLevel::Error, "%s: %s is null", fn, !out ? "ppInputLayout" : !code ? "pShaderBytecodeWithInputSignature" : "pInputElementDescs");
    return E_INVALIDARG;
  }
  if (num > 32) {
    Log(LogLevel::Error, "%s: %u elements (at most 32)", fn, num);
    return E_INVALIDARG;
  }
  if (len < 20 || len % 4) {
    Log(LogLevel::Error, "%s: vertex shader bytecode length %zu is not SPIR-V", fn, len);
    return E_INVALIDARG;
  }
  std::vector<uint32_t> words(len / 4);
  std::memcpy(words.data(), code, len);
  ShaderReflection refl;
  std::string err;
  if (!ReflectSpirv(words.data(), words.size(), &refl, &err) || refl.stage != VK_SHADER_STAGE_VERTEX_BIT) {
    Log(LogLevel::Error, "%s: %s", fn, err.empty() ? "the bytecode is not a vertex shader" : err.c_str());
    return E_INVALIDARG;
  }
  std::vector<InputLayoutImpl::Element> els;
  uint32_t nextOffset[IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT] = {};
  int slotRate[IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT];
  std::fill(std::begin(slotRate), std::end(slotRate), -1);
  uint32_t mask = 0;
  for (UINT i = 0; i < num; ++i) {
    const auto& e = elements[i];
    if (!e.SemanticName || !*e.SemanticName) {
      Log(LogLevel::Error, "%s: element %u has no SemanticName", fn, i);
      return E_INVALIDARG;
    }
    const FormatInfo* f = GetFormatInfo(e.Format);
    if (!f || f->bc || f->depth || !CheckFormatSupport(e.Format, BIND_VERTEX_BUFFER)) {
      Log(LogLevel::Error, "%s: element %u (%s%u): Format %u (%s) is not a vertex format", fn, i,
          e.SemanticName, e.SemanticIndex, e.Format, FormatName(e.Format));
      return E_INVALIDARG;
    }
    if (e.InputSlot >= IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT) {
      Log(LogLevel::Error, "%s: element %u (%s): InputSlot %u out of range (0..15)", fn, i, e.SemanticName, e.InputSlot);
      return E_INVALIDARG;
    }
    if (e.InputSlotClass > INPUT_PER_INSTANCE_DATA ||
        (e.InputSlotClass == INPUT_PER_VERTEX_DATA && e.InstanceDataStepRate != 0) ||
        (e.InputSlotClass == INPUT_PER_INSTANCE_DATA && e.InstanceDataStepRate != 1)) {
      Log(LogLevel::Error, "%s: element %u (%s): InputSlotClass %u with InstanceDataStepRate %u is not supported (per-vertex 0 or per-instance 1)", fn, i, e.SemanticName, e.InputSlotClass, e.InstanceDataStepRate);
      return E_INVALIDARG;
    }
    int rate = e.InputSlotClass == INPUT_PER_INSTANCE_DATA ? 1 : 0;
    if (slotRate[e.InputSlot] >= 0 && slotRate[e.InputSlot] != rate) {
      Log(LogLevel::Error, "%s: InputSlot %u mixes per-vertex and per-instance data", fn, e.InputSlot);
      return E_INVALIDARG;
    }
    slotRate[e.InputSlot] = rate;
    uint32_t off = e.AlignedByteOffset == APPEND_ALIGNED_ELEMENT ? (nextOffset[e.InputSlot] + 3) / 4 * 4 : e.AlignedByteOffset;
    if (off > 2048) {
      Log(LogLevel::Error, "%s: element %u (%s): AlignedByteOffset %u too large", fn, i, e.SemanticName, off);
      return E_INVALIDARG;
    }
    nextOffset[e.InputSlot] = off + f->bytes;
    InputLayoutImpl::Element el{ToUpper(e.SemanticName), e.SemanticIndex, f->vk, e.InputSlot, off, rate == 1};
    // "TEXCOORD1" written with the index in the name.
    size_t p = el.semantic.size();
    while (p > 0 && std::isdigit(static_cast<unsigned char>(el.semantic[p - 1]))) --p;
    if (p < el.semantic.size() && p > 0) {
      el.index = static_cast<uint32_t>(std::stoul(el.semantic.substr(p)));
      el.semantic.resize(p);
    }
    for (const auto& o : els)
      if (o.semantic == el.semantic && o.index == el.index) {
        Log(LogLevel::Error, "%s: semantic %s%u appears twice", fn, el.semantic.c_str(), el.index);
        return E_INVALIDARG;
      }
    els.push_back(el);
    mask |= 1u << e.InputSlot;
  }
  for (const auto& in : refl.inputs) {
    bool found = false;
    for (const auto& el : els)
      if (el.semantic == in.semantic && el.index == in.index) found = true;
    if (!found) {
      Log(LogLevel::Error, "%s: the vertex shader input %s%u (location %u) has no matching element", fn,
          in.semantic.empty() ? "<no semantic: compile with -fhlsl_functionality1>" : in.semantic.c_str(),
          in.index, in.location);
      return E_INVALIDARG;
    }
  }
  auto* il = new InputLayoutImpl(this);
  il->elements = std::move(els);
  il->slotMask = mask;
  *out = il;
  return S_OK;
}

}  // namespace d3dl::impl
