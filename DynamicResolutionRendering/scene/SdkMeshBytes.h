// Bounds-checked little-endian reads for the SDKMESH readers (SdkMesh.h): a
// read past the end yields zero, and Fits() tells before a read whether an
// array of records lies inside the file.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

namespace drr::sdkmesh {

struct ByteView {
  const uint8_t* data = nullptr;
  size_t size = 0;

  // count records of recordBytes each at offset lie inside the bytes (no overflow).
  bool Fits(uint64_t offset, uint64_t count, uint64_t recordBytes) const {
    if (offset > size) return false;
    return count == 0 || (recordBytes != 0 && count <= (size - offset) / recordBytes);
  }
  template <class T>
  T Get(uint64_t at) const {
    T v{};
    if (at <= size && sizeof(T) <= size - at) std::memcpy(&v, data + at, sizeof(T));
    return v;
  }
  uint8_t U8(uint64_t at) const { return Get<uint8_t>(at); }
  uint16_t U16(uint64_t at) const { return Get<uint16_t>(at); }
  uint32_t U32(uint64_t at) const { return Get<uint32_t>(at); }
  uint64_t U64(uint64_t at) const { return Get<uint64_t>(at); }
  float F32(uint64_t at) const { return Get<float>(at); }
  // A zero-terminated name in a field of maxBytes (unterminated: the whole field).
  std::string Name(uint64_t at, size_t maxBytes) const {
    std::string s;
    for (size_t i = 0; i < maxBytes && at + i < size; ++i) {
      const char c = char(data[at + i]);
      if (c == '\0') break;
      s += c;
    }
    return s;
  }
};

// Sets *error to "<path>: <message>" and returns false.
struct Failure {
  std::string path;
  std::string* error;
  bool operator()(const std::string& message) const {
    *error = path + ": " + message;
    return false;
  }
  // Inserts who after the path of the message already set.
  bool Prefix(const std::string& who) const {
    if (error->rfind(path + ": ", 0) == 0) error->insert(path.size() + 2, who);
    return false;
  }
};

}  // namespace drr::sdkmesh
