// The sample's command line. One table (kSpecs) lists every option once: its
// name, the kind of value it takes, its help text and the field of Options it
// writes. ParseCommandLine and Usage() both read that table; the values of the
// enum options come from the enums' own name tables (FilterOption in ResolveFilters.cpp,
// ControlModeOption and ControlLawOption in ResolutionController.cpp).
#include "Options.h"
#include "scene/ImportLimits.h"
#include "scene/RecordingThreads.h"

#include "Json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>
#include <optional>
#include <sstream>
#include <type_traits>
#include <variant>

namespace drr {
namespace {

// ------------------------------------------------------------ the option table

enum class Kind {
  Help,
  Flag,     // no value: stores flagValue
  Integer,  // whole number in [lo, hi]
  Number,   // number in [lo, hi]
  Scale,    // number, range checked once --supersampling is known; writes scaleX and/or scaleY
  Path,     // non-empty text
  Choice,   // one of an enum's command-line values
  Fixes,    // all | none | NAME[,NAME...] (Fixes.h)
};

// The values of an enum option, read from the enum's own name table.
struct Choices {
  int count = 0;
  const char* (*option)(int) = nullptr;
  const char* noun = nullptr;  // "unknown <noun> 'x'"
};
template <class Enum, const char* (*Option)(Enum)>
constexpr Choices ChoicesOf(const char* noun) {
  return {static_cast<int>(Enum::Count), [](int i) { return Option(static_cast<Enum>(i)); }, noun};
}

using Field = std::variant<std::monostate, bool Options::*, uint32_t Options::*, int Options::*,
                           int64_t Options::*, double Options::*, std::string Options::*,
                           Filter Options::*, ControlMode Options::*, ControlLaw Options::*,
                           FixSet Options::*, Renderer Options::*, ShadowLaw Options::*>;

struct Spec {
  const char* name;
  const char* metavar = nullptr;   // the value in the help ("--width W"); none for flags
  Kind kind = Kind::Flag;
  const char* help = nullptr;      // nullptr: listed on the line of the entry before. '\n'
                                   // starts a continuation line; {choices} and {range} expand
  Field field{};
  double lo = 0.0, hi = 0.0;       // Integer, Number
  Choices choices{};               // Choice
  bool flagValue = true;           // Flag
  int axes = 0;                    // Scale: 1 x, 2 y, 3 both
  bool Options::*given = nullptr;  // also set to true when the option is given
  const char* alias = nullptr;
};

constexpr Spec Flag(const char* name, bool Options::*field, bool value, const char* help) {
  return {.name = name, .kind = Kind::Flag, .help = help, .field = field, .flagValue = value};
}
constexpr Spec Int(const char* name, const char* metavar, Field field, double lo, double hi,
                   const char* help = nullptr) {
  return {.name = name, .metavar = metavar, .kind = Kind::Integer, .help = help, .field = field, .lo = lo, .hi = hi};
}
constexpr Spec Number(const char* name, const char* metavar, double Options::*field, double lo, double hi,
                      const char* help) {
  return {.name = name, .metavar = metavar, .kind = Kind::Number, .help = help, .field = field, .lo = lo, .hi = hi};
}
constexpr Spec Path(const char* name, const char* metavar, std::string Options::*field, const char* help) {
  return {.name = name, .metavar = metavar, .kind = Kind::Path, .help = help, .field = field};
}
constexpr Spec Choice(const char* name, const char* metavar, Field field, Choices choices, const char* help,
                      bool Options::*given = nullptr) {
  return {.name = name, .metavar = metavar, .kind = Kind::Choice, .help = help, .field = field,
          .choices = choices, .given = given};
}
constexpr Spec Scale(const char* name, int axes, const char* help = nullptr) {
  return {.name = name, .metavar = "S", .kind = Kind::Scale, .help = help, .axes = axes,
          .given = &Options::scaleGiven};
}

// In the order of the help text.
constexpr Spec kSpecs[] = {
    {.name = "--help", .kind = Kind::Help, .help = "this text", .alias = "-h"},
    Flag("--headless", &Options::headless, true, "no window (default when there is no display)"),
    Int("--width", "W", &Options::width, 1, 16384, "back buffer size (default 1280x720, {range})"),
    Int("--height", "H", &Options::height, 1, 16384),
    Int("--frames", "N", &Options::frames, 0, 1e9,
        "frames to render (default: 300 headless, windowed until closed)"),
    Path("--scene", "PATH", &Options::scene, "scene description or model (default: the build's Arena)"),
    Int("--camera", "N", &Options::camera, 0, 1000, "0 first person, 1.. the scene's cameras (default 1)"),
    Choice("--filter", "NAME", &Options::filter, ChoicesOf<Filter, FilterOption>("filter"),
           "{choices} (default taa)"),
    Scale("--scale", 3,
          "resolution scale of both axes, fraction (default 1.0);\n"
          "range [0.01, 1], [0.01, 2] with --supersampling; implies\n"
          "--control manual unless --control is given"),
    Scale("--scale-x", 1, "one axis (turns the aspect-ratio lock off)"),
    Scale("--scale-y", 2),
    Flag("--no-dynamic-resolution", &Options::dynamicResolution, false,
         "render at back-buffer size (full-resolution path)"),
    Flag("--supersampling", &Options::superSampling, true, "allow super sampling (2x render targets)"),
    Choice("--control", "MODE", &Options::control, ChoicesOf<ControlMode, ControlModeOption>("mode"),
           "{choices} (default vsync)", &Options::controlGiven),
    Choice("--law", "LAW", &Options::law, ChoicesOf<ControlLaw, ControlLawOption>("law"),
           "resolution control law of the vsync modes: {choices}\n"
           "(default article: the original's S' = S (1 + k (1 - t/T)) on the\n"
           "10-frame GPU average; robust and ue-style get per-frame GPU times)"),
    Number("--refresh", "HZ", &Options::refresh, 1, 1000,
           "controller target rate (default: the monitor's, 60 headless; {range})"),
    Flag("--no-vsync", &Options::vsync, false, "present without waiting for vertical sync"),
    Flag("--no-motion-blur", &Options::motionBlur, false, "motion blur off (default on)"),
    Flag("--symmetric-taa", &Options::symmetricTAA, true, "jitter -0.25/+0.25 px instead of 0/0.5 px"),
    Flag("--no-ps-clear", &Options::psClear, false, "clear with the API instead of a pixel shader"),
    Flag("--pause", &Options::pause, true, "start paused"),
    Flag("--zoom", &Options::zoom, true, "show the zoom box"),
    Flag("--show-cameras", &Options::showCameras, true, "draw the camera models"),
    Flag("--no-gui", &Options::gui, false, "hide the GUI"),
    Flag("--fullscreen", &Options::fullscreen, true, "start fullscreen (windowed mode)"),
    Path("--screenshot", "PATH", &Options::screenshot, "PNG/EXR of the back buffer after the last frame"),
    Flag("--screenshot-no-gui", &Options::screenshotNoGui, true, "the screenshot excludes the GUI"),
    Path("--report", "PATH", &Options::report, "JSON report (options, adapter, GPU times, scales, RT bytes)"),
    Flag("--validation", &Options::validation, true, "Vulkan core + sync validation; exit code 3 on any message"),
    Flag("--stats", &Options::stats, true, "print the scene statistics and the warnings"),
    Flag("--quiet", &Options::quiet, true, "no warnings on the console (--stats and the report keep them)"),
    Int("--anisotropy", "N", &Options::anisotropy, 0, 16,
        "scene sampler: 0 auto (x16 on GPUs, trilinear on CPU\n"
        "rasterisers such as lavapipe), 1 trilinear, 2..16 (default 0)"),
    Int("--threads", "N", &Options::threads, 0, kMaxRecordingThreads,
        "scene recording threads ({range}): 0 auto (one per core, at\n"
        "most 4), 1 the immediate context as the original, N: the main\n"
        "thread and N-1 workers on deferred contexts, same image (default 0)"),
    Number("--time", "T", &Options::time, 0, 1e7, "fixed animation time in seconds (reproducible frames)"),
    Number("--fixed-dt", "DT", &Options::fixedDt, 0, 10, "animation advances DT seconds per frame ({range})"),
    Path("--shader-dir", "DIR", &Options::shaderDir, "compiled shaders (default: the build's, or DRR_SHADER_DIR)"),
    Flag("--debug-marker-outside", &Options::debugMarkerOutside, true, "test aid: mark the RT outside the viewport"),
    Flag("--window-test", &Options::windowTest, true,
         "test aid: resize to 1x1, minimise, full screen while minimised,\n"
         "restore, windowed, full screen and back"),
    {.name = "--fix", .metavar = "LIST", .kind = Kind::Fixes,
     .help = "port fixes of the original's defects: all, none or names\n"
             "separated by commas (default none: the original; see below)",
     .field = &Options::fixes},
    // Upscaling (Docs/Upscaling.md)
    Int("--upscale-quality", "Q", &Options::upscaleQuality, 0, 5,
        "primary spatial upscale, r.Upscale.Quality in the engine's\n"
        "numbering 0..5 (its documentation's 1..6): 0 nearest,\n"
        "1 bilinear, 2 directional blur + unsharp mask, 3 Catmull-Rom\n"
        "(5 taps, their default), 4 Lanczos 3, 5 Gaussian unsharp mask;\n"
        "sets --filter upscale-*"),
    Flag("--temporal-upsampling", &Options::temporalUpsampling, true,
         "temporal upsample (r.TemporalAA.Upsampling 1): --filter taau;\n"
         "wins over --upscale-quality"),
    Number("--secondary-screen-percentage", "P", &Options::secondaryScreenPercentage, 25, 100,
           "static second spatial upscale after the primary one (or\n"
           "TAAU) and before the GUI, in percent of the back buffer\n"
           "({range}; default 100: none; 83.33 renders 900p for 1080p)"),
    Number("--mip-bias", "B", &Options::mipBias, -4, 4,
           "TAAU: added to its automatic texture mip bias log2(scale)\n({range}, default 0)"),
    Flag("--no-auto-mip-bias", &Options::autoMipBias, false,
         "TAAU: no automatic view mip bias (the original's sampler)"),
    Path("--mip-bias-opt-out", "LIST", &Options::mipBiasOptOut,
         "TAAU: materials (comma-separated) sampled without the view mip bias"),
    Flag("--no-taa-mip-bias", &Options::taaMipBias, false,
         "TAA: the scene's plain sampler instead of the original's\n"
         "MipLODBias -0.5 while TAA is on (an ablation)"),
    // Deferred shading (Docs/Deferred.md)
    Choice("--renderer", "NAME", &Options::renderer, ChoicesOf<Renderer, RendererOption>("renderer"),
           "{choices} (default forward: the original's path; deferred:\n"
           "G-buffer, SSAO, directional + the scene's point/spot lights)"),
    Flag("--no-ssao", &Options::ssao, false, "deferred: no screen-space ambient occlusion"),
    Flag("--no-local-lights", &Options::localLights, false,
         "deferred: ignore the scene's LIGHT entries (directional light only)"),
    Number("--shadow-scale", "S", &Options::shadowScale, 0.125, 1,
           "deferred: spot shadow-map scale, fraction of --shadow-map-size\n({range}, default 1)"),
    Choice("--shadow-law", "LAW", &Options::shadowLaw, ChoicesOf<ShadowLaw, ShadowLawOption>("shadow law"),
           "deferred: {choices} (default main: the shadow scale times\n"
           "the dynamic resolution scale; fixed: the shadow scale alone)"),
    Int("--shadow-map-size", "N", &Options::shadowMapSize, 64, 4096,
        "deferred: allocated spot shadow-map size in texels ({range},\ndefault 1024)"),
    // Tessellation (Docs/Tessellation.md)
    Flag("--tessellation", &Options::tessellation, true,
         "screen-space adaptive tessellation of the materials the scene\n"
         "description marks (tessellate=); factors follow the dynamic viewport"),
    Number("--tess-pixels-per-edge", "N", &Options::tessPixelsPerEdge, 1, 256,
           "tessellation detail: target edge length in pixels ({range}, default 8)"),
    Int("--max-tess-factor", "N", &Options::maxTessFactor, 1, 64, "max tessellation factor ({range}, default 16)"),
};

constexpr double kMinScale = 0.01;
constexpr std::size_t kHelpColumn = 27;  // where the help texts start
constexpr std::size_t kUsageWidth = 100; // a longer line is broken after a '|' of a choice list

const Spec* FindSpec(std::string_view name) {
  for (const Spec& s : kSpecs)
    if (name == s.name || (s.alias && name == s.alias)) return &s;
  return nullptr;
}

std::string Format(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string JoinChoices(const Choices& c, const char* separator) {
  std::string out;
  for (int i = 0; i < c.count; ++i) out += (i ? separator : "") + std::string(c.option(i));
  return out;
}

std::string Allowed(const Spec& s) { return " (allowed: " + JoinChoices(s.choices, ", ") + ")"; }

void Replace(std::string* text, std::string_view key, const std::string& by) {
  if (const std::size_t at = text->find(key); at != std::string::npos) text->replace(at, key.size(), by);
}

// The help of one table line: continuation lines indented to kHelpColumn.
void AppendHelp(std::ostringstream& u, const Spec& s) {
  std::string text = s.help;
  Replace(&text, "{choices}", JoinChoices(s.choices, "|"));
  Replace(&text, "{range}", Format(s.lo) + ".." + Format(s.hi));
  std::string_view rest = text;
  constexpr std::size_t kRoom = kUsageWidth - kHelpColumn;
  for (bool first = true; first || !rest.empty(); first = false) {
    std::size_t end = std::min(rest.find('\n'), rest.size());
    std::size_t skip = end < rest.size() ? 1 : 0;  // the '\n'
    if (const std::size_t bar = rest.rfind('|', kRoom - 1); end > kRoom && bar != std::string_view::npos) {
      end = bar + 1;
      skip = 0;
    }
    u << (first ? "" : std::string(kHelpColumn, ' ')) << rest.substr(0, end) << '\n';
    rest.remove_prefix(std::min(rest.size(), end + skip));
  }
}

std::string Label(const Spec& s) { return s.metavar ? std::string(s.name) + " " + s.metavar : s.name; }

// A decimal number as people and scripts write it, nothing around it: no
// leading or trailing space, no hexadecimal, no inf or nan (std::from_chars
// reads neither spaces nor "0x", and does not depend on the locale).
bool ParseDecimal(std::string_view text, double* out) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

// What --scale, --scale-x and --scale-y asked for; checked once --supersampling is known.
struct ScaleArg {
  std::string name, text;  // the option that set the axis last, and its value as given
  double value = 1.0;
  bool given = false;
};
struct ScaleArgs {
  ScaleArg axis[2];  // x, y
  bool perAxis = false;
};

void Store(Options* r, const Field& field, double number, const std::string& text) {
  std::visit(
      [&](auto member) {
        if constexpr (!std::is_same_v<decltype(member), std::monostate>) {
          using T = std::remove_reference_t<decltype(r->*member)>;
          if constexpr (std::is_same_v<T, std::string>) r->*member = text;
          else if constexpr (std::is_same_v<T, FixSet>) return;  // Apply parses the list
          else if constexpr (std::is_enum_v<T>) r->*member = static_cast<T>(static_cast<int>(number));
          else r->*member = static_cast<T>(number);
        }
      },
      field);
}

// Reads the value of a numeric option into *out; returns the error message, or "".
std::string ReadNumber(const Spec& s, const std::string& name, const std::string& text, double* out) {
  if (!ParseDecimal(text, out)) return "option " + name + ": '" + text + "' is not a number";
  if (s.kind == Kind::Scale) return {};
  const std::string range = "[" + Format(s.lo) + ", " + Format(s.hi) + "]";
  if (*out < s.lo || *out > s.hi) return "option " + name + ": value " + text + " is out of range " + range;
  if (s.kind == Kind::Integer && *out != std::floor(*out))
    return "option " + name + ": '" + text + "' is not an integer; expected an integer in " + range;
  return {};
}

// Applies one option (value: the text after '=' or the next argument, if any).
std::string Apply(const Spec& s, const std::string& name, const std::optional<std::string>& value, Options* r,
                  ScaleArgs* scales) {
  if (s.given) r->*s.given = true;
  if (s.kind == Kind::Flag) {
    Store(r, s.field, s.flagValue, {});
    return {};
  }
  if (s.kind == Kind::Path) {
    if (!value || value->empty()) return "option " + name + " needs a path";
    Store(r, s.field, 0.0, *value);
    return {};
  }
  if (!value) return "option " + name + " needs a value" + (s.kind == Kind::Choice ? Allowed(s) : "");
  if (s.kind == Kind::Fixes) {
    std::string error;
    if (!ParseFixes(*value, &(r->*std::get<FixSet Options::*>(s.field)), &error))
      return "option " + name + ": " + error;
    return {};
  }
  if (s.kind == Kind::Choice) {
    for (int i = 0; i < s.choices.count; ++i)
      if (*value == s.choices.option(i)) {
        Store(r, s.field, i, {});
        return {};
      }
    return "option " + name + ": unknown " + s.choices.noun + " '" + *value + "'" + Allowed(s);
  }
  double number = 0.0;
  if (std::string error = ReadNumber(s, name, *value, &number); !error.empty()) return error;
  if (s.kind != Kind::Scale) {
    Store(r, s.field, number, {});
    return {};
  }
  for (int a = 0; a < 2; ++a)
    if (s.axes & (1 << a)) scales->axis[a] = {name, *value, number, true};
  scales->perAxis |= s.axes != 3;
  return {};
}

// The scale range depends on --supersampling; a scale implies manual control.
std::string FinishScales(const ScaleArgs& scales, Options* r) {
  if (!r->scaleGiven) return {};
  const float hi = r->MaxScale();
  float* const out[2] = {&r->scaleX, &r->scaleY};
  for (int a = 0; a < 2; ++a) {
    const ScaleArg& arg = scales.axis[a];
    if (!arg.given) continue;
    const float v = static_cast<float>(arg.value);
    if (!(v >= static_cast<float>(kMinScale) && v <= hi))
      return "option " + arg.name + ": value " + arg.text + " is out of range [" + Format(kMinScale) + ", " +
             Format(hi) + "]" + (r->superSampling ? "" : " (up to 2 with --supersampling)");
    *out[a] = v;
  }
  if (scales.perAxis) r->aspectLock = (r->scaleX == r->scaleY);
  if (!r->controlGiven) r->control = ControlMode::Manual;
  return {};
}

ParseStatus Fail(std::string* message, std::string text) {
  *message = std::move(text);
  return ParseStatus::Error;
}

}  // namespace

std::string Usage() {
  std::ostringstream u;
  u << "Usage: DynamicResolutionRendering [options]\n"
       "Dynamic Resolution Rendering (Vulkan port of the Intel sample).\n\n";
  for (auto s = std::begin(kSpecs); s != std::end(kSpecs); ++s) {
    if (!s->help) continue;  // listed with the entry before
    std::string label = Label(*s);
    for (auto next = s + 1; next != std::end(kSpecs) && !next->help; ++next) label += ", " + Label(*next);
    // A label too long for the column gets its help on the next line.
    const bool fits = label.size() + 3 <= kHelpColumn;
    u << "  " << label << (fits ? std::string(kHelpColumn - 2 - label.size(), ' ') : "\n" + std::string(kHelpColumn, ' '));
    AppendHelp(u, *s);
  }
  u << "\nFixes (--fix), each off by default so that the default frame is the original's\n"
       "(Docs/Port-Notes.md gives each one's measured effect):\n";
  for (const FixInfo& f : FixTable()) {
    const std::size_t used = 2 + std::string_view(f.name).size();
    u << "  " << f.name << std::string(used + 2 <= kHelpColumn ? kHelpColumn - used : 1, ' ') << f.help << '\n';
  }
  u << "\n" << ImportLimitsHelp();
  u << "\n"
       "  --bench [--quick] --out DIR   measure image error against run time instead of running\n"
       "                           the sample (see --bench --help)\n";
  return u.str();
}

ParseStatus ParseCommandLine(int argc, char** argv, Options* options, std::string* message) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  return ParseCommandLine(args, options, message);
}

ParseStatus ParseCommandLine(const std::vector<std::string>& args, Options* o, std::string* message) {
  Options r;
  ScaleArgs scales;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const std::size_t eq = a.rfind("--", 0) == 0 ? a.find('=') : std::string::npos;
    const std::string name = a.substr(0, eq);
    const Spec* spec = FindSpec(name);
    if (!spec) return Fail(message, "unknown option '" + a + "'");
    if (spec->kind == Kind::Help) {
      *message = Usage();
      return ParseStatus::Help;
    }
    std::optional<std::string> value;
    if (spec->kind != Kind::Flag) {
      if (eq != std::string::npos) value = a.substr(eq + 1);
      else if (i + 1 < args.size()) value = args[++i];
    }
    if (std::string error = Apply(*spec, name, value, &r, &scales); !error.empty()) return Fail(message, error);
  }
  if (std::string error = FinishScales(scales, &r); !error.empty()) return Fail(message, error);
  if (r.upscaleQuality >= 0) r.filter = UpscaleQualityFilter(r.upscaleQuality);
  if (r.temporalUpsampling) r.filter = Filter::TAAU;
  *o = r;
  return ParseStatus::Ok;
}

