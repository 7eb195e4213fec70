// results.json's header: what ran, where, with which plan; the rows come from
// the column table (BenchColumns.cpp).
#include <cmath>

#include "Options.h"
#include "bench/Bench.h"
#include "bench/BenchColumns.h"

namespace drr {

using nlohmann::json;

json BenchJson(const BenchResults& res, const std::string& date) {
  const BenchPlan& plan = *res.plan;
  json j;
  j["adapter"] = res.adapter;
  j["driver"] = res.driver;
  j["date"] = date;
  j["quick"] = plan.quick;
  j["width"] = plan.base.width;
  j["height"] = plan.base.height;
  j["reference_factor"] = plan.referenceFactor;
  j["warmup_frames"] = plan.warmupFrames;
  j["warmup_min_ms"] = plan.warmupMs;
  j["measured_frames"] = plan.measuredFrames;
  j["seconds"] = std::round(res.seconds * 100) / 100;
  j["validation_messages"] = res.validationMessages;
  j["memory_bandwidth_gbs"] = std::isfinite(res.bandwidthGBs) ? json(res.bandwidthGBs) : json(nullptr);
  j["memory_bandwidth_source"] = res.bandwidthSource;
  j["flip_ppd"] = std::round(res.flipPpd * 1000) / 1000;
  j["flip_display"] = res.flipDisplay;
  j["complete"] = res.complete;
  j["options"] = json::parse(OptionsToJson(plan.base), nullptr, false);
  j["rows"] = json::array();
  for (const BenchRow& r : res.rows) j["rows"].push_back(RowJson(r));
  return j;
}

bool ReadBenchJsonHeader(const json& j, BenchResults* res, std::string* error) {
  if (!j.is_object()) {
    *error = "results.json is not a JSON object";
    return false;
  }
  auto number = [&](const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_number() ? it->get<double>() : std::nan("");
  };
  auto text = [&](const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  res->adapter = text("adapter");
  res->driver = text("driver");
  res->seconds = number("seconds");
  const double messages = number("validation_messages");
  res->validationMessages = std::isfinite(messages) && messages >= 0 ? uint64_t(messages) : 0;
  res->bandwidthGBs = number("memory_bandwidth_gbs");
  res->bandwidthSource = text("memory_bandwidth_source");
  res->flipPpd = number("flip_ppd");
  res->flipDisplay = text("flip_display");
  res->complete = !j.contains("complete") || j["complete"] == true;
  return true;
}

namespace {

std::vector<double> Numbers(const json& frames, const char* key) {
  std::vector<double> v;
  const auto it = frames.find(key);
  if (it == frames.end() || !it->is_array()) return v;
  for (const json& x : *it) v.push_back(x.is_number() ? x.get<double>() : std::nan(""));
  return v;
}

}  // namespace

bool ReadBenchJsonFrames(const json& j, BenchResults* res, std::string* error) {
  const auto rows = j.find("rows");
  if (rows == j.end() || !rows->is_array() || rows->size() != res->rows.size()) {
    *error = "results.json: its rows do not match results.csv's " + std::to_string(res->rows.size());
    return false;
  }
  for (size_t i = 0; i < res->rows.size(); ++i) {
    const auto rounds = (*rows)[i].find("per_round");
    if (rounds != (*rows)[i].end() && rounds->is_object()) {
      res->rows[i].roundFrameMs = Numbers(*rounds, "gpu_frame_ms");
      res->rows[i].roundClearMs = Numbers(*rounds, "gpu_clear_ms");
      res->rows[i].roundScaleMs = Numbers(*rounds, "gpu_scale_ms");
    }
    const auto frames = (*rows)[i].find("per_frame");
    if (frames == (*rows)[i].end() || !frames->is_object()) continue;
    res->rows[i].framePsnr = Numbers(*frames, "psnr_db");
    res->rows[i].frameFlip = Numbers(*frames, "flip");
    res->rows[i].frameInstability = Numbers(*frames, "instability_rms");
  }
  return true;
}

}  // namespace drr
