// Entry point of the DynamicResolutionRendering executable: the sample, or
// the error-against-run-time measurement with --bench.
#include "DynamicResolutionRendering.h"
#ifdef DRR_HAVE_BENCH
#include "bench/Bench.h"
#endif

int main(int argc, char** argv) {
#ifdef DRR_HAVE_BENCH
  if (drr::HasBenchFlag(argc, argv)) return drr::BenchMain(argc, argv);
#endif
  return drr::SampleMain(argc, argv);
}
