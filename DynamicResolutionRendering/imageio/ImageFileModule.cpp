// ImageFile.h over the OpenImageIO module (libdrr_imageio_oiio.so), opened on
// the first call rather than linked: a process that reads or writes no image
// (most test processes, the import worker on a model without textures) does
// not load OpenImageIO's dependency closure. The module is looked up beside
// the executable first, then at its build path.
#include <dlfcn.h>

#include <mutex>

#include "imageio/FileBytes.h"
#include "imageio/ImageFile.h"
#include "imageio/ImageFileModule.h"

namespace drr {

namespace {

struct LoadedModule {
  const ImageFileFunctions* functions = nullptr;
  std::string error;  // why it could not be loaded
};

LoadedModule Load() {
  LoadedModule loaded;
  std::string path = FileBesideExecutable(DRR_IMAGEIO_MODULE_NAME);
  if (path.empty()) path = DRR_IMAGEIO_MODULE_BUILD_PATH;
  // Never closed: OpenImageIO keeps threads and caches for the process's life.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    loaded.error = "the image module " + path + " could not be loaded (" + (why ? why : "unknown reason") + ")";
    return loaded;
  }
  using Entry = const ImageFileFunctions* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(handle, kImageFileFunctionsSymbol));
  const ImageFileFunctions* functions = entry ? entry() : nullptr;
  if (!functions || functions->version != kImageFileFunctionsVersion) {
    loaded.error = "the image module " + path + " is not this build's (rebuild drr_imageio_oiio)";
    return loaded;
  }
  loaded.functions = functions;
  return loaded;
}

const ImageFileFunctions* Functions(std::string* error) {
  static std::once_flag once;
  static LoadedModule module;
  std::call_once(once, [] { module = Load(); });
  if (!module.functions && error) *error = module.error;
  return module.functions;
}

}  // namespace

bool ReadImageFile(const std::string& path, ImageFileData* image, std::string* error, uint32_t maxDimension) {
  const ImageFileFunctions* f = Functions(error);
  return f && f->readFile(path, image, error, maxDimension);
}

bool ReadImageMemory(const void* data, size_t size, const std::string& name, ImageFileData* image,
                     std::string* error, uint32_t maxDimension) {
  const ImageFileFunctions* f = Functions(error);
  return f && f->readMemory(data, size, name, image, error, maxDimension);
}

bool WriteImageFile(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                    const uint8_t* pixels, std::string* error, uint32_t rowPitch) {
  const ImageFileFunctions* f = Functions(error);
  return f && f->writeFile(path, width, height, channels, pixels, error, rowPitch);
}

bool WriteImageFileFloat(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                         const float* pixels, std::string* error) {
  const ImageFileFunctions* f = Functions(error);
  return f && f->writeFileFloat(path, width, height, channels, pixels, error);
}

std::string ImageFileBackend() {
  std::string error;
  const ImageFileFunctions* f = Functions(&error);
  return f ? f->backend() : "OpenImageIO (not loaded: " + error + ")";
}

}  // namespace drr
