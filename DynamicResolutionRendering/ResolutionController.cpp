// Resolution control laws. See ResolutionController.h and Docs/Controller.md.
#include "ResolutionController.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace drr {
namespace {

bool FinitePositive(double v) { return std::isfinite(v) && v > 0.0; }

double Median(std::vector<double> values) {  // by value: sorted copy
  const std::size_t n = values.size();
  if (n == 0) return 0.0;
  std::sort(values.begin(), values.end());
  return (n % 2) ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double AimOf(const ControlTarget& sanitized) { return sanitized.budgetSeconds * (1.0 - sanitized.headroom); }

// One row per enumerator, in the enum's order: GUI name, command-line value.
struct EnumNames {
  const char* name;
  const char* option;
};
constexpr EnumNames kLawNames[] = {{"Article (original)", "article"}, {"Robust", "robust"}, {"UE-style", "ue-style"}};
constexpr EnumNames kModeNames[] = {{"Manual", "manual"}, {"VSync/2", "half-vsync"}, {"VSync", "vsync"}};
static_assert(std::size(kLawNames) == static_cast<std::size_t>(ControlLaw::Count));
static_assert(std::size(kModeNames) == static_cast<std::size_t>(ControlMode::Count));

template <class Enum, std::size_t N>
const EnumNames& Row(const EnumNames (&table)[N], Enum e) {
  static constexpr EnumNames kUnknown{"?", "?"};
  const auto i = static_cast<std::size_t>(e);
  return i < N ? table[i] : kUnknown;
}

}  // namespace

const char* ControlLawName(ControlLaw law) { return Row(kLawNames, law).name; }
const char* ControlLawOption(ControlLaw law) { return Row(kLawNames, law).option; }
const char* ControlModeName(ControlMode mode) { return Row(kModeNames, mode).name; }
const char* ControlModeOption(ControlMode mode) { return Row(kModeNames, mode).option; }

bool ParseControlLaw(std::string_view name, ControlLaw* law) {
  ControlLaw found = ControlLaw::Count;
  if (name == "ue") found = ControlLaw::UEStyle;
  for (int i = 0; i < static_cast<int>(ControlLaw::Count); ++i)
    if (name == kLawNames[i].option) found = static_cast<ControlLaw>(i);
  if (found == ControlLaw::Count) return false;
  if (law) *law = found;
  return true;
}

double TargetFrameSeconds(double refreshHz, ControlMode mode) {
  if (!FinitePositive(refreshHz)) refreshHz = 60.0;
  const double period = 1.0 / refreshHz;
  return mode == ControlMode::HalfVSync ? 2.0 * period : period;
}

ControlTarget SanitizeTarget(const ControlTarget& in) {
  ControlTarget t = in;
  if (!FinitePositive(t.budgetSeconds)) t.budgetSeconds = 1.0 / 60.0;
  if (!(std::isfinite(t.headroom) && t.headroom >= 0.0 && t.headroom <= 0.9)) t.headroom = 0.1;
  if (!FinitePositive(t.minScale)) t.minScale = 0.3;
  if (!(std::isfinite(t.maxScale) && t.maxScale >= t.minScale)) t.maxScale = std::max(1.0, t.minScale);
  return t;
}

double ClampScale(double scale, const ControlTarget& t) {
  if (!std::isfinite(scale)) scale = 1.0;
  return std::clamp(scale, t.minScale, t.maxScale);
}

double ResolutionController::AimSeconds(const ControlTarget& target) const {
  return AimOf(SanitizeTarget(target));
}

bool IsCpuBoundFrame(const FrameTiming& timing, const ControlTarget& target) {
  const ControlTarget t = SanitizeTarget(target);
  // 2 % tolerance: a vsync-quantised frame of exactly T is not "late".
  return FinitePositive(timing.frameSeconds) && FinitePositive(timing.gpuInnerSeconds) &&
         timing.frameSeconds > t.budgetSeconds * 1.02 && timing.gpuInnerSeconds <= t.budgetSeconds;
}

// ---------------------------------------------------------- measurement feed

bool BlockAverage::Add(double value) {
  m_Sum += value;
  if (++m_InBlock < m_Count) return false;
  m_Value = m_Sum / m_InBlock;
  m_Sum = 0.0;
  m_InBlock = 0;
  m_HasValue = true;
  return true;
}

void DxutFpsCounter::Tick(double now) {
  if (!m_Started) {  // DXUT: one frame over the clock's whole past, ~0 FPS
    m_Started = true;
    m_LastUpdate = now;
    m_Frames = 0;
    return;
  }
  ++m_Frames;
  if (now - m_LastUpdate > 1.0) {
    m_Fps = static_cast<double>(static_cast<float>(m_Frames / (now - m_LastUpdate)));  // DXUT keeps a float
    m_LastUpdate = now;
    m_Frames = 0;
  }
}

double DxutFpsCounter::FrameSeconds() const {
  return m_Fps > 0.0 ? 1.0 / m_Fps : std::numeric_limits<double>::infinity();
}

Feed FeedFor(ControlLaw law) { return law == ControlLaw::Article ? Feed::Original : Feed::PerResult; }

// ---------------------------------------------------------------- article law

ArticleController::ArticleController(double gain) : m_Gain(gain) {}

double ArticleController::AimSeconds(const ControlTarget& target) const {
  return SanitizeTarget(target).budgetSeconds;  // the original steers t to T
}

double ArticleController::MeasuredSeconds(const FrameTiming& timing) {
  const double gpu = timing.gpuInnerSeconds;
  const double frame = timing.frameSeconds;
  if (!(std::isfinite(gpu) && gpu >= 0.0)) return std::nan("");
  if (!FinitePositive(frame)) return gpu;  // unusable frame time: GPU time only
  if (frame > 2.0 * gpu) return gpu;       // original: ignore CPU-side spikes
  return 0.5 * (gpu + frame);              // original: average of GPU and frame time
}

float ArticleController::Step(float controlled, const FrameTiming& timing, const ControlTarget& target,
                              double gain) {
  const ControlTarget tgt = SanitizeTarget(target);
  const float lo = static_cast<float>(tgt.minScale), hi = static_cast<float>(tgt.maxScale);
  // A non-finite or non-positive integrator (only reachable through a caller's
  // Step) restarts at 1 clamped to the range.
  float c = std::isfinite(controlled) && controlled > 0.0f ? controlled : static_cast<float>(ClampScale(1.0, tgt));
  const float k = static_cast<float>(std::clamp(std::isfinite(gain) ? gain : kDefaultGain, kMinGain, kMaxGain));
  const double measured = MeasuredSeconds(timing);
  if (std::isnan(measured)) return std::clamp(c, lo, hi);  // unusable sample: hold
  // The original's float arithmetic: t/T, then k (1 - t/T) + 1, then C *= ratio.
  float t;
  const float gpu = static_cast<float>(timing.gpuInnerSeconds);
  const float frame = static_cast<float>(timing.frameSeconds);
  if (!FinitePositive(timing.frameSeconds) || frame > 2.0f * gpu) t = gpu;
  else t = (gpu + frame) / 2.0f;
  const float ratio = k * (1.0f - t / static_cast<float>(tgt.budgetSeconds)) + 1.0f;
  const float next = ratio * c;
  if (std::isnan(next)) return std::clamp(c, lo, hi);
  return std::clamp(next, lo, hi);  // +-Inf land on the limits
}

double ArticleController::Update(double /*currentScale*/, const FrameTiming& timing, const ControlTarget& target) {
  m_Controlled = Step(m_Controlled, timing, target, m_Gain);
  // The float clamp limits may round just outside a double range (0.9f < 0.9).
  const ControlTarget tgt = SanitizeTarget(target);
  return std::clamp(static_cast<double>(m_Controlled), tgt.minScale, tgt.maxScale);
}

// -------------------------------------------------------------- UE-style law

UEStyleController::Params UEStyleController::TunedParams() {
  Params p;
  p.historySize = 8;
  p.frameWeightExponent = 0.8;
  p.increaseBlend = 0.75;
  return p;
}

UEStyleController::UEStyleController() : UEStyleController(Params{}) {}

UEStyleController::UEStyleController(const Params& params) : m_Params(params) {
  m_Params.historySize = std::max(1, m_Params.historySize);
  m_Params.panicFrames = std::max(1, m_Params.panicFrames);
  if (!(m_Params.frameWeightExponent > 0.0 && m_Params.frameWeightExponent <= 1.0)) m_Params.frameWeightExponent = 0.9;
  if (!(m_Params.increaseBlend >= 0.0 && m_Params.increaseBlend < 1.0)) m_Params.increaseBlend = 0.9;
  if (!(m_Params.changeThreshold >= 0.0)) m_Params.changeThreshold = 0.02;
  m_Params.minChangePeriod = std::max(0, m_Params.minChangePeriod);
  m_Params.latencyFrames = std::clamp(m_Params.latencyFrames, 0, 64);
}

void UEStyleController::Reset() {
  m_History.clear();
  m_Called.clear();
  m_OverBudget = 0;
  m_SinceChange = 1 << 20;
}

// The scale the timed frame was rendered at: given by the caller, or the
// scale this law was called with latencyFrames calls ago (the current one
// until that many calls were made).
double UEStyleController::MeasuredScale(double s, const FrameTiming& timing) {
  m_Called.push_back(s);
  if (static_cast<int>(m_Called.size()) > m_Params.latencyFrames + 1) m_Called.erase(m_Called.begin());
  if (FinitePositive(timing.gpuScale)) return timing.gpuScale;
  return m_Called.front();
}

double UEStyleController::Update(double currentScale, const FrameTiming& timing, const ControlTarget& target) {
  const ControlTarget tgt = SanitizeTarget(target);
  const double s = ClampScale(currentScale, tgt);
  const double aim = AimOf(tgt);
  const double gpu = timing.gpuInnerSeconds;
  const double measuredAt = MeasuredScale(s, timing);
  ++m_SinceChange;
  auto change = [&](double next) {
    next = ClampScale(next, tgt);
    if (next != s) m_SinceChange = 0;
    return next;
  };
  if (!FinitePositive(gpu)) return s;  // no usable measurement
  if (IsCpuBoundFrame(timing, tgt)) {  // CPU-bound: the GPU time does not predict the frame
    m_OverBudget = 0;
    return s;
  }

  m_History.push_back({gpu, measuredAt});
  if (static_cast<int>(m_History.size()) > m_Params.historySize) m_History.erase(m_History.begin());
  m_OverBudget = gpu > tgt.budgetSeconds ? m_OverBudget + 1 : 0;

  if (m_OverBudget >= m_Params.panicFrames) {  // panic: trust the newest frame alone, at once
    const double next = measuredAt * std::sqrt(aim / gpu);
    m_History.clear();
    m_OverBudget = 0;
    return next < s ? change(next) : s;
  }

  // Each sample suggests the scale that would have hit the aim with a
  // quadratic cost model from the scale it was measured at; newer samples
  // weigh more.
  double weight = 1.0, sumW = 0.0, sum = 0.0;
  for (auto it = m_History.rbegin(); it != m_History.rend(); ++it) {
    sum += weight * it->scale * std::sqrt(aim / it->gpuSeconds);
    sumW += weight;
    weight *= m_Params.frameWeightExponent;
  }
  const double suggested = sum / sumW;
  if (!std::isfinite(suggested)) return s;
  if (m_SinceChange < m_Params.minChangePeriod) return s;  // minimum change period
  if (std::abs(suggested - s) < m_Params.changeThreshold * s) return s;
  double next = suggested;
  if (suggested > s) next = s + (suggested - s) * (1.0 - m_Params.increaseBlend);  // amortised increase
  return change(next);
}

// ---------------------------------------------------------------- robust law

RobustController::Params RobustController::PreviousParams() {
  Params p;
  p.maxStepUp = 1.5;
  p.minSamplesUp = 2;
  p.upQuantile = 0.5;
  p.riskQuantile = 0.0;
  p.riskLocal = false;
  return p;
}

RobustController::RobustController() : RobustController(Params{}) {}

RobustController::RobustController(const Params& params) : m_Params(params) {
  Params& p = m_Params;
  p.medianWindow = std::max(1, p.medianWindow);
  p.minSamples = std::clamp(p.minSamples, 1, p.medianWindow);
  if (!(p.deadband >= 0.0 && p.deadband < 1.0)) p.deadband = 0.05;
  if (!(p.outlierFactor > 1.0)) p.outlierFactor = 4.0;
  p.outlierPersistFrames = std::max(1, p.outlierPersistFrames);
  p.panicFrames = std::max(1, p.panicFrames);
  if (!(p.panicRatio >= 1.0)) p.panicRatio = 1.25;
  if (!(p.gammaMin > 0.0 && p.gammaMax >= p.gammaMin)) {
    p.gammaMin = 0.5;
    p.gammaMax = 3.0;
  }
  if (!(p.maxStepDown > 0.0 && p.maxStepDown <= 1.0)) p.maxStepDown = 0.5;
  if (!(p.maxStepUp >= 1.0)) p.maxStepUp = 1.5;
  p.latencyFrames = std::max(0, p.latencyFrames);
  if (!(p.noiseZ >= 0.0)) p.noiseZ = 3.5;
  if (!(p.initialNoise >= 0.0 && p.initialNoise < 1.0)) p.initialNoise = 0.01;
  if (!(p.riskQuantile >= 0.5 && p.riskQuantile < 1.0)) p.riskQuantile = 0.0;  // off
  p.riskFrames = std::max(10, p.riskFrames);
  if (!(p.upQuantile >= 0.5 && p.upQuantile <= 1.0)) p.upQuantile = 0.5;
  p.minSamplesUp = std::clamp(p.minSamplesUp, p.minSamples, p.medianWindow);
  m_Noise = p.initialNoise;
}

void RobustController::Reset() {
  m_Samples.clear();
  m_Outliers.clear();
  m_SkipFrames = 0;
  m_OverBudget = 0;
  m_LastAppliedScale = -1.0;
  m_HaveSecant = false;
  m_Gamma = 2.0;
  m_Noise = m_Params.initialNoise;
  m_LastSample = 0.0;
  m_Diffs.clear();
  m_Spread = 0.0;
  m_Recent.clear();
}

double RobustController::Band(int samples) const {
  const double noise = std::max(m_Noise, m_Spread);
  const double sigmaMedian = 1.25 * noise / std::sqrt(static_cast<double>(std::max(1, samples)));
  return std::max(m_Params.deadband, m_Params.noiseZ * sigmaMedian);
}

double RobustController::SetPoint(const ControlTarget& tgt) const {
  const double noiseAware = AimOf(tgt) * std::exp(-(Band(m_Params.medianWindow) - m_Params.deadband));
  if (m_Params.riskQuantile <= 0.0 || m_Recent.size() < 10) return noiseAware;
  std::vector<double> loads;  // the recent samples at scale 1, with the cost exponent now believed
  for (const Timed& x : m_Recent) loads.push_back(x.seconds / std::pow(x.scale, m_Gamma));
  std::vector<double> spread;  // what the quantile is taken of, relative to its level (ratio 1)
  if (m_Params.riskLocal) {
    constexpr std::size_t kLevel = 9;
    for (std::size_t i = kLevel; i < loads.size(); ++i)
      spread.push_back(loads[i] / Median(std::vector<double>(loads.begin() + (i - kLevel), loads.begin() + i)));
    if (spread.size() < 10) return noiseAware;
  } else {
    const double level = Median(loads);
    for (double l : loads) spread.push_back(l / level);
  }
  std::sort(spread.begin(), spread.end());
  const double ratio = spread[static_cast<std::size_t>(m_Params.riskQuantile * (spread.size() - 1) + 0.5)];
  return ratio > 1.0 ? std::min(noiseAware, tgt.budgetSeconds / ratio) : noiseAware;
}

double RobustController::Correct(double s, double measured, const ControlTarget& tgt, bool panic) {
  const double aim = SetPoint(tgt);
  const double ls = std::log(s);
  const double lt = std::log(measured);
  double gamma = 2.0;  // quadratic cost model: time ~ pixels ~ s^2
  if (m_HaveSecant && !panic) {
    const double dls = ls - m_PrevLogScale;
    if (std::abs(dls) > 0.01) {
      const double slope = (lt - m_PrevLogTime) / dls;
      if (std::isfinite(slope)) gamma = std::clamp(slope, m_Params.gammaMin, m_Params.gammaMax);
    }
  }
  m_Gamma = gamma;
  double step = std::log(aim / measured) / gamma;
  step = std::clamp(step, std::log(m_Params.maxStepDown), std::log(m_Params.maxStepUp));
  const double next = ClampScale(std::exp(ls + step), tgt);
  if (next != s) {
    m_HaveSecant = true;  // the next correction of this episode refines gamma
    m_PrevLogScale = ls;
    m_PrevLogTime = lt;
    m_Samples.clear();
    m_Outliers.clear();
    m_OverBudget = 0;
    m_SkipFrames = m_Params.latencyFrames;
  }
  return next;
}

// The frames Update holds on without looking at the time: someone else
// changed the scale (the samples no longer describe it), frames still in
// flight at the previous scale, a bad or CPU-bound time, or a time that names
// an earlier scale. Resets the samples where the scale moved under us.
bool RobustController::HoldsWithoutSample(double s, const FrameTiming& timing, const ControlTarget& tgt) {
  // 1 % tolerance absorbs the viewport quantisation of what we returned.
  if (m_LastAppliedScale > 0.0 && std::abs(std::log(s / m_LastAppliedScale)) > 0.01) {
    m_Samples.clear();
    m_Outliers.clear();
    m_OverBudget = 0;
    m_HaveSecant = false;
  }
  // A time that names its frame's scale needs no count of frames in flight.
  const bool paired = FinitePositive(timing.gpuScale);
  if (paired) m_SkipFrames = 0;
  if (m_SkipFrames > 0) {  // still measuring frames rendered at the previous scale
    --m_SkipFrames;
    return true;
  }
  if (!FinitePositive(timing.gpuInnerSeconds)) return true;  // NaN / Inf / zero / negative: hold
  if (IsCpuBoundFrame(timing, tgt)) {                          // the GPU is not what limits the frame
    m_OverBudget = 0;
    return true;
  }
  return paired && std::abs(std::log(timing.gpuScale / s)) > 0.01;  // an earlier scale's frame
}

// Takes the time t into the window, or into the outliers (relative to the
// running median, or right after a correction to the aim we steered to).
// Returns false while an outlier waits to persist; *outlier says whether t
// was one (a persistent outlier becomes the new window: the new load).
bool RobustController::AcceptSample(double t, double s, double aim, bool* outlier) {
  const double reference = m_Samples.empty() ? (m_HaveSecant ? aim : 0.0) : Median(m_Samples);
  *outlier = reference > 0.0 && (t > m_Params.outlierFactor * reference || t * m_Params.outlierFactor < reference);
  if (*outlier) {
    m_Outliers.push_back(t);
    if (static_cast<int>(m_Outliers.size()) < m_Params.outlierPersistFrames) return false;
    m_Samples = m_Outliers;
    if (m_Params.riskQuantile > 0.0)
      for (double x : m_Outliers) m_Recent.push_back({x, s});
    m_Outliers.clear();
  } else {
    m_Outliers.clear();
    m_Samples.push_back(t);
    if (m_Params.riskQuantile > 0.0) m_Recent.push_back({t, s});
    // Noise: successive log differences of accepted samples (a step or drift
    // moves one difference, not their median). sigma = 1.4826 MAD / sqrt(2).
    if (m_LastSample > 0.0) {
      m_Diffs.push_back(std::abs(std::log(t / m_LastSample)));
      if (m_Diffs.size() > 31) m_Diffs.erase(m_Diffs.begin());
      if (m_Diffs.size() >= 7) m_Noise = 1.4826 * Median(m_Diffs) / std::sqrt(2.0);
    }
    m_LastSample = t;
  }
  if (static_cast<int>(m_Samples.size()) > m_Params.medianWindow) m_Samples.erase(m_Samples.begin());
  while (static_cast<int>(m_Recent.size()) > m_Params.riskFrames) m_Recent.erase(m_Recent.begin());
  return true;
}

// The steady-state step: the window's median against the set point, inside a
// deadband widened to the median's noise (~1.25 sigma / sqrt(n)) with the set
// point lowered by the part of the band beyond `deadband`, so a noisy timer
// does not let the GPU time drift past aim + deadband; an increase needs
// enough samples and is decided on the upper quantile.
double RobustController::SteadyStep(double s, const ControlTarget& tgt) {
  if (static_cast<int>(m_Samples.size()) < m_Params.minSamples) return s;
  const double median = Median(m_Samples);
  m_Spread = 0.0;
  if (m_Params.spreadNoise && m_Samples.size() >= 5) {  // correlated noise: successive differences miss it
    std::vector<double> dev;
    for (double x : m_Samples) dev.push_back(std::abs(std::log(x / median)));
    m_Spread = 1.4826 * Median(dev);
  }
  const double bandNow = Band(static_cast<int>(m_Samples.size()));
  const double setPoint = SetPoint(tgt);
  if (std::abs(std::log(median / setPoint)) <= bandNow) return s;  // no swimming
  if (median < setPoint) {
    if (static_cast<int>(m_Samples.size()) < m_Params.minSamplesUp) return s;
    if (m_Params.upQuantile > 0.5) {
      std::vector<double> sorted = m_Samples;
      std::sort(sorted.begin(), sorted.end());
      const double upper = sorted[static_cast<std::size_t>(m_Params.upQuantile * (sorted.size() - 1) + 0.5)];
      if (upper >= setPoint) return s;
      return Correct(s, std::max(median, upper), tgt, false);
    }
  }
  return Correct(s, median, tgt, false);
}

double RobustController::Update(double currentScale, const FrameTiming& timing, const ControlTarget& target) {
  const ControlTarget tgt = SanitizeTarget(target);
  const double s = ClampScale(currentScale, tgt);
  auto finish = [&](double next) {
    m_LastAppliedScale = next;
    return next;
  };
  if (HoldsWithoutSample(s, timing, tgt)) return finish(s);
  const double t = timing.gpuInnerSeconds;
  bool outlier = false;
  if (!AcceptSample(t, s, AimOf(tgt), &outlier)) return finish(s);

  // Panic on sustained (or a large, plausible) overload.
  m_OverBudget = t > tgt.budgetSeconds ? m_OverBudget + 1 : 0;
  const bool bigOverload = t > tgt.budgetSeconds * m_Params.panicRatio;
  if (m_OverBudget >= m_Params.panicFrames || bigOverload || outlier) {
    const int n = std::min<int>(std::max(m_OverBudget, 1), static_cast<int>(m_Samples.size()));
    const double least = *std::min_element(m_Samples.end() - n, m_Samples.end());
    if (least > tgt.budgetSeconds || outlier) return finish(Correct(s, outlier ? Median(m_Samples) : least, tgt, true));
  }
  return finish(SteadyStep(s, tgt));
}

// ------------------------------------------------------------------ factory

std::unique_ptr<ResolutionController> MakeController(ControlLaw law, int latencyFrames) {
  switch (law) {
    case ControlLaw::Robust: {
      RobustController::Params p;
      p.latencyFrames = latencyFrames;
      return std::make_unique<RobustController>(p);
    }
    case ControlLaw::UEStyle: {
      UEStyleController::Params p;
      p.latencyFrames = latencyFrames;
      return std::make_unique<UEStyleController>(p);
    }
    case ControlLaw::Article:
    case ControlLaw::Count: break;
  }
  return std::make_unique<ArticleController>();
}

}  // namespace drr
