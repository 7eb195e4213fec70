// The rows of OptionTable.h, groups in the order of the help text and the GUI.
#include "OptionTable.h"
#include "scene/RecordingThreads.h"

#include <initializer_list>
#include <type_traits>
#include <vector>

namespace drr {
namespace {

using K = OptionKind;

constexpr OptionRow Heading(const char* help, const char* guiSection = nullptr) {
  return {.name = help, .kind = K::Heading, .label = guiSection};
}
constexpr OptionRow Flag(const char* name, bool Options::*field, bool value, const char* help) {
  return {.name = name, .kind = K::Flag, .help = help, .field = field, .flagValue = value};
}
constexpr OptionRow Int(const char* name, const char* metavar, OptionField field, double lo, double hi,
                        const char* help = nullptr) {
  return {.name = name, .metavar = metavar, .kind = K::Integer, .help = help, .field = field, .lo = lo, .hi = hi};
}
constexpr OptionRow Number(const char* name, const char* metavar, double Options::*field, double lo, double hi,
                           const char* help) {
  return {.name = name, .metavar = metavar, .kind = K::Number, .help = help, .field = field, .lo = lo, .hi = hi};
}
constexpr OptionRow Path(const char* name, const char* metavar, std::string Options::*field, const char* help) {
  return {.name = name, .metavar = metavar, .kind = K::Path, .help = help, .field = field};
}
constexpr OptionRow Choice(const char* name, const char* metavar, OptionField field, Choices choices,
                           const char* help, bool Options::*given = nullptr) {
  return {.name = name, .metavar = metavar, .kind = K::Choice, .help = help, .field = field,
          .choices = choices, .given = given};
}
constexpr OptionRow Scale(const char* name, int axes, OptionField field, const char* help = nullptr) {
  return {.name = name, .metavar = "S", .kind = K::Scale, .help = help, .field = field, .axes = axes,
          .given = &Options::scaleGiven};
}

bool Dynamic(const Options& o) { return o.dynamicResolution; }
bool Deferred(const Options& o) { return o.renderer == Renderer::Deferred; }
bool Tessellating(const Options& o) { return o.tessellation; }

// clang-format off
const OptionRow kRows[] = {
    Heading("Window and run"),
    {.name = "--help", .kind = K::Help, .help = "this text", .alias = "-h"},
    Flag("--headless", &Options::headless, true, "no window (default when there is no display)").Json("headless"),
    Int("--width", "W", &Options::width, 1, 16384, "back buffer size (default 1280x720, {range})").Json("width"),
    Int("--height", "H", &Options::height, 1, 16384).Json("height"),
    Int("--frames", "N", &Options::frames, 0, 1e9,
        "frames to render (default: 300 headless, windowed until closed)").Json("frames"),
    Flag("--fullscreen", &Options::fullscreen, true, "start fullscreen (windowed mode)"),
    Flag("--no-vsync", &Options::vsync, false, "present without waiting for vertical sync").Json("vsync"),
    Number("--pace-hz", "HZ", &Options::paceHz, 0, 1000,
           "headless only: present at this refresh rate as VSync would (sleep to\n"
           "the next period; frame times whole periods); also the controller's\n"
           "rate unless --refresh is given. 0 off (default {default}, {range})").Json("pace_hz"),
    Flag("--no-gui", &Options::gui, false, "hide the GUI").Json("gui"),
    Flag("--pause", &Options::pause, true, "start paused").Json("pause").Gui(Widget::Check, "Paused (P)").Original(),
    Number("--time", "T", &Options::time, 0, 1e7, "fixed animation time in seconds (reproducible frames)").Json("time"),
    Number("--fixed-dt", "DT", &Options::fixedDt, 0, 10, "animation advances DT seconds per frame ({range})")
        .Json("fixed_dt"),

    Heading("Scene"),
    Path("--scene", "PATH", &Options::scene, "scene description or model (default: the build's Arena)").Json("scene"),
    Int("--camera", "N", &Options::camera, 0, 1000, "0 first person, 1.. the scene's cameras (default 1)")
        .Json("camera").Gui(Widget::Custom, "Camera:").Original(),
    Flag("--show-cameras", &Options::showCameras, true, "draw the camera models")
        .Gui(Widget::Check, "Show Cameras").Original(),
    Int("--anisotropy", "N", &Options::anisotropy, 0, 16,
        "scene sampler: 0 auto (x16 on GPUs, trilinear on CPU\n"
        "rasterisers such as lavapipe), 1 trilinear, 2..16 (default {default})").Json("anisotropy"),
    Path("--shader-dir", "DIR", &Options::shaderDir, "compiled shaders (default: the build's, or DRR_SHADER_DIR)"),

    Heading("Resolution and its control", "Resolution control (port)"),
    Scale("--scale", 3, {},
          "resolution scale of both axes, fraction (default 1.0);\n"
          "range [0.01, 1], [0.01, 2] with --supersampling; implies\n"
          "--control manual unless --control is given"),
    Scale("--scale-x", 1, &Options::scaleX, "one axis (turns the aspect-ratio lock off)").Json("scale_x"),
    Scale("--scale-y", 2, &Options::scaleY).Json("scale_y"),
    Flag("--no-dynamic-resolution", &Options::dynamicResolution, false,
         "render at back-buffer size (full-resolution path)")
        .Json("dynamic_resolution").Gui(Widget::Check, "Dynamic Resolution").Original(),
    Flag("--supersampling", &Options::superSampling, true, "allow super sampling (2x render targets)")
        .Json("supersampling").Gui(Widget::Check, "Allow Super Sampling").Original(),
    OptionRow{.kind = K::GuiOnly, .field = &Options::aspectLock}.Gui(Widget::Check, "Aspect Ratio Lock").Original(),
    {.name = "--preset", .metavar = "NAME", .kind = K::Preset,
     .help = "a named system as a set of the settings here, applied where\n"
             "it stands (options after it override it); see below"},
    Choice("--control", "MODE", &Options::control,
           ChoicesOf<ControlMode, ControlModeOption, ControlModeName>("mode"), "{choices} (default {default})",
           &Options::controlGiven)
        .Json("control").Gui(Widget::Combo, "Resolution Control:").Original(),
    Choice("--law", "LAW", &Options::law, ChoicesOf<ControlLaw, ControlLawOption, ControlLawName>("law"),
           "resolution control law of the vsync modes: {choices}\n"
           "(default {default}: the original's S' = S (1 + k (1 - t/T)) on the\n"
           "10-frame GPU average; robust and ue-style get per-frame GPU times)")
        .Json("law").Gui(Widget::Combo, "Control law:").EnabledIf(Dynamic),
    Number("--refresh", "HZ", &Options::refresh, 1, 1000,
           "controller target rate (default: the monitor's, 60 headless; {range})").Json("refresh"),

    Heading("Filter and upscaling (Docs/Upscaling.md)", "Upscaling (port)"),
    Choice("--filter", "NAME", &Options::filter, ChoicesOf<Filter, FilterOption, FilterName>("filter"),
           "{choices} (default {default})")
        .Json("filter").Gui(Widget::Combo, "Filter:").Original(),
    Flag("--symmetric-taa", &Options::symmetricTAA, true, "jitter -0.25/+0.25 px instead of 0/0.5 px")
        .Json("symmetric_taa").Gui(Widget::Check, "Symmetric TAA").Original(),
    Int("--upscale-quality", "Q", &Options::upscaleQuality, 0, 5,
        "primary spatial upscale, r.Upscale.Quality in the engine's\n"
        "numbering 0..5 (its documentation's 1..6): 0 nearest,\n"
        "1 bilinear, 2 directional blur + unsharp mask, 3 Catmull-Rom\n"
        "(5 taps, their default), 4 Lanczos 3, 5 Gaussian unsharp mask;\n"
        "sets --filter upscale-*")
        .Gui(Widget::Custom, "r.Upscale.Quality"),
    Flag("--temporal-upsampling", &Options::temporalUpsampling, true,
         "temporal upsample (r.TemporalAA.Upsampling 1): --filter taau;\n"
         "wins over --upscale-quality")
        .Gui(Widget::Custom, "Temporal Upsample"),
    Choice("--upscale-shader", "KIND", &Options::upscaleShader,
           ChoicesOf<UpscaleShader, UpscaleShaderOption, UpscaleShaderName>("upscale shader"),
           "the port's upscalers (TAAU, r.Upscale.Quality, edge-\n"
           "adaptive, secondary) as {choices} shaders (default\n"
           "{default}: compute on GPUs, pixel on CPU rasterisers;\n"
           "pixel, with a notice, where the device has no storage\n"
           "images); the original's filters stay pixel")
        .Json("upscale_shader").Gui(Widget::Combo, "Upscaler shaders:").EnabledIf(Dynamic),
    Number("--secondary-screen-percentage", "P", &Options::secondaryScreenPercentage, 25, 100,
           "static second spatial upscale after the primary one (or\n"
           "TAAU) and before the GUI, in percent of the back buffer\n"
           "({range}; default {default}: none; 83.33 renders 900p for 1080p)")
        .Json("secondary_screen_percentage").Gui(Widget::SliderFloat, "Secondary %", "%.2f"),
    Flag("--no-auto-mip-bias", &Options::autoMipBias, false,
         "TAAU: no automatic view mip bias (the original's sampler)")
        .Json("auto_mip_bias").Gui(Widget::Check, "Automatic view mip bias"),
    Number("--mip-bias", "B", &Options::mipBias, -4, 4,
           "TAAU: added to its automatic texture mip bias log2(scale)\n({range}, default {default})")
        .Json("mip_bias").Gui(Widget::SliderFloat, "Mip bias", "%.2f"),
    Path("--mip-bias-opt-out", "LIST", &Options::mipBiasOptOut,
         "TAAU: materials (comma-separated) sampled without the view mip bias"),
    Flag("--no-taa-mip-bias", &Options::taaMipBias, false,
         "TAA: the scene's plain sampler instead of the original's\n"
         "MipLODBias -0.5 while TAA is on (an ablation)")
        .Json("taa_mip_bias").Gui(Widget::Check, "TAA mip bias -0.5 (original)"),

    Heading("Post-processing"),
    Flag("--no-motion-blur", &Options::motionBlur, false, "motion blur off (default on)")
        .Json("motion_blur").Gui(Widget::Check, "MotionBlur").Original(),
    Flag("--no-ps-clear", &Options::psClear, false, "clear with the API instead of a pixel shader")
        .Json("ps_clear").Gui(Widget::Check, "Clear with Pixel Shader").Original(),
    Flag("--zoom", &Options::zoom, true, "show the zoom box").Json("zoom").Gui(Widget::Check, "Show zoom box (Z)").Original(),

    Heading("Deferred shading (Docs/Deferred.md)", "Deferred shading (port)"),
    Choice("--renderer", "NAME", &Options::renderer, ChoicesOf<Renderer, RendererOption, RendererName>("renderer"),
           "{choices} (default {default}: the original's path; deferred:\n"
           "G-buffer, SSAO, directional + the scene's point/spot lights)")
        .Json("renderer").Gui(Widget::Combo, "Renderer:"),
    Flag("--no-ssao", &Options::ssao, false, "deferred: no screen-space ambient occlusion")
        .Json("ssao").Gui(Widget::Check, "SSAO").EnabledIf(Deferred),
    Flag("--no-local-lights", &Options::localLights, false,
         "deferred: ignore the scene's LIGHT entries (directional light only)")
        .Gui(Widget::Check, "Scene lights").EnabledIf(Deferred),
    Number("--shadow-scale", "S", &Options::shadowScale, kMinShadowScale, 1,
           "deferred: spot shadow-map scale, fraction of --shadow-map-size\n({range}, default {default})")
        .Json("shadow_scale").Gui(Widget::SliderFloat, "Shadow scale", "%.2f").EnabledIf(Deferred),
    Choice("--shadow-law", "LAW", &Options::shadowLaw,
           ChoicesOf<ShadowLaw, ShadowLawOption, ShadowLawName>("shadow law"),
           "deferred: {choices} (default {default}: the shadow scale times\n"
           "the dynamic resolution scale; fixed: the shadow scale alone)")
        .Json("shadow_law").Gui(Widget::Combo, "Shadow-map law:").EnabledIf(Deferred),
    Int("--shadow-map-size", "N", &Options::shadowMapSize, 64, 4096,
        "deferred: allocated spot shadow-map size in texels ({range},\ndefault {default})")
        .Json("shadow_map_size"),

    Heading("Tessellation (Docs/Tessellation.md)", "Tessellation (port)"),
    Flag("--tessellation", &Options::tessellation, true,
         "screen-space adaptive tessellation of the materials the scene\n"
         "description marks (tessellate=); factors follow the dynamic viewport")
        .Json("tessellation").Gui(Widget::Check, "Adaptive tessellation"),
    Number("--tess-pixels-per-edge", "N", &Options::tessPixelsPerEdge, 1, 256,
           "tessellation detail: target edge length in pixels ({range}, default {default})")
        .Json("tess_pixels_per_edge").Gui(Widget::SliderFloat, "Pixels per edge", "%.1f").EnabledIf(Tessellating),
    Int("--max-tess-factor", "N", &Options::maxTessFactor, 1, 64, "max tessellation factor ({range}, default {default})")
        .Json("max_tess_factor").Gui(Widget::SliderInt, "Max factor").EnabledIf(Tessellating),

    Heading("Port fixes", "Port fixes"),
    {.name = "--fix", .metavar = "LIST", .kind = K::Fixes,
     .help = "port fixes of the original's defects: all, none or names\n"
             "separated by commas (default {default}: the original; see below)",
     .field = &Options::fixes, .json = "fixes", .widget = Widget::Custom, .label = "one checkbox per fix"},

    Heading("Scene recording threads (Docs/Threads.md)", "Recording threads (port)"),
    Int("--threads", "N", &Options::threads, 0, kMaxRecordingThreads,
        "scene recording threads ({range}): 1 the immediate context as the\n"
        "original, 0 auto (a thread per 800 draws, at most one per core and 4),\n"
        "N: the main thread and N-1 workers on deferred contexts; the image\n"
        "is the same (default {default})")
        .Json("threads").Gui(Widget::SliderInt, "Threads (0 auto)"),  // GuiPanel adds the last frame's figures

    Heading("Output"),
    Path("--screenshot", "PATH", &Options::screenshot, "PNG/EXR of the back buffer after the last frame"),
    Flag("--screenshot-no-gui", &Options::screenshotNoGui, true, "the screenshot excludes the GUI"),
    Path("--report", "PATH", &Options::report, "JSON report (options, adapter, GPU times, scales, RT bytes)"),
    Flag("--validation", &Options::validation, true, "Vulkan core + sync validation, layer required; exit code 3 on any message")
        .Json("validation"),
    Flag("--stats", &Options::stats, true, "print the scene statistics and the warnings"),
    Flag("--quiet", &Options::quiet, true, "no warnings on the console (--stats and the report keep them)"),

    Heading("Test aids"),
    Flag("--debug-marker-outside", &Options::debugMarkerOutside, true, "test aid: mark the RT outside the viewport"),
    Flag("--window-test", &Options::windowTest, true,
         "test aid: resize to 1x1, minimise, full screen while minimised,\n"
         "restore, windowed, full screen and back"),
    Flag("--headless-bgra", &Options::headlessBgra, true,
         "test aid: the headless back buffer is BGRA8 sRGB (as many\n"
         "windows' are) instead of RGBA8 sRGB"),
};
// clang-format on

std::vector<OptionGroup> MakeGroups() {
  std::vector<OptionGroup> groups;
  const std::span<const OptionRow> all(kRows);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].kind != K::Heading) continue;
    std::size_t end = i + 1;
    while (end < all.size() && all[end].kind != K::Heading) ++end;
    groups.push_back({&all[i], all.subspan(i + 1, end - i - 1)});
  }
  return groups;
}

