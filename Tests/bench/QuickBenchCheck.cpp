// Checks the outputs of `DynamicResolutionRendering --bench --quick`:
// every file is there (results.csv, results.json, summary.md, three non-empty
// PNG plots), every row is valid with finite GPU times (the reference-repeat
// row has none and must be identical to the reference: PSNR inf in the CSV,
// "identical": true in the JSON), point filtering on the static view gets
// strictly better from scale 0.3 to 1.0, fixed-function-blit rows exist, and the run
// logged zero validation messages. Moving-camera rows (point, bilinear, taa
// and native on the moving cinematic camera) each cover the same number of
// frames (>= 2) with finite PSNR and its interval, FLIP in [0, 1] and a
// finite, non-negative flicker and instability (still sweep rows: the jitter
// instability; native on the still camera exactly 0); per-frame values and
// FLIP's pixels per degree in results.json; still rows have FLIP in [0, 1]; no row at or
// below 1.0 allowed 2x targets; every timed row has at least one distinct GPU
// sample (a moving row no more than its frames); the ablation rows and the
// labelled fronts are there. Timings are never compared (lavapipe's are not
// monotonic in resolution).
//
//   drr_quick_bench_check DIR      exit 0 = all good, 1 = failures (listed)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/BenchColumns.h"

namespace {

int g_failures = 0;
void Fail(const std::string& what) {
  std::fprintf(stderr, "FAIL: %s\n", what.c_str());
  ++g_failures;
}

bool ReadFile(const std::string& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  *out = s.str();
  return true;
}

// The CSV as the bench writes it (BenchColumns.h): fields, and numbers with
// "" for NaN and "inf" for infinity.
std::vector<std::string> SplitCsv(const std::string& line) { return drr::SplitCsvLine(line); }
double Parse(const std::string& s) { return drr::ParseNumber(s); }

// results.json: the repeat row is identical, zero validation messages, the
// run complete, as many rows as the CSV, FLIP's pixels per degree that of the
// frame full-screen on FLIP's reference display (0.7 m wide, 3840 pixels, 0.7
// m away), and every moving row's per-frame values: PSNR and FLIP for each
// compared frame, the instability for each frame after the first.
void CheckJson(const std::string& text, size_t csvRows) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("rows") || !j["rows"].is_array()) {
    Fail("results.json is not a JSON object with rows");
    return;
  }
  if (j.value("validation_messages", -1) != 0) Fail("results.json: validation messages are not 0");
  if (j.value("complete", false) != true) Fail("results.json: the run is not marked complete");
  const double width = j.value("width", 0.0), ppd = j.value("flip_ppd", 0.0);
  const double expected = 0.7 * (width / 0.7) * 3.14159265358979 / 180.0;  // distance x pixels per metre, per radian
  if (!(std::abs(ppd - expected) < 0.01)) Fail("results.json: flip_ppd " + std::to_string(ppd) + ", expected " + std::to_string(expected));
  if (j["rows"].size() != csvRows) Fail("results.json has " + std::to_string(j["rows"].size()) + " rows, results.csv " + std::to_string(csvRows));
  bool repeat = false;
  for (const nlohmann::json& r : j["rows"]) {
    const std::string where = "results.json row '" + r.value("view", "") + "' / '" + r.value("filter", "") + "'";
    if (r.value("filter", "") == "reference-repeat") {
      repeat = true;
      if (r.value("identical", false) != true) Fail(where + ": not \"identical\": true");
    }
    if (r.value("moving", false) != true) continue;
    const size_t frames = r.value("quality_frames", size_t(0));
    const nlohmann::json f = r.value("per_frame", nlohmann::json::object());
    for (const char* key : {"psnr_db", "flip", "instability_rms"}) {
      const size_t want = std::string(key) == "instability_rms" ? frames - 1 : frames;
      const nlohmann::json v = f.value(key, nlohmann::json::array());
      if (v.size() != want) Fail(where + ": per_frame " + key + " has " + std::to_string(v.size()) + " values, not " + std::to_string(want));
      for (const nlohmann::json& x : v)
        if (!x.is_number() || !std::isfinite(x.get<double>())) Fail(where + ": per_frame " + key + " holds a non-number");
    }
  }
  if (!repeat) Fail("results.json has no reference-repeat row");
}

// One CSV row by column name.
struct Row {
  const std::vector<std::string>& f;
  std::map<std::string, size_t>& col;
  const std::string& operator[](const char* name) const { return f[col[name]]; }
  double Num(const char* name) const { return Parse((*this)[name]); }
};

