// The project's own SDKMESH and SDKMESH_ANIM files: a writer of DXUT's
// version-101 layout (the records the reader in scene/SdkMesh.h parses) and
// the small test set drr_arenagen writes into <Arena>/sdkmesh/, which the
// reader tests load. The set uses every D3D9 vertex element type, 16- and
// 32-bit index buffers, several subsets and materials (triangle list,
// triangle strip and a line list the renderer skips), a frame hierarchy, an
// animated frame, a camera model with a camera animation, and a scene
// description in the original's form (backslashes, CRLF, trailing blanks).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sdkgen {

struct Element {
  uint16_t offset;
  uint8_t type, usage, usageIndex;
};
struct VertexBufferSpec {
  uint32_t stride = 0;
  uint64_t count = 0;
  std::vector<Element> decl;
  std::vector<uint8_t> data;  // count * stride bytes
};
struct IndexBufferSpec {
  bool is32Bit = false;
  std::vector<uint32_t> indices;
};
struct MeshSpec {
  std::string name;
  uint32_t vertexBuffer = 0, indexBuffer = 0;
  std::vector<uint32_t> subsets;
};
struct SubsetSpec {
  std::string name;
  uint32_t material = 0, primitiveType = 0;
  uint64_t indexStart = 0, indexCount = 0, vertexStart = 0, vertexCount = 0;
};
inline constexpr uint32_t kNone = 0xFFFFFFFFu;
struct FrameSpec {
  std::string name;
  uint32_t mesh = kNone, parent = kNone, child = kNone, sibling = kNone;
  std::array<float, 16> matrix{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // D3D row-major
};
struct MaterialSpec {
  std::string name, diffuse, normal, specular;
};
struct MeshFileSpec {
  std::vector<VertexBufferSpec> vertexBuffers;
  std::vector<IndexBufferSpec> indexBuffers;
  std::vector<MeshSpec> meshes;
  std::vector<SubsetSpec> subsets;
  std::vector<FrameSpec> frames;
  std::vector<MaterialSpec> materials;
};
struct AnimKeySpec {
  glm::vec3 translation{0.f};
  glm::vec4 orientation{0.f, 0.f, 0.f, 1.f};  // x, y, z, w
  glm::vec3 scaling{1.f};
};
struct AnimFrameSpec {
  std::string name;
  std::vector<AnimKeySpec> keys;
};

std::vector<uint8_t> EncodeMesh(const MeshFileSpec& spec);
std::vector<uint8_t> EncodeAnim(uint32_t fps, const std::vector<AnimFrameSpec>& frames);

// The test set (ArenaGenSdkMeshSet.cpp). Constants the tests check:
inline constexpr uint32_t kTestFps = 4, kTestKeys = 8;      // sdktest.sdkmesh_anim
inline constexpr uint32_t kCameraFps = 2, kCameraKeys = 4;  // sdkcam.sdkmesh_anim
inline constexpr float kCameraYawDeg = 20.f;                // left-handed yaw of the camera frame
inline constexpr glm::vec3 kCameraEye{-200.f, 150.f, -800.f};
inline constexpr float kCameraStepX = 100.f;                // the camera moves +x per key
float PendulumAngle(uint32_t key);                          // radians about x, key k of the pendulum
float PendulumScale(uint32_t key);
MeshFileSpec TestMesh();
std::vector<AnimFrameSpec> TestAnim();
MeshFileSpec CameraMesh();
std::vector<AnimFrameSpec> CameraAnim();
// Writes media/sdktest.sdkmesh(_anim), media/sdkcam.sdkmesh(_anim) and
// scene_description.txt into dir; false with *error on a write failure.
bool WriteSdkMeshSet(const std::filesystem::path& dir, std::string* error);

}  // namespace sdkgen
