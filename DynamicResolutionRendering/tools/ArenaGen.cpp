// drr_arenagen: writes the project's default scene, "Arena", as real files
// (glTF 2.0 .gltf + .bin written here, PNG textures through OpenImageIO, and a
// scene_description.txt in the original sample's form), which the sample then
// loads through the same Assimp / OpenImageIO path as any user's model.
//
// Contents (with tessellation rules and the floor's displacement map, used
// only with the sample's --tessellation): a walled arena a few thousand units across (floor, walls of stone
// blocks, a ring of columns with arches, stairways, scattered rubble) with
// normal- and specular-mapped materials on procedural textures; a bell
// swinging on a frame (node rotation animation); an unlit sky dome;
// alpha-blended decals on the floor and walls; a cinematic camera on a closed
// Catmull-Rom path (camera node animation, looping smoothly); two static
// cameras. No LOD. Output is deterministic (fixed seeds, own RNG).
//
// usage: drr_arenagen --out <dir> [--detail small|large|props] [--props N] [--seed N]
// props: the small Arena with N (default 3000) props on its floor, one draw
// each (ArenaGenProps.h).
//
// Textures, meshes and the glTF writer live in ArenaTextures, ArenaMesh and
// ArenaGltf; this file lays out the scene and writes its files. The small
// SDKMESH set of the reader tests (ArenaGenSdkMesh.h) goes into <out>/sdkmesh.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "ArenaGenDds.h"
#include "ArenaGenProps.h"
#include "ArenaGenSdkMesh.h"
#include "ArenaGltf.h"
#include "ArenaMath.h"
#include "ArenaMesh.h"
#include "ArenaTextures.h"

namespace fs = std::filesystem;
using namespace arena;

namespace {

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
  int props = 0;  // props.gltf's count (0: no file)
};
constexpr Detail kSmall{"small", 80, 200.f, 100.f, 24, 6, 16, 170, 1, 256, 32, 16, 32};
constexpr Detail kProps{"props", 80, 200.f, 100.f, 24, 6, 16, 170, 1, 256, 32, 16, 32, 3000};
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
  int child = g.MeshNode("CameraBodyMesh", "CameraBody", body, material);
  g.nodes[parentNode].insert(g.nodes[parentNode].size() - 1, ",\"children\":[" + std::to_string(child) + "]");
}

// ---------------------------------------------------------------------------
// Textures: written once, referenced by every file's materials.
struct TexFiles {
  std::string diffuse, normal, specular;  // paths relative to the output folder; empty = none
};
using TextureSet = std::map<std::string, TexFiles>;

bool SaveTextures(const fs::path& out, const std::string& name, const MaterialTextures& t, TextureSet& tex) {
  TexFiles f;
  f.diffuse = "textures/" + name + "_diffuse.png";
  if (!WritePng(out / f.diffuse, t.diffuse)) return false;
  if (t.hasNormal) { f.normal = "textures/" + name + "_normal.png"; if (!WritePng(out / f.normal, t.normal)) return false; }
  if (t.hasSpecular) { f.specular = "textures/" + name + "_specular.png"; if (!WritePng(out / f.specular, t.specular)) return false; }
  tex[name] = f;
  return true;
}

bool WriteAllTextures(const fs::path& out, int texSize, TextureSet& tex) {
  const int T = texSize;
  auto save = [&](const std::string& name, const MaterialTextures& t) { return SaveTextures(out, name, t, tex); };
  bool ok = save("floor", MakeStone(T, 11, vec3(0.50f, 0.46f, 0.40f), vec3(0.18f, 0.16f, 0.14f), 4, 4, false, 0.5f)) &&
            save("brick", MakeStone(T, 23, vec3(0.55f, 0.30f, 0.22f), vec3(0.40f, 0.38f, 0.35f), 4, 8, true, 0.25f)) &&
            save("marble", MakeMarble(T, 37)) && save("rock", MakeRock(T, 41)) && save("bronze", MakeBronze(T, 53));
  MaterialTextures sky;
  sky.diffuse = MakeSky(T * 2, 61);
  MaterialTextures decal;
  decal.diffuse = MakeDecal(T, 71);
  // The floor's displacement map, read only with --tessellation (Docs/Tessellation.md).
  const bool height = WritePng(out / "textures/floor_height.png", MakeFloorHeight(T, 11));
  return ok && height && save("sky", sky) && save("decal", decal);
}

