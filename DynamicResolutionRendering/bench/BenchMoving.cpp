// Moving-camera sequences: the cinematic camera runs through a stretch of its
// animation at several speeds; every frame after the warm-up is compared with
// the reference of the same animation time (4x4 super sampled, no jitter, no
// motion blur, box-filtered), and with the previous frame for the temporal
// error. The animation time is set per frame (Options::time through
// ApplySettings), so the test and the reference see exactly the same times
// and TAA keeps its history across the sequence.
#include <cmath>

#include "analysis/Flip.h"
#include "bench/BenchCommon.h"

namespace drr {
namespace {

constexpr int kCinematicCamera = 1;
constexpr double kBaseStep = 1.0 / 30.0;  // animation seconds per frame at speed 1
constexpr int kCiBlocks = 6;              // blocks of frames behind a sequence's intervals

struct MovingReference {
  double speed = 1.0;
  std::vector<ImageF> frames;  // frame k: animation time TimeOf(warmup + k)
};

double TimeOf(const BenchPlan& plan, double speed, int frame) {
  return plan.movingStart + double(frame) * kBaseStep * speed;
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
  return true;
}

// One configuration through the whole sequence: warm-up, then every frame
// captured and compared. GPU times from the measured frames.
BenchRow MeasureSequence(Sample& sample, const BenchPlan& plan, Options s, const MovingReference& ref,
                         const std::string& name, double scale) {
  for (int k = 0; k < plan.movingWarmup; ++k) {
    s.time = TimeOf(plan, ref.speed, k);
    sample.ApplySettings(s);
    sample.RenderFrame();
  }
  const size_t before = sample.Frames().size();
  std::vector<double> psnr, ssim, flip, flicker;
  ImageF previous;
  BenchRow row;
  for (int k = 0; k < plan.movingFrames; ++k) {
    s.time = TimeOf(plan, ref.speed, plan.movingWarmup + k);
    sample.ApplySettings(s);
    const ImageF image = ToImage(Capture(sample));
    const ImageError e = CompareImages(image, ref.frames[size_t(k)]);
    row.error.valid = (k == 0 || row.error.valid) && e.valid;
    row.error.maxAbsError = std::max(row.error.maxAbsError, e.maxAbsError);
    psnr.push_back(e.psnr);
    ssim.push_back(e.ssim);
    const FlipResult f = ComputeFlip(ref.frames[size_t(k)], image);
    flip.push_back(f.valid ? f.mean : std::nan(""));
    if (k > 0) flicker.push_back(TemporalErrorRms(previous, image, ref.frames[size_t(k) - 1], ref.frames[size_t(k)]));
    previous = image;
  }
  const auto& all = sample.Frames();
  FillGpuTimes({std::vector<FrameRecord>(all.begin() + std::ptrdiff_t(std::min(before, all.size())), all.end())}, &row);
  const MeanCi p = BlockMeanCi(psnr, kCiBlocks), f = BlockMeanCi(flip, kCiBlocks);
  row.view = "cinematic moving x" + Num2(ref.speed);
  row.filter = name;
  row.scale = scale;
  row.moving = true;
  row.speed = ref.speed;
  row.animTime = TimeOf(plan, ref.speed, plan.movingWarmup);
  row.qualityFrames = int(psnr.size());
  row.error.psnr = p.mean;
  row.psnrCi = p.halfWidth;
  row.error.ssim = BlockMeanCi(ssim, 1).mean;
  row.error.mse = std::pow(10.0, -p.mean / 10.0);  // of the mean PSNR
  row.flip = f.mean;
  row.flipCi = f.halfWidth;
  row.flicker = BlockMeanCi(flicker, 1).mean;
  row.error.valid = row.error.valid && std::isfinite(p.mean) && std::isfinite(f.mean) &&
                    (plan.movingFrames < 2 || std::isfinite(row.flicker));
  row.superSampling = s.superSampling;
  row.viewportW = s.dynamicResolution ? sample.GetDynamicResolution().GetViewport().Width : float(sample.BackBufferWidth());
  row.viewportH = s.dynamicResolution ? sample.GetDynamicResolution().GetViewport().Height : float(sample.BackBufferHeight());
  return row;
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
  auto add = [&](Options s, const std::string& name, double scale) {
    results->rows.push_back(MeasureSequence(sample, plan, s, ref, name, scale));
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
  results->validationMessages += sample.ValidationMessages();
  sample.Shutdown();
  return true;
}

}  // namespace

size_t MovingProgressSteps(const BenchPlan& plan) {
  if (!plan.moving) return 0;
  const size_t perSpeed = 2 + plan.movingFilters.size() * plan.movingScales.size();
  return plan.movingSpeeds.size() * perSpeed +
         (plan.ablations && !plan.movingSpeeds.empty() ? 5 + MipBiasAblations(plan).size() : 0);
}

bool MeasureMovingSequences(const BenchPlan& plan, BenchResults* results, Progress* progress, std::string* error) {
  for (double speed : plan.movingSpeeds)
    if (!MeasureSpeed(plan, speed, results, progress, error)) return false;
  return true;
}

}  // namespace drr
