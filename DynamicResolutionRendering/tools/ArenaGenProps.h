// The many-object Arena (drr_arenagen --detail props): the small Arena with
// thousands of props (crates, barrels, stones) scattered over its floor, each
// its own node and so its own draw: the scene on which recording the draws
// on several threads pays (Docs/Threads.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "ArenaGltf.h"

namespace arena {

// Adds to g a material named matName showing the textures saved as texName;
// returns its index.
using MaterialMaker = std::function<int(Gltf& g, const std::string& matName, const std::string& texName)>;

// Writes <out>/props.gltf: `count` props over the floor (the bell area kept
// clear), a few shared meshes, one node per prop. Adds their triangles to triTotal.
bool WriteProps(const std::filesystem::path& out, int count, uint64_t seed, const MaterialMaker& material,
                uint64_t& triTotal);

}  // namespace arena