// What the rows add up to, checked after the last one.
struct Tally {
  size_t rows = 0, blitRows = 0, repeatRows = 0, ghostRows = 0, movingRows = 0, inRange = 0;
  std::map<std::string, size_t> ablations;   // ablation filter name -> rows
  std::map<std::string, bool> movingFilters;  // filters seen on the moving camera
  double movingFrames = -1;
  std::map<double, double> pointPsnr, bilinearPsnr, blitPsnr;  // first (static) view, by scale
  std::string firstView;
};

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// GPU times, samples, 2x targets, FLIP range and the ablation names of a row.
void CheckTimesAndFlip(const Row& r, const std::string& where, Tally* t) {
  const std::string& filter = r["filter"];
  std::vector<const char*> times = {"gpu_scale_ms"};
  if (filter == "fixed-function-blit") ++t->blitRows;
  else times = {"gpu_frame_ms", "gpu_clear_ms", "gpu_scene_ms", "gpu_post_ms", "gpu_scale_ms"};
  for (const char* c : times) {
    const double v = r.Num(c);
    if (!std::isfinite(v) || v < 0) Fail(where + ": " + c + " is not a finite time ('" + r[c] + "')");
  }
  if (!(r.Num("gpu_samples") >= 1)) Fail(where + ": no distinct GPU sample");
  if (r.Num("scale") <= 1.0 + 1e-6 && r["supersampling"] == "1" && filter.find("ss-allowed") == std::string::npos)
    Fail(where + ": 2x targets allowed at or below 1.0");
  if (filter.find("symmetric-jitter") != std::string::npos || filter.find("motion blur on") != std::string::npos ||
      filter.find("mip-bias") != std::string::npos)
    ++t->ablations[filter + (r["moving"] == "1" ? " moving" : " still")];
  const double flip = r.Num("flip");
  if (filter != "fixed-function-blit" && !StartsWith(filter, "ghost ") && !StartsWith(filter, "motion-blur") &&
      !(flip >= 0 && flip <= 1))
    Fail(where + ": FLIP not in [0, 1] ('" + r["flip"] + "')");
}

// Moving rows: frame counts, finite PSNR interval and flicker. Instability:
// every moving row, and every still row of the sweep (its jitter instability
// over consecutive frames; native's exactly 0).
void CheckTemporal(const Row& r, const std::string& where, Tally* t) {
  const std::string& filter = r["filter"];
  const bool moving = r["moving"] == "1";
  if (moving) {
    ++t->movingRows;
    t->movingFilters[filter] = true;
    const double frames = r.Num("quality_frames");
    if (!(frames >= 2)) Fail(where + ": a moving row over fewer than 2 frames");
    if (t->movingFrames < 0) t->movingFrames = frames;
    else if (frames != t->movingFrames) Fail(where + ": moving rows over different frame counts");
    if (r.Num("gpu_samples") > frames) Fail(where + ": more GPU samples than frames");
    if (!std::isfinite(r.Num("psnr_db")) || !std::isfinite(r.Num("psnr_ci95"))) Fail(where + ": moving PSNR or its interval not finite");
    const double flicker = r.Num("flicker_rms");
    if (!(flicker >= 0 && std::isfinite(flicker))) Fail(where + ": flicker not a finite, non-negative number");
  }
  const bool stillSweep = !moving && filter != "fixed-function-blit" && !StartsWith(filter, "ghost ") &&
                          !StartsWith(filter, "motion-blur");
  const double instability = r.Num("instability_rms");
  if ((moving || stillSweep) && !(instability >= 0 && std::isfinite(instability)))
    Fail(where + ": instability not a finite, non-negative number ('" + r["instability_rms"] + "')");
  if (filter == "native" && !moving && !(instability == 0))
    Fail(where + ": native on a still camera changes between frames (instability " + r["instability_rms"] + ")");
}

void CheckRow(const Row& r, Tally* t) {
  ++t->rows;
  const std::string& view = r["view"];
  const std::string& filter = r["filter"];
  const std::string where = "row '" + view + "' / '" + filter + "' / " + r["scale"];
  if (t->firstView.empty()) t->firstView = view;
  if (r["valid"] != "1") Fail(where + ": not valid");
  const double psnr = r.Num("psnr_db");
  if (std::isnan(psnr)) Fail(where + ": PSNR is not a number");
  if (filter == "reference-repeat") {
    ++t->repeatRows;
    if (!(std::isinf(psnr) && psnr > 0)) Fail(where + ": the repeated reference differs (PSNR " + r["psnr_db"] + ")");
    for (const char* c : {"gpu_frame_ms", "gpu_scale_ms"})
      if (!r[c].empty()) Fail(where + ": has a GPU time in " + c);
    return;
  }
  CheckTimesAndFlip(r, where, t);
  CheckTemporal(r, where, t);
  if (StartsWith(filter, "ghost ")) {
    ++t->ghostRows;
    const double g = r.col.count("ghost_fraction") ? r.Num("ghost_fraction") : std::nan("");
    if (!(g >= 0 && g <= 1)) Fail(where + ": ghost fraction not in [0, 1]");
  }
  if (view != t->firstView) return;
  if (filter == "point") t->pointPsnr[r.Num("scale")] = psnr;
  if (filter == "bilinear") t->bilinearPsnr[r.Num("scale")] = psnr;
  if (filter == "fixed-function-blit") t->blitPsnr[r.Num("scale")] = psnr;
}

