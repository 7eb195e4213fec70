// D3D9 vertex declaration types (D3DDECLTYPE): their sizes, names and how
// Direct3D 9 expands each to four components (missing ones 0, w 1).
#include <cmath>
#include <cstring>

#include "scene/SdkMesh.h"

namespace drr::sdkmesh {

namespace {

struct TypeInfo {
  const char* name;
  size_t bytes;
};
constexpr TypeInfo kTypes[] = {{"FLOAT1", 4},   {"FLOAT2", 8},    {"FLOAT3", 12},    {"FLOAT4", 16},
                               {"D3DCOLOR", 4}, {"UBYTE4", 4},    {"SHORT2", 4},     {"SHORT4", 8},
                               {"UBYTE4N", 4},  {"SHORT2N", 4},   {"SHORT4N", 8},    {"USHORT2N", 4},
                               {"USHORT4N", 8}, {"UDEC3", 4},     {"DEC3N", 4},      {"FLOAT16_2", 4},
                               {"FLOAT16_4", 8}};
constexpr size_t kTypeCount = sizeof(kTypes) / sizeof(kTypes[0]);

float Half(uint16_t h) {
  const int sign = (h >> 15) & 1, exponent = (h >> 10) & 31, mantissa = h & 1023;
  float v;
  if (exponent == 0) v = std::ldexp(float(mantissa), -24);
  else if (exponent == 31) v = mantissa ? NAN : INFINITY;
  else v = std::ldexp(float(mantissa + 1024), exponent - 25);
  return sign ? -v : v;
}

template <class T>
T At(const uint8_t* p, int i) {
  T v;
  std::memcpy(&v, p + i * sizeof(T), sizeof(T));
  return v;
}

// count components of T, each scaled; the rest from (0, 0, 0, 1).
template <class T>
glm::vec4 Components(const uint8_t* p, int count, float scale) {
  glm::vec4 r(0.f, 0.f, 0.f, 1.f);
  for (int i = 0; i < count; ++i) r[i] = float(At<T>(p, i)) * scale;
  return r;
}

glm::vec4 Packed1010102(uint32_t v, bool isSigned) {
  glm::vec4 r(0.f, 0.f, 0.f, 1.f);
  for (int i = 0; i < 3; ++i) {
    int c = int((v >> (10 * i)) & 1023);
    if (isSigned && c >= 512) c -= 1024;
    r[i] = isSigned ? std::max(float(c) / 511.f, -1.f) : float(c);
  }
  return r;
}

glm::vec4 Halves(const uint8_t* p, int count) {
  glm::vec4 r(0.f, 0.f, 0.f, 1.f);
  for (int i = 0; i < count; ++i) r[i] = Half(At<uint16_t>(p, i));
  return r;
}

}  // namespace

const char* DeclTypeName(uint8_t type) { return type < kTypeCount ? kTypes[type].name : "unknown"; }
size_t DeclTypeSize(uint8_t type) { return type < kTypeCount ? kTypes[type].bytes : 0; }

const char* PrimitiveTypeName(uint32_t type) {
  static const char* const names[] = {"TRIANGLE_LIST",     "TRIANGLE_STRIP",     "LINE_LIST",     "LINE_STRIP",
                                      "POINT_LIST",        "TRIANGLE_LIST_ADJ",  "TRIANGLE_STRIP_ADJ",
                                      "LINE_LIST_ADJ",     "LINE_STRIP_ADJ",     "QUAD_PATCH_LIST",
                                      "TRIANGLE_PATCH_LIST"};
  return type <= kTrianglePatchList ? names[type] : "unknown";
}

glm::vec4 DecodeElement(uint8_t type, const uint8_t* p) {
  switch (type) {
    case kFloat1: return Components<float>(p, 1, 1.f);
    case kFloat2: return Components<float>(p, 2, 1.f);
    case kFloat3: return Components<float>(p, 3, 1.f);
    case kFloat4: return Components<float>(p, 4, 1.f);
    case kD3DColor: {  // bytes B, G, R, A
      const glm::vec4 bgra = Components<uint8_t>(p, 4, 1.f / 255.f);
      return {bgra.z, bgra.y, bgra.x, bgra.w};
    }
    case kUByte4: return Components<uint8_t>(p, 4, 1.f);
    case kShort2: return Components<int16_t>(p, 2, 1.f);
    case kShort4: return Components<int16_t>(p, 4, 1.f);
    case kUByte4N: return Components<uint8_t>(p, 4, 1.f / 255.f);
    case kShort2N: return glm::max(Components<int16_t>(p, 2, 1.f / 32767.f), glm::vec4(-1.f));
    case kShort4N: return glm::max(Components<int16_t>(p, 4, 1.f / 32767.f), glm::vec4(-1.f));
    case kUShort2N: return Components<uint16_t>(p, 2, 1.f / 65535.f);
    case kUShort4N: return Components<uint16_t>(p, 4, 1.f / 65535.f);
    case kUDec3: return Packed1010102(At<uint32_t>(p, 0), false);
    case kDec3N: return Packed1010102(At<uint32_t>(p, 0), true);
    case kFloat16_2: return Halves(p, 2);
    case kFloat16_4: return Halves(p, 4);
    default: return glm::vec4(0.f, 0.f, 0.f, 1.f);
  }
}

}  // namespace drr::sdkmesh
