// How D3D register slots become Vulkan bindings: one formula, documented in
// Docs/D3D11-to-Vulkan.md and applied to HLSL by glslang's per-stage binding
// shifts (cmake/HLSL.cmake, and the runtime compiler in ShaderCompiler.h).
//
//   descriptor set 0,  binding = 72 * stage + classBase + slot
//   stage:     VS = 0, PS = 1, HS = 2, DS = 3, GS = 4, CS = 5
//   classBase: b# = 0 (0..13), t# = 16 (0..31), s# = 48 (0..15), u# = 64 (0..7)
#pragma once

#include <cstdint>

namespace d3dl {

enum class ShaderStage : uint32_t { Vertex = 0, Pixel = 1, Hull = 2, Domain = 3,
                                    Geometry = 4, Compute = 5 };
enum class RegisterClass : uint32_t { ConstantBuffer, Texture, Sampler, UnorderedAccess };

inline constexpr uint32_t kStageBindingStride = 72;
inline constexpr uint32_t kConstantBufferBase = 0;
inline constexpr uint32_t kTextureBase = 16;
inline constexpr uint32_t kSamplerBase = 48;
inline constexpr uint32_t kMaxConstantBufferSlots = 14;  // D3D11: b0..b13
inline constexpr uint32_t kMaxTextureSlots = 32;         // t0..t31
inline constexpr uint32_t kMaxSamplerSlots = 16;         // D3D11: s0..s15
// Unordered access views (u#): D3D11.0's 8 UAV slots of the compute and pixel stages.
inline constexpr uint32_t kUnorderedAccessBase = 64;
inline constexpr uint32_t kMaxUnorderedAccessSlots = 8;  // u0..u7

inline constexpr uint32_t RegisterClassBase(RegisterClass c) {
  return c == RegisterClass::ConstantBuffer ? kConstantBufferBase
         : c == RegisterClass::Texture      ? kTextureBase
         : c == RegisterClass::Sampler      ? kSamplerBase
                                            : kUnorderedAccessBase;
}

inline constexpr uint32_t RegisterSlotCount(RegisterClass c) {
  return c == RegisterClass::ConstantBuffer ? kMaxConstantBufferSlots
         : c == RegisterClass::Texture      ? kMaxTextureSlots
         : c == RegisterClass::Sampler      ? kMaxSamplerSlots
                                            : kMaxUnorderedAccessSlots;
}

inline constexpr uint32_t VulkanBinding(ShaderStage stage, RegisterClass c, uint32_t slot) {
  return kStageBindingStride * static_cast<uint32_t>(stage) + RegisterClassBase(c) + slot;
}

static_assert(kTextureBase >= kConstantBufferBase + kMaxConstantBufferSlots);
static_assert(kSamplerBase >= kTextureBase + kMaxTextureSlots);
static_assert(kUnorderedAccessBase >= kSamplerBase + kMaxSamplerSlots);
static_assert(kStageBindingStride >= kUnorderedAccessBase + kMaxUnorderedAccessSlots);

}  // namespace d3dl
