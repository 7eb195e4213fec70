// Fuzz target: the SDKMESH reader and its conversion to the scene's model, in
// process. Whatever the bytes, the reader returns an error naming the file or
// a model that passes the import's validation (ImportWire.h).
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/ImportWire.h"
#include "scene/SdkMesh.h"
#include "scene/SdkMeshModel.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = "fuzz.sdkmesh";
  drr::ModelLoadOptions opts;
  opts.maxVertices = 1u << 20;
  opts.maxTriangles = 1u << 20;
  drr::sdkmesh::File file;
  drr::ModelData model;
  std::string error;
  if (drr::sdkmesh::ReadMesh(std::vector<uint8_t>(data, data + size), path, &file, &error) &&
      drr::SdkMeshToModel(file, opts, &model, &error)) {
    if (!drr::ValidateModel(model, opts).empty()) std::abort();  // the reader let invalid data through
  } else if (error.find(path) == std::string::npos) {
    std::abort();  // an error must name the file
  }
  return 0;
}
