// Input layouts: D3D11 elements matched to the vertex shader's inputs by
// semantic name and index. The checks need the computed offsets and the
// shader's reflected inputs, so they are made while the elements are built.
#include <cctype>

#include "Context.h"

namespace d3dl::impl {
namespace {
const char* kFn = "CreateInputLayout";

// Offsets and input rates of the slots so far (-1: slot unused).
struct SlotState {
  uint32_t nextOffset[IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT] = {};
  int rate[IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT];
  SlotState() { std::fill(std::begin(rate), std::end(rate), -1); }
};

bool ValidSlotClass(const INPUT_ELEMENT_DESC& e) {
  return e.InputSlotClass <= INPUT_PER_INSTANCE_DATA &&
         !(e.InputSlotClass == INPUT_PER_VERTEX_DATA && e.InstanceDataStepRate != 0) &&
         !(e.InputSlotClass == INPUT_PER_INSTANCE_DATA && e.InstanceDataStepRate != 1);
}

// Element i of the layout; false (logged) when it cannot be used.
bool BuildElement(DeviceImpl& dev, const INPUT_ELEMENT_DESC& e, UINT i, SlotState& slots, InputLayoutImpl::Element* el) {
  if (!e.SemanticName || !*e.SemanticName) {
    dev.Log(LogLevel::Error, "%s: element %u has no SemanticName", kFn, i);
    return false;
  }
  const FormatInfo* f = GetFormatInfo(e.Format);
  if (!f || f->bc || f->depth || !dev.CheckFormatSupport(e.Format, BIND_VERTEX_BUFFER)) {
    dev.Log(LogLevel::Error, "%s: element %u (%s%u): Format %u (%s) is not a vertex format", kFn, i, e.SemanticName,
            e.SemanticIndex, e.Format, FormatName(e.Format));
    return false;
  }
  if (e.InputSlot >= IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT) {
    dev.Log(LogLevel::Error, "%s: element %u (%s): InputSlot %u out of range (0..15)", kFn, i, e.SemanticName, e.InputSlot);
    return false;
  }
  if (!ValidSlotClass(e)) {
    dev.Log(LogLevel::Error, "%s: element %u (%s): InputSlotClass %u with InstanceDataStepRate %u is not supported (per-vertex 0 or per-instance 1)", kFn, i, e.SemanticName, e.InputSlotClass, e.InstanceDataStepRate);
    return false;
  }
  const int rate = e.InputSlotClass == INPUT_PER_INSTANCE_DATA ? 1 : 0;
  if (slots.rate[e.InputSlot] >= 0 && slots.rate[e.InputSlot] != rate) {
    dev.Log(LogLevel::Error, "%s: InputSlot %u mixes per-vertex and per-instance data", kFn, e.InputSlot);
    return false;
  }
  slots.rate[e.InputSlot] = rate;
  const uint32_t off = e.AlignedByteOffset == APPEND_ALIGNED_ELEMENT ? (slots.nextOffset[e.InputSlot] + 3) / 4 * 4
                                                                     : e.AlignedByteOffset;
  if (off > 2048) {
    dev.Log(LogLevel::Error, "%s: element %u (%s): AlignedByteOffset %u too large", kFn, i, e.SemanticName, off);
    return false;
  }
  slots.nextOffset[e.InputSlot] = off + f->bytes;
  *el = {ToUpper(e.SemanticName), e.SemanticIndex, f->vk, e.InputSlot, off, rate == 1};
  // "TEXCOORD1" written with the index in the name.
  const bool allDigits = std::all_of(el->semantic.begin(), el->semantic.end(),
                                     [](unsigned char c) { return std::isdigit(c) != 0; });
  if (!allDigits) SplitSemanticIndex(&el->semantic, &el->index);
  return true;
}

bool FindElement(const std::vector<InputLayoutImpl::Element>& els, const std::string& semantic, uint32_t index) {
  for (const auto& el : els)
    if (el.semantic == semantic && el.index == index) return true;
  return false;
}

// Every input of the vertex shader needs an element.
bool MatchShaderInputs(DeviceImpl& dev, const ShaderReflection& refl, const std::vector<InputLayoutImpl::Element>& els) {
  for (const auto& in : refl.inputs) {
    if (FindElement(els, in.semantic, in.index)) continue;
    dev.Log(LogLevel::Error, "%s: the vertex shader input %s%u (location %u) has no matching element", kFn,
            in.semantic.empty() ? "<no semantic: compile with -fhlsl_functionality1>" : in.semantic.c_str(),
            in.index, in.location);
    return false;
  }
  return true;
}

bool ReflectVertexShader(DeviceImpl& dev, const void* code, size_t len, ShaderReflection* refl) {
  if (len < 20 || len % 4) {
    dev.Log(LogLevel::Error, "%s: vertex shader bytecode length %zu is not SPIR-V", kFn, len);
    return false;
  }
  std::vector<uint32_t> words(len / 4);
  std::memcpy(words.data(), code, len);
  std::string err;
  if (!ReflectSpirv(words.data(), words.size(), refl, &err) || refl->stage != ShaderStage::Vertex) {
    dev.Log(LogLevel::Error, "%s: %s", kFn, err.empty() ? "the bytecode is not a vertex shader" : err.c_str());
    return false;
  }
  return true;
}

}  // namespace

HRESULT DeviceImpl::CreateInputLayout(const INPUT_ELEMENT_DESC* elements, UINT num, const void* code, size_t len,
                                      InputLayout** out) {
  if (out) *out = nullptr;
  if (!out || (!elements && num) || !code) {
    Log(LogLevel::Error, "%s: %s is null", kFn, !out ? "ppInputLayout" : !code ? "pShaderBytecodeWithInputSignature" : "pInputElementDescs");
    return E_INVALIDARG;
  }
  if (num > 32) {
    Log(LogLevel::Error, "%s: %u elements (at most 32)", kFn, num);
    return E_INVALIDARG;
  }
  ShaderReflection refl;
  if (!ReflectVertexShader(*this, code, len, &refl)) return E_INVALIDARG;
  std::vector<InputLayoutImpl::Element> els;
  SlotState slots;
  uint32_t mask = 0;
  for (UINT i = 0; i < num; ++i) {
    InputLayoutImpl::Element el;
    if (!BuildElement(*this, elements[i], i, slots, &el)) return E_INVALIDARG;
    if (FindElement(els, el.semantic, el.index)) {
      Log(LogLevel::Error, "%s: semantic %s%u appears twice", kFn, el.semantic.c_str(), el.index);
      return E_INVALIDARG;
    }
    els.push_back(el);
    mask |= 1u << elements[i].InputSlot;
  }
  if (!MatchShaderInputs(*this, refl, els)) return E_INVALIDARG;
  auto* il = new InputLayoutImpl(this);
  il->elements = std::move(els);
  il->slotMask = mask;
  *out = il;
  return S_OK;
}

}  // namespace d3dl::impl
