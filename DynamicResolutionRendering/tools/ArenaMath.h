// Shared by the Arena generator's files: the constant pi and a small
// deterministic random number generator (fixed seeds give the same Arena on
// every machine, so no standard-library engine whose output may differ).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace arena {

using glm::vec2;
using glm::vec3;

constexpr float kPi = 3.14159265358979f;

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

}  // namespace arena
