// The GUI's decisions and the zoom box's geometry on the CPU, against the
// original's InitApp/OnGUIEvent/RenderText and ZoomBox.hlsl numbers.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include <sstream>

#include "Fixes.h"
#include "GuiLogic.h"
#include "OptionTable.h"
#include "ZoomBox.h"

using namespace drr;

namespace {
Options Manual() {
  Options o;
  o.control = ControlMode::Manual;
  return o;
}
}  // namespace

// ---------------------------------------------------------------------------
// Enabled and shown widgets.
TEST(GuiWidgets, InitialStateAsTheOriginal) {
  Options o;  // defaults: dynamic resolution on, TAA, VSync control
  PanelWidgets w = InitialWidgets(o);
  EXPECT_TRUE(w.filter && w.superSampling && w.aspectLock && w.control);
  EXPECT_FALSE(w.sliders) << "sliders need Manual control";
  EXPECT_TRUE(w.symmetricTAA);

  w = InitialWidgets(Manual());
  EXPECT_TRUE(w.sliders);

  o = Manual();
  o.dynamicResolution = false;
  w = InitialWidgets(o);
  EXPECT_FALSE(w.filter || w.superSampling || w.aspectLock || w.control || w.sliders);
  EXPECT_TRUE(w.symmetricTAA) << "visibility follows the filter only";
}

TEST(GuiWidgets, SymmetricTAAShownOnlyForTheTAAFilters) {
  std::set<Filter> shown;
  Options before;
  PanelWidgets w = InitialWidgets(before);
  for (int i = 0; i < int(Filter::Count); ++i) {
    Options after = before;
    after.filter = Filter(i);
    w = UpdateWidgets(w, before, after);
    if (w.symmetricTAA) shown.insert(after.filter);
    EXPECT_EQ(w.symmetricTAA, InitialWidgets(after).symmetricTAA);
    before = after;
  }
  EXPECT_EQ(shown, (std::set<Filter>{Filter::TAA, Filter::TAANoiseOffset, Filter::TAABasic}));
}

TEST(GuiWidgets, ControlModeDecidesTheSliders) {
  Options before;  // VSync
  PanelWidgets w = InitialWidgets(before);
  Options after = before;
  after.control = ControlMode::Manual;
  w = UpdateWidgets(w, before, after);
  EXPECT_TRUE(w.sliders);
  before = after;
  after.control = ControlMode::HalfVSync;
  w = UpdateWidgets(w, before, after);
  EXPECT_FALSE(w.sliders);
}

// The original's Dynamic Resolution handler enables the sliders with dynamic
// resolution, whatever the control mode; fix gui-slider-state changes that
// and nothing else.
TEST(GuiWidgets, DynamicResolutionToggleAndFixGuiSliderState) {
  for (bool fix : {false, true}) {
    Options a;  // VSync control
    a.fixes.Set(Fix::GuiSliderState, fix);
    PanelWidgets w = InitialWidgets(a);
    Options off = a;
    off.dynamicResolution = false;
    w = UpdateWidgets(w, a, off);
    EXPECT_FALSE(w.filter || w.superSampling || w.aspectLock || w.control || w.sliders);
    w = UpdateWidgets(w, off, a);
    EXPECT_TRUE(w.filter && w.superSampling && w.aspectLock && w.control);
    EXPECT_EQ(w.sliders, !fix) << (fix ? "fixed: VSync control keeps the sliders disabled"
                                       : "original: the toggle enables them under VSync control");
    PanelWidgets expected = InitialWidgets(a);
    expected.sliders = !fix;
    EXPECT_EQ(w, expected) << "the fix changes the sliders only";
  }
}

// ---------------------------------------------------------------------------
// Scale sliders.
TEST(GuiSliders, IntegerRangeAsTheOriginal) {
  EXPECT_EQ(kSliderMin, 1);
  EXPECT_EQ(SliderMax(false), 100);
  EXPECT_EQ(SliderMax(true), 200);
  EXPECT_EQ(ClampToSlider(150, false), 100);
  EXPECT_EQ(ClampToSlider(150, true), 150);
  EXPECT_EQ(ClampToSlider(0, true), 1);
  EXPECT_FLOAT_EQ(ScaleFromPercent(71), 0.71f);
  EXPECT_FLOAT_EQ(ScaleFromPercent(200), 2.0f);
}

