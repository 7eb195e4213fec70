// A minimal glTF 2.0 writer: JSON written by hand, one .bin buffer per file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "ArenaMesh.h"

namespace arena {

// Each method that adds an object appends its JSON to the array of its kind and
// returns its index there.
struct Gltf {
  std::vector<uint8_t> bin;
  std::vector<std::string> bufferViews, accessors, meshes, nodes, materials, textures, images, cameras, animations;
  std::vector<int> sceneRoots;

  static std::string F(float v);
  int View(const void* data, size_t bytes, int target);
  int Accessor(int view, int compType, size_t count, const char* type, const std::string& minmax = "");
  int Image(const std::string& uri);
  // diffuse/normal/specular: texture indices or -1.
  int Material(const std::string& name, int diffuse, int normal, int specular, bool blend, vec3 factor = vec3(1));
  int Mesh(const std::string& name, const MeshBuf& m, int material);
  int Node(const std::string& name, const std::string& extra);
  static std::string TRS(vec3 t, glm::quat r);
  int Camera(float yfov, float znear, float zfar);
  // One animation with translation and/or rotation channels on one node.
  void Animation(const std::string& name, int node, const std::vector<float>& times, const std::vector<vec3>* trans,
                 const std::vector<glm::quat>* rots);
  static std::string Join(const std::vector<std::string>& v);
  bool Write(const std::filesystem::path& dir, const std::string& stem);
  // A node that holds one new mesh (named meshName) of the given material.
  int MeshNode(const std::string& nodeName, const std::string& meshName, const MeshBuf& m, int material);
};

}  // namespace arena
