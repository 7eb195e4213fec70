#include "GuiPanel.h"
#include "scene/RecordingThreads.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drr {

namespace {
constexpr float kPanelWidth = 220.0f;
constexpr float kComboWidth = 170.0f;  // the original's combo boxes

// A combo over an enum with Count and a name function, labelled by a static
// text above it as the original's.
template <class E>
void EnumCombo(const char* caption, const char* id, E* value, const char* (*name)(E)) {
  ImGui::TextUnformatted(caption);
  ImGui::SetNextItemWidth(kComboWidth);
  int v = static_cast<int>(*value);
  if (ImGui::BeginCombo(id, name(*value))) {
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
         a.control != b.control || a.law != b.law || a.fixes != b.fixes ||
         // Upscaling (port addition)
         a.secondaryScreenPercentage != b.secondaryScreenPercentage || a.mipBias != b.mipBias ||
         a.autoMipBias != b.autoMipBias || a.taaMipBias != b.taaMipBias ||
         // Deferred shading (port addition)
         a.renderer != b.renderer || a.ssao != b.ssao || a.localLights != b.localLights || a.shadowScale != b.shadowScale ||
         a.shadowLaw != b.shadowLaw ||
         // Tessellation (port addition)
         a.tessellation != b.tessellation || a.tessPixelsPerEdge != b.tessPixelsPerEdge ||
         a.maxTessFactor != b.maxTessFactor ||
         // Recording threads (port addition)
         a.threads != b.threads;
}

int OptionPercent(float scale) { return int(std::lround(100.0 * double(scale))); }
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

// The widget state follows every change of the options, whoever made it (the
// panel, a key, a test), as the original's dialog follows its events.
void GuiPanel::SyncWithOptions(const GuiView& v) {
  const Options& o = *v.options;
  if (!m_Seeded) {
    m_Widgets = InitialWidgets(o);
    m_Sliders = {OptionPercent(o.scaleX), OptionPercent(o.scaleY)};
    m_Seeded = true;
  } else {
    m_Widgets = UpdateWidgets(m_Widgets, m_Seen, o);
    if (o.scaleX != m_Seen.scaleX) m_Sliders.x = OptionPercent(o.scaleX);
    if (o.scaleY != m_Seen.scaleY) m_Sliders.y = OptionPercent(o.scaleY);
  }
  // ControlResolution sets the sliders' values to the scale it applied.
  if (o.dynamicResolution && o.control != ControlMode::Manual)
    m_Sliders = {ScalePercent(v.scaleX), ScalePercent(v.scaleY)};
  m_Seen = o;
}

void GuiPanel::Build(const GuiView& view) {
  SyncWithOptions(view);
  ImGui::NewFrame();
  if (enabled && showPanel) Panel(view);
  if (enabled && showText) Text(view);
  ImGui::Render();
}

void GuiPanel::Render(d3dl::DeviceContext* ctx, d3dl::RenderTargetView* rtv, const d3dl::VIEWPORT& viewport) {
  if (!Drawn()) return;
  ctx->BeginEvent("GUI");
  ctx->OMSetRenderTargets(1, &rtv, nullptr);
  ctx->RSSetViewports(1, &viewport);
  m_Renderer.Render(ctx, ImGui::GetDrawData());
  ctx->EndEvent();
}

// The panel: the original's HUD buttons, then its sample UI in its order.
void GuiPanel::Panel(const GuiView& v) {
  ImGui::SetNextWindowPos(ImVec2(float(v.backBufferW) - kPanelWidth - 10.0f, 30.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 0.0f), ImGuiCond_Always);
  ImGui::Begin("Dynamic Resolution Rendering", nullptr,
               ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
  const ImVec2 top = ImGui::GetWindowPos();
  Options o = *v.options;
  Buttons();
  Toggles(v, &o);
  staticRect = {top.x, top.y, top.x + kPanelWidth, ImGui::GetCursorScreenPos().y - 2.0f};
  const bool sliderMoved = ScaleSliders(v, &o);
  FilterAndControl(&o);
  for (const std::string& line : TimingLines(v.stats->timing))
    ImGui::TextUnformatted(line.c_str());
  PortSection(&o);
  ThreadsSection(v, &o);
  ImGui::End();
  if (sliderMoved || SettingsDiffer(o, *v.options)) v.apply(o);
}

// Upscaling (Docs/Upscaling.md): r.Upscale.Quality, r.TemporalAA.Upsampling,
// the secondary screen percentage and TAAU's view mip bias.
void GuiPanel::UpscaleSection(Options* o) {
  if (!ImGui::CollapsingHeader("Upscaling (port)")) return;
  const ScreenPercentageRange& range = ScreenPercentageRangeOf(o->scaleX);
  ImGui::TextWrapped("%.0f %%: %s", o->scaleX * 100.0, range.use);
  const int current = int(o->filter) - int(Filter::UpscaleNearest);
  int quality = current >= 0 && current < kUpscaleQualities ? current : -1;
  ImGui::SetNextItemWidth(kComboWidth);
  if (ImGui::SliderInt("r.Upscale.Quality", &quality, 0, kUpscaleQualities - 1, quality < 0 ? "-" : "%d"))
    o->filter = UpscaleQualityFilter(std::clamp(quality, 0, kUpscaleQualities - 1));
  bool taau = IsTemporalUpsample(o->filter);
  if (ImGui::Checkbox("Temporal Upsample", &taau))
    o->filter = taau ? Filter::TAAU : UpscaleQualityFilter(3);
  float secondary = float(o->secondaryScreenPercentage);
  ImGui::SetNextItemWidth(kComboWidth);
  if (ImGui::SliderFloat("Secondary %", &secondary, 50.0f, 100.0f, "%.2f")) o->secondaryScreenPercentage = secondary;
  ImGui::Checkbox("Automatic view mip bias", &o->autoMipBias);
  float bias = float(o->mipBias);
  ImGui::SetNextItemWidth(kComboWidth);
  if (ImGui::SliderFloat("Mip bias", &bias, -2.0f, 2.0f, "%.2f")) o->mipBias = bias;
  ImGui::Checkbox("TAA mip bias -0.5 (original)", &o->taaMipBias);
}

// Deferred shading (Docs/Deferred.md): the renderer, SSAO and the spot
// shadow maps' scale and law.
void GuiPanel::DeferredSection(Options* o) {
  if (!ImGui::CollapsingHeader("Deferred shading (port)")) return;
  EnumCombo("Renderer:", "##renderer", &o->renderer, RendererName);
  ImGui::BeginDisabled(o->renderer != Renderer::Deferred);
  ImGui::Checkbox("SSAO", &o->ssao);
  ImGui::Checkbox("Scene lights", &o->localLights);
  float shadow = float(o->shadowScale);
  ImGui::SetNextItemWidth(kComboWidth);
  if (ImGui::SliderFloat("Shadow scale", &shadow, float(kMinShadowScale), 1.0f, "%.2f")) o->shadowScale = shadow;
  EnumCombo("Shadow-map law:", "##shadowlaw", &o->shadowLaw, ShadowLawName);
  ImGui::EndDisabled();
}

// Tessellation (Docs/Tessellation.md): the seed's "Tessellation Detail" and
// "Max Tessellation Factor".
void GuiPanel::TessellationSection(Options* o) {
  if (!ImGui::CollapsingHeader("Tessellation (port)")) return;
  ImGui::Checkbox("Adaptive tessellation", &o->tessellation);
  ImGui::BeginDisabled(!o->tessellation);
  float pixels = float(o->tessPixelsPerEdge);
  ImGui::SetNextItemWidth(kComboWidth);
  if (ImGui::SliderFloat("Pixels per edge", &pixels, 1.0f, 64.0f, "%.1f")) o->tessPixelsPerEdge = pixels;
  ImGui::SetNextItemWidth(kComboWidth);
  ImGui::SliderInt("Max factor", &o->maxTessFactor, 1, 64);
  ImGui::EndDisabled();
}

// Scene recording threads (Docs/Threads.md): --threads and what the last
// frame used.
void GuiPanel::ThreadsSection(const GuiView& v, Options* o) {
  if (!ImGui::CollapsingHeader("Recording threads (port)")) return;
  ImGui::SetNextItemWidth(kComboWidth);
  ImGui::SliderInt("Threads (0 auto)", &o->threads, 0, kMaxRecordingThreads);
  o->threads = std::clamp(o->threads, 0, kMaxRecordingThreads);
  for (const std::string& line : RecordingLines(v.recording)) ImGui::TextUnformatted(line.c_str());
}

void GuiPanel::Buttons() {
  // The original's "Change device (F3)" opens DXUT's device dialog, which the port does not have.
  const ImVec2 size(kPanelWidth - 2.0f * ImGui::GetStyle().WindowPadding.x, 0.0f);
  if (ImGui::Button("Fullscreen (F2)", size)) m_Actions.toggleFullscreen = true;
  if (ImGui::Button("Reload Shaders (F4)", size)) m_Actions.reloadShaders = true;
  ImGui::Spacing();
}

void GuiPanel::Toggles(const GuiView& v, Options* o) {
  ImGui::Checkbox("Paused (P)", &o->pause);
  ImGui::Checkbox("Show Cameras", &o->showCameras);
  ImGui::Checkbox("MotionBlur", &o->motionBlur);
  ImGui::Checkbox("Show zoom box (Z)", &o->zoom);
  ImGui::TextUnformatted("Camera:");
  ImGui::SetNextItemWidth(kComboWidth);
  int cam = v.camera;
  if (ImGui::BeginCombo("##camera", v.cameraName(cam).c_str())) {
    for (int i = 0; i < v.cameraCount; ++i)
      if (ImGui::Selectable(v.cameraName(i).c_str(), i == cam)) cam = i;
    ImGui::EndCombo();
  }
  o->camera = cam;
  ImGui::Checkbox("Clear with Pixel Shader", &o->psClear);
  ImGui::Checkbox("Dynamic Resolution", &o->dynamicResolution);
  ImGui::BeginDisabled(!m_Widgets.superSampling);
  ImGui::Checkbox("Allow Super Sampling", &o->superSampling);
  ImGui::EndDisabled();
  ImGui::BeginDisabled(!m_Widgets.aspectLock);
  ImGui::Checkbox("Aspect Ratio Lock", &o->aspectLock);
  ImGui::EndDisabled();
}

// The texts show the applied scale (as of the last statistics update); the
// sliders hold the wanted percentages. True when a slider moved.
bool GuiPanel::ScaleSliders(const GuiView& v, Options* o) {
  const bool ss = v.options->superSampling;
  int x = ClampToSlider(m_Sliders.x, ss), y = ClampToSlider(m_Sliders.y, ss);
  bool moved = false;
  auto slider = [&](const char* id, int* value) {
    ImGui::SetNextItemWidth(120.0f);
    ImGui::BeginDisabled(!m_Widgets.sliders);
    const bool changed = ImGui::SliderInt(id, value, kSliderMin, SliderMax(ss), "");
    ImGui::EndDisabled();
    return changed;
  };
  ImGui::Text("Resolution Scale X %%: %d", ScalePercent(v.stats->scaleX));
  if (slider("##scalex", &x)) {
    m_Sliders = MoveSliderX(m_Sliders, x, o->aspectLock);
    moved = true;
  }
  ImGui::Text("Resolution Scale Y %%: %d", ScalePercent(v.stats->scaleY));
  if (slider("##scaley", &y)) {
    m_Sliders = MoveSliderY(m_Sliders, y, o->aspectLock);
    moved = true;
  }
  o->scaleX = moved ? ScaleFromPercent(m_Sliders.x) : v.scaleX;
  o->scaleY = moved ? ScaleFromPercent(m_Sliders.y) : v.scaleY;
  return moved;
}

void GuiPanel::FilterAndControl(Options* o) {
  ImGui::BeginDisabled(!m_Widgets.filter);
  EnumCombo("Filter:", "##filter", &o->filter, FilterName);
  ImGui::EndDisabled();
  // Hidden outside the TAA filters; its place stays, as in the original's fixed layout.
  if (m_Widgets.symmetricTAA) ImGui::Checkbox("Symmetric TAA", &o->symmetricTAA);
  else ImGui::Dummy(ImVec2(1.0f, ImGui::GetFrameHeight()));
  ImGui::BeginDisabled(!m_Widgets.control);
  EnumCombo("Resolution Control:", "##control", &o->control, ControlModeName);
  ImGui::EndDisabled();
}

// Port additions, below everything of the original's: the control law and
// one checkbox per fix of FixTable(), all off by default.
void GuiPanel::PortSection(Options* o) {
  ImGui::Separator();
  ImGui::BeginDisabled(!m_Widgets.control);
  EnumCombo("Control law (port):", "##law", &o->law, ControlLawName);
  ImGui::EndDisabled();
  UpscaleSection(o);
  DeferredSection(o);
  TessellationSection(o);
  if (ImGui::CollapsingHeader("Port fixes")) {
    for (const FixToggle& t : FixToggles(o->fixes)) {
      bool on = t.on;
      if (ImGui::Checkbox(t.name, &on)) o->fixes.Set(t.fix, on);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.help);
    }
  }
}

// The original's RenderText: yellow lines at the top left, 20 px apart, and
// the help block at 70 % of the height, 15 px per line.
void GuiPanel::Text(const GuiView& v) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImU32 yellow = IM_COL32(255, 255, 0, 255);
  StatusInfo s;
  s.fps = v.dxutFps;
  s.vsync = v.vsync;
  s.width = v.backBufferW;
  s.height = v.backBufferH;
  s.format = v.backBufferFormat;
  s.software = v.softwareAdapter;
  s.adapter = v.adapter;
  float y = 0.0f;
  for (const std::string& line : StatusLines(s)) {
    draw->AddText(ImVec2(2.0f, y), yellow, line.c_str());
    y += 20.0f;
  }
  if (!showHelp) {
    draw->AddText(ImVec2(2.0f, y), yellow, kHelpPrompt);
    y += 20.0f;
  } else {
    float hy = std::floor(float(v.backBufferH) * 0.7f);
    for (const std::string& line : HelpLines(v.options->fixes)) {
      draw->AddText(ImVec2(10.0f, hy), yellow, line.c_str());
      hy += 15.0f;
    }
  }
  if (!v.lastMessage.empty()) {
    // Port addition: the F4 reload result (the original shows compile errors in a message box).
    std::string shown, line;
    std::istringstream lines(v.lastMessage);
    for (int n = 0; n < 6 && std::getline(lines, line); ++n) shown += (n ? "\n" : "") + line.substr(0, 160);
    draw->AddText(ImVec2(2.0f, y), IM_COL32(255, 160, 160, 255), shown.c_str());
  }
}

}  // namespace drr
