#include "Json.h"

#include <cmath>
#include <cstdio>

namespace drr {

std::string JsonQuote(std::string_view s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      o += '\\';
      o += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
      o += b;
    } else {
      o += c;
    }
  }
  return o + "\"";
}

std::string JsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

void JsonWriter::Member(std::string_view key) {
  if (stack_.empty()) return;
  Level& l = stack_.back();
  if (!l.first) out_ << ",";
  const bool newline = pretty_ && !l.inlined;
  if (newline) out_ << "\n" << std::string(stack_.size() * 2, ' ');
  else if (!l.first) out_ << " ";
  l.first = false;
  if (!key.empty()) out_ << JsonQuote(key) << ": ";
}

void JsonWriter::Open(std::string_view key, char bracket) {
  Member(key);
  out_ << bracket;
  const bool parentInline = !stack_.empty() && stack_.back().inlined;
  stack_.push_back({true, parentInline});
}

void JsonWriter::Close(char bracket) {
  const Level l = stack_.back();
  stack_.pop_back();
  if (pretty_ && !l.inlined && !l.first) out_ << "\n" << std::string(stack_.size() * 2, ' ');
  out_ << bracket;
  if (stack_.empty() && pretty_) out_ << "\n";
}

JsonWriter& JsonWriter::BeginObject(std::string_view key) { Open(key, '{'); return *this; }
JsonWriter& JsonWriter::EndObject() { Close('}'); return *this; }
JsonWriter& JsonWriter::BeginArray(std::string_view key) { Open(key, '['); return *this; }
JsonWriter& JsonWriter::EndArray() { Close(']'); return *this; }

JsonWriter& JsonWriter::Inline() {
  if (!stack_.empty()) stack_.back().inlined = true;
  return *this;
}

JsonWriter& JsonWriter::Value(std::string_view key, double v) {
  Member(key);
  out_ << JsonNumber(v);
  return *this;
}
JsonWriter& JsonWriter::Value(std::string_view key, int64_t v) {
  Member(key);
  out_ << v;
  return *this;
}
JsonWriter& JsonWriter::Value(std::string_view key, uint64_t v) {
  Member(key);
  out_ << v;
  return *this;
}
JsonWriter& JsonWriter::Value(std::string_view key, bool v) {
  Member(key);
  out_ << (v ? "true" : "false");
  return *this;
}
JsonWriter& JsonWriter::Value(std::string_view key, std::string_view v) {
  Member(key);
  out_ << JsonQuote(v);
  return *this;
}
JsonWriter& JsonWriter::Raw(std::string_view key, std::string_view json) {
  Member(key);
  out_ << json;
  return *this;
}
JsonWriter& JsonWriter::Pair(std::string_view key, double a, double b) {
  Member(key);
  out_ << "[" << JsonNumber(a) << ", " << JsonNumber(b) << "]";
  return *this;
}

}  // namespace drr
