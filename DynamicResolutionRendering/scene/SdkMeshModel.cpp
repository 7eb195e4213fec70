#include "scene/SdkMeshModel.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <unordered_map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace drr {
namespace fs = std::filesystem;
using namespace sdkmesh;

namespace {

std::string LowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

constexpr uint64_t kMaxFileBytes = 4ull << 30;

// The original's input layout (Scene.cpp of the original): POSITION, NORMAL, TEXCOORD0, TANGENT,
// BINORMAL at fixed offsets, used for every file whatever its declaration.
constexpr VertexElement kOriginalTangent{0, 32, kFloat3, 0, kTangent, 0};
constexpr VertexElement kOriginalBinormal{0, 44, kFloat3, 0, kBinormal, 0};

// Whether the declaration starts as the original's layout (its files all do): position, normal
// and texture coordinates where that layout reads them, room for its tangent and binormal.
bool StartsAsOriginalLayout(const VertexBuffer& vb) {
  auto at = [&](uint8_t usage, uint16_t offset, uint8_t type) {
    const VertexElement* e = vb.Find(usage, 0);
    return e && e->offset == offset && e->type == type;
  };
  return vb.stride >= 56 && at(kPosition, 0, kFloat3) && at(kNormal, 12, kFloat3) && at(kTexCoord, 24, kFloat2);
}

// The elements of the scene's vertex in one vertex buffer (null when absent).
struct VertexLayout {
  const VertexElement *position, *normal, *texcoord, *tangent, *binormal;
  VertexLayout(const VertexBuffer& vb, bool declared)
      : position(vb.Find(kPosition, 0)), normal(vb.Find(kNormal, 0)), texcoord(vb.Find(kTexCoord, 0)),
        tangent(vb.Find(kTangent, 0)), binormal(vb.Find(kBinormal, 0)) {
    if (!declared && StartsAsOriginalLayout(vb)) {
      // As the original draws it: with two or more texture coordinate sets (64-, 72- and
      // 80-byte vertices) these bytes are the extra sets, not the tangent frame.
      tangent = &kOriginalTangent;
      binormal = &kOriginalBinormal;
    }
  }
};

SceneVertex DecodeVertex(const File& f, const VertexBuffer& vb, const VertexLayout& l, uint64_t v) {
  auto get3 = [&](const VertexElement* e) { return e ? glm::vec3(f.Element(vb, *e, v)) : glm::vec3(0.f); };
  SceneVertex sv;
  sv.position = VectorToRightHanded(get3(l.position));
  sv.normal = VectorToRightHanded(get3(l.normal));
  sv.texcoord = l.texcoord ? glm::vec2(f.Element(vb, *l.texcoord, v)) : glm::vec2(0.f);
  sv.tangent = VectorToRightHanded(get3(l.tangent));
  sv.binormal = VectorToRightHanded(get3(l.binormal));
  return sv;
}

// The subset's triangles as index triples into its vertex buffer (base vertex added).
std::vector<uint64_t> SubsetTriangles(const File& f, const IndexBuffer& ib, const Subset& s) {
  std::vector<uint64_t> tri;
  const bool strip = s.primitiveType == kTriangleStrip;
  const uint64_t count = strip ? (s.indexCount >= 3 ? s.indexCount - 2 : 0) : s.indexCount / 3;
  tri.reserve(count * 3);
  for (uint64_t t = 0; t < count; ++t) {
    uint64_t a = strip ? t : 3 * t, b = a + 1, c = a + 2;
    if (strip && (t & 1)) std::swap(b, c);  // every other strip triangle has the opposite order
    for (uint64_t k : {a, b, c}) tri.push_back(uint64_t(f.Index(ib, s.indexStart + k)) + s.vertexStart);
  }
  return tri;
}

struct Budget {
  const ModelLoadOptions& opts;
  uint64_t vertices = 0, triangles = 0;
};

// One subset as a MeshData; false with *error when it exceeds the limits.
bool ConvertSubset(const File& f, const Mesh& m, const Subset& s, Budget& budget, MeshData* out, std::string* error) {
  const VertexBuffer& vb = f.vertexBuffers[m.vertexBuffers[0]];
  const IndexBuffer& ib = f.indexBuffers[m.indexBuffer];
  out->name = m.name + "/" + s.name;
  out->material = s.material;
  const std::vector<uint64_t> tri = SubsetTriangles(f, ib, s);
  budget.triangles += tri.size() / 3;
  if (budget.triangles > budget.opts.maxTriangles) {
    *error = f.path + ": more than " + std::to_string(budget.opts.maxTriangles) + " triangles";
    return false;
  }
  const VertexLayout layout(vb, budget.opts.sdkmeshDeclaredLayout);
  std::unordered_map<uint64_t, uint32_t> remap;
  size_t outOfRange = 0;
  for (size_t t = 0; t + 2 < tri.size(); t += 3) {
    if (tri[t] >= vb.numVertices || tri[t + 1] >= vb.numVertices || tri[t + 2] >= vb.numVertices) {
      ++outOfRange;
      continue;
    }
    // Corners 0, 2, 1: the image is the original's, so its clockwise front faces must become the
    // port's counter-clockwise ones on screen.
    for (size_t k : {0, 2, 1}) {
      auto [it, added] = remap.try_emplace(tri[t + k], uint32_t(out->vertices.size()));
      if (added) out->vertices.push_back(DecodeVertex(f, vb, layout, tri[t + k]));
      out->indices.push_back(it->second);
    }
    if (budget.vertices + out->vertices.size() > budget.opts.maxVertices) {
      *error = f.path + ": more than " + std::to_string(budget.opts.maxVertices) + " vertices";
      return false;
    }
  }
  budget.vertices += out->vertices.size();
  if (outOfRange) *error = std::to_string(outOfRange) + " triangles with indices past the vertex buffer's end";
  return true;
}

bool IsTriangles(uint32_t primitiveType) { return primitiveType == kTriangleList || primitiveType == kTriangleStrip; }

// Meshes: for each SDKMESH mesh, the MeshData indices of its triangle subsets.
bool ConvertMeshes(const File& f, const ModelLoadOptions& opts, ModelData* out,
                   std::vector<std::vector<uint32_t>>* parts, std::string* error) {
  Budget budget{opts};
  for (const Mesh& m : f.meshes) {
    parts->emplace_back();
    for (uint32_t si : m.subsets) {
      const Subset& s = f.subsets[si];
      const std::string who = "mesh '" + m.name + "', subset '" + s.name + "': ";
      const IndexBuffer& ib = f.indexBuffers[m.indexBuffer];
      if (s.indexStart > ib.numIndices || s.indexCount > ib.numIndices - s.indexStart) {
        *error = f.path + ": " + who + "indices " + std::to_string(s.indexStart) + " + " + std::to_string(s.indexCount) +
                 " past the index buffer's " + std::to_string(ib.numIndices);
        return false;
      }
      if (!IsTriangles(s.primitiveType)) {
        out->warnings.push_back(who + PrimitiveTypeName(s.primitiveType) + " primitives are not drawn");
        continue;
      }
      MeshData md;
      std::string note;
      if (!ConvertSubset(f, m, s, budget, &md, &note)) {
        *error = note;
        return false;
      }
      if (!note.empty()) out->warnings.push_back(who + "dropped " + note);
      if (!RepairMesh(&md, &out->warnings)) continue;
      parts->back().push_back(uint32_t(out->meshes.size()));
      out->meshes.push_back(std::move(md));
    }
  }
  return true;
}

// The frames reached from frame 0 through child and sibling links, each with
// its parent frame (kInvalid for the top level), in an order where parents
// come first: the frames' own order when it has that property, else the visit order.
std::vector<std::pair<uint32_t, uint32_t>> ReachableFrames(const File& f, std::vector<std::string>* warnings) {
  std::vector<std::pair<uint32_t, uint32_t>> order;  // (frame, parent frame)
  if (f.frames.empty()) return order;
  std::vector<bool> seen(f.frames.size(), false);
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, kInvalid}};
  while (!stack.empty()) {
    const auto [frame, parent] = stack.back();
    stack.pop_back();
    if (frame >= f.frames.size() || seen[frame]) {
      warnings->push_back("frame link to " + std::to_string(frame) + " (out of range or seen before) ignored");
      continue;
    }
    seen[frame] = true;
    order.push_back({frame, parent});
    const Frame& fr = f.frames[frame];
    if (fr.sibling != kInvalid) stack.push_back({fr.sibling, parent});
    if (fr.child != kInvalid) stack.push_back({fr.child, frame});
  }
  for (size_t i = 0; i < f.frames.size(); ++i)
    if (!seen[i] && f.frames[i].mesh != kInvalid)
      warnings->push_back("frame '" + f.frames[i].name + "' is not linked from the first frame: not drawn");
  auto sorted = order;
  std::sort(sorted.begin(), sorted.end());
  const bool parentsFirst = std::all_of(sorted.begin(), sorted.end(), [](const auto& p) {
    return p.second == kInvalid || p.second < p.first;
  });
  return parentsFirst ? sorted : order;
}