TEST(GuiSliders, PercentIsTruncatedAsTheOriginalsCast) {
  EXPECT_EQ(ScalePercent(1.0f), 100);
  EXPECT_EQ(ScalePercent(0.709375f), 70);  // 908/1280: the applied scale of 71 %
  EXPECT_EQ(ScalePercent(0.3f), 30);
  EXPECT_EQ(ScalePercent(1.999f), 199);
  EXPECT_EQ(ScalePercent(0.0f), 0);
  // In float, 100 * 0.53f is 52.999996: the original's text shows 52 there too.
  EXPECT_EQ(ScalePercent(ScaleFromPercent(53)), 52);
  EXPECT_EQ(ScalePercent(ScaleFromPercent(50)), 50);
}

TEST(GuiSliders, AspectLockCouplesBothWays) {
  const SliderPair s{40, 60};
  EXPECT_EQ(MoveSliderX(s, 55, false), (SliderPair{55, 60}));
  EXPECT_EQ(MoveSliderY(s, 55, false), (SliderPair{40, 55}));
  EXPECT_EQ(MoveSliderX(s, 55, true), (SliderPair{55, 55}));
  EXPECT_EQ(MoveSliderY(s, 33, true), (SliderPair{33, 33})) << "Y drives X with the lock on";
}

// ---------------------------------------------------------------------------
// Text.
TEST(GuiText, StatusLinesAsDxutsStatistics) {
  StatusInfo s;
  s.fps = 59.987;
  s.width = 1280;
  s.height = 720;
  s.format = "R8G8B8A8_UNORM_SRGB";
  s.adapter = "NVIDIA H100";
  auto lines = StatusLines(s);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "Vulkan 59.99 fps Vsync on (1280x720), R8G8B8A8_UNORM_SRGB (MS1, Q0)");
  EXPECT_EQ(lines[1], "HARDWARE: NVIDIA H100");
  s.vsync = false;
  s.software = true;
  lines = StatusLines(s);
  EXPECT_EQ(lines[0], "Vulkan 59.99 fps Vsync off (1280x720), R8G8B8A8_UNORM_SRGB (MS1, Q0)");
  EXPECT_EQ(lines[1], "SOFTWARE");
  EXPECT_STREQ(kHelpPrompt, "Press F1 For Help");
}

TEST(GuiText, TimingLinesAndVSyncTime) {
  const auto lines = TimingLines({1.234, 0.1, 2.5, 0.333, 0.05, 60.0});
  const std::vector<std::string> expected = {"Frame Time (ms): 1.23", "Clear Time (ms): 0.10", "Scene Time (ms): 2.50",
                                             "PostP Time (ms): 0.33", "Scale Time (ms): 0.05", "VSync Time (ms): 16.67"};
  EXPECT_EQ(lines, expected);
  EXPECT_EQ(TimingLines({0, 0, 0, 0, 0, 144.0}).back(), "VSync Time (ms): 6.94");
}

// Fix help-text changes the two stale lines (and names the zoom centre) only.
TEST(GuiText, HelpLinesAndFixHelpText) {
  const std::vector<std::string> original = HelpLines({});
  const std::vector<std::string> expected = {"Controls:", "Fullscreen: F2", "Change device: F3", "Toggle warp: F4",
                                             "Toggle GUI: F10", "Toggle Demo Text: F11", "Camera Controls:",
                                             "    To Activate Camera Controls Select First Person Camera:",
                                             "    Rotate Camera: Left Mouse Button", "    Movement: WASD Keys",
                                             "Hide Help: F1", "Quit: ESC"};
  EXPECT_EQ(original, expected);
  FixSet fix;
  fix.Set(Fix::HelpText, true);
  std::vector<std::string> fixed = HelpLines(fix);
  ASSERT_EQ(fixed.size(), original.size());
  for (size_t i = 0; i < original.size(); ++i) {
    if (i != 2 && i != 3) {
      EXPECT_EQ(fixed[i], original[i]) << i;
    }
  }
  EXPECT_EQ(fixed[2], "Reload shaders: F4");
  EXPECT_EQ(fixed[3], "Zoom box centre: Right Mouse Button");
  // Other fixes leave the help alone.
  EXPECT_EQ(HelpLines(FixSet::All()), fixed);
  FixSet others = FixSet::All();
  others.Set(Fix::HelpText, false);
  EXPECT_EQ(HelpLines(others), original);
}

