#include "FrameLog.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "imageio/ImageFile.h"
#include "imageio/Srgb.h"

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

}  // namespace drr
