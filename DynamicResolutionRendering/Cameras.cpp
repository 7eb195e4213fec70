#include "Cameras.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace drr {

void Cameras::Init(const Scene* scene) {
  m_Scene = scene;
  m_Position = scene->OriginalCentre();
  m_Yaw = m_Pitch = 0.f;
  const glm::vec3 lo = scene->BoundsMin(), hi = scene->BoundsMax();
  const float diag = glm::length(hi - lo);
  m_Speed = std::isfinite(diag) && diag > 0 ? diag * 0.1f : 100.0f;
}

std::string Cameras::Name(int i) const {
  return i == kFirstPerson ? std::string("First Person") : m_Scene->CameraName(i - 1);
}

bool Cameras::Select(int i) {
  const int prev = m_Current;
  i = std::clamp(i, 0, Count() - 1);
  m_Current = i;  // the first-person camera keeps its own pose, as the original's
  return i != prev;
}

glm::vec3 Cameras::Forward() const {
  return {std::sin(m_Yaw) * std::cos(m_Pitch), std::sin(m_Pitch), -std::cos(m_Yaw) * std::cos(m_Pitch)};
}

CameraPose Cameras::Pose() const {
  if (!FirstPerson()) return m_Scene->Camera(m_Current - 1);
  CameraPose p;
  p.position = m_Position;
  p.view = glm::lookAtRH(m_Position, m_Position + Forward(), glm::vec3(0, 1, 0));
  return p;
}

glm::vec3 Cameras::ShadingEye(bool viewingCameraEye) const {
  return viewingCameraEye ? Pose().position : m_Position;
}

void Cameras::BeginDrag(double x, double y) {
  m_Dragging = true;
  m_LastCursor[0] = x;
  m_LastCursor[1] = y;
}

void Cameras::UpdateFirstPerson(GLFWwindow* window, bool keyboardFree, double elapsed) {
  if (!window || !FirstPerson()) return;
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  if (m_Dragging) {
    if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS) {
      m_Dragging = false;
    } else {
      // The original's rotation scaler: 0.01 radian per pixel.
      m_Yaw += float(x - m_LastCursor[0]) * 0.01f;
      m_Pitch = std::clamp(m_Pitch - float(y - m_LastCursor[1]) * 0.01f, -1.5f, 1.5f);
    }
  }
  m_LastCursor[0] = x;
  m_LastCursor[1] = y;
  if (!keyboardFree) return;
  const glm::vec3 fwd = Forward();
  const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
  glm::vec3 move(0.f);
  if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) move += fwd;
  if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) move -= fwd;
  if (glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) move += right;
  if (glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) move -= right;
  if (glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) move += glm::vec3(0, 1, 0);
  if (glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) move -= glm::vec3(0, 1, 0);
  const float speed = m_Speed * ((glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS) ? 4.f : 1.f);
  m_Position += move * speed * float(elapsed);
}

}  // namespace drr
