// drr_arenagen: writes the project's default scene, "Arena", as real files
// (glTF 2.0 .gltf + .bin written here, PNG textures through OpenImageIO, and a
// scene_description.txt in the original sample's form), which the sample then
// loads through the same Assimp / OpenImageIO path as any user's model.
//
// Contents: a walled arena a few thousand units across (floor, walls of stone
// blocks, a ring of columns with arches, stairways, scattered rubble) with
// normal- and specular-mapped materials on procedural textures; a bell
// swinging on a frame (node rotation animation); an unlit sky dome;
// alpha-blended decals on the floor and walls; a cinematic camera on a closed
// Catmull-Rom path (camera node animation, looping smoothly); two static
// cameras. No LOD. Output is deterministic (fixed seeds, own RNG).
//
// usage: drr_arenagen --out <dir> [--detail small|large] [--seed N]
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace fs = std::filesystem;
using glm::vec2;
using glm::vec3;

namespace {

constexpr float kPi = 3.14159265358979f;

// ---------------------------------------------------------------------------
// Deterministic random numbers and periodic noise.
struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed) {}
  uint64_t Next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float Uniform(float a = 0.f, float b = 1.f) { return a + (b - a) * float(Next() >> 40) / float(1 << 24); }
};

float Hash2(int x, int y, uint32_t seed) {
  uint32_t h = uint32_t(x) * 374761393u + uint32_t(y) * 668265263u + seed * 2246822519u;
  h = (h ^ (h >> 13)) * 1274126177u;
  h ^= h >> 16;
  return float(h & 0xffffff) / float(0xffffff);
}

// Value noise with lattice period 'period' (tileable), smooth interpolation.
float Noise(float x, float y, int period, uint32_t seed) {
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float fx = x - x0, fy = y - y0;
  auto w = [](int v, int p) { return ((v % p) + p) % p; };
  float a = Hash2(w(x0, period), w(y0, period), seed), b = Hash2(w(x0 + 1, period), w(y0, period), seed);
  float c = Hash2(w(x0, period), w(y0 + 1, period), seed), d = Hash2(w(x0 + 1, period), w(y0 + 1, period), seed);
  fx = fx * fx * (3 - 2 * fx);
  fy = fy * fy * (3 - 2 * fy);
  return glm::mix(glm::mix(a, b, fx), glm::mix(c, d, fx), fy);
}

// Fractal noise over [0,1)^2, tileable, in about [0,1].
float Fbm(float u, float v, int baseFreq, int octaves, uint32_t seed) {
  float sum = 0, amp = 0.5f, norm = 0;
  int f = baseFreq;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * Noise(u * f, v * f, f, seed + o * 131);
    norm += amp;
    amp *= 0.5f;
    f *= 2;
  }
  return sum / norm;
}

// ---------------------------------------------------------------------------
// Textures.
struct Image {
  int w, h, c;
  std::vector<uint8_t> px;
};

bool WritePng(const fs::path& file, const Image& img) {
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) return false;
  OIIO::ImageSpec spec(img.w, img.h, img.c, OIIO::TypeDesc::UINT8);
  if (!out->open(file.string(), spec)) return false;
  bool ok = out->write_image(OIIO::TypeDesc::UINT8, img.px.data());
  out->close();
  return ok;
}

uint8_t B(float v) { return uint8_t(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); }

// Height field (tileable) -> tangent-space normal map (+X = +u, +Y = +v, v downwards in the image).
Image NormalFromHeight(const std::vector<float>& h, int n, float strength) {
  Image img{n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      auto H = [&](int xx, int yy) { return h[size_t((yy + n) % n) * n + (xx + n) % n]; };
      float dx = (H(x + 1, y) - H(x - 1, y)) * strength, dy = (H(x, y + 1) - H(x, y - 1)) * strength;
      vec3 nn = glm::normalize(vec3(-dx, -dy, 1.f));
      uint8_t* p = &img.px[(size_t(y) * n + x) * 4];
      p[0] = B(nn.x * 0.5f + 0.5f); p[1] = B(nn.y * 0.5f + 0.5f); p[2] = B(nn.z * 0.5f + 0.5f); p[3] = 255;
    }
  return img;
}

struct MaterialTextures {
  Image diffuse, normal, specular;
  bool hasNormal = false, hasSpecular = false;
};

// Tiles / blocks pattern: returns (mortar 0..1, tile id) for uv in [0,1).
float BlockPattern(float u, float v, int cols, int rows, bool offsetRows, float mortar, int* id) {
  float fy = v * rows;
  int row = int(std::floor(fy));
  float fx = u * cols + (offsetRows && (row & 1) ? 0.5f : 0.f);
  int col = int(std::floor(fx));
  *id = ((row % rows) * 977 + ((col % cols) + cols) % cols * 131);
  float dx = std::min(fx - col, col + 1 - fx) / cols, dy = std::min(fy - row, row + 1 - fy) / rows;
  float d = std::min(dx, dy);
  return glm::smoothstep(0.f, mortar, d);  // 0 in the mortar, 1 inside the block
}

