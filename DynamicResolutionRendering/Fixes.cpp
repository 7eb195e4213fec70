#include "Fixes.h"

#include <array>

namespace drr {
namespace {

constexpr FixInfo kFixes[] = {
#define DRR_FIX(id, bit, name, help) {Fix::id, name, help},
#include "FixList.hlsli"
#undef DRR_FIX
};

constexpr bool BitsAreDistinct() {
  uint32_t seen = 0;
  for (const FixInfo& f : kFixes) {
    const uint32_t bit = 1u << static_cast<uint32_t>(f.fix);
    if (static_cast<uint32_t>(f.fix) >= 32 || (seen & bit)) return false;
    seen |= bit;
  }
  return true;
}
static_assert(BitsAreDistinct(), "FixList.hlsli: every fix needs its own bit below 32");

std::string KnownNames() {
  std::string out = "all, none";
  for (const FixInfo& f : kFixes) out += std::string(", ") + f.name;
  return out;
}

}  // namespace

std::span<const FixInfo> FixTable() { return kFixes; }

FixSet FixSet::All() {
  FixSet s;
  for (const FixInfo& f : kFixes) s.Set(f.fix, true);
  return s;
}

bool ParseFixes(std::string_view text, FixSet* out, std::string* error) {
  if (text == "all") return *out = FixSet::All(), true;
  if (text == "none") return *out = FixSet{}, true;
  FixSet set;
  while (true) {
    const std::size_t comma = text.find(',');
    const std::string_view item = text.substr(0, comma);
    const FixInfo* found = nullptr;
    for (const FixInfo& f : kFixes)
      if (item == f.name) found = &f;
    if (!found) {
      *error = "unknown fix '" + std::string(item) + "' (allowed: " + KnownNames() + ")";
      return false;
    }
    set.Set(found->fix, true);
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  *out = set;
  return true;
}

std::string FixNames(FixSet set) {
  if (set.bits == 0) return "none";
  if (set == FixSet::All()) return "all";
  std::string out;
  for (const FixInfo& f : kFixes)
    if (set.Has(f.fix)) out += (out.empty() ? "" : ",") + std::string(f.name);
  return out;
}

}  // namespace drr
