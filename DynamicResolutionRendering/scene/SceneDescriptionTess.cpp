// The scene description's tessellation options (Docs/Tessellation.md):
//   tessellate=phong | displace                    every material of the entry
//   tessellate=Floor:displace,Rock:phong           per material name
//   displacement=textures/floor_height.png         the height map (red channel, 0..1)
//   relief=12                                      object units of height 1
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "scene/SceneDescription.h"

namespace drr {

const char* TessModeName(TessMode m) {
  switch (m) {
    case TessMode::None: return "none";
    case TessMode::Phong: return "phong";
    case TessMode::Displace: return "displace";
  }
  return "?";
}

TessMode SceneEntry::TessModeOf(const std::string& material) const {
  for (const TessRule& r : tessellate)
    if (r.material.empty() || r.material == material) return r.mode;
  return TessMode::None;
}

namespace {
bool ParseMode(const std::string& s, TessMode* m) {
  if (s == "phong") *m = TessMode::Phong;
  else if (s == "displace") *m = TessMode::Displace;
  else if (s == "none") *m = TessMode::None;
  else return false;
  return true;
}

bool ParseRules(const std::string& value, std::vector<TessRule>* rules, std::string* why) {
  std::stringstream ss(value);
  std::string part;
  while (std::getline(ss, part, ',')) {
    TessRule r;
    const size_t colon = part.rfind(':');
    const std::string mode = colon == std::string::npos ? part : part.substr(colon + 1);
    if (colon != std::string::npos) r.material = part.substr(0, colon);
    if (colon != std::string::npos && r.material.empty()) {
      *why = "tessellate= has an empty material name before ':' in '" + part + "'";
      return false;
    }
    if (!ParseMode(mode, &r.mode)) {
      *why = "tessellate= has unknown mode '" + mode + "' (expected phong, displace or none, optionally after <material>:)";
      return false;
    }
    rules->push_back(r);
  }
  if (rules->empty()) {
    *why = "tessellate= needs a value (phong, displace, or <material>:<mode>,...)";
    return false;
  }
  return true;
}
}  // namespace

bool ApplyTessellationOption(SceneEntry& e, const std::string& key, const std::string& value, bool* handled,
                             std::string* why) {
  *handled = true;
  if (key == "tessellate") {
    std::vector<TessRule> rules;
    if (!ParseRules(value, &rules, why)) return false;
    e.tessellate = rules;
  } else if (key == "displacement") {
    if (value.empty()) {
      *why = "displacement= needs the path of a height map";
      return false;
    }
    e.displacementPath = value;
  } else if (key == "relief") {
    char* end = nullptr;
    errno = 0;
    const float f = std::strtof(value.c_str(), &end);
    if (value.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(f) || f <= 0.f || f > 1e6f) {
      *why = "relief= expects a positive number of object units up to 1e6, got '" + value + "'";
      return false;
    }
    e.relief = f;
  } else {
    *handled = false;
  }
  return true;
}

bool CheckTessellationEntry(const SceneEntry& e, std::string* why) {
  bool displace = false;
  for (const TessRule& r : e.tessellate) displace = displace || r.mode == TessMode::Displace;
  if (displace && (e.displacementPath.empty() || e.relief <= 0.f)) {
    *why = "tessellate=...displace needs displacement=<height map> and relief=<units> on the same entry";
    return false;
  }
  if (!displace && (!e.displacementPath.empty() || e.relief > 0.f)) {
    *why = "displacement= and relief= act only with a tessellate=...displace rule on the same entry";
    return false;
  }
  return true;
}

}  // namespace drr
