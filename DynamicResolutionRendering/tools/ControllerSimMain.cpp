// drr_controller_sim: closed-loop comparison of the resolution control laws.
// Run with --help for the options. The model and metrics live in
// ControllerSimCore.cpp (shared with the tests).
#include "ControllerSimCore.h"
#include "ControllerSimReplay.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

namespace {

using drr::ControlLaw;
using drr::sim::Scenario;

void Usage(std::ostream& out) {
  out << "usage: drr_controller_sim [options]\n"
         "  --controller NAME   article | ue-style | robust | all (default all); repeatable or comma list\n"
         "  --scenario NAME     step2x | step-half | ramp | periodic | cpu-bound | spikes | nan | vsync60 |\n"
         "                      still | all (default all: these nine) | bursts | drift (the shared-machine\n"
         "                      loads of the tuning set); repeatable or comma list\n"
         "  --frames N          frames per run, " << drr::sim::kMinFrames << "..1000000 (default 900)\n"
         "  --seed N            noise seed, 0..4294967295 (default 20110228)\n"
         "  --noise X           relative GPU-time noise, 0..0.5 (default 0.01; still uses min(X, 0.002))\n"
         "  --noise-corr R      AR(1) correlation of that noise from frame to frame, 0..0.99 (default 0)\n"
         "  --headroom H        every law aims at T (1 - H), 0..0.5 (default 0.1; the article law is\n"
         "                      handed the budget T (1 - H), over budget still counts against T)\n"
         "  --synthetic-set     totals of every law on the synthetic set (the scenarios under latency\n"
         "                      0..3, white 1 % and AR(0.9) 3 % noise): the only cases tuning may use\n"
         "  --scan-robust       the robust law's tuning scan on the tuning set: the synthetic set, the\n"
         "                      shared-machine scenarios (bursts, drift) and --tuning-traces; never --traces\n"
         "  --scan-ue           the UE-style law's scan: the same tuning set, 24 rows as --scan-robust's\n"
         "  --tuning-traces DIR recorded tuning traces for --scan-robust and --scan-ue\n"
         "                      (Tests/controller/tuning-traces);\n"
         "                      a held-out trace in DIR is refused\n"
         "  --traces DIR        replay the held-out traces of DIR (Tests/controller/traces) instead\n"
         "                      of the scenarios, budget = the sweep's time at scale 0.7, latency as\n"
         "                      --latency (default: the sample's, 1)\n"
         "  --robust-before     also run the robust law as it was before the tuning-set scan, named\n"
         "                      robust-before (RobustController::PreviousParams)\n"
         "  --ue-tuned          also run the UE-style law with the tuning-set scan's pick, named\n"
         "                      ue-style-tuned (UEStyleController::TunedParams)\n"
         "  --headroom-sweep    instead of the tables: each law's totals at headrooms 0.05, 0.1, 0.2, 0.3\n"
         "                      (over budget against resolution given up), with --traces, --synthetic-set\n"
         "                      or the scenarios\n"
         "  --latency N         frames before a GPU time reaches the controller, 0..16 (default 1, the\n"
         "                      sample's on lavapipe); the robust and UE-style laws are told N\n"
         "  --gain K            gain of the article law, 0.001..10 (default 0.01)\n"
         "  --article-variant V original | frame-period | applied-scale | all: run the article law only,\n"
         "                      as the original (default feed), with the ctrl-frame-period fix, or\n"
         "                      integrating the applied scale (the port's former ratchet); repeatable\n"
         "  --feed F            original | per-result: what every law is fed (default: the article law\n"
         "                      original = 10-result average and 1 / once-a-second FPS, the others\n"
         "                      per-result = the newest GPU time and that frame's period)\n"
         "  --csv PATH          also write the table (or the sweep) as CSV\n"
         "  --per-frame PATH    also write every frame of every run as CSV (scale, budget scale, times,\n"
         "                      over budget, changed), for diagnosing a law\n"
         "  --sweep-k           sweep the article law's gain k over 0.001..10 instead of the matrix\n"
         "  --help              this text\n"
         "Plant: gpu = (2 ms + 30 ms * sx * sy * load) * (1 + noise N(0,1)), budget 1/60 s, headroom 10 %,\n"
         "scale in [0.3, 1], back buffer 1280x720; disturbance at frame 300.\n";
}

[[noreturn]] void Fail(const std::string& message) {
  std::cerr << "drr_controller_sim: " << message << "\n\n";
  Usage(std::cerr);
  std::exit(2);
}

bool ParseDouble(std::string_view text, double* out) {
  if (text.empty()) return false;
  std::string s(text);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

bool ParseInt(std::string_view text, long long lo, long long hi, long long* out) {
  long long v = 0;
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || p != text.data() + text.size() || v < lo || v > hi) return false;
  *out = v;
  return true;
}

std::vector<std::string_view> SplitCommas(std::string_view s) {
  std::vector<std::string_view> parts;
  while (true) {
    const auto comma = s.find(',');
    parts.push_back(s.substr(0, comma));
    if (comma == std::string_view::npos) break;
    s.remove_prefix(comma + 1);
  }
  return parts;
}

// Appends the laws of a comma list ("all" = every law).
void AddLaws(std::string_view list, std::vector<ControlLaw>* laws) {
  for (std::string_view name : SplitCommas(list)) {
    if (name == "all") {
      *laws = drr::sim::AllLaws();
      continue;
    }
    ControlLaw law;
    if (!drr::ParseControlLaw(name, &law)) Fail("unknown controller '" + std::string(name) + "'");
    laws->push_back(law);
  }
}

// Appends the scenarios of a comma list ("all" = every scenario).
void AddScenarios(std::string_view list, std::vector<Scenario>* scenarios) {
  for (std::string_view name : SplitCommas(list)) {
    if (name == "all") {
      *scenarios = drr::sim::AllScenarios();
      continue;
    }
    Scenario s;
    if (!drr::sim::ParseScenario(name, &s)) Fail("unknown scenario '" + std::string(name) + "'");
    scenarios->push_back(s);
  }
}

struct SimArgs {
  std::vector<ControlLaw> laws;  // empty: all
  std::vector<Scenario> scenarios;  // empty: all
  drr::sim::SimConfig config;
  double gain = drr::ArticleController::kDefaultGain;
  bool gainSet = false;
  std::string csvPath;
  bool sweep = false;
  std::vector<drr::sim::ArticleVariant> variants;  // non-empty: article variants instead of the laws
  std::string tracesDir;
  std::string tuningTracesDir;  // --tuning-traces: recorded traces the scan may use (none held out)
  std::string perFramePath;  // --per-frame: every frame of every run, for diagnosis
  bool syntheticSet = false;
  bool scanRobust = false;
  bool scanUE = false;
  bool robustBefore = false;   // also the robust law before the tuning-set scan ("robust-before")
  bool ueTuned = false;        // also the UE-style law with the scan's pick ("ue-style-tuned")
  bool headroomSweep = false;  // totals per law at each headroom of the scan instead of the tables
};

// The options' values: argv[*i + 1], moving *i past it; the usage exit when
// there is none.
struct ArgCursor {
  int argc;
  char** argv;
  int* i;
  std::string_view Value(std::string_view name) const {
    if (*i + 1 >= argc) Fail("missing value after " + std::string(name));
    return argv[++*i];
  }
};

// The on/off options; false when arg is none of them.
bool ParseFlag(std::string_view arg, SimArgs* args) {
  struct Flag {
    std::string_view name;
    bool SimArgs::*member;
  };
  static constexpr Flag kFlags[] = {{"--scan-robust", &SimArgs::scanRobust},     {"--scan-ue", &SimArgs::scanUE},
                                    {"--synthetic-set", &SimArgs::syntheticSet}, {"--robust-before", &SimArgs::robustBefore},
                                    {"--ue-tuned", &SimArgs::ueTuned},
                                    {"--headroom-sweep", &SimArgs::headroomSweep}, {"--sweep-k", &SimArgs::sweep}};
  for (const Flag& f : kFlags)
    if (arg == f.name) {
      args->*f.member = true;
      return true;
    }
  return false;
}

// The numbers of the runs, the plant and the laws; false when arg is none of
// them, the usage exit on a bad value.
bool ParseNumber(std::string_view arg, const ArgCursor& in, SimArgs* args) {
  drr::sim::SimConfig& config = args->config;
  long long n;
  double x;
  if (arg == "--frames") {
    if (!ParseInt(in.Value(arg), drr::sim::kMinFrames, 1000000, &n)) Fail("--frames needs an integer in range");
    config.frames = static_cast<int>(n);
  } else if (arg == "--seed") {
    if (!ParseInt(in.Value(arg), 0, 4294967295LL, &n)) Fail("--seed needs an integer 0..4294967295");
    config.seed = static_cast<std::uint32_t>(n);
  } else if (arg == "--noise") {
    if (!ParseDouble(in.Value(arg), &x) || x < 0.0 || x > 0.5) Fail("--noise needs a number 0..0.5");
    config.plant.noise = x;
  } else if (arg == "--noise-corr") {
    if (!ParseDouble(in.Value(arg), &x) || x < 0.0 || x > 0.99) Fail("--noise-corr needs a number 0..0.99");
    config.plant.noiseCorrelation = x;
  } else if (arg == "--headroom") {
    if (!ParseDouble(in.Value(arg), &x) || x < 0.0 || x > 0.5) Fail("--headroom needs a number 0..0.5");
    config.target.headroom = x;
  } else if (arg == "--latency") {
    if (!ParseInt(in.Value(arg), 0, 16, &n)) Fail("--latency needs an integer 0..16");
    config.plant.latencyFrames = static_cast<int>(n);
  } else if (arg == "--gain") {
    if (!ParseDouble(in.Value(arg), &args->gain) || args->gain < drr::ArticleController::kMinGain ||
        args->gain > drr::ArticleController::kMaxGain)
      Fail("--gain needs a number 0.001..10");
    args->gainSet = true;
  } else {
    return false;
  }
  return true;
}

// Appends the article variants of a comma list ("all" = the three).
void AddArticleVariants(std::string_view list, std::vector<drr::sim::ArticleVariant>* variants) {
  for (std::string_view name : SplitCommas(list)) {
    drr::sim::ArticleVariant v;
    if (name == "all") {
      *variants = {drr::sim::ArticleVariant::Original, drr::sim::ArticleVariant::FramePeriod,
                   drr::sim::ArticleVariant::AppliedScale};
    } else if (drr::sim::ParseArticleVariant(name, &v)) {
      variants->push_back(v);
    } else {
      Fail("unknown article variant '" + std::string(name) + "'");
    }
  }
}

// A non-empty path value of arg.
std::string PathValue(std::string_view arg, const ArgCursor& in, const char* what) {
  std::string path(in.Value(arg));
  if (path.empty()) Fail(std::string(arg) + " needs " + what);
  return path;
}

// The names, lists and paths; false when arg is none of them, the usage exit
// on a bad value.
bool ParseText(std::string_view arg, const ArgCursor& in, SimArgs* args) {
  if (arg == "--controller") {
    AddLaws(in.Value(arg), &args->laws);
  } else if (arg == "--scenario") {
    AddScenarios(in.Value(arg), &args->scenarios);
  } else if (arg == "--article-variant") {
    AddArticleVariants(in.Value(arg), &args->variants);
  } else if (arg == "--feed") {
    const std::string_view f = in.Value(arg);
    if (f == "original") args->config.feed = drr::Feed::Original;
    else if (f == "per-result") args->config.feed = drr::Feed::PerResult;
    else Fail("--feed needs original or per-result");
  } else if (arg == "--traces") {
    args->tracesDir = PathValue(arg, in, "a directory");
  } else if (arg == "--tuning-traces") {
    args->tuningTracesDir = PathValue(arg, in, "a directory");
  } else if (arg == "--csv") {
    args->csvPath = PathValue(arg, in, "a path");
  } else if (arg == "--per-frame") {
    args->perFramePath = PathValue(arg, in, "a path");
  } else {
    return false;
  }
  return true;
}

// Reads the option at argv[*i] and its value (moving *i past it); exits with
// the usage on a bad one.
void ParseOption(int argc, char** argv, int* i, SimArgs* args) {
  const std::string_view arg = argv[*i];
  const ArgCursor in{argc, argv, i};
  if (!ParseFlag(arg, args) && !ParseNumber(arg, in, args) && !ParseText(arg, in, args))
    Fail("unknown argument '" + std::string(arg) + "'");
}

// The options, with every law and scenario when none is named; false after --help.
bool ParseArgs(int argc, char** argv, SimArgs* args) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      Usage(std::cout);
      return false;
    }
    ParseOption(argc, argv, &i, args);
  }
  if (args->laws.empty()) args->laws = drr::sim::AllLaws();
  if (args->scenarios.empty()) args->scenarios = drr::sim::AllScenarios();
  return true;
}

