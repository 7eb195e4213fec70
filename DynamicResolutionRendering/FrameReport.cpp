// The --report JSON file (FrameLog::WriteReport), built as a JSON value with
// nlohmann-json. Layout: one top-level member per line, each frame record on
// a line of its own, so that the file stays small and a line is one frame.
#include "FrameLog.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include "GuiLogic.h"
#include "OptionsJson.h"
#include "scene/Scene.h"

namespace drr {

namespace {
// averages_ms: GPU averages over the frames that received a new result (the
// records repeat the last result in between); the CPU average over rendered
// frames. Accumulated one record at a time, so the records can stream.
struct AverageRow {
  const char* key;
  double FrameRecord::*member;
  bool gpu;
};
constexpr AverageRow kAverages[] = {
    {"cpu_frame", &FrameRecord::cpuFrameMs, false}, {"gpu_frame", &FrameRecord::gpuFrame, true},
    {"clear", &FrameRecord::gpuClear, true},        {"scene", &FrameRecord::gpuScene, true},
    {"postp", &FrameRecord::gpuPostP, true},        {"scale", &FrameRecord::gpuScale, true}};

class FrameAverages {
 public:
  void Add(const FrameRecord& r) {
    for (size_t i = 0; i < std::size(kAverages); ++i) {
      const AverageRow& row = kAverages[i];
      const double v = r.*row.member;
      if (r.rendered && (!row.gpu || r.gpuFrameNew) && std::isfinite(v) && v > 0) {
        m_Sum[i] += v;
        ++m_Count[i];
      }
    }
  }
  JsonValue Json() const {
    JsonValue j = JsonValue::object();
    for (size_t i = 0; i < std::size(kAverages); ++i) j[kAverages[i].key] = m_Count[i] ? m_Sum[i] / m_Count[i] : 0.0;
    return j;
  }

