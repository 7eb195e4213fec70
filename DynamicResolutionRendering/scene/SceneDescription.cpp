#include "scene/SceneDescription.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

namespace drr {
namespace fs = std::filesystem;

const char* EntryTypeName(EntryType t) {
  switch (t) {
    case EntryType::Lit: return "LIT";
    case EntryType::Unlit: return "UNLIT";
    case EntryType::Camera: return "CAMERA";
    case EntryType::Decal: return "DECAL";
  }
  return "?";
}

glm::mat4 SceneEntry::Transform() const {
  glm::mat4 m = glm::translate(glm::mat4(1.f), translate);
  m = glm::rotate(m, glm::radians(rotateDeg.z), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotateDeg.y), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotateDeg.x), glm::vec3(1, 0, 0));
  return glm::scale(m, scale);
}

bool IsSceneDescriptionPath(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".txt" || ext == ".scene";
}

namespace {

struct Token {
  std::string text;
  int line = 0;
  bool quoted = false;
};

std::string Loc(const std::string& file, int line) { return file + ":" + std::to_string(line) + ": "; }

std::string Printable(const std::string& s, size_t maxLen = 60) {
  std::string r;
  for (char c : s.substr(0, maxLen)) {
    unsigned char u = static_cast<unsigned char>(c);
    if (u < 32 || u == 127) {
      char buf[8];
      snprintf(buf, sizeof buf, "\\x%02x", u);
      r += buf;
    } else {
      r += c;
    }
  }
  if (s.size() > maxLen) r += "...";
  return r;
}

bool ParseFloats(const std::string& v, int wanted, float* out) {
  std::stringstream ss(v);
  std::string part;
  int n = 0;
  while (std::getline(ss, part, ',')) {
    if (n >= wanted) return false;
    if (part.empty()) return false;
    char* end = nullptr;
    errno = 0;
    float f = std::strtof(part.c_str(), &end);
    if (end == part.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(f)) return false;
    out[n++] = f;
  }
  return n == wanted;
}

bool ApplyOption(SceneEntry& e, const std::string& key, const std::string& value, std::string* why) {
  float f[3];
  if (key == "name") {
    if (value.empty()) { *why = "name= needs a value"; return false; }
    e.name = value;
  } else if (key == "translate") {
    if (!ParseFloats(value, 3, f)) { *why = "translate= expects x,y,z (three finite numbers)"; return false; }
    e.translate = {f[0], f[1], f[2]};
  } else if (key == "rotate") {
    if (!ParseFloats(value, 3, f)) { *why = "rotate= expects x,y,z in degrees (three finite numbers)"; return false; }
    e.rotateDeg = {f[0], f[1], f[2]};
  } else if (key == "scale") {
    if (ParseFloats(value, 1, f)) {
      e.scale = glm::vec3(f[0]);
    } else if (ParseFloats(value, 3, f)) {
      e.scale = {f[0], f[1], f[2]};
    } else {
      *why = "scale= expects s or x,y,z (finite numbers)";
      return false;
    }
    if (e.scale.x == 0.f || e.scale.y == 0.f || e.scale.z == 0.f) { *why = "scale= must not be zero"; return false; }
  } else if (key == "hidden") {
    if (value != "0" && value != "1") { *why = "hidden= expects 0 or 1"; return false; }
    e.hidden = value == "1";
  } else if (key == "loop") {
    if (!ParseFloats(value, 1, f) || f[0] <= 0.f) { *why = "loop= expects a positive number of seconds"; return false; }
    e.loopSeconds = f[0];
  } else if (bool handled = false; !ApplyTessellationOption(e, key, value, &handled, why)) {
    return false;
  } else if (handled) {
    return true;
  } else {
    *why = "unknown option '" + Printable(key) +
           "' (expected name=, translate=, rotate=, scale=, hidden=, loop=, tessellate=, displacement=, relief=)";
    return false;
  }
  return true;
}

bool ParseType(const std::string& s, EntryType* t) {
  std::string u = s;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  if (u == "LIT") *t = EntryType::Lit;
  else if (u == "UNLIT") *t = EntryType::Unlit;
  else if (u == "CAMERA") *t = EntryType::Camera;
  else if (u == "DECAL") *t = EntryType::Decal;
  else return false;
  return true;
}

bool IsNoAnim(const std::string& s) {
  std::string u = s;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  return u == "NO_ANIM";
}

// Why parsing stopped: the line (0 = the file as a whole) and the message.
struct ParseFailure {
  int line = 0;
  std::string message;
};

bool Fail(ParseFailure* why, int line, const std::string& message) {
  why->line = line;
  why->message = message;
  return false;
}

std::string HexByte(unsigned char c) {
  char b[4];
  snprintf(b, sizeof b, "%02x", c);
  return b;
}

// Appends the tokens of one line (CR and newline already removed): words
// separated by blanks, "quoted paths", up to a '#' comment.
bool TokeniseLine(const std::string& l, int line, std::vector<Token>* tokens, ParseFailure* why) {
  for (size_t i = 0; i < l.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(l[i]);
    if ((c < 32 && c != '\t') || c == 127)
      return Fail(why, line, "unexpected binary data (byte 0x" + HexByte(c) + " in column " + std::to_string(i + 1) +
                                 "); expected a text file of 'mesh animation|NO_ANIM LIT|UNLIT|CAMERA|DECAL' entries");
  }
  size_t i = 0;
  while (i < l.size()) {
    while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) ++i;
    if (i >= l.size() || l[i] == '#') break;
    Token t;
    t.line = line;
    if (l[i] == '"') {
      size_t close = l.find('"', i + 1);
      if (close == std::string::npos) return Fail(why, line, "unterminated quoted path (expected a closing '\"')");
      t.text = l.substr(i + 1, close - i - 1);
      t.quoted = true;
      i = close + 1;
    } else {
      size_t s = i;
      while (i < l.size() && l[i] != ' ' && l[i] != '\t' && l[i] != '#') ++i;
      t.text = l.substr(s, i - s);
    }
    tokens->push_back(std::move(t));
  }
  return true;
}

