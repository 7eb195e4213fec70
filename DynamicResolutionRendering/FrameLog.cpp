#include "FrameLog.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "Json.h"
#include "imageio/ImageFile.h"
#include "imageio/Srgb.h"
#include "scene/Scene.h"

namespace drr {

namespace {
// Writes 8-bit RGBA, or linear float RGBA for .exr/.hdr (the back buffer is sRGB-encoded).
bool SaveImageRGBA8(const std::string& path, uint32_t w, uint32_t h, const uint8_t* rgba,
                    std::string* error) {
  std::string ext = path.substr(path.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext != "exr" && ext != "hdr") return WriteImageFile(path, w, h, 4, rgba, error);
  // The back buffer holds sRGB-encoded values; EXR/HDR store linear light.
  std::vector<float> f(size_t(w) * h * 4);
  for (size_t i = 0; i < f.size(); ++i) {
    const float c = rgba[i] / 255.0f;
    f[i] = (i % 4 == 3) ? c : SrgbToLinear(c);
  }
  return WriteImageFileFloat(path, w, h, 4, f.data(), error);
}

}  // namespace

void FrameLog::AddRendered(int64_t frame, const DynamicResolution& dr, bool dynamic, const BackBuffer& bb,
                           bool fullscreen, double elapsedSeconds, const FrameTimers& t) {
  FrameRecord r;
  r.frame = frame;
  r.scaleX = dr.GetScaleX();
  r.scaleY = dr.GetScaleY();
  r.viewportW = dynamic ? dr.GetViewportWidth() : bb.width;
  r.viewportH = dynamic ? dr.GetViewportHeight() : bb.height;
  r.backBufferW = bb.width;
  r.backBufferH = bb.height;
  r.fullscreen = fullscreen;
  r.cpuFrameMs = elapsedSeconds * 1000.0;
  r.gpuFrame = t.frame.LastMs();
  r.gpuFrameNew = t.frame.NewResults() > 0;
  r.gpuFrameDelay = t.frame.LastDelayFrames();
  r.gpuClear = t.clear.LastMs();
  r.gpuScene = t.scene.LastMs();
  r.gpuPostP = t.postP.LastMs();
  r.gpuScale = t.scale.LastMs();
  Add(r);
}

void FrameLog::AddMinimised(int64_t frame, bool fullscreen) {
  FrameRecord r;
  r.frame = frame;
  r.rendered = false;
  r.fullscreen = fullscreen;
  Add(r);
}

bool FrameLog::SetRecords(FrameRecords mode) {
  m_Frames.clear();
  m_Frames.shrink_to_fit();
  m_Stream.reset();
  m_StreamFailed = false;
  m_Mode = mode;
  if (mode == FrameRecords::Stream) {
    m_Stream.reset(std::tmpfile());
    if (!m_Stream) {
      m_Mode = FrameRecords::Off;
      return false;
    }
  }
  return true;
}

void FrameLog::Add(const FrameRecord& r) {
  if (m_Mode == FrameRecords::Memory) m_Frames.push_back(r);
  else if (m_Mode == FrameRecords::Stream && std::fwrite(&r, sizeof r, 1, m_Stream.get()) != 1) m_StreamFailed = true;
}

void FrameLog::ForEachFrame(const std::function<void(const FrameRecord&)>& visit) const {
  if (m_Mode != FrameRecords::Stream) {
    for (const FrameRecord& r : m_Frames) visit(r);
    return;
  }
  // Read back in blocks; the file stays positioned at its end for the next Add.
  std::FILE* f = m_Stream.get();
  std::fflush(f);
  const long end = std::ftell(f);
  std::rewind(f);
  FrameRecord block[256];
  size_t n = 0;
  while ((n = std::fread(block, sizeof(FrameRecord), std::size(block), f)) > 0)
    for (size_t i = 0; i < n; ++i) visit(block[i]);
  std::fseek(f, end, SEEK_SET);
}

bool FrameLog::BeginFrame() {
  m_Capturing = m_Requested;
  m_Requested = false;
  m_Pending.clear();
  return m_Capturing;
}

void FrameLog::Queue(d3dl::Device* device, d3dl::DeviceContext* ctx, d3dl::Texture2D* texture, Capture kind) {
  if (!texture) return;
  ctx->OMSetRenderTargets(0, nullptr, nullptr);
  d3dl::ComPtr<d3dl::Texture2D> staging = CopyToStaging(device, ctx, texture);
  if (staging) m_Pending.push_back({std::move(staging), kind});
}

void FrameLog::Resolve(d3dl::Device* device, d3dl::DeviceContext* ctx) {
  m_Capturing = false;
  if (m_Pending.empty()) return;
  ctx->Flush();
  device->WaitIdle();
  m_Captured[int(Capture::Velocity)] = {};
  for (Pending& p : m_Pending) {
    Image& out = m_Captured[int(p.kind)];
    std::string error;
    if (!MapStaging(ctx, p.staging.Get(), &out, &error)) continue;
    out.SwizzleToRGBA();
  }
  m_Pending.clear();
}

bool FrameLog::SaveScreenshot(const std::string& path, bool noGui, std::string* error) const {
  const Image& img = Captured(noGui ? Capture::BackBufferNoGui : Capture::BackBuffer);
  if (img.Empty()) {
    *error = "no frame was captured for the screenshot";
    return false;
  }
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  // The back buffer's alpha holds no coverage (the post passes write velocity
  // weights there); a screenshot is what the window shows: opaque.
  std::vector<uint8_t> opaque = img.pixels;
  for (size_t i = 3; i < opaque.size(); i += 4) opaque[i] = 255;
  return SaveImageRGBA8(path, img.width, img.height, opaque.data(), error);
}

namespace {
// GPU averages over the frames that received a new result (the records
// repeat the last result in between); the CPU average over rendered frames.
double Average(const FrameLog& log, double FrameRecord::*m, bool gpu) {
  double s = 0;
  int64_t n = 0;
  log.ForEachFrame([&](const FrameRecord& r) {
    if (r.rendered && (!gpu || r.gpuFrameNew) && std::isfinite(r.*m) && r.*m > 0) {
      s += r.*m;
      ++n;
    }
  });
  return n ? s / double(n) : 0.0;
}

void WriteTargets(JsonWriter& j, const ReportInfo& info) {
  j.BeginObject("render_targets").Inline();
  for (int i = 0; i < int(RT::Count); ++i) {
    const RenderTarget& rt = (*info.targets)[RT(i)];
    if (!rt.Valid()) continue;
    j.BeginObject(RenderTargetSet::Name(RT(i)))
        .Pair("size", rt.width, rt.height)
        .Value("format", d3dl::FormatName(rt.format))
        .Value("bytes", rt.Bytes())
        .EndObject();
  }
  if (info.zoomBoxBytes > 0) j.BeginObject("zoom_box_copy").Value("bytes", info.zoomBoxBytes).EndObject();
  j.EndObject();
}

void WriteFrame(JsonWriter& j, const FrameRecord& r) {
  j.BeginObject().Inline();
  j.Value("frame", r.frame).Value("rendered", r.rendered).Pair("scale", r.scaleX, r.scaleY);
  j.Pair("viewport", r.viewportW, r.viewportH).Pair("back_buffer", r.backBufferW, r.backBufferH);
  j.Value("fullscreen", r.fullscreen).Value("cpu_ms", r.cpuFrameMs);
  j.Value("gpu_new", r.gpuFrameNew).Value("gpu_delay_frames", r.gpuFrameDelay);
  j.BeginObject("gpu_ms").Value("frame", r.gpuFrame).Value("clear", r.gpuClear).Value("scene", r.gpuScene);
  j.Value("postp", r.gpuPostP).Value("scale", r.gpuScale).EndObject();
  j.EndObject();
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
  const Options& o = *info.options;
  JsonWriter j(f);
  j.BeginObject().Raw("options", OptionsToJson(o));
  j.BeginObject("control").Inline().Value("mode", ControlModeOption(o.control)).Value("law", ControlLawOption(o.law));
  j.Value("refresh_hz", info.refreshHz).Value("budget_ms", info.budgetMs);
  j.Value("law_latency_frames", info.lawLatencyFrames).EndObject();
  j.Value("adapter", info.adapter).Value("driver", info.driver).Value("scene", info.scenePath);
  j.Pair("back_buffer", info.backBuffer[0], info.backBuffer[1]);
  j.Pair("dynamic_rt", info.dynamicRT[0], info.dynamicRT[1]);
  j.Value("render_target_bytes", info.targets->Bytes() + info.zoomBoxBytes);
  j.Value("render_target_bytes_original", RenderTargetSet::OriginalBytes(info.backBuffer[0], info.backBuffer[1],
                                                                         info.dynamicRT[0], info.dynamicRT[1]));
  WriteTargets(j, info);
  j.BeginObject("passes_run").Inline();
  for (const auto& [name, count] : *info.passesRun) j.Value(name, count);
  j.EndObject();
  j.Value("validation_messages", info.validationMessages);
  j.Value("frames_rendered", info.framesRendered).Value("frames_minimised", info.framesMinimised);
  j.BeginObject("averages_ms").Inline().Value("cpu_frame", Average(*this, &FrameRecord::cpuFrameMs, false));
  j.Value("gpu_frame", Average(*this, &FrameRecord::gpuFrame, true));
  j.Value("clear", Average(*this, &FrameRecord::gpuClear, true));
  j.Value("scene", Average(*this, &FrameRecord::gpuScene, true));
  j.Value("postp", Average(*this, &FrameRecord::gpuPostP, true));
  j.Value("scale", Average(*this, &FrameRecord::gpuScale, true)).EndObject();
  j.Pair("final_scale", info.finalScale[0], info.finalScale[1]);
  if (info.scene) {
    const SceneStats st = info.scene->Stats();
    j.BeginObject("scene_stats").Inline().Value("draws_issued", st.drawsIssued).Value("draws_culled", st.drawsCulled);
    j.Value("triangles", st.triangles).Value("texture_bytes", st.textureBytes);
    if (st.tessellatedDraws) j.Value("tessellated_draws", st.tessellatedDraws).Value("patches_submitted", st.patchesSubmitted);
    j.Value("recording_threads", st.recordingThreads).Value("record_ms", st.recordMs);
    j.BeginArray("draws_per_thread").Inline();
    for (uint32_t n : st.drawsPerThread) j.Value({}, n);
    j.EndArray().EndObject();
  }
  j.BeginArray("warnings");
  if (info.warnings)
    for (const std::string& w : *info.warnings) j.Value({}, w);
  j.EndArray();
  j.BeginArray("frames");
  ForEachFrame([&](const FrameRecord& r) { WriteFrame(j, r); });
  j.EndArray().EndObject();
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
