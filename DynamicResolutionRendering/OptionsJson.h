// The sample's JSON, written and read with nlohmann-json (Debian's
// nlohmann-json3-dev): the options object of the report, from the rows of
// OptionTable.h, and the number conventions of every JSON file the sample writes.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "Options.h"

namespace drr {

using JsonValue = nlohmann::ordered_json;  // keys in the order they were added

// Every row of OptionTable.h that has a report key, in the table's order;
// enums by their command-line names, fixes as FixNames, frames as EffectiveFrames().
JsonValue OptionsJson(const Options& o);
// A float as the shortest decimal that reads back as the same float (0.71f
// is written 0.71, not 0.709999978542328).
JsonValue FloatJson(float v);
// Compact text of a value; invalid UTF-8 in strings is replaced, never thrown on.
std::string DumpJson(const JsonValue& value);

}  // namespace drr
