// Entry point of the DynamicResolutionRendering executable: the sample, or
// the error-against-run-time measurement with --bench.
#include <cstdio>

#include "DynamicResolutionRendering.h"
#include "bench/Bench.h"

namespace drr {
namespace {
// Parses the command line, runs the sample, returns the exit code.
int SampleMain(int argc, char** argv) {
  Options options;
  std::string message;
  switch (ParseCommandLine(argc, argv, &options, &message)) {
    case ParseStatus::Help:
      std::printf("%s", message.c_str());
      return 0;
    case ParseStatus::Error:
      std::fprintf(stderr, "error: %s\n\n%s", message.c_str(), Usage().c_str());
      return 2;
    case ParseStatus::Ok:
      break;
  }
  Sample sample;
  std::string error;
  if (int rc = sample.Init(options, &error); rc != 0) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return rc;
  }
  const int rc = sample.Run();
  // A device left alive or validation messages while destroying it (objects
  // not destroyed) count as validation failures.
  if (!sample.Shutdown() && rc == 0 && options.validation) return 3;
  return rc;
}

}  // namespace
}  // namespace drr

int main(int argc, char** argv) {
  if (drr::HasBenchFlag(argc, argv)) return drr::BenchMain(argc, argv);
  return drr::SampleMain(argc, argv);
}
