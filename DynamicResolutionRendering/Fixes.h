// The port's fixes of the original's defects (Shaders/FixList.hlsli lists
// them). Off by default: the default frame is the original's. Selected with
// --fix NAME[,NAME...] | all | none and in the GUI; shaders get the set as a
// bit mask (g_Fixes) in their constant buffers.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace drr {

enum class Fix : uint32_t {
#define DRR_FIX(id, bit, name, help) id = bit,
#include "FixList.hlsli"
#undef DRR_FIX
};

struct FixInfo {
  Fix fix;
  const char* name;  // command line and GUI
  const char* help;
};
std::span<const FixInfo> FixTable();

struct FixSet {
  uint32_t bits = 0;
  bool Has(Fix f) const { return (bits >> static_cast<uint32_t>(f)) & 1u; }
  void Set(Fix f, bool on) {
    const uint32_t bit = 1u << static_cast<uint32_t>(f);
    bits = on ? (bits | bit) : (bits & ~bit);
  }
  static FixSet All();
  bool operator==(const FixSet&) const = default;
};

// "none", "all", or a comma-separated list of names. On error, *error names
// the unknown entry and lists the known ones.
bool ParseFixes(std::string_view text, FixSet* out, std::string* error);
// "none", "all" or the comma-separated names (what ParseFixes reads back).
std::string FixNames(FixSet set);

}  // namespace drr
