// Limits of the import worker (IsolatedImport.h), in a header of its own so
// that the command line's --help can list them without linking the loaders.
#pragma once

#include <cstdint>
#include <string>

namespace drr {

struct ImportLimits {
  uint64_t memoryMiB = 4096;  // address space of the worker (RLIMIT_AS)
  uint32_t cpuSeconds = 60;   // CPU time of the worker (RLIMIT_CPU)
  uint32_t wallSeconds = 120; // wall time, for a worker blocked without using CPU
  uint64_t replyMiB = 2048;   // largest reply accepted (decoded geometry and pixels)
  // The defaults, overridden by DRR_IMPORT_MEMORY_MB, DRR_IMPORT_CPU_SECONDS,
  // DRR_IMPORT_TIMEOUT_SECONDS and DRR_IMPORT_REPLY_MB (positive integers).
  static ImportLimits FromEnvironment();
};

// A paragraph for --help: the variables above and their defaults.
inline std::string ImportLimitsHelp() {
  const ImportLimits d;
  return "Model and texture files are decoded in a separate process (drr_import_worker); a file\n"
         "that crashes the decoder or exceeds a limit is an error naming it. Limits per file\n"
         "(environment variables, positive integers):\n"
         "  DRR_IMPORT_MEMORY_MB       address space (default " + std::to_string(d.memoryMiB) + ")\n"
         "  DRR_IMPORT_CPU_SECONDS     CPU time (default " + std::to_string(d.cpuSeconds) + ")\n"
         "  DRR_IMPORT_TIMEOUT_SECONDS wall time (default " + std::to_string(d.wallSeconds) + ")\n"
         "  DRR_IMPORT_REPLY_MB        decoded geometry and pixels (default " + std::to_string(d.replyMiB) + ")\n"
         "  DRR_IMPORT_WORKER          the worker (default: drr_import_worker next to this program)\n";
}

}  // namespace drr
