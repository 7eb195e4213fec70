// Fuzz target: the sample's side of the isolation layer, reading a reply of
// the import worker (ImportWire.h): any bytes are rejected or validated.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/ImportWire.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> reply(data, data + size);
  drr::ModelData m;
  drr::TextureData t;
  std::string error;
  if (drr::WireReadModel(reply, {}, &m, &error)) {
    std::vector<glm::mat4> g;
    m.Evaluate(0.5, &g);
  }
  drr::WireReadTexture(reply, 4096, &t, &error);
  return 0;
}
