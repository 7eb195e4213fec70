// The --report JSON file (FrameLog::WriteReport), built as a JSON value with
// nlohmann-json. Layout: one top-level member per line, each frame record on
// a line of its own, so that the file stays small and a line is one frame.
#include "FrameLog.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "GuiLogic.h"
#include "OptionsJson.h"
#include "scene/Scene.h"

namespace drr {

namespace {
// GPU averages over the frames that received a new result (the records
// repeat the last result in between); the CPU average over rendered frames.
double Average(const std::vector<FrameRecord>& frames, double FrameRecord::*m, bool gpu) {
  double s = 0;
  int n = 0;
  for (const FrameRecord& r : frames)
    if (r.rendered && (!gpu || r.gpuFrameNew) && std::isfinite(r.*m) && r.*m > 0) {
      s += r.*m;
      ++n;
    }
  return n ? s / n : 0.0;
}

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

JsonValue Averages(const std::vector<FrameRecord>& f) {
  return {{"cpu_frame", Average(f, &FrameRecord::cpuFrameMs, false)},
          {"gpu_frame", Average(f, &FrameRecord::gpuFrame, true)},
          {"clear", Average(f, &FrameRecord::gpuClear, true)},
          {"scene", Average(f, &FrameRecord::gpuScene, true)},
          {"postp", Average(f, &FrameRecord::gpuPostP, true)},
          {"scale", Average(f, &FrameRecord::gpuScale, true)}};
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

JsonValue Report(const ReportInfo& info, const std::vector<FrameRecord>& frames) {
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
  j["averages_ms"] = Averages(frames);
  j["final_scale"] = FloatPair(info.finalScale[0], info.finalScale[1]);
  if (info.scene) j["scene_stats"] = SceneStatsJson(*info.scene);
  if (info.gui && !info.gui->lastHeaderTitle.empty()) j["gui"] = GuiLayoutJson(*info.gui);
  j["warnings"] = info.warnings ? JsonValue(*info.warnings) : JsonValue::array();
  j["frames"] = JsonValue::array();
  for (const FrameRecord& r : frames) j["frames"].push_back(Frame(r));
  return j;
}

// One top-level member per line; an array's elements each on a line of their own.
void WriteLines(std::ostream& out, const JsonValue& report) {
  const char* separator = "{\n  ";
  for (const auto& [key, value] : report.items()) {
    out << separator << DumpJson(key) << ": ";
    separator = ",\n  ";
    if (!value.is_array() || value.empty() || !value.front().is_object()) {
      out << DumpJson(value);
      continue;
    }
    const char* itemSeparator = "[\n    ";
    for (const JsonValue& item : value) {
      out << itemSeparator << DumpJson(item);
      itemSeparator = ",\n    ";
    }
    out << "\n  ]";
  }
  out << "\n}\n";
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
  WriteLines(f, Report(info, AllFrames()));
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