// A material of g using the textures saved under texName.
int AddMaterial(Gltf& g, const TextureSet& tex, const std::string& mat, const std::string& texName, bool blend = false) {
  const TexFiles& f = tex.at(texName);
  int di = g.Image(f.diffuse);
  int ni = f.normal.empty() ? -1 : g.Image(f.normal);
  int si = f.specular.empty() ? -1 : g.Image(f.specular);
  return g.Material(mat, di, ni, si, blend);
}

// ---------------------------------------------------------------------------
// arena.gltf: floor, walls, columns, arches, stairs, rubble, bell frame.

// Floor: tiles split per cell.
void BuildFloor(const Detail& d, Chunked& floor) {
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
}

// Walls: blocks of stone on the four sides, facing inwards, with buttresses.
void BuildWalls(const Detail& d, Rng& rng, Chunked& walls) {
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
}

// Columns with bases and capitals, arches between neighbours; the bell frame at the centre.
void BuildColumnsAndBellFrame(const Detail& d, Chunked& marble) {
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
  // Bell frame: two posts and a beam.
  MeshBuf& m = marble.At(vec3(0));
  AddBox(m, vec3(-300, kBellPivotY * 0.5f + 20, 0), vec3(30, kBellPivotY * 0.5f + 20, 30), 0.f, 200.f, 2);
  AddBox(m, vec3(300, kBellPivotY * 0.5f + 20, 0), vec3(30, kBellPivotY * 0.5f + 20, 30), 0.f, 200.f, 2);
  AddBox(m, vec3(0, kBellPivotY + 40, 0), vec3(340, 25, 35), 0.f, 200.f, 4);
}

// Where the i-th rock lies: a third near a wall, a third around a column, the rest anywhere but the bell area.
vec3 RubblePosition(int i, Rng& rng) {
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
  return p;
}

// Rubble: rocks scattered over the floor, more near the walls and columns.
void BuildRubble(const Detail& d, Rng& rng, Chunked& rock) {
  for (int i = 0; i < d.rocks; ++i) {
    vec3 p = RubblePosition(i, rng);
    float s = rng.Uniform(8, 45) * (rng.Uniform() < 0.1f ? 2.5f : 1.f);
    vec3 sc(s * rng.Uniform(0.8f, 1.6f), s * rng.Uniform(0.5f, 1.0f), s * rng.Uniform(0.8f, 1.6f));
    p.y = sc.y * 0.6f;
    AddRock(rock.At(p), p, sc, d.rockSubdiv, rng);
  }
}

// One node per non-empty cell, named <name>_<cell>; their indices go to children.
void AddChunkNodes(Gltf& g, const char* name, const Chunked& ch, int mat, std::vector<int>& children,
                   uint64_t& triTotal) {
  for (auto& [cell, m] : ch.cells) {
    if (m.idx.empty()) continue;
    triTotal += m.Tris();
    std::string n = std::string(name) + "_" + std::to_string(cell);
    children.push_back(g.MeshNode(n, n, m, mat));
  }
}

bool WriteArena(const Detail& d, Rng& rng, const TextureSet& tex, const fs::path& out, uint64_t& triTotal) {
  Gltf g;
  Chunked floor, walls, marble, rock;
  BuildFloor(d, floor);
  BuildWalls(d, rng, walls);
  BuildColumnsAndBellFrame(d, marble);
  BuildRubble(d, rng, rock);
  int mFloor = AddMaterial(g, tex, "Floor", "floor"), mWall = AddMaterial(g, tex, "Brick", "brick"),
      mMarble = AddMaterial(g, tex, "Marble", "marble"), mRock = AddMaterial(g, tex, "Rock", "rock");
  std::vector<int> children;
  AddChunkNodes(g, "Floor", floor, mFloor, children, triTotal);
  AddChunkNodes(g, "Walls", walls, mWall, children, triTotal);
  AddChunkNodes(g, "Marble", marble, mMarble, children, triTotal);
  AddChunkNodes(g, "Rubble", rock, mRock, children, triTotal);
  std::string kids;
  for (size_t i = 0; i < children.size(); ++i) kids += (i ? "," : "") + std::to_string(children[i]);
  g.sceneRoots.push_back(g.Node("Arena", ",\"children\":[" + kids + "]"));
  return g.Write(out, "arena");
}