// Tokenises the whole text line by line, with the line numbers kept.
bool Tokenise(const std::string& text, const ParseOptions& opts, std::vector<Token>* tokens, ParseFailure* why) {
  size_t pos = 0;
  int line = 0;
  if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
      static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF)
    pos = 3;  // UTF-8 byte order mark
  while (pos < text.size()) {
    ++line;
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string l = text.substr(pos, end - pos);
    pos = end + 1;
    if (!l.empty() && l.back() == '\r') l.pop_back();  // CRLF
    if (l.size() > opts.maxLineLength)
      return Fail(why, line, "line too long (" + std::to_string(l.size()) + " characters, at most " +
                                 std::to_string(opts.maxLineLength) + " expected)");
    if (!TokeniseLine(l, line, tokens, why)) return false;
  }
  return true;
}

bool IsOption(const Token& t) { return !t.quoted && t.text.find('=') != std::string::npos; }

bool ReadMeshToken(const Token& mesh, SceneEntry* e, ParseFailure* why) {
  e->line = mesh.line;
  if (IsOption(mesh))
    return Fail(why, mesh.line, "option '" + Printable(mesh.text) + "' where a mesh path was expected (options follow the type)");
  EntryType dummy;
  if (ParseType(mesh.text, &dummy) && !mesh.quoted)
    return Fail(why, mesh.line, "type '" + mesh.text + "' where a mesh path was expected (entry: mesh animation|NO_ANIM type)");
  e->meshPath = mesh.text;
  std::replace(e->meshPath.begin(), e->meshPath.end(), '\\', '/');
  if (e->meshPath.empty()) return Fail(why, mesh.line, "empty mesh path");
  return true;
}

