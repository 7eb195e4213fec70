#include "scene/ModelLoader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/FiniteVector.h"
#include "scene/SdkMeshModel.h"

namespace drr {
namespace fs = std::filesystem;

namespace {

glm::mat4 ToGlm(const aiMatrix4x4& m) {
  // aiMatrix4x4 is row-major (a1..a4 = first row); glm is column-major.
  return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4);
}
glm::vec3 ToGlm(const aiVector3D& v) { return {v.x, v.y, v.z}; }

template <class K, class V, class F>
V SampleKeys(const std::vector<K>& keys, double t, const V& def, F interp) {
  if (keys.empty()) return def;
  if (keys.size() == 1 || t <= keys.front().time) return keys.front().value;
  if (t >= keys.back().time) return keys.back().value;
  auto it = std::upper_bound(keys.begin(), keys.end(), t, [](double v, const K& k) { return v < k.time; });
  const K& b = *it;
  const K& a = *(it - 1);
  double span = b.time - a.time;
  float f = span > 0 ? static_cast<float>((t - a.time) / span) : 0.f;
  return interp(a.value, b.value, f);
}

std::string TexRef(const aiScene* sc, const aiMaterial* mat, aiTextureType type, const fs::path& folder) {
  if (mat->GetTextureCount(type) == 0) return {};
  aiString p;
  if (mat->GetTexture(type, 0, &p) != AI_SUCCESS || p.length == 0) return {};
  std::string s(p.C_Str());
  if (!s.empty() && s[0] == '*') return s;
  if (sc->GetEmbeddedTexture(s.c_str())) {
    // Embedded by name (glb, fbx): find its index.
    for (unsigned i = 0; i < sc->mNumTextures; ++i)
      if (sc->mTextures[i] == sc->GetEmbeddedTexture(s.c_str())) return "*" + std::to_string(i);
  }
  std::replace(s.begin(), s.end(), '\\', '/');
  if (s.rfind("file://", 0) == 0) s = s.substr(7);
  fs::path rp(s);
  fs::path full = rp.is_absolute() ? rp : folder / rp;
  std::error_code ec;
  if (!fs::exists(full, ec)) {
    // Models often carry absolute paths of their author's machine: try the file name next to the model.
    fs::path alt = folder / rp.filename();
    if (fs::exists(alt, ec)) full = alt;
  }
  return full.lexically_normal().string();
}

}  // namespace

uint64_t ModelData::Triangles() const {
  uint64_t n = 0;
  for (const auto& m : meshes) n += m.indices.size() / 3;
  return n;
}
uint64_t ModelData::Vertices() const {
  uint64_t n = 0;
  for (const auto& m : meshes) n += m.vertices.size();
  return n;
}
int ModelData::FindNode(const std::string& name) const {
  for (size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].name == name) return static_cast<int>(i);
  return -1;
}

void ModelData::Evaluate(double t, std::vector<glm::mat4>* globals, double loopSeconds) const {
  std::vector<glm::mat4> local(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) local[i] = nodes[i].local;
  if (!animations.empty()) {
    const AnimationData& a = animations[0];
    double period = loopSeconds > 0 ? loopSeconds : a.duration;
    double tt = 0;
    if (period > 0 && std::isfinite(t)) {
      tt = std::fmod(t, period);
      if (tt < 0) tt += period;
    }
    for (const auto& ch : a.channels) {
      if (ch.node < 0 || ch.node >= static_cast<int>(nodes.size())) continue;
      const NodeData& n = nodes[ch.node];
      auto lerp = [](const glm::vec3& x, const glm::vec3& y, float f) { return glm::mix(x, y, f); };
      auto slerp = [](const glm::quat& x, const glm::quat& y, float f) {
        glm::quat yy = glm::dot(x, y) < 0.f ? -y : y;
        return glm::normalize(glm::slerp(x, yy, f));
      };
      glm::vec3 T = SampleKeys(ch.positions, tt, n.baseT, lerp);
      glm::quat R = SampleKeys(ch.rotations, tt, n.baseR, slerp);
      glm::vec3 S = SampleKeys(ch.scalings, tt, n.baseS, lerp);
      local[ch.node] = glm::translate(glm::mat4(1.f), T) * glm::mat4_cast(R) * glm::scale(glm::mat4(1.f), S);
    }
  }
  globals->resize(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i)
    (*globals)[i] = nodes[i].parent >= 0 ? (*globals)[nodes[i].parent] * local[i] : local[i];
}

