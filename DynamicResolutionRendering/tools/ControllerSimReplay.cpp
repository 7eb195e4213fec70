// Trace replay: see ControllerSimReplay.h.
#include "ControllerSimReplay.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <istream>
#include <sstream>

namespace drr::sim {
namespace {

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

bool ParseNumber(const std::string& text, double* out) {
  std::istringstream in(text);
  double v;
  if (!(in >> v) || !(in >> std::ws).eof() || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

// Frame n of a recorded trace at the applied scale.
class TracePlant final : public Plant {
public:
  TracePlant(const Trace& trace, const CostCurve& cost) : m_Cost(cost) {
    for (const TraceRow& r : trace.rows) m_Load.push_back(r.gpuSeconds / cost.Seconds(r.scale));
    const int n = static_cast<int>(m_Load.size());
    for (int i = 0; i < n; ++i) {
      std::vector<double> window;
      for (int j = std::max(0, i - 4); j <= std::min(n - 1, i + 4); ++j) window.push_back(m_Load[j]);
      m_Smooth.push_back(Median(window));
    }
  }
  // The budget: the median load's time at budgetScale.
  double Budget(double budgetScale) const { return Median(m_Load) * m_Cost.Seconds(budgetScale); }
  void SetTarget(const ControlTarget& target) {
    const ControlTarget t = SanitizeTarget(target);
    m_BudgetScale.clear();
    for (double load : m_Smooth) m_BudgetScale.push_back(m_Cost.ScaleFor(t.budgetSeconds / load, t.minScale, t.maxScale));
  }
  PlantFrame Frame(int n, double pixelFraction) override {
    const double unit = m_Cost.Seconds(std::sqrt(pixelFraction));
    PlantFrame f;
    f.model = m_Smooth[n] * unit;
    f.actual = m_Load[n] * unit;
    f.frameSeconds = f.actual;  // lavapipe: the CPU renders, so the frame is the GPU time
    f.load = m_Smooth[n];
    f.budgetScale = m_BudgetScale[n];
    return f;
  }

private:
  const CostCurve& m_Cost;
  std::vector<double> m_Load, m_Smooth, m_BudgetScale;
};

}  // namespace

bool Trace::HeldOut() const {
  return std::any_of(comments.begin(), comments.end(),
                     [](const std::string& c) { return c.find("held-out") != std::string::npos; });
}

bool ReadTrace(std::istream& in, const std::string& name, Trace* trace, std::string* error) {
  Trace t;
  t.name = name;
  std::string line;
  int lineNo = 0;
  bool header = false;
  auto fail = [&](const std::string& why) {
    *error = name + ":" + std::to_string(lineNo) + ": " + why;
    return false;
  };
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line[0] == '#') {
      t.comments.push_back(line.substr(1));
      continue;
    }
    if (!header) {
      if (line != "frame,scale,gpu_ms") return fail("expected the header 'frame,scale,gpu_ms'");
      header = true;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    double frame, scale, ms;
    if (cells.size() != 3 || !ParseNumber(cells[0], &frame) || !ParseNumber(cells[1], &scale) ||
        !ParseNumber(cells[2], &ms))
      return fail("expected three numbers 'frame,scale,gpu_ms'");
    if (!(scale > 0.0 && scale <= 2.0)) return fail("scale outside (0, 2]");
    if (!(ms > 0.0)) return fail("GPU time not > 0");
    if (!t.rows.empty() && frame <= static_cast<double>(t.rows.back().frame)) return fail("frames not increasing");
    t.rows.push_back({static_cast<long long>(frame), scale, ms / 1000.0});
  }
  if (t.rows.size() < 2) return fail("fewer than 2 rows");
  *trace = std::move(t);
  return true;
}

bool LoadTrace(const std::string& path, Trace* trace, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = "cannot read '" + path + "'";
    return false;
  }
  return ReadTrace(in, std::filesystem::path(path).stem().string(), trace, error);
}

bool CostCurve::FromSweep(const Trace& sweep, std::string* error) {
  std::vector<std::pair<double, std::vector<double>>> byScale;
  for (const TraceRow& r : sweep.rows) {
    auto it = std::find_if(byScale.begin(), byScale.end(),
                           [&](const auto& p) { return std::abs(p.first - r.scale) < 1e-3; });
    if (it == byScale.end()) byScale.push_back({r.scale, {}}), it = byScale.end() - 1;
    it->second.push_back(r.gpuSeconds);
  }
  if (byScale.size() < 2) {
    *error = sweep.name + ": a sweep needs at least 2 distinct scales";
    return false;
  }
  m_Points.clear();
  for (const auto& [s, times] : byScale) m_Points.push_back({s, Median(times)});
  std::sort(m_Points.begin(), m_Points.end());
  for (std::size_t i = 1; i < m_Points.size(); ++i)  // noise must not make a larger scale cheaper
    m_Points[i].second = std::max(m_Points[i].second, m_Points[i - 1].second);
  return true;
}

double CostCurve::Seconds(double scale) const {
  const double p = scale * scale;
  const auto& first = m_Points.front();
  if (scale <= first.first) return first.second * p / (first.first * first.first);
  for (std::size_t i = 1; i < m_Points.size(); ++i) {
    const auto& a = m_Points[i - 1];
    const auto& b = m_Points[i];
    const double pa = a.first * a.first, pb = b.first * b.first;
    if (scale <= b.first || i + 1 == m_Points.size())
      return std::max(a.second + (b.second - a.second) * (p - pa) / (pb - pa), 1e-9);
  }
  return m_Points.back().second;
}

double CostCurve::ScaleFor(double seconds, double lo, double hi) const {
  if (Seconds(lo) >= seconds) return lo;
  if (Seconds(hi) <= seconds) return hi;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Seconds(mid) < seconds ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {
LoopSpec ReplayLoop(const Trace& trace, const ReplaySpec& spec) {
  LoopSpec loop;
  loop.scenario = trace.name;
  loop.frames = static_cast<int>(trace.rows.size());
  loop.metricsFrom = std::clamp(spec.warmupFrames, 0, std::max(0, loop.frames - 1));
  loop.settleFrom = 0;  // the loop starts at scale 1, over the budget
  loop.settleIsFirstReach = true;  // a recorded load never keeps still
  loop.target.headroom = spec.headroom;
  loop.latencyFrames = spec.latencyFrames;
  return loop;
}
}  // namespace

SimResult ReplayTraceWith(ResolutionController& law, const Trace& trace, const CostCurve& cost, const ReplaySpec& spec,
                          bool keepTrace) {
  LoopSpec loop = ReplayLoop(trace, spec);
  TracePlant plant(trace, cost);
  loop.target.budgetSeconds = plant.Budget(spec.budgetScale);
  plant.SetTarget(loop.target);
  return RunLoop(law, plant, loop, keepTrace);
}

std::vector<SimResult> ReplayTrace(const std::vector<ControlLaw>& laws, const Trace& trace, const CostCurve& cost,
                                   const ReplaySpec& spec, bool keepTrace) {
  std::vector<SimResult> out;
  for (ControlLaw law : laws) {
    auto controller = MakeController(law, spec.latencyFrames);
    out.push_back(ReplayTraceWith(*controller, trace, cost, spec, keepTrace));
  }
  return out;
}

double ReplayBudget(const Trace& trace, const CostCurve& cost, const ReplaySpec& spec) {
  return TracePlant(trace, cost).Budget(spec.budgetScale);
}

bool LoadTraceDir(const std::string& dir, std::vector<TraceCase>* cases, std::string* error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> files;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (it->path().extension() == ".csv" && name.find("-sweep.csv") == std::string::npos) files.push_back(it->path());
  }
  if (ec) {
    *error = "cannot list '" + dir + "': " + ec.message();
    return false;
  }
  std::sort(files.begin(), files.end());
  cases->clear();
  for (const fs::path& f : files) {
    TraceCase c;
    const std::string stem = f.stem().string();
    Trace sweep;
    const fs::path sweepPath = f.parent_path() / (stem.substr(0, stem.find('-')) + "-sweep.csv");
    if (!LoadTrace(f.string(), &c.trace, error) || !LoadTrace(sweepPath.string(), &sweep, error) ||
        !c.cost.FromSweep(sweep, error))
      return false;
    cases->push_back(std::move(c));
  }
  if (cases->empty()) {
    *error = "no traces in '" + dir + "'";
    return false;
  }
  return true;
}

}  // namespace drr::sim
