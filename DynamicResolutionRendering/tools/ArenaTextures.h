// Procedural, tileable textures of the Arena's materials and their PNG files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "ArenaMath.h"

namespace arena {

struct Image {
  int w, h, c;
  std::vector<uint8_t> px;
};

struct MaterialTextures {
  Image diffuse, normal, specular;
  bool hasNormal = false, hasSpecular = false;
};

bool WritePng(const std::filesystem::path& file, const Image& img);

// Stone blocks or tiles: diffuse, normal and specular maps.
MaterialTextures MakeStone(int n, uint32_t seed, vec3 base, vec3 mortarCol, int cols, int rows, bool offset,
                           float specLevel);
MaterialTextures MakeMarble(int n, uint32_t seed);
MaterialTextures MakeRock(int n, uint32_t seed);    // normal map, no specular map
MaterialTextures MakeBronze(int n, uint32_t seed);  // specular map, no normal map
Image MakeSky(int n, uint32_t seed);    // n x n/2: u = azimuth, v = 0 zenith .. 1 below horizon
Image MakeDecal(int n, uint32_t seed);
Image MakeFloorHeight(int n, uint32_t seed);  // the floor's displacement map (Docs/Tessellation.md)  // 2x2 atlas of scorch marks / cracks / glyphs, with alpha

}  // namespace arena