void ModelData::Bounds(glm::vec3* mn, glm::vec3* mx) const {
  std::vector<glm::mat4> g;
  Evaluate(0.0, &g);
  *mn = glm::vec3(std::numeric_limits<float>::max());
  *mx = glm::vec3(-std::numeric_limits<float>::max());
  for (size_t i = 0; i < nodes.size(); ++i)
    for (uint32_t mi : nodes[i].meshes) {
      const MeshData& m = meshes[mi];
      for (int c = 0; c < 8; ++c) {
        glm::vec3 p((c & 1) ? m.boundsMax.x : m.boundsMin.x, (c & 2) ? m.boundsMax.y : m.boundsMin.y,
                    (c & 4) ? m.boundsMax.z : m.boundsMin.z);
        glm::vec3 w = glm::vec3(g[i] * glm::vec4(p, 1.f));
        if (!Finite(w)) continue;
        *mn = glm::min(*mn, w);
        *mx = glm::max(*mx, w);
      }
    }
  if (mn->x > mx->x) *mn = *mx = glm::vec3(0.f);
}

namespace {


// Zeroes the non-finite positions and collapses the faces that use them, so
// that the FindDegenerates step removes them. Returns how many faces it
// collapsed. (Assimp's own FindInvalidData would drop a whole mesh for one NaN;
// this drops only the faces using it.)
size_t CollapseNonFiniteFaces(const aiScene* sc) {
  size_t nanFaces = 0;
  for (unsigned mi = 0; mi < sc->mNumMeshes; ++mi) {
    aiMesh* am = sc->mMeshes[mi];
    if (!am || !am->mVertices) continue;
    std::vector<uint8_t> bad(am->mNumVertices, 0);
    bool any = false;
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      aiVector3D& p = am->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        bad[v] = 1;
        any = true;
        p = aiVector3D(0.f);
      }
    }
    if (!any) continue;
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      aiFace& face = am->mFaces[f];
      bool hit = false;
      for (unsigned k = 0; k < face.mNumIndices; ++k) hit |= face.mIndices[k] < bad.size() && bad[face.mIndices[k]];
      if (hit && face.mNumIndices > 0) {  // made degenerate: FindDegenerates removes it
        for (unsigned k = 1; k < face.mNumIndices; ++k) face.mIndices[k] = face.mIndices[0];
        ++nanFaces;
      }
    }
  }
  return nanFaces;
}

unsigned PostProcessFlags(const ModelLoadOptions& opts) {
  if (opts.animationsOnly) return aiProcess_ValidateDataStructure;
  return aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_SortByPType |
         aiProcess_FindDegenerates | aiProcess_GenSmoothNormals |
         aiProcess_GenUVCoords | aiProcess_TransformUVCoords | aiProcess_CalcTangentSpace |
         aiProcess_JoinIdenticalVertices | aiProcess_ImproveCacheLocality |
         aiProcess_RemoveRedundantMaterials | aiProcess_FlipUVs;
}

// Reads the file and post-processes it; null (with *error set) when Assimp
// cannot import it or it has no node hierarchy.
const aiScene* ImportScene(Assimp::Importer& importer, const std::string& path, const ModelLoadOptions& opts,
                           size_t* nanFaces, std::string* error) {
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  importer.SetPropertyBool(AI_CONFIG_PP_FD_REMOVE, true);
  importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 80.f);
  const aiScene* sc = nullptr;
  try {
    // Read without post-processing first: non-finite positions must go before
    // the steps that sort vertices spatially.
    sc = importer.ReadFile(path, 0);
    if (sc && !opts.animationsOnly) *nanFaces = CollapseNonFiniteFaces(sc);
    if (sc) sc = importer.ApplyPostProcessing(PostProcessFlags(opts));
  } catch (const std::exception& e) {
    *error = path + ": import failed (" + e.what() + ")";
    return nullptr;
  } catch (...) {
    *error = path + ": import failed (unknown exception)";
    return nullptr;
  }
  if (!sc) {
    std::string e = importer.GetErrorString();
    *error = path + ": Assimp could not import the file" + (e.empty() ? std::string() : " (" + e + ")");
    return nullptr;
  }
  if (!sc->mRootNode) {
    *error = path + ": the file has no node hierarchy";
    return nullptr;
  }
  return sc;
}

