// Primitive topologies: the D3D11 values the RHI accepts, their Vulkan
// topology, and the primitive class pipelines are built for (the exact
// topology inside a class is dynamic state; a patch list's control-point
// count is pipeline state).
#pragma once

#include <vulkan/vulkan.h>

#include "d3dl/Types.h"

namespace d3dl::impl {

enum PrimitiveClass : uint32_t { kPointClass = 0, kLineClass = 1, kTriangleClass = 2, kPatchClass = 3 };

constexpr bool IsPatchList(PRIMITIVE_TOPOLOGY t) {
  return t >= PRIMITIVE_TOPOLOGY_1_CONTROL_POINT_PATCHLIST && t <= PRIMITIVE_TOPOLOGY_32_CONTROL_POINT_PATCHLIST;
}

// Control points per patch (1..32), 0 for the other topologies.
constexpr uint32_t PatchControlPoints(PRIMITIVE_TOPOLOGY t) {
  return IsPatchList(t) ? t - PRIMITIVE_TOPOLOGY_1_CONTROL_POINT_PATCHLIST + 1 : 0;
}

// UNDEFINED, the list and strip topologies and the patch lists.
constexpr bool IsSupportedTopology(PRIMITIVE_TOPOLOGY t) {
  return t <= PRIMITIVE_TOPOLOGY_TRIANGLESTRIP || IsPatchList(t);
}

constexpr PrimitiveClass TopologyClass(PRIMITIVE_TOPOLOGY t) {
  switch (t) {
    case PRIMITIVE_TOPOLOGY_POINTLIST: return kPointClass;
    case PRIMITIVE_TOPOLOGY_LINELIST:
    case PRIMITIVE_TOPOLOGY_LINESTRIP: return kLineClass;
    default: return IsPatchList(t) ? kPatchClass : kTriangleClass;
  }
}

constexpr VkPrimitiveTopology ToVkTopology(PRIMITIVE_TOPOLOGY t) {
  switch (t) {
    case PRIMITIVE_TOPOLOGY_POINTLIST: return VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    case PRIMITIVE_TOPOLOGY_LINELIST: return VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
    case PRIMITIVE_TOPOLOGY_LINESTRIP: return VK_PRIMITIVE_TOPOLOGY_LINE_STRIP;
    case PRIMITIVE_TOPOLOGY_TRIANGLESTRIP: return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    default: return IsPatchList(t) ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  }
}

// The pipeline's topology for a key's class.
constexpr VkPrimitiveTopology ClassTopology(uint32_t cls) {
  return cls == kPointClass  ? VK_PRIMITIVE_TOPOLOGY_POINT_LIST
         : cls == kLineClass ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST
         : cls == kPatchClass ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST
                              : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
}

}  // namespace d3dl::impl
