// Scene description files, as in the original sample: a text file of entries,
// each "mesh path", "animation path or NO_ANIM" and a type LIT | UNLIT |
// CAMERA | DECAL; paths are relative to the file.
//
// Accepted forms (both of the original's layouts load):
//   arena.gltf NO_ANIM LIT                 (one entry per line)
//   arena.gltf                             (or one token per line; tokens are
//   NO_ANIM                                 grouped three by three)
//   LIT
// Extensions: '#' starts a comment (to the end of the line); paths with
// spaces may be quoted ("my model.obj"); Windows '\' separators are accepted;
// after the type, optional key=value tokens belong to that entry:
//   name=<text>  translate=x,y,z  rotate=x,y,z (degrees, applied Z*Y*X)  scale=s or x,y,z
//   hidden=0|1   loop=<seconds>   (overrides the animation's own duration)
// Light entries (the deferred renderer's; the forward path, as the original,
// lights with its one directional light only), position and direction in world units:
//   LIGHT POINT position=x,y,z color=r,g,b radius=R
//   LIGHT SPOT  position=x,y,z direction=x,y,z color=r,g,b radius=R angle=DEG [shadow=0|1]
// radius > 0 (the light reaches zero there), color components in [0, 64],
// angle (the cone's half angle) in (0, 89] degrees, direction not zero.
//   tessellate=phong|displace or tessellate=<material>:<mode>[,<material>:<mode>...]
//   displacement=<height map, relative path>  relief=<units>   (with a displace mode)
//   (acted on only with the sample's --tessellation; Docs/Tessellation.md)
// Errors are reported as "file:line: what was found, what was expected".
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace drr {

enum class EntryType { Lit, Unlit, Camera, Decal };

// Adaptive tessellation of an entry's meshes (Docs/Tessellation.md).
enum class TessMode { None, Phong, Displace };
const char* TessModeName(TessMode m);
struct TessRule {
  std::string material;  // the model's material name; empty: every material of the entry
  TessMode mode = TessMode::None;
};

const char* EntryTypeName(EntryType t);

struct SceneEntry {
  std::string meshPath;       // as written (separators normalised to '/')
  std::string animPath;       // empty for NO_ANIM
  std::string meshFile;       // resolved against the description's folder
  std::string animFile;       // resolved, empty for NO_ANIM
  EntryType type = EntryType::Lit;
  int line = 0;               // line of the entry's first token
  // Options (extensions of the original format).
  std::string name;           // defaults to the mesh file's stem
  glm::vec3 translate{0.f};
  glm::vec3 rotateDeg{0.f};
  glm::vec3 scale{1.f};
  bool hidden = false;
  double loopSeconds = 0.0;   // 0 = use the animation's duration
  // Tessellation (SceneDescriptionTess.cpp): rules in the order written, the
  // height map of the displace rules (as written, and resolved) and its relief.
  std::vector<TessRule> tessellate;
  std::string displacementPath, displacementFile;
  float relief = 0.f;
  TessMode TessModeOf(const std::string& material) const;  // the first rule naming it, or the all-rule
  glm::mat4 Transform() const;
};

enum class LightType { Point, Spot };

struct SceneLight {
  LightType type = LightType::Point;
  glm::vec3 position{0.f};
  glm::vec3 direction{0.f, -1.f, 0.f};  // spot: normalised
  glm::vec3 color{1.f};
  float radius = 0.f;
  float angleDeg = 45.f;                // spot: cone half angle
  bool shadow = false;                  // spot: casts shadows (a slice of the shadow-map array)
  int line = 0;
};
inline constexpr size_t kMaxSceneLights = 32;   // the lighting pass's constant buffer
inline constexpr size_t kMaxShadowedSpots = 4;  // slices of the shadow-map array

struct SceneDescription {
  std::string file;   // path of the description
  std::string folder; // folder the paths are relative to
  std::vector<SceneEntry> entries;
  std::vector<SceneLight> lights;  // LIGHT entries, in file order
  // "file:line: ..." for options that were ignored (transforms out of range).
  std::vector<std::string> warnings;
};

// Transforms beyond these bounds put a model where float arithmetic cannot
// draw it (a blank frame): they are ignored with a warning.
inline constexpr float kMaxTranslate = 1e7f;          // per component
inline constexpr float kMinEntryScale = 1e-6f, kMaxEntryScale = 1e6f;  // |scale| per axis

struct ParseOptions {
  bool checkFiles = true;        // the mesh and animation files must exist
  size_t maxLineLength = 4096;   // longer lines are an error
  size_t maxEntries = 100000;
};

// The tessellation options (tessellate=, displacement=, relief=): false with
// *why when key is one of them and its value is wrong; *handled false for any other key.
bool ApplyTessellationOption(SceneEntry& e, const std::string& key, const std::string& value, bool* handled,
                             std::string* why);
// After an entry's options: a displace rule needs displacement= and relief=, and those need one.
bool CheckTessellationEntry(const SceneEntry& e, std::string* why);

// Parses text as if it were the content of 'file' (used for messages and to
// resolve relative paths). Returns false with error = "file:line: ...".
bool ParseSceneDescription(const std::string& text, const std::string& file,
                           const ParseOptions& opts, SceneDescription* out, std::string* error);
// Reads and parses a file.
bool LoadSceneDescription(const std::string& file, const ParseOptions& opts,
                          SceneDescription* out, std::string* error);

// Whether a path looks like a scene description (by extension .txt / .scene).
bool IsSceneDescriptionPath(const std::string& path);

}  // namespace drr
