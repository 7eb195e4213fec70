// The one table of the sample's settings, grouped by feature. Each row names a
// setting once: its command-line name and value, its range, its help (the
// default shown there is read from a default-constructed Options), the key it
// has in the report's "options" object, and its widget in the GUI (kind,
// label, the same range). The parser, --help, the report, the GUI's widgets
// and the GUI's change detection all read these rows (Options.cpp,
// OptionsJson.cpp, GuiPanel.cpp).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "Options.h"

namespace drr {

enum class OptionKind {
  Heading,  // starts a group: help heading, GUI section title
  Help,
  Flag,     // no value: stores flagValue
  Integer,  // whole number in [lo, hi]
  Number,   // number in [lo, hi]
  Scale,    // number, range checked once --supersampling is known; writes scaleX and/or scaleY
  Path,     // non-empty text
  Choice,   // one of an enum's command-line values
  Fixes,    // all | none | NAME[,NAME...] (Fixes.h)
  GuiOnly,  // no command-line option (the aspect-ratio lock follows --scale-x/--scale-y)
  Preset,   // a name from OptionPresets(): sets the preset's settings where it stands
};

// The GUI widget of a row. Original: drawn in the original's panel, in its
// order, by GuiPanel; the others in their group's collapsing section.
enum class Widget { None, Check, SliderInt, SliderFloat, Combo, Custom };

// The values of an enum option, read from the enum's own name tables.
struct Choices {
  int count = 0;
  const char* (*option)(int) = nullptr;  // command line and report
  const char* (*gui)(int) = nullptr;     // GUI combo
  const char* noun = nullptr;            // "unknown <noun> 'x'"
};
template <class Enum, const char* (*Option)(Enum), const char* (*Gui)(Enum)>
constexpr Choices ChoicesOf(const char* noun) {
  return {static_cast<int>(Enum::Count), [](int i) { return Option(static_cast<Enum>(i)); },
          [](int i) { return Gui(static_cast<Enum>(i)); }, noun};
}

using OptionField = std::variant<std::monostate, bool Options::*, uint32_t Options::*, int Options::*,
                                 int64_t Options::*, double Options::*, float Options::*, std::string Options::*,
                                 Filter Options::*, ControlMode Options::*, ControlLaw Options::*,
                                 FixSet Options::*, Renderer Options::*, ShadowLaw Options::*,
                                 UpscaleShader Options::*>;

struct OptionRow {
  const char* name = nullptr;      // command line; Heading: the help heading
  const char* metavar = nullptr;   // the value in the help ("--width W"); none for flags
  OptionKind kind = OptionKind::Flag;
  const char* help = nullptr;      // nullptr: listed on the line of the row before. '\n' starts
                                   // a continuation line; {choices}, {range} and {default} expand
  OptionField field{};
  double lo = 0.0, hi = 0.0;       // Integer, Number; the GUI slider's range too
  Choices choices{};               // Choice
  bool flagValue = true;           // Flag
  int axes = 0;                    // Scale: 1 x, 2 y, 3 both
  bool Options::*given = nullptr;  // also set to true when the option is given
  const char* alias = nullptr;
  const char* json = nullptr;      // key in the report's options; nullptr: not reported
  Widget widget = Widget::None;
  const char* label = nullptr;     // GUI label (a combo's caption); Heading: the GUI section title
  const char* format = nullptr;    // GUI slider's number format
  bool original = false;           // drawn in the original's panel (GuiPanel's fixed layout)
  bool (*enabled)(const Options&) = nullptr;  // GUI: nullptr = always enabled

  constexpr OptionRow Json(const char* key) const {
    OptionRow r = *this;
    r.json = key;
    return r;
  }
  constexpr OptionRow Gui(Widget w, const char* text, const char* numberFormat = nullptr) const {
    OptionRow r = *this;
    r.widget = w;
    r.label = text;
    r.format = numberFormat;
    return r;
  }
  constexpr OptionRow Original() const {
    OptionRow r = *this;
    r.original = true;
    return r;
  }
  constexpr OptionRow EnabledIf(bool (*when)(const Options&)) const {
    OptionRow r = *this;
    r.enabled = when;
    return r;
  }
  bool HasRange() const { return kind == OptionKind::Integer || kind == OptionKind::Number; }
};

// A named system as a set of existing settings (--preset NAME). Applied where
// it stands on the command line, so options after it override it.
struct PresetSetting {
  OptionField field;  // a row's field (FindOptionOf finds its row)
  double value;       // as SetFieldNumber writes it (an enum's index, bool 0/1)
};
struct OptionPreset {
  const char* name;
  const char* help;  // one line for --help
  std::span<const PresetSetting> settings;
  FixSet fixesOff;   // port fixes the preset turns off (the system does what the original does there)
};
std::span<const OptionPreset> OptionPresets();
const OptionPreset* FindPreset(std::string_view name);

// Every row, groups in order, each group's Heading row first.
std::span<const OptionRow> OptionRows();

// A group: its heading row and the rows after it.
struct OptionGroup {
  const OptionRow* heading;
  std::span<const OptionRow> rows;
};
std::span<const OptionGroup> OptionGroups();

// The row of a command-line name or alias; the row that holds a field. nullptr: none.
const OptionRow* FindOption(std::string_view name);
const OptionRow* FindOptionOf(const OptionField& field);

// A row's field as a number (bool 0/1, an enum's index) and back; 0 / no-op
// for text and fix sets.
double FieldNumber(const OptionRow& row, const Options& o);
void SetFieldNumber(const OptionRow& row, Options* o, double v);
bool FieldsDiffer(const OptionRow& row, const Options& a, const Options& b);

// The GUI's change detection: true when a setting that the GUI shows (a row
// with a widget) differs.
bool SettingsDiffer(const Options& a, const Options& b);

}  // namespace drr
