// The sample's command line: ParseCommandLine and Usage() read the rows of
// OptionTable.h (one row per setting, grouped by feature); the values of the
// enum options come from the enums' own name tables (FilterOption in
// ResolveFilters.cpp, ControlModeOption and ControlLawOption in
// ResolutionController.cpp, RendererOption and ShadowLawOption in DeferredSettings.cpp).
#include "Options.h"
#include "OptionTable.h"
#include "scene/ImportLimits.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>

namespace drr {
namespace {

using K = OptionKind;

constexpr double kMinScale = 0.01;
constexpr std::size_t kHelpColumn = 27;  // where the help texts start
constexpr std::size_t kUsageWidth = 100; // a longer line is broken after a '|' of a choice list

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

std::string Allowed(const OptionRow& s) { return " (allowed: " + JoinChoices(s.choices, ", ") + ")"; }

void Replace(std::string* text, std::string_view key, const std::string& by) {
  if (const std::size_t at = text->find(key); at != std::string::npos) text->replace(at, key.size(), by);
}

// The default of a row as the command line writes it, read from a default-constructed Options.
std::string DefaultText(const OptionRow& s) {
  const Options defaults;
  if (s.kind == K::Fixes) return FixNames(defaults.fixes);
  const double v = FieldNumber(s, defaults);
  if (s.kind == K::Choice) return s.choices.option(static_cast<int>(v));
  return Format(v);
}

// The help of one table line: continuation lines indented to kHelpColumn.
void AppendHelp(std::ostringstream& u, const OptionRow& s) {
  std::string text = s.help;
  Replace(&text, "{choices}", JoinChoices(s.choices, "|"));
  Replace(&text, "{range}", Format(s.lo) + ".." + Format(s.hi));
  Replace(&text, "{default}", DefaultText(s));
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

std::string Label(const OptionRow& s) { return s.metavar ? std::string(s.name) + " " + s.metavar : s.name; }

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

// Reads the value of a numeric option into *out; returns the error message, or "".
std::string ReadNumber(const OptionRow& s, const std::string& name, const std::string& text, double* out) {
  if (!ParseDecimal(text, out)) return "option " + name + ": '" + text + "' is not a number";
  if (s.kind == K::Scale) return {};
  const std::string range = "[" + Format(s.lo) + ", " + Format(s.hi) + "]";
  if (*out < s.lo || *out > s.hi) return "option " + name + ": value " + text + " is out of range " + range;
  if (s.kind == K::Integer && *out != std::floor(*out))
    return "option " + name + ": '" + text + "' is not an integer; expected an integer in " + range;
  return {};
}

std::string PresetNames() {
  std::string names;
  for (const OptionPreset& p : OptionPresets()) names += (names.empty() ? "" : ", ") + std::string(p.name);
  return names;
}

// Sets the settings of the preset called `value`.
std::string ApplyPreset(const std::string& name, const std::string& value, Options* r) {
  const OptionPreset* preset = FindPreset(value);
  if (!preset) return "option " + name + ": unknown preset '" + value + "' (allowed: " + PresetNames() + ")";
  for (const PresetSetting& setting : preset->settings)
    if (const OptionRow* row = FindOptionOf(setting.field)) SetFieldNumber(*row, r, setting.value);
  r->fixes.bits &= ~preset->fixesOff.bits;
  return {};
}

// Applies one option (value: the text after '=' or the next argument, if any).
std::string Apply(const OptionRow& s, const std::string& name, const std::optional<std::string>& value, Options* r,
                  ScaleArgs* scales) {
  if (s.given) r->*s.given = true;
  if (s.kind == K::Flag) {
    SetFieldNumber(s, r, s.flagValue);
    return {};
  }
  if (s.kind == K::Path) {
    if (!value || value->empty()) return "option " + name + " needs a path";
    r->*std::get<std::string Options::*>(s.field) = *value;
    return {};
  }
  if (!value) return "option " + name + " needs a value" + (s.kind == K::Choice ? Allowed(s) : "");
  if (s.kind == K::Preset) return ApplyPreset(name, *value, r);
  if (s.kind == K::Fixes) {
    std::string error;
    if (!ParseFixes(*value, &(r->*std::get<FixSet Options::*>(s.field)), &error))
      return "option " + name + ": " + error;
    return {};
  }
  if (s.kind == K::Choice) {
    for (int i = 0; i < s.choices.count; ++i)
      if (*value == s.choices.option(i)) {
        SetFieldNumber(s, r, i);
        return {};
      }
    return "option " + name + ": unknown " + s.choices.noun + " '" + *value + "'" + Allowed(s);
  }
  double number = 0.0;
  if (std::string error = ReadNumber(s, name, *value, &number); !error.empty()) return error;
  if (s.kind != K::Scale) {
    SetFieldNumber(s, r, number);
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
  for (const OptionGroup& group : OptionGroups()) {
    u << group.heading->name << ":\n";
    for (auto s = group.rows.begin(); s != group.rows.end(); ++s) {
      if (!s->help) continue;  // listed with the entry before
      std::string label = Label(*s);
      for (auto next = s + 1; next != group.rows.end() && !next->help && next->name; ++next)
        label += ", " + Label(*next);
      // A label too long for the column gets its help on the next line.
      const bool fits = label.size() + 3 <= kHelpColumn;
      u << "  " << label
        << (fits ? std::string(kHelpColumn - 2 - label.size(), ' ') : "\n" + std::string(kHelpColumn, ' '));
      AppendHelp(u, *s);
    }
    u << "\n";
  }
  u << "Fixes (--fix), each off by default so that the default frame is the original's\n"
       "(Docs/Port-Notes.md gives each one's measured effect):\n";
  for (const FixInfo& f : FixTable()) {
    const std::size_t used = 2 + std::string_view(f.name).size();
    u << "  " << f.name << std::string(used + 2 <= kHelpColumn ? kHelpColumn - used : 1, ' ') << f.help << '\n';
  }
  u << "\nPresets (--preset NAME):\n";
  for (const OptionPreset& p : OptionPresets()) {
    std::string line = "  " + std::string(p.name);
    line += std::string(kHelpColumn > line.size() ? kHelpColumn - line.size() : 1, ' ');
    for (char c : std::string(p.help)) line += c == '\n' ? "\n" + std::string(kHelpColumn, ' ') : std::string(1, c);
    u << line << '\n';
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
    const OptionRow* spec = FindOption(name);
    if (!spec) return Fail(message, "unknown option '" + a + "'");
    if (spec->kind == K::Help) {
      *message = Usage();
      return ParseStatus::Help;
    }
    std::optional<std::string> value;
    if (spec->kind != K::Flag) {
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

}  // namespace drr
