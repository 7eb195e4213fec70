// Fuzz target: the SDKMESH_ANIM reader and its conversion to animation
// channels, in process: an error naming the file, or keys that pass the
// import's validation.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/ImportWire.h"
#include "scene/SdkMesh.h"
#include "scene/SdkMeshModel.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = "fuzz.sdkmesh_anim";
  drr::ModelLoadOptions opts;
  opts.animationsOnly = true;
  drr::sdkmesh::AnimFile file;
  drr::ModelData model;
  std::string error;
  if (drr::sdkmesh::ReadAnim(std::vector<uint8_t>(data, data + size), path, &file, &error) &&
      drr::SdkMeshAnimToModel(file, &model, &error)) {
    if (!drr::ValidateModel(model, opts).empty()) std::abort();
  } else if (error.find(path) == std::string::npos) {
    std::abort();
  }
  return 0;
}
