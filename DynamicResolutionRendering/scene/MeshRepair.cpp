// Mesh repair (ModelLoader.h, RepairMesh): what every loader's meshes go
// through before validation, whatever the format.
#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/FiniteVector.h"
#include "scene/ModelLoader.h"

namespace drr {

namespace {

void OrthoBasis(const glm::vec3& n, glm::vec3* t, glm::vec3* b) {
  glm::vec3 a = std::fabs(n.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  *t = glm::normalize(glm::cross(a, n));
  *b = glm::cross(n, *t);
}

// Drops the triangles with out-of-range indices, non-finite positions or no
// area, and says how many of each went.
void DropBadTriangles(MeshData* mesh, const std::string& who, std::vector<std::string>* messages) {
  auto& V = mesh->vertices;
  auto& I = mesh->indices;
  size_t badIndex = 0, badPos = 0, degenerate = 0;
  std::vector<uint8_t> posOk(V.size());
  for (size_t i = 0; i < V.size(); ++i) posOk[i] = Finite(V[i].position);
  std::vector<uint32_t> kept;
  kept.reserve(I.size());
  for (size_t t = 0; t + 2 < I.size(); t += 3) {
    uint32_t a = I[t], b = I[t + 1], c = I[t + 2];
    if (a >= V.size() || b >= V.size() || c >= V.size()) { ++badIndex; continue; }
    if (!posOk[a] || !posOk[b] || !posOk[c]) { ++badPos; continue; }
    glm::vec3 e1 = V[b].position - V[a].position, e2 = V[c].position - V[a].position;
    float area2 = glm::length(glm::cross(e1, e2));
    float scale = std::max({glm::dot(e1, e1), glm::dot(e2, e2), 1e-30f});
    if (a == b || b == c || a == c || !(area2 > 1e-7f * scale)) { ++degenerate; continue; }
    kept.insert(kept.end(), {a, b, c});
  }
  if (I.size() % 3) messages->push_back(who + ": index count not a multiple of 3, dropped the trailing " +
                                        std::to_string(I.size() % 3) + " indices");
  if (badIndex) messages->push_back(who + ": dropped " + std::to_string(badIndex) + " triangles with out-of-range indices");
  if (badPos) messages->push_back(who + ": dropped " + std::to_string(badPos) + " triangles with non-finite (NaN/Inf) vertex positions");
  if (degenerate) messages->push_back(who + ": dropped " + std::to_string(degenerate) + " degenerate (zero-area) triangles");
  I.swap(kept);
}

// Removes unreferenced vertices (among them every non-finite one), keeping
// the others in the order of their first use.
void CompactVertices(MeshData* mesh) {
  auto& V = mesh->vertices;
  std::vector<uint32_t> remap(V.size(), UINT32_MAX);
  std::vector<SceneVertex> nv;
  nv.reserve(V.size());
  for (uint32_t& idx : mesh->indices) {
    if (remap[idx] == UINT32_MAX) {
      remap[idx] = static_cast<uint32_t>(nv.size());
      nv.push_back(V[idx]);
    }
    idx = remap[idx];
  }
  V.swap(nv);
}

// For each vertex whose normal is unusable, the sum of its faces' normals
// (zero for the others).
std::vector<glm::vec3> FaceNormalSums(const MeshData& mesh, const std::vector<uint8_t>& needN) {
  const auto& V = mesh.vertices;
  const auto& I = mesh.indices;
  std::vector<glm::vec3> faceN(V.size(), glm::vec3(0.f));
  for (size_t t = 0; t < I.size(); t += 3) {
    glm::vec3 n = glm::cross(V[I[t + 1]].position - V[I[t]].position, V[I[t + 2]].position - V[I[t]].position);
    for (int k = 0; k < 3; ++k)
      if (needN[I[t + k]]) faceN[I[t + k]] += n;
  }
  return faceN;
}

// Tangent frame: orthonormalised against the normal, rebuilt when unusable.
void RepairTangentFrame(SceneVertex& v) {
  glm::vec3 t = v.tangent - v.normal * glm::dot(v.normal, v.tangent);
  float tl = glm::length(t);
  if (!Finite(v.tangent) || !Finite(v.binormal) || !std::isfinite(tl) || tl < 1e-6f) {
    OrthoBasis(v.normal, &v.tangent, &v.binormal);
  } else {
    t /= tl;
    float hand = glm::dot(glm::cross(v.normal, t), v.binormal) < 0.f ? -1.f : 1.f;
    v.tangent = t;
    v.binormal = glm::cross(v.normal, t) * hand;
  }
}

// Normals (rebuilt from the faces where missing), texture coordinates and
// tangent frames made finite and unit length.
void RepairVertexAttributes(MeshData* mesh, const std::string& who, std::vector<std::string>* messages) {
  auto& V = mesh->vertices;
  std::vector<uint8_t> needN(V.size());
  size_t fixedN = 0, fixedUV = 0;
  for (size_t i = 0; i < V.size(); ++i) {
    float l = glm::length(V[i].normal);
    needN[i] = !Finite(V[i].normal) || !(l > 1e-6f);
  }
  const std::vector<glm::vec3> faceN = FaceNormalSums(*mesh, needN);
  for (size_t i = 0; i < V.size(); ++i) {
    SceneVertex& v = V[i];
    if (needN[i]) {
      ++fixedN;
      float l = glm::length(faceN[i]);
      v.normal = (std::isfinite(l) && l > 0) ? faceN[i] / l : glm::vec3(0, 1, 0);
    } else {
      v.normal = glm::normalize(v.normal);
    }
    if (!Finite(v.texcoord)) { v.texcoord = glm::vec2(0.f); ++fixedUV; }
    RepairTangentFrame(v);  // silently: many files have no UVs, so no tangents
  }
  if (fixedN) messages->push_back(who + ": rebuilt " + std::to_string(fixedN) + " missing or non-finite normals");
  if (fixedUV) messages->push_back(who + ": replaced " + std::to_string(fixedUV) + " non-finite texture coordinates by 0");
}

void ComputeBounds(MeshData* mesh) {
  const auto& V = mesh->vertices;
  glm::vec3 mn(std::numeric_limits<float>::max()), mx(-std::numeric_limits<float>::max());
  for (const auto& v : V) {
    mn = glm::min(mn, v.position);
    mx = glm::max(mx, v.position);
  }
  mesh->boundsMin = mn;
  mesh->boundsMax = mx;
  mesh->sphereCenter = (mn + mx) * 0.5f;
  float r2 = 0;
  for (const auto& v : V) r2 = std::max(r2, glm::dot(v.position - mesh->sphereCenter, v.position - mesh->sphereCenter));
  mesh->sphereRadius = std::sqrt(r2);
}

}  // namespace

bool RepairMesh(MeshData* mesh, std::vector<std::string>* messages) {
  const std::string who = "mesh '" + mesh->name + "'";
  DropBadTriangles(mesh, who, messages);
  CompactVertices(mesh);
  if (mesh->indices.empty()) return false;
  RepairVertexAttributes(mesh, who, messages);
  ComputeBounds(mesh);
  return true;
}

}  // namespace drr
