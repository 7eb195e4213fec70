#include "ArenaGltf.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace arena {

std::string Gltf::F(float v) {
  char b[32];
  snprintf(b, sizeof b, "%.9g", v);
  return b;
}

int Gltf::View(const void* data, size_t bytes, int target) {
  while (bin.size() % 4) bin.push_back(0);
  size_t off = bin.size();
  bin.insert(bin.end(), (const uint8_t*)data, (const uint8_t*)data + bytes);
  std::string s = "{\"buffer\":0,\"byteOffset\":" + std::to_string(off) + ",\"byteLength\":" + std::to_string(bytes);
  if (target) s += ",\"target\":" + std::to_string(target);
  bufferViews.push_back(s + "}");
  return int(bufferViews.size() - 1);
}

int Gltf::Accessor(int view, int compType, size_t count, const char* type, const std::string& minmax) {
  accessors.push_back("{\"bufferView\":" + std::to_string(view) + ",\"componentType\":" + std::to_string(compType) +
                      ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type + "\"" + minmax + "}");
  return int(accessors.size() - 1);
}

int Gltf::Image(const std::string& uri) {
  images.push_back("{\"uri\":\"" + uri + "\"}");
  textures.push_back("{\"source\":" + std::to_string(images.size() - 1) + ",\"sampler\":0}");
  return int(textures.size() - 1);
}

int Gltf::Material(const std::string& name, int diffuse, int normal, int specular, bool blend, vec3 factor) {
  std::string f3 = F(factor.x) + "," + F(factor.y) + "," + F(factor.z);
  std::string s = "{\"name\":\"" + name + "\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[" + f3 +
                  ",1],\"metallicFactor\":0,\"roughnessFactor\":1";
  if (diffuse >= 0) s += ",\"baseColorTexture\":{\"index\":" + std::to_string(diffuse) + "}";
  s += "}";
  if (normal >= 0) s += ",\"normalTexture\":{\"index\":" + std::to_string(normal) + "}";
  // Specular map through KHR_materials_pbrSpecularGlossiness (Assimp maps it to aiTextureType_SPECULAR).
  s += ",\"extensions\":{\"KHR_materials_pbrSpecularGlossiness\":{\"diffuseFactor\":[" + f3 + ",1]";
  if (diffuse >= 0) s += ",\"diffuseTexture\":{\"index\":" + std::to_string(diffuse) + "}";
  if (specular >= 0) s += ",\"specularGlossinessTexture\":{\"index\":" + std::to_string(specular) + "}";
  s += "}}";
  if (blend) s += ",\"alphaMode\":\"BLEND\"";
  materials.push_back(s + "}");
  return int(materials.size() - 1);
}

int Gltf::Mesh(const std::string& name, const MeshBuf& m, int material) {
  vec3 mn(1e30f), mx(-1e30f);
  for (auto& p : m.pos) { mn = glm::min(mn, p); mx = glm::max(mx, p); }
  std::string mm = ",\"min\":[" + F(mn.x) + "," + F(mn.y) + "," + F(mn.z) + "],\"max\":[" + F(mx.x) + "," + F(mx.y) +
                   "," + F(mx.z) + "]";
  int ap = Accessor(View(m.pos.data(), m.pos.size() * 12, 34962), 5126, m.pos.size(), "VEC3", mm);
  int an = Accessor(View(m.nrm.data(), m.nrm.size() * 12, 34962), 5126, m.nrm.size(), "VEC3");
  int at = Accessor(View(m.uv.data(), m.uv.size() * 8, 34962), 5126, m.uv.size(), "VEC2");
  int ai = Accessor(View(m.idx.data(), m.idx.size() * 4, 34963), 5125, m.idx.size(), "SCALAR");
  meshes.push_back("{\"name\":\"" + name + "\",\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(ap) +
                   ",\"NORMAL\":" + std::to_string(an) + ",\"TEXCOORD_0\":" + std::to_string(at) +
                   "},\"indices\":" + std::to_string(ai) + ",\"material\":" + std::to_string(material) + "}]}");
  return int(meshes.size() - 1);
}

int Gltf::Node(const std::string& name, const std::string& extra) {
  nodes.push_back("{\"name\":\"" + name + "\"" + extra + "}");
  return int(nodes.size() - 1);
}

