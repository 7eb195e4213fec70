// The table an image backend module exports (ImageFileOIIO.cpp), and the
// name of the one function the loader (ImageFileModule.cpp) looks up in it.
// Module and loader are built by the same compiler in the same build, so the
// table carries C++ types; the version guards against a stale module file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "imageio/ImageFile.h"

namespace drr {

inline constexpr uint32_t kImageFileFunctionsVersion = 1;

struct ImageFileFunctions {
  uint32_t version;
  bool (*readFile)(const std::string& path, ImageFileData* image, std::string* error, uint32_t maxDimension);
  bool (*readMemory)(const void* data, size_t size, const std::string& name, ImageFileData* image,
                     std::string* error, uint32_t maxDimension);
  bool (*writeFile)(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                    const uint8_t* pixels, std::string* error, uint32_t rowPitch);
  bool (*writeFileFloat)(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                         const float* pixels, std::string* error);
  std::string (*backend)();
};

inline constexpr const char* kImageFileFunctionsSymbol = "DrrImageFileFunctions";

}  // namespace drr
