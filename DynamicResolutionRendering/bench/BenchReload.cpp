// --report-from DIR: rebuilds the report (summary.md, plots, results.json)
// from a finished run's results.csv and results.json, without rendering, so a
// long sweep's report can be rewritten after the report code changed. The
// command line must name the same sweep as the run (views, filters, scales).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "bench/BenchCommon.h"

namespace drr {
namespace {

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

double ToNumber(const std::string& s) {
  if (s.empty()) return std::nan("");
  if (s == "inf") return INFINITY;
  if (s == "-inf") return -INFINITY;
  return std::strtod(s.c_str(), nullptr);
}

// The value after "key": in the JSON header (strings unquoted, no escapes).
std::string JsonField(const std::string& json, const std::string& key) {
  const size_t k = json.find("\"" + key + "\": ");
  if (k == std::string::npos) return "";
  size_t p = k + key.size() + 4;
  if (json[p] == '"') {
    const size_t e = json.find('"', p + 1);
    return json.substr(p + 1, e - p - 1);
  }
  const size_t e = json.find_first_of(",\n}", p);
  return json.substr(p, e - p);
}

BenchRow RowFromFields(const std::vector<std::string>& f, std::map<std::string, size_t>& col) {
  auto num = [&](const char* c) { return col.count(c) ? ToNumber(f[col[c]]) : std::nan(""); };
  auto stat = [&](const char* m, const char* lo, const char* hi) {
    return Stat{num(m), lo ? num(lo) : std::nan(""), hi ? num(hi) : std::nan("")};
  };
  BenchRow r;
  r.view = f[col["view"]];
  r.filter = f[col["filter"]];
  r.scale = num("scale");
  r.viewportW = float(num("viewport_w"));
  r.viewportH = float(num("viewport_h"));
  r.error.psnr = num("psnr_db");
  r.error.ssim = num("ssim");
  r.error.maxAbsError = num("max_abs_error");
  r.error.mse = num("mse");
  r.error.valid = f[col["valid"]] == "1";
  r.gpuFrame = stat("gpu_frame_ms", "gpu_frame_p25", "gpu_frame_p75");
  r.gpuClear = stat("gpu_clear_ms", nullptr, nullptr);
  r.gpuScene = stat("gpu_scene_ms", nullptr, nullptr);
  r.gpuPost = stat("gpu_post_ms", nullptr, nullptr);
  r.gpuScale = stat("gpu_scale_ms", "gpu_scale_p25", "gpu_scale_p75");
  r.wall = stat("wall_ms", "wall_p25", "wall_p75");
  r.animTime = num("anim_time");
  r.ghostFraction = num("ghost_fraction");
  r.psnrVsNative = num("psnr_vs_native_db");
  r.gpuSamples = int(num("gpu_samples"));
  r.moving = col.count("moving") && f[col["moving"]] == "1";
  r.speed = num("speed");
  r.qualityFrames = int(num("quality_frames"));
  r.superSampling = col.count("supersampling") && f[col["supersampling"]] == "1";
  r.flip = num("flip");
  r.flipCi = num("flip_ci95");
  r.psnrCi = num("psnr_ci95");
  r.flicker = num("flicker_rms");
  return r;
}

}  // namespace

bool ReloadBenchResults(const std::string& dir, BenchResults* res, std::string* error) {
  std::ifstream csv(dir + "/results.csv"), json(dir + "/results.json");
  if (!csv || !json) {
    *error = "cannot read " + dir + "/results.csv and results.json";
    return false;
  }
  std::stringstream js;
  js << json.rdbuf();
  const std::string header = js.str();
  res->adapter = JsonField(header, "adapter");
  res->driver = JsonField(header, "driver");
  res->seconds = ToNumber(JsonField(header, "seconds"));
  res->validationMessages = uint64_t(ToNumber(JsonField(header, "validation_messages")));
  res->bandwidthGBs = ToNumber(JsonField(header, "memory_bandwidth_gbs"));
  res->bandwidthSource = JsonField(header, "memory_bandwidth_source");
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> names = SplitCsvLine(line);
  std::map<std::string, size_t> col;
  for (size_t i = 0; i < names.size(); ++i) col[names[i]] = i;
  while (std::getline(csv, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = SplitCsvLine(line);
    if (f.size() != names.size()) {
      *error = "results.csv: a row with " + std::to_string(f.size()) + " fields";
      return false;
    }
    res->rows.push_back(RowFromFields(f, col));
  }
  return true;
}

}  // namespace drr
