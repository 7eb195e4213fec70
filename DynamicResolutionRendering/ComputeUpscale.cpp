#include "ComputeUpscale.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

#include "FrameConstants.h"
#include "ResolveFilters.h"

namespace drr {

namespace {
constexpr uint32_t kTile = 8;  // UPSCALE_TILE in Shaders/UpscaleComputeTile.hlsli
constexpr char kSharpenCS[] = "UpscaleSpatial_SharpenCS";
constexpr char kSecondaryCS[] = "UpscaleSpatial_SecondaryCS";

// Constants of Shaders/UpscaleComputeTile.hlsli (cbComputeUpscale at b2).
struct ComputeConstants {
  uint32_t writeSecond;  // TAAU: the image to u1 too
  uint32_t encode[2];    // u0's and u1's kEncode* bits
  uint32_t pad;
};
// ENCODE_* in Shaders/UpscaleComputeTile.hlsli.
constexpr uint32_t kEncodeSrgb = 1, kEncodeSwapRB = 2;

// The port's upscalers have compute versions; the original's filters stay pixel shaders.
bool HasComputeVersion(Filter f) { return std::strncmp(GetFilterInfo(f).shader, "Upscale", 7) == 0; }

// A filter's compute shader: its pixel shader's name with CS for PS.
std::string ComputeName(Filter f) {
  std::string name = GetFilterInfo(f).shader;
  return name.replace(name.size() - 2, 2, "CS");
}

// A tiled compute shader's version without the tile: DirectCS for CS
// (Shaders/CMakeLists.txt compiles one for each tiled filter).
std::string DirectName(const std::string& name) { return name.substr(0, name.size() - 2) + "DirectCS"; }

// The tiles have room for the texels of 8x8 output pixels at up to this many
// viewport texels per output pixel (TEMPORAL_TILE_SIDE, SPATIAL_TILE_SIDE).
constexpr float kTileTexelsPerPixel = 2.0f;

// The dynamic viewport's texels per output pixel on its denser axis
// (ViewportTexels() / g_OutputSize in the shaders).
float TexelsPerPixel(const DynamicConstants& dc, const UpscaleConstants& uc) {
  float r = 0.0f;
  for (int i = 0; i < 2; ++i) r = std::max(r, dc.ratioCurr[i] * dc.dynSize[i] / uc.outputSize[i]);
  return r;
}

// Every compute shader to load: each upscaler's, and the direct version of
// those the build made one for (the tiled ones).
std::vector<std::string> ComputeShaderNames(const ShaderLibrary& lib) {
  std::vector<std::string> names = {kSharpenCS, kSecondaryCS};
  for (int f = 0; f < int(Filter::Count); ++f)
    if (HasComputeVersion(Filter(f))) names.push_back(ComputeName(Filter(f)));
  const size_t count = names.size();
  for (size_t i = 0; i < count; ++i)
    if (lib.Has(DirectName(names[i]))) names.push_back(DirectName(names[i]));
  return names;
}

// How a target without a storage view is written: the scratch's format, and
// what the shader encodes so that a copy of the scratch's bits leaves in the
// target what the target's own writes would (an sRGB encoding, BGRA order).
struct ScratchPlan {
  d3dl::DXGI_FORMAT format;
  uint32_t encode;
};
ScratchPlan ScratchFor(d3dl::DXGI_FORMAT target) {
  const d3dl::DXGI_FORMAT bits = d3dl::FormatLinearOf(target);
  const uint32_t encode = bits != target ? kEncodeSrgb : 0u;
  if (bits == d3dl::DXGI_FORMAT_B8G8R8A8_UNORM) return {d3dl::DXGI_FORMAT_R8G8B8A8_UNORM, encode | kEncodeSwapRB};
  return {bits, encode};
}

d3dl::HRESULT CreateDynamicCB(d3dl::Device* device, uint32_t bytes, d3dl::Buffer** cb) {
  d3dl::BUFFER_DESC d;
  d.ByteWidth = bytes;
  d.Usage = d3dl::USAGE_DYNAMIC;
  d.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  d.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  return device->CreateBuffer(&d, nullptr, cb);
}

void Upload(d3dl::DeviceContext* ctx, d3dl::Buffer* cb, const void* data, size_t size) {
  d3dl::MAPPED_SUBRESOURCE m;
  if (d3dl::SUCCEEDED(ctx->Map(cb, 0, d3dl::MAP_WRITE_DISCARD, 0, &m))) {
    std::memcpy(m.pData, data, size);
    ctx->Unmap(cb, 0);
  }
}
}  // namespace

bool ComputeUpscale::Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* whyNot) {
  m_Device = device;
  m_NoticePrinted = false;
  m_Unavailable.clear();
  size_t compiled = 0;
  std::string error;
  if (!LoadShaders(shaders, false, &error, &compiled)) m_Unavailable = error;
  else if (!CreateStates(device)) m_Unavailable = "cannot create the compute upscalers' constant buffers or sampler";
  // The scratch formats must be storage images.
  for (d3dl::DXGI_FORMAT f : {d3dl::DXGI_FORMAT_R8G8B8A8_UNORM, d3dl::DXGI_FORMAT_R16G16B16A16_FLOAT}) {
    Scratch probe;
    if (m_Unavailable.empty() && !MakeScratch(probe, 1, 1, f))
      m_Unavailable = "the device has no storage view of the scratch formats";
  }
  *whyNot = m_Unavailable;
  return m_Unavailable.empty();
}

