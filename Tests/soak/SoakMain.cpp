// drr_soak: runs the sample in process for N frames, cycling the resolve
// filter, the scale, the camera and the back-buffer size, and samples the
// process's resident memory and the device's live API objects. Passes when
// both are flat (mean of the last quarter of the samples within 2 % of the
// first quarter's) and no validation message was raised. Not part of CTest
// (scripts/soak.sh runs it; 20,000 frames take tens of minutes on lavapipe).
//   drr_soak [--frames N] [--every K] [--csv FILE] [sample options...]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "DynamicResolutionRendering.h"
#include "d3dl/D3DLike.h"

using namespace drr;

namespace {
long RssKiB() {
  std::ifstream f("/proc/self/statm");
  long pages = 0, resident = 0;
  f >> pages >> resident;
  return resident * 4;  // 4 KiB pages
}

struct Sample_ { long frame, rssKiB; unsigned long long objects; };

double Mean(const std::vector<Sample_>& s, size_t from, size_t to, bool rss) {
  double sum = 0;
  for (size_t i = from; i < to; ++i) sum += rss ? double(s[i].rssKiB) : double(s[i].objects);
  return to > from ? sum / double(to - from) : 0;
}

// The settings of step k of the cycle: every filter, four scales, every camera.
Options Step(Options o, int k, int cameras) {
  o.filter = Filter(k % int(Filter::Count));
  static const float scales[] = {1.0f, 0.71f, 0.5f, 0.33f};
  o.scaleX = o.scaleY = scales[(k / int(Filter::Count)) % 4];
  o.camera = cameras > 0 ? (k / 3) % cameras : -1;
  return o;
}
}  // namespace

int main(int argc, char** argv) {
  long frames = 20000, every = 50;
  std::string csv;
  std::vector<std::string> args = {"--headless", "--width", "320", "--height", "180", "--validation", "--control",
                                   "manual", "--frames", "1"};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--every") && i + 1 < argc) every = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
    else args.push_back(argv[i]);
  }
  Options options;
  std::string message;
  if (ParseCommandLine(args, &options, &message) != ParseStatus::Ok) {
    std::fprintf(stderr, "error: %s\n", message.c_str());
    return 2;
  }
  Sample sample;
  if (sample.Init(options, &message) != 0) {
    std::fprintf(stderr, "error: %s\n", message.c_str());
    return 1;
  }
  const int cameras = 3;
  static const uint32_t sizes[][2] = {{320, 180}, {256, 256}, {400, 120}, {97, 61}};
  std::vector<Sample_> samples;
  for (long f = 0; f < frames; ++f) {
    if (f % every == 0) {
      const long k = f / every;
      sample.ApplySettings(Step(sample.Settings(), int(k), cameras));
      if (k % 7 == 6) sample.Resize(sizes[(k / 7) % 4][0], sizes[(k / 7) % 4][1]);
      d3dl::DEVICE_STATS st;
      sample.GetDevice()->GetStats(&st);
      samples.push_back({f, RssKiB(), (unsigned long long)st.LiveObjects});
    }
    if (!sample.RenderFrame()) break;
  }
  const uint64_t messages = sample.ValidationMessages();
  const bool clean = sample.Shutdown();
  if (!csv.empty()) {
    std::ofstream out(csv);
    out << "frame,rss_kib,live_objects\n";
    for (const auto& s : samples) out << s.frame << ',' << s.rssKiB << ',' << s.objects << '\n';
  }
  const size_t q = samples.size() / 4;
  const double rss0 = Mean(samples, 1, q + 1, true), rss1 = Mean(samples, samples.size() - q, samples.size(), true);
  const double obj0 = Mean(samples, 1, q + 1, false), obj1 = Mean(samples, samples.size() - q, samples.size(), false);
  const bool rssFlat = q > 0 && rss1 <= rss0 * 1.02, objFlat = q > 0 && obj1 <= obj0 * 1.02;
  std::printf("soak: %ld frames, %zu samples: RSS %.1f -> %.1f MiB (%+.2f %%), live objects %.1f -> %.1f (%+.2f %%), "
              "validation messages %llu, clean shutdown %s\n",
              frames, samples.size(), rss0 / 1024, rss1 / 1024, q ? (rss1 / rss0 - 1) * 100 : 0.0, obj0, obj1,
              q ? (obj1 / obj0 - 1) * 100 : 0.0, (unsigned long long)messages, clean ? "yes" : "no");
  const bool ok = rssFlat && objFlat && messages == 0 && clean;
  std::printf("soak: %s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}
