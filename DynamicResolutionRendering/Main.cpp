// Entry point of the DynamicResolutionRendering executable: the sample, or
// the error-against-run-time measurement with --bench.
#include "DynamicResolutionRendering.h"
#include "bench/Bench.h"

int main(int argc, char** argv) {
  if (drr::HasBenchFlag(argc, argv)) return drr::BenchMain(argc, argv);
  return drr::SampleMain(argc, argv);
}