bool ComputeUpscale::CreateStates(d3dl::Device* device) {
  d3dl::SAMPLER_DESC linear;  // as the full-screen passes' linear clamp sampler (g_LinearClamp)
  linear.Filter = d3dl::FILTER_MIN_MAG_MIP_LINEAR;
  linear.MinLOD = 0.0f;
  linear.ComparisonFunc = d3dl::COMPARISON_ALWAYS;
  return d3dl::SUCCEEDED(CreateDynamicCB(device, sizeof(DynamicConstants), m_DynamicCB.ReleaseAndGetAddressOf())) &&
         d3dl::SUCCEEDED(CreateDynamicCB(device, sizeof(UpscaleConstants), m_UpscaleCB.ReleaseAndGetAddressOf())) &&
         d3dl::SUCCEEDED(CreateDynamicCB(device, sizeof(ComputeConstants), m_ComputeCB.ReleaseAndGetAddressOf())) &&
         d3dl::SUCCEEDED(device->CreateSamplerState(&linear, m_Linear.ReleaseAndGetAddressOf()));
}

bool ComputeUpscale::LoadShaders(const ShaderLibrary& lib, bool fromSource, std::string* error, size_t* compiled) {
  std::map<std::string, d3dl::ComPtr<d3dl::ComputeShader>> next;
  *compiled = 0;
  for (const std::string& name : ComputeShaderNames(lib)) {
    std::vector<uint32_t> code;
    bool c = false;
    if (!lib.Load(name, fromSource, &code, error, &c)) return false;
    if (d3dl::FAILED(m_Device->CreateComputeShader(code.data(), code.size() * sizeof(uint32_t),
                                                   next[name].GetAddressOf()))) {
      *error = "cannot create the compute shader " + name;
      return false;
    }
    *compiled += c;
  }
  m_Shaders = std::move(next);
  return true;
}

void ComputeUpscale::Release() {
  m_Shaders.clear();
  m_DynamicCB = m_UpscaleCB = m_ComputeCB = nullptr;
  m_Linear = nullptr;
  m_History = m_Output = m_Final = Scratch{};
  m_Device = nullptr;
}

bool ComputeUpscale::MakeScratch(Scratch& slot, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT format) {
  if (slot.texture) {
    d3dl::TEXTURE2D_DESC d;
    slot.texture->GetDesc(&d);
    if (d.Width == w && d.Height == h && d.Format == format) return true;
  }
  slot = Scratch{};
  d3dl::TEXTURE2D_DESC d;
  d.Width = w;
  d.Height = h;
  d.MipLevels = 1;
  d.Format = format;
  d.BindFlags = d3dl::BIND_UNORDERED_ACCESS;
  if (d3dl::FAILED(m_Device->CreateTexture2D(&d, nullptr, slot.texture.GetAddressOf())) ||
      d3dl::FAILED(m_Device->CreateUnorderedAccessView(slot.texture.Get(), nullptr, slot.uav.GetAddressOf()))) {
    slot = Scratch{};
    return false;
  }
  slot.texture->SetDebugName("compute upscale scratch");
  return true;
}