TEST(GuiFixes, OneCheckboxPerTableRowAllOff) {
  const auto toggles = FixToggles({});
  ASSERT_EQ(toggles.size(), FixTable().size());
  for (size_t i = 0; i < toggles.size(); ++i) {
    EXPECT_EQ(toggles[i].fix, FixTable()[i].fix);
    EXPECT_STREQ(toggles[i].name, FixTable()[i].name);
    EXPECT_FALSE(toggles[i].on) << toggles[i].name;
  }
  for (const FixToggle& t : FixToggles(FixSet::All())) EXPECT_TRUE(t.on) << t.name;
}

// ---------------------------------------------------------------------------
// The widgets of the settings rows (OptionTable.h).

// A slider's range is its row's, which is the command line's: the ends are
// accepted by the parser and a step beyond them is refused.
TEST(GuiSettings, SlidersTakeTheCommandLinesRange) {
  int sliders = 0;
  for (const OptionRow& row : OptionRows()) {
    if (row.widget != Widget::SliderInt && row.widget != Widget::SliderFloat) continue;
    ++sliders;
    const GuiSlider s = SliderOf(row);
    for (const auto& [value, ok] : {std::pair{double(s.lo), true}, std::pair{double(s.hi), true},
                                    std::pair{double(s.lo) - 0.5, false}, std::pair{double(s.hi) + 0.5, false}}) {
      std::ostringstream text;
      text << value;
      Options o;
      std::string m;
      EXPECT_EQ(ParseCommandLine({row.name, text.str()}, &o, &m) == ParseStatus::Ok, ok)
          << row.label << " " << value << ": " << m;
    }
  }
  EXPECT_GE(sliders, 6);
  // The three that once disagreed with the command line.
  auto slider = [](auto field) { return SliderOf(*FindOptionOf(field)); };
  EXPECT_EQ(slider(&Options::secondaryScreenPercentage).lo, 25.0f);
  EXPECT_EQ(slider(&Options::secondaryScreenPercentage).hi, 100.0f);
  EXPECT_EQ(slider(&Options::mipBias).lo, -4.0f);
  EXPECT_EQ(slider(&Options::mipBias).hi, 4.0f);
  EXPECT_EQ(slider(&Options::tessPixelsPerEdge).hi, 256.0f);
  EXPECT_TRUE(slider(&Options::tessPixelsPerEdge).logarithmic);
  EXPECT_FALSE(slider(&Options::secondaryScreenPercentage).logarithmic);
}

// Change detection covers exactly the settings that have a widget: a change
// of any of them is applied, a change of the others (size, frames, paths) is not.
TEST(GuiSettings, ChangeDetectionFollowsTheWidgetRows) {
  int detected = 0;
  for (const OptionRow& row : OptionRows()) {
    if (row.field.index() == 0) continue;
    Options a, b;
    if (row.kind == OptionKind::Fixes) b.fixes = FixSet::All();
    else if (row.kind == OptionKind::Path) b.*std::get<std::string Options::*>(row.field) = "x";
    else if (row.kind == OptionKind::Choice) SetFieldNumber(row, &b, (int(FieldNumber(row, a)) + 1) % row.choices.count);
    else SetFieldNumber(row, &b, FieldNumber(row, a) == 0 ? 1 : 0);
    ASSERT_TRUE(FieldsDiffer(row, a, b)) << (row.name ? row.name : row.label);
    EXPECT_EQ(SettingsDiffer(a, b), row.widget != Widget::None) << (row.name ? row.name : row.label);
    detected += SettingsDiffer(a, b);
  }
  EXPECT_GE(detected, 25);
}

// The port's sections: one per group with a GUI title, in the table's order,
// each with a widget; the original's widgets are not in them.
TEST(GuiSettings, PortSectionsAreTheGroupsWithAGuiTitle) {
  std::vector<std::string> titles;
  for (const OptionGroup& g : OptionGroups()) {
    if (!g.heading->label) continue;
    titles.push_back(g.heading->label);
    int widgets = 0;
    for (const OptionRow& row : g.rows) widgets += row.widget != Widget::None && !row.original;
    EXPECT_GT(widgets, 0) << titles.back();
  }
  const std::vector<std::string> expected = {"Resolution control (port)", "Upscaling (port)",
                                             "Deferred shading (port)",   "Tessellation (port)",
                                             "Port fixes",                "Recording threads (port)"};
  EXPECT_EQ(titles, expected);
}

