#include "scene/SdkMesh.h"

#include <cmath>
#include <cstring>
#include <fstream>

#include "scene/SdkMeshBytes.h"

namespace drr::sdkmesh {

namespace {

// The header's fields (SDKMESH_HEADER), by offset.
struct Header {
  uint32_t version = 0;
  uint64_t headerSize = 0, nonBufferDataSize = 0, bufferDataSize = 0;
  uint32_t numVertexBuffers = 0, numIndexBuffers = 0, numMeshes = 0, numSubsets = 0, numFrames = 0,
           numMaterials = 0;
  uint64_t vertexOffset = 0, indexOffset = 0, meshOffset = 0, subsetOffset = 0, frameOffset = 0,
           materialOffset = 0;
};

Header ReadHeader(const ByteView& b) {
  Header h;
  h.version = b.U32(0);
  h.headerSize = b.U64(8);
  h.nonBufferDataSize = b.U64(16);
  h.bufferDataSize = b.U64(24);
  h.numVertexBuffers = b.U32(32);
  h.numIndexBuffers = b.U32(36);
  h.numMeshes = b.U32(40);
  h.numSubsets = b.U32(44);
  h.numFrames = b.U32(48);
  h.numMaterials = b.U32(52);
  h.vertexOffset = b.U64(56);
  h.indexOffset = b.U64(64);
  h.meshOffset = b.U64(72);
  h.subsetOffset = b.U64(80);
  h.frameOffset = b.U64(88);
  h.materialOffset = b.U64(96);
  return h;
}

bool CheckHeader(const ByteView& b, const Header& h, Failure& fail) {
  if (b.size < kHeaderSize)
    return fail("file of " + std::to_string(b.size) + " bytes is shorter than the 104-byte SDKMESH header");
  if (h.version != kFileVersion)
    return fail("SDKMESH version " + std::to_string(h.version) + ", expected " + std::to_string(kFileVersion));
  // IsBigEndian is not checked: the original's loader ignores it, and its own files set it to 1
  // over little-endian data.
  if (h.headerSize < kHeaderSize || h.headerSize > b.size)
    return fail("HeaderSize " + std::to_string(h.headerSize) + " outside [104, file size " + std::to_string(b.size) + "]");
  struct Array { const char* what; uint64_t offset; uint32_t count; size_t record; };
  const Array arrays[] = {{"vertex buffer headers", h.vertexOffset, h.numVertexBuffers, kVertexBufferHeaderSize},
                          {"index buffer headers", h.indexOffset, h.numIndexBuffers, kIndexBufferHeaderSize},
                          {"meshes", h.meshOffset, h.numMeshes, kMeshSize},
                          {"subsets", h.subsetOffset, h.numSubsets, kSubsetSize},
                          {"frames", h.frameOffset, h.numFrames, kFrameSize},
                          {"materials", h.materialOffset, h.numMaterials, kMaterialSize}};
  for (const Array& a : arrays)
    if (!b.Fits(a.offset, a.count, a.record))
      return fail(std::to_string(a.count) + " " + a.what + " at offset " + std::to_string(a.offset) +
                  " do not fit in the file (" + std::to_string(b.size) + " bytes)");
  return true;
}

bool ReadDeclaration(const ByteView& b, uint64_t at, uint64_t stride, VertexBuffer* vb, Failure& fail) {
  for (size_t e = 0; e < kMaxVertexElements; ++e) {
    const uint64_t p = at + e * 8;
    VertexElement el{b.U16(p), b.U16(p + 2), b.U8(p + 4), b.U8(p + 5), b.U8(p + 6), b.U8(p + 7)};
    if (el.stream == 0xFF || el.type == kUnused) break;  // D3DDECL_END
    const size_t bytes = DeclTypeSize(el.type);
    if (bytes == 0) return fail("vertex element " + std::to_string(e) + " has unknown type " + std::to_string(el.type));
    if (el.offset + bytes > stride)
      return fail("vertex element " + std::to_string(e) + " (" + DeclTypeName(el.type) + " at offset " +
                  std::to_string(el.offset) + ") extends past the stride of " + std::to_string(stride) + " bytes");
    vb->decl.push_back(el);
  }
  return true;
}

bool ReadVertexBuffers(const ByteView& b, const Header& h, File* out, Failure& fail) {
  for (uint32_t i = 0; i < h.numVertexBuffers; ++i) {
    const uint64_t at = h.vertexOffset + uint64_t(i) * kVertexBufferHeaderSize;
    VertexBuffer vb;
    vb.numVertices = b.U64(at);
    vb.sizeBytes = b.U64(at + 8);
    vb.stride = b.U64(at + 16);
    vb.dataOffset = b.U64(at + 24 + kMaxVertexElements * 8);
    const std::string who = "vertex buffer " + std::to_string(i) + ": ";
    if (vb.stride == 0 || vb.stride > 4096) return fail(who + "stride " + std::to_string(vb.stride) + " outside [1, 4096]");
    if (!b.Fits(vb.dataOffset, vb.numVertices, vb.stride) || vb.numVertices * vb.stride > vb.sizeBytes)
      return fail(who + std::to_string(vb.numVertices) + " vertices of " + std::to_string(vb.stride) +
                  " bytes at offset " + std::to_string(vb.dataOffset) + " do not fit in its " +
                  std::to_string(vb.sizeBytes) + " bytes or in the file (" + std::to_string(b.size) + " bytes)");
    if (!ReadDeclaration(b, at + 24, vb.stride, &vb, fail)) return fail.Prefix(who);
    if (!vb.Find(kPosition, 0)) return fail(who + "its declaration has no POSITION element");
    out->vertexBuffers.push_back(std::move(vb));
  }
  return true;
}

bool ReadIndexBuffers(const ByteView& b, const Header& h, File* out, Failure& fail) {
  for (uint32_t i = 0; i < h.numIndexBuffers; ++i) {
    const uint64_t at = h.indexOffset + uint64_t(i) * kIndexBufferHeaderSize;
    IndexBuffer ib;
    ib.numIndices = b.U64(at);
    ib.sizeBytes = b.U64(at + 8);
    ib.indexType = b.U32(at + 16);
    ib.dataOffset = b.U64(at + 24);
    const std::string who = "index buffer " + std::to_string(i) + ": ";
    if (ib.indexType != k16Bit && ib.indexType != k32Bit)
      return fail(who + "index type " + std::to_string(ib.indexType) + " (expected 0 for 16-bit or 1 for 32-bit)");
    if (!b.Fits(ib.dataOffset, ib.numIndices, ib.IndexBytes()) || ib.numIndices * ib.IndexBytes() > ib.sizeBytes)
      return fail(who + std::to_string(ib.numIndices) + " indices at offset " + std::to_string(ib.dataOffset) +
                  " do not fit in its " + std::to_string(ib.sizeBytes) + " bytes or in the file (" +
                  std::to_string(b.size) + " bytes)");
    out->indexBuffers.push_back(ib);
  }
  return true;
}

bool ReadMeshRecord(const ByteView& b, uint64_t at, const File& f, Mesh* m, Failure& fail) {
  m->name = b.Name(at, kNameSize);
  const uint8_t numVB = b.U8(at + 100);
  if (numVB == 0 || numVB > kMaxVertexStreams)
    return fail("mesh '" + m->name + "': " + std::to_string(numVB) + " vertex buffers (expected 1 to 16)");
  for (uint8_t k = 0; k < numVB; ++k) {
    const uint32_t vb = b.U32(at + 104 + 4 * k);
    if (vb >= f.vertexBuffers.size())
      return fail("mesh '" + m->name + "': vertex buffer " + std::to_string(vb) + " of " +
                  std::to_string(f.vertexBuffers.size()));
    m->vertexBuffers.push_back(vb);
  }
  m->indexBuffer = b.U32(at + 168);
  if (m->indexBuffer >= f.indexBuffers.size())
    return fail("mesh '" + m->name + "': index buffer " + std::to_string(m->indexBuffer) + " of " +
                std::to_string(f.indexBuffers.size()));
  const uint32_t numSubsets = b.U32(at + 172);
  const uint64_t subsetOffset = b.U64(at + 208);
  if (!b.Fits(subsetOffset, numSubsets, 4))
    return fail("mesh '" + m->name + "': " + std::to_string(numSubsets) + " subset indices at offset " +
                std::to_string(subsetOffset) + " do not fit in the file");
  for (uint32_t s = 0; s < numSubsets; ++s) {
    const uint32_t subset = b.U32(subsetOffset + 4 * uint64_t(s));
    if (subset >= f.subsets.size())
      return fail("mesh '" + m->name + "': subset " + std::to_string(subset) + " of " + std::to_string(f.subsets.size()));
    m->subsets.push_back(subset);
  }
  m->boxCenter = {b.F32(at + 180), b.F32(at + 184), b.F32(at + 188)};
  m->boxExtents = {b.F32(at + 192), b.F32(at + 196), b.F32(at + 200)};
  return true;
}

bool ReadSubsets(const ByteView& b, const Header& h, File* out, Failure& fail) {
  for (uint32_t i = 0; i < h.numSubsets; ++i) {
    const uint64_t at = h.subsetOffset + uint64_t(i) * kSubsetSize;
    Subset s;
    s.name = b.Name(at, kNameSize);
    s.material = b.U32(at + 100);
    s.primitiveType = b.U32(at + 104);
    s.indexStart = b.U64(at + 112);
    s.indexCount = b.U64(at + 120);
    s.vertexStart = b.U64(at + 128);
    s.vertexCount = b.U64(at + 136);
    if (s.material >= h.numMaterials)
      return fail("subset '" + s.name + "': material " + std::to_string(s.material) + " of " + std::to_string(h.numMaterials));
    if (s.primitiveType > kTrianglePatchList)
      return fail("subset '" + s.name + "': unknown primitive type " + std::to_string(s.primitiveType));
    out->subsets.push_back(std::move(s));
  }
  return true;
}

bool ReadFrames(const ByteView& b, const Header& h, File* out, Failure& fail) {
  for (uint32_t i = 0; i < h.numFrames; ++i) {
    const uint64_t at = h.frameOffset + uint64_t(i) * kFrameSize;
    Frame fr;
    fr.name = b.Name(at, kNameSize);
    fr.mesh = b.U32(at + 100);
    fr.parent = b.U32(at + 104);
    fr.child = b.U32(at + 108);
    fr.sibling = b.U32(at + 112);
    for (int k = 0; k < 16; ++k) fr.matrix[k] = b.F32(at + 116 + 4 * k);
    fr.animationDataIndex = b.U32(at + 180);
    for (float v : fr.matrix)
      if (!std::isfinite(v)) return fail("frame '" + fr.name + "': its matrix is not finite");
    out->frames.push_back(std::move(fr));
  }
  return true;
}

void ReadMaterials(const ByteView& b, const Header& h, File* out) {
  for (uint32_t i = 0; i < h.numMaterials; ++i) {
    const uint64_t at = h.materialOffset + uint64_t(i) * kMaterialSize;
    Material m;
    m.name = b.Name(at, kNameSize);
    m.diffuseTexture = b.Name(at + 360, kPathSize);
    m.normalTexture = b.Name(at + 620, kPathSize);
    m.specularTexture = b.Name(at + 880, kPathSize);
    glm::vec4* colours[] = {&m.diffuse, &m.ambient, &m.specular, &m.emissive};
    for (int c = 0; c < 4; ++c)
      *colours[c] = {b.F32(at + 1140 + 16 * c), b.F32(at + 1144 + 16 * c), b.F32(at + 1148 + 16 * c),
                     b.F32(at + 1152 + 16 * c)};
    m.power = b.F32(at + 1204);
    out->materials.push_back(std::move(m));
  }
}

}  // namespace

const VertexElement* VertexBuffer::Find(uint8_t usage, uint8_t usageIndex) const {
  for (const VertexElement& e : decl)
    if (e.usage == usage && e.usageIndex == usageIndex) return &e;
  return nullptr;
}

glm::vec4 File::Element(const VertexBuffer& vb, const VertexElement& e, uint64_t v) const {
  return DecodeElement(e.type, bytes.data() + vb.dataOffset + v * vb.stride + e.offset);
}

uint32_t File::Index(const IndexBuffer& ib, uint64_t i) const {
  const ByteView b{bytes.data(), bytes.size()};
  return ib.indexType == k32Bit ? b.U32(ib.dataOffset + 4 * i) : b.U16(ib.dataOffset + 2 * i);
}

bool ReadMesh(std::vector<uint8_t> bytes, const std::string& path, File* out, std::string* error) {
  *out = File{};
  out->path = path;
  out->bytes = std::move(bytes);
  const ByteView b{out->bytes.data(), out->bytes.size()};
  Failure fail{path, error};
  const Header h = b.size >= kHeaderSize ? ReadHeader(b) : Header{};
  if (!CheckHeader(b, h, fail) || !ReadVertexBuffers(b, h, out, fail) || !ReadIndexBuffers(b, h, out, fail) ||
      !ReadSubsets(b, h, out, fail) || !ReadFrames(b, h, out, fail))
    return false;
  ReadMaterials(b, h, out);
  for (uint32_t i = 0; i < h.numMeshes; ++i) {
    Mesh m;
    if (!ReadMeshRecord(b, h.meshOffset + uint64_t(i) * kMeshSize, *out, &m, fail)) return false;
    out->meshes.push_back(std::move(m));
  }
  return true;
}

bool LoadFileBytes(const std::string& path, uint64_t maxBytes, std::vector<uint8_t>* bytes, std::string* error) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) {
    *error = path + ": cannot open the file";
    return false;
  }
  const std::streamoff size = in.tellg();
  if (size < 0 || uint64_t(size) > maxBytes) {
    *error = path + ": file of " + std::to_string(size) + " bytes is larger than the " + std::to_string(maxBytes) +
             "-byte limit";
    return false;
  }
  bytes->resize(size_t(size));
  in.seekg(0);
  if (size > 0 && !in.read(reinterpret_cast<char*>(bytes->data()), size)) {
    *error = path + ": read error";
    return false;
  }
  return true;
}

}  // namespace drr::sdkmesh