// Which parameters a law runs with: its defaults (the sample's), the robust
// law's before the tuning-set scan, or the UE-style law's scan pick.
enum class LawParams { Default, RobustBefore, UETuned };

// A fresh controller of the law told the latency; the article law with
// --gain when given.
std::unique_ptr<drr::ResolutionController> MakeLaw(const SimArgs& args, ControlLaw law, LawParams params,
                                                   int latency) {
  if (law == ControlLaw::Article && args.gainSet) return std::make_unique<drr::ArticleController>(args.gain);
  if (params == LawParams::RobustBefore) {
    drr::RobustController::Params p = drr::RobustController::PreviousParams();
    p.latencyFrames = latency;
    return std::make_unique<drr::RobustController>(p);
  }
  if (params == LawParams::UETuned) {
    drr::UEStyleController::Params p = drr::UEStyleController::TunedParams();
    p.latencyFrames = latency;
    return std::make_unique<drr::UEStyleController>(p);
  }
  return drr::MakeController(law, latency);
}
// One law to run and the name its results carry.
struct LawRun {
  ControlLaw law;
  LawParams params;
  std::string Name() const {
    if (params == LawParams::RobustBefore) return "robust-before";
    if (params == LawParams::UETuned) return "ue-style-tuned";
    return drr::ControlLawOption(law);
  }
};
std::vector<LawRun> LawRuns(const SimArgs& args) {
  std::vector<LawRun> runs;
  for (ControlLaw law : args.laws) {
    if (law == ControlLaw::Robust && args.robustBefore) runs.push_back({law, LawParams::RobustBefore});
    runs.push_back({law, LawParams::Default});
    if (law == ControlLaw::UEStyle && args.ueTuned) runs.push_back({law, LawParams::UETuned});
  }
  return runs;
}