// Calls f with the row's field of o (a reference), or does nothing for a row without one.
template <class O, class F>
void VisitField(const OptionRow& row, O& o, F&& f) {
  std::visit(
      [&](auto member) {
        if constexpr (!std::is_same_v<decltype(member), std::monostate>) f(o.*member);
      },
      row.field);
}

// The OpenGL ES 2.0 version of the article (Intel's "Dynamic Resolution
// Rendering on OpenGL ES 2.0"): the scene into a native-size off-screen
// target at viewport (w f, h f), one factor for both axes set by hand; a
// full-screen quad samples it bilinearly with texture coordinates to (f, f),
// not clamped inside the rendered part (the clamp-to-edge sampler only);
// no TAA, no motion blur and so no velocity target; glClear clears the whole
// target; the UI at native resolution (as the port always draws it).
constexpr PresetSetting kGles2[] = {
    {&Options::dynamicResolution, 1},
    {&Options::superSampling, 0},  // the target at native size
    {&Options::aspectLock, 1},
    {&Options::control, double(ControlMode::Manual)},
    {&Options::filter, double(Filter::Bilinear)},
    {&Options::motionBlur, 0},
    {&Options::psClear, 0},
    {&Options::renderer, double(Renderer::Forward)},
    {&Options::secondaryScreenPercentage, 100},
    {&Options::tessellation, 0},
};

