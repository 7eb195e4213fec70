// The sample's GUI, as the original's: the settings panel (right), the
// statistics text (top left) and the help window, built with Dear ImGui and
// drawn at back-buffer resolution after the zoom box.
#pragma once

#include <array>
#include <functional>
#include <string>

#include "GuiRenderer.h"
#include "Options.h"

struct ImGuiContext;

namespace drr {

// Everything the GUI shows as statistics (refreshed by Sample::UpdateStats).
struct SampleStats {
  double frameMs = 0, clearMs = 0, sceneMs = 0, postPMs = 0, scaleMs = 0, vsyncMs = 0;
  double fps = 0;
  float scaleX = 1, scaleY = 1;
};

// What the panel reads of the sample this frame.
struct GuiView {
  const Options* options = nullptr;
  const SampleStats* stats = nullptr;
  int camera = 0, cameraCount = 1;
  std::function<std::string(int)> cameraName;
  float scaleX = 1, scaleY = 1;  // the applied dynamic scale
  uint32_t backBufferW = 0, backBufferH = 0, rtW = 0, rtH = 0, viewportW = 0, viewportH = 0;
  std::string adapter, lastMessage;
  // Called inside Build when the user changed a setting (scales: the applied
  // ones unless a slider moved), before the statistics text is built.
  std::function<void(const Options&)> apply;
};

class GuiPanel {
 public:
  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error);
  void Release();
  GuiRenderer& Renderer() { return m_Renderer; }

  // Builds this frame's windows (view.apply sees the user's changes).
  void Build(const GuiView& view);
  // Draws what Build made into rtv (back-buffer viewport).
  void Render(d3dl::DeviceContext* ctx, d3dl::RenderTargetView* rtv, const d3dl::VIEWPORT& viewport);

  bool show = true, showText = true, showHelp = false;
  // Part of the panel above the scale sliders (its content does not depend on
  // the scale), in back-buffer pixels: x0, y0, x1, y1.
  std::array<float, 4> staticRect{0, 0, 0, 0};

 private:
  void Panel(const GuiView& view);
  void Text(const GuiView& view);
  void Help(const GuiView& view);

  ImGuiContext* m_ImGui = nullptr;
  GuiRenderer m_Renderer;
};

}  // namespace drr