// ---------------------------------------------------------------------------
// Zoom box geometry: the original's ZoomBox.hlsl numbers.
TEST(ZoomBoxGeometryTest, OriginalNumbers) {
  EXPECT_FLOAT_EQ(ZoomBoxGeometry::kMagnification, 10.0f);
  const ZoomBoxGeometry g = MakeZoomBoxGeometry(0.5f, 0.5f);
  // First strip vertex (right, bottom), last (left, top).
  EXPECT_FLOAT_EQ(g.quad[0], -0.55f);
  EXPECT_FLOAT_EQ(g.quad[1], -0.2f);
  EXPECT_FLOAT_EQ(g.quad[2], -0.95f);
  EXPECT_FLOAT_EQ(g.quad[3], 0.2f);
  EXPECT_FLOAT_EQ(g.source[0], 0.51f);
  EXPECT_FLOAT_EQ(g.source[1], 0.51f);
  EXPECT_FLOAT_EQ(g.source[2], 0.49f);
  EXPECT_FLOAT_EQ(g.source[3], 0.49f);
  const float frame[12][2] = {{-0.54f, -0.21f}, {-0.54f, 0.21f}, {-0.96f, 0.21f}, {-0.96f, -0.21f},
                              {-0.54f, -0.21f}, {-0.02f, -0.02f}, {-0.02f, 0.02f}, {0.02f, 0.02f},
                              {0.02f, -0.02f},  {-0.02f, -0.02f}, {-0.02f, 0.02f}, {-0.54f, 0.21f}};
  for (int i = 0; i < 12; ++i) {
    EXPECT_NEAR(g.frame[i][0], frame[i][0], 1e-6f) << i;
    EXPECT_NEAR(g.frame[i][1], frame[i][1], 1e-6f) << i;
  }
}

TEST(ZoomBoxGeometryTest, MarkerFramesTheSourceRegion) {
  // In pixels of a W x H back buffer, the marker is the magnified region and
  // the box is 10x that, on both axes, for any centre (no clamping).
  for (float u : {0.0f, 0.13f, 0.5f, 0.97f}) {
    for (float v : {0.0f, 0.42f, 1.0f}) {
      const ZoomBoxGeometry g = MakeZoomBoxGeometry(u, v);
      const float markerU0 = (g.frame[5][0] + 1.0f) * 0.5f, markerU1 = (g.frame[7][0] + 1.0f) * 0.5f;
      const float markerV0 = (1.0f - g.frame[6][1]) * 0.5f, markerV1 = (1.0f - g.frame[5][1]) * 0.5f;
      EXPECT_NEAR(markerU0, g.source[2], 1e-6f);
      EXPECT_NEAR(markerU1, g.source[0], 1e-6f);
      EXPECT_NEAR(markerV0, g.source[3], 1e-6f);
      EXPECT_NEAR(markerV1, g.source[1], 1e-6f);
      const float boxU = (g.quad[0] - g.quad[2]) * 0.5f, boxV = (g.quad[3] - g.quad[1]) * 0.5f;
      EXPECT_NEAR(boxU / (g.source[0] - g.source[2]), 10.0f, 1e-4f);
      EXPECT_NEAR(boxV / (g.source[1] - g.source[3]), 10.0f, 1e-4f);
    }
  }
}

// The recording-threads section: threads, auto or asked, which context, the
// draws of each thread in order and the CPU time.
TEST(GuiText, RecordingLines) {
  RecordingInfo r;
  r.requested = 0;
  r.drawsPerThread = {30, 29};
  r.recordMs = 0.25;
  const std::vector<std::string> two = RecordingLines(r);
  ASSERT_EQ(two.size(), 3u);
  EXPECT_EQ(two[0], "Threads: 2 (auto), deferred contexts");
  EXPECT_EQ(two[1], "Draws per thread: 30 + 29");
  EXPECT_EQ(two[2], "Scene recording CPU: 0.250 ms");
  r.requested = 1;
  r.drawsPerThread = {59};
  EXPECT_EQ(RecordingLines(r)[0], "Threads: 1, immediate context");
  EXPECT_EQ(RecordingLines(r)[1], "Draws per thread: 59");
  r.drawsPerThread.clear();  // before the first frame
  EXPECT_EQ(RecordingLines(r)[1], "Draws per thread: -");
}