// Every law on every scenario.
std::vector<drr::sim::SimResult> RunLawsOnScenarios(const SimArgs& args) {
  const drr::sim::SimConfig& config = args.config;
  std::vector<drr::sim::SimResult> results;
  for (const LawRun& run : LawRuns(args)) {
    for (Scenario s : args.scenarios) {
      auto controller = MakeLaw(args, run.law, run.params, config.plant.latencyFrames);
      results.push_back(drr::sim::RunScenario(*controller, drr::sim::ConfigFor(s, config), !args.perFramePath.empty()));
      results.back().controller = run.Name();
    }
  }
  return results;
}

// Every law on every trace of --traces (exits on an unreadable directory).
std::vector<drr::sim::SimResult> RunLawsOnTraces(const SimArgs& args, bool print) {
  std::vector<drr::sim::TraceCase> cases;
  std::string error;
  if (!drr::sim::LoadTraceDir(args.tracesDir, &cases, &error)) {
    std::cerr << "drr_controller_sim: " << error << "\n";
    std::exit(1);
  }
  drr::sim::ReplaySpec spec;
  spec.headroom = args.config.target.headroom;
  spec.latencyFrames = args.config.plant.latencyFrames;
  std::vector<drr::sim::SimResult> results;
  for (const drr::sim::TraceCase& c : cases) {
    for (const LawRun& run : LawRuns(args)) {
      auto controller = MakeLaw(args, run.law, run.params, spec.latencyFrames);
      results.push_back(drr::sim::ReplayTraceWith(*controller, c.trace, c.cost, spec, !args.perFramePath.empty()));
      results.back().controller = run.Name();
    }
    if (print)
      std::cout << c.trace.name << (c.trace.HeldOut() ? " (held out)" : "") << ": " << c.trace.rows.size()
                << " frames, budget " << drr::sim::ReplayBudget(c.trace, c.cost, spec) * 1000.0 << " ms\n";
  }
  if (print)
    std::cout << "Replay: latency " << spec.latencyFrames << ", headroom " << spec.headroom << ", warm-up "
              << spec.warmupFrames << " frames from scale 1\n\n";
  std::stable_sort(results.begin(), results.end(), [](const auto& a, const auto& b) { return a.controller < b.controller; });
  return results;
}

