// Fuzz target: model import through the isolation layer. The input is
// written to a file (the first byte picks the format) and imported by the
// worker under small limits: the caller must get a model that passed
// validation or an error naming the file, whatever the worker does.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "scene/ImportWire.h"
#include "scene/IsolatedImport.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* exts[] = {"obj", "ply", "stl", "off", "gltf", "fbx", "dae", "3ds"};
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("drr_fuzz_model_" + std::to_string(getpid()) + "." + exts[data[0] % 8])).string();
  {
    std::ofstream f(file, std::ios::binary);
    f.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  drr::ImportLimits limits;
  limits.memoryMiB = 512;
  limits.cpuSeconds = 2;
  limits.wallSeconds = 5;
  limits.replyMiB = 64;
  drr::ModelData m;
  std::string error;
  if (drr::ImportModelIsolated(file, {}, limits, &m, &error)) {
    if (!drr::ValidateModel(m, {}).empty()) std::abort();  // the reader let invalid data through
  } else if (error.find(file) == std::string::npos) {
    std::abort();  // an error must name the file
  }
  std::remove(file.c_str());
  return 0;
}
