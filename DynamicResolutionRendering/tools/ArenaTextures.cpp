#include "ArenaTextures.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/imageio.h>

namespace fs = std::filesystem;

namespace arena {
namespace {

// Deterministic periodic noise.
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

// A colour channel in [0,1] as an 8-bit value.
uint8_t B(float v) { return uint8_t(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); }

// An RGBA8 image, all zero.
Image Blank(int w, int h) { return {w, h, 4, std::vector<uint8_t>(size_t(w) * h * 4)}; }

void Put(Image& img, int x, int y, vec3 c, uint8_t alpha = 255) {
  uint8_t* p = &img.px[(size_t(y) * img.w + x) * 4];
  p[0] = B(c.r); p[1] = B(c.g); p[2] = B(c.b); p[3] = alpha;
}

void PutGray(Image& img, int x, int y, float v) {
  uint8_t* q = &img.px[(size_t(y) * img.w + x) * 4];
  q[0] = q[1] = q[2] = B(v); q[3] = 255;
}

// Height field (tileable) -> tangent-space normal map (+X = +u, +Y = +v, v downwards in the image).
Image NormalFromHeight(const std::vector<float>& h, int n, float strength) {
  Image img = Blank(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      auto H = [&](int xx, int yy) { return h[size_t((yy + n) % n) * n + (xx + n) % n]; };
      float dx = (H(x + 1, y) - H(x - 1, y)) * strength, dy = (H(x, y + 1) - H(x, y - 1)) * strength;
      vec3 nn = glm::normalize(vec3(-dx, -dy, 1.f));
      Put(img, x, y, nn * 0.5f + 0.5f);
    }
  return img;
}

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

}  // namespace

bool WritePng(const fs::path& file, const Image& img) {
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) return false;
  OIIO::ImageSpec spec(img.w, img.h, img.c, OIIO::TypeDesc::UINT8);
  if (!out->open(file.string(), spec)) return false;
  bool ok = out->write_image(OIIO::TypeDesc::UINT8, img.px.data());
  out->close();
  return ok;
}

// Calls texel(x, y, u, v) for each texel of an n x n texture, (u, v) at its centre.
template <class Texel>
void ForEachTexel(int n, Texel texel) {
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) texel(x, y, (x + 0.5f) / n, (y + 0.5f) / n);
}

// n x n diffuse (and specular) maps, all zero.
MaterialTextures BlankMaterial(int n, bool withSpecular) {
  MaterialTextures t;
  t.diffuse = Blank(n, n);
  if (withSpecular) t.specular = Blank(n, n);
  t.hasSpecular = withSpecular;
  return t;
}

MaterialTextures MakeStone(int n, uint32_t seed, vec3 base, vec3 mortarCol, int cols, int rows, bool offset,
                           float specLevel) {
  MaterialTextures t = BlankMaterial(n, true);
  std::vector<float> height(size_t(n) * n);
  ForEachTexel(n, [&](int x, int y, float u, float v) {
    int id;
    float blk = BlockPattern(u, v, cols, rows, offset, 0.012f, &id);
    float nz = Fbm(u, v, 8, 5, seed);
    float tint = Hash2(id, 7, seed) * 0.25f + 0.85f;
    vec3 c = glm::mix(mortarCol, base * tint * (0.75f + 0.5f * nz), blk);
    height[size_t(y) * n + x] = blk * 0.6f + nz * 0.4f;
    Put(t.diffuse, x, y, c);
    PutGray(t.specular, x, y, specLevel * blk * (0.6f + 0.8f * Fbm(u, v, 16, 3, seed + 9)));
  });
  t.normal = NormalFromHeight(height, n, n / 64.f);
  t.hasNormal = true;
  return t;
}

MaterialTextures MakeMarble(int n, uint32_t seed) {
  MaterialTextures t = BlankMaterial(n, true);
  std::vector<float> height(size_t(n) * n);
  ForEachTexel(n, [&](int x, int y, float u, float v) {
    float turb = Fbm(u, v, 4, 6, seed);
    float vein = std::pow(std::fabs(std::sin((u * 4.f + turb * 6.f) * kPi)), 0.35f);
    vec3 c = glm::mix(vec3(0.35f, 0.33f, 0.32f), vec3(0.85f, 0.83f, 0.78f), vein);
    // Flutes along v (columns): a cosine groove pattern.
    float flute = 0.5f + 0.5f * std::cos(u * 2 * kPi * 12.f);
    height[size_t(y) * n + x] = flute * 0.7f + turb * 0.3f;
    Put(t.diffuse, x, y, c);
    PutGray(t.specular, x, y, 0.35f + 0.5f * vein);
  });
  t.normal = NormalFromHeight(height, n, n / 96.f);
  t.hasNormal = true;
  return t;
}

MaterialTextures MakeRock(int n, uint32_t seed) {  // normal map, no specular map
  MaterialTextures t = BlankMaterial(n, false);
  std::vector<float> height(size_t(n) * n);
  ForEachTexel(n, [&](int x, int y, float u, float v) {
    float a = Fbm(u, v, 6, 6, seed), b = Fbm(u, v, 24, 3, seed + 5);
    vec3 c = vec3(0.42f, 0.38f, 0.33f) * (0.6f + 0.7f * a) + vec3(0.05f) * b;
    height[size_t(y) * n + x] = a * 0.8f + b * 0.2f;
    Put(t.diffuse, x, y, c);
  });
  t.normal = NormalFromHeight(height, n, n / 24.f);
  t.hasNormal = true;
  return t;
}

MaterialTextures MakeBronze(int n, uint32_t seed) {  // specular map, no normal map
  MaterialTextures t = BlankMaterial(n, true);
  ForEachTexel(n, [&](int x, int y, float u, float v) {
    float patina = glm::smoothstep(0.55f, 0.75f, Fbm(u, v, 4, 5, seed));
    vec3 c = glm::mix(vec3(0.55f, 0.36f, 0.16f), vec3(0.22f, 0.45f, 0.38f), patina);
    float band = std::fmod(v * 10.f, 1.f) < 0.08f ? 0.7f : 1.f;
    c *= band;
    Put(t.diffuse, x, y, c);
    PutGray(t.specular, x, y, 0.9f * (1.f - patina) + 0.1f);
  });
  return t;
}

Image MakeSky(int n, uint32_t seed) {  // u = azimuth, v = 0 zenith .. 1 below horizon
  Image img = Blank(n, n / 2);
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
      Put(img, x, y, c);
    }
  return img;
}

Image MakeDecal(int n, uint32_t seed) {  // 2x2 atlas of scorch marks / cracks / glyphs, with alpha
  Image img = Blank(n, n);
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
      Put(img, x, y, c, B(a));
    }
  return img;
}


// The floor's displacement map (grey, 0 in the mortar, up to 1 on a stone),
// for --tessellation. Its pattern repeats every half texture: the floor's
// cells are 2.5 texture repeats wide and each starts at texture coordinate 0,
// so a period of 0.5 gives the same height on both sides of a cell border
// (no crack). Its stones fall on MakeStone's 4x4 grid.
Image MakeFloorHeight(int n, uint32_t seed) {
  Image img = Blank(n, n);
  ForEachTexel(n, [&](int x, int y, float u, float v) {
    const float u2 = std::fmod(2.f * u, 1.f), v2 = std::fmod(2.f * v, 1.f);
    int id;
    const float blk = BlockPattern(u2, v2, 2, 2, false, 0.024f, &id);
    const float dome = Fbm(u2, v2, 4, 4, seed);
    PutGray(img, x, y, blk * (0.55f + 0.45f * dome));
  });
  return img;
}

}  // namespace arena