bool ReadAnimToken(const Token& anim, SceneEntry* e, ParseFailure* why) {
  EntryType dummy;
  if (!anim.quoted && ParseType(anim.text, &dummy))
    return Fail(why, anim.line, "found type '" + anim.text + "' where the animation path or NO_ANIM was expected");
  if (IsOption(anim))
    return Fail(why, anim.line, "option '" + Printable(anim.text) + "' where the animation path or NO_ANIM was expected");
  if (!IsNoAnim(anim.text) || anim.quoted) {
    e->animPath = anim.text;
    std::replace(e->animPath.begin(), e->animPath.end(), '\\', '/');
    if (e->animPath.empty()) return Fail(why, anim.line, "empty animation path (write NO_ANIM for none)");
  }
  return true;
}

// Reads one entry from tokens[*k]: mesh, animation, type, then key=value
// options; *k moves past it. *animLine: the line of its animation token.
bool ReadEntry(const std::vector<Token>& tokens, size_t* k, SceneEntry* e, int* animLine, ParseFailure* why) {
  const Token& mesh = tokens[*k];
  if (!ReadMeshToken(mesh, e, why)) return false;
  if (*k + 1 >= tokens.size())
    return Fail(why, mesh.line, "entry '" + Printable(mesh.text) + "' is missing its animation path (or NO_ANIM) and type (LIT|UNLIT|CAMERA|DECAL)");
  const Token& anim = tokens[*k + 1];
  *animLine = anim.line;
  if (!ReadAnimToken(anim, e, why)) return false;
  if (*k + 2 >= tokens.size())
    return Fail(why, anim.line, "entry '" + Printable(mesh.text) + "' is missing its type (expected LIT, UNLIT, CAMERA or DECAL)");
  const Token& type = tokens[*k + 2];
  if (type.quoted || !ParseType(type.text, &e->type))
    return Fail(why, type.line, "unknown type '" + Printable(type.text) + "' (expected LIT, UNLIT, CAMERA or DECAL)");
  *k += 3;
  while (*k < tokens.size() && IsOption(tokens[*k])) {
    const Token& o = tokens[*k];
    size_t eq = o.text.find('=');
    std::string message;
    if (!ApplyOption(*e, o.text.substr(0, eq), o.text.substr(eq + 1), &message)) return Fail(why, o.line, message);
    ++*k;
  }
  std::string message;
  if (!CheckTessellationEntry(*e, &message)) return Fail(why, e->line, message);
  return true;
}

// The entry's files, relative to the description's folder unless absolute;
// checked to exist when opts.checkFiles.
bool ResolveFiles(const std::string& folder, const ParseOptions& opts, int animLine, SceneEntry* e, ParseFailure* why) {
  auto resolve = [&](const std::string& p) {
    fs::path rp(p);
    if (rp.is_absolute()) return rp.lexically_normal().string();
    return (fs::path(folder) / rp).lexically_normal().string();
  };
  e->meshFile = resolve(e->meshPath);
  if (!e->animPath.empty()) e->animFile = resolve(e->animPath);
  if (!e->displacementPath.empty()) e->displacementFile = resolve(e->displacementPath);
  if (!opts.checkFiles) return true;
  std::error_code ec;
  if (!fs::is_regular_file(e->meshFile, ec))
    return Fail(why, e->line, "mesh file '" + Printable(e->meshPath, 200) + "' not found (looked for " + e->meshFile + ")");
  if (!e->displacementPath.empty() && !fs::is_regular_file(e->displacementFile, ec))
    return Fail(why, e->line, "displacement map '" + Printable(e->displacementPath, 200) + "' not found (looked for " +
                                  e->displacementFile + ")");
  if (!e->animFile.empty() && !fs::is_regular_file(e->animFile, ec))
    return Fail(why, animLine, "animation file '" + Printable(e->animPath, 200) + "' not found (looked for " + e->animFile +
                                   "; write NO_ANIM for none)");
  return true;
}

