// props.gltf of the many-object Arena (ArenaGenProps.h).
#include "ArenaGenProps.h"

#include <cmath>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "ArenaMath.h"
#include "ArenaMesh.h"

namespace arena {
namespace {

constexpr float kFloorHalf = 1850.f;  // props stay inside the walls and stairways
constexpr float kBellClear = 420.f;   // and off the bell's swing

// The shared shapes: two crates, a barrel, two stones; base at y = 0.
struct PropShape {
  MeshBuf mesh;
  int material;  // 0 brick, 1 marble, 2 rock
};

std::vector<PropShape> MakeShapes(uint64_t seed) {
  std::vector<PropShape> shapes(5);
  AddBox(shapes[0].mesh, vec3(0, 20, 0), vec3(20, 20, 20), 0.f, 80.f);
  shapes[0].material = 0;
  AddBox(shapes[1].mesh, vec3(0, 12, 0), vec3(30, 12, 18), 0.f, 80.f);
  shapes[1].material = 0;
  AddCylinder(shapes[2].mesh, vec3(0), 16.f, 44.f, 16, 2, true, [](float t) { return 1.f + 0.12f * std::sin(t * kPi); });
  shapes[2].material = 1;
  Rng rng(seed + 501);
  AddRock(shapes[3].mesh, vec3(0, 10, 0), vec3(22, 14, 18), 1, rng);
  shapes[3].material = 2;
  AddRock(shapes[4].mesh, vec3(0, 6, 0), vec3(12, 9, 14), 1, rng);
  shapes[4].material = 2;
  return shapes;
}

// A place on the floor outside the bell area.
vec3 PropPosition(Rng& rng) {
  for (;;) {
    const vec3 p(rng.Uniform(-kFloorHalf, kFloorHalf), 0.f, rng.Uniform(-kFloorHalf, kFloorHalf));
    if (std::hypot(p.x, p.z) > kBellClear) return p;
  }
}

}  // namespace

bool WriteProps(const std::filesystem::path& out, int count, uint64_t seed, const MaterialMaker& material,
                uint64_t& triTotal) {
  Gltf g;
  const int materials[3] = {material(g, "PropBrick", "brick"), material(g, "PropMarble", "marble"),
                            material(g, "PropRock", "rock")};
  const std::vector<PropShape> shapes = MakeShapes(seed);
  std::vector<int> meshes;
  for (size_t k = 0; k < shapes.size(); ++k)
    meshes.push_back(g.Mesh("Prop" + std::to_string(k), shapes[k].mesh, materials[shapes[k].material]));
  Rng rng(seed + 503);
  std::string kids;
  for (int i = 0; i < count; ++i) {
    const size_t shape = size_t(rng.Uniform(0.f, float(shapes.size()))) % shapes.size();
    const vec3 at = PropPosition(rng);
    const glm::quat yaw = glm::angleAxis(rng.Uniform(0.f, 2.f * kPi), vec3(0, 1, 0));
    triTotal += shapes[shape].mesh.Tris();
    const int node = g.Node("Prop_" + std::to_string(i), Gltf::TRS(at, yaw) + ",\"mesh\":" + std::to_string(meshes[shape]));
    kids += (i ? "," : "") + std::to_string(node);
  }
  g.sceneRoots.push_back(g.Node("Props", ",\"children\":[" + kids + "]"));
  return g.Write(out, "props");
}

}  // namespace arena
