// stb backend of ImageFile.h (Debian's libstb: the implementation is in the
// shared library, so only the declarations are included here).
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "imageio/ImageFile.h"

#include "imageio/FileBytes.h"

namespace drr {

namespace {

// Decodes through stb's memory API, so files and embedded images share it.
bool Decode(const uint8_t* bytes, size_t size, const std::string& name, ImageFileData* image,
            std::string* error, uint32_t maxDimension) {
  int w = 0, h = 0, n = 0;
  const int len = int(std::min<size_t>(size, 0x7fffffff));
  if (!stbi_info_from_memory(bytes, len, &w, &h, &n)) {
    if (error) *error = name + ": " + (stbi_failure_reason() ? stbi_failure_reason() : "unreadable");
    return false;
  }
  if (w <= 0 || h <= 0 || uint32_t(w) > maxDimension || uint32_t(h) > maxDimension) {
    if (error) {
      *error = name + ": image too large or empty: " + std::to_string(w) + "x" + std::to_string(h) +
               " (at most " + std::to_string(maxDimension) + " per side)";
    }
    return false;
  }
  image->width = uint32_t(w);
  image->height = uint32_t(h);
  image->channels = uint32_t(std::clamp(n, 1, 4));
  image->linear = stbi_is_hdr_from_memory(bytes, len);
  const bool is16 = !image->linear && stbi_is_16_bit_from_memory(bytes, len);
  image->isFloat = image->linear || is16;
  const size_t count = size_t(w) * h * image->channels;
  if (is16) {  // stbi_loadf would apply its own gamma to these: keep the stored values
    stbi_us* data = stbi_load_16_from_memory(bytes, len, &w, &h, &n, int(image->channels));
    if (!data) {
      if (error) *error = name + ": " + stbi_failure_reason();
      return false;
    }
    image->f32.resize(count);
    for (size_t i = 0; i < count; ++i) image->f32[i] = data[i] / 65535.f;
    stbi_image_free(data);
  } else if (image->isFloat) {
    float* data = stbi_loadf_from_memory(bytes, len, &w, &h, &n, int(image->channels));
    if (!data) {
      if (error) *error = name + ": " + stbi_failure_reason();
      return false;
    }
    image->f32.assign(data, data + count);
    stbi_image_free(data);
  } else {
    stbi_uc* data = stbi_load_from_memory(bytes, len, &w, &h, &n, int(image->channels));
    if (!data) {
      if (error) *error = name + ": " + stbi_failure_reason();
      return false;
    }
    image->u8.assign(data, data + count);
    stbi_image_free(data);
  }
  return true;
}

}  // namespace

bool ReadImageFile(const std::string& path, ImageFileData* image, std::string* error,
                   uint32_t maxDimension) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = path + ": cannot open the file";
    return false;
  }
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return Decode(bytes.data(), bytes.size(), path, image, error, maxDimension);
}

bool ReadImageMemory(const void* data, size_t size, const std::string& name, ImageFileData* image,
                     std::string* error, uint32_t maxDimension) {
  return Decode(static_cast<const uint8_t*>(data), size, name, image, error, maxDimension);
}

namespace {
void Append(void* context, void* data, int size) {
  auto* v = static_cast<std::vector<uint8_t>*>(context);
  v->insert(v->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
}

}  // namespace

bool WriteImageFile(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                    const uint8_t* pixels, std::string* error, uint32_t rowPitch) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  const int w = int(width), h = int(height), c = int(channels);
  const int pitch = int(rowPitch ? rowPitch : width * channels);
  int ok = 0;
  std::vector<uint8_t> encoded;
  if (ext == ".png") {
    ok = stbi_write_png_to_func(Append, &encoded, w, h, c, pixels, pitch);
  } else {
    // The other writers take tightly packed rows.
    std::vector<uint8_t> packed(size_t(width) * height * channels);
    for (uint32_t y = 0; y < height; ++y)
      std::memcpy(&packed[size_t(y) * width * channels], pixels + size_t(y) * pitch, width * channels);
    if (ext == ".jpg" || ext == ".jpeg") ok = stbi_write_jpg_to_func(Append, &encoded, w, h, c, packed.data(), 95);
    else if (ext == ".tga") ok = stbi_write_tga_to_func(Append, &encoded, w, h, c, packed.data());
    else if (ext == ".bmp") ok = stbi_write_bmp_to_func(Append, &encoded, w, h, c, packed.data());
    else {
      if (error) *error = path + ": format not supported by the stb image backend (use .png, .jpg, .tga, .bmp)";
      return false;
    }
  }
  if (!ok) {
    if (error) *error = path + ": cannot encode the image";
    return false;
  }
  return WriteFileBytes(path, encoded, error);
}

bool WriteImageFileFloat(const std::string& path, uint32_t width, uint32_t height,
                         uint32_t channels, const float* pixels, std::string* error) {
  if (std::filesystem::path(path).extension() != ".hdr") {
    if (error) *error = path + ": the stb image backend writes float images only as .hdr";
    return false;
  }
  std::vector<uint8_t> encoded;
  if (!stbi_write_hdr_to_func(Append, &encoded, int(width), int(height), int(channels), pixels)) {
    if (error) *error = path + ": cannot encode the image";
    return false;
  }
  return WriteFileBytes(path, encoded, error);
}

std::string ImageFileBackend() { return "stb"; }

}  // namespace drr