MaterialTextures MakeStone(int n, uint32_t seed, vec3 base, vec3 mortarCol, int cols, int rows, bool offset,
                           float specLevel) {
  MaterialTextures t;
  t.diffuse = {n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  t.specular = {n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  std::vector<float> height(size_t(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      float u = (x + 0.5f) / n, v = (y + 0.5f) / n;
      int id;
      float blk = BlockPattern(u, v, cols, rows, offset, 0.012f, &id);
      float nz = Fbm(u, v, 8, 5, seed);
      float tint = Hash2(id, 7, seed) * 0.25f + 0.85f;
      vec3 c = glm::mix(mortarCol, base * tint * (0.75f + 0.5f * nz), blk);
      height[size_t(y) * n + x] = blk * 0.6f + nz * 0.4f;
      uint8_t* p = &t.diffuse.px[(size_t(y) * n + x) * 4];
      p[0] = B(c.r); p[1] = B(c.g); p[2] = B(c.b); p[3] = 255;
      float s = specLevel * blk * (0.6f + 0.8f * Fbm(u, v, 16, 3, seed + 9));
      uint8_t* q = &t.specular.px[(size_t(y) * n + x) * 4];
      q[0] = q[1] = q[2] = B(s); q[3] = 255;
    }
  t.normal = NormalFromHeight(height, n, n / 64.f);
  t.hasNormal = t.hasSpecular = true;
  return t;
}

MaterialTextures MakeMarble(int n, uint32_t seed) {
  MaterialTextures t;
  t.diffuse = {n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  t.specular = {n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  std::vector<float> height(size_t(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      float u = (x + 0.5f) / n, v = (y + 0.5f) / n;
      float turb = Fbm(u, v, 4, 6, seed);
      float vein = std::pow(std::fabs(std::sin((u * 4.f + turb * 6.f) * kPi)), 0.35f);
      vec3 c = glm::mix(vec3(0.35f, 0.33f, 0.32f), vec3(0.85f, 0.83f, 0.78f), vein);
      // Flutes along v (columns): a cosine groove pattern.
      float flute = 0.5f + 0.5f * std::cos(u * 2 * kPi * 12.f);
      height[size_t(y) * n + x] = flute * 0.7f + turb * 0.3f;
      uint8_t* p = &t.diffuse.px[(size_t(y) * n + x) * 4];
      p[0] = B(c.r); p[1] = B(c.g); p[2] = B(c.b); p[3] = 255;
      uint8_t* q = &t.specular.px[(size_t(y) * n + x) * 4];
      q[0] = q[1] = q[2] = B(0.35f + 0.5f * vein); q[3] = 255;
    }
  t.normal = NormalFromHeight(height, n, n / 96.f);
  t.hasNormal = t.hasSpecular = true;
  return t;
}

MaterialTextures MakeRock(int n, uint32_t seed) {  // normal map, no specular map
  MaterialTextures t;
  t.diffuse = {n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  std::vector<float> height(size_t(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      float u = (x + 0.5f) / n, v = (y + 0.5f) / n;
      float a = Fbm(u, v, 6, 6, seed), b = Fbm(u, v, 24, 3, seed + 5);
      vec3 c = vec3(0.42f, 0.38f, 0.33f) * (0.6f + 0.7f * a) + vec3(0.05f) * b;
      height[size_t(y) * n + x] = a * 0.8f + b * 0.2f;
      uint8_t* p = &t.diffuse.px[(size_t(y) * n + x) * 4];
      p[0] = B(c.r); p[1] = B(c.g); p[2] = B(c.b); p[3] = 255;
    }
  t.normal = NormalFromHeight(height, n, n / 24.f);
  t.hasNormal = true;
  return t;
}

MaterialTextures MakeBronze(int n, uint32_t seed) {  // specular map, no normal map
  MaterialTextures t;
  t.diffuse = {n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  t.specular = {n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      float u = (x + 0.5f) / n, v = (y + 0.5f) / n;
      float patina = glm::smoothstep(0.55f, 0.75f, Fbm(u, v, 4, 5, seed));
      vec3 c = glm::mix(vec3(0.55f, 0.36f, 0.16f), vec3(0.22f, 0.45f, 0.38f), patina);
      float band = std::fmod(v * 10.f, 1.f) < 0.08f ? 0.7f : 1.f;
      c *= band;
      uint8_t* p = &t.diffuse.px[(size_t(y) * n + x) * 4];
      p[0] = B(c.r); p[1] = B(c.g); p[2] = B(c.b); p[3] = 255;
      uint8_t* q = &t.specular.px[(size_t(y) * n + x) * 4];
      q[0] = q[1] = q[2] = B(0.9f * (1.f - patina) + 0.1f); q[3] = 255;
    }
  t.hasSpecular = true;
  return t;
}

Image MakeSky(int n, uint32_t seed) {  // u = azimuth, v = 0 zenith .. 1 below horizon
  Image img{n, n / 2, 4, std::vector<uint8_t>(size_t(n) * (n / 2) * 4)};
  for (int y = 0; y < n / 2; ++y)
    for (int x = 0; x < n; ++x) {
      float u = (x + 0.5f) / n, v = (y + 0.5f) / (n / 2);
      float elev = 1.f - v * 2.f;  // 1 zenith, 0 horizon, -1 nadir
      vec3 zen(0.10f, 0.22f, 0.50f), hor(0.62f, 0.70f, 0.80f), gnd(0.30f, 0.28f, 0.25f);
      vec3 c = elev > 0 ? glm::mix(hor, zen, std::pow(elev, 0.6f)) : glm::mix(hor, gnd, std::min(1.f, -elev * 4.f));
      if (elev > 0.02f) {
        float cl = glm::smoothstep(0.5f, 0.8f, Fbm(u, v * 0.5f, 8, 5, seed));
        c = glm::mix(c, vec3(0.95f), cl * std::min(1.f, elev * 4.f) * 0.8f);
      }
      uint8_t* p = &img.px[(size_t(y) * n + x) * 4];
      p[0] = B(c.r); p[1] = B(c.g); p[2] = B(c.b); p[3] = 255;
    }
  return img;
}

Image MakeDecal(int n, uint32_t seed) {  // 2x2 atlas of scorch marks / cracks / glyphs, with alpha
  Image img{n, n, 4, std::vector<uint8_t>(size_t(n) * n * 4)};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      int cell = (y * 2 / n) * 2 + (x * 2 / n);
      float u = std::fmod((x + 0.5f) / n * 2.f, 1.f) * 2.f - 1.f, v = std::fmod((y + 0.5f) / n * 2.f, 1.f) * 2.f - 1.f;
      float r = std::sqrt(u * u + v * v);
      float nz = Fbm((x + 0.5f) / n, (y + 0.5f) / n, 16, 4, seed + cell);
      vec3 c(0.05f);
      float a = 0;
      if (cell == 0 || cell == 3) {  // scorch mark
        a = glm::clamp((1.f - r) * 1.6f - 0.4f + (nz - 0.5f) * 0.8f, 0.f, 1.f) * 0.9f;
        c = vec3(0.04f, 0.03f, 0.02f);
      } else if (cell == 1) {  // painted ring glyph
        float ring = 1.f - glm::smoothstep(0.03f, 0.06f, std::fabs(r - 0.7f));
        float cross = (1.f - glm::smoothstep(0.03f, 0.06f, std::min(std::fabs(u), std::fabs(v)))) * (r < 0.7f);
        a = std::max(ring, cross) * (0.6f + 0.4f * nz);
        c = vec3(0.65f, 0.08f, 0.05f);
      } else {  // moss / dirt patch
        a = glm::clamp((0.9f - r) * 2.f, 0.f, 1.f) * glm::smoothstep(0.35f, 0.65f, nz);
        c = vec3(0.18f, 0.28f, 0.08f);
      }
      uint8_t* p = &img.px[(size_t(y) * n + x) * 4];
      p[0] = B(c.r); p[1] = B(c.g); p[2] = B(c.b); p[3] = B(a);
    }
  return img;
}

// ---------------------------------------------------------------------------
// Geometry.
struct MeshBuf {
  std::vector<vec3> pos, nrm;
  std::vector<vec2> uv;
  std::vector<uint32_t> idx;
  size_t Tris() const { return idx.size() / 3; }
  uint32_t Vert(vec3 p, vec3 n, vec2 t) {
    pos.push_back(p);
    nrm.push_back(n);
    uv.push_back(t);
    return uint32_t(pos.size() - 1);
  }
  void Tri(uint32_t a, uint32_t b, uint32_t c) { idx.insert(idx.end(), {a, b, c}); }
  // Counter-clockwise quad a b c d seen from the front.
  void Quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    Tri(a, b, c);
    Tri(a, c, d);
  }
  void Append(const MeshBuf& o) {
    uint32_t base = uint32_t(pos.size());
    pos.insert(pos.end(), o.pos.begin(), o.pos.end());
    nrm.insert(nrm.end(), o.nrm.begin(), o.nrm.end());
    uv.insert(uv.end(), o.uv.begin(), o.uv.end());
    for (uint32_t i : o.idx) idx.push_back(base + i);
  }
};

// Planar grid: origin + s*du + t*dv, s,t in [0,1], normal = cross(du, dv) direction.
void AddGrid(MeshBuf& m, vec3 origin, vec3 du, vec3 dv, int nu, int nv, float texScale,
             const std::function<float(float, float)>& bump = nullptr) {
  vec3 n = glm::normalize(glm::cross(du, dv));
  uint32_t base = uint32_t(m.pos.size());
  float lu = glm::length(du), lv = glm::length(dv);
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      float s = float(i) / nu, t = float(j) / nv;
      vec3 p = origin + du * s + dv * t;
      if (bump) p += n * bump(s, t);
      m.Vert(p, n, vec2(s * lu / texScale, t * lv / texScale));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      uint32_t a = base + j * (nu + 1) + i;
      m.Quad(a, a + 1, a + nu + 2, a + nu + 1);
    }
}

// Oriented box (rotation about Y), UVs in world units / texScale.
void AddBox(MeshBuf& m, vec3 c, vec3 h, float yaw, float texScale, int subdiv = 1) {
  glm::mat3 R(glm::vec3(std::cos(yaw), 0, -std::sin(yaw)), glm::vec3(0, 1, 0), glm::vec3(std::sin(yaw), 0, std::cos(yaw)));
  vec3 ax[3] = {R[0] * h.x, R[1] * h.y, R[2] * h.z};
  // For each face: normal axis k with sign, and two tangent axes chosen so that cross(du, dv) = outward normal.
  for (int k = 0; k < 3; ++k)
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      vec3 n = ax[k] * float(sgn);
      vec3 du = ax[(k + 1) % 3] * 2.f, dv = ax[(k + 2) % 3] * 2.f;
      if (glm::dot(glm::cross(du, dv), n) < 0) std::swap(du, dv);
      vec3 origin = c + n - du * 0.5f - dv * 0.5f;
      AddGrid(m, origin, du, dv, subdiv, subdiv, texScale);
    }
}

// Cylinder along Y (side only, plus optional caps), UV u around, v along height.
void AddCylinder(MeshBuf& m, vec3 base, float r, float height, int radial, int rings, bool caps,
                 const std::function<float(float)>& profile = nullptr) {
  uint32_t b0 = uint32_t(m.pos.size());
  for (int j = 0; j <= rings; ++j) {
    float t = float(j) / rings;
    float rr = r * (profile ? profile(t) : 1.f);
    for (int i = 0; i <= radial; ++i) {
      float a = 2 * kPi * i / radial;
      vec3 n(std::sin(a), 0, std::cos(a));
      m.Vert(base + vec3(0, t * height, 0) + n * rr, n, vec2(float(i) / radial * 2.f, t * height / 400.f));
    }
  }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < radial; ++i) {
      uint32_t a = b0 + j * (radial + 1) + i;
      m.Quad(a, a + 1, a + radial + 2, a + radial + 1);
    }
  if (caps) {
    for (int top = 0; top <= 1; ++top) {
      float rr = r * (profile ? profile(float(top)) : 1.f);
      vec3 n(0, top ? 1.f : -1.f, 0);
      vec3 cpos = base + vec3(0, top ? height : 0.f, 0);
      uint32_t ci = m.Vert(cpos, n, vec2(0.5f));
      uint32_t s0 = uint32_t(m.pos.size());
      for (int i = 0; i <= radial; ++i) {
        float a = 2 * kPi * i / radial;
        m.Vert(cpos + vec3(std::sin(a), 0, std::cos(a)) * rr, n, vec2(0.5f + 0.5f * std::sin(a), 0.5f + 0.5f * std::cos(a)));
      }
      for (int i = 0; i < radial; ++i) top ? m.Tri(ci, s0 + i, s0 + i + 1) : m.Tri(ci, s0 + i + 1, s0 + i);
    }
  }
}

// Icosphere (subdivided), displaced by noise: a rock.
void AddRock(MeshBuf& m, vec3 c, vec3 scale, int subdiv, Rng& rng) {
  const float t = (1.f + std::sqrt(5.f)) / 2.f;
  std::vector<vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<glm::uvec3> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                               {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                               {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (auto& p : v) p = glm::normalize(p);
  for (int s = 0; s < subdiv; ++s) {
    std::map<uint64_t, uint32_t> mid;
    auto M = [&](uint32_t a, uint32_t b) {
      uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(glm::normalize(v[a] + v[b]));
      return mid[key] = uint32_t(v.size() - 1);
    };
    std::vector<glm::uvec3> nf;
    for (auto& tri : f) {
      uint32_t a = M(tri.x, tri.y), b = M(tri.y, tri.z), cc = M(tri.z, tri.x);
      nf.insert(nf.end(), {{tri.x, a, cc}, {tri.y, b, a}, {tri.z, cc, b}, {a, b, cc}});
    }
    f.swap(nf);
  }
  float ph[3] = {rng.Uniform(0, 6.28f), rng.Uniform(0, 6.28f), rng.Uniform(0, 6.28f)};
  std::vector<vec3> p(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    float d = 1.f + 0.18f * std::sin(v[i].x * 3.1f + ph[0]) * std::sin(v[i].y * 2.7f + ph[1]) +
              0.1f * std::sin(v[i].z * 5.3f + ph[2]);
    p[i] = c + v[i] * scale * d;
  }
  // Smooth normals from the faces.
  std::vector<vec3> n(v.size(), vec3(0));
  for (auto& tri : f) {
    vec3 fn = glm::cross(p[tri.y] - p[tri.x], p[tri.z] - p[tri.x]);
    n[tri.x] += fn; n[tri.y] += fn; n[tri.z] += fn;
  }
  uint32_t base = uint32_t(m.pos.size());
  for (size_t i = 0; i < v.size(); ++i) {
    // Triplanar-ish UV from the direction (seams are acceptable on rubble).
    vec2 uv(std::atan2(v[i].x, v[i].z) / (2 * kPi) + 0.5f, std::acos(std::clamp(v[i].y, -1.f, 1.f)) / kPi);
    m.Vert(p[i], glm::normalize(n[i]), uv * 2.f);
  }
  for (auto& tri : f) m.Tri(base + tri.x, base + tri.y, base + tri.z);
}

// Arch between two points (a half ring of rectangular section), in the vertical plane through a and b.
void AddArch(MeshBuf& m, vec3 a, vec3 b, float thickness, float depth, int segs) {
  vec3 mid = (a + b) * 0.5f;
  vec3 ax = b - a;
  float radius = glm::length(ax) * 0.5f;
  ax = glm::normalize(ax);
  vec3 up(0, 1, 0), side = glm::normalize(glm::cross(ax, up));
  auto P = [&](float ang, float r, float s) { return mid + ax * (-std::cos(ang) * r) + up * (std::sin(ang) * r) + side * s; };
  float r0 = radius - thickness * 0.5f, r1 = radius + thickness * 0.5f, d = depth * 0.5f;
  struct Strip { float ra, sa, rb, sb; };
  // Four faces of the section: outer, inner, front, back.
  Strip strips[4] = {{r1, -d, r1, d}, {r0, d, r0, -d}, {r0, d, r1, d}, {r1, -d, r0, -d}};
  for (auto& st : strips) {
    uint32_t base = uint32_t(m.pos.size());
    for (int i = 0; i <= segs; ++i) {
      float ang = kPi * i / segs;
      vec3 pa = P(ang, st.ra, st.sa), pb = P(ang, st.rb, st.sb);
      m.Vert(pa, vec3(0), vec2(float(i) / segs * radius / 100.f, 0));
      m.Vert(pb, vec3(0), vec2(float(i) / segs * radius / 100.f, 0.5f));
    }
    for (int i = 0; i < segs; ++i) {
      uint32_t q = base + i * 2;
      m.Quad(q, q + 1, q + 3, q + 2);
    }
    // Normals: from the quads' geometry (flat per strip column, smooth along the arc).
    for (int i = 0; i <= segs; ++i) {
      float ang = kPi * i / segs;
      vec3 radial = -ax * std::cos(ang) + up * std::sin(ang);
      vec3 nn = (st.ra == st.rb) ? (st.ra == r1 ? radial : -radial) : (st.sa > 0 ? side : -side);
      m.nrm[base + i * 2] = m.nrm[base + i * 2 + 1] = nn;
    }
    // Make winding agree with the normal.
    for (int i = 0; i < segs; ++i) {
      size_t t0 = m.idx.size() - size_t(segs - i) * 6;
      vec3 p0 = m.pos[m.idx[t0]], p1 = m.pos[m.idx[t0 + 1]], p2 = m.pos[m.idx[t0 + 2]];
      if (glm::dot(glm::cross(p1 - p0, p2 - p0), m.nrm[m.idx[t0]]) < 0) {
        std::swap(m.idx[t0 + 1], m.idx[t0 + 2]);
        std::swap(m.idx[t0 + 4], m.idx[t0 + 5]);
      }
    }
  }
}

// ---------------------------------------------------------------------------
// glTF 2.0 writer (JSON by hand, one .bin per file).
struct Gltf {
  std::vector<uint8_t> bin;
  std::vector<std::string> bufferViews, accessors, meshes, nodes, materials, textures, images, cameras, animations;
  std::vector<int> sceneRoots;

  static std::string F(float v) {
    char b[32];
    snprintf(b, sizeof b, "%.9g", v);
    return b;
  }
  int View(const void* data, size_t bytes, int target) {
    while (bin.size() % 4) bin.push_back(0);
    size_t off = bin.size();
    bin.insert(bin.end(), (const uint8_t*)data, (const uint8_t*)data + bytes);
    std::string s = "{\"buffer\":0,\"byteOffset\":" + std::to_string(off) + ",\"byteLength\":" + std::to_string(bytes);
    if (target) s += ",\"target\":" + std::to_string(target);
    bufferViews.push_back(s + "}");
    return int(bufferViews.size() - 1);
  }
  int Accessor(int view, int compType, size_t count, const char* type, const std::string& minmax = "") {
    accessors.push_back("{\"bufferView\":" + std::to_string(view) + ",\"componentType\":" + std::to_string(compType) +
                        ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type + "\"" + minmax + "}");
    return int(accessors.size() - 1);
  }
  int Image(const std::string& uri) {
    images.push_back("{\"uri\":\"" + uri + "\"}");
    textures.push_back("{\"source\":" + std::to_string(images.size() - 1) + ",\"sampler\":0}");
    return int(textures.size() - 1);
  }
  // diffuse/normal/specular: texture indices or -1.
  int Material(const std::string& name, int diffuse, int normal, int specular, bool blend, vec3 factor = vec3(1)) {
    std::string f3 = F(factor.x) + "," + F(factor.y) + "," + F(factor.z);
    std::string s = "{\"name\":\"" + name + "\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[" + f3 +
                    ",1],\"metallicFactor\":0,\"roughnessFactor\":1";
    if (diffuse >= 0) s += ",\"baseColorTexture\":{\"index\":" + std::to_string(diffuse) + "}";
    s += "}";
    if (normal >= 0) s += ",\"normalTexture\":{\"index\":" + std::to_string(normal) + "}";
    // Specular map through KHR_materials_pbrSpecularGlossiness (Assimp maps it to aiTextureType_SPECULAR).
    s += ",\"extensions\":{\"KHR_materials_pbrSpecularGlossiness\":{\"diffuseFactor\":[" + f3 + ",1]";
    if (diffuse >= 0) s += ",\"diffuseTexture\":{\"index\":" + std::to_string(diffuse) + "}";
    if (specular >= 0) s += ",\"specularGlossinessTexture\":{\"index\":" + std::to_string(specular) + "}";
    s += "}}";
    if (blend) s += ",\"alphaMode\":\"BLEND\"";
    materials.push_back(s + "}");
    return int(materials.size() - 1);
  }
  int Mesh(const std::string& name, const MeshBuf& m, int material) {
    vec3 mn(1e30f), mx(-1e30f);
    for (auto& p : m.pos) { mn = glm::min(mn, p); mx = glm::max(mx, p); }
    std::string mm = ",\"min\":[" + F(mn.x) + "," + F(mn.y) + "," + F(mn.z) + "],\"max\":[" + F(mx.x) + "," + F(mx.y) +
                     "," + F(mx.z) + "]";
    int ap = Accessor(View(m.pos.data(), m.pos.size() * 12, 34962), 5126, m.pos.size(), "VEC3", mm);
    int an = Accessor(View(m.nrm.data(), m.nrm.size() * 12, 34962), 5126, m.nrm.size(), "VEC3");
    int at = Accessor(View(m.uv.data(), m.uv.size() * 8, 34962), 5126, m.uv.size(), "VEC2");
    int ai = Accessor(View(m.idx.data(), m.idx.size() * 4, 34963), 5125, m.idx.size(), "SCALAR");
    meshes.push_back("{\"name\":\"" + name + "\",\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(ap) +
                     ",\"NORMAL\":" + std::to_string(an) + ",\"TEXCOORD_0\":" + std::to_string(at) +
                     "},\"indices\":" + std::to_string(ai) + ",\"material\":" + std::to_string(material) + "}]}");
    return int(meshes.size() - 1);
  }
  int Node(const std::string& name, const std::string& extra) {
    nodes.push_back("{\"name\":\"" + name + "\"" + extra + "}");
    return int(nodes.size() - 1);
  }
  static std::string TRS(vec3 t, glm::quat r) {
    return ",\"translation\":[" + F(t.x) + "," + F(t.y) + "," + F(t.z) + "],\"rotation\":[" + F(r.x) + "," + F(r.y) +
           "," + F(r.z) + "," + F(r.w) + "]";
  }
  int Camera(float yfov, float znear, float zfar) {
    cameras.push_back("{\"type\":\"perspective\",\"perspective\":{\"aspectRatio\":1.7777778,\"yfov\":" + F(yfov) +
                      ",\"znear\":" + F(znear) + ",\"zfar\":" + F(zfar) + "}}");
    return int(cameras.size() - 1);
  }
  // One animation with translation and/or rotation channels on one node.
  void Animation(const std::string& name, int node, const std::vector<float>& times, const std::vector<vec3>* trans,
                 const std::vector<glm::quat>* rots) {
    float tmax = times.back();
    int at = Accessor(View(times.data(), times.size() * 4, 0), 5126, times.size(), "SCALAR",
                      ",\"min\":[" + F(times.front()) + "],\"max\":[" + F(tmax) + "]");
    std::string samplers, channels;
    int si = 0;
    auto add = [&](const char* path, int acc) {
      if (si) { samplers += ","; channels += ","; }
      samplers += "{\"input\":" + std::to_string(at) + ",\"output\":" + std::to_string(acc) + ",\"interpolation\":\"LINEAR\"}";
      channels += "{\"sampler\":" + std::to_string(si) + ",\"target\":{\"node\":" + std::to_string(node) + ",\"path\":\"" + path + "\"}}";
      ++si;
    };
    if (trans) add("translation", Accessor(View(trans->data(), trans->size() * 12, 0), 5126, trans->size(), "VEC3"));
    if (rots) {
      std::vector<float> q;
      for (auto& r : *rots) q.insert(q.end(), {r.x, r.y, r.z, r.w});
      add("rotation", Accessor(View(q.data(), q.size() * 4, 0), 5126, rots->size(), "VEC4"));
    }
    animations.push_back("{\"name\":\"" + name + "\",\"samplers\":[" + samplers + "],\"channels\":[" + channels + "]}");
  }
  static std::string Join(const std::vector<std::string>& v) {
    std::string s;
    for (size_t i = 0; i < v.size(); ++i) s += (i ? ",\n    " : "\n    ") + v[i];
    return s;
  }
  bool Write(const fs::path& dir, const std::string& stem) {
    std::string binName = stem + ".bin";
    std::ofstream b(dir / binName, std::ios::binary);
    b.write((const char*)bin.data(), std::streamsize(bin.size()));
    if (!b) return false;
    std::string roots;
    for (size_t i = 0; i < sceneRoots.size(); ++i) roots += (i ? "," : "") + std::to_string(sceneRoots[i]);
    std::ostringstream j;
    j << "{\n  \"asset\":{\"version\":\"2.0\",\"generator\":\"drr_arenagen\"},\n";
    bool sg = !materials.empty();
    if (sg) j << "  \"extensionsUsed\":[\"KHR_materials_pbrSpecularGlossiness\"],\n";
    j << "  \"scene\":0,\n  \"scenes\":[{\"nodes\":[" << roots << "]}],\n";
    j << "  \"nodes\":[" << Join(nodes) << "],\n";
    if (!meshes.empty()) j << "  \"meshes\":[" << Join(meshes) << "],\n";
    if (!materials.empty()) j << "  \"materials\":[" << Join(materials) << "],\n";
    if (!textures.empty())
      j << "  \"textures\":[" << Join(textures) << "],\n  \"images\":[" << Join(images)
        << "],\n  \"samplers\":[{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":10497,\"wrapT\":10497}],\n";
    if (!cameras.empty()) j << "  \"cameras\":[" << Join(cameras) << "],\n";
    if (!animations.empty()) j << "  \"animations\":[" << Join(animations) << "],\n";
    j << "  \"accessors\":[" << Join(accessors) << "],\n";
    j << "  \"bufferViews\":[" << Join(bufferViews) << "],\n";
    j << "  \"buffers\":[{\"uri\":\"" << binName << "\",\"byteLength\":" << bin.size() << "}]\n}\n";
    std::ofstream g(dir / (stem + ".gltf"), std::ios::binary);
    g << j.str();
    return bool(g);
  }
};

// ---------------------------------------------------------------------------
struct Detail {
  const char* name;
  int floorGrid;      // floor quads per side (whole arena)
  float blockW, blockH;
  int columnRadial, columnRings;
  int archSegs;
  int rocks, rockSubdiv;
  int texSize;
  int bellRadial, bellRings;
  int skySegs;
};
constexpr Detail kSmall{"small", 80, 200.f, 100.f, 24, 6, 16, 170, 1, 256, 32, 16, 32};
constexpr Detail kLarge{"large", 420, 50.f, 25.f, 64, 48, 96, 2100, 2, 1024, 96, 64, 96};

constexpr float kHalf = 2000.f;     // arena half size (units)
constexpr float kWallH = 800.f;
constexpr float kColRing = 1250.f;  // column ring radius
constexpr int kColumns = 16;
constexpr float kColR = 60.f, kColH = 600.f;
constexpr float kBellPivotY = 760.f;

// Spatial chunks so culling has something to work with: 4x4 cells.
int Cell(vec3 p) {
  int cx = std::clamp(int((p.x + kHalf) / (2 * kHalf) * 4), 0, 3);
  int cz = std::clamp(int((p.z + kHalf) / (2 * kHalf) * 4), 0, 3);
  return cz * 4 + cx;
}

struct Chunked {
  std::map<int, MeshBuf> cells;
  MeshBuf& At(vec3 p) { return cells[Cell(p)]; }
};

vec3 CatmullRom(const std::vector<vec3>& pts, float s) {  // closed, s in [0, n)
  int n = int(pts.size());
  int i = int(std::floor(s));
  float t = s - i;
  auto P = [&](int k) { return pts[((k % n) + n) % n]; };
  vec3 p0 = P(i - 1), p1 = P(i), p2 = P(i + 1), p3 = P(i + 2);
  float t2 = t * t, t3 = t2 * t;
  return 0.5f * ((2.f * p1) + (-p0 + p2) * t + (2.f * p0 - 5.f * p1 + 4.f * p2 - p3) * t2 + (-p0 + 3.f * p1 - 3.f * p2 + p3) * t3);
}

void AddCameraBody(Gltf& g, int parentNode, int material) {
  MeshBuf body;
  AddBox(body, vec3(0, 0, 12), vec3(10, 8, 14), 0.f, 40.f);
  MeshBuf lens;
  AddCylinder(lens, vec3(0, 0, 0), 5.f, 10.f, 16, 1, true);
  // Lens points along -Z: rotate the Y cylinder to -Z.
  for (auto& p : lens.pos) p = vec3(p.x, -p.z, -p.y);
  for (auto& n : lens.nrm) n = vec3(n.x, -n.z, -n.y);
  body.Append(lens);
  int mesh = g.Mesh("CameraBody", body, material);
  int child = g.Node("CameraBodyMesh", ",\"mesh\":" + std::to_string(mesh));
  g.nodes[parentNode].insert(g.nodes[parentNode].size() - 1, ",\"children\":[" + std::to_string(child) + "]");
}

int Run(const Detail& d, const fs::path& out, uint64_t seed) {
  std::error_code ec;
  fs::create_directories(out / "textures", ec);
  if (ec) {
    fprintf(stderr, "drr_arenagen: cannot create %s: %s\n", out.string().c_str(), ec.message().c_str());
    return 1;
  }
  Rng rng(seed);
  const int T = d.texSize;
  uint64_t triTotal = 0;

  // Textures.
  struct TexFiles { std::string diffuse, normal, specular; };
  std::map<std::string, TexFiles> tex;
  auto save = [&](const std::string& name, const MaterialTextures& t) {
    TexFiles f;
    f.diffuse = "textures/" + name + "_diffuse.png";
    if (!WritePng(out / f.diffuse, t.diffuse)) return false;
    if (t.hasNormal) { f.normal = "textures/" + name + "_normal.png"; if (!WritePng(out / f.normal, t.normal)) return false; }
    if (t.hasSpecular) { f.specular = "textures/" + name + "_specular.png"; if (!WritePng(out / f.specular, t.specular)) return false; }
    tex[name] = f;
    return true;
  };
  bool ok = save("floor", MakeStone(T, 11, vec3(0.50f, 0.46f, 0.40f), vec3(0.18f, 0.16f, 0.14f), 4, 4, false, 0.5f)) &&
            save("brick", MakeStone(T, 23, vec3(0.55f, 0.30f, 0.22f), vec3(0.40f, 0.38f, 0.35f), 4, 8, true, 0.25f)) &&
            save("marble", MakeMarble(T, 37)) && save("rock", MakeRock(T, 41)) && save("bronze", MakeBronze(T, 53));
  MaterialTextures sky;
  sky.diffuse = MakeSky(T * 2, 61);
  MaterialTextures decal;
  decal.diffuse = MakeDecal(T, 71);
  ok = ok && save("sky", sky) && save("decal", decal);
  if (!ok) {
    fprintf(stderr, "drr_arenagen: cannot write the textures under %s\n", (out / "textures").string().c_str());
    return 1;
  }
  auto material = [&](Gltf& g, const std::string& mat, const std::string& texName, bool blend = false) {
    const TexFiles& f = tex[texName];
    int di = g.Image(f.diffuse);
    int ni = f.normal.empty() ? -1 : g.Image(f.normal);
    int si = f.specular.empty() ? -1 : g.Image(f.specular);
    return g.Material(mat, di, ni, si, blend);
  };

  // ---- arena.gltf: floor, walls, columns, arches, stairs, rubble, bell frame.
  {
    Gltf g;
    Chunked floor, walls, marble, rock;
    // Floor: tiles split per cell.
    int perCell = std::max(1, d.floorGrid / 4);
    for (int cz = 0; cz < 4; ++cz)
      for (int cx = 0; cx < 4; ++cx) {
        float x0 = -kHalf + cx * kHalf / 2, z0 = -kHalf + cz * kHalf / 2;
        // du along +X, dv along -Z so that the normal (du x dv) is +Y.
        AddGrid(floor.cells[cz * 4 + cx], vec3(x0, 0, z0 + kHalf / 2), vec3(kHalf / 2, 0, 0), vec3(0, 0, -kHalf / 2),
                perCell, perCell, 400.f,
                [&](float s, float t) {  // gentle, deterministic undulation (detail without LOD)
                  float x = x0 + s * kHalf / 2, z = z0 + kHalf / 2 - t * kHalf / 2;
                  return 1.5f * std::sin(x * 0.013f) * std::sin(z * 0.011f);
                });
      }
    // Walls: blocks of stone on the four sides, facing inwards, with buttresses.
    for (int side = 0; side < 4; ++side) {
      float yaw = side * kPi / 2;
      vec3 along(std::cos(yaw), 0, -std::sin(yaw)), inward(-std::sin(yaw), 0, -std::cos(yaw));
      vec3 wallCenter = -inward * (kHalf + 40.f);
      int cols = int(2 * kHalf / d.blockW), rows = int(kWallH / d.blockH);
      for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
          float off = (r & 1) ? 0.5f : 0.f;
          float s = -kHalf + (c + off) * d.blockW;
          float w = d.blockW;
          if (s + w > kHalf) w = kHalf - s;
          if (w < 1.f) continue;
          float jitter = rng.Uniform(-0.04f, 0.04f) * d.blockH;
          vec3 center = wallCenter + along * (s + w * 0.5f) + vec3(0, r * d.blockH + d.blockH * 0.5f, 0) + inward * jitter;
          AddBox(walls.At(center), center, vec3(w * 0.5f - 1.f, d.blockH * 0.5f - 1.f, 40.f), yaw, 200.f);
        }
      for (int b = 1; b < 8; ++b) {
        if (b == 4) continue;  // stairway in the middle
        vec3 c = wallCenter + along * (-kHalf + b * kHalf / 4) + inward * 80.f + vec3(0, kWallH * 0.5f, 0);
        AddBox(walls.At(c), c, vec3(50, kWallH * 0.5f, 45), yaw, 200.f, 2);
      }
      // Stairway: steps up to a landing against the wall.
      int steps = 14;
      for (int s = 0; s < steps; ++s) {
        float h = (s + 1) * 25.f;
        vec3 c = wallCenter + inward * (80.f + 40.f * (steps - s)) + vec3(0, h * 0.5f, 0);
        AddBox(walls.At(c), c, vec3(180, h * 0.5f, 20.f), yaw, 200.f);
      }
    }
    // Columns with bases and capitals, arches between neighbours.
    for (int i = 0; i < kColumns; ++i) {
      float a = 2 * kPi * i / kColumns;
      vec3 base(std::sin(a) * kColRing, 0, std::cos(a) * kColRing);
      MeshBuf& m = marble.At(base);
      AddBox(m, base + vec3(0, 20, 0), vec3(90, 20, 90), a, 200.f);
      AddCylinder(m, base + vec3(0, 40, 0), kColR, kColH - 80.f, d.columnRadial, d.columnRings, false,
                  [](float t) { return 1.f - 0.12f * t; });  // entasis
      AddBox(m, base + vec3(0, kColH - 20, 0), vec3(85, 20, 85), a, 200.f);
      float b2 = 2 * kPi * (i + 1) / kColumns;
      vec3 next(std::sin(b2) * kColRing, 0, std::cos(b2) * kColRing);
      AddArch(marble.At((base + next) * 0.5f), base + vec3(0, kColH + 20, 0), next + vec3(0, kColH + 20, 0), 60.f, 110.f, d.archSegs);
    }
    // Bell frame at the centre: two posts and a beam.
    {
      MeshBuf& m = marble.At(vec3(0));
      AddBox(m, vec3(-300, kBellPivotY * 0.5f + 20, 0), vec3(30, kBellPivotY * 0.5f + 20, 30), 0.f, 200.f, 2);
      AddBox(m, vec3(300, kBellPivotY * 0.5f + 20, 0), vec3(30, kBellPivotY * 0.5f + 20, 30), 0.f, 200.f, 2);
      AddBox(m, vec3(0, kBellPivotY + 40, 0), vec3(340, 25, 35), 0.f, 200.f, 4);
    }
    // Rubble: rocks scattered over the floor, more near the walls and columns.
    for (int i = 0; i < d.rocks; ++i) {
      vec3 p;
      if (i % 3 == 0) {  // near a wall
        float t = rng.Uniform(-kHalf + 100, kHalf - 100);
        int side = int(rng.Uniform(0, 4)) % 4;
        float inset = rng.Uniform(120, 400);
        p = side == 0 ? vec3(t, 0, kHalf - inset) : side == 1 ? vec3(t, 0, -kHalf + inset)
          : side == 2 ? vec3(kHalf - inset, 0, t) : vec3(-kHalf + inset, 0, t);
      } else if (i % 3 == 1) {  // around a column
        float a = 2 * kPi * int(rng.Uniform(0, kColumns)) / kColumns + rng.Uniform(-0.15f, 0.15f);
        float r = kColRing + rng.Uniform(-250, 250);
        p = vec3(std::sin(a) * r, 0, std::cos(a) * r);
      } else {
        p = vec3(rng.Uniform(-kHalf + 150, kHalf - 150), 0, rng.Uniform(-kHalf + 150, kHalf - 150));
        if (glm::length(vec3(p.x, 0, p.z)) < 450) p *= 3.f;  // keep the bell area clear
        p = glm::clamp(p, vec3(-kHalf + 150), vec3(kHalf - 150));
      }
      float s = rng.Uniform(8, 45) * (rng.Uniform() < 0.1f ? 2.5f : 1.f);
      vec3 sc(s * rng.Uniform(0.8f, 1.6f), s * rng.Uniform(0.5f, 1.0f), s * rng.Uniform(0.8f, 1.6f));
      p.y = sc.y * 0.6f;
      AddRock(rock.At(p), p, sc, d.rockSubdiv, rng);
    }
    int mFloor = material(g, "Floor", "floor"), mWall = material(g, "Brick", "brick"), mMarble = material(g, "Marble", "marble"),
        mRock = material(g, "Rock", "rock");
    std::vector<int> children;
    auto emit = [&](const char* name, Chunked& ch, int mat) {
      for (auto& [cell, m] : ch.cells) {
        if (m.idx.empty()) continue;
        triTotal += m.Tris();
        std::string n = std::string(name) + "_" + std::to_string(cell);
        int mesh = g.Mesh(n, m, mat);
        children.push_back(g.Node(n, ",\"mesh\":" + std::to_string(mesh)));
      }
    };
    emit("Floor", floor, mFloor);
    emit("Walls", walls, mWall);
    emit("Marble", marble, mMarble);
    emit("Rubble", rock, mRock);
    std::string kids;
    for (size_t i = 0; i < children.size(); ++i) kids += (i ? "," : "") + std::to_string(children[i]);
    g.sceneRoots.push_back(g.Node("Arena", ",\"children\":[" + kids + "]"));
    if (!g.Write(out, "arena")) return 1;
  }

  // ---- bell.gltf: a lathed bell under a pivot node that swings (rotation about X).
  {
    Gltf g;
    MeshBuf bell;
    // Profile (radius, height below the pivot) of a bell, outside then inside (lip).
    std::vector<vec2> prof = {{0, -60}, {70, -70}, {95, -120}, {105, -200}, {125, -300}, {175, -360}, {190, -380},
                              {170, -385}, {150, -360}, {105, -300}, {85, -200}, {75, -120}, {0, -100}};
    std::vector<vec2> fine;
    for (size_t i = 0; i + 1 < prof.size(); ++i)
      for (int k = 0; k < d.bellRings / 4 + 1; ++k) fine.push_back(glm::mix(prof[i], prof[i + 1], float(k) / (d.bellRings / 4 + 1)));
    fine.push_back(prof.back());
    int R = d.bellRadial;
    uint32_t base = 0;
    for (size_t j = 0; j < fine.size(); ++j) {
      vec2 tangent = fine[std::min(j + 1, fine.size() - 1)] - fine[j > 0 ? j - 1 : 0];
      for (int i = 0; i <= R; ++i) {
        float a = 2 * kPi * i / R;
        vec3 dir(std::sin(a), 0, std::cos(a));
        vec3 p = dir * fine[j].x + vec3(0, fine[j].y, 0);
        // Outward normal of the profile: rotate the 2-D tangent (dr, dy) by -90 degrees.
        vec2 n2 = glm::length(tangent) > 0 ? glm::normalize(vec2(-tangent.y, tangent.x)) : vec2(0, 1);
        vec3 n = glm::normalize(dir * n2.x + vec3(0, n2.y, 0));
        bell.Vert(p, glm::length(n) > 0 ? n : vec3(0, 1, 0), vec2(float(i) / R * 3.f, float(j) / fine.size()));
      }
    }
    for (size_t j = 0; j + 1 < fine.size(); ++j)
      for (int i = 0; i < R; ++i) {
        uint32_t a = base + uint32_t(j) * (R + 1) + i;
        bell.Tri(a, a + R + 1, a + 1);
        bell.Tri(a + 1, a + R + 1, a + R + 2);
      }
    // Drop degenerate triangles at the poles (radius 0) and fix normals' orientation per triangle.
    {
      std::vector<uint32_t> keep;
      for (size_t t = 0; t < bell.idx.size(); t += 3) {
        vec3 a = bell.pos[bell.idx[t]], b = bell.pos[bell.idx[t + 1]], c = bell.pos[bell.idx[t + 2]];
        vec3 fn = glm::cross(b - a, c - a);
        if (glm::length(fn) < 1e-4f) continue;
        if (glm::dot(fn, bell.nrm[bell.idx[t]] + bell.nrm[bell.idx[t + 1]] + bell.nrm[bell.idx[t + 2]]) < 0)
          keep.insert(keep.end(), {bell.idx[t], bell.idx[t + 2], bell.idx[t + 1]});
        else
          keep.insert(keep.end(), {bell.idx[t], bell.idx[t + 1], bell.idx[t + 2]});
      }
      bell.idx.swap(keep);
    }
    AddCylinder(bell, vec3(0, -65, 0), 12.f, 65.f, 12, 1, false);  // the hanger
    MeshBuf clapper;
    Rng r2(seed + 99);
    AddRock(clapper, vec3(0, -330, 0), vec3(28, 34, 28), 1, r2);
    bell.Append(clapper);
    triTotal += bell.Tris();
    int mat = material(g, "Bronze", "bronze");
    int mesh = g.Mesh("Bell", bell, mat);
    int bellNode = g.Node("BellMesh", ",\"mesh\":" + std::to_string(mesh));
    int pivot = g.Node("BellPivot", Gltf::TRS(vec3(0, kBellPivotY, 0), glm::quat(1, 0, 0, 0)) + ",\"children\":[" +
                                         std::to_string(bellNode) + "]");
    g.sceneRoots.push_back(pivot);
    const float period = 4.f, amp = glm::radians(28.f);
    const int keys = 120;  // dense sampling of a sine swing; first and last keys are equal (smooth loop)
    std::vector<float> times;
    std::vector<glm::quat> rots;
    for (int k = 0; k <= keys; ++k) {
      float t = period * k / keys;
      times.push_back(t);
      rots.push_back(glm::angleAxis(amp * std::sin(2 * kPi * k / keys), vec3(1, 0, 0)));
    }
    g.Animation("Swing", pivot, times, nullptr, &rots);
    if (!g.Write(out, "bell")) return 1;
  }

  // ---- sky.gltf: an inward-facing dome (unlit).
  {
    Gltf g;
    MeshBuf sky;
    const float R = 150000.f;
    int S = d.skySegs, Rn = d.skySegs / 2;
    for (int j = 0; j <= Rn; ++j) {
      float v = float(j) / Rn, th = v * kPi;  // 0 zenith .. pi nadir
      for (int i = 0; i <= S; ++i) {
        float ph = 2 * kPi * i / S;
        vec3 dir(std::sin(th) * std::sin(ph), std::cos(th), std::sin(th) * std::cos(ph));
        sky.Vert(dir * R, -dir, vec2(float(i) / S, v));
      }
    }
    for (int j = 0; j < Rn; ++j)
      for (int i = 0; i < S; ++i) {
        uint32_t a = j * (S + 1) + i;
        // Facing inwards: seen from the centre, counter-clockwise.
        if (j != 0) sky.Tri(a, a + 1, a + S + 1);
        if (j != Rn - 1) sky.Tri(a + 1, a + S + 2, a + S + 1);
      }
    triTotal += sky.Tris();
    int mat = material(g, "Sky", "sky");
    int mesh = g.Mesh("SkyDome", sky, mat);
    g.sceneRoots.push_back(g.Node("Sky", ",\"mesh\":" + std::to_string(mesh)));
    if (!g.Write(out, "sky")) return 1;
  }

  // ---- decals.gltf: alpha-blended quads slightly above the floor and in front of the walls.
  {
    Gltf g;
    MeshBuf dm;
    Rng r3(seed + 7);
    auto quad = [&](vec3 c, vec3 du, vec3 dv, int atlas) {
      vec3 n = glm::normalize(glm::cross(du, dv));
      vec2 o((atlas & 1) * 0.5f, (atlas >> 1) * 0.5f);
      uint32_t a = dm.Vert(c - du * 0.5f - dv * 0.5f, n, o + vec2(0, 0.5f));
      uint32_t b = dm.Vert(c + du * 0.5f - dv * 0.5f, n, o + vec2(0.5f, 0.5f));
      uint32_t cc = dm.Vert(c + du * 0.5f + dv * 0.5f, n, o + vec2(0.5f, 0));
      uint32_t e = dm.Vert(c - du * 0.5f + dv * 0.5f, n, o);
      dm.Quad(a, b, cc, e);
    };
    for (int i = 0; i < 40; ++i) {  // floor decals (2 units above the highest undulation)
      vec3 c(r3.Uniform(-1800, 1800), 4.f, r3.Uniform(-1800, 1800));
      float s = r3.Uniform(120, 420), a = r3.Uniform(0, 2 * kPi);
      vec3 du(std::cos(a) * s, 0, -std::sin(a) * s), dv(-std::sin(a) * s, 0, -std::cos(a) * s);
      if (glm::dot(glm::cross(du, dv), vec3(0, 1, 0)) < 0) dv = -dv;
      quad(c, du, dv, i % 4);
    }
    for (int side = 0; side < 4; ++side)  // wall decals, 2 units in front of the block faces
      for (int k = 0; k < 4; ++k) {
        float yaw = side * kPi / 2;
        vec3 along(std::cos(yaw), 0, -std::sin(yaw)), inward(-std::sin(yaw), 0, -std::cos(yaw));
        float t = -1500.f + k * 1000.f + r3.Uniform(-150, 150);
        float s = r3.Uniform(180, 320);
        vec3 c = -inward * kHalf + inward * (2.f + 0.05f * d.blockH) + along * t + vec3(0, r3.Uniform(200, 600), 0);
        vec3 du = -along * s, dv = vec3(0, s, 0);
        if (glm::dot(glm::cross(du, dv), inward) < 0) du = -du;
        quad(c, du, dv, (k + side) % 4);
      }
    triTotal += dm.Tris();
    int mat = material(g, "Decals", "decal", true);
    int mesh = g.Mesh("Decals", dm, mat);
    g.sceneRoots.push_back(g.Node("Decals", ",\"mesh\":" + std::to_string(mesh)));
    if (!g.Write(out, "decals")) return 1;
  }

  // ---- cameras: cinematic (animated along a closed Catmull-Rom path) and two static ones.
  const float fov = glm::radians(45.f);
  auto cameraFile = [&](const std::string& stem, const std::string& nodeName, vec3 pos, vec3 target, bool animate) {
    Gltf g;
    int camMat = g.Material("CameraBody", -1, -1, -1, false, vec3(0.2f, 0.2f, 0.22f));
    int cam = g.Camera(fov, 20.f, 400000.f);
    glm::quat q = glm::quatLookAtRH(glm::normalize(target - pos), vec3(0, 1, 0));
    int node = g.Node(nodeName, Gltf::TRS(pos, q) + ",\"camera\":" + std::to_string(cam));
    AddCameraBody(g, node, camMat);
    g.sceneRoots.push_back(node);
    if (animate) {
      std::vector<vec3> path = {{-1500, 250, -1500}, {0, 450, -1650}, {1500, 300, -1400}, {1650, 650, 0},
                                {1400, 220, 1450}, {0, 350, 1650}, {-1450, 800, 1400}, {-1650, 300, 0}};
      std::vector<vec3> look = {{0, 300, 0}, {300, 200, 300}, {0, 500, 0}, {-400, 150, 0},
                                {0, 600, 0}, {300, 250, -300}, {0, 450, 0}, {0, 200, 400}};
      const float loop = 48.f;
      const int keys = 48 * 30;  // 30 keys per second; the last equals the first
      std::vector<float> times;
      std::vector<vec3> ts;
      std::vector<glm::quat> rs;
      for (int k = 0; k <= keys; ++k) {
        float s = float(k % keys) / keys * path.size();
        vec3 p = CatmullRom(path, s), l = CatmullRom(look, s);
        glm::quat r = glm::quatLookAtRH(glm::normalize(l - p), vec3(0, 1, 0));
        if (!rs.empty() && glm::dot(rs.back(), r) < 0) r = -r;  // keep the quaternions on one hemisphere
        times.push_back(loop * k / keys);
        ts.push_back(p);
        rs.push_back(r);
      }
      g.Animation("CinematicPath", node, times, &ts, &rs);
    }
    return g.Write(out, stem);
  };
  if (!cameraFile("camera_cinematic", "CinematicCamera", vec3(-1500, 250, -1500), vec3(0, 300, 0), true) ||
      !cameraFile("camera_static1", "StaticCamera1", vec3(-1650, 420, 1650), vec3(0, 250, 0), false) ||
      !cameraFile("camera_static2", "StaticCamera2", vec3(1550, 1100, -900), vec3(0, kBellPivotY - 200, 0), false)) {
    fprintf(stderr, "drr_arenagen: cannot write the camera files\n");
    return 1;
  }

  // ---- scene_description.txt in the original's form (mesh, animation or NO_ANIM, type).
  std::ofstream sd(out / "scene_description.txt", std::ios::binary);
  sd << "# Arena (" << d.name << " detail, " << triTotal << " triangles), generated by drr_arenagen --detail " << d.name
     << " --seed " << seed << "\n"
     << "# mesh                  animation              type\n"
     << "arena.gltf              NO_ANIM                LIT\n"
     << "bell.gltf               bell.gltf              LIT\n"
     << "sky.gltf                NO_ANIM                UNLIT\n"
     << "decals.gltf             NO_ANIM                DECAL\n"
     << "camera_cinematic.gltf   camera_cinematic.gltf  CAMERA\n"
     << "camera_static1.gltf     NO_ANIM                CAMERA\n"
     << "camera_static2.gltf     NO_ANIM                CAMERA\n";
  if (!sd) return 1;
  printf("drr_arenagen: wrote the %s Arena (%llu triangles) to %s\n", d.name, (unsigned long long)triTotal, out.string().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string outDir, detail = "small";
  uint64_t seed = 20110301;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) outDir = argv[++i];
    else if (a == "--detail" && i + 1 < argc) detail = argv[++i];
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else {
      fprintf(stderr, "usage: drr_arenagen --out <dir> [--detail small|large] [--seed N]\n");
      return 2;
    }
  }
  if (outDir.empty() || (detail != "small" && detail != "large")) {
    fprintf(stderr, "usage: drr_arenagen --out <dir> [--detail small|large] [--seed N]\n");
    return 2;
  }
  return Run(detail == "small" ? kSmall : kLarge, outDir, seed);
}