// Resets a translation or scale out of the drawable range to the identity,
// with a warning naming the line.
void RejectAbsurdTransform(const std::string& file, SceneEntry* e, std::vector<std::string>* warnings) {
  auto describe = [](const glm::vec3& v) {
    char b[96];
    std::snprintf(b, sizeof b, "%g,%g,%g", v.x, v.y, v.z);
    return std::string(b);
  };
  const glm::vec3 t = glm::abs(e->translate), s = glm::abs(e->scale);
  if (std::max({t.x, t.y, t.z}) > kMaxTranslate) {
    warnings->push_back(Loc(file, e->line) + "translate=" + describe(e->translate) + " is beyond +-1e7, ignored");
    e->translate = glm::vec3(0.f);
  }
  if (std::max({s.x, s.y, s.z}) > kMaxEntryScale || std::min({s.x, s.y, s.z}) < kMinEntryScale) {
    warnings->push_back(Loc(file, e->line) + "scale=" + describe(e->scale) + " is outside [1e-6, 1e6], ignored");
    e->scale = glm::vec3(1.f);
  }
}

bool IsLightKeyword(const Token& t) {
  std::string u = t.text;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  return !t.quoted && u == "LIGHT";
}

bool ApplyLightOption(SceneLight& l, const std::string& key, const std::string& value, std::string* why) {
  float f[3];
  const bool spot = l.type == LightType::Spot;
  if (key == "position") {
    if (!ParseFloats(value, 3, f)) { *why = "position= expects x,y,z (three finite numbers)"; return false; }
    l.position = {f[0], f[1], f[2]};
  } else if (key == "direction" && spot) {
    if (!ParseFloats(value, 3, f) || glm::length(glm::vec3(f[0], f[1], f[2])) < 1e-6f) {
      *why = "direction= expects x,y,z, not all zero";
      return false;
    }
    l.direction = glm::normalize(glm::vec3(f[0], f[1], f[2]));
  } else if (key == "color") {
    if (!ParseFloats(value, 3, f) || std::min({f[0], f[1], f[2]}) < 0.f || std::max({f[0], f[1], f[2]}) > 64.f) {
      *why = "color= expects r,g,b, each in [0, 64]";
      return false;
    }
    l.color = {f[0], f[1], f[2]};
  } else if (key == "radius") {
    if (!ParseFloats(value, 1, f) || !(f[0] > 0.f) || f[0] > 1e7f) { *why = "radius= expects a number in (0, 1e7]"; return false; }
    l.radius = f[0];
  } else if (key == "angle" && spot) {
    if (!ParseFloats(value, 1, f) || !(f[0] > 0.f) || f[0] > 89.f) { *why = "angle= expects degrees in (0, 89]"; return false; }
    l.angleDeg = f[0];
  } else if (key == "shadow" && spot) {
    if (value != "0" && value != "1") { *why = "shadow= expects 0 or 1"; return false; }
    l.shadow = value == "1";
  } else {
    *why = "unknown light option '" + Printable(key) + "' (expected position=, color=, radius=" +
           (spot ? ", direction=, angle=, shadow=)" : ")");
    return false;
  }
  return true;
}

