// Command-line parser and generated-texture tests of the sample (no GPU).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "OptionTable.h"
#include "Options.h"
#include "OptionsJson.h"
#include "TexGenUtils.h"

using namespace drr;

namespace {
ParseStatus Parse(std::vector<std::string> args, Options* o, std::string* msg) {
  return ParseCommandLine(args, o, msg);
}
}  // namespace

TEST(SampleOptions, Defaults) {
  Options o;
  std::string m;
  ASSERT_EQ(Parse({}, &o, &m), ParseStatus::Ok);
  EXPECT_EQ(o.width, 1280u);
  EXPECT_EQ(o.height, 720u);
  EXPECT_EQ(o.filter, Filter::TAA);
  EXPECT_EQ(o.control, ControlMode::VSync);
  EXPECT_TRUE(o.motionBlur);
  EXPECT_TRUE(o.psClear);
  EXPECT_TRUE(o.dynamicResolution);
  EXPECT_FALSE(o.superSampling);
  EXPECT_FALSE(o.symmetricTAA);
  EXPECT_EQ(o.EffectiveFrames(), -1);
  o.headless = true;
  EXPECT_EQ(o.EffectiveFrames(), 300);
}

TEST(SampleOptions, AllOptions) {
  Options o;
  std::string m;
  ASSERT_EQ(Parse({"--headless", "--width", "160", "--height=90", "--frames", "3", "--scene", "a.txt",
                   "--camera", "2", "--filter", "taa-noise-offset", "--scale", "0.71",
                   "--supersampling", "--control", "half-vsync", "--refresh", "144", "--no-motion-blur",
                   "--symmetric-taa", "--no-ps-clear", "--pause", "--zoom", "--no-gui", "--screenshot",
                   "s.png", "--screenshot-no-gui", "--report", "r.json", "--validation", "--stats",
                   "--time", "1.5", "--fixed-dt", "0.01", "--no-dynamic-resolution"},
                  &o, &m),
            ParseStatus::Ok)
      << m;
  EXPECT_TRUE(o.headless);
  EXPECT_EQ(o.width, 160u);
  EXPECT_EQ(o.height, 90u);
  EXPECT_EQ(o.frames, 3);
  EXPECT_EQ(o.scene, "a.txt");
  EXPECT_EQ(o.camera, 2);
  EXPECT_EQ(o.filter, Filter::TAANoiseOffset);
  EXPECT_FLOAT_EQ(o.scaleX, 0.71f);
  EXPECT_FLOAT_EQ(o.scaleY, 0.71f);
  EXPECT_EQ(o.control, ControlMode::HalfVSync);  // explicit --control wins over --scale
  EXPECT_DOUBLE_EQ(o.refresh, 144.0);
  EXPECT_FALSE(o.motionBlur);
  EXPECT_TRUE(o.symmetricTAA);
  EXPECT_FALSE(o.psClear);
  EXPECT_TRUE(o.pause);
  EXPECT_TRUE(o.zoom);
  EXPECT_FALSE(o.gui);
  EXPECT_EQ(o.screenshot, "s.png");
  EXPECT_TRUE(o.screenshotNoGui);
  EXPECT_EQ(o.report, "r.json");
  EXPECT_TRUE(o.validation);
  EXPECT_TRUE(o.stats);
  EXPECT_DOUBLE_EQ(o.time, 1.5);
  EXPECT_DOUBLE_EQ(o.fixedDt, 0.01);
  EXPECT_FALSE(o.dynamicResolution);
}

TEST(SampleOptions, ScaleImpliesManual) {
  Options o;
  std::string m;
  ASSERT_EQ(Parse({"--scale", "0.5"}, &o, &m), ParseStatus::Ok);
  EXPECT_EQ(o.control, ControlMode::Manual);
  ASSERT_EQ(Parse({"--scale-x", "0.5", "--scale-y", "0.25"}, &o, &m), ParseStatus::Ok);
  EXPECT_FLOAT_EQ(o.scaleX, 0.5f);
  EXPECT_FLOAT_EQ(o.scaleY, 0.25f);
  EXPECT_FALSE(o.aspectLock);
}

TEST(SampleOptions, EveryFilterName) {
  const char* names[] = {"none", "point", "bilinear", "bicubic", "noise", "noise-offset", "taa",
                         "taa-noise-offset", "taa-basic"};
  for (int i = 0; i < 9; ++i) {
    Options o;
    std::string m;
    ASSERT_EQ(Parse({"--filter", names[i]}, &o, &m), ParseStatus::Ok) << names[i];
    EXPECT_EQ(static_cast<int>(o.filter), i);
    EXPECT_STREQ(FilterOption(o.filter), names[i]);
  }
}

