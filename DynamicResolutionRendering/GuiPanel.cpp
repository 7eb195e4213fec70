#include "GuiPanel.h"
#include "OptionTable.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>
#include <string>

namespace drr {

namespace {
constexpr float kPanelWidth = 220.0f;
constexpr float kComboWidth = 170.0f;  // the original's combo boxes
constexpr float kPanelTop = 30.0f, kPanelMargin = 10.0f;

const OptionRow& RowOf(const OptionField& field) { return *FindOptionOf(field); }

// A combo over a row's enum, labelled by a static text above it as the original's.
bool RowCombo(const OptionRow& row, Options* o) {
  ImGui::TextUnformatted(row.label);
  ImGui::SetNextItemWidth(kComboWidth);
  const int current = int(FieldNumber(row, *o));
  int chosen = current;
  if (ImGui::BeginCombo((std::string("##") + row.name).c_str(), row.choices.gui(current))) {
    for (int i = 0; i < row.choices.count; ++i)
      if (ImGui::Selectable(row.choices.gui(i), i == current)) chosen = i;
    ImGui::EndCombo();
  }
  if (chosen != current) SetFieldNumber(row, o, chosen);
  return chosen != current;
}

// The widget of a row (not a Custom one): its label, kind and range from the row.
bool RowWidget(const OptionRow& row, Options* o, bool enabled = true) {
  ImGui::BeginDisabled(!enabled || (row.enabled && !row.enabled(*o)));
  bool changed = false;
  const GuiSlider slider = SliderOf(row);
  const ImGuiSliderFlags flags =
      ImGuiSliderFlags_AlwaysClamp | (slider.logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
  if (row.widget == Widget::Check) {
    bool on = FieldNumber(row, *o) != 0.0;
    changed = ImGui::Checkbox(row.label, &on);
    if (changed) SetFieldNumber(row, o, on);
  } else if (row.widget == Widget::SliderInt) {
    int v = int(FieldNumber(row, *o));
    ImGui::SetNextItemWidth(kComboWidth);
    changed = ImGui::SliderInt(row.label, &v, int(slider.lo), int(slider.hi), "%d", flags);
    if (changed) SetFieldNumber(row, o, v);
  } else if (row.widget == Widget::SliderFloat) {
    float v = float(FieldNumber(row, *o));
    ImGui::SetNextItemWidth(kComboWidth);
    changed = ImGui::SliderFloat(row.label, &v, slider.lo, slider.hi, slider.format, flags);
    if (changed) SetFieldNumber(row, o, v);
  } else if (row.widget == Widget::Combo) {
    changed = RowCombo(row, o);
  }
  ImGui::EndDisabled();
  return changed;
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

// The panel: the original's HUD buttons, then its sample UI in its order,
// then the port's sections (one per group of OptionTable.h with a GUI
// title), collapsed by default. The panel is at most the window's height
// less its margins; taller (a section opened in a small window), it scrolls.
void GuiPanel::Panel(const GuiView& v) {
  const float maxHeight = std::max(kPanelMargin, float(v.backBufferH) - kPanelTop - kPanelMargin);
  ImGui::SetNextWindowPos(ImVec2(float(v.backBufferW) - kPanelWidth - kPanelMargin, kPanelTop), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(kPanelWidth, 0.0f), ImVec2(kPanelWidth, maxHeight));
  // Rows 3 px apart (ImGui's default is 4) and the timing lines packed as the
  // original's 12-px statistics, so that the panel with its sections closed
  // fits a 1280x720 window.
  const ImVec2 spacing = ImGui::GetStyle().ItemSpacing;
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(spacing.x, 3.0f));
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
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(spacing.x, 0.0f));
  for (const std::string& line : TimingLines(v.stats->timing))
    ImGui::TextUnformatted(line.c_str());
  ImGui::PopStyleVar();
  PortSections(v, &o);
  const ImVec2 size = ImGui::GetWindowSize();
  m_Layout.panel = {top.x, top.y, top.x + size.x, top.y + size.y};
  ImGui::End();
  ImGui::PopStyleVar();
  if (sliderMoved || SettingsDiffer(o, *v.options)) v.apply(o);
}

// One collapsing section per group that has a GUI title: its rows' widgets,
// in the table's order.
void GuiPanel::PortSections(const GuiView& v, Options* o) {
  ImGui::Separator();
  for (const OptionGroup& group : OptionGroups()) {
    if (!group.heading->label) continue;
    const bool open = ImGui::CollapsingHeader(group.heading->label);
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    m_Layout.lastHeader = {min.x, min.y, max.x, max.y};
    m_Layout.lastHeaderTitle = group.heading->label;
    if (!open) continue;
    for (const OptionRow& row : group.rows) {
      if (row.widget == Widget::None || row.original) continue;
      if (row.widget == Widget::Custom) CustomWidget(row, o);
      else RowWidget(row, o);
      if (&row == &RowOf(&Options::threads))
        for (const std::string& line : RecordingLines(v.recording)) ImGui::TextUnformatted(line.c_str());
    }
  }
}

// The rows whose widget is not one value on one control.
void GuiPanel::CustomWidget(const OptionRow& row, Options* o) {
  if (&row == &RowOf(&Options::upscaleQuality)) {
    // r.Upscale.Quality and the temporal upsample choose the filter.
    const ScreenPercentageRange& range = ScreenPercentageRangeOf(o->scaleX);
    ImGui::TextWrapped("%.0f %%: %s", o->scaleX * 100.0, range.use);
    const int current = int(o->filter) - int(Filter::UpscaleNearest);
    int quality = current >= 0 && current < kUpscaleQualities ? current : -1;
    ImGui::SetNextItemWidth(kComboWidth);
    if (ImGui::SliderInt(row.label, &quality, int(row.lo), int(row.hi), quality < 0 ? "-" : "%d"))
      o->filter = UpscaleQualityFilter(std::clamp(quality, int(row.lo), int(row.hi)));
  } else if (&row == &RowOf(&Options::temporalUpsampling)) {
    bool taau = IsTemporalUpsample(o->filter);
    if (ImGui::Checkbox(row.label, &taau)) o->filter = taau ? Filter::TAAU : UpscaleQualityFilter(3);
  } else if (&row == &RowOf(&Options::fixes)) {
    for (const FixToggle& t : FixToggles(o->fixes)) {
      bool on = t.on;
      if (ImGui::Checkbox(t.name, &on)) o->fixes.Set(t.fix, on);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.help);
    }
  }
}

void GuiPanel::Buttons() {
  // The original's "Change device (F3)" opens DXUT's device dialog, which the port does not have.
  const ImVec2 size(-FLT_MIN, 0.0f);  // the panel's width, less a scrollbar when there is one
  if (ImGui::Button("Fullscreen (F2)", size)) m_Actions.toggleFullscreen = true;
  if (ImGui::Button("Reload Shaders (F4)", size)) m_Actions.reloadShaders = true;
  ImGui::Spacing();
}

// The original's toggles and camera combo, in its order; labels from the rows.
void GuiPanel::Toggles(const GuiView& v, Options* o) {
  RowWidget(RowOf(&Options::pause), o);
  RowWidget(RowOf(&Options::showCameras), o);
  RowWidget(RowOf(&Options::motionBlur), o);
  RowWidget(RowOf(&Options::zoom), o);
  ImGui::TextUnformatted(RowOf(&Options::camera).label);
  ImGui::SetNextItemWidth(kComboWidth);
  int cam = v.camera;
  if (ImGui::BeginCombo("##camera", v.cameraName(cam).c_str())) {
    for (int i = 0; i < v.cameraCount; ++i)
      if (ImGui::Selectable(v.cameraName(i).c_str(), i == cam)) cam = i;
    ImGui::EndCombo();
  }
  o->camera = cam;
  RowWidget(RowOf(&Options::psClear), o);
  RowWidget(RowOf(&Options::dynamicResolution), o);
  RowWidget(RowOf(&Options::superSampling), o, m_Widgets.superSampling);
  RowWidget(RowOf(&Options::aspectLock), o, m_Widgets.aspectLock);
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
  RowWidget(RowOf(&Options::filter), o, m_Widgets.filter);
  // Hidden outside the TAA filters; its place stays, as in the original's fixed layout.
  if (m_Widgets.symmetricTAA) RowWidget(RowOf(&Options::symmetricTAA), o);
  else ImGui::Dummy(ImVec2(1.0f, ImGui::GetFrameHeight()));
  RowWidget(RowOf(&Options::control), o, m_Widgets.control);
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
