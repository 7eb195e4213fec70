// Paced headless frames (--pace-hz): a run without a window presents at a
// refresh period as a VSync'd swap chain would. After each frame the loop
// sleeps to the next period boundary, and the frame time the controller and
// the animation see is the time between the boundaries a frame was shown at,
// a whole number of periods, as with VSync. Off (0 Hz): no sleep, measured
// frame times.
#pragma once

#include <functional>

namespace drr {

class FramePacer {
 public:
  // Seconds on a monotonic clock; sleeps until that clock reads `until`.
  using Now = std::function<double()>;
  using SleepUntil = std::function<void(double until)>;

  FramePacer() = default;  // off
  explicit FramePacer(double hz);  // the steady clock and a real sleep; hz <= 0: off
  FramePacer(double hz, Now now, SleepUntil sleepUntil);  // injected clock (tests)

  bool Enabled() const { return period_ > 0.0; }
  double PeriodSeconds() const { return period_; }

  // Call where the frame is presented: sleeps to the first period boundary
  // not before now (boundaries at start + k periods, start being the first
  // call, so late wake-ups do not drift the schedule) and returns that
  // boundary's time. Off: returns now without sleeping.
  double Present();
  // The frame time to use for the frame after a Present: off, `measured`;
  // paced, the time between the last two boundaries shown (one period
  // before the second presentation).
  double FrameSeconds(double measured) const;

 private:
  double period_ = 0.0;
  Now now_;
  SleepUntil sleepUntil_;
  bool started_ = false;
  double start_ = 0.0;     // the first boundary
  long long shown_ = -1;   // index of the last boundary presented at
  double interval_ = 0.0;  // seconds between the last two boundaries presented at
};

}  // namespace drr