// ---------------------------------------------------------------------------
// bell.gltf: a lathed bell under a pivot node that swings (rotation about X).

// Lathes the bell's profile around Y.
MeshBuf LatheBell(const Detail& d) {
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
  return bell;
}

// Drops degenerate triangles (at the poles, where the radius is 0) and turns
// each remaining one to agree with its vertices' normals.
void DropDegenerateAndOrient(MeshBuf& m) {
  std::vector<uint32_t> keep;
  for (size_t t = 0; t < m.idx.size(); t += 3) {
    vec3 a = m.pos[m.idx[t]], b = m.pos[m.idx[t + 1]], c = m.pos[m.idx[t + 2]];
    vec3 fn = glm::cross(b - a, c - a);
    if (glm::length(fn) < 1e-4f) continue;
    if (glm::dot(fn, m.nrm[m.idx[t]] + m.nrm[m.idx[t + 1]] + m.nrm[m.idx[t + 2]]) < 0)
      keep.insert(keep.end(), {m.idx[t], m.idx[t + 2], m.idx[t + 1]});
    else
      keep.insert(keep.end(), {m.idx[t], m.idx[t + 1], m.idx[t + 2]});
  }
  m.idx.swap(keep);
}

// The swing: a dense sampling of a sine; first and last keys are equal (smooth loop).
void AddSwing(Gltf& g, int pivot) {
  const float period = 4.f, amp = glm::radians(28.f);
  const int keys = 120;
  std::vector<float> times;
  std::vector<glm::quat> rots;
  for (int k = 0; k <= keys; ++k) {
    float t = period * k / keys;
    times.push_back(t);
    rots.push_back(glm::angleAxis(amp * std::sin(2 * kPi * k / keys), vec3(1, 0, 0)));
  }
  g.Animation("Swing", pivot, times, nullptr, &rots);
}

bool WriteBell(const Detail& d, uint64_t seed, const TextureSet& tex, const fs::path& out, uint64_t& triTotal) {
  Gltf g;
  MeshBuf bell = LatheBell(d);
  DropDegenerateAndOrient(bell);
  AddCylinder(bell, vec3(0, -65, 0), 12.f, 65.f, 12, 1, false);  // the hanger
  MeshBuf clapper;
  Rng r2(seed + 99);
  AddRock(clapper, vec3(0, -330, 0), vec3(28, 34, 28), 1, r2);
  bell.Append(clapper);
  triTotal += bell.Tris();
  int mat = AddMaterial(g, tex, "Bronze", "bronze");
  int bellNode = g.MeshNode("BellMesh", "Bell", bell, mat);
  int pivot = g.Node("BellPivot", Gltf::TRS(vec3(0, kBellPivotY, 0), glm::quat(1, 0, 0, 0)) + ",\"children\":[" +
                                       std::to_string(bellNode) + "]");
  g.sceneRoots.push_back(pivot);
  AddSwing(g, pivot);
  return g.Write(out, "bell");
}

// ---------------------------------------------------------------------------
// sky.gltf: an inward-facing dome (unlit).
MeshBuf BuildSkyDome(const Detail& d) {
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
  return sky;
}

// A file whose one root node holds one mesh.
bool WriteSingleMeshFile(const fs::path& out, const std::string& stem, const std::string& nodeName,
                         const std::string& meshName, const MeshBuf& m, const TextureSet& tex,
                         const std::string& matName, const std::string& texName, bool blend, uint64_t& triTotal) {
  Gltf g;
  triTotal += m.Tris();
  int mat = AddMaterial(g, tex, matName, texName, blend);
  g.sceneRoots.push_back(g.MeshNode(nodeName, meshName, m, mat));
  return g.Write(out, stem);
}

