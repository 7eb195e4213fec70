// The settings table (OptionTable.h): every row's range is the parser's and
// the help's, every report key is written from its row's field, the defaults
// the help shows are the Options struct's, and each setting has one row.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <sstream>

#include "OptionTable.h"
#include "Options.h"
#include "OptionsJson.h"

using namespace drr;

namespace {
// As the parser and the help print numbers (6 significant digits).
std::string Text(double v, int digits = 6) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

ParseStatus Parse(std::vector<std::string> args, std::string* message) {
  Options o;
  return ParseCommandLine(args, &o, message);
}

// A command line that gives the row a value other than its default; the
// value's expected report JSON in *expected.
std::vector<std::string> NonDefault(const OptionRow& row, nlohmann::json* expected) {
  const Options defaults;
  switch (row.kind) {
    case OptionKind::Flag: *expected = row.flagValue; return {row.name};
    case OptionKind::Path: *expected = "x.txt"; return {row.name, "x.txt"};
    case OptionKind::Fixes: *expected = "all"; return {row.name, "all"};
    case OptionKind::Scale: *expected = 0.5; return {row.name, "0.5"};
    case OptionKind::Choice: {
      const int other = (int(FieldNumber(row, defaults)) + 1) % row.choices.count;
      *expected = row.choices.option(other);
      return {row.name, row.choices.option(other)};
    }
    default: {
      const double v = FieldNumber(row, defaults) == row.hi ? row.lo : row.hi;
      *expected = v;
      return {row.name, Text(v)};
    }
  }
}
}  // namespace

// Each range is the one the parser enforces and the help prints.
TEST(OptionTable, EveryRangeIsTheParsersAndTheHelps) {
  const std::string help = Usage();
  int ranges = 0;
  for (const OptionRow& row : OptionRows()) {
    if (!row.HasRange()) continue;
    ++ranges;
    std::string m;
    const std::string range = "[" + Text(row.lo) + ", " + Text(row.hi) + "]";
    EXPECT_EQ(Parse({row.name, Text(row.lo)}, &m), ParseStatus::Ok) << row.name << ": " << m;
    EXPECT_EQ(Parse({row.name, Text(row.hi)}, &m), ParseStatus::Ok) << row.name << ": " << m;
    const double step = row.kind == OptionKind::Integer ? 1.0 : std::max(1e-3, std::abs(row.hi) * 1e-3);
    for (double outside : {row.lo - step, row.hi + step}) {
      EXPECT_EQ(Parse({row.name, Text(outside, 15)}, &m), ParseStatus::Error) << row.name << " " << outside;
      EXPECT_NE(m.find(range), std::string::npos) << m;
    }
    if (std::string(row.help ? row.help : "").find("{range}") != std::string::npos) {
      EXPECT_NE(help.find(Text(row.lo) + ".." + Text(row.hi)), std::string::npos) << row.name;
    }
  }
  EXPECT_GE(ranges, 15);
}

// The report's options are written from the rows: each key once, its value
// the field's (a non-default value given on the command line shows there).
TEST(OptionTable, EveryReportKeyComesFromItsRow) {
  std::set<std::string> keys;
  for (const OptionRow& row : OptionRows()) {
    if (!row.json) continue;
    EXPECT_TRUE(keys.insert(row.json).second) << "report key twice: " << row.json;
    nlohmann::json expected;
    const std::vector<std::string> args = NonDefault(row, &expected);
    Options o;
    std::string m;
    ASSERT_EQ(ParseCommandLine(args, &o, &m), ParseStatus::Ok) << args[0] << ": " << m;
    const nlohmann::json written = nlohmann::json::parse(OptionsToJson(o));
    const nlohmann::json defaults = nlohmann::json::parse(OptionsToJson(Options{}));
    EXPECT_EQ(written[row.json], expected) << row.json;
    EXPECT_NE(written[row.json], defaults[row.json]) << row.json << " does not follow " << args[0];
  }
  // The keys the report has always had (scripts and tests read them).
  const std::set<std::string> known = {
      "headless", "width", "height", "frames", "scene", "camera", "filter", "scale_x", "scale_y",
      "dynamic_resolution", "supersampling", "control", "law", "refresh", "vsync", "pace_hz", "motion_blur",
      "symmetric_taa", "ps_clear", "pause", "zoom", "gui", "anisotropy", "threads", "time", "fixed_dt",
      "validation", "fixes", "secondary_screen_percentage", "mip_bias", "auto_mip_bias", "renderer", "ssao",
      "shadow_scale", "shadow_law", "shadow_map_size", "taa_mip_bias", "tessellation", "tess_pixels_per_edge",
      "max_tess_factor", "upscale_shader"};
  EXPECT_EQ(keys, known);
}

