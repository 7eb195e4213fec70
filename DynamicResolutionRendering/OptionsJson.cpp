#include "OptionsJson.h"
#include "OptionTable.h"

#include <charconv>
#include <cstdlib>
#include <type_traits>

namespace drr {

namespace {
JsonValue RowJson(const OptionRow& row, const Options& o) {
  JsonValue out;
  std::visit(
      [&](auto member) {
        if constexpr (!std::is_same_v<decltype(member), std::monostate>) {
          const auto& value = o.*member;
          using T = std::remove_cvref_t<decltype(value)>;
          if constexpr (std::is_same_v<T, FixSet>) out = FixNames(value);
          else if constexpr (std::is_enum_v<T>) out = row.choices.option(static_cast<int>(value));
          else if constexpr (std::is_same_v<T, float>) out = FloatJson(value);
          else out = value;
        }
      },
      row.field);
  return out;
}
}  // namespace

JsonValue FloatJson(float v) {
  char text[32];
  const auto [end, ec] = std::to_chars(text, text + sizeof text - 1, v);
  if (ec != std::errc()) return JsonValue(double(v));
  *end = '\0';
  return JsonValue(std::strtod(text, nullptr));  // inf and nan read back as such; dumped as null
}

std::string DumpJson(const JsonValue& value) { return value.dump(-1, ' ', false, JsonValue::error_handler_t::replace); }

JsonValue OptionsJson(const Options& o) {
  JsonValue out = JsonValue::object();
  for (const OptionRow& row : OptionRows()) {
    if (!row.json) continue;
    out[row.json] = &row == FindOptionOf(&Options::frames) ? JsonValue(o.EffectiveFrames()) : RowJson(row, o);
  }
  return out;
}

std::string OptionsToJson(const Options& o) { return DumpJson(OptionsJson(o)); }

}  // namespace drr