FixSet FixesOf(std::initializer_list<Fix> fixes) {
  FixSet set;
  for (Fix f : fixes) set.Set(f, true);
  return set;
}

const OptionPreset kPresets[] = {
    {"gles2",
     "the OpenGL ES 2.0 article's system: bilinear quad to (f, f) without\n"
     "the uv-inset clamp, no TAA, no motion blur (no velocity target), API\n"
     "clear of the whole target, native-size target, manual --scale",
     kGles2, FixesOf({Fix::UvInset})},
};

}  // namespace

std::span<const OptionPreset> OptionPresets() { return kPresets; }

const OptionPreset* FindPreset(std::string_view name) {
  for (const OptionPreset& p : kPresets)
    if (name == p.name) return &p;
  return nullptr;
}

std::span<const OptionRow> OptionRows() { return kRows; }

std::span<const OptionGroup> OptionGroups() {
  static const std::vector<OptionGroup> groups = MakeGroups();
  return groups;
}

const OptionRow* FindOption(std::string_view name) {
  for (const OptionRow& r : kRows)
    if (r.kind != K::Heading && r.name && (name == r.name || (r.alias && name == r.alias))) return &r;
  return nullptr;
}

const OptionRow* FindOptionOf(const OptionField& field) {
  for (const OptionRow& r : kRows)
    if (r.field.index() != 0 && r.field == field) return &r;
  return nullptr;
}