// Every law on every scenario of every case of the synthetic set.
std::vector<drr::sim::SimResult> RunLawsOnSyntheticSet(const SimArgs& args, bool print) {
  std::vector<drr::sim::SimResult> results;
  for (const drr::sim::SyntheticCase& c : drr::sim::SyntheticSet(args.config)) {
    SimArgs one = args;
    one.config = c.base;
    const auto rows = RunLawsOnScenarios(one);
    if (print) {
      std::cout << "### " << c.label << "\n\n";
      drr::sim::PrintTable(std::cout, rows);
      std::cout << "\n";
    }
    results.insert(results.end(), rows.begin(), rows.end());
  }
  return results;
}

void PrintTotals(const std::vector<drr::sim::SimResult>& results, const char* firstColumn, const std::string& first,
                 bool header = true) {
  char line[240];
  if (header)
    std::cout << "| " << firstColumn << " | law | over budget | given up % | changes | still changes | never settled |\n"
            << "| --- | --- | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& t : drr::sim::Summarise(results)) {
    std::snprintf(line, sizeof line, "| %s | %-13s | %11d | %10.1f | %7d | %13d | %13d |\n", first.c_str(),
                  t.controller.c_str(), t.overBudget, t.givenUpPct, t.changes, t.stillChanges, t.neverSettled);
    std::cout << line;
  }
}