std::string Gltf::TRS(vec3 t, glm::quat r) {
  return ",\"translation\":[" + F(t.x) + "," + F(t.y) + "," + F(t.z) + "],\"rotation\":[" + F(r.x) + "," + F(r.y) +
         "," + F(r.z) + "," + F(r.w) + "]";
}

int Gltf::Camera(float yfov, float znear, float zfar) {
  cameras.push_back("{\"type\":\"perspective\",\"perspective\":{\"aspectRatio\":1.7777778,\"yfov\":" + F(yfov) +
                    ",\"znear\":" + F(znear) + ",\"zfar\":" + F(zfar) + "}}");
  return int(cameras.size() - 1);
}

void Gltf::Animation(const std::string& name, int node, const std::vector<float>& times, const std::vector<vec3>* trans,
               const std::vector<glm::quat>* rots) {
  float tmax = times.back();
  int at = Accessor(View(times.data(), times.size() * 4, 0), 5126, times.size(), "SCALAR",
                    ",\"min\":[" + F(times.front()) + "],\"max\":[" + F(tmax) + "]");
  std::string samplers, channels;
  int si = 0;
  auto add = [&](const char* path, int acc) {
    if (si) { samplers += ","; channels += ","; }
    samplers += "{\"input\":" + std::to_string(at) + ",\"output\":" + std::to_string(acc) + ",\"interpolation\":\"LINEAR\"}";
    channels += "{\"sampler\":" + std::to_string(si) + ",\"target\":{\"node\":" + std::to_string(node) + ",\"path\":\"" + path + "\"}}";
    ++si;
  };
  if (trans) add("translation", Accessor(View(trans->data(), trans->size() * 12, 0), 5126, trans->size(), "VEC3"));
  if (rots) {
    std::vector<float> q;
    for (auto& r : *rots) q.insert(q.end(), {r.x, r.y, r.z, r.w});
    add("rotation", Accessor(View(q.data(), q.size() * 4, 0), 5126, rots->size(), "VEC4"));
  }
  animations.push_back("{\"name\":\"" + name + "\",\"samplers\":[" + samplers + "],\"channels\":[" + channels + "]}");
}

std::string Gltf::Join(const std::vector<std::string>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ",\n    " : "\n    ") + v[i];
  return s;
}

bool Gltf::Write(const fs::path& dir, const std::string& stem) {
  std::string binName = stem + ".bin";
  std::ofstream b(dir / binName, std::ios::binary);
  b.write((const char*)bin.data(), std::streamsize(bin.size()));
  if (!b) return false;
  std::string roots;
  for (size_t i = 0; i < sceneRoots.size(); ++i) roots += (i ? "," : "") + std::to_string(sceneRoots[i]);
  std::ostringstream j;
  j << "{\n  \"asset\":{\"version\":\"2.0\",\"generator\":\"drr_arenagen\"},\n";
  bool sg = !materials.empty();
  if (sg) j << "  \"extensionsUsed\":[\"KHR_materials_pbrSpecularGlossiness\"],\n";
  j << "  \"scene\":0,\n  \"scenes\":[{\"nodes\":[" << roots << "]}],\n";
  j << "  \"nodes\":[" << Join(nodes) << "],\n";
  if (!meshes.empty()) j << "  \"meshes\":[" << Join(meshes) << "],\n";
  if (!materials.empty()) j << "  \"materials\":[" << Join(materials) << "],\n";
  if (!textures.empty())
    j << "  \"textures\":[" << Join(textures) << "],\n  \"images\":[" << Join(images)
      << "],\n  \"samplers\":[{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":10497,\"wrapT\":10497}],\n";
  if (!cameras.empty()) j << "  \"cameras\":[" << Join(cameras) << "],\n";
  if (!animations.empty()) j << "  \"animations\":[" << Join(animations) << "],\n";
  j << "  \"accessors\":[" << Join(accessors) << "],\n";
  j << "  \"bufferViews\":[" << Join(bufferViews) << "],\n";
  j << "  \"buffers\":[{\"uri\":\"" << binName << "\",\"byteLength\":" << bin.size() << "}]\n}\n";
  std::ofstream g(dir / (stem + ".gltf"), std::ios::binary);
  g << j.str();
  return bool(g);
}

int Gltf::MeshNode(const std::string& nodeName, const std::string& meshName, const MeshBuf& m, int material) {
  int mesh = Mesh(meshName, m, material);
  return Node(nodeName, ",\"mesh\":" + std::to_string(mesh));
}

}  // namespace arena
