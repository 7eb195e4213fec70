// Reading and writing image files, in one place for the whole sample
// (textures, screenshots, report plots). Two backends chosen at configure
// time with DRR_IMAGE_IO: OpenImageIO (default: PNG, JPG, TGA, DDS, EXR, ...)
// or stb (Debian's libstb: PNG, JPG, TGA, BMP, HDR) for portable builds that
// cannot carry OpenImageIO's dependencies.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace drr {

struct ImageFileData {
  uint32_t width = 0, height = 0, channels = 0;  // channels 1..4
  bool isFloat = false;                           // f32 holds the data, else u8
  // f32 holds linear light (EXR, HDR, half/float TIFF); 16-bit integer files
  // come back as float too but keep their stored (sRGB-encoded) values.
  bool linear = false;
  std::vector<uint8_t> u8;
  std::vector<float> f32;
};

// Largest width or height accepted, checked from the header before any
// pixel is decoded (a corrupt header must not allocate gigabytes).
inline constexpr uint32_t kMaxImageDimension = 16384;

// Reads a whole image (first subimage, mip 0). 8-bit data stays 8-bit;
// 16-bit and high-dynamic-range sources (EXR, HDR, 32-bit) come back as float.
// On failure returns false and names the file and the reason.
bool ReadImageFile(const std::string& path, ImageFileData* image, std::string* error,
                   uint32_t maxDimension = kMaxImageDimension);

// Same, from an encoded file held in memory (textures embedded in a model);
// name is used in messages only.
bool ReadImageMemory(const void* data, size_t size, const std::string& name, ImageFileData* image,
                     std::string* error, uint32_t maxDimension = kMaxImageDimension);

// Writes 8-bit pixels (rows tightly packed unless rowPitch is given); the
// format follows the extension (.png, .jpg, .tga, .bmp; .exr with OpenImageIO).
bool WriteImageFile(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                    const uint8_t* pixels, std::string* error, uint32_t rowPitch = 0);

// Writes float pixels (.exr with OpenImageIO, .hdr with either backend).
bool WriteImageFileFloat(const std::string& path, uint32_t width, uint32_t height,
                         uint32_t channels, const float* pixels, std::string* error);

// "OpenImageIO 2.4.7" or "stb".
std::string ImageFileBackend();

}  // namespace drr
