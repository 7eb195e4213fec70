#include "Json.h"

#include "OptionsJson.h"

namespace drr {

std::string JsonQuote(std::string_view s) { return DumpJson(JsonValue(std::string(s))); }

}  // namespace drr