// The defaults: the report of a default Options, and the help's "(default X)"
// read from the same struct.
TEST(OptionTable, DefaultsAreTheOriginals) {
  Options o;
  o.headless = true;
  const nlohmann::json j = nlohmann::json::parse(OptionsToJson(o));
  EXPECT_EQ(j["frames"], 300);  // the headless default, as EffectiveFrames() gives it
  EXPECT_EQ(j["filter"], "taa");
  EXPECT_EQ(j["control"], "vsync");
  EXPECT_EQ(j["law"], "article");
  EXPECT_EQ(j["scale_x"], 1.0);
  EXPECT_EQ(j["secondary_screen_percentage"], 100.0);
  EXPECT_EQ(j["fixes"], "none");
  EXPECT_EQ(j["renderer"], "forward");
  EXPECT_EQ(j["shadow_law"], "main");
  EXPECT_EQ(j["tess_pixels_per_edge"], 8.0);
  EXPECT_EQ(j["max_tess_factor"], 16);
  const std::string help = Usage();
  EXPECT_EQ(help.find('{'), std::string::npos) << "a placeholder was not expanded";
  for (const char* shown : {"(default vsync)", "(default taa)", "default 100: none", "default 8)", "default 16)",
                            "(default article:", "(default forward:", "(default main:", "default 1024)",
                            "(default none: the original"})
    EXPECT_NE(help.find(shown), std::string::npos) << shown;
}

// A float is written as the shortest decimal that reads back as that float.
TEST(OptionTable, ScaleIsWrittenAsGiven) {
  Options o;
  std::string m;
  ASSERT_EQ(ParseCommandLine({"--scale", "0.71"}, &o, &m), ParseStatus::Ok);
  EXPECT_NE(OptionsToJson(o).find("\"scale_x\":0.71,"), std::string::npos) << OptionsToJson(o);
}

// One row per setting and per command-line name; every row in one group; the
// groups in the order of the help, each named there.
TEST(OptionTable, OneRowPerSettingGroupedByFeature) {
  std::set<std::string> names;
  std::size_t grouped = 0;
  const std::string help = Usage();
  for (const OptionGroup& g : OptionGroups()) {
    EXPECT_NE(help.find(std::string(g.heading->name) + ":\n"), std::string::npos) << g.heading->name;
    grouped += 1 + g.rows.size();
    for (const OptionRow& row : g.rows) {
      EXPECT_NE(row.kind, OptionKind::Heading);
      if (row.name) {
        EXPECT_TRUE(names.insert(row.name).second) << "option twice: " << row.name;
      }
      if (row.field.index() != 0) {
        EXPECT_EQ(FindOptionOf(row.field), &row) << "field of two rows";
      }
      if (row.widget != Widget::None) {
        EXPECT_NE(row.label, nullptr) << "a widget without a label";
      }
    }
  }
  EXPECT_EQ(grouped, OptionRows().size());
  EXPECT_EQ(OptionRows().front().kind, OptionKind::Heading);
  EXPECT_GE(OptionGroups().size(), 8u);
}

// A path that is not UTF-8 is written with replacement characters: the
// report stays valid JSON instead of the writer throwing.
TEST(OptionTable, NonUtf8PathIsWrittenAsValidJson) {
  Options o;
  std::string m;
  ASSERT_EQ(ParseCommandLine({"--scene", "/tmp/\xff\xfe.txt"}, &o, &m), ParseStatus::Ok);
  const nlohmann::json j = nlohmann::json::parse(OptionsToJson(o), nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["scene"], "/tmp/\xEF\xBF\xBD\xEF\xBF\xBD.txt");
}
