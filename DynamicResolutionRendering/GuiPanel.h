// The sample's GUI, as the original's DXUT dialogs: the settings panel on the
// right (its HUD buttons and sample UI, in the original's order and labels)
// and the yellow text at the top left (the original's RenderText, with the
// F1 help), built with Dear ImGui and drawn at back-buffer resolution after
// the zoom box. The decisions live in GuiLogic (CPU-tested).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <utility>

#include "GuiLogic.h"
#include "GuiRenderer.h"
#include "Options.h"

struct ImGuiContext;

namespace drr {

struct OptionRow;

// Everything the GUI shows as statistics (refreshed by Sample::UpdateStats):
// the timing lines and the scale the sliders' labels show.
struct SampleStats {
  TimingStats timing;
  float scaleX = 1, scaleY = 1;
};

// What the panel reads of the sample this frame.
struct GuiView {
  const Options* options = nullptr;
  const SampleStats* stats = nullptr;
  int camera = 0, cameraCount = 1;
  std::function<std::string(int)> cameraName;
  float scaleX = 1, scaleY = 1;  // the applied dynamic scale
  uint32_t backBufferW = 0, backBufferH = 0;
  double dxutFps = 0.0;  // DXUT's one-second figure (the coordinator's DxutFpsCounter)
  bool vsync = true, softwareAdapter = false;
  std::string backBufferFormat, adapter, lastMessage;
  RecordingInfo recording;  // port addition: the scene's recording threads (Docs/Threads.md)
  // Called inside Build when the user changed a setting (scales: the applied
  // ones unless a slider moved).
  std::function<void(const Options&)> apply;
};

// Buttons whose action must wait for the end of the frame.
struct GuiActions {
  bool toggleFullscreen = false, reloadShaders = false;
};

class GuiPanel {
 public:
  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error);
  void Release();
  GuiRenderer& Renderer() { return m_Renderer; }

  // Builds this frame's panel and text (view.apply sees the user's changes).
  void Build(const GuiView& view);
  bool Drawn() const { return enabled && (showPanel || showText); }
  // Draws what Build made into rtv (back-buffer viewport).
  void Render(d3dl::DeviceContext* ctx, d3dl::RenderTargetView* rtv, const d3dl::VIEWPORT& viewport);
  GuiActions TakeActions() { return std::exchange(m_Actions, GuiActions{}); }
  const PanelWidgets& Widgets() const { return m_Widgets; }

  bool enabled = true;     // --no-gui: neither panel nor text
  bool showPanel = true;   // F10 (the original's g_bDisplayGUI)
  bool showText = true;    // F11 (g_bDisplayDemoText)
  bool showHelp = false;   // F1 (g_bShowHelp)
  // Part of the panel above the scale texts (its content does not depend on
  // the scale), in back-buffer pixels: x0, y0, x1, y1.
  std::array<float, 4> staticRect{0, 0, 0, 0};
  // Where the panel and its last section's header were drawn (the report's "gui").
  const GuiLayout& Layout() const { return m_Layout; }

 private:
  void SyncWithOptions(const GuiView& view);
  void Panel(const GuiView& view);
  void Buttons();
  void Toggles(const GuiView& view, Options* o);
  bool ScaleSliders(const GuiView& view, Options* o);
  void FilterAndControl(Options* o);
  void PortSections(const GuiView& v, Options* o);  // port additions, one section per settings group
  void CustomWidget(const OptionRow& row, Options* o);
  void Text(const GuiView& view);

  ImGuiContext* m_ImGui = nullptr;
  GuiRenderer m_Renderer;
  bool m_Seeded = false;
  Options m_Seen;           // the options of the last Build
  PanelWidgets m_Widgets;   // enabled/shown, as the original's dialog keeps them
  SliderPair m_Sliders;     // the original's g_ResolutionScaleX/Y
  GuiActions m_Actions;
  GuiLayout m_Layout;
};

}  // namespace drr
