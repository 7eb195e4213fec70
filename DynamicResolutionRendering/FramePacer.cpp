// FramePacer.h: sleeping to the next refresh boundary.
#include "FramePacer.h"

#include <chrono>
#include <cmath>
#include <thread>

namespace drr {
namespace {

using Clock = std::chrono::steady_clock;

double SteadySeconds() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }

void SleepUntilSteady(double until) {
  const auto at = Clock::time_point(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(until)));
  std::this_thread::sleep_until(at);
}

}  // namespace

FramePacer::FramePacer(double hz) : FramePacer(hz, SteadySeconds, SleepUntilSteady) {}

FramePacer::FramePacer(double hz, Now now, SleepUntil sleepUntil)
    : period_(std::isfinite(hz) && hz > 0.0 ? 1.0 / hz : 0.0), now_(std::move(now)), sleepUntil_(std::move(sleepUntil)) {}

double FramePacer::Present() {
  const double now = now_ ? now_() : 0.0;
  if (!Enabled()) return now;
  if (!started_) {  // the first frame shows at once and sets the phase
    started_ = true;
    start_ = now;
    shown_ = 0;
    interval_ = period_;
    return now;
  }
  // The first boundary at or after now, and never the one already shown at
  // (one presentation per refresh, as a FIFO swap chain).
  long long k = static_cast<long long>(std::ceil((now - start_) / period_ - 1e-9));
  if (k <= shown_) k = shown_ + 1;
  const double boundary = start_ + double(k) * period_;
  interval_ = double(k - shown_) * period_;
  shown_ = k;
  if (boundary > now) sleepUntil_(boundary);
  return boundary;
}

double FramePacer::FrameSeconds(double measured) const { return Enabled() && started_ ? interval_ : measured; }

}  // namespace drr
