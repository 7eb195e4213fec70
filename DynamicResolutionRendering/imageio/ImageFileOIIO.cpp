// OpenImageIO backend of ImageFile.h, built as a module of its own
// (libdrr_imageio_oiio.so) that ImageFileModule.cpp opens on the first image
// call: OpenImageIO brings about 260 shared libraries, whose loading cost
// about 0.4 s of CPU in every process that linked it, image or not (the
// import worker and each test process among them).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "imageio/ImageFile.h"

#include "imageio/FileBytes.h"
#include "imageio/ImageFileModule.h"

namespace drr {

namespace {

bool ReadFrom(OIIO::ImageInput* in, const std::string& name, ImageFileData* image,
              std::string* error, uint32_t maxDimension) {
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1 ||
      uint32_t(spec.width) > maxDimension || uint32_t(spec.height) > maxDimension) {
    if (error) {
      *error = name + ": image too large or empty: " + std::to_string(spec.width) + "x" +
               std::to_string(spec.height) + "x" + std::to_string(spec.nchannels) +
               " (at most " + std::to_string(maxDimension) + " per side, 2-D only)";
    }
    return false;
  }
  image->width = uint32_t(spec.width);
  image->height = uint32_t(spec.height);
  image->channels = uint32_t(std::min(spec.nchannels, 4));
  image->isFloat = spec.format.basetype != OIIO::TypeDesc::UINT8 &&
                   spec.format.basetype != OIIO::TypeDesc::INT8;
  image->linear = spec.format.basetype == OIIO::TypeDesc::HALF || spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                  spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  const size_t count = size_t(image->width) * image->height * image->channels;
  bool ok;
  if (image->isFloat) {
    image->f32.resize(count);
    ok = in->read_image(0, 0, 0, int(image->channels), OIIO::TypeDesc::FLOAT, image->f32.data());
  } else {
    image->u8.resize(count);
    ok = in->read_image(0, 0, 0, int(image->channels), OIIO::TypeDesc::UINT8, image->u8.data());
  }
  if (!ok) {
    if (error) *error = name + ": " + in->geterror();
    return false;
  }
  return true;
}

// Keep straight (unassociated) alpha as stored: decals and masks need it.
OIIO::ImageSpec ReadConfig() {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return config;
}

}  // namespace

bool OiioReadImageFile(const std::string& path, ImageFileData* image, std::string* error,
                   uint32_t maxDimension) {
  const OIIO::ImageSpec config = ReadConfig();
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    if (error) *error = path + ": " + OIIO::geterror();
    return false;
  }
  return ReadFrom(in.get(), path, image, error, maxDimension);
}

bool OiioReadImageMemory(const void* data, size_t size, const std::string& name, ImageFileData* image,
                     std::string* error, uint32_t maxDimension) {
  OIIO::Filesystem::IOMemReader reader(const_cast<void*>(data), size);
  OIIO::ImageSpec config = ReadConfig();
  // The format is sniffed from the bytes; the name only needs an extension OIIO knows.
  auto in = OIIO::ImageInput::open(name.find('.') == std::string::npos ? name + ".png" : name,
                                   &config, &reader);
  if (!in) {
    if (error) *error = name + ": " + OIIO::geterror();
    return false;
  }
  return ReadFrom(in.get(), name, image, error, maxDimension);
}

namespace {

bool Write(const std::string& path, uint32_t w, uint32_t h, uint32_t channels,
           OIIO::TypeDesc type, const void* pixels, size_t rowPitch, std::string* error) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    if (error) *error = path + ": " + OIIO::geterror();
    return false;
  }
  OIIO::ImageSpec spec(int(w), int(h), int(channels), type);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // the pixels are not premultiplied
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  const bool inMemory = out->supports("ioproxy") && out->set_ioproxy(&memory);
  if (!out->open(path, spec) ||
      !out->write_image(type, pixels, OIIO::AutoStride, OIIO::stride_t(rowPitch)) || !out->close()) {
    if (error) *error = path + ": " + out->geterror();
    return false;
  }
  return inMemory ? WriteFileBytes(path, encoded, error) : true;
}
}  // namespace

bool OiioWriteImageFile(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                    const uint8_t* pixels, std::string* error, uint32_t rowPitch) {
  const size_t pitch = rowPitch ? rowPitch : size_t(width) * channels;
  return Write(path, width, height, channels, OIIO::TypeDesc::UINT8, pixels, pitch, error);
}

bool OiioWriteImageFileFloat(const std::string& path, uint32_t width, uint32_t height,
                         uint32_t channels, const float* pixels, std::string* error) {
  return Write(path, width, height, channels, OIIO::TypeDesc::FLOAT, pixels,
               size_t(width) * channels * sizeof(float), error);
}

std::string OiioImageFileBackend() { return std::string("OpenImageIO ") + OIIO_VERSION_STRING; }

}  // namespace drr

extern "C" __attribute__((visibility("default"))) const drr::ImageFileFunctions* DrrImageFileFunctions() {
  static const drr::ImageFileFunctions functions{
      drr::kImageFileFunctionsVersion, &drr::OiioReadImageFile,      &drr::OiioReadImageMemory,
      &drr::OiioWriteImageFile,        &drr::OiioWriteImageFileFloat, &drr::OiioImageFileBackend};
  return &functions;
}
