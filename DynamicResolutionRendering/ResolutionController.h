// Resolution control laws: pure CPU code, no GPU needed. The sample's
// ControlResolution() calls one of them once per frame:
//
//   FrameTiming timing{averagedInnerGpuSeconds, dxutFps.FrameSeconds()};
//   ControlTarget target{TargetFrameSeconds(refreshHz, mode), ...};
//   double s = controller.Update(dynamicResolution.GetScaleX(), timing, target);
//   dynamicResolution.SetScale(float(s), float(s));
//
// The article law integrates its own continuous scale (the original's
// g_ControlledScale) and does not read the applied, quantised scale back; the
// port's laws (robust, ue-style) work from the applied scale.
//
// Every Update() returns a finite scale inside [target.minScale, target.maxScale]
// (after SanitizeTarget) for any input, including NaN, infinities, zero and
// negative times and a non-finite current scale.
//
// Laws (details and stability analysis in Docs/Controller.md):
//  - ArticleController: the 2011 article / original sample, unchanged for valid
//    inputs: S' = S (1 + k (1 - t/T)) on a continuous float S.
//  - UEStyleController: our implementation of the idea Unreal Engine published
//    for its dynamic resolution heuristic: weighted GPU-time history, quadratic
//    cost model, change threshold, panic on consecutive over-budget frames,
//    CPU-bound frame rejection.
//  - RobustController: median-filtered GPU time with outlier/NaN rejection,
//    quadratic feed-forward refined by a secant estimate of the cost exponent,
//    log-domain integration clamped at the limits (anti-windup), deadband
//    (zero changes under a still load), fast panic on overload.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