// --headroom-sweep: the totals of each law at each headroom of the scan.
void SweepHeadroom(const SimArgs& args) {
  bool header = true;
  for (double h : drr::sim::kScanHeadrooms) {
    SimArgs one = args;
    one.config.target.headroom = h;
    const auto results = !args.tracesDir.empty() ? RunLawsOnTraces(one, false)
                         : args.syntheticSet      ? RunLawsOnSyntheticSet(one, false)
                                                  : RunLawsOnScenarios(one);
    std::ostringstream label;
    label << h;
    PrintTotals(results, "headroom", label.str(), header);
    header = false;
  }
}

// The --csv table and the --per-frame rows, when asked for.
void WriteOutputs(const SimArgs& args, std::ofstream& csv, const std::vector<drr::sim::SimResult>& results) {
  if (csv.is_open()) drr::sim::WriteCsv(csv, results);
  if (args.perFramePath.empty()) return;
  std::ofstream perFrame(args.perFramePath);
  if (!perFrame) {
    std::cerr << "drr_controller_sim: cannot write '" << args.perFramePath << "'\n";
    std::exit(1);
  }
  drr::sim::WritePerFrameCsv(perFrame, results);
}

// --scan-robust, --scan-ue: the scan on the tuning set (held-out traces refused).
int RunScan(const SimArgs& args) {
  const drr::sim::SimConfig& config = args.config;
  if (!args.tracesDir.empty()) Fail("--scan-robust and --scan-ue tune on the tuning set only; --traces is held out");
  std::vector<drr::sim::TraceCase> tuning;
  std::string error;
  if (!args.tuningTracesDir.empty() && !drr::sim::LoadTraceDir(args.tuningTracesDir, &tuning, &error)) {
    std::cerr << "drr_controller_sim: " << error << "\n";
    return 1;
  }
  for (const drr::sim::TraceCase& c : tuning)
    if (c.trace.HeldOut()) Fail("'" + c.trace.name + "' is a held-out trace: it must not be used for tuning");
  if (args.scanUE) drr::sim::PrintUEStyleScan(std::cout, drr::sim::ScanUEStyle(config, tuning), config.target.headroom);
  else drr::sim::PrintRobustScan(std::cout, drr::sim::ScanRobust(config, tuning), config.target.headroom);
  return 0;
}

