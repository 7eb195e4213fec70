#include "GuiLogic.h"
#include "OptionTable.h"

#include <algorithm>
#include <cstdio>

namespace drr {

namespace {
bool ManualSliders(const Options& o) { return o.dynamicResolution && o.control == ControlMode::Manual; }

std::string Format(const char* fmt, double value) {
  char text[96];
  std::snprintf(text, sizeof text, fmt, value);
  return text;
}
}  // namespace

PanelWidgets InitialWidgets(const Options& o) {
  PanelWidgets w;
  w.filter = w.superSampling = w.aspectLock = w.control = o.dynamicResolution;
  w.sliders = ManualSliders(o);
  w.symmetricTAA = IsTAA(o.filter);
  return w;
}

PanelWidgets UpdateWidgets(PanelWidgets w, const Options& before, const Options& after) {
  // One handler per changed control, in the original's order of cases.
  if (after.dynamicResolution != before.dynamicResolution) {
    w.filter = w.superSampling = w.aspectLock = w.control = after.dynamicResolution;
    w.sliders = after.dynamicResolution;
  }
  if (after.filter != before.filter) w.symmetricTAA = IsTAA(after.filter);
  if (after.control != before.control) w.sliders = ManualSliders(after);
  if (after.fixes.Has(Fix::GuiSliderState)) w.sliders = ManualSliders(after);
  return w;
}

GuiSlider SliderOf(const OptionRow& row) {
  GuiSlider s;
  s.lo = float(row.lo);
  s.hi = float(row.hi);
  if (row.format) s.format = row.format;
  s.logarithmic = row.lo > 0 && row.hi >= 100 * row.lo;
  return s;
}

int SliderMax(bool superSampling) { return superSampling ? 200 : 100; }

int ClampToSlider(int percent, bool superSampling) {
  return std::clamp(percent, kSliderMin, SliderMax(superSampling));
}

int ScalePercent(float scale) {
  const float percent = 100.0f * scale;
  return percent > 0.0f ? int(percent) : 0;  // truncation, as the original's (UINT) cast
}

SliderPair MoveSliderX(SliderPair s, int x, bool aspectLock) {
  s.x = x;
  if (aspectLock) s.y = x;
  return s;
}

SliderPair MoveSliderY(SliderPair s, int y, bool aspectLock) {
  s.y = y;
  if (aspectLock) s.x = y;
  return s;
}

std::vector<std::string> TimingLines(const TimingStats& t) {
  const double vsyncMs = t.refreshHz > 0 ? 1000.0 / t.refreshHz : 0.0;
  return {Format("Frame Time (ms): %.2f", t.frameMs), Format("Clear Time (ms): %.2f", t.clearMs),
          Format("Scene Time (ms): %.2f", t.sceneMs), Format("PostP Time (ms): %.2f", t.postPMs),
          Format("Scale Time (ms): %.2f", t.scaleMs), Format("VSync Time (ms): %.2f", vsyncMs)};
}

std::vector<std::string> StatusLines(const StatusInfo& s) {
  // DXUT's frame statistics and device statistics. The port draws through
  // Vulkan, so the API named is Vulkan; a CPU rasteriser is a third-party
  // software driver (DXUT prints its type alone).
  char line[512];
  const std::string fps = Format("%0.2f fps ", s.fps);
  std::snprintf(line, sizeof line, "Vulkan %sVsync %s (%ux%u), %s (MS1, Q0)", fps.c_str(), s.vsync ? "on" : "off",
                s.width, s.height, s.format.c_str());
  const std::string device = s.software ? std::string("SOFTWARE") : "HARDWARE: " + s.adapter;
  return {line, device};
}

std::vector<std::string> RecordingLines(const RecordingInfo& r) {
  std::string draws;
  for (uint32_t n : r.drawsPerThread) draws += (draws.empty() ? "" : " + ") + std::to_string(n);
  const size_t threads = r.drawsPerThread.size();
  return {"Threads: " + std::to_string(threads) + (r.requested == 0 ? " (auto)" : "") +
              (threads == 1 ? ", immediate context" : ", deferred contexts"),
          "Draws per thread: " + (draws.empty() ? std::string("-") : draws),
          Format("Scene recording CPU: %.3f ms", r.recordMs)};
}

std::vector<std::string> HelpLines(const FixSet& fixes) {
  const bool fixed = fixes.Has(Fix::HelpText);
  std::vector<std::string> lines = {"Controls:", "Fullscreen: F2"};
  if (fixed) {
    lines.push_back("Reload shaders: F4");
    lines.push_back("Zoom box centre: Right Mouse Button");
  } else {
    lines.push_back("Change device: F3");
    lines.push_back("Toggle warp: F4");
  }
  for (const char* l : {"Toggle GUI: F10", "Toggle Demo Text: F11", "Camera Controls:",
                        "    To Activate Camera Controls Select First Person Camera:",
                        "    Rotate Camera: Left Mouse Button", "    Movement: WASD Keys", "Hide Help: F1", "Quit: ESC"})
    lines.push_back(l);
  return lines;
}

std::vector<FixToggle> FixToggles(const FixSet& fixes) {
  std::vector<FixToggle> out;
  for (const FixInfo& f : FixTable()) out.push_back({f.fix, f.name, f.help, fixes.Has(f.fix)});
  return out;
}

}  // namespace drr