namespace drr {

// Inputs measured for the frame that just ended.
struct FrameTiming {
  double gpuInnerSeconds = 0.0;  // GPU time of the inner frame (the article law: the 10-result average, 0 before the first)
  double frameSeconds = 0.0;     // whole frame period (the article law: 1 / DXUT-style FPS, +Inf before the first figure)
  // Scale per axis of the frame the GPU time measured (the timer's result
  // arrives frames late, after later frames changed the scale); 0 = unknown:
  // the UE-style law then pairs it with the scale it was called with
  // latencyFrames calls earlier. The article law ignores it.
  double gpuScale = 0.0;
};

// The arithmetic of the original's AveragedGPUTimer: results are summed in
// blocks of `count`; Value() is the mean of the last complete block and 0
// until the first block completes (the original feeds that 0 to the law).
class BlockAverage {
public:
  explicit BlockAverage(unsigned count = 10) : m_Count(count ? count : 1) {}
  // Returns true when this result completed a block (a new Value()).
  bool Add(double value);
  double Value() const { return m_Value; }
  bool HasValue() const { return m_HasValue; }
  void Clear() { *this = BlockAverage(m_Count); }

private:
  unsigned m_Count;
  unsigned m_InBlock = 0;
  double m_Sum = 0.0;
  double m_Value = 0.0;
  bool m_HasValue = false;
};

// DXUT's frames-per-second figure (DXUTGetFPS): each frame counts one; when
// more than one second has passed since the last figure, the figure becomes
// frames / elapsed and the count restarts. DXUT's very first figure divides one
// frame by the time since its clock's origin, i.e. practically 0; this counter
// reports 0 until its first full second. Tick once per frame, before the
// frame's work, with a monotonic time in seconds.
class DxutFpsCounter {
public:
  void Tick(double nowSeconds);
  double Fps() const { return m_Fps; }
  // 1 / Fps(): what the original's ControlResolution uses (+Inf while Fps is 0).
  double FrameSeconds() const;
  void Reset() { *this = DxutFpsCounter(); }

private:
  bool m_Started = false;
  double m_LastUpdate = 0.0;
  unsigned long m_Frames = 0;
  double m_Fps = 0.0;
};

// What the controller must achieve.
struct ControlTarget {
  double budgetSeconds = 1.0 / 60.0;  // T: frame period to hold (1/refresh, or 2/refresh for VSync/2)
  double headroom = 0.10;             // fraction of T kept free by UE-style and robust laws (aim = T (1 - headroom));
                                      // the article law aims at T itself, as the original
  double minScale = 0.3;              // the original's lower clamp
  double maxScale = 1.0;              // the maximum scaling (1, or 2 with super sampling)
};

// Resolution control law used in the VSync and VSync/2 modes (Docs/Controller.md).
// Article is the original's. The names come from one table (ResolutionController.cpp).
enum class ControlLaw { Article, Robust, UEStyle, Count };
const char* ControlLawName(ControlLaw law);    // GUI name ("Article (original)")
const char* ControlLawOption(ControlLaw law);  // command-line value and ResolutionController::Name() ("ue-style")
// A command-line value, or "ue" for ue-style; false (and *law untouched) for an unknown name.
bool ParseControlLaw(std::string_view name, ControlLaw* law);

// How the scale is chosen: by hand, or by the law for a frame period of
// 2/refresh (VSync/2) or 1/refresh (VSync).
enum class ControlMode { Manual, HalfVSync, VSync, Count };
const char* ControlModeName(ControlMode mode);    // GUI name ("VSync/2")
const char* ControlModeOption(ControlMode mode);  // command-line value ("half-vsync")

// T = 1/refresh (VSync) or 2/refresh (VSync/2); Manual returns 1/refresh.
// A refresh rate that is not finite and > 0 is replaced by 60 Hz.
double TargetFrameSeconds(double refreshHz, ControlMode mode);

// Makes a target usable: budget finite > 0 (else 1/60), headroom in [0, 0.9]
// (else 0.1), minScale finite > 0 (else 0.3), maxScale finite >= minScale
// (else max(1, minScale)).
ControlTarget SanitizeTarget(const ControlTarget& target);

// Clamps to [minScale, maxScale]; a non-finite scale becomes 1 clamped to the range.
double ClampScale(double scale, const ControlTarget& sanitizedTarget);

class ResolutionController {
public:
  virtual ~ResolutionController() = default;
  virtual std::string_view Name() const = 0;
  // GPU time the law steers to (used by the simulator's metrics).
  virtual double AimSeconds(const ControlTarget& target) const;
  // New scale per axis from the current (applied, quantised) scale and the
  // timing of the last frame. Always finite and inside the target's range.
  virtual double Update(double currentScale, const FrameTiming& timing, const ControlTarget& target) = 0;
  // Forget all history (after a resize, a mode switch, a camera cut).
  virtual void Reset() {}
};

// The original sample's law, kept exactly for valid inputs, in float as the
// original computes it:
//   t = (t_gpuInner + t_frame) / 2, or t_gpuInner when t_frame > 2 t_gpuInner
//   C' = C (1 + k (1 - t/T)), clamped to [minScale, maxScale]
// C is the controller's own continuous scale (the original's
// g_ControlledScale): it starts at 1, the applied (quantised) scale is never
// read back, and nothing resets it (the original keeps it for the whole run,
// through resizes and mode switches). Update's currentScale is ignored.
// Robustness (only for inputs the original mishandled): a GPU time that is NaN,
// infinite or negative leaves the scale unchanged; a frame time that is not
// finite and > 0 is ignored (t = t_gpuInner, which is what the original's
// comparison gives for +Inf); a non-finite product is clamped.
class ArticleController final : public ResolutionController {
public:
  static constexpr double kDefaultGain = 0.01;
  static constexpr double kMinGain = 0.001;  // documented gain range; values outside are clamped into it
  static constexpr double kMaxGain = 10.0;

  explicit ArticleController(double gain = kDefaultGain);
  std::string_view Name() const override { return ControlLawOption(ControlLaw::Article); }
  double AimSeconds(const ControlTarget& target) const override;
  double Update(double currentScale, const FrameTiming& timing, const ControlTarget& target) override;
  void Reset() override {}  // the original never resets g_ControlledScale
  double Gain() const { return m_Gain; }
  float ControlledScale() const { return m_Controlled; }

