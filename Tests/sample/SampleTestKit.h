// Small helpers shared by the whole-sample render tests: start a sample with
// validation in force and end it with no validation message, render n frames
// and capture the last (on a given sample, or on one of its own), and compare
// two captured back buffers pixel by pixel.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <type_traits>
#include <utility>

#include "DynamicResolutionRendering.h"
#include "ValidationInForce.h"

namespace drr::testkit {

// A headless sample for image tests: no GUI, no console output, manual
// control (the scale stays where the test puts it), a fixed animation time.
inline Options HeadlessOptions(uint32_t width, uint32_t height, double time) {
  Options o;
  o.headless = true;
  o.width = width;
  o.height = height;
  o.gui = false;
  o.quiet = true;
  o.control = ControlMode::Manual;
  o.time = time;
  return o;
}

// Starts a sample for a test: Init succeeds and, where D3DL_VALIDATION asks
// for validation, the layer is in force. Otherwise the test fails here and
// the result is false; a test ends then (`if (!Start(s, o)) return;`),
// as an ASSERT would, rather than render on a sample that did not start.
inline bool Start(Sample& s, const Options& o) {
  std::string err;
  if (s.Init(o, &err) != 0) {
    ADD_FAILURE() << "Sample::Init: " << err;
    return false;
  }
  if (s.ValidationLayerMissing()) {
    ADD_FAILURE() << drrtest::kValidationLayerMissing;
    return false;
  }
  return true;
}

// Ends a sample started by Start: no validation message came (the count
// covers the whole run), then Shutdown.
inline void Finish(Sample& s) {
  EXPECT_EQ(s.ValidationMessages(), 0u) << "validation messages were reported";
  s.Shutdown();
}

// Renders n frames and returns the back buffer of the last (with the GUI, if on).
inline Image RenderAndCapture(Sample& s, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == n - 1) s.RequestCapture();
    EXPECT_TRUE(s.RenderFrame());
  }
  return s.CapturedBackBuffer();
}

// A sample of its own for one run: Start, n frames with the last captured,
// then `readBack(sample, backBuffer)` while the sample still lives (for what a
// test needs besides the back buffer: other targets, stats, frame records),
// then Finish. Returns what readBack returns; a failed start fails the test
// and returns a value-initialised result (empty images).
template <class ReadBack>
auto RunFresh(const Options& o, int n, ReadBack&& readBack) {
  using Result = std::invoke_result_t<ReadBack&, Sample&, Image&&>;
  Sample s;
  if (!Start(s, o)) return Result{};
  Result result = readBack(s, RenderAndCapture(s, n));
  Finish(s);
  return result;
}

// The common case: the last back buffer and the passes the run ran.
struct FreshRun {
  Image image;
  std::map<std::string, uint64_t> passes;
};
inline FreshRun RenderFresh(const Options& o, int n) {
  return RunFresh(o, n, [](Sample& s, Image&& backBuffer) { return FreshRun{std::move(backBuffer), s.PassesRun()}; });
}

// Largest RGB difference, pixels that differ and the mean of the per-pixel
// largest difference, over the pixels at least `border` inside the edges.
// Images of different sizes: maxAbs 256 and every pixel counted as differing.
struct Diff {
  int maxAbs = 0;
  uint64_t differing = 0;
  double meanAbs = 0;
};
inline Diff Compare(const Image& a, const Image& b, uint32_t border = 0) {
  Diff d;
  if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size()) return {256, ~0ull, 256.0};
  uint64_t counted = 0;
  double sum = 0;
  for (uint32_t y = border; y + border < a.height; ++y)
    for (uint32_t x = border; x + border < a.width; ++x) {
      int m = 0;
      const size_t p = (size_t(y) * a.width + x) * 4;  // 8-bit RGBA or BGRA, both the same layout
      for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(int(a.pixels[p + c]) - int(b.pixels[p + c])));
      d.maxAbs = std::max(d.maxAbs, m);
      d.differing += m > 0;
      sum += m;
      ++counted;
    }
  d.meanAbs = counted ? sum / double(counted) : 0.0;
  return d;
}

// One sample per test, started by the test and shut down after it; any
// validation message fails the test.
class SampleTest : public ::testing::Test {
 protected:
  void StartSample(const Options& o) { ASSERT_TRUE(Start(sample, o)); }
  void TearDown() override { Finish(sample); }
  Sample sample;
};

}  // namespace drr::testkit
