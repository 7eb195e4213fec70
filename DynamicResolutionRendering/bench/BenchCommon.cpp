#include "bench/BenchCommon.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace drr {
namespace {

double Percentile(std::vector<double> v, double p) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double pos = p * double(v.size() - 1);
  const size_t i = size_t(pos);
  const double f = pos - double(i);
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

}  // namespace

std::string Num2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.2f", v);
  return buf;
}

Stat Summarise(const std::vector<double>& v) {
  return {Percentile(v, 0.5), Percentile(v, 0.25), Percentile(v, 0.75)};
}

ImageF ToImage(const Image& img) {
  return ImageFromRGBA8(img.pixels.data(), img.width, img.height, img.width * 4);
}

double StudentT95(int dof) {
  static const double t[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228};
  if (dof < 1) return std::nan("");
  return dof <= 10 ? t[dof - 1] : dof <= 30 ? 2.042 + (2.228 - 2.042) * (30 - dof) / 20.0 : 1.96;
}

MeanCi BlockMeanCi(const std::vector<double>& perFrame, int blocks) {
  std::vector<double> v;
  for (double x : perFrame)
    if (std::isfinite(x)) v.push_back(x);
  MeanCi r{std::nan(""), std::nan("")};
  if (v.empty()) return r;
  double sum = 0;
  for (double x : v) sum += x;
  r.mean = sum / double(v.size());
  const size_t n = std::min<size_t>(size_t(std::max(blocks, 0)), v.size());
  if (n < 2) return r;
  const size_t per = v.size() / n;  // the last block takes the remainder
  std::vector<double> means;
  for (size_t b = 0; b < n; ++b) {
    const size_t from = b * per, to = b + 1 == n ? v.size() : from + per;
    double s = 0;
    for (size_t i = from; i < to; ++i) s += v[i];
    means.push_back(s / double(to - from));
  }
  double m = 0, var = 0;
  for (double x : means) m += x;
  m /= double(n);
  for (double x : means) var += (x - m) * (x - m);
  var /= double(n - 1);
  r.halfWidth = StudentT95(int(n) - 1) * std::sqrt(var / double(n));
  return r;
}

MeanCi PairedDifferenceCi(const std::vector<double>& a, const std::vector<double>& b, int blocks) {
  std::vector<double> d;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (std::isfinite(a[i]) && std::isfinite(b[i])) d.push_back(a[i] - b[i]);
  return BlockMeanCi(d, blocks);
}

int SideOf(const MeanCi& d, double threshold) {
  if (!std::isfinite(d.mean) || !std::isfinite(d.halfWidth)) return 0;
  if (d.mean - d.halfWidth > threshold) return 1;
  if (d.mean + d.halfWidth < threshold) return -1;
  return 0;
}

std::vector<FrameRecord> RenderFrames(Sample& sample, int frames) {
  const size_t before = sample.Frames().size();
  for (int i = 0; i < frames; ++i) sample.RenderFrame();
  const auto& all = sample.Frames();
  return std::vector<FrameRecord>(all.begin() + std::ptrdiff_t(std::min(before, all.size())), all.end());
}

void WarmUpFor(Sample& sample, int ms) {
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(ms)) sample.RenderFrame();
}

Image Capture(Sample& sample) {
  sample.RequestCapture();
  sample.RenderFrame();
  return sample.CapturedBackBufferNoGui();
}

Options ViewOptions(const BenchPlan& plan, const BenchView& view) {
  Options o = plan.base;
  o.headless = true;
  o.gui = false;
  o.camera = view.camera;
  o.time = view.time;
  o.fixedDt = 0.0;  // the sweep renders one fixed animation time per view
  o.control = ControlMode::Manual;
  o.controlGiven = true;
  o.scaleGiven = true;
  o.vsync = false;
  o.screenshot.clear();
  o.report.clear();
  return o;
}

void FillGpuTimes(const std::vector<std::vector<FrameRecord>>& rounds, BenchRow* row) {
  std::vector<double> f, c, sc, p, scl, wall;
  // A result lags gpuFrameDelay frames; a record without a new result
  // repeats an older one and is not a sample.
  row->roundFrameMs.clear(), row->roundClearMs.clear(), row->roundScaleMs.clear();
  for (const std::vector<FrameRecord>& records : rounds) {
  const size_t before = f.size();
  const int64_t firstMeasured = records.empty() ? 0 : records.front().frame;
  for (const FrameRecord& r : records) {
    wall.push_back(r.cpuFrameMs);
    if (!r.gpuFrameNew || r.frame - int64_t(r.gpuFrameDelay) < firstMeasured) continue;
    f.push_back(r.gpuFrame);
    c.push_back(r.gpuClear);
    sc.push_back(r.gpuScene);
    p.push_back(r.gpuPostP);
    scl.push_back(r.gpuScale);
  }
  if (rounds.size() > 1) {
    auto median = [&](const std::vector<double>& v) {
      return Percentile(std::vector<double>(v.begin() + std::ptrdiff_t(before), v.end()), 0.5);
    };
    row->roundFrameMs.push_back(median(f));
    row->roundClearMs.push_back(median(c));
    row->roundScaleMs.push_back(median(scl));
  }
  }
  row->gpuSamples = int(f.size());
  row->gpuFrame = Summarise(f);
  row->gpuClear = Summarise(c);
  row->gpuScene = Summarise(sc);
  row->gpuPost = Summarise(p);
  row->gpuScale = Summarise(scl);
  row->wall = Summarise(wall);
}

double RoundSpread(const std::vector<double>& perRound) {
  double lo = INFINITY, hi = -INFINITY;
  int n = 0;
  for (double v : perRound)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v), ++n;
  return n >= 2 ? hi - lo : std::nan("");
}

Progress::Progress(size_t total) : total_(total), tty_(isatty(2)) {}

void Progress::Step(const std::string& what) {
  ++done_;
  total_ = std::max(total_, done_);
  const int width = 30;
  const int filled = int(width * done_ / std::max<size_t>(total_, 1));
  if (tty_) {
    std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu %-40.40s", filled, "==============================", width - filled,
                 "", done_, total_, what.c_str());
    if (done_ == total_) std::fprintf(stderr, "\n");
  } else {
    std::fprintf(stderr, "bench %zu/%zu %s\n", done_, total_, what.c_str());
  }
  std::fflush(stderr);
}

// TAA at 0.71, TAAU at 0.71 and (not in the quick preset) at 0.5, where its bias is -1.
std::vector<MipBiasAblation> MipBiasAblations(const BenchPlan& plan) {
  std::vector<MipBiasAblation> rows = {
      {kTaaNoMipBias, [](Options& s) { s.filter = Filter::TAA, s.scaleX = s.scaleY = 0.71f, s.taaMipBias = false; }},
      {kTaauNoMipBias, [](Options& s) { s.filter = Filter::TAAU, s.scaleX = s.scaleY = 0.71f, s.autoMipBias = false; }},
  };
  if (!plan.quick)
    rows.push_back({kTaauNoMipBias, [](Options& s) { s.filter = Filter::TAAU, s.scaleX = s.scaleY = 0.5f, s.autoMipBias = false; }});
  return rows;
}

}  // namespace drr
