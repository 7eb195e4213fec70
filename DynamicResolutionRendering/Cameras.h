// The cameras the user can pick: the scene's (cinematic, static) and a
// first-person camera that starts where the previous camera was and moves
// with WASD and the left mouse button.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scene/Scene.h"

struct GLFWwindow;

namespace drr {

class Cameras {
 public:
  void Init(const Scene* scene);
  int Count() const { return SceneCount() + 1; }
  int Current() const { return m_Current; }
  std::string Name(int i) const;
  // Clamped to the range; true when the camera changed (a cut: the velocity
  // history is reset).
  bool Select(int i);
  // This frame's pose (first person: from the window's keys and mouse).
  CameraPose Pose() const;
  void UpdateFirstPerson(GLFWwindow* window, bool keyboardFree, double elapsed);
  void BeginDrag(double x, double y);

 private:
  int SceneCount() const { return m_Scene ? m_Scene->CameraCount() : 0; }
  bool FirstPerson() const { return m_Current == SceneCount(); }
  glm::vec3 Forward() const;

  const Scene* m_Scene = nullptr;
  int m_Current = 1;
  glm::vec3 m_Position{0.f};
  float m_Yaw = 0.f, m_Pitch = 0.f, m_Speed = 100.f;
  bool m_Dragging = false;
  double m_LastCursor[2] = {0, 0};
};

}  // namespace drr
