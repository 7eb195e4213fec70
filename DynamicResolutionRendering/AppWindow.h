// The window and its events (GLFW): whether to run headless, the window,
// full screen, minimise, the scripted window test, and the key and mouse
// callbacks (forwarded to ImGui, then to the sample). The original's DXUT
// window code, in one place.
#pragma once

#include <cstdint>
#include <string>

#include "GuiRenderer.h"

struct GLFWwindow;

namespace drr {

class AppWindow {
 public:
  ~AppWindow() { Destroy(); }
  // Headless when asked, when there is no display, or when GLFW cannot start
  // or has no Vulkan loader; otherwise GLFW is initialised.
  bool Start(bool headlessAsked);
  bool Headless() const { return m_Headless; }
  bool Create(uint32_t width, uint32_t height, std::string* error);
  void Destroy();
  GLFWwindow* Handle() const { return m_Window; }

  void InstallInput(GuiInput* input, void* user, GuiInput::KeyHandler keys, GuiInput::MouseHandler mouse);
  // The monitor's refresh rate, else `fallback`.
  double RefreshHz(double fallback) const;
  void FramebufferSize(uint32_t* w, uint32_t* h) const;
  // Window coordinates to fractions of the client area (0..1).
  void ToClientFraction(double x, double y, float* u, float* v) const;

  // Full screen on the primary monitor and back. While the window is hidden
  // or minimised the request waits for the restore: GLFW 3.3's X11 backend
  // would wait forever for a minimised window to be mapped under window
  // managers that keep it unmapped (matchbox, for one).
  void ToggleFullscreen();
  bool Fullscreen() const { return m_Fullscreen; }
  bool Shown() const;  // mapped and not minimised
  void RequestClose();

  enum class Frame { Closed, Minimised, Ready };
  // Per frame: the window test's scripted step for `frame`, events, a
  // deferred full-screen request; Ready with the framebuffer size.
  Frame BeginFrame(int64_t frame, bool windowTest, uint32_t testW, uint32_t testH, uint32_t* fbW, uint32_t* fbH);
  // Blocks until the next window event (scripted: at most 20 ms).
  void WaitWhileMinimised(bool scripted);

 private:
  void WindowTestStep(int64_t frame, uint32_t testW, uint32_t testH);
  void LogWindowTestState(int64_t frame, int fbW, int fbH);

  bool m_Headless = true;
  bool m_GlfwStarted = false;
  GLFWwindow* m_Window = nullptr;
  bool m_Fullscreen = false;
  bool m_FullscreenPending = false;  // asked for while minimised
  int m_WindowedPos[2] = {100, 100}, m_WindowedSize[2] = {1280, 720};
  std::string m_WindowTestState;  // --window-test: last state logged
};

}  // namespace drr
