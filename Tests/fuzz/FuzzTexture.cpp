// Fuzz target: texture decoding and conversion (ImageFile.h decoders, RGBA8
// conversion, mip chain) in process, as the import worker runs them. The
// first byte picks the format hint and the texture kind.
#include <cstdint>
#include <string>

#include "scene/TextureLoader.h"

// Under ASan: unwind allocation stacks with the full (DWARF) unwinder. OpenImageIO's
// PNG reader leaks a std::string when libpng longjmps out of its read callback
// on a malformed file; the fast unwinder stops inside libstdc++, one frame short
// of libOpenImageIO, and the library-name suppression (lsan.supp) cannot match.
// Only this target sets it: it slows every allocation down. The environment's
// ASAN_OPTIONS still override it flag by flag.
extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0"; }

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* hints[] = {"png", "jpg", "tga", "bmp", "hdr"};
  drr::TextureLoadOptions o;
  o.maxDimension = 1024;  // keeps one execution small; larger sizes are rejected from the header
  drr::TextureData t;
  std::string error;
  drr::LoadTextureMemory(data + 1, size - 1, hints[data[0] % 5], "fuzz", drr::TextureKind(data[0] / 5 % 3), o, &t,
                         &error);
  return 0;
}