// The mesh's vertices and triangles as they are in the file (not yet repaired).
MeshData ConvertMesh(const aiScene* sc, const aiMesh* am, const std::string& name) {
  MeshData m;
  m.name = name;
  m.material = am->mMaterialIndex < sc->mNumMaterials ? am->mMaterialIndex : 0;
  m.vertices.resize(am->mNumVertices);
  const bool hasUV = am->HasTextureCoords(0);
  const bool hasTB = am->HasTangentsAndBitangents();
  for (unsigned v = 0; v < am->mNumVertices; ++v) {
    SceneVertex& sv = m.vertices[v];
    sv.position = ToGlm(am->mVertices[v]);
    sv.normal = am->HasNormals() ? ToGlm(am->mNormals[v]) : glm::vec3(std::nanf(""));
    sv.texcoord = hasUV ? glm::vec2(am->mTextureCoords[0][v].x, am->mTextureCoords[0][v].y) : glm::vec2(0.f);
    sv.tangent = hasTB ? ToGlm(am->mTangents[v]) : glm::vec3(0.f);
    sv.binormal = hasTB ? ToGlm(am->mBitangents[v]) : glm::vec3(0.f);
  }
  m.indices.reserve(size_t(am->mNumFaces) * 3);
  for (unsigned f = 0; f < am->mNumFaces; ++f) {
    const aiFace& face = am->mFaces[f];
    if (face.mNumIndices != 3) continue;
    m.indices.insert(m.indices.end(), {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
  }
  return m;
}

// Converts and repairs the triangle meshes; meshMap[i] becomes the index in
// out->meshes of the file's mesh i, or -1 where it was skipped. False (with
// *error set) when the model is over the size limits.
bool ConvertMeshes(const aiScene* sc, const std::string& path, const ModelLoadOptions& opts, ModelData* out,
                   std::vector<int>* meshMap, std::string* error) {
  uint64_t totalV = 0, totalT = 0;
  for (unsigned mi = 0; mi < sc->mNumMeshes; ++mi) {
    const aiMesh* am = sc->mMeshes[mi];
    std::string name = am->mName.length ? am->mName.C_Str() : "mesh" + std::to_string(mi);
    if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || !am->HasPositions() || am->mNumVertices == 0 ||
        am->mNumFaces == 0) {
      continue;  // points and lines are not drawn by this renderer
    }
    totalV += am->mNumVertices;
    totalT += am->mNumFaces;
    if (totalV > opts.maxVertices || totalT > opts.maxTriangles) {
      *error = path + ": too large (more than " + std::to_string(opts.maxVertices) + " vertices or " +
               std::to_string(opts.maxTriangles) + " triangles)";
      return false;
    }
    MeshData m = ConvertMesh(sc, am, name);
    if (!RepairMesh(&m, &out->warnings)) {
      out->warnings.push_back("mesh '" + name + "': no valid triangles left, skipped");
      continue;
    }
    (*meshMap)[mi] = static_cast<int>(out->meshes.size());
    out->meshes.push_back(std::move(m));
  }
  return true;
}

// Diffuse colour (with opacity), made finite and clamped to [0, 16] (alpha to [0, 1]).
glm::vec4 DiffuseColor(const aiMaterial* am) {
  glm::vec4 color = MaterialData{}.diffuseColor;
  aiColor4D c;
  if (am->Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || am->Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
    color = glm::vec4(c.r, c.g, c.b, c.a);
  float opacity = 1.f;
  if (am->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && std::isfinite(opacity) && opacity < 1.f && opacity > 0.f) {
    color.a *= opacity;
  }
  for (int k = 0; k < 4; ++k)
    if (!std::isfinite(color[k])) color[k] = 1.f;
  color = glm::clamp(color, 0.f, 16.f);
  color.a = std::min(color.a, 1.f);
  return color;
}

MaterialData ConvertMaterial(const aiScene* sc, const aiMaterial* am, const fs::path& folder) {
  MaterialData md;
  aiString n;
  if (am->Get(AI_MATKEY_NAME, n) == AI_SUCCESS) md.name = n.C_Str();
  md.diffuseTex = TexRef(sc, am, aiTextureType_DIFFUSE, folder);
  if (md.diffuseTex.empty()) md.diffuseTex = TexRef(sc, am, aiTextureType_BASE_COLOR, folder);
  md.normalTex = TexRef(sc, am, aiTextureType_NORMALS, folder);
  md.specularTex = TexRef(sc, am, aiTextureType_SPECULAR, folder);
  md.diffuseColor = DiffuseColor(am);
  int two = 0;
  if (am->Get(AI_MATKEY_TWOSIDED, two) == AI_SUCCESS) md.twoSided = two != 0;
  aiString alphaMode;
  if (am->Get("$mat.gltf.alphaMode", 0, 0, alphaMode) == AI_SUCCESS) md.alphaBlend = std::string(alphaMode.C_Str()) == "BLEND";
  return md;
}

// The file's materials, at least one (a default when the file has none).
void ConvertMaterials(const aiScene* sc, const fs::path& folder, ModelData* out) {
  for (unsigned i = 0; i < std::max(1u, sc->mNumMaterials); ++i) {
    MaterialData md = i < sc->mNumMaterials ? ConvertMaterial(sc, sc->mMaterials[i], folder) : MaterialData{};
    if (md.name.empty()) md.name = "material" + std::to_string(i);
    out->materials.push_back(std::move(md));
  }
}

// A compressed texture keeps its file bytes; an uncompressed one becomes RGBA8
// (left empty when over 2^28 texels).
EmbeddedTexture ConvertEmbeddedTexture(const aiTexture* t) {
  EmbeddedTexture et;
  if (!t || !t->pcData) return et;
  if (t->mHeight == 0) {
    et.hint = t->achFormatHint;
    et.bytes.assign(reinterpret_cast<const uint8_t*>(t->pcData), reinterpret_cast<const uint8_t*>(t->pcData) + t->mWidth);
  } else if (uint64_t(t->mWidth) * t->mHeight <= (1ull << 28)) {
    et.width = t->mWidth;
    et.height = t->mHeight;
    et.bytes.resize(size_t(t->mWidth) * t->mHeight * 4);
    for (size_t p = 0; p < size_t(t->mWidth) * t->mHeight; ++p) {
      const aiTexel& x = t->pcData[p];
      et.bytes[p * 4 + 0] = x.r; et.bytes[p * 4 + 1] = x.g; et.bytes[p * 4 + 2] = x.b; et.bytes[p * 4 + 3] = x.a;
    }
  }
  return et;
}

NodeData ConvertNode(const aiNode* n, int parent, const std::vector<int>& meshMap, std::vector<std::string>* warnings) {
  NodeData nd;
  nd.name = n->mName.C_Str();
  nd.parent = parent;
  nd.local = ToGlm(n->mTransformation);
  for (int k = 0; k < 16; ++k)
    if (!std::isfinite(glm::value_ptr(nd.local)[k])) {
      warnings->push_back("node '" + nd.name + "': non-finite transform replaced by identity");
      nd.local = glm::mat4(1.f);
      break;
    }
  aiVector3D s, p;
  aiQuaternion r;
  n->mTransformation.Decompose(s, r, p);
  nd.baseT = ToGlm(p);
  nd.baseS = ToGlm(s);
  nd.baseR = glm::quat(r.w, r.x, r.y, r.z);
  if (!Finite(nd.baseT) || !Finite(nd.baseS) || !std::isfinite(nd.baseR.w)) {
    nd.baseT = glm::vec3(0.f); nd.baseS = glm::vec3(1.f); nd.baseR = glm::quat(1, 0, 0, 0);
  }
  for (unsigned k = 0; k < n->mNumMeshes; ++k)
    if (n->mMeshes[k] < meshMap.size() && meshMap[n->mMeshes[k]] >= 0) nd.meshes.push_back(meshMap[n->mMeshes[k]]);
  return nd;
}

// Node hierarchy, depth first (parents before children).
void AddNodes(const aiNode* n, int parent, int depth, const std::vector<int>& meshMap, ModelData* out) {
  if (depth > 256) {
    out->warnings.push_back("node hierarchy deeper than 256 levels, truncated");
    return;
  }
  int self = static_cast<int>(out->nodes.size());
  out->nodes.push_back(ConvertNode(n, parent, meshMap, &out->warnings));
  for (unsigned c = 0; c < n->mNumChildren; ++c)
    if (n->mChildren[c]) AddNodes(n->mChildren[c], self, depth + 1, meshMap, out);
}

// Appends the finite, time-ordered keys (times in seconds); *maxKey grows to the latest.
void AddVectorKeys(const aiVectorKey* keys, unsigned n, double tps, std::vector<VecKey>* dst, double* maxKey) {
  for (unsigned k = 0; k < n; ++k) {
    double t = keys[k].mTime / tps;
    glm::vec3 v = ToGlm(keys[k].mValue);
    if (!std::isfinite(t) || !Finite(v)) continue;
    if (!dst->empty() && t < dst->back().time) continue;  // keys must be sorted
    dst->push_back({t, v});
    *maxKey = std::max(*maxKey, t);
  }
}

// The same for rotations, normalised; zero-length ones are dropped.
void AddRotationKeys(const aiQuatKey* keys, unsigned n, double tps, std::vector<QuatKey>* dst, double* maxKey) {
  for (unsigned k = 0; k < n; ++k) {
    double t = keys[k].mTime / tps;
    const aiQuaternion& q = keys[k].mValue;
    glm::quat g(q.w, q.x, q.y, q.z);
    float l = glm::length(g);
    if (!std::isfinite(t) || !std::isfinite(l) || l < 1e-6f) continue;
    if (!dst->empty() && t < dst->back().time) continue;
    dst->push_back({t, g / l});
    *maxKey = std::max(*maxKey, t);
  }
}

// The channels whose node the model has; the duration in seconds.
AnimationData ConvertAnimation(const aiAnimation* an, const ModelData& model) {
  AnimationData ad;
  ad.name = an->mName.C_Str();
  double tps = an->mTicksPerSecond > 0 && std::isfinite(an->mTicksPerSecond) ? an->mTicksPerSecond : 25.0;
  double maxKey = 0;
  for (unsigned c = 0; c < an->mNumChannels; ++c) {
    const aiNodeAnim* na = an->mChannels[c];
    NodeChannel ch;
    ch.node = model.FindNode(na->mNodeName.C_Str());
    if (ch.node < 0) continue;
    AddVectorKeys(na->mPositionKeys, na->mNumPositionKeys, tps, &ch.positions, &maxKey);
    AddVectorKeys(na->mScalingKeys, na->mNumScalingKeys, tps, &ch.scalings, &maxKey);
    AddRotationKeys(na->mRotationKeys, na->mNumRotationKeys, tps, &ch.rotations, &maxKey);
    ad.channels.push_back(std::move(ch));
  }
  double dur = an->mDuration / tps;
  ad.duration = std::isfinite(dur) && dur > 0 ? std::max(dur, maxKey) : maxKey;
  return ad;
}

CameraData ConvertCamera(const aiCamera* c, const ModelData& model, bool isGltf) {
  CameraData cd;
  cd.name = c->mName.C_Str();
  cd.node = model.FindNode(cd.name);
  cd.position = ToGlm(c->mPosition);
  cd.lookAt = ToGlm(c->mLookAt);
  cd.up = ToGlm(c->mUp);
  if (!Finite(cd.position)) cd.position = glm::vec3(0.f);
  // A glTF camera sits at its node's origin looking down -Z (spec); Assimp 5.2
  // copies the node's translation into mPosition as well, which would apply it twice.
  if (isGltf && cd.node >= 0) cd.position = glm::vec3(0.f);
  if (!Finite(cd.lookAt) || glm::length(cd.lookAt) < 1e-6f) cd.lookAt = glm::vec3(0, 0, -1);
  if (!Finite(cd.up) || glm::length(cd.up) < 1e-6f) cd.up = glm::vec3(0, 1, 0);
  float hfov = c->mHorizontalFOV, aspect = c->mAspect;
  if (std::isfinite(hfov) && hfov > 0.01f && hfov < 3.1f) {
    if (isGltf && std::isfinite(aspect) && aspect > 0.01f)
      cd.fovY = hfov / aspect;  // Assimp 5.2's glTF importer stores yfov * aspectRatio as the horizontal FOV
    else
      cd.fovY = (std::isfinite(aspect) && aspect > 0.01f) ? 2.f * std::atan(std::tan(hfov * 0.5f) / aspect) : hfov;
  }
  return cd;
}

bool IsGltfFile(const std::string& path) {
  std::string lowerExt = fs::path(path).extension().string();
  for (auto& c : lowerExt) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lowerExt == ".gltf" || lowerExt == ".glb";
}

// Everything but the import itself: meshes, materials, embedded textures
// (unless only the animations are wanted), nodes, animations, cameras.
bool ConvertScene(const aiScene* sc, const std::string& path, const ModelLoadOptions& opts, ModelData* out,
                  std::string* error) {
  std::vector<int> meshMap(sc->mNumMeshes, -1);
  if (!opts.animationsOnly) {
    if (!ConvertMeshes(sc, path, opts, out, &meshMap, error)) return false;
    ConvertMaterials(sc, fs::path(path).parent_path(), out);
    for (unsigned i = 0; i < sc->mNumTextures; ++i) out->embedded.push_back(ConvertEmbeddedTexture(sc->mTextures[i]));
  }
  AddNodes(sc->mRootNode, -1, 0, meshMap, out);
  for (unsigned ai = 0; ai < sc->mNumAnimations; ++ai) {
    AnimationData ad = ConvertAnimation(sc->mAnimations[ai], *out);
    if (!ad.channels.empty()) out->animations.push_back(std::move(ad));
  }
  const bool isGltf = IsGltfFile(path);
  for (unsigned ci = 0; ci < sc->mNumCameras; ++ci) out->cameras.push_back(ConvertCamera(sc->mCameras[ci], *out, isGltf));
  return true;
}

}  // namespace

bool LoadModel(const std::string& path, const ModelLoadOptions& opts, ModelData* out, std::string* error) {
  *out = ModelData{};
  out->file = path;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    *error = path + ": model file not found";
    return false;
  }
  if (IsSdkMeshPath(path) || IsSdkMeshAnimPath(path)) return LoadSdkMeshModel(path, opts, out, error);
  Assimp::Importer importer;
  size_t nanFaces = 0;
  const aiScene* sc = ImportScene(importer, path, opts, &nanFaces, error);
  if (!sc) return false;
  if (nanFaces)
    out->warnings.push_back("dropped " + std::to_string(nanFaces) + " faces with non-finite (NaN/Inf) vertex positions");
  try {
    if (!ConvertScene(sc, path, opts, out, error)) return false;
  } catch (const std::bad_alloc&) {
    *error = path + ": out of memory while converting the model";
    return false;
  }
  if (!opts.animationsOnly && out->meshes.empty() && out->cameras.empty()) {
    *error = path + ": no triangle meshes in the file (nothing to draw)";
    return false;
  }
  return true;
}

