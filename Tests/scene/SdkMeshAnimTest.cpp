// SDKMESH_ANIM keys evaluated as the original's interpolating transform
// (SDKMeshExt.cpp), against matrices written out by hand in Direct3D's
// convention (row vectors, left-handed) and then mirrored to the port's
// right-handed frame; and the camera a CAMERA entry's model gives.
#include <gtest/gtest.h>

#include <cmath>

#include "ArenaGenSdkMesh.h"
#include "scene/SdkMesh.h"
#include "scene/SdkMeshModel.h"

using namespace drr;

namespace {

// A Direct3D matrix: m[row][column], points as row vectors (p' = p * M).
struct D3DMatrix {
  float m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
};
D3DMatrix Multiply(const D3DMatrix& a, const D3DMatrix& b) {
  D3DMatrix r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      r.m[i][j] = 0.f;
      for (int k = 0; k < 4; ++k) r.m[i][j] += a.m[i][k] * b.m[k][j];
    }
  return r;
}
D3DMatrix Scaling(float s) {
  D3DMatrix r;
  r.m[0][0] = r.m[1][1] = r.m[2][2] = s;
  return r;
}
D3DMatrix Translation(float x, float y, float z) {
  D3DMatrix r;
  r.m[3][0] = x, r.m[3][1] = y, r.m[3][2] = z;
  return r;
}
D3DMatrix RotationX(float a) {  // as D3DXMatrixRotationX
  D3DMatrix r;
  r.m[1][1] = std::cos(a), r.m[1][2] = std::sin(a);
  r.m[2][1] = -std::sin(a), r.m[2][2] = std::cos(a);
  return r;
}

// The port's matrix for a Direct3D one: transposed (column vectors), z mirrored.
glm::mat4 ToPort(const D3DMatrix& d) {
  glm::mat4 g;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = d.m[i][j] * ((i == 2) != (j == 2) ? -1.f : 1.f);
  return g;
}

void ExpectNear(const glm::mat4& got, const glm::mat4& want, float tol) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(got[i][j], want[i][j], tol) << "[" << i << "][" << j << "]";
}

ModelData LoadPair(const sdkgen::MeshFileSpec& mesh, uint32_t fps, const std::vector<sdkgen::AnimFrameSpec>& keys) {
  sdkmesh::File f;
  sdkmesh::AnimFile a;
  ModelData model, anim;
  std::string error;
  EXPECT_TRUE(sdkmesh::ReadMesh(sdkgen::EncodeMesh(mesh), "m.sdkmesh", &f, &error)) << error;
  EXPECT_TRUE(SdkMeshToModel(f, {}, &model, &error)) << error;
  EXPECT_TRUE(sdkmesh::ReadAnim(sdkgen::EncodeAnim(fps, keys), "m.sdkmesh_anim", &a, &error)) << error;
  EXPECT_TRUE(SdkMeshAnimToModel(a, &anim, &error)) << error;
  AttachAnimations(&model, anim);
  return model;
}

// The pendulum's world matrix at key k blended towards key k+1 by f, by hand:
// scale * rotation * translation of the blended key, times its parent "group".
glm::mat4 PendulumByHand(uint32_t k, float f) {
  const float angle = sdkgen::PendulumAngle(k) + f * (sdkgen::PendulumAngle(k + 1) - sdkgen::PendulumAngle(k));
  const float scale = sdkgen::PendulumScale(k) + f * (sdkgen::PendulumScale(k + 1) - sdkgen::PendulumScale(k));
  const D3DMatrix local = Multiply(Multiply(Scaling(scale), RotationX(angle)), Translation(0.f, 150.f, 0.f));
  const D3DMatrix group = Multiply(Scaling(2.f), Translation(0.f, 50.f, 300.f));
  return ToPort(Multiply(local, group));
}

constexpr int kPendulumNode = 4;

}  // namespace