std::string OptionsToJson(const Options& o) {
  std::ostringstream j;
  j << "{\"headless\": " << (o.headless ? "true" : "false") << ", \"width\": " << o.width
    << ", \"height\": " << o.height << ", \"frames\": " << o.EffectiveFrames()
    << ", \"scene\": " << JsonQuote(o.scene) << ", \"camera\": " << o.camera
    << ", \"filter\": \"" << FilterOption(o.filter) << "\", \"scale_x\": " << o.scaleX
    << ", \"scale_y\": " << o.scaleY
    << ", \"dynamic_resolution\": " << (o.dynamicResolution ? "true" : "false")
    << ", \"supersampling\": " << (o.superSampling ? "true" : "false") << ", \"control\": \""
    << ControlModeOption(o.control) << "\", \"law\": \"" << ControlLawOption(o.law)
    << "\", \"refresh\": " << o.refresh
    << ", \"vsync\": " << (o.vsync ? "true" : "false")
    << ", \"motion_blur\": " << (o.motionBlur ? "true" : "false")
    << ", \"symmetric_taa\": " << (o.symmetricTAA ? "true" : "false")
    << ", \"ps_clear\": " << (o.psClear ? "true" : "false")
    << ", \"pause\": " << (o.pause ? "true" : "false")
    << ", \"zoom\": " << (o.zoom ? "true" : "false") << ", \"gui\": " << (o.gui ? "true" : "false")
    << ", \"anisotropy\": " << o.anisotropy << ", \"threads\": " << o.threads
    << ", \"time\": " << o.time << ", \"fixed_dt\": " << o.fixedDt
    << ", \"validation\": " << (o.validation ? "true" : "false")
    << ", \"fixes\": " << JsonQuote(FixNames(o.fixes))
    << ", \"secondary_screen_percentage\": " << o.secondaryScreenPercentage << ", \"mip_bias\": " << o.mipBias
    << ", \"auto_mip_bias\": " << (o.autoMipBias ? "true" : "false")
    << ", \"renderer\": \"" << RendererOption(o.renderer) << "\", \"ssao\": " << (o.ssao ? "true" : "false")
    << ", \"shadow_scale\": " << o.shadowScale << ", \"shadow_law\": \"" << ShadowLawOption(o.shadowLaw)
    << "\", \"shadow_map_size\": " << o.shadowMapSize
    << ", \"taa_mip_bias\": " << (o.taaMipBias ? "true" : "false")
    << ", \"tessellation\": " << (o.tessellation ? "true" : "false")
    << ", \"tess_pixels_per_edge\": " << o.tessPixelsPerEdge << ", \"max_tess_factor\": " << o.maxTessFactor << "}";
  return j.str();
}

}  // namespace drr