// LIGHT POINT|SPOT key=value...: tokens[*k] is the LIGHT keyword; *k moves past the entry.
bool ReadLight(const std::vector<Token>& tokens, size_t* k, SceneLight* l, ParseFailure* why) {
  const Token& keyword = tokens[*k];
  l->line = keyword.line;
  std::string kind = *k + 1 < tokens.size() ? tokens[*k + 1].text : "";
  std::transform(kind.begin(), kind.end(), kind.begin(), [](unsigned char c) { return std::toupper(c); });
  if (kind == "POINT") l->type = LightType::Point;
  else if (kind == "SPOT") l->type = LightType::Spot;
  else return Fail(why, keyword.line, "LIGHT needs its kind: found '" + Printable(kind) + "', expected POINT or SPOT");
  *k += 2;
  bool hasPosition = false, hasRadius = false, hasDirection = false;
  while (*k < tokens.size() && IsOption(tokens[*k])) {
    const Token& o = tokens[*k];
    const size_t eq = o.text.find('=');
    const std::string key = o.text.substr(0, eq);
    std::string message;
    if (!ApplyLightOption(*l, key, o.text.substr(eq + 1), &message)) return Fail(why, o.line, message);
    hasPosition |= key == "position";
    hasRadius |= key == "radius";
    hasDirection |= key == "direction";
    ++*k;
  }
  const bool spot = l->type == LightType::Spot;
  if (!hasPosition || !hasRadius || (spot && !hasDirection))
    return Fail(why, keyword.line, std::string("LIGHT ") + (spot ? "SPOT" : "POINT") + " needs position=" +
                                       (spot ? ", direction=" : "") + " and radius=");
  return true;
}

bool AddLight(const SceneLight& l, SceneDescription* out, ParseFailure* why) {
  if (out->lights.size() >= kMaxSceneLights)
    return Fail(why, l.line, "too many lights (at most " + std::to_string(kMaxSceneLights) + ")");
  size_t shadowed = 0;
  for (const SceneLight& o : out->lights) shadowed += o.shadow;
  if (l.shadow && shadowed >= kMaxShadowedSpots)
    return Fail(why, l.line, "too many spot lights with shadow=1 (at most " + std::to_string(kMaxShadowedSpots) + ")");
  out->lights.push_back(l);
  return true;
}

bool ParseEntries(const std::string& text, const ParseOptions& opts, SceneDescription* out, ParseFailure* why) {
  std::vector<Token> tokens;
  if (!Tokenise(text, opts, &tokens, why)) return false;
  if (tokens.empty())
    return Fail(why, 0, "no entries (empty file, or only comments); expected lines of 'mesh animation|NO_ANIM LIT|UNLIT|CAMERA|DECAL'");
  size_t k = 0;
  while (k < tokens.size()) {
    if (out->entries.size() >= opts.maxEntries)
      return Fail(why, tokens[k].line, "too many entries (more than " + std::to_string(opts.maxEntries) + ")");
    if (IsLightKeyword(tokens[k])) {
      SceneLight light;
      if (!ReadLight(tokens, &k, &light, why) || !AddLight(light, out, why)) return false;
      continue;
    }
    SceneEntry e;
    int animLine = 0;
    if (!ReadEntry(tokens, &k, &e, &animLine, why) || !ResolveFiles(out->folder, opts, animLine, &e, why)) return false;
    if (e.name.empty()) e.name = fs::path(e.meshPath).stem().string();
    RejectAbsurdTransform(out->file, &e, &out->warnings);
    out->entries.push_back(std::move(e));
  }
  return true;
}

}  // namespace

bool ParseSceneDescription(const std::string& text, const std::string& file, const ParseOptions& opts,
                           SceneDescription* out, std::string* error) {
  *out = SceneDescription{};
  out->file = file;
  out->folder = fs::path(file).parent_path().string();
  ParseFailure why;
  if (ParseEntries(text, opts, out, &why)) return true;
  if (error) *error = why.line > 0 ? Loc(file, why.line) + why.message : file + ": " + why.message;
  return false;
}

bool LoadSceneDescription(const std::string& file, const ParseOptions& opts, SceneDescription* out,
                          std::string* error) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    if (error) *error = file + ": cannot open scene description (no such file)";
    return false;
  }
  auto size = fs::file_size(file, ec);
  if (ec || size > (64u << 20)) {
    if (error) *error = file + ": scene description is too large (" + std::to_string(size) + " bytes, at most 64 MiB expected)";
    return false;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    if (error) *error = file + ": cannot open scene description";
    return false;
  }
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return ParseSceneDescription(text, file, opts, out, error);
}

}  // namespace drr
