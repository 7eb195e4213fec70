// The scene's vertex (input layout semantics POSITION, NORMAL, TEXCOORD0,
// TANGENT, BINORMAL), shared by the CPU loaders and the renderer.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

namespace drr {

struct SceneVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 texcoord;
  glm::vec3 tangent;
  glm::vec3 binormal;
};
static_assert(sizeof(SceneVertex) == 56, "SceneVertex must be 56 bytes");
static_assert(offsetof(SceneVertex, normal) == 12);
static_assert(offsetof(SceneVertex, texcoord) == 24);
static_assert(offsetof(SceneVertex, tangent) == 32);
static_assert(offsetof(SceneVertex, binormal) == 44);

}  // namespace drr