ModelData CopyWithoutGeometry(const ModelData& model) {
  ModelData copy;
  copy.file = model.file;
  copy.materials = model.materials;
  copy.nodes = model.nodes;
  copy.animations = model.animations;
  copy.cameras = model.cameras;
  copy.warnings = model.warnings;
  copy.meshes.reserve(model.meshes.size());
  for (const MeshData& m : model.meshes) {
    MeshData g;
    g.name = m.name;
    g.material = m.material;
    g.boundsMin = m.boundsMin, g.boundsMax = m.boundsMax;
    g.sphereCenter = m.sphereCenter, g.sphereRadius = m.sphereRadius;
    copy.meshes.push_back(std::move(g));
  }
  return copy;
}

int AttachAnimations(ModelData* model, const ModelData& source) {
  int matched = 0;
  model->animations.clear();
  for (const auto& a : source.animations) {
    AnimationData ad;
    ad.name = a.name;
    ad.duration = a.duration;
    for (const auto& ch : a.channels) {
      if (ch.node < 0 || ch.node >= static_cast<int>(source.nodes.size())) continue;
      int n = model->FindNode(source.nodes[ch.node].name);
      if (n < 0) continue;
      NodeChannel c = ch;
      c.node = n;
      ad.channels.push_back(std::move(c));
      ++matched;
    }
    if (!ad.channels.empty()) model->animations.push_back(std::move(ad));
  }
  return matched;
}

