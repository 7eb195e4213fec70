#include "scene/ImportWire.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include <glm/gtc/type_ptr.hpp>

#include "scene/DdsBlocks.h"
#include "scene/FiniteVector.h"

namespace drr {

namespace {

// Appends plain values, strings and arrays of plain values.
struct Writer {
  std::vector<uint8_t>* out;
  template <class T>
  void Put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const uint8_t*>(&v);
    out->insert(out->end(), p, p + sizeof(T));
  }
  template <class T>
  void PutArray(const std::vector<T>& v) {
    Put<uint64_t>(v.size());
    const auto* p = reinterpret_cast<const uint8_t*>(v.data());
    out->insert(out->end(), p, p + v.size() * sizeof(T));
  }
  void PutString(const std::string& s) {
    Put<uint64_t>(s.size());
    out->insert(out->end(), s.begin(), s.end());
  }
};

// Reads what Writer wrote; any overrun or absurd count sets ok = false and
// yields zeroes, so a malformed reply never allocates more than its own size.
struct Reader {
  const std::vector<uint8_t>& in;
  size_t pos = 0;
  bool ok = true;
  template <class T>
  T Get() {
    T v{};
    if (!ok || in.size() - pos < sizeof(T)) { ok = false; return v; }
    std::memcpy(&v, in.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  // An element count whose elements (each at least minBytes) fit in what is left.
  size_t Count(size_t minBytes) {
    uint64_t n = Get<uint64_t>();
    if (!ok || n > (in.size() - pos) / std::max<size_t>(minBytes, 1)) { ok = false; return 0; }
    return size_t(n);
  }
  template <class T>
  std::vector<T> GetArray() {
    std::vector<T> v(Count(sizeof(T)));
    if (!v.empty()) std::memcpy(v.data(), in.data() + pos, v.size() * sizeof(T));
    pos += v.size() * sizeof(T);
    return v;
  }
  std::string GetString() {
    size_t n = Count(1);
    std::string s(reinterpret_cast<const char*>(in.data() + pos), n);
    pos += n;
    return s;
  }
};

void Header(Writer& w, uint8_t status) {
  w.Put(kImportWireMagic);
  w.Put(kImportWireVersion);
  w.Put(status);
}

// Checks the header; on a worker's error reply sets *error to its message.
bool ReadHeader(Reader& r, std::string* error) {
  if (r.Get<uint32_t>() != kImportWireMagic || r.Get<uint32_t>() != kImportWireVersion || !r.ok) {
    *error = "the import worker's reply is not in the expected format";
    return false;
  }
  if (r.Get<uint8_t>() != 0) {
    *error = r.GetString();
    if (!r.ok || error->empty()) *error = "the import worker failed without a message";
    return false;
  }
  return true;
}

void PutMesh(Writer& w, const MeshData& m) {
  w.PutString(m.name);
  w.PutArray(m.vertices);
  w.PutArray(m.indices);
  w.Put(m.material);
  w.Put(m.boundsMin), w.Put(m.boundsMax), w.Put(m.sphereCenter), w.Put(m.sphereRadius);
}
MeshData GetMesh(Reader& r) {
  MeshData m;
  m.name = r.GetString();
  m.vertices = r.GetArray<SceneVertex>();
  m.indices = r.GetArray<uint32_t>();
  m.material = r.Get<uint32_t>();
  m.boundsMin = r.Get<glm::vec3>(), m.boundsMax = r.Get<glm::vec3>();
  m.sphereCenter = r.Get<glm::vec3>(), m.sphereRadius = r.Get<float>();
  return m;
}

void PutMaterial(Writer& w, const MaterialData& m) {
  w.PutString(m.name), w.PutString(m.diffuseTex), w.PutString(m.normalTex), w.PutString(m.specularTex);
  w.Put(m.diffuseColor), w.Put(uint8_t(m.twoSided)), w.Put(uint8_t(m.alphaBlend));
}
MaterialData GetMaterial(Reader& r) {
  MaterialData m;
  m.name = r.GetString(), m.diffuseTex = r.GetString(), m.normalTex = r.GetString(), m.specularTex = r.GetString();
  m.diffuseColor = r.Get<glm::vec4>();
  m.twoSided = r.Get<uint8_t>() != 0;
  m.alphaBlend = r.Get<uint8_t>() != 0;
  return m;
}

void PutNode(Writer& w, const NodeData& n) {
  w.PutString(n.name), w.Put(n.parent), w.Put(n.local), w.Put(n.baseT), w.Put(n.baseS), w.Put(n.baseR);
  w.PutArray(n.meshes);
}
NodeData GetNode(Reader& r) {
  NodeData n;
  n.name = r.GetString(), n.parent = r.Get<int>(), n.local = r.Get<glm::mat4>();
  n.baseT = r.Get<glm::vec3>(), n.baseS = r.Get<glm::vec3>(), n.baseR = r.Get<glm::quat>();
  n.meshes = r.GetArray<uint32_t>();
  return n;
}

void PutAnimation(Writer& w, const AnimationData& a) {
  w.PutString(a.name), w.Put(a.duration);
  w.Put<uint64_t>(a.channels.size());
  for (const auto& c : a.channels) w.Put(c.node), w.PutArray(c.positions), w.PutArray(c.scalings), w.PutArray(c.rotations);
}
AnimationData GetAnimation(Reader& r) {
  AnimationData a;
  a.name = r.GetString(), a.duration = r.Get<double>();
  a.channels.resize(r.Count(4 + 3 * 8));
  for (auto& c : a.channels) {
    c.node = r.Get<int>();
    c.positions = r.GetArray<VecKey>(), c.scalings = r.GetArray<VecKey>(), c.rotations = r.GetArray<QuatKey>();
  }
  return a;
}

void PutCamera(Writer& w, const CameraData& c) {
  w.PutString(c.name), w.Put(c.node), w.Put(c.position), w.Put(c.lookAt), w.Put(c.up), w.Put(c.fovY);
}
CameraData GetCamera(Reader& r) {
  CameraData c;
  c.name = r.GetString(), c.node = r.Get<int>();
  c.position = r.Get<glm::vec3>(), c.lookAt = r.Get<glm::vec3>(), c.up = r.Get<glm::vec3>(), c.fovY = r.Get<float>();
  return c;
}

void PutEmbedded(Writer& w, const EmbeddedTexture& e) {
  w.PutString(e.hint), w.PutArray(e.bytes), w.Put(e.width), w.Put(e.height), w.PutString(e.error);
}
EmbeddedTexture GetEmbedded(Reader& r) {
  EmbeddedTexture e;
  e.hint = r.GetString(), e.bytes = r.GetArray<uint8_t>();
  e.width = r.Get<uint32_t>(), e.height = r.Get<uint32_t>(), e.error = r.GetString();
  return e;
}

template <class T, class F>
void PutList(Writer& w, const std::vector<T>& v, F put) {
  w.Put<uint64_t>(v.size());
  for (const auto& x : v) put(w, x);
}
// minBytes: the smallest encoding of one element, which bounds the count.
template <class T, class F>
void GetList(Reader& r, size_t minBytes, std::vector<T>* v, F get) {
  v->resize(r.Count(minBytes));
  for (auto& x : *v) {
    x = get(r);
    if (!r.ok) return;
  }
}

std::string ValidateMesh(const MeshData& m, size_t materials) {
  if (m.indices.empty() || m.indices.size() % 3) return "mesh '" + m.name + "': index count not a positive multiple of 3";
  for (uint32_t i : m.indices)
    if (i >= m.vertices.size()) return "mesh '" + m.name + "': index " + std::to_string(i) + " out of range";
  static_assert(sizeof(SceneVertex) % sizeof(float) == 0);
  if (!FiniteFloats(reinterpret_cast<const float*>(m.vertices.data()), m.vertices.size() * sizeof(SceneVertex) / 4))
    return "mesh '" + m.name + "': non-finite vertex data";
  if (m.material >= materials) return "mesh '" + m.name + "': material out of range";
  return {};
}

std::string ValidateNodes(const ModelData& model) {
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const NodeData& n = model.nodes[i];
    if (n.parent < -1 || n.parent >= int(i)) return "node '" + n.name + "': parent out of order";
    if (!FiniteFloats(glm::value_ptr(n.local), 16)) return "node '" + n.name + "': non-finite transform";
    for (uint32_t m : n.meshes)
      if (m >= model.meshes.size()) return "node '" + n.name + "': mesh out of range";
  }
  return {};
}

std::string ValidateAnimations(const ModelData& model) {
  for (const auto& a : model.animations) {
    if (!std::isfinite(a.duration) || a.duration < 0) return "animation '" + a.name + "': bad duration";
    for (const auto& c : a.channels) {
      if (c.node < 0 || c.node >= int(model.nodes.size())) return "animation '" + a.name + "': node out of range";
      auto sorted = [](const auto& keys) {
        for (size_t k = 0; k < keys.size(); ++k)
          if (!std::isfinite(keys[k].time) || (k && keys[k].time < keys[k - 1].time)) return false;
        return true;
      };
      if (!sorted(c.positions) || !sorted(c.scalings) || !sorted(c.rotations))
        return "animation '" + a.name + "': keys not finite and ordered";
    }
  }
  for (const auto& c : model.cameras)
    if (c.node < -1 || c.node >= int(model.nodes.size())) return "camera '" + c.name + "': node out of range";
  return {};
}

}  // namespace

std::string ValidateModel(const ModelData& model, const ModelLoadOptions& opts) {
  if (model.Vertices() > opts.maxVertices || model.Triangles() > opts.maxTriangles) return "more vertices or triangles than allowed";
  if (!opts.animationsOnly && model.materials.empty() && !model.meshes.empty()) return "meshes without materials";
  for (const auto& m : model.meshes)
    if (std::string e = ValidateMesh(m, model.materials.size()); !e.empty()) return e;
  if (std::string e = ValidateNodes(model); !e.empty()) return e;
  if (std::string e = ValidateAnimations(model); !e.empty()) return e;
  for (size_t i = 0; i < model.embedded.size(); ++i) {
    const EmbeddedTexture& t = model.embedded[i];
    if (t.width && uint64_t(t.width) * t.height * 4 != t.bytes.size())
      return "embedded texture *" + std::to_string(i) + ": size does not match its texels";
  }
  return {};
}

void WireWriteError(const std::string& message, std::vector<uint8_t>* out) {
  Writer w{out};
  Header(w, 1);
  w.PutString(message);
}

void WireWriteModel(const ModelData& m, std::vector<uint8_t>* out) {
  Writer w{out};
  Header(w, 0);
  w.PutString(m.file);
  PutList(w, m.meshes, PutMesh);
  PutList(w, m.materials, PutMaterial);
  PutList(w, m.nodes, PutNode);
  PutList(w, m.animations, PutAnimation);
  PutList(w, m.cameras, PutCamera);
  PutList(w, m.embedded, PutEmbedded);
  PutList(w, m.warnings, [](Writer& ww, const std::string& s) { ww.PutString(s); });
}

bool WireReadModel(const std::vector<uint8_t>& in, const ModelLoadOptions& opts, ModelData* m, std::string* error) {
  Reader r{in};
  if (!ReadHeader(r, error)) return false;
  *m = ModelData{};
  m->file = r.GetString();
  GetList(r, 8 * 3 + 4, &m->meshes, GetMesh);
  GetList(r, 8 * 4 + 18, &m->materials, GetMaterial);
  GetList(r, 8 * 2 + 4, &m->nodes, GetNode);
  GetList(r, 8 * 3, &m->animations, GetAnimation);
  GetList(r, 8 + 4, &m->cameras, GetCamera);
  GetList(r, 8 * 3 + 8, &m->embedded, GetEmbedded);
  GetList(r, 8, &m->warnings, [](Reader& rr) { return rr.GetString(); });
  if (!r.ok || r.pos != in.size()) {
    *error = "the import worker's reply is truncated or malformed";
    return false;
  }
  if (std::string e = ValidateModel(*m, opts); !e.empty()) {
    *error = "the import worker returned invalid data (" + e + ")";
    return false;
  }
  return true;
}

void WireWriteTexture(const TextureData& t, std::vector<uint8_t>* out) {
  Writer w{out};
  Header(w, 0);
  w.PutString(t.source);
  w.Put(uint8_t(t.kind)), w.Put(uint8_t(t.hasAlpha));
  w.Put(uint32_t(t.format)), w.Put(uint8_t(t.mipsFromFile));
  // Decoded images send mip 0 (the parent builds the chain); DDS files all their mips.
  const size_t count = t.mipsFromFile ? t.mips.size() : std::min<size_t>(t.mips.size(), 1);
  w.Put(uint64_t(count));
  for (size_t i = 0; i < count; ++i) w.Put(t.mips[i].width), w.Put(t.mips[i].height), w.PutArray(t.mips[i].rgba);
}

namespace {

// Each mip half the size of the one before (at least 1) with exactly the bytes its format needs.
std::string CheckTextureMips(const TextureData& d, uint32_t maxDimension) {
  const uint32_t w = d.Width(), h = d.Height();
  if (d.mips.empty() || d.mips.size() > 32 || w == 0 || h == 0 || w > maxDimension || h > maxDimension)
    return std::to_string(d.mips.size()) + " mips, " + std::to_string(w) + "x" + std::to_string(h);
  for (size_t i = 0; i < d.mips.size(); ++i) {
    const TextureMip& m = d.mips[i];
    if (m.width != std::max(1u, w >> i) || m.height != std::max(1u, h >> i) ||
        m.rgba.size() != TextureMipBytes(d.format, m.width, m.height))
      return "mip " + std::to_string(i) + ": " + std::to_string(m.width) + "x" + std::to_string(m.height) + ", " +
             std::to_string(m.rgba.size()) + " bytes";
  }
  return "";
}

}  // namespace

bool WireReadTexture(const std::vector<uint8_t>& in, uint32_t maxDimension, TextureData* t, std::string* error) {
  Reader r{in};
  if (!ReadHeader(r, error)) return false;
  TextureData d;
  d.source = r.GetString();
  uint8_t kind = r.Get<uint8_t>();
  d.hasAlpha = r.Get<uint8_t>() != 0;  // recomputed below for RGBA8 texels
  d.format = d3dl::DXGI_FORMAT(r.Get<uint32_t>());
  d.mipsFromFile = r.Get<uint8_t>() != 0;
  const size_t count = r.Count(16);  // each mip: two sizes and an array length at least
  for (size_t i = 0; i < count && r.ok; ++i) {
    TextureMip m;
    m.width = r.Get<uint32_t>(), m.height = r.Get<uint32_t>();
    m.rgba = r.GetArray<uint8_t>();
    d.mips.push_back(std::move(m));
  }
  if (!r.ok || r.pos != in.size() || kind > uint8_t(TextureKind::Specular) || !IsTextureDataFormat(d.format)) {
    *error = "the import worker's reply is truncated or malformed";
    return false;
  }
  if (std::string bad = CheckTextureMips(d, maxDimension); !bad.empty()) {
    *error = "the import worker returned an image of inconsistent size (" + bad + ")";
    return false;
  }
  if (!BcBlockBytes(d.format)) {
    const auto& m = d.mips[0].rgba;
    d.hasAlpha = false;
    for (size_t i = 3; i < m.size() && !d.hasAlpha; i += 4) d.hasAlpha = m[i] < 255;
  }
  d.kind = TextureKind(kind);
  *t = std::move(d);
  return true;
}

}  // namespace drr
