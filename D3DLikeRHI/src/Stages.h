// Typed shader stages: the graphics stages the backend binds (kStages; the
// pipeline cache iterates them), per-stage arrays indexed by ShaderStage, and
// the names and Vulkan bits of each stage. Compute is not a graphics stage:
// its state is kept apart.
#pragma once

#include <vulkan/vulkan.h>

#include "d3dl/Bindings.h"

namespace d3dl::impl {

inline constexpr ShaderStage kStages[] = {ShaderStage::Vertex, ShaderStage::Pixel, ShaderStage::Hull,
                                          ShaderStage::Domain, ShaderStage::Geometry};
inline constexpr uint32_t kStageCount = sizeof(kStages) / sizeof(kStages[0]);

constexpr uint32_t StageIndex(ShaderStage s) { return static_cast<uint32_t>(s); }
// PerStage arrays hold kStageCount items: every graphics stage indexes one.
static_assert([] {
  for (ShaderStage s : kStages)
    if (StageIndex(s) >= kStageCount) return false;
  return true;
}());

// Prefix of the stage's context methods ("VS" in VSSetShader).
constexpr const char* StagePrefix(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return "VS";
    case ShaderStage::Pixel: return "PS";
    case ShaderStage::Hull: return "HS";
    case ShaderStage::Domain: return "DS";
    case ShaderStage::Geometry: return "GS";
    case ShaderStage::Compute: return "CS";  // not in kStages: compute state is apart
  }
  return "?";
}

// The stage in messages ("a vertex shader").
constexpr const char* StageName(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return "vertex";
    case ShaderStage::Pixel: return "pixel";
    case ShaderStage::Hull: return "hull";
    case ShaderStage::Domain: return "domain";
    case ShaderStage::Geometry: return "geometry";
    case ShaderStage::Compute: return "compute";
  }
  return "?";
}

constexpr VkShaderStageFlagBits ToVkStage(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return VK_SHADER_STAGE_VERTEX_BIT;
    case ShaderStage::Pixel: return VK_SHADER_STAGE_FRAGMENT_BIT;
    case ShaderStage::Hull: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    case ShaderStage::Domain: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
    case ShaderStage::Geometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
    case ShaderStage::Compute: return VK_SHADER_STAGE_COMPUTE_BIT;
  }
  return VK_SHADER_STAGE_ALL;
}

// One T per shader stage, indexed by ShaderStage.
template <class T>
class PerStage {
 public:
  T& operator[](ShaderStage s) { return items_[StageIndex(s)]; }
  const T& operator[](ShaderStage s) const { return items_[StageIndex(s)]; }
  T* begin() { return items_; }
  T* end() { return items_ + kStageCount; }
  const T* begin() const { return items_; }
  const T* end() const { return items_ + kStageCount; }

 private:
  T items_[kStageCount]{};
};

}  // namespace d3dl::impl
