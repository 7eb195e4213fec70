#include "bench/BenchColumns.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace drr {
namespace {

using nlohmann::json;

// Column rows: a number, an integer count, a 1/0 flag, a text.
#define DRR_NUMBER(name, ptr, decimals, member)                                                      \
  BenchColumn{name, ptr, ColumnKind::Number, decimals,                                               \
              [](const BenchRow& r) { return double(r.member); },                                    \
              [](BenchRow& r, double v) { r.member = decltype(r.member)(v); }, nullptr}
#define DRR_COUNT(name, ptr, member)                                                                 \
  BenchColumn{name, ptr, ColumnKind::Count, 0, [](const BenchRow& r) { return double(r.member); },   \
              [](BenchRow& r, double v) { r.member = std::isfinite(v) ? decltype(r.member)(v) : 0; }, nullptr}
#define DRR_FLAG(name, ptr, member)                                                                  \
  BenchColumn{name, ptr, ColumnKind::Flag, 0, [](const BenchRow& r) { return r.member ? 1.0 : 0.0; }, \
              [](BenchRow& r, double v) { r.member = v == 1.0; }, nullptr}
#define DRR_TEXT(name, ptr, member) BenchColumn{name, ptr, ColumnKind::Text, 0, nullptr, nullptr, &BenchRow::member}
#define DRR_STAT(name, ptr, stat) DRR_NUMBER(name "_ms", ptr "/median", 4, stat.median),                \
    DRR_NUMBER(name "_p25", ptr "/p25", 4, stat.p25), DRR_NUMBER(name "_p75", ptr "/p75", 4, stat.p75)

std::vector<BenchColumn> MakeColumns() {
  return {
      DRR_TEXT("view", "/view", view),
      DRR_TEXT("filter", "/filter", filter),
      DRR_NUMBER("scale", "/scale", 3, scale),
      DRR_NUMBER("viewport_w", "/viewport/0", 3, viewportW),
      DRR_NUMBER("viewport_h", "/viewport/1", 3, viewportH),
      DRR_NUMBER("psnr_db", "/psnr_db", 3, error.psnr),
      DRR_NUMBER("ssim", "/ssim", 5, error.ssim),
      DRR_NUMBER("max_abs_error", "/max_abs_error", 5, error.maxAbsError),
      DRR_NUMBER("mse", "/mse", 8, error.mse),
      DRR_FLAG("valid", "/valid", error.valid),
      DRR_STAT("gpu_frame", "/gpu_ms/frame", gpuFrame),
      DRR_STAT("gpu_clear", "/gpu_ms/clear", gpuClear),
      DRR_STAT("gpu_scene", "/gpu_ms/scene", gpuScene),
      DRR_STAT("gpu_post", "/gpu_ms/post", gpuPost),
      DRR_STAT("gpu_scale", "/gpu_ms/scale", gpuScale),
      DRR_STAT("wall", "/wall_ms", wall),
      DRR_NUMBER("anim_time", "/anim_time", 6, animTime),
      DRR_NUMBER("ghost_fraction", "/ghost_fraction", 6, ghostFraction),
      DRR_NUMBER("psnr_vs_native_db", "/psnr_vs_native_db", 3, psnrVsNative),
      DRR_COUNT("gpu_samples", "/gpu_samples", gpuSamples),
      DRR_FLAG("moving", "/moving", moving),
      DRR_NUMBER("speed", "/speed", 3, speed),
      DRR_COUNT("quality_frames", "/quality_frames", qualityFrames),
      DRR_FLAG("supersampling", "/supersampling", superSampling),
      DRR_NUMBER("flip", "/flip", 6, flip),
      DRR_NUMBER("flip_ci95", "/flip_ci95", 6, flipCi),
      DRR_NUMBER("psnr_ci95", "/psnr_ci95", 3, psnrCi),
      DRR_NUMBER("flicker_rms", "/flicker_rms", 6, flicker),
      DRR_NUMBER("instability_rms", "/instability_rms", 6, instability),
  };
}

#undef DRR_NUMBER
#undef DRR_COUNT
#undef DRR_FLAG
#undef DRR_TEXT
#undef DRR_STAT

// A field with quotes or commas is quoted (no quotes inside our names).
std::string CsvText(const std::string& s) {
  return s.find_first_of(",\" ") == std::string::npos ? s : '"' + s + '"';
}

// JSON has no infinity nor NaN: they are null (identical images say "identical": true).
json JsonNumber(double v, int decimals) {
  if (!std::isfinite(v)) return nullptr;
  const double p = std::pow(10.0, decimals);
  return std::round(v * p) / p;
}

}  // namespace

