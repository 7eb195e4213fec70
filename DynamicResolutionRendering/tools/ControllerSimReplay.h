// Replays GPU-time traces recorded from the sample (ControllerSimRecord.sh)
// as a plant of the closed-loop simulator. The traces are held out: no code
// path that tunes a law reads them (Docs/Controller.md); they are replayed to
// judge the laws once.
//
// A trace row pairs the GPU time of a frame with the scale that frame was
// rendered at. With the scene's cost curve t(s) (a sweep of scales, the
// animation paused) the replay renders frame n at scale s in
//   actual(n, s) = L(n) t(s),  L(n) = recorded(n) / t(recorded scale(n))
// and takes as noise-free time model(n, s) = Ls(n) t(s), Ls = the centred
// 9-frame median of L. The budget is median(L) t(budgetScale): the time of
// the trace's median load at budgetScale (0.7 unless told), so that every
// trace asks for a scale inside the range whatever the machine's load was.
// The settle column of a replay is the first frame within the band (a
// recorded load never keeps still).
#pragma once

#include "ControllerSimCore.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace drr::sim {

struct TraceRow {
  long long frame = 0;
  double scale = 1.0;       // scale per axis the frame was rendered at
  double gpuSeconds = 0.0;  // its inner-frame GPU time
};

struct Trace {
  std::string name;
  std::vector<std::string> comments;  // the '#' header lines, without '#'
  std::vector<TraceRow> rows;
  bool HeldOut() const;               // a header line says "held-out"
};

// CSV "frame,scale,gpu_ms" after '#' lines. false with a message naming the
// line for anything else (a bad number, a scale outside (0, 2], a time not
// finite and > 0, frames not increasing, fewer than 2 rows).
bool ReadTrace(std::istream& in, const std::string& name, Trace* trace, std::string* error);
bool LoadTrace(const std::string& path, Trace* trace, std::string* error);

// t(s) from a sweep trace: the median time of each distinct scale, made
// non-decreasing in s, interpolated linearly in pixels (s^2) and extrapolated
// proportionally to s^2 below the smallest scale and along the last segment
// above the largest.
class CostCurve {
public:
  bool FromSweep(const Trace& sweep, std::string* error);
  double Seconds(double scale) const;
  // The scale in [lo, hi] whose time is `seconds` (lo or hi when out of reach).
  double ScaleFor(double seconds, double lo, double hi) const;
  const std::vector<std::pair<double, double>>& Points() const { return m_Points; }

private:
  std::vector<std::pair<double, double>> m_Points;  // (scale, seconds), increasing scale
};

struct ReplaySpec {
  double budgetScale = 0.7;  // budget T = median load x t(budgetScale)
  double headroom = 0.1;
  int warmupFrames = 30;     // metrics start here; the loop starts at scale 1
  int latencyFrames = kSampleTimerLatency;
};

// The budget a replay of the trace uses (seconds).
double ReplayBudget(const Trace& trace, const CostCurve& cost, const ReplaySpec& spec);

// Each law on the trace (a fresh controller per run, told the latency).
std::vector<SimResult> ReplayTrace(const std::vector<ControlLaw>& laws, const Trace& trace, const CostCurve& cost,
                                   const ReplaySpec& spec, bool keepTrace = false);

// One law (already made, told the latency) on the trace.
SimResult ReplayTraceWith(ResolutionController& law, const Trace& trace, const CostCurve& cost, const ReplaySpec& spec,
                          bool keepTrace = false);

// Every "*.csv" of dir except "*-sweep.csv", in name order, each with the
// sweep "<prefix>-sweep.csv" of its scene (prefix: the name up to its first
// '-'). false with a message when a file is unreadable or a sweep is missing.
struct TraceCase {
  Trace trace;
  CostCurve cost;
};
bool LoadTraceDir(const std::string& dir, std::vector<TraceCase>* cases, std::string* error);

}  // namespace drr::sim