void ComputeUpscale::Dispatch(d3dl::DeviceContext* ctx, const char* shader, const FrameSetup& s,
                              const UpscaleConstants& uc, d3dl::ShaderResourceView* const* srvs, uint32_t srvCount,
                              const Destination* out, uint32_t outCount) {
  ComputeConstants cc{outCount > 1 && out[1].written, {0, 0}, 0};
  d3dl::UnorderedAccessView* uavs[2] = {};
  for (uint32_t i = 0; i < outCount; ++i) {
    uavs[i] = out[i].storage;
    if (uavs[i]) continue;
    d3dl::TEXTURE2D_DESC t;
    out[i].target->GetDesc(&t);
    const ScratchPlan plan = ScratchFor(t.Format);
    if (!MakeScratch(*out[i].scratch, t.Width, t.Height, plan.format)) return;  // out of memory: the old image stays
    uavs[i] = out[i].scratch->uav.Get();
    cc.encode[i] = plan.encode;
  }
  Upload(ctx, m_DynamicCB.Get(), &s.dc, sizeof s.dc);
  Upload(ctx, m_UpscaleCB.Get(), &uc, sizeof uc);
  Upload(ctx, m_ComputeCB.Get(), &cc, sizeof cc);
  d3dl::Buffer* cbs[3] = {m_DynamicCB.Get(), m_UpscaleCB.Get(), m_ComputeCB.Get()};
  ctx->CSSetConstantBuffers(0, 3, cbs);
  d3dl::SamplerState* samplers[3] = {m_Linear.Get(), m_Linear.Get(), m_Linear.Get()};
  ctx->CSSetSamplers(0, 3, samplers);
  ctx->CSSetShaderResources(0, srvCount, srvs);
  ctx->CSSetUnorderedAccessViews(0, outCount, uavs, nullptr);
  ctx->CSSetShader(ShaderFor(shader, s.dc, uc));
  ctx->Dispatch((uint32_t(uc.outputSize[0]) + kTile - 1) / kTile, (uint32_t(uc.outputSize[1]) + kTile - 1) / kTile, 1);
  d3dl::ShaderResourceView* noSrvs[8] = {};
  d3dl::UnorderedAccessView* noUavs[2] = {};
  ctx->CSSetShaderResources(0, srvCount, noSrvs);
  ctx->CSSetUnorderedAccessViews(0, outCount, noUavs, nullptr);
  // A copy of the scratch's bits (its format and the target's are copy-compatible).
  for (uint32_t i = 0; i < outCount; ++i)
    if (!out[i].storage && out[i].written) ctx->CopyResource(out[i].target, out[i].scratch->texture.Get());
}

d3dl::ComputeShader* ComputeUpscale::ShaderFor(const std::string& name, const DynamicConstants& dc,
                                               const UpscaleConstants& uc) const {
  if (TexelsPerPixel(dc, uc) > kTileTexelsPerPixel) {
    const auto direct = m_Shaders.find(DirectName(name));
    if (direct != m_Shaders.end()) return direct->second.Get();
  }
  return m_Shaders.at(name).Get();
}

ComputeUpscale::Destination ComputeUpscale::ToTarget(RenderTarget& rt, Scratch* scratch) {
  return {rt.texture.Get(), scratch, rt.uav.Get()};
}