const std::vector<BenchColumn>& BenchColumns() {
  static const std::vector<BenchColumn> columns = MakeColumns();
  return columns;
}

std::string FormatNumber(double v, int decimals) {
  if (std::isnan(v)) return "";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

double ParseNumber(const std::string& s) {
  if (s.empty()) return std::nan("");
  if (s == "inf") return INFINITY;
  if (s == "-inf") return -INFINITY;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return end && *end == 0 ? v : std::nan("");
}

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> f;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) f.push_back(cur), cur.clear();
    else if (c != '\r') cur += c;
  }
  f.push_back(cur);
  return f;
}

std::string CsvHeader() {
  std::string h;
  for (const BenchColumn& c : BenchColumns()) h += (h.empty() ? "" : ",") + std::string(c.name);
  return h;
}

std::string CsvLine(const BenchRow& row) {
  std::string line;
  for (const BenchColumn& c : BenchColumns()) {
    if (&c != &BenchColumns().front()) line += ',';
    if (c.kind == ColumnKind::Text) line += CsvText(row.*c.text);
    else if (c.kind == ColumnKind::Number) line += FormatNumber(c.get(row), c.decimals);
    else line += std::to_string(int64_t(c.get(row)));
  }
  return line;
}

json RowJson(const BenchRow& row) {
  json j = json::object();
  for (const BenchColumn& c : BenchColumns()) {
    const json::json_pointer at(c.json);
    if (c.kind == ColumnKind::Text) j[at] = row.*c.text;
    else if (c.kind == ColumnKind::Flag) j[at] = c.get(row) != 0;
    else if (c.kind == ColumnKind::Count) j[at] = int64_t(c.get(row));
    else j[at] = JsonNumber(c.get(row), c.decimals);
  }
  j["identical"] = row.error.valid && row.error.mse == 0;
  if (!row.framePsnr.empty()) {
    json& f = j["per_frame"];
    for (double v : row.framePsnr) f["psnr_db"].push_back(JsonNumber(v, 4));
    for (double v : row.frameFlip) f["flip"].push_back(JsonNumber(v, 6));
    for (double v : row.frameInstability) f["instability_rms"].push_back(JsonNumber(v, 6));
  }
  if (!row.roundFrameMs.empty()) {
    json& r = j["per_round"];
    for (double v : row.roundFrameMs) r["gpu_frame_ms"].push_back(JsonNumber(v, 4));
    for (double v : row.roundClearMs) r["gpu_clear_ms"].push_back(JsonNumber(v, 4));
    for (double v : row.roundScaleMs) r["gpu_scale_ms"].push_back(JsonNumber(v, 4));
  }
  return j;
}

BenchRow RowFromFields(const std::vector<std::string>& fields, const std::map<std::string, size_t>& col) {
  BenchRow r;
  for (const BenchColumn& c : BenchColumns()) {
    const auto it = col.find(c.name);
    const bool present = it != col.end() && it->second < fields.size();
    if (c.kind == ColumnKind::Text) {
      if (present) r.*c.text = fields[it->second];
    } else {
      c.set(r, present ? ParseNumber(fields[it->second]) : std::nan(""));
    }
  }
  return r;
}

}  // namespace drr
