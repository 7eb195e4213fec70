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
         "                      still | all (default all); repeatable or comma list\n"
         "  --frames N          frames per run, " << drr::sim::kMinFrames << "..1000000 (default 900)\n"
         "  --seed N            noise seed, 0..4294967295 (default 20110228)\n"
         "  --noise X           relative GPU-time noise, 0..0.5 (default 0.01; still uses min(X, 0.002))\n"
         "  --noise-corr R      AR(1) correlation of that noise from frame to frame, 0..0.99 (default 0)\n"
         "  --headroom H        every law aims at T (1 - H), 0..0.5 (default 0.1; the article law is\n"
         "                      handed the budget T (1 - H), over budget still counts against T)\n"
         "  --synthetic-set     totals of every law on the synthetic set (the scenarios under latency\n"
         "                      0..3, white 1 % and AR(0.9) 3 % noise): the only cases tuning may use\n"
         "  --scan-robust       the robust law's tuning scan on the synthetic set (never the traces)\n"
         "  --traces DIR        replay the held-out traces of DIR (Tests/controller/traces) instead\n"
         "                      of the scenarios, budget = the sweep's time at scale 0.7, latency as\n"
         "                      --latency (default: the sample's, 1)\n"
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
  bool syntheticSet = false;
  bool scanRobust = false;
};

// Reads the option at argv[*i] and its value (moving *i past it); exits with
// the usage on a bad one.
void ParseOption(int argc, char** argv, int* i, SimArgs* args) {
  const std::string_view arg = argv[*i];
  auto value = [&](std::string_view name) -> std::string_view {
    if (*i + 1 >= argc) Fail("missing value after " + std::string(name));
    return argv[++*i];
  };
  drr::sim::SimConfig& config = args->config;
  long long n;
  double x;
  if (arg == "--controller") {
    AddLaws(value(arg), &args->laws);
  } else if (arg == "--scenario") {
    AddScenarios(value(arg), &args->scenarios);
  } else if (arg == "--frames") {
    if (!ParseInt(value(arg), drr::sim::kMinFrames, 1000000, &n)) Fail("--frames needs an integer in range");
    config.frames = static_cast<int>(n);
  } else if (arg == "--seed") {
    if (!ParseInt(value(arg), 0, 4294967295LL, &n)) Fail("--seed needs an integer 0..4294967295");
    config.seed = static_cast<std::uint32_t>(n);
  } else if (arg == "--noise") {
    if (!ParseDouble(value(arg), &x) || x < 0.0 || x > 0.5) Fail("--noise needs a number 0..0.5");
    config.plant.noise = x;
  } else if (arg == "--noise-corr") {
    if (!ParseDouble(value(arg), &x) || x < 0.0 || x > 0.99) Fail("--noise-corr needs a number 0..0.99");
    config.plant.noiseCorrelation = x;
  } else if (arg == "--headroom") {
    if (!ParseDouble(value(arg), &x) || x < 0.0 || x > 0.5) Fail("--headroom needs a number 0..0.5");
    config.target.headroom = x;
  } else if (arg == "--scan-robust") {
    args->scanRobust = true;
  } else if (arg == "--synthetic-set") {
    args->syntheticSet = true;
  } else if (arg == "--traces") {
    args->tracesDir = std::string(value(arg));
    if (args->tracesDir.empty()) Fail("--traces needs a directory");
  } else if (arg == "--latency") {
    if (!ParseInt(value(arg), 0, 16, &n)) Fail("--latency needs an integer 0..16");
    config.plant.latencyFrames = static_cast<int>(n);
  } else if (arg == "--gain") {
    if (!ParseDouble(value(arg), &args->gain) || args->gain < drr::ArticleController::kMinGain ||
        args->gain > drr::ArticleController::kMaxGain)
      Fail("--gain needs a number 0.001..10");
    args->gainSet = true;
  } else if (arg == "--article-variant") {
    for (std::string_view name : SplitCommas(value(arg))) {
      drr::sim::ArticleVariant v;
      if (name == "all") {
        args->variants = {drr::sim::ArticleVariant::Original, drr::sim::ArticleVariant::FramePeriod,
                          drr::sim::ArticleVariant::AppliedScale};
      } else if (drr::sim::ParseArticleVariant(name, &v)) {
        args->variants.push_back(v);
      } else {
        Fail("unknown article variant '" + std::string(name) + "'");
      }
    }
  } else if (arg == "--feed") {
    const std::string_view f = value(arg);
    if (f == "original") config.feed = drr::Feed::Original;
    else if (f == "per-result") config.feed = drr::Feed::PerResult;
    else Fail("--feed needs original or per-result");
  } else if (arg == "--csv") {
    args->csvPath = std::string(value(arg));
    if (args->csvPath.empty()) Fail("--csv needs a path");
  } else if (arg == "--sweep-k") {
    args->sweep = true;
  } else {
    Fail("unknown argument '" + std::string(arg) + "'");
  }
}

