#include "RenderTargets.h"

#include <iterator>

namespace drr {

namespace {
using Plan = const RenderTargetPlan&;
// The original's colour targets are R8G8B8A8_UNORM: they hold the shader's
// linear values in 8 bits; only the back buffer is sRGB.
constexpr d3dl::DXGI_FORMAT kColor = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM;
constexpr d3dl::DXGI_FORMAT kVelocity = d3dl::DXGI_FORMAT_R16G16_FLOAT;
constexpr d3dl::DXGI_FORMAT kDepth = d3dl::DXGI_FORMAT_D32_FLOAT;
constexpr d3dl::DXGI_FORMAT kHistory = d3dl::DXGI_FORMAT_R16G16B16A16_FLOAT;
constexpr d3dl::DXGI_FORMAT kSrgb = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
// One row per target: its name, format, size rule and when the plan needs it
// (the original's InitDynamicResolution rules, then the port's additions).
// The fast TAA path reads velocity from the motion-blur alpha: one velocity
// target is enough there. TAAU reads velocity 0 and writes its history; the
// secondary upscale reads the history or the primary spatial upscale's output.
constexpr RenderTargetRow kTargets[] = {
    {"g_ColorDynamic", kColor, SizeRule::Dynamic, [](Plan p) { return p.dynamic && p.motionBlur; }},
    {"g_DepthDynamic", kDepth, SizeRule::Dynamic, [](Plan p) { return p.dynamic; }},
    {"g_VelocityDynamic[0]", kVelocity, SizeRule::Dynamic,
     [](Plan p) { return p.dynamic && (p.motionBlur || p.taa || p.taau); }},
    {"g_VelocityDynamic[1]", kVelocity, SizeRule::Dynamic, [](Plan p) { return p.dynamic && p.taa && !p.motionBlur; }},
    {"g_FinalRTDynamic[0]", kColor, SizeRule::Dynamic, [](Plan p) { return p.dynamic; }},
    {"g_FinalRTDynamic[1]", kColor, SizeRule::Dynamic, [](Plan p) { return p.dynamic && p.taa; }},
    {"g_ColorFull", kColor, SizeRule::Full, [](Plan p) { return !p.dynamic && p.motionBlur; }},
    {"g_VelocityFull", kVelocity, SizeRule::Full, [](Plan p) { return !p.dynamic && p.motionBlur; }},
    {"g_DepthFull", kDepth, SizeRule::Full, [](Plan p) { return !p.dynamic; }},
    {"upscale history[0]", kHistory, SizeRule::Output, [](Plan p) { return p.dynamic && p.taau; }},
    {"upscale history[1]", kHistory, SizeRule::Output, [](Plan p) { return p.dynamic && p.taau; }},
    {"upscale output", kColor, SizeRule::Output, [](Plan p) { return p.dynamic && p.Secondary() && !p.taau; }},
    {"upscale sharpen input", kColor, SizeRule::Output, [](Plan p) { return p.dynamic && p.sharpenPass; }},
    // Deferred shading: the dynamic RT's size on both paths.
    {"g_GBufferDiffuse", kSrgb, SizeRule::Dynamic, [](Plan p) { return p.deferred; }},
    {"g_GBufferSpecular", kSrgb, SizeRule::Dynamic, [](Plan p) { return p.deferred; }},
    {"g_GBufferNormal", d3dl::DXGI_FORMAT_R10G10B10A2_UNORM, SizeRule::Dynamic, [](Plan p) { return p.deferred; }},
    {"g_GBufferAO", d3dl::DXGI_FORMAT_R8_UNORM, SizeRule::Dynamic, [](Plan p) { return p.deferred && p.ssao; }},
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

const RenderTargetRow& RenderTargetSet::Row(RT rt) { return kTargets[int(rt)]; }

bool RenderTargetSet::Needed(RT rt, const RenderTargetPlan& plan) { return Row(rt).needed(plan); }

void RenderTargetPlan::Size(SizeRule rule, uint32_t dynW, uint32_t dynH, uint32_t* w, uint32_t* h) const {
  switch (rule) {
    case SizeRule::Dynamic: *w = dynW, *h = dynH; break;
    case SizeRule::Output: *w = outputW, *h = outputH; break;
    case SizeRule::Full: *w = backBufferW, *h = backBufferH; break;
  }
}

bool RenderTargetSet::Allocate(d3dl::Device* device, const RenderTargetPlan& plan, uint32_t dynW, uint32_t dynH) {
  Release();
  bool ok = true;
  for (int i = 0; i < int(RT::Count); ++i) {
    const RT rt = RT(i);
    if (!Needed(rt, plan)) continue;
    uint32_t w = 0, h = 0;
    plan.Size(kTargets[i].size, dynW, dynH, &w, &h);
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