TEST(SdkMeshAnim, KeysInterpolatedAndLoopedAsTheOriginal) {
  const ModelData m = LoadPair(sdkgen::TestMesh(), sdkgen::kTestFps, sdkgen::TestAnim());
  const double period = double(sdkgen::kTestKeys) / sdkgen::kTestFps;  // 2 s
  std::vector<glm::mat4> g;
  struct Case { double t; uint32_t key; float f; };
  const Case cases[] = {{0.0, 0, 0.f},   {0.3, 1, 0.2f},  {1.0, 4, 0.f},            {1.875, 7, 0.5f},  // last into first
                        {period + 0.3, 1, 0.2f}, {5 * period + 1.0, 4, 0.f}};
  for (const Case& c : cases) {
    m.Evaluate(c.t, &g);
    SCOPED_TRACE("t = " + std::to_string(c.t));
    ExpectNear(g[kPendulumNode], PendulumByHand(c.key, c.f), 2e-3f);
  }
}

TEST(SdkMeshAnim, ZeroQuaternionIsIdentityAndUnknownFramesIgnored) {
  const ModelData m = LoadPair(sdkgen::TestMesh(), sdkgen::kTestFps, sdkgen::TestAnim());
  std::vector<glm::mat4> g;
  m.Evaluate(0.7, &g);
  ExpectNear(g[1], glm::mat4(1.f), 1e-6f);  // RootNode: all-zero orientation keys
  for (const auto& n : m.nodes) EXPECT_NE(n.name, "ghost");
}

TEST(SdkMeshAnim, WithoutAnimationTheFrameMatrices) {
  sdkmesh::File f;
  ModelData m;
  std::string error;
  ASSERT_TRUE(sdkmesh::ReadMesh(sdkgen::EncodeMesh(sdkgen::TestMesh()), "m.sdkmesh", &f, &error)) << error;
  ASSERT_TRUE(SdkMeshToModel(f, {}, &m, &error)) << error;
  std::vector<glm::mat4> g;
  m.Evaluate(0.9, &g);
  const D3DMatrix group = Multiply(Scaling(2.f), Translation(0.f, 50.f, 300.f));
  ExpectNear(g[kPendulumNode], ToPort(Multiply(Translation(0.f, 150.f, 0.f), group)), 1e-3f);
}

// The original views from the camera model's last frame with a mesh (view =
// inverse of its world matrix, looking down its +z); in the port that frame
// looks down -z of the mirrored matrix, from the mirrored eye.
TEST(SdkMeshAnim, CameraFromTheLastFrameWithAMesh) {
  const ModelData m = LoadPair(sdkgen::CameraMesh(), sdkgen::kCameraFps, sdkgen::CameraAnim());
  int last = -1;
  for (size_t n = 0; n < m.nodes.size(); ++n)
    if (!m.nodes[n].meshes.empty()) last = int(n);
  ASSERT_EQ(last, 2);
  const float yaw = glm::radians(sdkgen::kCameraYawDeg);
  const glm::vec3 forwardLH(std::sin(yaw), 0.f, std::cos(yaw));  // row 2 of D3DXMatrixRotationY
  for (double t : {0.0, 1.25}) {
    std::vector<glm::mat4> g;
    m.Evaluate(t, &g);
    const float keys = float(t * sdkgen::kCameraFps);  // 2.5 at 1.25 s: halfway between keys 2 and 3
    const glm::vec3 eyeLH = sdkgen::kCameraEye + glm::vec3(sdkgen::kCameraStepX * keys, 0.f, 0.f);
    const glm::vec3 eye = glm::vec3(g[last][3]);
    EXPECT_NEAR(eye.x, eyeLH.x, 1e-2f);
    EXPECT_NEAR(eye.y, eyeLH.y, 1e-2f);
    EXPECT_NEAR(eye.z, -eyeLH.z, 1e-2f);
    const glm::vec3 look = glm::normalize(glm::vec3(g[last] * glm::vec4(0.f, 0.f, -1.f, 0.f)));
    EXPECT_NEAR(look.x, forwardLH.x, 1e-5f);
    EXPECT_NEAR(look.z, -forwardLH.z, 1e-5f);
  }
}
