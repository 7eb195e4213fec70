#include "ArenaMesh.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace arena {

void AddGrid(MeshBuf& m, vec3 origin, vec3 du, vec3 dv, int nu, int nv, float texScale,
             const std::function<float(float, float)>& bump) {
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

void AddBox(MeshBuf& m, vec3 c, vec3 h, float yaw, float texScale, int subdiv) {
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

void AddCylinder(MeshBuf& m, vec3 base, float r, float height, int radial, int rings, bool caps,
                 const std::function<float(float)>& profile) {
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

}  // namespace arena
