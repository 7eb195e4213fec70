#include "AppWindow.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace drr {

bool AppWindow::Start(bool headlessAsked) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  m_Headless = headlessAsked || ((!display || !*display) && (!wayland || !*wayland));
  if (m_Headless) return true;
  if (glfwInit() != GLFW_TRUE) {
    std::fprintf(stderr, "GLFW could not start; running headless\n");
    m_Headless = true;
    return true;
  }
  m_GlfwStarted = true;
  if (!glfwVulkanSupported()) {
    std::fprintf(stderr, "GLFW: no Vulkan loader for windows; running headless\n");
    m_Headless = true;
  }
  return true;
}

bool AppWindow::Create(uint32_t width, uint32_t height, std::string* error) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  m_Window = glfwCreateWindow(int(width), int(height), "Dynamic Resolution Rendering", nullptr, nullptr);
  if (!m_Window) {
    *error = "cannot create the window";
    return false;
  }
  return true;
}

void AppWindow::Destroy() {
  if (m_Window) {
    glfwDestroyWindow(m_Window);
    m_Window = nullptr;
  }
  if (m_GlfwStarted) {
    glfwTerminate();
    m_GlfwStarted = false;
  }
}

void AppWindow::InstallInput(GuiInput* input, void* user, GuiInput::KeyHandler keys, GuiInput::MouseHandler mouse) {
  if (m_Window) input->Install(m_Window, user, keys, mouse);
}

double AppWindow::RefreshHz(double fallback) const {
  if (!m_Window) return fallback;
  if (GLFWmonitor* mon = glfwGetPrimaryMonitor())
    if (const GLFWvidmode* mode = glfwGetVideoMode(mon); mode && mode->refreshRate > 0) return mode->refreshRate;
  return fallback;
}

void AppWindow::FramebufferSize(uint32_t* w, uint32_t* h) const {
  int fw = 0, fh = 0;
  if (m_Window) glfwGetFramebufferSize(m_Window, &fw, &fh);
  *w = uint32_t(std::max(fw, 0));
  *h = uint32_t(std::max(fh, 0));
}

void AppWindow::ToClientFraction(double x, double y, float* u, float* v) const {
  int ww = 1, wh = 1;
  glfwGetWindowSize(m_Window, &ww, &wh);
  *u = float(x / std::max(ww, 1));
  *v = float(y / std::max(wh, 1));
}

bool AppWindow::Shown() const {
  return m_Window && glfwGetWindowAttrib(m_Window, GLFW_VISIBLE) && !glfwGetWindowAttrib(m_Window, GLFW_ICONIFIED);
}

void AppWindow::RequestClose() {
  if (m_Window) glfwSetWindowShouldClose(m_Window, GLFW_TRUE);
}

void AppWindow::ToggleFullscreen() {
  if (!m_Window) return;
  if (!Shown()) {  // see the header: applied when shown again; two requests cancel out
    m_FullscreenPending = !m_FullscreenPending;
    return;
  }
  m_FullscreenPending = false;
  if (!m_Fullscreen) {
    GLFWmonitor* mon = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = mon ? glfwGetVideoMode(mon) : nullptr;
    if (!mode) return;
    glfwGetWindowPos(m_Window, &m_WindowedPos[0], &m_WindowedPos[1]);
    glfwGetWindowSize(m_Window, &m_WindowedSize[0], &m_WindowedSize[1]);
    glfwSetWindowMonitor(m_Window, mon, 0, 0, mode->width, mode->height, mode->refreshRate);
    m_Fullscreen = true;
  } else {
    glfwSetWindowMonitor(m_Window, nullptr, m_WindowedPos[0], m_WindowedPos[1], m_WindowedSize[0],
                         m_WindowedSize[1], GLFW_DONT_CARE);
    m_Fullscreen = false;
  }
}

// --window-test: scripted window events (the frame numbers are arbitrary).
void AppWindow::WindowTestStep(int64_t frame, uint32_t testW, uint32_t testH) {
  switch (frame) {
    case 5: glfwSetWindowSize(m_Window, 1, 1); break;
    case 10: glfwIconifyWindow(m_Window); break;
    case 13: ToggleFullscreen(); break;  // while minimised: deferred to the restore
    case 15: glfwRestoreWindow(m_Window); break;
    case 20: ToggleFullscreen(); break;
    case 23: glfwSetWindowSize(m_Window, int(testW), int(testH)); break;
    case 26: ToggleFullscreen(); break;
    case 31: ToggleFullscreen(); break;
    case 35: glfwSetWindowSize(m_Window, int(testW), int(testH)); break;
    default: break;
  }
}

void AppWindow::LogWindowTestState(int64_t frame, int fbW, int fbH) {
  char state[160];
  std::snprintf(state, sizeof(state), "framebuffer %dx%d visible %d iconified %d fullscreen %d%s", fbW, fbH,
                glfwGetWindowAttrib(m_Window, GLFW_VISIBLE), glfwGetWindowAttrib(m_Window, GLFW_ICONIFIED),
                int(m_Fullscreen), m_FullscreenPending ? " (toggle pending)" : "");
  if (m_WindowTestState != state)
    std::fprintf(stderr, "window-test frame %lld: %s\n", static_cast<long long>(frame), state);
  m_WindowTestState = state;
}

AppWindow::Frame AppWindow::BeginFrame(int64_t frame, bool windowTest, uint32_t testW, uint32_t testH,
                                       uint32_t* fbW, uint32_t* fbH) {
  if (!m_Window) return Frame::Ready;
  if (windowTest) WindowTestStep(frame, testW, testH);
  glfwPollEvents();
  if (glfwWindowShouldClose(m_Window)) return Frame::Closed;
  if (m_FullscreenPending && Shown()) ToggleFullscreen();
  int fw = 0, fh = 0;
  glfwGetFramebufferSize(m_Window, &fw, &fh);
  if (windowTest) LogWindowTestState(frame, fw, fh);
  if (fw <= 0 || fh <= 0 || glfwGetWindowAttrib(m_Window, GLFW_ICONIFIED)) return Frame::Minimised;
  *fbW = uint32_t(fw);
  *fbH = uint32_t(fh);
  return Frame::Ready;
}

void AppWindow::WaitWhileMinimised(bool scripted) {
  // Nothing to draw until the window is restored: sleep until an event
  // arrives. The scripted window test counts its steps in frames, so there a
  // minimised frame still passes every 20 ms.
  if (scripted) glfwWaitEventsTimeout(0.02);
  else glfwWaitEvents();
}

}  // namespace drr
