// DXUT's SDKMESH (version 101) and SDKMESH_ANIM files, the original sample's
// mesh and animation formats (DXUT/Optional/SDKmesh.h of the original's
// repository describes the layout; these readers are the port's own).
//
// An SDKMESH file is a 104-byte header followed by arrays of fixed-size
// records (vertex-buffer headers with a D3D9 vertex declaration, index-buffer
// headers, meshes, subsets, frames, materials) at offsets the header gives,
// then the vertex and index data at absolute offsets. All little-endian,
// records laid out with the natural alignment of their members.
// An SDKMESH_ANIM file is a 40-byte header, one record per animated frame
// (its name and the offset of its keys) and the keys: translation,
// orientation quaternion (x, y, z, w) and scaling per key, NumAnimationKeys
// keys per frame at AnimationFPS keys per second.
//
// The readers trust nothing: every count and offset is checked against the
// file's size before it is used, and errors name the file and what was wrong.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace drr::sdkmesh {

inline constexpr uint32_t kFileVersion = 101;
inline constexpr uint32_t kInvalid = 0xFFFFFFFFu;  // INVALID_FRAME / INVALID_MESH / INVALID_ANIMATION_DATA

// Record sizes of version 101.
inline constexpr size_t kHeaderSize = 104;
inline constexpr size_t kVertexBufferHeaderSize = 288;
inline constexpr size_t kIndexBufferHeaderSize = 32;
inline constexpr size_t kMeshSize = 224;
inline constexpr size_t kSubsetSize = 144;
inline constexpr size_t kFrameSize = 184;
inline constexpr size_t kMaterialSize = 1256;
inline constexpr size_t kAnimHeaderSize = 40;
inline constexpr size_t kAnimFrameSize = 112;
inline constexpr size_t kAnimKeySize = 40;
inline constexpr size_t kMaxVertexElements = 32;
inline constexpr size_t kMaxVertexStreams = 16;
inline constexpr size_t kNameSize = 100;      // frame, mesh, subset and material names
inline constexpr size_t kPathSize = 260;      // texture and material paths (MAX_PATH)

// D3DDECLTYPE values.
enum DeclType : uint8_t {
  kFloat1 = 0, kFloat2, kFloat3, kFloat4, kD3DColor, kUByte4, kShort2, kShort4, kUByte4N, kShort2N, kShort4N,
  kUShort2N, kUShort4N, kUDec3, kDec3N, kFloat16_2, kFloat16_4, kUnused
};
// D3DDECLUSAGE values the scene's vertex takes (others are read and ignored).
enum DeclUsage : uint8_t { kPosition = 0, kNormal = 3, kTexCoord = 5, kTangent = 6, kBinormal = 7 };
enum PrimitiveType : uint32_t {
  kTriangleList = 0, kTriangleStrip, kLineList, kLineStrip, kPointList, kTriangleListAdj, kTriangleStripAdj,
  kLineListAdj, kLineStripAdj, kQuadPatchList, kTrianglePatchList
};
enum IndexType : uint32_t { k16Bit = 0, k32Bit = 1 };

const char* DeclTypeName(uint8_t type);
const char* PrimitiveTypeName(uint32_t type);
// Bytes of one element of the type; 0 for an unknown type.
size_t DeclTypeSize(uint8_t type);
// One element decoded as D3D9 does (missing components 0, w 1); p holds DeclTypeSize(type) bytes.
glm::vec4 DecodeElement(uint8_t type, const uint8_t* p);

struct VertexElement {
  uint16_t stream = 0, offset = 0;
  uint8_t type = 0, method = 0, usage = 0, usageIndex = 0;
};

struct VertexBuffer {
  uint64_t numVertices = 0, sizeBytes = 0, stride = 0, dataOffset = 0;
  std::vector<VertexElement> decl;  // up to the D3DDECL_END marker
  const VertexElement* Find(uint8_t usage, uint8_t usageIndex) const;
};

struct IndexBuffer {
  uint64_t numIndices = 0, sizeBytes = 0, dataOffset = 0;
  uint32_t indexType = k16Bit;
  size_t IndexBytes() const { return indexType == k32Bit ? 4 : 2; }
};

struct Mesh {
  std::string name;
  std::vector<uint32_t> vertexBuffers;
  uint32_t indexBuffer = 0;
  std::vector<uint32_t> subsets;  // indices into File::subsets
  glm::vec3 boxCenter{0.f}, boxExtents{0.f};
};

struct Subset {
  std::string name;
  uint32_t material = 0, primitiveType = kTriangleList;
  uint64_t indexStart = 0, indexCount = 0, vertexStart = 0, vertexCount = 0;
};

struct Frame {
  std::string name;
  uint32_t mesh = kInvalid, parent = kInvalid, child = kInvalid, sibling = kInvalid;
  float matrix[16] = {};  // D3D row-major, row vectors (world = local * parent)
  uint32_t animationDataIndex = kInvalid;
};

struct Material {
  std::string name, diffuseTexture, normalTexture, specularTexture;  // as stored (relative to the mesh file)
  glm::vec4 diffuse{0.f}, ambient{0.f}, specular{0.f}, emissive{0.f};
  float power = 0.f;
};

struct File {
  std::string path;
  std::vector<uint8_t> bytes;  // the whole file: vertex and index data are read from it
  std::vector<VertexBuffer> vertexBuffers;
  std::vector<IndexBuffer> indexBuffers;
  std::vector<Mesh> meshes;
  std::vector<Subset> subsets;
  std::vector<Frame> frames;
  std::vector<Material> materials;
  // Element e of vertex v of buffer vb, decoded (the buffer and element checked by Read).
  glm::vec4 Element(const VertexBuffer& vb, const VertexElement& e, uint64_t v) const;
  // Index i of buffer ib (i < numIndices).
  uint32_t Index(const IndexBuffer& ib, uint64_t i) const;
};

struct AnimKey {
  glm::vec3 translation{0.f};
  glm::vec4 orientation{0.f, 0.f, 0.f, 1.f};  // x, y, z, w as stored
  glm::vec3 scaling{1.f};
};

struct AnimFrame {
  std::string name;
  std::vector<AnimKey> keys;  // numKeys of them
};

struct AnimFile {
  std::string path;
  uint32_t frameTransformType = 0;  // 0 relative, 1 absolute
  uint32_t numKeys = 0, fps = 0;
  std::vector<AnimFrame> frames;
};

// Parse a whole file held in bytes (moved into out->bytes). False with *error
// = "<path>: <what>" when anything is out of range or inconsistent.
bool ReadMesh(std::vector<uint8_t> bytes, const std::string& path, File* out, std::string* error);
bool ReadAnim(const std::vector<uint8_t>& bytes, const std::string& path, AnimFile* out, std::string* error);
// Reads the file from disk (at most maxBytes) and parses it.
bool LoadFileBytes(const std::string& path, uint64_t maxBytes, std::vector<uint8_t>* bytes, std::string* error);

}  // namespace drr::sdkmesh