bool ComputeUpscale::Record(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                            const BackBuffer& bb, FrameProfiler* profiler) {
  m_Profiler = profiler;
  if (!s.dynamic || !HasComputeVersion(s.filter)) return false;
  if (!m_Unavailable.empty()) {
    if (!m_NoticePrinted)
      std::fprintf(stderr, "note: compute upscalers unavailable (%s): using the pixel shaders\n", m_Unavailable.c_str());
    m_NoticePrinted = true;
    return false;
  }
  ctx->OMSetRenderTargets(0, nullptr, nullptr);  // the scene's and motion blur's targets are read now
  // The primary upscale's output: the secondary upscale's source or the back buffer.
  const Destination out = s.secondary ? ToTarget(rts[RT::UpscaleOutput], &m_Output) : Destination{bb.texture, &m_Final};
  if (s.TAAU()) {
    Temporal(ctx, s, rts, bb);
  } else if (HasSharpenPass(s.filter)) {
    Spatial(ctx, s, rts, ToTarget(rts[RT::UpscaleSharpenInput], &m_Output));
    Sharpen(ctx, s, rts, out);
  } else {
    Spatial(ctx, s, rts, out);
  }
  if (s.secondary) Secondary(ctx, s, rts, bb);
  return true;
}

// TAAU: this frame's colour, velocity and depth and the last history into
// the new history and, unless the secondary upscale follows, the back buffer.
void ComputeUpscale::Temporal(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                              const BackBuffer& bb) {
  ctx->BeginEvent("TemporalUpsampleCS");
  d3dl::ShaderResourceView* srv[7] = {rts.Final(s.cur).srv.Get(), rts.UpscaleHistory(s.historyPrev).srv.Get(),
                                      rts.Velocity(0).srv.Get(), nullptr, nullptr, nullptr,
                                      rts[RT::DepthDynamic].srv.Get()};
  const Destination out[2] = {ToTarget(rts.UpscaleHistory(s.historyCur), &m_History),
                              {bb.texture, &m_Final, nullptr, !s.secondary}};
  Dispatch(ctx, ComputeName(s.filter).c_str(), s, s.uc, srv, 7, out, 2);
  m_Profiler->CountPass(GetFilterInfo(s.filter).pass);
  ctx->EndEvent();
}

// The spatial filter into out (the back buffer, or the next pass's source).
void ComputeUpscale::Spatial(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                             const Destination& out) {
  ctx->BeginEvent("ScaleCS");
  d3dl::ShaderResourceView* srv = rts.Final(s.cur).srv.Get();
  Dispatch(ctx, ComputeName(s.filter).c_str(), s, s.uc, &srv, 1, &out, 1);
  m_Profiler->CountPass(GetFilterInfo(s.filter).pass);
  ctx->EndEvent();
}

// Contrast-limited sharpening of the edge-adaptive upscale's output.
void ComputeUpscale::Sharpen(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                             const Destination& out) {
  ctx->BeginEvent("SharpenCS");
  d3dl::ShaderResourceView* srv = rts[RT::UpscaleSharpenInput].srv.Get();
  Dispatch(ctx, kSharpenCS, s, s.uc, &srv, 1, &out, 1);
  m_Profiler->CountPass("Sharpen");
  ctx->EndEvent();
}

// The static secondary upscale: the primary upscale's output (or TAAU's new
// history) to the back buffer, a dispatch over the back buffer's pixels.
void ComputeUpscale::Secondary(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                               const BackBuffer& bb) {
  ctx->BeginEvent("SecondaryUpscaleCS");
  d3dl::ShaderResourceView* srv =
      s.TAAU() ? rts.UpscaleHistory(s.historyCur).srv.Get() : rts[RT::UpscaleOutput].srv.Get();
  UpscaleConstants uc = s.uc;
  uc.outputSize[0] = s.backBufferViewport.Width;
  uc.outputSize[1] = s.backBufferViewport.Height;
  uc.invOutputSize[0] = 1.0f / uc.outputSize[0];
  uc.invOutputSize[1] = 1.0f / uc.outputSize[1];
  const Destination out{bb.texture, &m_Final};
  Dispatch(ctx, kSecondaryCS, s, uc, &srv, 1, &out, 1);
  m_Profiler->CountPass("SecondaryUpscale");
  ctx->EndEvent();
}

}  // namespace drr
