// JSON text for code that still assembles JSON by hand (the bench's result
// files): a quoted string, written by nlohmann-json like every other JSON
// value of the sample (OptionsJson.h).
#pragma once

#include <string>
#include <string_view>

namespace drr {

// A quoted JSON string; control characters escaped, invalid UTF-8 replaced.
std::string JsonQuote(std::string_view s);

}  // namespace drr