  // One step of the law from the continuous scale `controlled` (pure function).
  static float Step(float controlled, const FrameTiming& timing, const ControlTarget& target, double gain);
  // The "t" the original feeds into the law (NaN when the GPU time is unusable).
  static double MeasuredSeconds(const FrameTiming& timing);

private:
  double m_Gain;
  float m_Controlled = 1.0f;  // g_ControlledScale
};

// Returns true for a frame that was late although the GPU fitted the budget:
// the CPU (or something else) set the pace, so the GPU time says nothing about
// what a different resolution would do to the frame time.
bool IsCpuBoundFrame(const FrameTiming& timing, const ControlTarget& target);

// Our implementation of the idea behind Unreal Engine's dynamic resolution
// heuristic (written from the published description, no engine code). Each
// history entry pairs a GPU time with the scale of the frame it measured
// (FrameTiming::gpuScale, else the scale of latencyFrames calls earlier), so
// a delayed time is never read as the cost of the current scale.
class UEStyleController final : public ResolutionController {
public:
  struct Params {
    int historySize = 16;              // frames of GPU time kept
    double frameWeightExponent = 0.9;  // weight of a sample = exponent^age
    double changeThreshold = 0.02;     // relative scale change below which nothing changes
    int panicFrames = 2;               // consecutive over-budget frames that trigger a panic drop
    double increaseBlend = 0.9;        // increases move (1 - blend) of the way per frame (amortised)
    int minChangePeriod = 8;           // calls between two changes (a panic does not wait)
    int latencyFrames = 0;             // calls between a frame and its GPU time, when gpuScale is 0
  };
  // The pick of the tuning-set scan (drr_controller_sim --scan-ue, Docs/Controller.md):
  // history 8 weighted 0.8^age, increase blend 0.75, period and threshold as
  // above. Judged on the fresh held-out traces as "ue-style-tuned"; the sample's
  // --law ue-style keeps the defaults above.
  static Params TunedParams();
  UEStyleController();
  explicit UEStyleController(const Params& params);
  std::string_view Name() const override { return ControlLawOption(ControlLaw::UEStyle); }
  double Update(double currentScale, const FrameTiming& timing, const ControlTarget& target) override;
  void Reset() override;

private:
  struct Sample {
    double gpuSeconds;
    double scale;  // scale of the frame that took gpuSeconds
  };
  double MeasuredScale(double currentScale, const FrameTiming& timing);
  Params m_Params;
  std::vector<Sample> m_History;  // newest last
  std::vector<double> m_Called;   // scales of the latest calls, newest last (for latencyFrames)
  int m_OverBudget = 0;
  int m_SinceChange = 1 << 20;    // calls since the last change
};

// The project's law. Per frame:
//  1. reject unusable samples (NaN, Inf, <= 0) and CPU-bound frames;
//  2. reject isolated outliers (> outlierFactor x the running median) unless
//     they persist for outlierPersistFrames frames (then they are the new load);
//  3. median of the samples measured at the current scale (window medianWindow,
//     at least minSamples before acting; samples still in flight after a change,
//     latencyFrames, are skipped);
//  4. deadband: act only when the median is more than max(deadband,
//     noiseZ x sigma_median) away from the aim (relative), sigma_median from a
//     running robust estimate of the sample noise (the larger of: the median
//     of successive log differences, insensitive to drifts and steps; and the
//     spread of the window around its median, which sees correlated noise the
//     differences miss), so a still load changes the scale zero times even
//     when the GPU timer is noisy;
//  5. step in log scale: dlog s = log(aim / t) / gamma, gamma = 2 (quadratic
//     cost model: pixels ~ s^2) for the first correction of an episode, then the
//     secant slope measured between the last two corrections (clamped to
//     [gammaMin, gammaMax]), which absorbs the fixed, resolution-independent
//     part of the frame; the step is limited to [maxStepDown, maxStepUp];
//  6. panic: panicFrames consecutive usable frames over the budget, or one
//     frame over the budget by more than panicRatio, act at once on the
//     smallest of those samples without waiting for the median;
//  7. risk-aware set point: on a machine whose load jumps (a shared machine),
//     the set point drops so that the 75th percentile of how far a frame rises
//     above the recent level lands on the budget, not only the median on the
//     aim; with a steady load it changes nothing.
// The scale itself is the integrator state and is clamped to [min, max], so
// nothing winds up while the scale sits at a limit (anti-windup).
class RobustController final : public ResolutionController {
public:
  struct Params {
    int medianWindow = 9;       // most samples (at the current scale) in the median
    int minSamples = 2;         // fewest samples before a (non-panic) correction
    double deadband = 0.05;     // smallest relative error acted on (0.03 before the synthetic-set tuning)
    double noiseZ = 3.5;        // the deadband widens to noiseZ x the median's estimated noise
    double initialNoise = 0.01; // relative noise assumed before any estimate
    double outlierFactor = 4.0;
    int outlierPersistFrames = 3;
    int panicFrames = 2;
    double panicRatio = 1.25;
    double gammaMin = 0.5;
    double gammaMax = 3.0;
    double maxStepDown = 0.5;   // smallest factor per correction
    double maxStepUp = 1.2;     // largest factor per correction (1.5 before the tuning-set scan)
    int latencyFrames = 0;      // frames between a scale change and the first GPU time measured at it
                                // (when FrameTiming::gpuScale is 0; else that scale says it)
    bool spreadNoise = true;    // the noise is also the spread of the window around its median
    // Risk-aware set point: the median is steered to at most T / r, r = the
    // riskQuantile-th quantile over the median of the last riskFrames usable
    // samples, each normalised to scale 1 (t / s^gamma), so that the recent
    // load's riskQuantile-th quantile lands on the budget T rather than the
    // median on the aim. The memory is not flushed by corrections, so a machine
    // that had bursts keeps the law low until riskFrames pass. 0: off (the
    // law before the tuning-set scan).
    double riskQuantile = 0.75;
    int riskFrames = 60;
    // true: the quantile is taken of each normalised sample over the median of
    // the 9 before it (how far a frame jumps above the recent level), so a
    // lasting change of the load (a step) does not count as risk, only
    // short-lived rises do.
    bool riskLocal = true;
    // Increases are decided on this quantile of the window (at the current
    // scale) instead of its median: 1 = the largest sample, so the law gives
    // resolution back only when every recent sample says it fits. 0.5: the median.
    double upQuantile = 0.5;
    // Samples at the current scale needed before an increase (a decrease
    // needs minSamples): a dip of a wandering load must last before the law
    // gives resolution back into it. Below minSamples: minSamples.
    int minSamplesUp = 2;
  };
  // The parameters before the tuning-set scan (Docs/Controller.md): increases
  // of up to 1.5x after 2 samples on the median, no risk-aware set point.
  // The defaults are the scan's pick: increases of up to 1.2x, the risk-aware
  // set point on the local jumps (quantile 0.75 over 60 samples).
  static Params PreviousParams();
  RobustController();
  explicit RobustController(const Params& params);
  std::string_view Name() const override { return ControlLawOption(ControlLaw::Robust); }
  double Update(double currentScale, const FrameTiming& timing, const ControlTarget& target) override;
  void Reset() override;

private:
  double Correct(double scale, double measured, const ControlTarget& target, bool panic);
  bool HoldsWithoutSample(double scale, const FrameTiming& timing, const ControlTarget& target);
  bool AcceptSample(double t, double scale, double aim, bool* outlier);
  double SteadyStep(double scale, const ControlTarget& target);
  double Band(int samples) const;                    // relative deadband for a median of `samples`
  double SetPoint(const ControlTarget& target) const; // GPU time steered to
  Params m_Params;
  std::vector<double> m_Samples;  // usable samples at the current scale, newest last
  std::vector<double> m_Outliers; // consecutive rejected outliers
  int m_SkipFrames = 0;
  int m_OverBudget = 0;
  double m_LastAppliedScale = -1.0;  // scale we returned last (to notice external changes)
  // Secant memory: the previous correction's (log scale, log time) pair.
  bool m_HaveSecant = false;
  double m_PrevLogScale = 0.0;
  double m_PrevLogTime = 0.0;
  double m_Gamma = 2.0;
  double m_Noise = 0.01;             // estimated relative noise of one sample (log domain)
  double m_LastSample = 0.0;         // previous usable sample (for the noise estimate)
  std::vector<double> m_Diffs;       // recent |log(t_i / t_i-1)|
  double m_Spread = 0.0;             // robust spread of the window's samples (log domain)
  struct Timed {
    double seconds, scale;
  };
  std::vector<Timed> m_Recent;       // last riskFrames usable samples with their scales (risk-aware set point)
};

// What a law is fed. Original: the article law as the original feeds it, every
// frame, on the 10-result average of the inner-frame GPU timer (0 before the
// first average) and 1 / DXUT-style FPS. PerResult: the port's laws, once per
// new inner-frame GPU result, on that result and the last frame's period.
enum class Feed { Original, PerResult };
Feed FeedFor(ControlLaw law);

// A fresh controller of the law with its default parameters. The robust and
// UE-style laws are told latencyFrames: how many GPU results after a scale
// change still describe the old scale (the robust law skips them; UE-style
// pairs a time with its frame's scale through it when gpuScale is 0); the
// article law ignores it.
std::unique_ptr<ResolutionController> MakeController(ControlLaw law, int latencyFrames = 0);

}  // namespace drr
