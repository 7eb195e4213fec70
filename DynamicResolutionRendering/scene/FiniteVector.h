// Whether every component of a vector read from an untrusted file is finite:
// the model readers and the mesh repair drop or replace what is not.
#pragma once

#include <cmath>
#include <cstddef>

#include <glm/glm.hpp>

namespace drr {

inline bool Finite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
inline bool Finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline bool FiniteFloats(const float* p, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(p[i])) return false;
  return true;
}

}  // namespace drr
