// Shader modules: SPIR-V checked against the stage and the binding formula
// of Bindings.h, stripped of the HLSL-only decorations, cached by the
// pipeline cache under the shader's uid.
#include <cstdio>

#include "Context.h"
#include "Spirv.h"
#include "Validate.h"

namespace d3dl::impl {
namespace {

// glslang's -fhlsl_functionality1 adds SPV_GOOGLE_hlsl_functionality1 /
// SPV_GOOGLE_user_type and their decorations (the HLSL semantics reflected
// by ReflectSpirv). Drivers without VK_GOOGLE_hlsl_functionality1 must not
// see them, so the module is created from a copy without those instructions.
bool IsGoogleInstruction(const uint32_t* w, uint32_t op, uint32_t wc) {
  using namespace spirv;
  if (op == OpExtension) {
    const std::string name = ReadSpirvString(w + 1, wc - 1);
    return name == "SPV_GOOGLE_hlsl_functionality1" || name == "SPV_GOOGLE_user_type" ||
           name == "SPV_GOOGLE_decorate_string";
  }
  if (op == OpDecorateString && wc >= 3) return w[2] == DecUserSemantic || w[2] == DecUserType;
  if (op == OpMemberDecorateString && wc >= 4) return w[3] == DecUserSemantic || w[3] == DecUserType;
  if (op == OpDecorateId && wc >= 3) return w[2] == DecHlslCounterBuffer;
  return false;
}

std::vector<uint32_t> StripGoogleDecorations(const std::vector<uint32_t>& in) {
  std::vector<uint32_t> out(in.begin(), in.begin() + 5);
  for (size_t i = 5; i < in.size();) {
    const uint32_t op = in[i] & 0xffff, wc = in[i] >> 16;
    if (wc == 0 || i + wc > in.size()) return in;
    if (!IsGoogleInstruction(&in[i], op, wc)) out.insert(out.end(), in.begin() + i, in.begin() + i + wc);
    i += wc;
  }
  return out;
}

// Storage buffers are StructuredBuffer/ByteAddressBuffer (t#) or their RW
// forms (u#): the binding's range tells which.
RegisterClass ClassOf(const ReflectedBinding& b, uint32_t stageBase, bool* known) {
  *known = true;
  switch (b.type) {
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC: return RegisterClass::ConstantBuffer;
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: return RegisterClass::Texture;
    case VK_DESCRIPTOR_TYPE_SAMPLER: return RegisterClass::Sampler;
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: *known = !b.image1D; return RegisterClass::UnorderedAccess;  // RWTexture2D
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
      return b.binding >= stageBase + kUnorderedAccessBase ? RegisterClass::UnorderedAccess : RegisterClass::Texture;
    default: *known = false; return RegisterClass::ConstantBuffer;
  }
}

// D3D11.0 has UAVs in the compute and pixel stages only.
bool StageHasUavs(ShaderStage s) { return s == ShaderStage::Compute || s == ShaderStage::Pixel; }

// Checks that every binding follows the formula of Bindings.h for the stage.
bool CheckBindings(const ShaderReflection& r, ShaderStage stage, std::string* error) {
  const uint32_t base = kStageBindingStride * StageIndex(stage);
  char buf[256];
  for (const auto& b : r.bindings) {
    bool known;
    const RegisterClass cls = ClassOf(b, base, &known);
    const uint32_t lo = base + RegisterClassBase(cls), hi = lo + RegisterSlotCount(cls);
    if (b.set != 0)
      std::snprintf(buf, sizeof(buf), "'%s' uses descriptor set %u (only set 0 is used)", b.name.c_str(), b.set);
    else if (!known)
      std::snprintf(buf, sizeof(buf), "'%s' (binding %u) is a resource kind D3DLikeRHI does not bind (only cbuffer, Texture1D/2D, SamplerState, (RW)StructuredBuffer, (RW)ByteAddressBuffer, RWTexture2D)", b.name.c_str(), b.binding);
    else if (cls == RegisterClass::UnorderedAccess && !StageHasUavs(stage))
      std::snprintf(buf, sizeof(buf), "'%s' (binding %u) is an unordered access view; only compute and pixel shaders have them", b.name.c_str(), b.binding);
    else if (b.binding < lo || b.binding >= hi)
      std::snprintf(buf, sizeof(buf), "'%s' has binding %u, outside [%u, %u) required by the binding formula for this stage; compile with the shifts of cmake/HLSL.cmake", b.name.c_str(), b.binding, lo, hi);
    else
      continue;
    *error = buf;
    return false;
  }
  return true;
}

// Reflects `code` and checks it is a shader of `stage` following the binding
// formula; false with a message otherwise.
bool ReflectStage(const std::vector<uint32_t>& words, ShaderStage stage, ShaderReflection* refl, std::string* err) {
  if (!ReflectSpirv(words.data(), words.size(), refl, err)) return false;
  if (refl->stage != stage) {
    *err = "the SPIR-V entry point '" + refl->entry + "' is a " + StageName(refl->stage) + " shader";
    return false;
  }
  if (refl->geometryAdjacency) {
    *err = "the geometry shader takes lineadj/triangleadj input; D3DLikeRHI has no adjacency topologies";
    return false;
  }
  return CheckBindings(*refl, stage, err);
}

}  // namespace

template <class Iface>
ShaderImpl<Iface>::~ShaderImpl() {
  this->dev_->pipelines().ForgetShader(cacheId);
  this->dev_->Defer(VK_OBJECT_TYPE_SHADER_MODULE, reinterpret_cast<uint64_t>(module));
}
template <class Iface>
void ShaderImpl<Iface>::OnDebugName() {
  this->dev_->SetName(VK_OBJECT_TYPE_SHADER_MODULE, reinterpret_cast<uint64_t>(module), this->name_);
}
template class ShaderImpl<VertexShader>;
template class ShaderImpl<PixelShader>;
template class ShaderImpl<HullShader>;
template class ShaderImpl<DomainShader>;
template class ShaderImpl<GeometryShader>;
template class ShaderImpl<ComputeShader>;

template <class Impl, class Iface>
static HRESULT CreateShader(DeviceImpl* dev, const char* fn, ShaderStage stage, const void* code, size_t len,
                            Iface** out) {
  if (out) *out = nullptr;
  const HRESULT valid = ValidateShaderBytecode(*dev, fn, code, len, out);
  if (FAILED(valid)) return valid;
  std::vector<uint32_t> words(len / 4);
  std::memcpy(words.data(), code, len);
  ShaderReflection refl;
  std::string err;
  if (!ReflectStage(words, stage, &refl, &err)) {
    dev->Log(LogLevel::Error, "%s: %s", fn, err.c_str());
    return E_INVALIDARG;
  }
  const std::vector<uint32_t> stripped = StripGoogleDecorations(words);
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
HRESULT DeviceImpl::CreateComputeShader(const void* code, size_t len, ComputeShader** out) {
  return CreateShader<ComputeShaderImpl>(this, "CreateComputeShader", ShaderStage::Compute, code, len, out);
}

// Hull, domain and geometry shaders: only on adapters that have the stage.
namespace {
bool StageSupported(DeviceImpl* dev, const char* fn, bool supported, const char* what, const char* feature) {
  if (supported) return true;
  dev->Log(LogLevel::Error, "%s: the adapter %s does not support %s (VkPhysicalDeviceFeatures::%s)", fn,
           dev->props().deviceName, what, feature);
  return false;
}
}  // namespace

HRESULT DeviceImpl::CreateHullShader(const void* code, size_t len, HullShader** out) {
  if (out) *out = nullptr;
  if (!StageSupported(this, "CreateHullShader", features().tessellation, "tessellation", "tessellationShader")) return E_NOTIMPL;
  return CreateShader<HullShaderImpl>(this, "CreateHullShader", ShaderStage::Hull, code, len, out);
}
HRESULT DeviceImpl::CreateDomainShader(const void* code, size_t len, DomainShader** out) {
  if (out) *out = nullptr;
  if (!StageSupported(this, "CreateDomainShader", features().tessellation, "tessellation", "tessellationShader")) return E_NOTIMPL;
  return CreateShader<DomainShaderImpl>(this, "CreateDomainShader", ShaderStage::Domain, code, len, out);
}
HRESULT DeviceImpl::CreateGeometryShader(const void* code, size_t len, GeometryShader** out) {
  if (out) *out = nullptr;
  if (!StageSupported(this, "CreateGeometryShader", features().geometry, "geometry shaders", "geometryShader")) return E_NOTIMPL;
  return CreateShader<GeometryShaderImpl>(this, "CreateGeometryShader", ShaderStage::Geometry, code, len, out);
}

}  // namespace d3dl::impl
