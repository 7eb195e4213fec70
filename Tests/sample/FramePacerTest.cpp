// FramePacer (--pace-hz) on an injected clock: presentations land on the
// refresh boundaries whatever the render time, frame times are whole
// periods, late wake-ups do not drift the schedule; and the VSync control
// law fed by the pacer sees exactly the frame times of a VSync'd window
// (frame time = render time rounded up to whole periods).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "FramePacer.h"
#include "ResolutionController.h"

using namespace drr;

namespace {

constexpr double kHz = 60.0, kPeriod = 1.0 / kHz;

// A clock that moves only when the code under test renders or sleeps; each
// sleep overshoots by `late` seconds, as a real one wakes late.
struct FakeClock {
  double now = 100.0, late = 0.0;
  std::vector<double> sleptUntil;
  FramePacer Pacer(double hz) {
    return FramePacer(hz, [this] { return now; }, [this](double until) {
      sleptUntil.push_back(until);
      now = std::max(now, until) + late;
    });
  }
};

}  // namespace

TEST(FramePacer, PresentsOnBoundariesWithWholePeriodFrameTimes) {
  FakeClock clock;
  FramePacer pacer = clock.Pacer(kHz);
  ASSERT_TRUE(pacer.Enabled());
  const double start = pacer.Present();  // the first frame sets the phase
  EXPECT_EQ(start, 100.0);
  const double renders[] = {0.005, 0.010, 0.020, 0.016, 0.040, 0.0};
  const int periods[] = {1, 1, 2, 1, 3, 1};  // 0 s: still the next boundary, never the one shown at
  double last = start;
  for (size_t i = 0; i < std::size(renders); ++i) {
    clock.now += renders[i];
    const double shown = pacer.Present();
    EXPECT_NEAR(shown - last, periods[i] * kPeriod, 1e-9) << "frame " << i;
    EXPECT_NEAR(std::remainder(shown - start, kPeriod), 0.0, 1e-9) << "frame " << i;
    EXPECT_NEAR(pacer.FrameSeconds(0.123), periods[i] * kPeriod, 1e-9) << "frame " << i;
    EXPECT_GE(clock.now, shown);
    last = shown;
  }
  EXPECT_EQ(clock.sleptUntil.size(), std::size(renders));
}

TEST(FramePacer, LateWakeUpsDoNotDriftTheSchedule) {
  FakeClock clock;
  clock.late = 0.0004;  // every sleep 0.4 ms late
  FramePacer pacer = clock.Pacer(kHz);
  const double start = pacer.Present();
  double shown = start;
  for (int i = 0; i < 1000; ++i) {
    clock.now += 0.005;
    shown = pacer.Present();
  }
  EXPECT_NEAR(shown - start, 1000 * kPeriod, 1e-6);
  EXPECT_NEAR(pacer.FrameSeconds(0.0), kPeriod, 1e-9);
}

TEST(FramePacer, OffPassesTheMeasuredTimeAndNeverSleeps) {
  FakeClock clock;
  for (double hz : {0.0, -5.0, std::nan("")}) {
    FramePacer pacer = clock.Pacer(hz);
    EXPECT_FALSE(pacer.Enabled()) << hz;
    clock.now += 0.007;
    EXPECT_EQ(pacer.Present(), clock.now);
    EXPECT_EQ(pacer.FrameSeconds(0.007), 0.007);
  }
  EXPECT_TRUE(clock.sleptUntil.empty());
  EXPECT_FALSE(FramePacer().Enabled());
}

// A plant whose GPU time grows with the pixel count: 22 ms at full scale,
// over the 16.7 ms period. The article law (VSync mode) run once on the
// window's quantised frame times (a frame shows at the first vertical blank
// after its rendering) and once on the pacer's takes the same scales, frame
// by frame, and settles: the last 100 frames hold the period at a scale that
// moves less than 0.05.
TEST(FramePacer, VSyncLawSeesWhatAWindowShows) {
  const auto gpu = [](double scale) { return 0.004 + 0.018 * scale * scale; };
  ControlTarget target;
  target.budgetSeconds = TargetFrameSeconds(kHz, ControlMode::VSync);
  target.maxScale = 1.0;
  const auto run = [&](bool paced) {
    auto law = MakeController(ControlLaw::Article);
    FakeClock clock;
    FramePacer pacer = clock.Pacer(kHz);
    pacer.Present();
    std::vector<double> scales, frames;
    double scale = 1.0;
    for (int i = 0; i < 400; ++i) {
      const double render = gpu(scale);
      clock.now += render;
      pacer.Present();
      const double window = std::ceil(render / kPeriod - 1e-9) * kPeriod;
      const double frame = paced ? pacer.FrameSeconds(render) : window;
      scale = law->Update(scale, FrameTiming{render, frame}, target);
      scales.push_back(scale);
      frames.push_back(frame);
    }
    return std::pair(scales, frames);
  };
  const auto [windowScales, windowFrames] = run(false);
  const auto [pacedScales, pacedFrames] = run(true);
  ASSERT_EQ(windowScales.size(), pacedScales.size());
  for (size_t i = 0; i < windowScales.size(); ++i) {
    ASSERT_NEAR(pacedFrames[i], windowFrames[i], 1e-9) << "frame " << i;
    ASSERT_NEAR(pacedScales[i], windowScales[i], 1e-6) << "frame " << i;
  }
  const auto tail = pacedScales.end() - 100;
  const auto [lo, hi] = std::minmax_element(tail, pacedScales.end());
  EXPECT_LT(*hi - *lo, 0.05);
  EXPECT_LT(*hi, 1.0);
  for (auto f = pacedFrames.end() - 100; f != pacedFrames.end(); ++f) EXPECT_NEAR(*f, kPeriod, 1e-9);
}
