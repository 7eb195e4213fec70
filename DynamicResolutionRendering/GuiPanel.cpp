#include "GuiPanel.h"

#include <imgui.h>

#include <algorithm>
#include <sstream>

namespace drr {

namespace {
// A combo over an enum with Count and a name function.
template <class E>
void EnumCombo(const char* label, E* value, const char* (*name)(E)) {
  int v = static_cast<int>(*value);
  if (ImGui::BeginCombo(label, name(*value))) {
    for (int i = 0; i < static_cast<int>(E::Count); ++i)
      if (ImGui::Selectable(name(static_cast<E>(i)), i == v)) v = i;
    ImGui::EndCombo();
  }
  *value = static_cast<E>(v);
}

bool SettingsDiffer(const Options& a, const Options& b) {
  return a.pause != b.pause || a.showCameras != b.showCameras || a.motionBlur != b.motionBlur ||
         a.zoom != b.zoom || a.camera != b.camera || a.psClear != b.psClear ||
         a.dynamicResolution != b.dynamicResolution || a.superSampling != b.superSampling ||
         a.aspectLock != b.aspectLock || a.filter != b.filter || a.symmetricTAA != b.symmetricTAA ||
         a.control != b.control || a.law != b.law;
}
}  // namespace

bool GuiPanel::Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error) {
  m_ImGui = ImGui::CreateContext();
  ImGui::SetCurrentContext(m_ImGui);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 1.0f;  // opaque panel
  return m_Renderer.Init(device, shaders, error);
}

void GuiPanel::Release() {
  m_Renderer.Release();
  if (m_ImGui) {
    ImGui::DestroyContext(m_ImGui);
    m_ImGui = nullptr;
  }
}

void GuiPanel::Build(const GuiView& view) {
  ImGui::NewFrame();
  if (show) {
    Panel(view);
    Help(view);
    if (showText) Text(view);
  }
  ImGui::Render();
}

void GuiPanel::Render(d3dl::DeviceContext* ctx, d3dl::RenderTargetView* rtv, const d3dl::VIEWPORT& viewport) {
  if (!show) return;
  ctx->BeginEvent("GUI");
  ctx->OMSetRenderTargets(1, &rtv, nullptr);
  ctx->RSSetViewports(1, &viewport);
  m_Renderer.Render(ctx, ImGui::GetDrawData());
  ctx->EndEvent();
}

// The settings panel, as the original's (its controls in the same order).
void GuiPanel::Panel(const GuiView& v) {
  const float panelW = 300.0f;
  ImGui::SetNextWindowPos(ImVec2(float(v.backBufferW) - panelW - 10.0f, 10.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(panelW, 0.0f), ImGuiCond_Always);
  ImGui::Begin("Dynamic Resolution Rendering", nullptr,
               ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  const ImVec2 top = ImGui::GetWindowPos();
  Options o = *v.options;
  ImGui::Checkbox("Pause (P)", &o.pause);
  ImGui::Checkbox("Show cameras", &o.showCameras);
  ImGui::Checkbox("Motion blur", &o.motionBlur);
  ImGui::Checkbox("Zoom box (Z)", &o.zoom);
  int cam = v.camera;
  if (ImGui::BeginCombo("Camera", v.cameraName(cam).c_str())) {
    for (int i = 0; i < v.cameraCount; ++i)
      if (ImGui::Selectable(v.cameraName(i).c_str(), i == cam)) cam = i;
    ImGui::EndCombo();
  }
  o.camera = cam;
  ImGui::Checkbox("Clear with pixel shader", &o.psClear);
  ImGui::Checkbox("Dynamic resolution", &o.dynamicResolution);
  ImGui::Checkbox("Allow super sampling", &o.superSampling);
  ImGui::Checkbox("Lock aspect ratio", &o.aspectLock);
  EnumCombo("Filter", &o.filter, FilterName);
  ImGui::Checkbox("Symmetric TAA", &o.symmetricTAA);
  EnumCombo("Control", &o.control, ControlModeName);
  EnumCombo("Control law", &o.law, ControlLawName);
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  staticRect = {top.x, top.y, top.x + panelW, cursor.y - 2.0f};

  // Scales (the controller overrides them unless Manual).
  const float maxPct = o.superSampling ? 200.0f : 100.0f;
  float sx = v.scaleX * 100.0f, sy = v.scaleY * 100.0f;
  bool scaleEdited = ImGui::SliderFloat("Scale X %", &sx, 1.0f, maxPct, "%.1f");
  scaleEdited |= ImGui::SliderFloat("Scale Y %", &sy, 1.0f, maxPct, "%.1f");
  if (scaleEdited) {
    if (o.aspectLock) sy = sx;
    o.scaleX = std::clamp(sx, 1.0f, maxPct) / 100.0f;
    o.scaleY = std::clamp(sy, 1.0f, maxPct) / 100.0f;
  } else {
    o.scaleX = v.scaleX;
    o.scaleY = v.scaleY;
  }
  const SampleStats& st = *v.stats;
  ImGui::Separator();
  ImGui::Text("Frame %6.2f ms   Clear %6.2f ms", st.frameMs, st.clearMs);
  ImGui::Text("Scene %6.2f ms   PostP %6.2f ms", st.sceneMs, st.postPMs);
  ImGui::Text("Scale %6.2f ms   VSync %6.2f ms", st.scaleMs, st.vsyncMs);
  ImGui::Text("Scale X %.1f %%  Y %.1f %%", st.scaleX * 100.0f, st.scaleY * 100.0f);
  ImGui::End();
  if (scaleEdited || SettingsDiffer(o, *v.options)) v.apply(o);
}

void GuiPanel::Help(const GuiView& v) {
  if (!showHelp) return;
  ImGui::SetNextWindowPos(ImVec2(10.0f, float(v.backBufferH) * 0.5f), ImGuiCond_FirstUseEver);
  ImGui::Begin("Help", &showHelp, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextUnformatted(
      "F1  help\nF2  fullscreen\nF4  reload shaders\nF10 GUI\nF11 text\nP   pause\nZ   zoom box\n"
      "Right mouse: zoom centre\nFirst Person camera: WASD + left mouse drag\nEsc quit");
  ImGui::End();
}

void GuiPanel::Text(const GuiView& v) {
  ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.35f);
  ImGui::Begin("##stats", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  const Options& o = *v.options;
  ImGui::Text("%.1f fps  %s", v.stats->fps, v.adapter.c_str());
  ImGui::Text("Back buffer %ux%u  RT %ux%u  viewport %ux%u", v.backBufferW, v.backBufferH, v.rtW, v.rtH,
              v.viewportW, v.viewportH);
  ImGui::Text("Filter %s  control %s (%s)  camera %s", FilterName(o.filter), ControlModeName(o.control),
              ControlLawOption(o.law), v.cameraName(v.camera).c_str());
  if (!v.lastMessage.empty()) {
    // Compiler output can be long: the first lines here, all of it on stderr.
    std::string shown, line;
    std::istringstream lines(v.lastMessage);
    for (int n = 0; n < 6 && std::getline(lines, line); ++n) shown += (n ? "\n" : "") + line.substr(0, 160);
    ImGui::TextUnformatted(shown.c_str());
  }
  ImGui::Text("F1 help");
  ImGui::End();
}

}  // namespace drr
