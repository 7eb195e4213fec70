// Models through Assimp, CPU side only: meshes (SceneVertex, 32-bit indices
// in memory, 16-bit on upload when a mesh has <= 65535 vertices), materials
// (diffuse / normal / specular texture references), the node hierarchy, node
// animations (translation / rotation / scale keys, sampled with interpolation)
// and cameras. Bad input is repaired or rejected with a message, never a crash.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/SceneVertex.h"
#include "scene/TextureLoader.h"

namespace drr {

struct MaterialData {
  std::string name;
  // Texture references: a resolved file path, "*<n>" for an embedded texture, or empty (none).
  std::string diffuseTex, normalTex, specularTex;
  glm::vec4 diffuseColor{1.f};  // factor multiplied with the diffuse texture (alpha = opacity)
  bool twoSided = false;
  bool alphaBlend = false;      // glTF alphaMode BLEND, or opacity < 1
};

struct MeshData {
  std::string name;
  std::vector<SceneVertex> vertices;
  std::vector<uint32_t> indices;  // triangle list
  uint32_t material = 0;
  glm::vec3 boundsMin{0.f}, boundsMax{0.f};
  glm::vec3 sphereCenter{0.f};
  float sphereRadius = 0.f;
  bool Use16BitIndices() const { return vertices.size() <= 65535; }
};

struct NodeData {
  std::string name;
  int parent = -1;  // parents come before their children
  glm::mat4 local{1.f};
  glm::vec3 baseT{0.f}, baseS{1.f};
  glm::quat baseR{1.f, 0.f, 0.f, 0.f};
  std::vector<uint32_t> meshes;  // indices into ModelData::meshes
};

struct VecKey { double time; glm::vec3 value; };
struct QuatKey { double time; glm::quat value; };

struct NodeChannel {
  int node = -1;
  std::vector<VecKey> positions, scalings;
  std::vector<QuatKey> rotations;
};

struct AnimationData {
  std::string name;
  double duration = 0.0;  // seconds
  std::vector<NodeChannel> channels;
};

struct CameraData {
  std::string name;
  int node = -1;  // node that carries the camera (-1: the root)
  glm::vec3 position{0.f}, lookAt{0.f, 0.f, -1.f}, up{0.f, 1.f, 0.f};  // in the node's space
  float fovY = 0.f;  // radians, 0 = not given
};

struct EmbeddedTexture {
  std::string hint;             // "png", "jpg", ... ("" for raw texels)
  std::vector<uint8_t> bytes;   // compressed file bytes, or RGBA8 texels
  uint32_t width = 0, height = 0;  // raw texels only
  std::string error;            // why the import worker could not decode it (bytes then empty)
};

struct ModelData {
  std::string file;
  std::vector<MeshData> meshes;
  std::vector<MaterialData> materials;
  std::vector<NodeData> nodes;
  std::vector<AnimationData> animations;
  std::vector<CameraData> cameras;
  std::vector<EmbeddedTexture> embedded;
  std::vector<std::string> warnings;

  uint64_t Triangles() const;
  uint64_t Vertices() const;
  int FindNode(const std::string& name) const;
  // Global node transforms at time t (seconds) of the first animation, looping
  // over its duration (or loopSeconds when > 0). No animation = bind pose.
  void Evaluate(double t, std::vector<glm::mat4>* globals, double loopSeconds = 0.0) const;
  double AnimationDuration() const { return animations.empty() ? 0.0 : animations[0].duration; }
  // Bounds of all meshes placed by the bind pose.
  void Bounds(glm::vec3* mn, glm::vec3* mx) const;
};

struct ModelLoadOptions {
  uint64_t maxVertices = 50'000'000;   // per model, larger is rejected
  uint64_t maxTriangles = 50'000'000;
  bool animationsOnly = false;         // skip meshes and materials (an animation file)
  // SDKMESH vertices (SdkMeshModel.h): false reads them as the original's one input layout does
  // (tangent and binormal at bytes 32 and 44 whatever the declaration says); true reads every
  // element where the file's declaration puts it.
  bool sdkmeshDeclaredLayout = false;
};

// Returns false with error naming the file on failure (Assimp import error,
// no usable meshes, limits exceeded). Repairs are listed in out->warnings.
bool LoadModel(const std::string& path, const ModelLoadOptions& opts, ModelData* out, std::string* error);

// The model without its meshes' vertices and indices and without its embedded
// textures (names, materials, bounds kept): what a scene entry needs once the
// geometry and textures are on the GPU.
ModelData CopyWithoutGeometry(const ModelData& model);

// Uses the animations of 'source' for 'model', mapping channels by node name.
// Returns the number of channels that found their node.
int AttachAnimations(ModelData* model, const ModelData& source);

// Repairs a mesh in place: drops triangles with out-of-range indices,
// non-finite positions or zero area, fixes non-finite or zero normals,
// texcoords and tangent frames, removes unreferenced vertices, computes the
// bounds. Messages describe what was repaired. Returns false if nothing is left.
bool RepairMesh(MeshData* mesh, std::vector<std::string>* messages);

// CPU texture cache: one TextureData per (file, kind); missing or broken
// textures become the kind's fallback with exactly one warning naming the file.
class TextureCache {
 public:
  // Decodes a texture file into *out (mips built by the cache) or returns false with *error.
  using FileLoader = std::function<bool(const std::string& path, TextureKind kind, const TextureLoadOptions& opts,
                                        TextureData* out, std::string* error)>;
  // loader: how files are decoded; empty = in this process (LoadTextureFile).
  // The sample passes IsolatedTextureLoader() (IsolatedImport.h).
  explicit TextureCache(TextureLoadOptions opts = {}, FileLoader loader = {}) : opts_(opts), loader_(std::move(loader)) {}
  // ref: as in MaterialData; empty ref returns the fallback without a warning.
  std::shared_ptr<const TextureData> Get(const ModelData& model, const std::string& ref, TextureKind kind,
                                         std::vector<std::string>* warnings);
  std::shared_ptr<const TextureData> Fallback(TextureKind kind);
  size_t LoadedCount() const { return cache_.size(); }  // real textures (fallbacks not counted)
  uint64_t LoadedBytes() const;

 private:
  bool Load(const ModelData& model, const std::string& ref, TextureKind kind, TextureData* tex, std::string* err);
  TextureLoadOptions opts_;
  FileLoader loader_;
  std::map<std::string, std::shared_ptr<const TextureData>> cache_;
  std::map<int, std::shared_ptr<const TextureData>> fallbacks_;
  std::set<std::string> failed_;
};

}  // namespace drr