// ---------------------------------------------------------------------------
// decals.gltf: alpha-blended quads slightly above the floor and in front of the walls.

// Quad centred on c with edges du, dv, showing cell 'atlas' of the 2x2 decal atlas.
void AddDecalQuad(MeshBuf& dm, vec3 c, vec3 du, vec3 dv, int atlas) {
  vec3 n = glm::normalize(glm::cross(du, dv));
  vec2 o((atlas & 1) * 0.5f, (atlas >> 1) * 0.5f);
  uint32_t a = dm.Vert(c - du * 0.5f - dv * 0.5f, n, o + vec2(0, 0.5f));
  uint32_t b = dm.Vert(c + du * 0.5f - dv * 0.5f, n, o + vec2(0.5f, 0.5f));
  uint32_t cc = dm.Vert(c + du * 0.5f + dv * 0.5f, n, o + vec2(0.5f, 0));
  uint32_t e = dm.Vert(c - du * 0.5f + dv * 0.5f, n, o);
  dm.Quad(a, b, cc, e);
}

MeshBuf BuildDecals(const Detail& d, uint64_t seed) {
  MeshBuf dm;
  Rng r3(seed + 7);
  for (int i = 0; i < 40; ++i) {  // floor decals (2 units above the highest undulation)
    vec3 c(r3.Uniform(-1800, 1800), 4.f, r3.Uniform(-1800, 1800));
    float s = r3.Uniform(120, 420), a = r3.Uniform(0, 2 * kPi);
    vec3 du(std::cos(a) * s, 0, -std::sin(a) * s), dv(-std::sin(a) * s, 0, -std::cos(a) * s);
    if (glm::dot(glm::cross(du, dv), vec3(0, 1, 0)) < 0) dv = -dv;
    AddDecalQuad(dm, c, du, dv, i % 4);
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
      AddDecalQuad(dm, c, du, dv, (k + side) % 4);
    }
  return dm;
}

// ---------------------------------------------------------------------------
// Cameras: cinematic (animated along a closed Catmull-Rom path) and two static ones.