// The scenario table: every law, or the article variants, on every scenario,
// under the plant's line.
std::vector<drr::sim::SimResult> RunScenarioTable(const SimArgs& args) {
  const drr::sim::SimConfig& config = args.config;
  std::vector<drr::sim::SimResult> results;
  if (args.variants.empty()) {
    results = RunLawsOnScenarios(args);
  } else {
    for (drr::sim::ArticleVariant v : args.variants) {
      const auto rows = drr::sim::RunArticleVariant(v, args.scenarios, config);
      results.insert(results.end(), rows.begin(), rows.end());
    }
  }
  std::cout << "Plant: gpu = (2 ms + 30 ms * sx * sy * load) * (1 + " << config.plant.noise << " e), e AR(1) of "
            << config.plant.noiseCorrelation << ", budget 16.67 ms, every law aims at "
            << 1000.0 / 60.0 * (1.0 - config.target.headroom) << " ms"
            << (args.variants.empty() ? "" : " (article variants: at 16.67 ms, the original's)") << ", latency "
            << config.plant.latencyFrames << ", seed " << config.seed << ", " << config.frames
            << " frames, disturbance at 300\n\n";
  drr::sim::PrintTable(std::cout, results);
  return results;
}

}  // namespace

int main(int argc, char** argv) {
  SimArgs args;
  if (!ParseArgs(argc, argv, &args)) return 0;  // --help
  const drr::sim::SimConfig& config = args.config;

  std::ofstream csv;
  if (!args.csvPath.empty()) {
    csv.open(args.csvPath);
    if (!csv) {
      std::cerr << "drr_controller_sim: cannot write '" << args.csvPath << "'\n";
      return 1;
    }
  }

  if (args.sweep) {
    const auto rows = drr::sim::SweepArticleGain(config);
    drr::sim::PrintSweep(std::cout, rows, config);
    if (csv.is_open()) drr::sim::WriteSweepCsv(csv, rows);
    return 0;
  }
  if (args.scanRobust || args.scanUE) return RunScan(args);
  if (args.headroomSweep) {
    SweepHeadroom(args);
    return 0;
  }
  std::vector<drr::sim::SimResult> results;
  if (!args.tracesDir.empty()) {
    results = RunLawsOnTraces(args, true);
    drr::sim::PrintTable(std::cout, results);
  } else if (args.syntheticSet) {
    std::cout << "Synthetic set (latency " << "0..3, white 1 % and AR(0.9) 3 %), seed " << config.seed << "\n\n";
    results = RunLawsOnSyntheticSet(args, true);
    std::cout << "### whole synthetic set\n\n";
    PrintTotals(results, "set", "all");
  } else {
    results = RunScenarioTable(args);
  }
  WriteOutputs(args, csv, results);
  return 0;
}
