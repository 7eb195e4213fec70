// Fuzz target: the scene description parser (no file checks).
#include <cstdint>
#include <string>

#include "scene/SceneDescription.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  drr::ParseOptions o;
  o.checkFiles = false;
  drr::SceneDescription d;
  std::string error;
  drr::ParseSceneDescription(std::string(reinterpret_cast<const char*>(data), size), "/fuzz/scene.txt", o, &d, &error);
  for (const auto& e : d.entries) (void)e.Transform();
  // Parsed lights hold the documented ranges (the lighting pass divides by the radius).
  for (const auto& l : d.lights)
    if (!(l.radius > 0.f) || l.angleDeg <= 0.f || l.angleDeg > 89.f) __builtin_trap();
  return 0;
}
