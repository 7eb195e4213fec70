// Fuzz target: the DDS reader (headers, pixel formats, mip offsets), the
// texture it becomes, the CPU BC decoder that expands it, and its trip
// through the import worker's reply format, all in process.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/DdsReader.h"
#include "scene/ImportWire.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  drr::DdsImage img;
  std::string error;
  if (!drr::ReadDds(data, size, "fuzz.dds", 1024, &img, &error)) return 0;  // larger sides are rejected from the header
  drr::TextureData t, expanded, back;
  drr::TextureFromDds(std::move(img), "fuzz.dds", drr::TextureKind::Color, {}, &t);
  drr::ExpandToRgba8(t, &expanded, &error);
  std::vector<uint8_t> wire;
  drr::WireWriteTexture(t, &wire);
  drr::WireReadTexture(wire, 1024, &back, &error);
  return 0;
}