// Every law on every scenario; the article law with --gain when given.
std::vector<drr::sim::SimResult> RunLawsOnScenarios(const SimArgs& args) {
  const drr::sim::SimConfig& config = args.config;
  std::vector<drr::sim::SimResult> results;
  for (ControlLaw law : args.laws) {
    for (Scenario s : args.scenarios) {
      std::unique_ptr<drr::ResolutionController> controller =
          (law == ControlLaw::Article && args.gainSet) ? std::make_unique<drr::ArticleController>(args.gain)
                                                       : drr::MakeController(law, config.plant.latencyFrames);
      results.push_back(drr::sim::RunScenario(*controller, drr::sim::ConfigFor(s, config)));
    }
  }
  return results;
}

}  // namespace

int main(int argc, char** argv) {
  SimArgs args;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      Usage(std::cout);
      return 0;
    }
    ParseOption(argc, argv, &i, &args);
  }
  if (args.laws.empty()) args.laws = drr::sim::AllLaws();
  if (args.scenarios.empty()) args.scenarios = drr::sim::AllScenarios();
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

  std::vector<drr::sim::SimResult> results;
  if (args.scanRobust) {
    if (!args.tracesDir.empty()) Fail("--scan-robust tunes on the synthetic set only; --traces is held out");
    drr::sim::PrintRobustScan(std::cout, drr::sim::ScanRobustOnSyntheticSet(config));
    return 0;
  }
  if (!args.tracesDir.empty()) {
    std::vector<drr::sim::TraceCase> cases;
    std::string error;
    if (!drr::sim::LoadTraceDir(args.tracesDir, &cases, &error)) {
      std::cerr << "drr_controller_sim: " << error << "\n";
      return 1;
    }
    drr::sim::ReplaySpec spec;
    spec.headroom = config.target.headroom;
    spec.latencyFrames = config.plant.latencyFrames;
    for (const drr::sim::TraceCase& c : cases) {
      const auto rows = drr::sim::ReplayTrace(args.laws, c.trace, c.cost, spec);
      results.insert(results.end(), rows.begin(), rows.end());
      std::cout << c.trace.name << (c.trace.HeldOut() ? " (held out)" : "") << ": " << c.trace.rows.size()
                << " frames, budget " << drr::sim::ReplayBudget(c.trace, c.cost, spec) * 1000.0 << " ms\n";
    }
    std::cout << "Replay: latency " << spec.latencyFrames << ", headroom " << spec.headroom << ", warm-up "
              << spec.warmupFrames << " frames from scale 1\n\n";
    std::stable_sort(results.begin(), results.end(), [](const auto& a, const auto& b) { return a.controller < b.controller; });
    drr::sim::PrintTable(std::cout, results);
    if (csv.is_open()) drr::sim::WriteCsv(csv, results);
    return 0;
  }
  if (args.syntheticSet) {
    std::cout << "Synthetic set (latency " << "0..3, white 1 % and AR(0.9) 3 %), seed " << config.seed << "\n\n";
    for (const drr::sim::SyntheticCase& c : drr::sim::SyntheticSet(config)) {
      std::cout << "### " << c.label << "\n\n";
      SimArgs one = args;
      one.config = c.base;
      const auto rows = RunLawsOnScenarios(one);
      drr::sim::PrintTable(std::cout, rows);
      std::cout << "\n";
      results.insert(results.end(), rows.begin(), rows.end());
    }
    std::cout << "### whole synthetic set\n\n";
    char line[200];
    std::cout << "| law | over budget | given up % | changes | still changes | never settled |\n"
                 "| --- | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto& t : drr::sim::Summarise(results)) {
      std::snprintf(line, sizeof line, "| %-9s | %11d | %10.1f | %7d | %13d | %13d |\n", t.controller.c_str(),
                    t.overBudget, t.givenUpPct, t.changes, t.stillChanges, t.neverSettled);
      std::cout << line;
    }
    if (csv.is_open()) drr::sim::WriteCsv(csv, results);
    return 0;
  }
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
  if (csv.is_open()) drr::sim::WriteCsv(csv, results);
  return 0;
}