// The rows as a whole: every kind present, point PSNR rising with scale on
// the static view, the blit as good as the bilinear resolve.
void CheckTally(Tally& t) {
  if (t.rows == 0) Fail("results.csv has no rows");
  if (t.repeatRows == 0) Fail("no reference-repeat row");
  if (t.blitRows == 0) Fail("no fixed-function-blit rows");
  if (t.ghostRows == 0) Fail("no ghosting rows");
  if (t.movingRows == 0) Fail("no moving-camera rows");
  for (const char* m : {"native", "point", "bilinear", "taa", "taau"})
    if (!t.movingFilters.count(m)) Fail(std::string("no moving row for ") + m);
  for (const char* a : {"taa symmetric-jitter still", "taa symmetric-jitter moving", "taa fast (motion blur on) moving",
                        "native (motion blur on) moving", "taa mip-bias 0 still", "taa mip-bias 0 moving",
                        "taau no-auto-mip-bias still", "taau no-auto-mip-bias moving"})
    if (!t.ablations.count(a)) Fail(std::string("no ablation row '") + a + "'");
  double prev = -INFINITY;
  for (const auto& [scale, psnr] : t.pointPsnr) {
    if (scale < 0.3 - 1e-6 || scale > 1.0 + 1e-6) continue;
    ++t.inRange;
    if (!(psnr > prev)) Fail("point PSNR does not increase at scale " + std::to_string(scale));
    prev = psnr;
  }
  if (t.inRange < 2) Fail("fewer than two point rows between 0.3 and 1.0 on the static view");
  // The blit is a linear filter of the same scene colour into the same sRGB
  // back buffer: its image must be as good as the bilinear resolve's (a wrong
  // format on either side costs it ten decibels or more).
  for (const auto& [scale, psnr] : t.blitPsnr)
    if (t.bilinearPsnr.count(scale) && !(std::abs(psnr - t.bilinearPsnr[scale]) < 1.0))
      Fail("fixed-function-blit PSNR " + std::to_string(psnr) + " is not within 1 dB of bilinear's " +
           std::to_string(t.bilinearPsnr[scale]) + " at scale " + std::to_string(scale));
}

// Every output file is there; the PNGs are PNGs.
void ReadOutputs(const std::string& dir, std::string* csv, std::string* json, std::string* summary) {
  if (!ReadFile(dir + "/results.csv", csv) || csv->empty()) Fail("results.csv missing or empty");
  if (!ReadFile(dir + "/results.json", json) || json->empty()) Fail("results.json missing or empty");
  if (!ReadFile(dir + "/summary.md", summary) || summary->empty()) Fail("summary.md missing or empty");
  for (const char* png : {"error_vs_scale_time.png", "error_vs_frame_time.png", "frame_time_vs_scale.png",
                          "front_still_flip.png", "front_still_psnr.png", "front_moving_flip.png", "front_moving_psnr.png"}) {
    std::string data;
    if (!ReadFile(dir + "/" + png, &data) || data.size() < 8 || data.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
      Fail(std::string(png) + " missing, empty or not a PNG");
  }
}

// The CSV: its columns, then every row.
bool CheckCsv(const std::string& csv, Tally* t) {
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  const std::vector<std::string> header = SplitCsv(line);
  std::map<std::string, size_t> col;
  for (size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
  for (const char* c : {"view", "filter", "scale", "psnr_db", "valid", "gpu_frame_ms", "gpu_clear_ms",
                        "gpu_scene_ms", "gpu_post_ms", "gpu_scale_ms", "gpu_samples", "moving", "speed", "quality_frames",
                        "supersampling", "flip", "psnr_ci95", "flicker_rms", "instability_rms"})
    if (!col.count(c)) Fail(std::string("results.csv has no column ") + c);
  if (g_failures) return false;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = SplitCsv(line);
    if (f.size() != header.size())
      Fail("row with " + std::to_string(f.size()) + " fields instead of " + std::to_string(header.size()) + ": " + line);
    else CheckRow(Row{f, col}, t);
  }
  CheckTally(*t);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s BENCH_OUT_DIR\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  std::string csv, json, summary;
  ReadOutputs(dir, &csv, &json, &summary);
  Tally t;
  if (g_failures || !CheckCsv(csv, &t)) return 1;
  CheckJson(json, t.rows);
  for (const char* section : {"ratio to blit", "### Claims", "### Ghosting", "### Still camera", "### Moving camera",
                              "### Ablations", "### Iso-time", "ppd)"})
    if (summary.find(section) == std::string::npos) Fail(std::string("summary.md lacks '") + section + "'");
  if (g_failures) {
    std::fprintf(stderr, "%d check(s) failed in %s\n", g_failures, dir.c_str());
    return 1;
  }
  std::printf("quick bench outputs OK: %zu rows (%zu fixed-function-blit, %zu ghosting, %zu moving over %.0f frames each), "
              "point PSNR increasing over %zu scales\n", t.rows, t.blitRows, t.ghostRows, t.movingRows, t.movingFrames, t.inRange);
  return 0;
}
