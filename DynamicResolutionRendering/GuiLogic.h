// The GUI's decisions, without ImGui or a GPU, so they can be tested on the
// CPU: which widgets of the panel are enabled or shown (the original's InitApp
// and OnGUIEvent), the scale sliders and their percentages, DXUT's
// once-per-second FPS figure, and the lines of the original's RenderText.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "Options.h"

namespace drr {

struct OptionRow;

// Enabled (or, for Symmetric TAA, shown) widgets of the panel. The rest of
// the original's widgets are always enabled.
struct PanelWidgets {
  bool filter = true, superSampling = true, aspectLock = true, control = true;
  bool sliders = true;
  bool symmetricTAA = true;  // shown only for the TAA filters
  bool operator==(const PanelWidgets&) const = default;
};

// As the original's InitApp sets them for these options.
PanelWidgets InitialWidgets(const Options& o);
// After the user changed `before` into `after`, as the original's OnGUIEvent
// handlers do. The original's Dynamic Resolution handler enables the sliders
// whenever dynamic resolution is on, whatever the control mode (a defect:
// the controller then overwrites them); fix gui-slider-state keeps them
// enabled only with dynamic resolution on and Manual control.
PanelWidgets UpdateWidgets(PanelWidgets w, const Options& before, const Options& after);

// The slider of a settings row (OptionTable.h): the row's range and format;
// logarithmic when the range spans two decades or more (pixels per edge 1..256).
struct GuiSlider {
  float lo = 0, hi = 1;
  const char* format = "%.2f";
  bool logarithmic = false;
};
GuiSlider SliderOf(const OptionRow& row);

// The scale sliders: integer percentages 1..100, 1..200 with super sampling.
constexpr int kSliderMin = 1;
int SliderMax(bool superSampling);
int ClampToSlider(int percent, bool superSampling);  // what the slider shows
// The original's (UINT)(100 * scale): the percentage a scale shows as.
int ScalePercent(float scale);
inline float ScaleFromPercent(int percent) { return float(percent) / 100.0f; }

// The two sliders' values (the original's g_ResolutionScaleX/Y). With the
// aspect lock on, moving either slider moves the other to the same value.
struct SliderPair {
  int x = 100, y = 100;
  bool operator==(const SliderPair&) const = default;
};
SliderPair MoveSliderX(SliderPair s, int x, bool aspectLock);
SliderPair MoveSliderY(SliderPair s, int y, bool aspectLock);

// The panel's timing lines (the original's UpdateStats texts), in order.
struct TimingStats {
  double frameMs = 0, clearMs = 0, sceneMs = 0, postPMs = 0, scaleMs = 0;
  double refreshHz = 60.0;  // the VSync line shows 1000 / refresh, whatever the control mode
};
std::vector<std::string> TimingLines(const TimingStats& t);

// What the original's RenderText prints at the top left.
struct StatusInfo {
  double fps = 0.0;
  bool vsync = true;
  uint32_t width = 0, height = 0;
  std::string format;   // back-buffer format, e.g. R8G8B8A8_UNORM_SRGB
  bool software = false;  // a CPU rasteriser
  std::string adapter;
};
// Line 1: the API, the FPS, vsync, size and format; line 2: the device.
std::vector<std::string> StatusLines(const StatusInfo& s);
constexpr const char* kHelpPrompt = "Press F1 For Help";
// The help block (F1). The original's lists F3 (a device dialog the port does
// not have) and calls F4 "Toggle warp" (it reloads the shaders); fix
// help-text lists the port's keys instead.
std::vector<std::string> HelpLines(const FixSet& fixes);

// The "Recording threads (port)" section (Docs/Threads.md): what --threads
// asked for, the threads that recorded the last frame's scene and the draws
// each recorded, and that recording's CPU time.
struct RecordingInfo {
  int requested = 0;  // Options::threads, 0 = automatic
  std::vector<uint32_t> drawsPerThread;
  double recordMs = 0.0;
};
std::vector<std::string> RecordingLines(const RecordingInfo& r);

// Where the panel was drawn in the last frame that showed it, in back-buffer
// pixels (x0, y0, x1, y1): the panel's visible rectangle and the header of
// its last section (the report's "gui" object; the window test reads it).
struct GuiLayout {
  std::array<float, 4> panel{0, 0, 0, 0}, lastHeader{0, 0, 0, 0};
  std::string lastHeaderTitle;
};

// The "Port fixes" section: one checkbox per row of FixTable(), in order.
struct FixToggle {
  Fix fix;
  const char* name;
  const char* help;
  bool on;
};
std::vector<FixToggle> FixToggles(const FixSet& fixes);

}  // namespace drr