std::shared_ptr<const TextureData> TextureCache::Fallback(TextureKind kind) {
  auto& f = fallbacks_[static_cast<int>(kind)];
  if (!f) f = std::make_shared<TextureData>(FallbackTexture(kind));
  return f;
}

uint64_t TextureCache::LoadedBytes() const {
  uint64_t b = 0;
  for (const auto& [k, t] : cache_) b += t->Bytes();
  return b;
}

bool TextureCache::Load(const ModelData& model, const std::string& ref, TextureKind kind, TextureData* tex,
                        std::string* err) {
  if (ref[0] != '*') return loader_ ? loader_(ref, kind, opts_, tex, err) : LoadTextureFile(ref, kind, opts_, tex, err);
  char* end = nullptr;
  long idx = std::strtol(ref.c_str() + 1, &end, 10);
  if (*end != '\0' || idx < 0 || idx >= static_cast<long>(model.embedded.size()) || model.embedded[idx].bytes.empty()) {
    const bool known = *end == '\0' && idx >= 0 && idx < static_cast<long>(model.embedded.size());
    *err = known && !model.embedded[idx].error.empty() ? model.embedded[idx].error
                                                       : model.file + ": embedded texture " + ref + " is missing";
    return false;
  }
  const EmbeddedTexture& et = model.embedded[idx];
  std::string name = model.file + " (embedded texture " + ref + ")";
  return et.width ? MakeTextureRGBA8(et.bytes.data(), et.width, et.height, name, kind, opts_, tex, err)
                  : LoadTextureMemory(et.bytes.data(), et.bytes.size(), et.hint, name, kind, opts_, tex, err);
}

std::shared_ptr<const TextureData> TextureCache::Get(const ModelData& model, const std::string& ref, TextureKind kind,
                                                     std::vector<std::string>* warnings) {
  if (ref.empty()) return Fallback(kind);
  std::string key = (ref[0] == '*' ? model.file + ref : ref) + "|" + TextureKindName(kind);
  if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  std::string failKey = ref[0] == '*' ? model.file + ref : ref;
  if (failed_.count(failKey)) return Fallback(kind);
  auto tex = std::make_shared<TextureData>();
  std::string err;
  bool ok;
  try {
    ok = Load(model, ref, kind, tex.get(), &err);
  } catch (const std::bad_alloc&) {
    err = (ref[0] == '*' ? model.file + " (embedded texture " + ref + ")" : ref) + ": out of memory while converting the texture";
    ok = false;
  }
  if (!ok) {
    failed_.insert(failKey);
    if (warnings)
      warnings->push_back(err + "; using the " + FallbackTexture(kind).source.substr(1, FallbackTexture(kind).source.size() - 2) +
                          " texture instead");
    return Fallback(kind);
  }
  cache_[key] = tex;
  return tex;
}

}  // namespace drr