TEST(SampleOptions, UnknownOptionIsAnError) {
  Options o;
  std::string m;
  EXPECT_EQ(Parse({"--bogus"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("--bogus"), std::string::npos) << m;
  EXPECT_EQ(Parse({"--filter", "lanczos"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("lanczos"), std::string::npos) << m;
  EXPECT_NE(m.find("taa-basic"), std::string::npos) << m;  // lists the allowed values
  EXPECT_EQ(Parse({"--control", "fast"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("fast"), std::string::npos);
}

TEST(SampleOptions, OutOfRangeValuesNameValueAndRange) {
  Options o;
  std::string m;
  EXPECT_EQ(Parse({"--scale", "1.5"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("1.5"), std::string::npos) << m;
  EXPECT_NE(m.find("[0.01, 1]"), std::string::npos) << m;
  EXPECT_EQ(Parse({"--scale", "1.5", "--supersampling"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_EQ(Parse({"--scale", "2.5", "--supersampling"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("[0.01, 2]"), std::string::npos) << m;
  EXPECT_EQ(Parse({"--scale", "0"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--scale-x", "-1"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--scale", "nan"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--scale", "inf"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--width", "0"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("--width"), std::string::npos);
  EXPECT_EQ(Parse({"--width", "99999"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--width", "12.5"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--width", "abc"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--frames", "-1"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--refresh", "0"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--fixed-dt", "-0.1"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(Parse({"--width"}, &o, &m), ParseStatus::Error);  // missing value
  EXPECT_NE(m.find("needs a value"), std::string::npos);
}

// Numbers are plain decimal for every kind of numeric option: a space before or
// after the value, or hexadecimal, is "not a number" whichever way it is given.
TEST(SampleOptions, NumbersArePlainDecimal) {
  for (const char* option : {"--width", "--frames", "--refresh", "--time", "--anisotropy", "--scale", "--scale-x"}) {
    for (const char* bad : {" 5", "5 ", "0x10", "0X1p0", " 0.5", "0.5 ", "1,5", "1e", ""}) {
      for (bool inlineValue : {false, true}) {
        Options o;
        std::string m;
        const std::vector<std::string> args =
            inlineValue ? std::vector<std::string>{std::string(option) + "=" + bad}
                        : std::vector<std::string>{option, bad};
        EXPECT_EQ(Parse(args, &o, &m), ParseStatus::Error) << option << " '" << bad << "'";
        EXPECT_EQ(m, std::string("option ") + option + ": '" + bad + "' is not a number") << m;
      }
    }
  }
  Options o;
  std::string m;
  ASSERT_EQ(Parse({"--width", "+640", "--refresh", "1e2", "--time", ".5", "--scale", "0.50"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_EQ(o.width, 640u);
  EXPECT_DOUBLE_EQ(o.refresh, 100.0);
  EXPECT_DOUBLE_EQ(o.time, 0.5);
  EXPECT_FLOAT_EQ(o.scaleX, 0.5f);
}

// A finite but huge scale is reported against the range the user can give,
// not against an internal bound; the option named is the one that set the axis.
TEST(SampleOptions, ScaleRangeIsTheUsersRange) {
  Options o;
  std::string m;
  EXPECT_EQ(Parse({"--scale-x", "1e308"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --scale-x: value 1e308 is out of range [0.01, 1] (up to 2 with --supersampling)");
  EXPECT_EQ(Parse({"--scale-y=-1e308", "--supersampling"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --scale-y: value -1e308 is out of range [0.01, 2]");
  EXPECT_EQ(Parse({"--scale", "1e300", "--supersampling"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("[0.01, 2]"), std::string::npos) << m;
  EXPECT_EQ(Parse({"--scale", "0.5", "--scale-x", "3"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m.rfind("option --scale-x: value 3 ", 0), 0u) << m;
  EXPECT_EQ(Parse({"--scale-x", "1e309"}, &o, &m), ParseStatus::Error);  // not finite as a double
  EXPECT_NE(m.find("is not a number"), std::string::npos) << m;
  // Nothing is written on an error; the side effects of a good scale stay.
  ASSERT_EQ(Parse({"--scale-y", "0.5"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_FLOAT_EQ(o.scaleX, 1.0f);
  EXPECT_FLOAT_EQ(o.scaleY, 0.5f);
  EXPECT_FALSE(o.aspectLock);
  EXPECT_EQ(o.control, ControlMode::Manual);
  ASSERT_EQ(Parse({"--scale-x", "0.5", "--scale-y", "0.5"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_TRUE(o.aspectLock);
}

TEST(SampleOptions, IntegerAndChoiceMessages) {
  Options o;
  std::string m;
  EXPECT_EQ(Parse({"--width=12.5"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --width: '12.5' is not an integer; expected an integer in [1, 16384]");
  EXPECT_EQ(Parse({"--anisotropy", "2.5"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("expected an integer in [0, 16]"), std::string::npos) << m;
  EXPECT_EQ(Parse({"--anisotropy", "17"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --anisotropy: value 17 is out of range [0, 16]");
  EXPECT_EQ(Parse({"--frames", "2e9"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --frames: value 2e9 is out of range [0, 1e+09]");
  EXPECT_EQ(Parse({"--filter"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m.rfind("option --filter needs a value (allowed: none, point, ", 0), 0u) << m;
  EXPECT_EQ(Parse({"--control", "fast"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --control: unknown mode 'fast' (allowed: manual, half-vsync, vsync)");
  EXPECT_EQ(Parse({"--scene="}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --scene needs a path");
  EXPECT_EQ(Parse({"--headless", "--bogus=1"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "unknown option '--bogus=1'");
}

// The help is generated from the table the parser reads: every option it shows
// is accepted, every enum value is listed, and it keeps the --bench lines.
TEST(SampleOptions, HelpAndParserShareOneTable) {
  Options o;
  std::string help, m;
  ASSERT_EQ(Parse({"-h"}, &o, &help), ParseStatus::Help);
  std::istringstream lines(help);
  int shown = 0;
  for (std::string line; std::getline(lines, line);) {
    EXPECT_LE(line.size(), 100u) << line;
    if (line.rfind("  --bench ", 0) == 0) break;  // the --bench command line has its own parser
    if (line.rfind("  -", 0) != 0) continue;
    const std::size_t end = line.find("  ", 2);  // the label ends at the help column (or the line)
    std::istringstream label(line.substr(2, end == std::string::npos ? std::string::npos : end - 2));
    for (std::string word; label >> word;) {
      if (word.back() == ',') word.pop_back();
      if (word[0] != '-') continue;
      ++shown;
      Parse({word}, &o, &m);
      EXPECT_EQ(m.find("unknown option"), std::string::npos) << word << ": " << m;
    }
  }
  EXPECT_EQ(shown, 59);  // every option of the sample once (-h is --help's other name)
  for (const FixInfo& f : FixTable()) EXPECT_NE(help.find(std::string("  ") + f.name + " "), std::string::npos);
  for (int f = 0; f < static_cast<int>(Filter::Count); ++f)
    EXPECT_NE(help.find(FilterOption(static_cast<Filter>(f))), std::string::npos);
  EXPECT_NE(help.find("manual|half-vsync|vsync (default vsync)"), std::string::npos) << help;
  EXPECT_NE(help.find("\n  --bench [--quick] --out DIR"), std::string::npos);
  EXPECT_NE(help.find("(see --bench --help)"), std::string::npos);
  EXPECT_NE(help.find("--width W, --height H    back buffer size (default 1280x720, 1..16384)"), std::string::npos);
  EXPECT_NE(help.find("(default: the monitor's, 60 headless; 1..1000)"), std::string::npos);
}

TEST(SampleOptions, HelpListsEveryOption) {
  Options o;
  std::string m;
  ASSERT_EQ(Parse({"--help"}, &o, &m), ParseStatus::Help);
  for (const char* opt : {"--headless", "--width", "--height", "--frames", "--scene", "--camera", "--filter",
                          "--scale", "--scale-x", "--scale-y", "--no-dynamic-resolution", "--supersampling",
                          "--control", "--refresh", "--no-motion-blur", "--symmetric-taa", "--no-ps-clear",
                          "--pause", "--zoom", "--no-gui", "--screenshot", "--screenshot-no-gui", "--report",
                          "--validation", "--stats", "--time", "--fixed-dt", "--help"})
    EXPECT_NE(m.find(opt), std::string::npos) << opt;
}

TEST(TexGenUtils, CubicLookupIsPartitionOfUnityAndReproducesLinear) {
  const auto t = CubicFilterLookupTable::Generate(128);
  ASSERT_EQ(t.size(), 128u * 4u);
  for (int i = 0; i < 128; ++i) {
    const float a = i / 128.0f;  // the original's entry i is for the fraction i / 128
    const float h0 = t[i * 4], h1 = t[i * 4 + 1], g0 = t[i * 4 + 2], g1 = t[i * 4 + 3];
    EXPECT_NEAR(g0 + g1, 1.0f, 1e-6f);
    EXPECT_GT(g0, 0.0f);
    EXPECT_GT(g1, 0.0f);
    // Taps at x - h0 and x + h1 (x = sample position). The B-spline reproduces
    // linear functions: g0 (x - h0) + g1 (x + h1) = x.
    EXPECT_NEAR(g1 * h1 - g0 * h0, 0.0f, 1e-5f) << i;
    // Relative to the base texel, the first tap lies between texels -1 and 0,
    // the second between 1 and 2 (each bilinear tap blends one pair).
    EXPECT_GE(a - h0, -1.0f - 1e-5f);
    EXPECT_LE(a - h0, 0.0f + 1e-5f);
    EXPECT_GE(a + h1, 1.0f - 1e-5f);
    EXPECT_LE(a + h1, 2.0f + 1e-5f);
  }
  // Entry 0 (fraction 0): weights 1/6, 4/6, 1/6, 0.
  EXPECT_NEAR(t[2], 5.0f / 6.0f, 1e-6f);
  EXPECT_NEAR(t[0], 1.0f - 0.8f, 1e-6f);  // h0 = 1 - (4/6) / (5/6)
}

// The original seeds its C library's rand() with 42 (Microsoft's generator,
// whose first outputs are 175, 400, 17869, 30056, ...) and stores
// byte(256 * r / 32767) per channel.
TEST(TexGenUtils, NoiseIsTheOriginalsRandSequence) {
  MsvcRand rng(42);
  for (int expected : {175, 400, 17869, 30056, 16083}) EXPECT_EQ(rng.Next(), expected);
  const auto a = NoiseTexture::Generate(128);
  ASSERT_EQ(a.size(), 128u * 128u * 4u);
  const uint8_t first[8] = {1, 3, 139, 234, 125, 100, 62, 59};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(a[i], first[i]) << i;
  EXPECT_EQ(a, NoiseTexture::Generate(128));
  double mean = 0;
  for (uint8_t v : a) mean += v;
  mean /= a.size();
  EXPECT_NEAR(mean, 127.5, 2.0);
  EXPECT_NE(NoiseTexture::Generate(128, 1), a);
  // The Noise filter's offsets continue the sequence after the 65536 texels.
  MsvcRand after(0);
  NoiseTexture::Generate(128, 42, &after);
  EXPECT_EQ(after.Next(), 19964);  // 0.6092529296875 * 32768
}

TEST(SampleOptions, ControlLaw) {
  Options o;
  std::string m;
  ASSERT_EQ(Parse({}, &o, &m), ParseStatus::Ok);
  EXPECT_EQ(o.law, ControlLaw::Article);  // the original's law by default
  const std::pair<const char*, ControlLaw> laws[] = {
      {"article", ControlLaw::Article}, {"robust", ControlLaw::Robust}, {"ue-style", ControlLaw::UEStyle}};
  for (const auto& [name, law] : laws) {
    ASSERT_EQ(Parse({"--law", name}, &o, &m), ParseStatus::Ok) << m;
    EXPECT_EQ(o.law, law);
    EXPECT_STREQ(ControlLawOption(law), name);
    ASSERT_EQ(Parse({std::string("--law=") + name}, &o, &m), ParseStatus::Ok) << m;
    EXPECT_EQ(o.law, law);
    EXPECT_EQ(nlohmann::json::parse(OptionsToJson(o))["law"], name);
  }
  for (const char* bad : {"ue", "Robust", "", "pid"}) {
    EXPECT_EQ(Parse({"--law", bad}, &o, &m), ParseStatus::Error) << bad;
    EXPECT_NE(m.find("allowed: article, robust, ue-style"), std::string::npos) << m;
  }
  EXPECT_EQ(Parse({"--law"}, &o, &m), ParseStatus::Error);
  // --help documents the option, its values and its default.
  ASSERT_EQ(Parse({"--help"}, &o, &m), ParseStatus::Help);
  EXPECT_NE(m.find("--law LAW"), std::string::npos);
  EXPECT_NE(m.find("article|robust|ue-style"), std::string::npos);
  EXPECT_NE(m.find("default article"), std::string::npos);
}

TEST(SampleOptions, FixListParsesAndRoundTrips) {
  Options o;
  std::string m;
  EXPECT_EQ(o.fixes, FixSet{});  // the original by default
  ASSERT_EQ(ParseCommandLine(std::vector<std::string>{"--fix", "all"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_EQ(o.fixes, FixSet::All());
  EXPECT_EQ(FixNames(o.fixes), "all");
  for (const FixInfo& f : FixTable()) {
    ASSERT_EQ(ParseCommandLine(std::vector<std::string>{std::string("--fix=") + f.name}, &o, &m), ParseStatus::Ok);
    EXPECT_TRUE(o.fixes.Has(f.fix));
    FixSet back;
    ASSERT_TRUE(ParseFixes(FixNames(o.fixes), &back, &m)) << m;
    EXPECT_EQ(back, o.fixes);
  }
  ASSERT_EQ(ParseCommandLine(std::vector<std::string>{"--fix", "none"}, &o, &m), ParseStatus::Ok);
  EXPECT_EQ(o.fixes, FixSet{});
  for (const char* bad : {"", "bogus", "uv-inset,", ",uv-inset", "all,uv-inset", "UV-INSET"}) {
    EXPECT_EQ(ParseCommandLine(std::vector<std::string>{"--fix", bad}, &o, &m), ParseStatus::Error) << bad;
    EXPECT_NE(m.find("--fix"), std::string::npos) << m;
  }
}

TEST(SampleOptions, QuietIsOffByDefaultAndParsed) {
  Options o;
  std::string m;
  ASSERT_EQ(Parse({}, &o, &m), ParseStatus::Ok);
  EXPECT_FALSE(o.quiet);
  ASSERT_EQ(Parse({"--quiet"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_TRUE(o.quiet);
}

// Deferred shading (Docs/Deferred.md): forward by default, the values from
// their name tables, errors naming the value and what is allowed.
TEST(SampleOptions, DeferredRenderer) {
  Options o;
  std::string m;
  ASSERT_EQ(Parse({}, &o, &m), ParseStatus::Ok);
  EXPECT_EQ(o.renderer, Renderer::Forward);
  EXPECT_TRUE(o.ssao);
  EXPECT_TRUE(o.localLights);
  EXPECT_EQ(o.shadowLaw, ShadowLaw::Main);
  ASSERT_EQ(Parse({"--renderer", "deferred", "--no-ssao", "--no-local-lights", "--shadow-scale=0.5", "--shadow-law",
                   "fixed", "--shadow-map-size", "512"},
                  &o, &m),
            ParseStatus::Ok)
      << m;
  EXPECT_EQ(o.renderer, Renderer::Deferred);
  EXPECT_FALSE(o.ssao);
  EXPECT_FALSE(o.localLights);
  EXPECT_EQ(o.shadowScale, 0.5);
  EXPECT_EQ(o.shadowLaw, ShadowLaw::Fixed);
  EXPECT_EQ(o.shadowMapSize, 512u);
  const nlohmann::json json = nlohmann::json::parse(OptionsToJson(o));
  EXPECT_EQ(json["renderer"], "deferred");
  EXPECT_EQ(json["ssao"], false);
  EXPECT_EQ(Parse({"--renderer", "tiled"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --renderer: unknown renderer 'tiled' (allowed: forward, deferred)");
  EXPECT_EQ(Parse({"--shadow-law", "area"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --shadow-law: unknown shadow law 'area' (allowed: fixed, main)");
  EXPECT_EQ(Parse({"--shadow-scale", "0.1"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --shadow-scale: value 0.1 is out of range [0.125, 1]");
  EXPECT_EQ(Parse({"--shadow-map-size", "8192"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --shadow-map-size: value 8192 is out of range [64, 4096]");
  ASSERT_EQ(Parse({"--help"}, &o, &m), ParseStatus::Help);
  EXPECT_NE(m.find("--renderer NAME"), std::string::npos);
  EXPECT_NE(m.find("forward|deferred (default forward"), std::string::npos) << m;
}

// Tessellation (Docs/Tessellation.md): off by default, the two settings
// range-checked with the value named.
TEST(SampleOptions, TessellationSettings) {
  Options o;
  std::string m;
  ASSERT_EQ(Parse({}, &o, &m), ParseStatus::Ok);
  EXPECT_FALSE(o.tessellation);
  EXPECT_EQ(o.tessPixelsPerEdge, 8.0);
  EXPECT_EQ(o.maxTessFactor, 16);
  ASSERT_EQ(Parse({"--tessellation", "--tess-pixels-per-edge", "2.5", "--max-tess-factor=64"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_TRUE(o.tessellation);
  EXPECT_EQ(o.tessPixelsPerEdge, 2.5);
  EXPECT_EQ(o.maxTessFactor, 64);
  EXPECT_EQ(Parse({"--max-tess-factor", "65"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("--max-tess-factor"), std::string::npos) << m;
  EXPECT_NE(m.find("65"), std::string::npos) << m;
  EXPECT_EQ(Parse({"--tess-pixels-per-edge", "0"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("--tess-pixels-per-edge"), std::string::npos) << m;
}

// --threads (Docs/Threads.md): 1 the immediate context (the default, as the
// original), 0 automatic, up to 8; anything else is refused naming the value
// and the range; --help says which is which.
TEST(SampleOptions, RecordingThreads) {
  Options o;
  std::string m;
  EXPECT_EQ(o.threads, 1);
  EXPECT_EQ(Parse({"--threads", "0"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_EQ(o.threads, 0);
  EXPECT_EQ(nlohmann::json::parse(OptionsToJson(o))["threads"], 0);
  EXPECT_EQ(Parse({"--threads", "3"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_EQ(o.threads, 3);
  EXPECT_EQ(Parse({"--threads=1"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_EQ(o.threads, 1);
  EXPECT_EQ(Parse({"--threads", "9"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --threads: value 9 is out of range [0, 8]");
  EXPECT_EQ(Parse({"--threads", "-1"}, &o, &m), ParseStatus::Error);
  EXPECT_EQ(m, "option --threads: value -1 is out of range [0, 8]");
  EXPECT_EQ(Parse({"--threads", "two"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("'two' is not a number"), std::string::npos) << m;
  EXPECT_EQ(nlohmann::json::parse(OptionsToJson(o))["threads"], 1);
  EXPECT_NE(Usage().find("--threads N"), std::string::npos);
  EXPECT_NE(Usage().find("0 auto"), std::string::npos);
  EXPECT_NE(Usage().find("(default 1)"), std::string::npos);
}

// --preset sets existing settings where it stands: later options override it,
// earlier ones it overrides; every setting of a preset has its row.
TEST(SampleOptions, Gles2Preset) {
  Options o;
  std::string m;
  ASSERT_EQ(ParseCommandLine({"--supersampling", "--fix", "all", "--preset", "gles2", "--scale", "0.625"}, &o, &m),
            ParseStatus::Ok) << m;
  EXPECT_EQ(o.filter, Filter::Bilinear);
  EXPECT_FALSE(o.motionBlur);
  EXPECT_FALSE(o.psClear);
  EXPECT_FALSE(o.superSampling);
  EXPECT_TRUE(o.dynamicResolution);
  EXPECT_TRUE(o.aspectLock);
  EXPECT_EQ(o.control, ControlMode::Manual);
  EXPECT_FLOAT_EQ(o.scaleX, 0.625f);
  EXPECT_FLOAT_EQ(o.scaleY, 0.625f);
  EXPECT_FALSE(o.fixes.Has(Fix::UvInset)) << "the article's quad is not clamped";
  EXPECT_TRUE(o.fixes.Has(Fix::FrustumCull)) << "fixes elsewhere stay";
  ASSERT_EQ(ParseCommandLine({"--preset", "gles2", "--filter", "taa"}, &o, &m), ParseStatus::Ok) << m;
  EXPECT_EQ(o.filter, Filter::TAA);
  EXPECT_FALSE(o.motionBlur);
  EXPECT_EQ(ParseCommandLine({"--preset", "gles3"}, &o, &m), ParseStatus::Error);
  EXPECT_NE(m.find("unknown preset 'gles3' (allowed: gles2)"), std::string::npos) << m;
  EXPECT_EQ(ParseCommandLine({"--preset"}, &o, &m), ParseStatus::Error);
  for (const OptionPreset& p : OptionPresets()) {
    EXPECT_NE(Usage().find("  " + std::string(p.name) + " "), std::string::npos) << p.name;
    for (const PresetSetting& s : p.settings) EXPECT_NE(FindOptionOf(s.field), nullptr) << p.name;
  }
}
