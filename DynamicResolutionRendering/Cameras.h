// The cameras the user can pick, in the original's order: 0 is the
// first-person camera (WASD, Q/E down/up, left mouse to turn), 1.. the
// scene's cameras (a description's CAMERA entries in file order). The
// original's default is 1: the Arena's moving cinematic camera.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scene/Scene.h"

struct GLFWwindow;

namespace drr {

class Cameras {
 public:
  static constexpr int kFirstPerson = 0;
  void Init(const Scene* scene);
  int Count() const { return SceneCount() + 1; }
  int Current() const { return m_Current; }
  // The original's g_CameraIndex = 1, or First Person when the scene has no camera.
  int Default() const { return SceneCount() > 0 ? 1 : kFirstPerson; }
  std::string Name(int i) const;
  // Clamped to the range; true when the camera changed.
  bool Select(int i);
  // This frame's pose (first person: from the window's keys and mouse).
  CameraPose Pose() const;
  // The eye of the specular term. The original's scene cameras only replace
  // the view matrix, and its shader reads the first-person camera's eye
  // whichever camera is viewing; the camera-eye fix uses the viewing one's.
  glm::vec3 ShadingEye(bool viewingCameraEye) const;
  // Moves the first-person camera (only while it is selected, as the original's FrameMove).
  void UpdateFirstPerson(GLFWwindow* window, bool keyboardFree, double elapsed);
  void BeginDrag(double x, double y);

 private:
  int SceneCount() const { return m_Scene ? m_Scene->CameraCount() : 0; }
  bool FirstPerson() const { return m_Current == kFirstPerson; }
  glm::vec3 Forward() const;

  const Scene* m_Scene = nullptr;
  int m_Current = 1;
  // The original's first-person camera starts at the scene centre looking down -z.
  glm::vec3 m_Position{0.f};
  float m_Yaw = 0.f, m_Pitch = 0.f, m_Speed = 100.f;
  bool m_Dragging = false;
  double m_LastCursor[2] = {0, 0};
};

}  // namespace drr