double FieldNumber(const OptionRow& row, const Options& o) {
  double v = 0.0;
  VisitField(row, o, [&](const auto& value) {
    using T = std::remove_cvref_t<decltype(value)>;
    if constexpr (std::is_enum_v<T>) v = static_cast<int>(value);
    else if constexpr (std::is_arithmetic_v<T>) v = static_cast<double>(value);
  });
  return v;
}

void SetFieldNumber(const OptionRow& row, Options* o, double v) {
  VisitField(row, *o, [&](auto& value) {
    using T = std::remove_reference_t<decltype(value)>;
    if constexpr (std::is_enum_v<T>) value = static_cast<T>(static_cast<int>(v));
    else if constexpr (std::is_same_v<T, bool>) value = v != 0.0;
    else if constexpr (std::is_arithmetic_v<T>) value = static_cast<T>(v);
  });
}

bool FieldsDiffer(const OptionRow& row, const Options& a, const Options& b) {
  bool differ = false;
  std::visit(
      [&](auto member) {
        if constexpr (!std::is_same_v<decltype(member), std::monostate>) differ = !(a.*member == b.*member);
      },
      row.field);
  return differ;
}

bool SettingsDiffer(const Options& a, const Options& b) {
  for (const OptionRow& r : kRows)
    if (r.widget != Widget::None && FieldsDiffer(r, a, b)) return true;
  return false;
}

}  // namespace drr
