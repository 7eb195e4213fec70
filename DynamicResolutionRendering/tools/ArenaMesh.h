// Triangle meshes of the Arena and the primitives they are built from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "ArenaMath.h"

namespace arena {

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
             const std::function<float(float, float)>& bump = nullptr);
// Oriented box (rotation about Y), UVs in world units / texScale.
void AddBox(MeshBuf& m, vec3 c, vec3 h, float yaw, float texScale, int subdiv = 1);
// Cylinder along Y (side only, plus optional caps), UV u around, v along height.
void AddCylinder(MeshBuf& m, vec3 base, float r, float height, int radial, int rings, bool caps,
                 const std::function<float(float)>& profile = nullptr);
// Icosphere (subdivided), displaced by noise: a rock.
void AddRock(MeshBuf& m, vec3 c, vec3 scale, int subdiv, Rng& rng);
// Arch between two points (a half ring of rectangular section), in the vertical plane through a and b.
void AddArch(MeshBuf& m, vec3 a, vec3 b, float thickness, float depth, int segs);

}  // namespace arena