void ConvertFrames(const File& f, const std::vector<std::vector<uint32_t>>& parts, ModelData* out) {
  const auto order = ReachableFrames(f, &out->warnings);
  std::vector<int> nodeOf(f.frames.size(), -1);
  for (const auto& [frame, parent] : order) {
    const Frame& fr = f.frames[frame];
    NodeData n;
    n.name = fr.name;
    n.parent = parent == kInvalid ? -1 : nodeOf[parent];
    n.local = FrameMatrixToRightHanded(fr.matrix);
    n.baseT = glm::vec3(n.local[3]);
    if (fr.mesh != kInvalid && fr.mesh < parts.size()) n.meshes = parts[fr.mesh];
    else if (fr.mesh != kInvalid) out->warnings.push_back("frame '" + fr.name + "': mesh " + std::to_string(fr.mesh) + " out of range");
    nodeOf[frame] = int(out->nodes.size());
    out->nodes.push_back(std::move(n));
  }
}

std::string TexturePath(const fs::path& folder, std::string name) {
  if (name.empty()) return {};
  std::replace(name.begin(), name.end(), '\\', '/');
  return (folder / name).lexically_normal().string();
}

}  // namespace

bool IsSdkMeshPath(const std::string& path) { return LowerExtension(path) == ".sdkmesh"; }
bool IsSdkMeshAnimPath(const std::string& path) { return LowerExtension(path) == ".sdkmesh_anim"; }

