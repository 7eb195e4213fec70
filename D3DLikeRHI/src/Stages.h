// Typed shader stages: every stage a context holds state for (kAllStages,
// indexed by ShaderStage's value, as Bindings.h numbers them), the graphics
// stages a pipeline is built from (kGraphicsStages; the pipeline cache iterates
// them), per-stage arrays, and the names and Vulkan bits of each stage.
#pragma once

#include <vulkan/vulkan.h>

#include "d3dl/Bindings.h"

namespace d3dl::impl {

inline constexpr ShaderStage kGraphicsStages[] = {ShaderStage::Vertex, ShaderStage::Pixel, ShaderStage::Hull,
                                                  ShaderStage::Domain, ShaderStage::Geometry};
inline constexpr uint32_t kGraphicsStageCount = sizeof(kGraphicsStages) / sizeof(kGraphicsStages[0]);
inline constexpr ShaderStage kAllStages[] = {ShaderStage::Vertex, ShaderStage::Pixel,    ShaderStage::Hull,
                                             ShaderStage::Domain, ShaderStage::Geometry, ShaderStage::Compute};
inline constexpr uint32_t kStageCount = sizeof(kAllStages) / sizeof(kAllStages[0]);

constexpr uint32_t StageIndex(ShaderStage s) { return static_cast<uint32_t>(s); }
// The graphics stages come first, so that a pipeline key's per-stage ids are
// the first kGraphicsStageCount entries of a PerStage array.
static_assert([] {
  for (uint32_t i = 0; i < kStageCount; ++i)
    if (StageIndex(kAllStages[i]) != i) return false;
  for (ShaderStage s : kGraphicsStages)
    if (StageIndex(s) >= kGraphicsStageCount) return false;
  return StageIndex(ShaderStage::Compute) == kGraphicsStageCount;
}());

// Prefix of the stage's context methods ("VS" in VSSetShader).
constexpr const char* StagePrefix(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return "VS";
    case ShaderStage::Pixel: return "PS";
    case ShaderStage::Hull: return "HS";
    case ShaderStage::Domain: return "DS";
    case ShaderStage::Geometry: return "GS";
    case ShaderStage::Compute: return "CS";
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

// One T per shader stage (compute included), indexed by ShaderStage.
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
