// The one JSON writer of the sample, the bench and the tools: a streaming
// writer that places commas and quotes, so report code only names keys and
// values. JSON has no NaN or infinity: those are written as null.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace drr {

// A quoted JSON string; control characters become \u00XX escapes.
std::string JsonQuote(std::string_view s);
// A number with 9 significant digits; null when not finite.
std::string JsonNumber(double v);

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out, bool pretty = true) : out_(out), pretty_(pretty) {}
  JsonWriter& BeginObject(std::string_view key = {});
  JsonWriter& EndObject();
  JsonWriter& BeginArray(std::string_view key = {});
  JsonWriter& EndArray();
  // Array members and object members (key given).
  JsonWriter& Value(std::string_view key, double v);
  JsonWriter& Value(std::string_view key, int64_t v);
  JsonWriter& Value(std::string_view key, uint64_t v);
  JsonWriter& Value(std::string_view key, int v) { return Value(key, int64_t(v)); }
  JsonWriter& Value(std::string_view key, uint32_t v) { return Value(key, uint64_t(v)); }
  JsonWriter& Value(std::string_view key, bool v);
  JsonWriter& Value(std::string_view key, std::string_view v);
  JsonWriter& Value(std::string_view key, const char* v) { return Value(key, std::string_view(v)); }
  // Already-formatted JSON (an object written by another writer).
  JsonWriter& Raw(std::string_view key, std::string_view json);
  // Small arrays of numbers on one line: "size": [640, 360].
  JsonWriter& Pair(std::string_view key, double a, double b);
  // The next members of the current container go on one line.
  JsonWriter& Inline();

 private:
  void Member(std::string_view key);
  void Open(std::string_view key, char bracket);
  void Close(char bracket);
  struct Level {
    bool first = true, inlined = false;
  };
  std::ostream& out_;
  bool pretty_;
  std::vector<Level> stack_;
};

}  // namespace drr