// 48 s around the arena, 30 keys per second; the last key equals the first.
void AddCinematicPath(Gltf& g, int node) {
  std::vector<vec3> path = {{-1500, 250, -1500}, {0, 450, -1650}, {1500, 300, -1400}, {1650, 650, 0},
                            {1400, 220, 1450}, {0, 350, 1650}, {-1450, 800, 1400}, {-1650, 300, 0}};
  std::vector<vec3> look = {{0, 300, 0}, {300, 200, 300}, {0, 500, 0}, {-400, 150, 0},
                            {0, 600, 0}, {300, 250, -300}, {0, 450, 0}, {0, 200, 400}};
  const float loop = 48.f;
  const int keys = 48 * 30;
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

bool WriteCameraFile(const fs::path& out, const std::string& stem, const std::string& nodeName, vec3 pos,
                     vec3 target, bool animate) {
  const float fov = glm::radians(45.f);
  Gltf g;
  int camMat = g.Material("CameraBody", -1, -1, -1, false, vec3(0.2f, 0.2f, 0.22f));
  int cam = g.Camera(fov, 20.f, 400000.f);
  glm::quat q = glm::quatLookAtRH(glm::normalize(target - pos), vec3(0, 1, 0));
  int node = g.Node(nodeName, Gltf::TRS(pos, q) + ",\"camera\":" + std::to_string(cam));
  AddCameraBody(g, node, camMat);
  g.sceneRoots.push_back(node);
  if (animate) AddCinematicPath(g, node);
  return g.Write(out, stem);
}

// ---------------------------------------------------------------------------
// scene_description.txt in the original's form (mesh, animation or NO_ANIM, type).
bool WriteSceneDescription(const fs::path& out, const Detail& d, uint64_t seed, uint64_t triTotal) {
  std::ofstream sd(out / "scene_description.txt", std::ios::binary);
  sd << "# Arena (" << d.name << " detail, " << triTotal << " triangles), generated by drr_arenagen --detail " << d.name
     << " --seed " << seed << "\n"
     << "# mesh                  animation              type\n"
     << "# tessellate=, displacement=, relief=: used only with --tessellation (Docs/Tessellation.md)\n"
     << "arena.gltf              NO_ANIM                LIT"
     << " tessellate=Floor:displace,Rock:phong,Marble:phong displacement=textures/floor_height.png relief=8\n"
     << "bell.gltf               bell.gltf              LIT    tessellate=phong\n"
     << "sky.gltf                NO_ANIM                UNLIT\n"
     << "decals.gltf             NO_ANIM                DECAL\n"
     << "camera_cinematic.gltf   camera_cinematic.gltf  CAMERA\n"
     << "camera_static1.gltf     NO_ANIM                CAMERA\n"
     << "camera_static2.gltf     NO_ANIM                CAMERA\n";
  if (d.props > 0) sd << "props.gltf              NO_ANIM                LIT\n";
  return bool(sd);
}

int Run(const Detail& d, const fs::path& out, uint64_t seed) {
  std::error_code ec;
  fs::create_directories(out / "textures", ec);
  if (ec) {
    fprintf(stderr, "drr_arenagen: cannot create %s: %s\n", out.string().c_str(), ec.message().c_str());
    return 1;
  }
  TextureSet tex;
  if (!WriteAllTextures(out, d.texSize, tex)) {
    fprintf(stderr, "drr_arenagen: cannot write the textures under %s\n", (out / "textures").string().c_str());
    return 1;
  }
  Rng rng(seed);
  uint64_t triTotal = 0;
  if (!WriteArena(d, rng, tex, out, triTotal) || !WriteBell(d, seed, tex, out, triTotal) ||
      !WriteSingleMeshFile(out, "sky", "Sky", "SkyDome", BuildSkyDome(d), tex, "Sky", "sky", false, triTotal) ||
      !WriteSingleMeshFile(out, "decals", "Decals", "Decals", BuildDecals(d, seed), tex, "Decals", "decal", true,
                           triTotal))
    return 1;
  const MaterialMaker material = [&](Gltf& g, const std::string& mat, const std::string& texName) {
    return AddMaterial(g, tex, mat, texName);
  };
  if (d.props > 0 && !WriteProps(out, d.props, seed, material, triTotal)) return 1;
  if (!WriteCameraFile(out, "camera_cinematic", "CinematicCamera", vec3(-1500, 250, -1500), vec3(0, 300, 0), true) ||
      !WriteCameraFile(out, "camera_static1", "StaticCamera1", vec3(-1650, 420, 1650), vec3(0, 250, 0), false) ||
      !WriteCameraFile(out, "camera_static2", "StaticCamera2", vec3(1550, 1100, -900), vec3(0, kBellPivotY - 200, 0),
                       false)) {
    fprintf(stderr, "drr_arenagen: cannot write the camera files\n");
    return 1;
  }
  if (!WriteSceneDescription(out, d, seed, triTotal)) return 1;
  if (std::string error; !sdkgen::WriteSdkMeshSet(out / "sdkmesh", &error)) {
    fprintf(stderr, "drr_arenagen: %s\n", error.c_str());
    return 1;
  }
  printf("drr_arenagen: wrote the %s Arena (%llu triangles) to %s\n", d.name, (unsigned long long)triTotal, out.string().c_str());
  return 0;
}

// The usage line on stderr and exit status 2, for any bad argument.
int Usage() {
  fprintf(stderr, "usage: drr_arenagen --out <dir> [--detail small|large|props] [--props N] [--seed N]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string outDir, detail = "small";
  uint64_t seed = 20110301;
  int props = -1;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) outDir = argv[++i];
    else if (a == "--detail" && i + 1 < argc) detail = argv[++i];
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--props" && i + 1 < argc) props = std::atoi(argv[++i]);
    else return Usage();
  }
  if (outDir.empty() || (detail != "small" && detail != "large" && detail != "props") || props > 100000) return Usage();
  Detail d = detail == "small" ? kSmall : detail == "large" ? kLarge : kProps;
  if (props >= 0) d.props = props;
  const int rc = Run(d, outDir, seed);
  return rc != 0 ? rc : arena::WriteArenaDdsSet(outDir);
}
