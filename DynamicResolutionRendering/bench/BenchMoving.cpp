// Moving-camera sequences: the cinematic camera runs through a stretch of its
// animation at several speeds; every frame after the warm-up is compared with
// the reference of the same animation time (4x4 super sampled, no jitter, no
// motion blur, box-filtered), and with the previous frame for the temporal
// error. The animation time is set per frame (Options::time through
// ApplySettings), so the test and the reference see exactly the same times
// and TAA keeps its history across the sequence.
#include <cmath>

#include "analysis/Flip.h"
#include "analysis/TemporalStability.h"
#include "bench/BenchCommon.h"

namespace drr {
namespace {

constexpr int kCinematicCamera = 1;
constexpr double kBaseStep = 1.0 / 30.0;  // animation seconds per frame at speed 1
constexpr int kCiBlocks = 6;              // blocks of frames behind a sequence's intervals

struct MovingReference {
  double speed = 1.0;
  std::vector<ImageF> frames;  // frame k: animation time TimeOf(warmup + k)
  // Frame k's screen motion from frame k - 1, at the test's size: the scene's
  // velocity target of a native render (motion blur on, so it is written).
  std::vector<MotionField> motion;
};

double TimeOf(const BenchPlan& plan, double speed, int frame) {
  return plan.movingStart + double(frame) * kBaseStep * speed;
}

MotionField MotionOf(const Image& velocity) {
  if (velocity.Empty()) return {};
  std::vector<float> uv(size_t(velocity.width) * velocity.height * 2);
  for (uint32_t y = 0; y < velocity.height; ++y)
    for (uint32_t x = 0; x < velocity.width; ++x)
      for (uint32_t c = 0; c < 2; ++c) uv[(size_t(y) * velocity.width + x) * 2 + c] = velocity.Float(x, y, c);
  return MotionFromUvVelocity(uv, velocity.width, velocity.height);
}

// The reference's screen motion of every compared frame (see MovingReference).
bool MakeMovingMotion(const BenchPlan& plan, MovingReference* ref, std::string* error) {
  Options o = ViewOptions(plan, {kCinematicCamera, plan.movingStart, "moving"});
  o.dynamicResolution = false;
  o.superSampling = false;
  o.motionBlur = true;
  o.filter = Filter::Point;
  Sample sample;
  if (sample.Init(o, error) != 0) return false;
  for (int k = 0; k <= plan.movingWarmup + plan.movingFrames; ++k) {
    o.time = TimeOf(plan, ref->speed, k - 1);
    sample.ApplySettings(o);
    if (k < plan.movingWarmup) {
      sample.RenderFrame();
      continue;
    }
    sample.RequestCapture();
    sample.RenderFrame();
    ref->motion.push_back(MotionOf(sample.CapturedVelocity()));
    if (ref->motion.back().Empty()) {
      *error = "the moving reference's velocity could not be read back";
      return false;
    }
  }
  ref->motion.erase(ref->motion.begin());  // frame warmup - 1: only the previous of frame 0
  sample.Shutdown();
  return true;
}


bool MakeMovingReference(const BenchPlan& plan, double speed, MovingReference* ref, std::string* error) {
  Options o = ViewOptions(plan, {kCinematicCamera, plan.movingStart, "moving"});
  o.width = plan.base.width * plan.referenceFactor;
  o.height = plan.base.height * plan.referenceFactor;
  o.dynamicResolution = false;
  o.superSampling = false;
  o.motionBlur = false;
  o.filter = Filter::Point;
  Sample sample;
  if (sample.Init(o, error) != 0) return false;
  RenderFrames(sample, 2);
  ref->speed = speed;
  for (int k = 0; k < plan.movingFrames; ++k) {
    o.time = TimeOf(plan, speed, plan.movingWarmup + k);
    sample.ApplySettings(o);
    const Image image = Capture(sample);
    if (image.Empty()) {
      *error = "a moving reference frame could not be read back";
      return false;
    }
    ref->frames.push_back(Downsample(ToImage(image), plan.referenceFactor));
  }
  sample.Shutdown();
  return MakeMovingMotion(plan, ref, error);
}

// The per-frame values of one sequence; instability and flicker from the
// second frame on.
struct SequenceValues {
  std::vector<double> psnr, ssim, flip, flicker, instability;
  double maxAbsError = 0;
  bool valid = true;
};

// The image numbers of a row from its per-frame values: means, and the
// intervals over blocks of frames.
void FillSequenceRow(const BenchPlan& plan, const SequenceValues& v, BenchRow* row) {
  const MeanCi p = BlockMeanCi(v.psnr, kCiBlocks), f = BlockMeanCi(v.flip, kCiBlocks);
  row->qualityFrames = int(v.psnr.size());
  row->error.maxAbsError = v.maxAbsError;
  row->error.psnr = p.mean;
  row->psnrCi = p.halfWidth;
  row->error.ssim = BlockMeanCi(v.ssim, 1).mean;
  row->error.mse = std::pow(10.0, -p.mean / 10.0);  // of the mean PSNR
  row->flip = f.mean;
  row->flipCi = f.halfWidth;
  row->flicker = BlockMeanCi(v.flicker, 1).mean;
  row->instability = BlockMeanCi(v.instability, 1).mean;
  row->framePsnr = v.psnr;
  row->frameFlip = v.flip;
  row->frameInstability = v.instability;
  row->error.valid = v.valid && std::isfinite(p.mean) && std::isfinite(f.mean) &&
                     (plan.movingFrames < 2 || (std::isfinite(row->flicker) && std::isfinite(row->instability)));
}

// Renders the sequence's warm-up frames of configuration `s`.
void WarmUpSequence(Sample& sample, const BenchPlan& plan, Options& s, double speed) {
  for (int k = 0; k < plan.movingWarmup; ++k) {
    s.time = TimeOf(plan, speed, k);
    sample.ApplySettings(s);
    sample.RenderFrame();
  }
}

// One configuration through the whole sequence: warm-up, then every frame
// captured and compared. GPU times from the measured frames (replaced by
// TimeSequences' when the plan has timing rounds).
BenchRow MeasureSequence(Sample& sample, const BenchPlan& plan, Options s, const MovingReference& ref,
                         const std::string& name, double scale) {
  WarmUpSequence(sample, plan, s, ref.speed);
  const size_t before = sample.Frames().size();
  SequenceValues v;
  ImageF previous;
  for (int k = 0; k < plan.movingFrames; ++k) {
    s.time = TimeOf(plan, ref.speed, plan.movingWarmup + k);
    sample.ApplySettings(s);
    const ImageF image = ToImage(Capture(sample));
    const ImageF& reference = ref.frames[size_t(k)];
    const ImageError e = CompareImages(image, reference);
    v.valid = v.valid && e.valid;
    v.maxAbsError = std::max(v.maxAbsError, e.maxAbsError);
    v.psnr.push_back(e.psnr);
    v.ssim.push_back(e.ssim);
    const FlipResult f = ComputeFlip(reference, image, FlipPpd(plan));
    v.flip.push_back(f.valid ? f.mean : std::nan(""));
    if (k > 0) {
      const ImageF& refPrev = ref.frames[size_t(k) - 1];
      v.flicker.push_back(TemporalErrorRms(previous, image, refPrev, reference));
      v.instability.push_back(ReprojectedInstability(previous, image, refPrev, reference, ref.motion[size_t(k)]));
    }
    previous = image;
  }
  BenchRow row;
  const auto& all = sample.Frames();
  FillGpuTimes({std::vector<FrameRecord>(all.begin() + std::ptrdiff_t(std::min(before, all.size())), all.end())}, &row);
  FillSequenceRow(plan, v, &row);
  row.view = "cinematic moving x" + Num2(ref.speed);
  row.filter = name;
  row.scale = scale;
  row.moving = true;
  row.speed = ref.speed;
  row.animTime = TimeOf(plan, ref.speed, plan.movingWarmup);
  row.superSampling = s.superSampling;
  row.viewportW = s.dynamicResolution ? sample.GetDynamicResolution().GetViewport().Width : float(sample.BackBufferWidth());
  row.viewportH = s.dynamicResolution ? sample.GetDynamicResolution().GetViewport().Height : float(sample.BackBufferHeight());
  return row;
}

// Timing apart from the image metrics: plan.timingRounds rounds over every
// configuration of the speed, each round starting one configuration later
// (rotating order); each turn warms up (the sequence's warm-up frames, then
// at least plan.timingWarmupMs of its first frame) and renders the compared
// frames without capturing. The rows' GPU and wall times are replaced.
void TimeSequences(Sample& sample, const BenchPlan& plan, double speed,
                   const std::vector<std::pair<Options, size_t>>& configs, BenchResults* results) {
  if (plan.timingRounds <= 0 || configs.empty()) return;
  std::vector<std::vector<std::vector<FrameRecord>>> rounds(configs.size());
  for (int r = 0; r < plan.timingRounds; ++r)
    for (size_t turn = 0; turn < configs.size(); ++turn) {
      const size_t i = (turn + size_t(r)) % configs.size();
      Options s = configs[i].first;
      WarmUpSequence(sample, plan, s, speed);
      WarmUpFor(sample, plan.timingWarmupMs);
      const size_t before = sample.Frames().size();
      for (int k = 0; k < plan.movingFrames; ++k) {
        s.time = TimeOf(plan, speed, plan.movingWarmup + k);
        sample.ApplySettings(s);
        sample.RenderFrame();
      }
      const auto& all = sample.Frames();
      rounds[i].emplace_back(all.begin() + std::ptrdiff_t(std::min(before, all.size())), all.end());
    }
  for (size_t i = 0; i < configs.size(); ++i) FillGpuTimes(rounds[i], &results->rows[configs[i].second]);
}

// The speed the ablations run at: 1 if swept, else the first.
double AblationSpeed(const BenchPlan& plan) {
  for (double s : plan.movingSpeeds)
    if (std::abs(s - 1.0) < 1e-9) return s;
  return plan.movingSpeeds.empty() ? 1.0 : plan.movingSpeeds.front();
}

bool MeasureSpeed(const BenchPlan& plan, double speed, BenchResults* results, Progress* progress,
                  std::string* error) {
  MovingReference ref;
  if (!MakeMovingReference(plan, speed, &ref, error)) return false;
  progress->Step("moving x" + Num2(speed) + " reference");
  Options o = ViewOptions(plan, {kCinematicCamera, plan.movingStart, "moving"});
  o.superSampling = false;
  o.motionBlur = false;  // the reference has none; TAA is then the velocity-reading one
  Sample sample;
  if (sample.Init(o, error) != 0) return false;
  std::vector<std::pair<Options, size_t>> timed;
  auto add = [&](Options s, const std::string& name, double scale) {
    results->Add(MeasureSequence(sample, plan, s, ref, name, scale));
    timed.emplace_back(s, results->rows.size() - 1);
    progress->Step("moving x" + Num2(speed) + " " + name + " " + Num2(scale));
  };
  Options native = o;
  native.dynamicResolution = false;
  native.filter = Filter::Point;
  add(native, "native", 1.0);
  for (Filter f : plan.movingFilters)
    for (float scale : plan.movingScales) {
      Options s = o;
      s.dynamicResolution = true;
      s.filter = f;
      s.scaleX = s.scaleY = scale;
      add(s, FilterOption(f), scale);
    }
  if (plan.ablations && speed == AblationSpeed(plan)) {
    for (float scale : {0.71f, 1.0f}) {
      Options s = o;
      s.dynamicResolution = true;
      s.filter = Filter::TAA;
      s.scaleX = s.scaleY = scale;
      s.symmetricTAA = true;
      add(s, kTaaSymmetric, scale);
      s.symmetricTAA = false;
      s.motionBlur = true;
      add(s, kTaaFast, scale);
    }
    native.motionBlur = true;
    add(native, kNativeMotionBlur, 1.0);
    for (const MipBiasAblation& a : MipBiasAblations(plan)) {
      Options s = o;
      s.dynamicResolution = true;
      a.edit(s);
      add(s, a.name, s.scaleX);
    }
  }
  TimeSequences(sample, plan, speed, timed, results);
  if (plan.timingRounds > 0) progress->Step("moving x" + Num2(speed) + " interleaved timing");
  results->validationMessages += sample.ValidationMessages();
  sample.Shutdown();
  return true;
}

}  // namespace

size_t MovingProgressSteps(const BenchPlan& plan) {
  if (!plan.moving) return 0;
  const size_t perSpeed = 2 + plan.movingFilters.size() * plan.movingScales.size() + (plan.timingRounds > 0 ? 1 : 0);
  return plan.movingSpeeds.size() * perSpeed +
         (plan.ablations && !plan.movingSpeeds.empty() ? 5 + MipBiasAblations(plan).size() : 0);
}

bool MeasureMovingSequences(const BenchPlan& plan, BenchResults* results, Progress* progress, std::string* error) {
  for (double speed : plan.movingSpeeds)
    if (!MeasureSpeed(plan, speed, results, progress, error)) return false;
  return true;
}

}  // namespace drr