glm::vec3 VectorToRightHanded(const glm::vec3& v) { return {v.x, v.y, -v.z}; }

glm::mat4 FrameMatrixToRightHanded(const float rowMajor[16]) {
  // Row-major with row vectors read column-major is the column-vector matrix.
  const glm::mat4 m = glm::make_mat4(rowMajor);
  const glm::mat4 mirror = glm::scale(glm::mat4(1.f), glm::vec3(1.f, 1.f, -1.f));
  return mirror * m * mirror;
}

glm::quat OrientationToRightHanded(const glm::vec4& q) {
  // In double: components near the float range would overflow the length.
  const glm::dvec4 d(q);
  const double length = glm::length(d);
  if (!(length > 0.0) || !std::isfinite(length)) return glm::quat(1.f, 0.f, 0.f, 0.f);  // all zero: identity
  const glm::vec4 n(d / length);
  return glm::quat(n.w, -n.x, -n.y, n.z);  // mirrored z: the axis's x, y flip with the angle
}

bool SdkMeshToModel(const File& f, const ModelLoadOptions& opts, ModelData* out, std::string* error) {
  *out = ModelData{};
  out->file = f.path;
  const fs::path folder = fs::path(f.path).parent_path();
  for (const Material& m : f.materials) {
    MaterialData md;
    md.name = m.name;
    md.diffuseTex = TexturePath(folder, m.diffuseTexture);
    md.normalTex = TexturePath(folder, m.normalTexture);
    md.specularTex = TexturePath(folder, m.specularTexture);
    out->materials.push_back(std::move(md));
  }
  std::vector<std::vector<uint32_t>> parts;
  if (!ConvertMeshes(f, opts, out, &parts, error)) return false;
  ConvertFrames(f, parts, out);
  if (out->meshes.empty()) {
    *error = f.path + ": no triangles to draw (" + std::to_string(f.meshes.size()) + " meshes, " +
             std::to_string(f.subsets.size()) + " subsets)";
    return false;
  }
  return true;
}

bool SdkMeshAnimToModel(const AnimFile& a, ModelData* out, std::string* /*error*/) {
  *out = ModelData{};
  out->file = a.path;
  AnimationData anim;
  anim.name = fs::path(a.path).stem().string();
  // Keys 0..n-1 at k / fps, then key 0 again at n / fps: the last key blends into the first.
  const uint32_t n = a.fps ? a.numKeys : 1;
  anim.duration = a.fps ? double(n) / a.fps : 0.0;
  for (const AnimFrame& fr : a.frames) {
    NodeData node;
    node.name = fr.name;
    NodeChannel ch;
    ch.node = int(out->nodes.size());
    for (uint32_t k = 0; k <= n; ++k) {
      const AnimKey& key = fr.keys[k % n];
      const double t = a.fps ? double(k) / a.fps : double(k);
      ch.positions.push_back({t, VectorToRightHanded(key.translation)});
      ch.rotations.push_back({t, OrientationToRightHanded(key.orientation)});
      ch.scalings.push_back({t, key.scaling});
    }
    out->nodes.push_back(std::move(node));
    anim.channels.push_back(std::move(ch));
  }
  out->animations.push_back(std::move(anim));
  return true;
}

bool LoadSdkMeshModel(const std::string& path, const ModelLoadOptions& opts, ModelData* out, std::string* error) {
  std::vector<uint8_t> bytes;
  if (!LoadFileBytes(path, kMaxFileBytes, &bytes, error)) return false;
  if (IsSdkMeshAnimPath(path)) {
    if (!opts.animationsOnly) {
      *error = path + ": an SDKMESH_ANIM file holds no mesh (it belongs in a description's animation line)";
      return false;
    }
    AnimFile anim;
    return ReadAnim(bytes, path, &anim, error) && SdkMeshAnimToModel(anim, out, error);
  }
  if (opts.animationsOnly) {
    *error = path + ": an SDKMESH file holds no animation (the original's animations are .sdkmesh_anim files)";
    return false;
  }
  File file;
  return ReadMesh(std::move(bytes), path, &file, error) && SdkMeshToModel(file, opts, out, error);
}

}  // namespace drr
