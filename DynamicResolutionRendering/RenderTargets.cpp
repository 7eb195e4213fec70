#include "RenderTargets.h"

#include <iterator>

namespace drr {

namespace {
struct TargetInfo {
  const char* name;
  d3dl::DXGI_FORMAT format;
  bool dynamic;  // sized as the dynamic RT, else as the back buffer
  bool output = false;  // port addition: on the dynamic path, at the upscale's output size
  bool gbuffer = false;  // deferred shading: the dynamic RT's size on both paths
};
// The original's colour targets are R8G8B8A8_UNORM: they hold the shader's
// linear values in 8 bits; only the back buffer is sRGB.
constexpr d3dl::DXGI_FORMAT kColor = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM;
constexpr d3dl::DXGI_FORMAT kVelocity = d3dl::DXGI_FORMAT_R16G16_FLOAT;
constexpr d3dl::DXGI_FORMAT kDepth = d3dl::DXGI_FORMAT_D32_FLOAT;
constexpr TargetInfo kTargets[] = {
    {"g_ColorDynamic", kColor, true},          {"g_DepthDynamic", kDepth, true},
    {"g_VelocityDynamic[0]", kVelocity, true}, {"g_VelocityDynamic[1]", kVelocity, true},
    {"g_FinalRTDynamic[0]", kColor, true},     {"g_FinalRTDynamic[1]", kColor, true},
    {"g_ColorFull", kColor, false},            {"g_VelocityFull", kVelocity, false},
    {"g_DepthFull", kDepth, false},
    {"upscale history[0]", d3dl::DXGI_FORMAT_R16G16B16A16_FLOAT, false, true},
    {"upscale history[1]", d3dl::DXGI_FORMAT_R16G16B16A16_FLOAT, false, true},
    {"upscale output", kColor, false, true},
    {"upscale sharpen input", kColor, false, true},
    {"g_GBufferDiffuse", d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, true, false, true},
    {"g_GBufferSpecular", d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, true, false, true},
    {"g_GBufferNormal", d3dl::DXGI_FORMAT_R10G10B10A2_UNORM, true, false, true},
    {"g_GBufferAO", d3dl::DXGI_FORMAT_R8_UNORM, true, false, true},
};
// TAAU reads the dynamic depth: typeless, with a depth and a float view.
constexpr d3dl::DXGI_FORMAT kReadableDepth = d3dl::DXGI_FORMAT_R32_TYPELESS;
static_assert(std::size(kTargets) == size_t(RT::Count));
}  // namespace

d3dl::HRESULT RenderTarget::Create(d3dl::Device* device, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT fmt,
                                   const char* name) {
  Release();
  const bool readableDepth = fmt == kReadableDepth;
  const bool depth = fmt == d3dl::DXGI_FORMAT_D32_FLOAT || readableDepth;
  d3dl::TEXTURE2D_DESC d;
  d.Width = w;
  d.Height = h;
  d.MipLevels = 1;
  d.Format = fmt;
  d.BindFlags = depth ? d3dl::BIND_DEPTH_STENCIL : (d3dl::BIND_RENDER_TARGET | d3dl::BIND_SHADER_RESOURCE);
  if (readableDepth) d.BindFlags |= d3dl::BIND_SHADER_RESOURCE;
  d3dl::HRESULT hr = device->CreateTexture2D(&d, nullptr, texture.ReleaseAndGetAddressOf());
  if (d3dl::FAILED(hr)) return hr;
  texture->SetDebugName(name);
  if (readableDepth) {
    d3dl::DEPTH_STENCIL_VIEW_DESC dv;
    dv.Format = d3dl::DXGI_FORMAT_D32_FLOAT;
    dv.ViewDimension = d3dl::DSV_DIMENSION_TEXTURE2D;
    d3dl::SHADER_RESOURCE_VIEW_DESC sv;
    sv.Format = d3dl::DXGI_FORMAT_R32_FLOAT;
    sv.ViewDimension = d3dl::SRV_DIMENSION_TEXTURE2D;
    hr = device->CreateDepthStencilView(texture.Get(), &dv, dsv.ReleaseAndGetAddressOf());
    if (d3dl::SUCCEEDED(hr)) hr = device->CreateShaderResourceView(texture.Get(), &sv, srv.ReleaseAndGetAddressOf());
  } else if (depth) {
    hr = device->CreateDepthStencilView(texture.Get(), nullptr, dsv.ReleaseAndGetAddressOf());
  } else {
    hr = device->CreateRenderTargetView(texture.Get(), nullptr, rtv.ReleaseAndGetAddressOf());
    if (d3dl::SUCCEEDED(hr)) hr = device->CreateShaderResourceView(texture.Get(), nullptr, srv.ReleaseAndGetAddressOf());
  }
  if (d3dl::FAILED(hr)) {
    Release();
    return hr;
  }
  width = w;
  height = h;
  format = fmt;
  return d3dl::S_OK;
}

void RenderTarget::Release() {
  dsv = nullptr;
  srv = nullptr;
  rtv = nullptr;
  texture = nullptr;
  width = height = 0;
  format = d3dl::DXGI_FORMAT_UNKNOWN;
}

uint64_t RenderTarget::Bytes() const {
  return Valid() ? uint64_t(width) * height * d3dl::FormatBytesPerElement(format) : 0;
}

const char* RenderTargetSet::Name(RT rt) { return kTargets[int(rt)].name; }
d3dl::DXGI_FORMAT RenderTargetSet::Format(RT rt, bool srgbColour) {
  const d3dl::DXGI_FORMAT f = kTargets[int(rt)].format;
  return srgbColour && f == kColor ? d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB : f;
}

uint64_t RenderTargetSet::OriginalBytes(uint32_t backW, uint32_t backH, uint32_t dynW, uint32_t dynH) {
  const uint64_t colour = d3dl::FormatBytesPerElement(kColor), velocity = d3dl::FormatBytesPerElement(kVelocity),
                 depth = d3dl::FormatBytesPerElement(kDepth);
  const uint64_t zoomCopy = colour;  // the back buffer's RGBA8 format
  const uint64_t full = uint64_t(backW) * backH * (colour + velocity + depth + zoomCopy);
  const uint64_t dyn = uint64_t(dynW) * dynH * (depth + colour + 2 * velocity + 2 * colour);
  return full + dyn;
}

bool RenderTargetSet::Needed(RT rt, const RenderTargetPlan& p) {
  if (kTargets[int(rt)].gbuffer) return p.deferred && (rt != RT::GBufferAO || p.ssao);
  if (kTargets[int(rt)].output) {
    if (!p.dynamic) return false;
    // TAAU writes its history; the secondary upscale reads it, or the primary spatial upscale's output.
    if (rt == RT::UpscaleOutput) return p.Secondary() && !p.taau;
    if (rt == RT::UpscaleSharpenInput) return p.sharpenPass;
    return p.taau;
  }
  if (kTargets[int(rt)].dynamic != p.dynamic) return false;
  if (rt == RT::VelocityDynamic0 && p.taau) return true;
  switch (rt) {
    case RT::DepthDynamic:
    case RT::FinalDynamic0:
    case RT::DepthFull: return true;
    case RT::FinalDynamic1: return p.taa;
    case RT::ColorDynamic:
    case RT::ColorFull:
    case RT::VelocityFull: return p.motionBlur;
    case RT::VelocityDynamic0: return p.motionBlur || p.taa;
    // The fast TAA path reads velocity from the motion-blur alpha: one velocity target is enough.
    case RT::VelocityDynamic1: return p.taa && !p.motionBlur;
    default: return false;
  }
}

bool RenderTargetSet::Allocate(d3dl::Device* device, const RenderTargetPlan& plan, uint32_t dynW, uint32_t dynH) {
  Release();
  bool ok = true;
  for (int i = 0; i < int(RT::Count); ++i) {
    const RT rt = RT(i);
    if (!Needed(rt, plan)) continue;
    const bool dyn = kTargets[i].dynamic, out = kTargets[i].output;
    const uint32_t w = dyn ? dynW : out ? plan.outputW : plan.backBufferW;
    const uint32_t h = dyn ? dynH : out ? plan.outputH : plan.backBufferH;
    // Depth read by TAAU or by the deferred passes: typeless.
    const bool readDepth = (rt == RT::DepthDynamic && (plan.taau || plan.deferred)) || (rt == RT::DepthFull && plan.deferred);
    const d3dl::DXGI_FORMAT fmt = readDepth ? kReadableDepth : Format(rt, plan.srgbColour);
    ok = ok && d3dl::SUCCEEDED(m_Targets[i].Create(device, w, h, fmt, Name(rt)));
  }
  m_Plan = plan;
  return ok;
}

void RenderTargetSet::ZeroContents(d3dl::DeviceContext* ctx) {
  constexpr float kZero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (RenderTarget& t : m_Targets) {
    if (t.rtv) ctx->ClearRenderTargetView(t.rtv.Get(), kZero);
    if (t.dsv) ctx->ClearDepthStencilView(t.dsv.Get(), d3dl::CLEAR_DEPTH, 1.0f, 0);
  }
}

void RenderTargetSet::Release() {
  for (RenderTarget& t : m_Targets) t.Release();
  m_Plan = {};
}

uint64_t RenderTargetSet::Bytes() const {
  uint64_t b = 0;
  for (const RenderTarget& t : m_Targets) b += t.Bytes();
  return b;
}

}  // namespace drr
