// The test set of ArenaGenSdkMesh.h: a plate of two quads (two subsets and
// materials on one 16-bit index buffer, the second subset with a base
// vertex), a pendulum quad (a triangle strip and a line list on a 32-bit
// index buffer, the decals' 72-byte layout) swinging about x, a triangle
// whose vertex buffer holds every D3D9 element type, and a camera model
// moving along x. Left-handed coordinates and clockwise front faces, as the
// original's files; positions in the Arena's units.
#include <cmath>
#include <cstring>
#include <fstream>

#include "ArenaGenSdkMesh.h"

namespace sdkgen {

namespace {

constexpr uint8_t kF1 = 0, kF2 = 1, kF3 = 2, kF4 = 3, kColor = 4, kUB4 = 5, kS2 = 6, kS4 = 7, kUB4N = 8, kS2N = 9,
                  kS4N = 10, kUS2N = 11, kUS4N = 12, kUDec3 = 13, kDec3N = 14, kH2 = 15, kH4 = 16;
constexpr uint8_t kPos = 0, kWeight = 1, kIndices = 2, kNormal = 3, kPSize = 4, kTex = 5, kTangent = 6, kBinormal = 7,
                  kColorUsage = 10;

struct VertexWriter {
  VertexBufferSpec* vb;
  std::vector<uint8_t> vertex;
  template <class T>
  void Put(uint16_t offset, const T* values, int n) {
    std::memcpy(vertex.data() + offset, values, sizeof(T) * size_t(n));
  }
  void Floats(uint16_t offset, std::initializer_list<float> v) { Put(offset, v.begin(), int(v.size())); }
  void Begin() { vertex.assign(vb->stride, 0); }
  void End() {
    vb->data.insert(vb->data.end(), vertex.begin(), vertex.end());
    ++vb->count;
  }
};

// The original's 56-byte layout (position, normal, texcoord, tangent, binormal).
VertexBufferSpec PlateVertices() {
  VertexBufferSpec vb;
  vb.stride = 56;
  vb.decl = {{0, kF3, kPos, 0}, {12, kF3, kNormal, 0}, {24, kF2, kTex, 0}, {32, kF3, kTangent, 0}, {44, kF3, kBinormal, 0}};
  VertexWriter w{&vb, {}};
  for (float x0 : {-100.f, 0.f}) {
    const float corners[4][2] = {{x0, -50.f}, {x0, 50.f}, {x0 + 100.f, 50.f}, {x0 + 100.f, -50.f}};
    for (const auto& c : corners) {
      w.Begin();
      w.Floats(0, {c[0], 0.f, c[1]});
      w.Floats(12, {0.f, 1.f, 0.f});
      w.Floats(24, {(c[0] + 100.f) / 200.f, (50.f - c[1]) / 100.f});
      w.Floats(32, {1.f, 0.f, 0.f});
      w.Floats(44, {0.f, 0.f, 1.f});
      w.End();
    }
  }
  return vb;
}

// The decals' 72-byte layout: three texture coordinate sets.
VertexBufferSpec PendulumVertices() {
  VertexBufferSpec vb;
  vb.stride = 72;
  vb.decl = {{0, kF3, kPos, 0},      {12, kF3, kNormal, 0},  {24, kF2, kTex, 0},     {32, kF2, kTex, 1},
             {40, kF2, kTex, 2},     {48, kF3, kTangent, 0}, {60, kF3, kBinormal, 0}};
  VertexWriter w{&vb, {}};
  const float corners[4][2] = {{-20.f, -100.f}, {-20.f, 0.f}, {20.f, -100.f}, {20.f, 0.f}};  // strip order
  for (const auto& c : corners) {
    w.Begin();
    w.Floats(0, {c[0], c[1], 0.f});
    w.Floats(12, {0.f, 0.f, -1.f});
    w.Floats(24, {(c[0] + 20.f) / 40.f, -c[1] / 100.f});
    w.Floats(32, {0.25f, 0.75f});
    w.Floats(40, {0.5f, 0.5f});
    w.Floats(48, {1.f, 0.f, 0.f});
    w.Floats(60, {0.f, 1.f, 0.f});
    w.End();
  }
  return vb;
}

uint16_t HalfOf(float f) {  // exact for the values used (powers of two and small multiples)
  if (f == 0.f) return 0;
  int e;
  const float m = std::frexp(std::fabs(f), &e);  // f = m * 2^e, m in [0.5, 1)
  const uint16_t mant = uint16_t(std::lround((m * 2.f - 1.f) * 1024.f));
  return uint16_t((f < 0 ? 0x8000 : 0) | ((e - 1 + 15) << 10) | mant);
}

// Every D3D9 element type once; the values are those the reader test expects.
VertexBufferSpec AllTypesVertices() {
  VertexBufferSpec vb;
  vb.stride = 108;
  vb.decl = {{0, kF3, kPos, 0},    {12, kDec3N, kNormal, 0}, {16, kS2N, kTex, 0},  {20, kH4, kTangent, 0},
             {28, kF4, kBinormal, 0}, {44, kF1, kTex, 1},   {48, kF2, kTex, 2},   {56, kColor, kTex, 3},
             {60, kUB4, kTex, 4},  {64, kS2, kTex, 5},      {68, kS4, kTex, 6},   {76, kUB4N, kTex, 7},
             {80, kS4N, kColorUsage, 0}, {88, kUS2N, kColorUsage, 1}, {92, kUS4N, kWeight, 0},
             {100, kUDec3, kIndices, 0}, {104, kH2, kPSize, 0}};
  VertexWriter w{&vb, {}};
  const float positions[3][3] = {{0.f, 0.f, 0.f}, {0.f, 40.f, 0.f}, {40.f, 0.f, 0.f}};
  for (const auto& p : positions) {
    w.Begin();
    w.Floats(0, {p[0], p[1], p[2]});
    const uint32_t dec3n = (511u) | ((1024u - 511u) << 10) | (0u << 20);  // (1, -1, 0)
    w.Put(12, &dec3n, 1);
    const int16_t s2n[2] = {16384, -32767};
    w.Put(16, s2n, 2);
    const uint16_t h4[4] = {HalfOf(0.5f), HalfOf(-2.f), HalfOf(1.f), HalfOf(0.25f)};
    w.Put(20, h4, 4);
    w.Floats(28, {0.f, 0.f, 1.f, -1.f});
    w.Floats(44, {3.5f});
    w.Floats(48, {-1.25f, 8.f});
    const uint8_t bgra[4] = {0, 128, 255, 64};  // D3DCOLOR: R 255, G 128, B 0, A 64
    w.Put(56, bgra, 4);
    const uint8_t ub4[4] = {1, 2, 3, 4};
    w.Put(60, ub4, 4);
    const int16_t s2[2] = {-7, 300};
    w.Put(64, s2, 2);
    const int16_t s4[4] = {-1, 2, -3, 4};
    w.Put(68, s4, 4);
    const uint8_t ub4n[4] = {0, 51, 102, 255};
    w.Put(76, ub4n, 4);
    const int16_t s4n[4] = {32767, -32767, 0, 16384};
    w.Put(80, s4n, 4);
    const uint16_t us2n[2] = {65535, 0};
    w.Put(88, us2n, 2);
    const uint16_t us4n[4] = {0, 65535, 32768, 1};
    w.Put(92, us4n, 4);
    const uint32_t udec3 = 1u | (512u << 10) | (1023u << 20);
    w.Put(100, &udec3, 1);
    const uint16_t h2[2] = {HalfOf(-0.5f), HalfOf(6.f)};
    w.Put(104, h2, 2);
    w.End();
  }
  return vb;
}

std::array<float, 16> Translation(float x, float y, float z, float scale = 1.f) {
  return {scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0, x, y, z, 1};
}

}  // namespace

float PendulumAngle(uint32_t key) {
  return 30.f * 3.14159265f / 180.f * std::sin(2.f * 3.14159265f * float(key % kTestKeys) / float(kTestKeys));
}
float PendulumScale(uint32_t key) { return 1.f + 0.125f * float(key % kTestKeys); }

MeshFileSpec TestMesh() {
  MeshFileSpec s;
  s.vertexBuffers = {PlateVertices(), PendulumVertices(), AllTypesVertices()};
  s.indexBuffers = {{false, {0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3}},
                    {true, {0, 1, 2, 3, 0, 1, 70000}},  // the last index is read by the tests only
                    {false, {0, 1, 2}}};
  s.meshes = {{"plate", 0, 0, {0, 1}}, {"pendulum", 1, 1, {2, 3}}, {"types", 2, 2, {4}}};
  s.subsets = {{"left", 0, 0, 0, 6, 0, 4},  {"right", 1, 0, 6, 6, 4, 4}, {"quad", 1, 1, 0, 4, 0, 4},
               {"rope", 0, 2, 4, 2, 0, 4},  {"typed", 2, 0, 0, 3, 0, 3}};
  s.frames = {{"", kNone, kNone, 1, kNone},
              {"RootNode", kNone, 0, 2, kNone},
              {"group", kNone, 1, 3, kNone, Translation(0.f, 50.f, 300.f, 2.f)},
              {"plate", 0, 2, kNone, 4},
              {"pendulum", 1, 2, kNone, 5, Translation(0.f, 150.f, 0.f)},
              {"types", 2, 2, kNone, kNone, Translation(-60.f, 20.f, 0.f)}};
  s.materials = {{"stone", "..\\..\\textures\\floor_diffuse.png", "..\\..\\textures\\floor_normal.png",
                  "..\\..\\textures\\floor_specular.png"},
                 {"bronze", "..\\..\\textures\\bronze_diffuse.png", "", "sdk_missing_sm.dds"},
                 {"typed", "sdk_missing.dds", "", ""}};
  return s;
}

std::vector<AnimFrameSpec> TestAnim() {
  AnimFrameSpec root{"RootNode", {}}, pendulum{"pendulum", {}}, ghost{"ghost", {}};
  for (uint32_t k = 0; k < kTestKeys; ++k) {
    AnimKeySpec zero;
    zero.orientation = glm::vec4(0.f);  // all zero: the identity, as the original reads it
    root.keys.push_back(zero);
    const float a = PendulumAngle(k);
    pendulum.keys.push_back({{0.f, 150.f, 0.f}, {std::sin(a / 2), 0.f, 0.f, std::cos(a / 2)}, glm::vec3(PendulumScale(k))});
    ghost.keys.push_back({{1e3f, 0.f, 0.f}, {0.f, 0.f, 0.f, 1.f}, glm::vec3(1.f)});
  }
  return {root, pendulum, ghost};
}

MeshFileSpec CameraMesh() {
  MeshFileSpec s;
  VertexBufferSpec vb = PlateVertices();
  s.vertexBuffers = {vb};
  s.indexBuffers = {{false, {0, 1, 2}}};
  s.meshes = {{"cameraBody", 0, 0, {0}}};
  s.subsets = {{"body", 0, 0, 0, 3, 0, 4}};
  const float yaw = kCameraYawDeg * 3.14159265f / 180.f, c = std::cos(yaw), sn = std::sin(yaw);
  FrameSpec camera{"camera", 0, 1, kNone, kNone};
  camera.matrix = {10 * c, 0, -10 * sn, 0, 0, 10, 0, 0, 10 * sn, 0, 10 * c, 0, kCameraEye.x, kCameraEye.y, kCameraEye.z, 1};
  s.frames = {{"", kNone, kNone, 1, kNone}, {"RootNode", kNone, 0, 2, kNone}, camera};
  s.materials = {{"lambert1", "default.dds", "default-normalmap.dds", ""}};
  return s;
}

std::vector<AnimFrameSpec> CameraAnim() {
  const float yaw = kCameraYawDeg * 3.14159265f / 180.f;
  AnimFrameSpec camera{"camera", {}};
  for (uint32_t k = 0; k < kCameraKeys; ++k)
    camera.keys.push_back({kCameraEye + glm::vec3(kCameraStepX * float(k), 0.f, 0.f),
                           {0.f, std::sin(yaw / 2), 0.f, std::cos(yaw / 2)}, glm::vec3(10.f)});
  return {camera};
}

bool WriteSdkMeshSet(const std::filesystem::path& dir, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir / "media", ec);
  auto write = [&](const std::filesystem::path& p, const std::vector<uint8_t>& bytes) {
    std::ofstream f(p, std::ios::binary);
    f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!f) *error = "cannot write " + p.string();
    return bool(f);
  };
  // The original's form: Windows separators, CRLF, three lines per entry, trailing blanks.
  const std::string description =
      "media\\sdktest.sdkmesh\r\nmedia\\sdktest.sdkmesh_anim  \r\nLIT\r\n"
      "media\\sdkcam.sdkmesh\r\nmedia\\sdkcam.sdkmesh_anim\r\nCAMERA \r\n";
  return write(dir / "media/sdktest.sdkmesh", EncodeMesh(TestMesh())) &&
         write(dir / "media/sdktest.sdkmesh_anim", EncodeAnim(kTestFps, TestAnim())) &&
         write(dir / "media/sdkcam.sdkmesh", EncodeMesh(CameraMesh())) &&
         write(dir / "media/sdkcam.sdkmesh_anim", EncodeAnim(kCameraFps, CameraAnim())) &&
         write(dir / "scene_description.txt", std::vector<uint8_t>(description.begin(), description.end()));
}

}  // namespace sdkgen