 private:
  double m_Sum[std::size(kAverages)] = {};
  int64_t m_Count[std::size(kAverages)] = {};
};

JsonValue FloatPair(float a, float b) { return JsonValue::array({FloatJson(a), FloatJson(b)}); }
JsonValue SizePair(uint32_t a, uint32_t b) { return JsonValue::array({a, b}); }

JsonValue Targets(const ReportInfo& info) {
  JsonValue out = JsonValue::object();
  for (int i = 0; i < int(RT::Count); ++i) {
    const RenderTarget& rt = (*info.targets)[RT(i)];
    if (!rt.Valid()) continue;
    JsonValue& row = out[RenderTargetSet::Name(RT(i))];
    row = {{"size", SizePair(rt.width, rt.height)}, {"format", d3dl::FormatName(rt.format)}, {"bytes", rt.Bytes()}};
    if (rt.slices > 0) row["slices"] = rt.slices;  // an array: bytes = size x slices
  }
  return out;
}

JsonValue Frame(const FrameRecord& r) {
  return {{"frame", r.frame},
          {"rendered", r.rendered},
          {"scale", FloatPair(r.scaleX, r.scaleY)},
          {"viewport", SizePair(r.viewportW, r.viewportH)},
          {"back_buffer", SizePair(r.backBufferW, r.backBufferH)},
          {"fullscreen", r.fullscreen},
          {"cpu_ms", r.cpuFrameMs},
          {"gpu_new", r.gpuFrameNew},
          {"gpu_delay_frames", r.gpuFrameDelay},
          {"gpu_ms",
           {{"frame", r.gpuFrame}, {"clear", r.gpuClear}, {"scene", r.gpuScene}, {"postp", r.gpuPostP},
            {"scale", r.gpuScale}}}};
}

JsonValue SceneStatsJson(const Scene& scene) {
  const SceneStats st = scene.Stats();
  JsonValue out = {{"draws_issued", st.drawsIssued}, {"draws_culled", st.drawsCulled},
                   {"triangles", st.triangles}, {"texture_bytes", st.textureBytes},
                   {"texture_bytes_as_rgba8", st.textureBytesAsRgba8}};
  if (st.tessellatedDraws) {
    out["tessellated_draws"] = st.tessellatedDraws;
    out["patches_submitted"] = st.patchesSubmitted;
  }
  out["recording_threads"] = st.recordingThreads;
  out["record_ms"] = st.recordMs;
  out["draws_per_thread"] = st.drawsPerThread;
  return out;
}

// The GUI panel's rectangle and its last section header's, in back-buffer
// pixels (x0, y0, x1, y1): the window test checks the header is on screen.
JsonValue GuiLayoutJson(const GuiLayout& g) {
  auto rect = [](const std::array<float, 4>& r) { return JsonValue::array({r[0], r[1], r[2], r[3]}); };
  return {{"panel", rect(g.panel)}, {"last_header", rect(g.lastHeader)}, {"last_header_title", g.lastHeaderTitle}};
}

// Everything but the frames (written after it by WriteReport, one record at a time).
JsonValue Report(const ReportInfo& info, const FrameAverages& averages) {
  const Options& o = *info.options;
  JsonValue j = {{"options", OptionsJson(o)},
                 {"control",
                  {{"mode", ControlModeOption(o.control)}, {"law", ControlLawOption(o.law)},
                   {"refresh_hz", info.refreshHz}, {"budget_ms", info.budgetMs},
                   {"law_latency_frames", info.lawLatencyFrames}}},
                 {"adapter", info.adapter},
                 {"driver", info.driver},
                 {"scene", info.scenePath},
                 {"back_buffer", SizePair(info.backBuffer[0], info.backBuffer[1])},
                 {"dynamic_rt", SizePair(info.dynamicRT[0], info.dynamicRT[1])},
                 {"render_target_bytes", info.targets->Bytes()},
                 {"render_target_bytes_original",
                  RenderTargetSet::OriginalBytes(info.backBuffer[0], info.backBuffer[1], info.dynamicRT[0],
                                                 info.dynamicRT[1])}};
  j["render_targets"] = Targets(info);
  j["passes_run"] = *info.passesRun;
  j["validation_messages"] = info.validationMessages;
  j["frames_rendered"] = info.framesRendered;
  j["frames_minimised"] = info.framesMinimised;
  j["averages_ms"] = averages.Json();
  j["final_scale"] = FloatPair(info.finalScale[0], info.finalScale[1]);
  if (info.scene) j["scene_stats"] = SceneStatsJson(*info.scene);
  if (info.gui && !info.gui->lastHeaderTitle.empty()) j["gui"] = GuiLayoutJson(*info.gui);
  j["warnings"] = info.warnings ? JsonValue(*info.warnings) : JsonValue::array();
  return j;
}

// An array of objects, one element per line: "[]" when empty. forEach calls
// its argument with each element's dumped text.
void WriteObjectArray(std::ostream& out, const std::function<void(const std::function<void(const std::string&)>&)>& forEach) {
  const char* separator = "[\n    ";
  forEach([&](const std::string& item) {
    out << separator << item;
    separator = ",\n    ";
  });
  out << (*separator == '[' ? "[]" : "\n  ]");
}

// One top-level member per line; an array's elements each on a line of their
// own. The closing brace is left to the caller (WriteReport adds the frames).
void WriteLines(std::ostream& out, const JsonValue& report) {
  const char* separator = "{\n  ";
  for (const auto& [key, value] : report.items()) {
    out << separator << DumpJson(key) << ": ";
    separator = ",\n  ";
    if (!value.is_array() || value.empty() || !value.front().is_object()) {
      out << DumpJson(value);
      continue;
    }
    WriteObjectArray(out, [&](const auto& emit) {
      for (const JsonValue& item : value) emit(DumpJson(item));
    });
  }
}
}  // namespace

bool FrameLog::WriteReport(const std::string& path, const ReportInfo& info, std::string* error) const {
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  std::ofstream f(path);
  if (!f) {
    *error = "cannot write " + path + ": " + std::strerror(errno);
    return false;
  }
  FrameAverages averages;
  ForEachFrame([&](const FrameRecord& r) { averages.Add(r); });
  WriteLines(f, Report(info, averages));
  // The frames last, a record per line as WriteLines writes arrays, streamed
  // from the records so a long run's report needs no memory per frame.
  f << ",\n  \"frames\": ";
  WriteObjectArray(f, [&](const auto& emit) { ForEachFrame([&](const FrameRecord& r) { emit(DumpJson(Frame(r))); }); });
  f << "\n}\n";
  f.flush();
  if (m_StreamFailed) {
    *error = "cannot write " + path + ": the frame records' temporary file failed (disk full?)";
    return false;
  }
  if (!f) {
    *error = "cannot write " + path + " (disk full or write error)";
    return false;
  }
  return true;
}

}  // namespace drr
