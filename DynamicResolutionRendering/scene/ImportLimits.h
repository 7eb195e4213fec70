// Limits of the import worker (IsolatedImport.h), in a header of its own so
// that the command line's --help can list them without linking the loaders.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

namespace drr {

// CPU and wall time of one import grow with its input: a small base plus an
// allowance per MiB read, so that a tiny malformed file that makes a decoder
// loop ends in seconds while a large valid one gets the time it needs. The
// ImportLimits values (below, or the environment's) cap the result.
struct ImportTimeScale {
  uint32_t baseSeconds;
  uint32_t secondsPerMiB;
};
inline constexpr ImportTimeScale kImportCpuScale{2, 10};
inline constexpr ImportTimeScale kImportWallScale{10, 20};

inline uint32_t ScaledImportSeconds(ImportTimeScale scale, uint64_t inputBytes, uint32_t capSeconds) {
  const uint64_t bytes = std::min<uint64_t>(inputBytes, uint64_t(1) << 40);  // no overflow below
  const uint64_t seconds = scale.baseSeconds + ((bytes * scale.secondsPerMiB) >> 20);
  return uint32_t(std::min<uint64_t>(seconds, capSeconds));
}

struct ImportLimits {
  uint64_t memoryMiB = 4096;  // address space of the worker (RLIMIT_AS)
  uint32_t cpuSeconds = 60;   // CPU time of the worker (RLIMIT_CPU) for the largest input
  uint32_t wallSeconds = 120; // wall time, for a worker blocked without using CPU
  uint64_t replyMiB = 2048;   // largest reply accepted (decoded geometry and pixels)
  // The defaults, overridden by DRR_IMPORT_MEMORY_MB, DRR_IMPORT_CPU_SECONDS,
  // DRR_IMPORT_TIMEOUT_SECONDS and DRR_IMPORT_REPLY_MB (positive integers).
  static ImportLimits FromEnvironment();
  // These limits for an input of inputBytes: CPU and wall time scaled
  // (kImportCpuScale, kImportWallScale) and capped at this object's values.
  ImportLimits ForInput(uint64_t inputBytes) const {
    ImportLimits l = *this;
    l.cpuSeconds = ScaledImportSeconds(kImportCpuScale, inputBytes, cpuSeconds);
    l.wallSeconds = ScaledImportSeconds(kImportWallScale, inputBytes, wallSeconds);
    return l;
  }
};

// The bytes an import of path reads: the file and its companions, the files
// beside it whose names start with its stem (a glTF's .bin, an OBJ's .mtl, a
// mesh's animation file). 0 when the file cannot be read.
uint64_t ImportInputBytes(const std::string& path);

// The limits for importing path, for every reader the worker runs (models,
// textures, and any format added to it): caps.ForInput(ImportInputBytes(path)).
ImportLimits ImportLimitsForFile(const ImportLimits& caps, const std::string& path);

// A paragraph for --help: the variables above and their defaults.
inline std::string ImportLimitsHelp() {
  const ImportLimits d;
  const auto scale = [](ImportTimeScale s) {
    return std::to_string(s.baseSeconds) + " s + " + std::to_string(s.secondsPerMiB) + " s per MiB";
  };
  return "Model and texture files are decoded in a separate process (drr_import_worker); a file\n"
         "that crashes the decoder or exceeds a limit is an error naming it. Limits per file\n"
         "(environment variables, positive integers); CPU and wall time grow with the file's size\n"
         "(CPU " + scale(kImportCpuScale) + ", wall " + scale(kImportWallScale) + ") up to:\n"
         "  DRR_IMPORT_MEMORY_MB       address space (default " + std::to_string(d.memoryMiB) + ")\n"
         "  DRR_IMPORT_CPU_SECONDS     CPU time (default " + std::to_string(d.cpuSeconds) + ")\n"
         "  DRR_IMPORT_TIMEOUT_SECONDS wall time (default " + std::to_string(d.wallSeconds) + ")\n"
         "  DRR_IMPORT_REPLY_MB        decoded geometry and pixels (default " + std::to_string(d.replyMiB) + ")\n"
         "  DRR_IMPORT_WORKER          the worker (default: drr_import_worker next to this program)\n";
}

}  // namespace drr
