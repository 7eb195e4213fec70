// The SDKMESH / SDKMESH_ANIM writer: header, then the vertex- and
// index-buffer headers (HeaderSize covers them), then meshes, subsets,
// frames, materials and each mesh's subset list (NonBufferDataSize), then the
// vertex and index data (BufferDataSize) at absolute offsets.
#include "ArenaGenSdkMesh.h"

#include <cstring>

namespace sdkgen {

namespace {

struct Bytes {
  std::vector<uint8_t> b;
  template <class T>
  void Put(size_t at, const T& v) {
    if (b.size() < at + sizeof(T)) b.resize(at + sizeof(T));
    std::memcpy(b.data() + at, &v, sizeof(T));
  }
  void PutName(size_t at, const std::string& s, size_t field) {
    if (b.size() < at + field) b.resize(at + field);
    std::memcpy(b.data() + at, s.data(), std::min(s.size(), field - 1));
  }
  void PutBytes(size_t at, const std::vector<uint8_t>& v) {
    if (b.size() < at + v.size()) b.resize(at + v.size());
    if (!v.empty()) std::memcpy(b.data() + at, v.data(), v.size());
  }
};

constexpr size_t kHeader = 104, kVB = 288, kIB = 32, kMesh = 224, kSubset = 144, kFrame = 184, kMaterial = 1256;

void PutVertexHeader(Bytes& out, size_t at, const VertexBufferSpec& vb, uint64_t dataOffset) {
  out.Put<uint64_t>(at, vb.count);
  out.Put<uint64_t>(at + 8, vb.data.size());
  out.Put<uint64_t>(at + 16, vb.stride);
  for (size_t e = 0; e < 32; ++e) {
    const size_t p = at + 24 + e * 8;
    if (e < vb.decl.size()) {
      const Element& el = vb.decl[e];
      out.Put<uint16_t>(p, 0);
      out.Put<uint16_t>(p + 2, el.offset);
      out.Put<uint8_t>(p + 4, el.type);
      out.Put<uint8_t>(p + 5, 0);
      out.Put<uint8_t>(p + 6, el.usage);
      out.Put<uint8_t>(p + 7, el.usageIndex);
    } else {  // D3DDECL_END and unused slots
      out.Put<uint16_t>(p, 0xFF);
      out.Put<uint16_t>(p + 2, 0);
      out.Put<uint8_t>(p + 4, 17);
    }
  }
  out.Put<uint64_t>(at + 24 + 256, dataOffset);
}

std::vector<uint8_t> IndexBytes(const IndexBufferSpec& ib) {
  std::vector<uint8_t> v;
  for (uint32_t i : ib.indices) {
    const uint8_t* p = reinterpret_cast<const uint8_t*>(&i);
    v.insert(v.end(), p, p + (ib.is32Bit ? 4 : 2));
  }
  return v;
}

void PutMeshRecord(Bytes& out, size_t at, const MeshSpec& m, uint64_t subsetListOffset) {
  out.PutName(at, m.name, 100);
  out.Put<uint8_t>(at + 100, 1);
  out.Put<uint32_t>(at + 104, m.vertexBuffer);
  out.Put<uint32_t>(at + 168, m.indexBuffer);
  out.Put<uint32_t>(at + 172, uint32_t(m.subsets.size()));
  out.Put<uint32_t>(at + 176, 0);
  out.Put<uint64_t>(at + 208, subsetListOffset);
  out.Put<uint64_t>(at + 216, subsetListOffset);
}

void PutRecords(Bytes& out, const MeshFileSpec& s, size_t subsetAt, size_t frameAt, size_t materialAt) {
  for (size_t i = 0; i < s.subsets.size(); ++i) {
    const SubsetSpec& ss = s.subsets[i];
    const size_t at = subsetAt + i * kSubset;
    out.PutName(at, ss.name, 100);
    out.Put<uint32_t>(at + 100, ss.material);
    out.Put<uint32_t>(at + 104, ss.primitiveType);
    out.Put<uint64_t>(at + 112, ss.indexStart);
    out.Put<uint64_t>(at + 120, ss.indexCount);
    out.Put<uint64_t>(at + 128, ss.vertexStart);
    out.Put<uint64_t>(at + 136, ss.vertexCount);
  }
  for (size_t i = 0; i < s.frames.size(); ++i) {
    const FrameSpec& f = s.frames[i];
    const size_t at = frameAt + i * kFrame;
    out.PutName(at, f.name, 100);
    const uint32_t links[] = {f.mesh, f.parent, f.child, f.sibling};
    for (int k = 0; k < 4; ++k) out.Put<uint32_t>(at + 100 + 4 * k, links[k]);
    for (int k = 0; k < 16; ++k) out.Put<float>(at + 116 + 4 * k, f.matrix[k]);
    out.Put<uint32_t>(at + 180, kNone);
  }
  for (size_t i = 0; i < s.materials.size(); ++i) {
    const MaterialSpec& m = s.materials[i];
    const size_t at = materialAt + i * kMaterial;
    out.PutName(at, m.name, 100);
    out.PutName(at + 360, m.diffuse, 260);
    out.PutName(at + 620, m.normal, 260);
    out.PutName(at + 880, m.specular, 260);
    out.Put<uint64_t>(at + 1248, 0);
  }
}

}  // namespace

std::vector<uint8_t> EncodeMesh(const MeshFileSpec& s) {
  Bytes out;
  const size_t vbAt = kHeader, ibAt = vbAt + s.vertexBuffers.size() * kVB, meshAt = ibAt + s.indexBuffers.size() * kIB;
  const size_t subsetAt = meshAt + s.meshes.size() * kMesh, frameAt = subsetAt + s.subsets.size() * kSubset;
  const size_t materialAt = frameAt + s.frames.size() * kFrame;
  size_t listAt = materialAt + s.materials.size() * kMaterial;
  for (size_t i = 0; i < s.meshes.size(); ++i) {
    PutMeshRecord(out, meshAt + i * kMesh, s.meshes[i], listAt);
    for (uint32_t sub : s.meshes[i].subsets) out.Put<uint32_t>(listAt, sub), listAt += 4;
  }
  PutRecords(out, s, subsetAt, frameAt, materialAt);
  const size_t bufferStart = listAt;
  size_t dataAt = bufferStart;
  for (size_t i = 0; i < s.vertexBuffers.size(); ++i) {
    PutVertexHeader(out, vbAt + i * kVB, s.vertexBuffers[i], dataAt);
    out.PutBytes(dataAt, s.vertexBuffers[i].data);
    dataAt += s.vertexBuffers[i].data.size();
  }
  for (size_t i = 0; i < s.indexBuffers.size(); ++i) {
    const std::vector<uint8_t> bytes = IndexBytes(s.indexBuffers[i]);
    const size_t at = ibAt + i * kIB;
    out.Put<uint64_t>(at, s.indexBuffers[i].indices.size());
    out.Put<uint64_t>(at + 8, bytes.size());
    out.Put<uint32_t>(at + 16, s.indexBuffers[i].is32Bit ? 1 : 0);
    out.Put<uint64_t>(at + 24, dataAt);
    out.PutBytes(dataAt, bytes);
    dataAt += bytes.size();
  }
  const uint32_t counts[] = {uint32_t(s.vertexBuffers.size()), uint32_t(s.indexBuffers.size()), uint32_t(s.meshes.size()),
                             uint32_t(s.subsets.size()), uint32_t(s.frames.size()), uint32_t(s.materials.size())};
  const uint64_t offsets[] = {vbAt, ibAt, meshAt, subsetAt, frameAt, materialAt};
  out.Put<uint32_t>(0, 101);
  out.Put<uint8_t>(4, 1);  // IsBigEndian: 1 as in the original's files, which are little-endian all the same
  out.Put<uint64_t>(8, meshAt);                  // HeaderSize: header and buffer headers
  out.Put<uint64_t>(16, bufferStart - meshAt);   // NonBufferDataSize
  out.Put<uint64_t>(24, dataAt - bufferStart);   // BufferDataSize
  for (int k = 0; k < 6; ++k) out.Put<uint32_t>(32 + 4 * k, counts[k]);
  for (int k = 0; k < 6; ++k) out.Put<uint64_t>(56 + 8 * k, offsets[k]);
  return out.b;
}

std::vector<uint8_t> EncodeAnim(uint32_t fps, const std::vector<AnimFrameSpec>& frames) {
  Bytes out;
  const uint32_t keys = frames.empty() ? 0 : uint32_t(frames[0].keys.size());
  const size_t frameAt = 40, keysAt = frameAt + frames.size() * 112;  // key offsets count from byte 40
  for (size_t i = 0; i < frames.size(); ++i) {
    const size_t at = frameAt + i * 112;
    const size_t data = keysAt + i * keys * 40;
    out.PutName(at, frames[i].name, 100);
    out.Put<uint64_t>(at + 104, data - 40);
    for (uint32_t k = 0; k < keys; ++k) {
      const AnimKeySpec& key = frames[i].keys[k];
      const size_t p = data + k * 40;
      for (int c = 0; c < 3; ++c) out.Put<float>(p + 4 * c, key.translation[c]);
      for (int c = 0; c < 4; ++c) out.Put<float>(p + 12 + 4 * c, key.orientation[c]);
      for (int c = 0; c < 3; ++c) out.Put<float>(p + 28 + 4 * c, key.scaling[c]);
    }
  }
  out.Put<uint32_t>(0, 101);
  out.Put<uint8_t>(4, 1);  // IsBigEndian: 1 as in the original's files, which are little-endian all the same
  out.Put<uint32_t>(8, 0);  // relative transforms
  out.Put<uint32_t>(12, uint32_t(frames.size()));
  out.Put<uint32_t>(16, keys);
  out.Put<uint32_t>(20, fps);
  out.Put<uint64_t>(24, out.b.size() > 40 ? out.b.size() - 40 : 0);
  out.Put<uint64_t>(32, frameAt);
  return out.b;
}

}  // namespace sdkgen
