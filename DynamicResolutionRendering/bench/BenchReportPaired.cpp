// The image-quality claims of summary.md judged on paired intervals: two
// configurations are compared frame by frame (moving: the same animation
// times; the per-frame differences in 6 blocks of consecutive frames, since
// neighbouring frames are correlated) or view by view (still: one pair per
// view), mean +- t s / sqrt(n) of the differences. Where the interval spans
// the claim's threshold, or PSNR and FLIP point different ways, the verdict
// is "cannot decide".
#include <cmath>

#include "bench/Bench.h"
#include "bench/BenchCommon.h"
#include "bench/BenchReportSections.h"

namespace drr {
namespace {

constexpr int kFrameBlocks = 6;

// A metric of a row and of its frames.
struct Metric {
  const char* name;
  double (*row)(const BenchRow&);
  const std::vector<double>& (*frames)(const BenchRow&);
};
const Metric kPsnr{"PSNR", [](const BenchRow& r) { return r.error.psnr; },
                   [](const BenchRow& r) -> const std::vector<double>& { return r.framePsnr; }};
const Metric kFlip{"FLIP", [](const BenchRow& r) { return r.flip; },
                   [](const BenchRow& r) -> const std::vector<double>& { return r.frameFlip; }};

const BenchRow* MovingRow(const BenchResults& res, double speed, const std::string& filter, double scale) {
  for (const BenchRow& r : res.rows)
    if (r.moving && SameScale(r.speed, speed) && r.filter == filter && SameScale(r.scale, scale)) return &r;
  return nullptr;
}

// Per view of the plan, the still row's value (NaN where missing).
std::vector<double> PerView(const BenchResults& res, const std::string& filter, double scale, const Metric& m) {
  std::vector<double> v;
  for (const BenchView& view : res.plan->views) {
    double x = std::nan("");
    for (const BenchRow& r : res.rows)
      if (!r.moving && r.view == view.name && r.filter == filter && SameScale(r.scale, scale)) x = m.row(r);
    v.push_back(x);
  }
  return v;
}

// a - k b per frame of two moving rows (k scales b: a threshold relative to b).
MeanCi MovingDifference(const BenchRow* a, const BenchRow* b, const Metric& m, double k = 1.0) {
  if (!a || !b) return {std::nan(""), std::nan("")};
  std::vector<double> scaled = m.frames(*b);
  for (double& x : scaled) x *= k;
  return PairedDifferenceCi(m.frames(*a), scaled, kFrameBlocks);
}

// Both differences have an interval (a run without per-frame values has none).
bool Measured(const MeanCi& a, const MeanCi& b) {
  return std::isfinite(a.mean) && std::isfinite(a.halfWidth) && std::isfinite(b.mean) && std::isfinite(b.halfWidth);
}
constexpr const char* kNoFrames = "cannot decide (no per-frame values, or fewer than 2 blocks)";

std::string Interval(const MeanCi& d, int decimals) {
  return FormatCell(d.mean, decimals) + " ± " + FormatCell(d.halfWidth, decimals);
}

// "agree" / "disagree" / "cannot decide" from the sides of the PSNR and FLIP
// intervals (+1: the claim holds for that metric, -1: it fails, 0: spans).
std::string Decide(int psnr, int flip) {
  if (psnr > 0 && flip > 0) return "agree (PSNR and FLIP)";
  if (psnr < 0 && flip < 0) return "disagree (PSNR and FLIP)";
  if (psnr == 0 || flip == 0) return "cannot decide (an interval spans the threshold)";
  return "cannot decide (PSNR and FLIP disagree)";
}

void ClaimTaaNearNative(const BenchResults& res, std::ostringstream& md) {
  const double speed = ReportSpeed(res);
  const BenchRow *t71 = MovingRow(res, speed, "taa", 0.71), *nat = MovingRow(res, speed, "native", 1.0);
  // The claim holds when native's PSNR is less than 1.5 dB above and TAA's FLIP
  // under 1.1 x native's, with the interval wholly on that side.
  const MeanCi dp = MovingDifference(nat, t71, kPsnr), df = MovingDifference(t71, nat, kFlip, 1.1);
  std::ostringstream o;
  o << "moving x" << FormatCell(speed, 2) << ", paired per frame (" << kFrameBlocks << " blocks): native - taa 0.71 PSNR "
    << Interval(dp, 2) << " dB (threshold 1.5); taa FLIP - 1.1 x native's " << Interval(df, 4) << " (threshold 0)";
  const std::string v = !t71 || !nat        ? "cannot measure (no moving rows)"
                        : !Measured(dp, df) ? kNoFrames
                                            : Decide(-SideOf(dp, 1.5), -SideOf(df, 0.0));
  ClaimLine(md, "TAA at 0.71x gives almost full-resolution quality (moving camera)", o.str(), v);
}

void ClaimTaaBeatsNative(const BenchResults& res, std::ostringstream& md) {
  const double speed = ReportSpeed(res);
  const BenchRow* nat = MovingRow(res, speed, "native", 1.0);
  std::ostringstream o;
  std::string v;
  for (const char* name : {"taa", kTaaSymmetric}) {
    const BenchRow* t = MovingRow(res, speed, name, 1.0);
    if (!t || !nat) continue;
    const MeanCi dp = MovingDifference(t, nat, kPsnr), df = MovingDifference(t, nat, kFlip);
    o << name << " 1.0 - native, paired per frame: PSNR " << Interval(dp, 2) << " dB, FLIP " << Interval(df, 4) << "; ";
    v += std::string(name) + ": " + (Measured(dp, df) ? Decide(SideOf(dp, 0.0), -SideOf(df, 0.0)) : kNoFrames) + "; ";
  }
  ClaimLine(md, "TAA at >= 1.0x acts as anti-aliasing (better than native)", o.str(),
            v.empty() ? "cannot measure (no moving rows)" : v);
}

// Counts of the bicubic - bilinear verdicts over scale points.
struct Tally {
  int better = 0, worse = 0, negligible = 0, undecided = 0;
  int Total() const { return better + worse + negligible + undecided; }
};

void Judge(const MeanCi& dp, const MeanCi& df, const std::string& where, std::ostringstream& o, Tally* t) {
  if (!std::isfinite(dp.mean)) return;
  o << where << ": " << Interval(dp, 2) << " dB, FLIP " << Interval(df, 4) << "; ";
  const bool tiny = SideOf(dp, 0.1) < 0 && SideOf(dp, -0.1) > 0 && SideOf(df, 0.001) < 0 && SideOf(df, -0.001) > 0;
  const int p = SideOf(dp, 0.0), f = -SideOf(df, 0.0);
  if (tiny) ++t->negligible;
  else if (p == 0 || f == 0 || p != f) ++t->undecided;
  else if (p > 0) ++t->better;
  else ++t->worse;
}

}  // namespace

void ClaimTaaQuality(const BenchResults& res, std::ostringstream& md) {
  ClaimTaaNearNative(res, md);
  ClaimTaaBeatsNative(res, md);
}

void ClaimBicubicQuality(const BenchResults& res, std::ostringstream& md) {
  std::ostringstream o;
  Tally t;
  const int views = int(res.plan->views.size());
  for (float s : res.plan->scales)
    if (s <= 1.0f)
      Judge(PairedDifferenceCi(PerView(res, "bicubic", s, kPsnr), PerView(res, "bilinear", s, kPsnr), views),
            PairedDifferenceCi(PerView(res, "bicubic", s, kFlip), PerView(res, "bilinear", s, kFlip), views),
            "still " + FormatCell(s, 2) + " (per view)", o, &t);
  const double speed = ReportSpeed(res);
  for (float s : res.plan->movingScales) {
    const BenchRow *bc = MovingRow(res, speed, "bicubic", s), *bl = MovingRow(res, speed, "bilinear", s);
    if (bc && bl && (bc->framePsnr.empty() || bl->framePsnr.empty())) {
      o << "moving " << FormatCell(s, 2) << ": no per-frame values in this run; ";
      continue;
    }
    Judge(MovingDifference(bc, bl, kPsnr), MovingDifference(bc, bl, kFlip), "moving " + FormatCell(s, 2) + " (per frame)", o, &t);
  }
  std::string v = "better at " + std::to_string(t.better) + ", worse at " + std::to_string(t.worse) +
                  ", within 0.1 dB and 0.001 FLIP at " + std::to_string(t.negligible) + ", cannot decide at " +
                  std::to_string(t.undecided) + " (an interval spans 0, or PSNR and FLIP disagree) of " +
                  std::to_string(t.Total()) + " scale points";
  if (t.Total() == 0) v = "cannot measure";
  else if ((t.undecided + t.negligible) * 2 >= t.Total()) v = "cannot decide: " + v;
  else v = (t.better > t.worse ? "partly agree (better, not only at 0.5x): " : "disagree: ") + v;
  ClaimLine(md, "Bicubic only slightly better than bilinear, and only at 0.5x",
            "bicubic - bilinear, paired differences: " + o.str(), v);
}

}  // namespace drr
