#include "RenderTargets.h"

#include <algorithm>
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
// Depth a pass reads (TAAU, the deferred passes, the shadow maps): typeless,
// with a depth and a float view.
constexpr d3dl::DXGI_FORMAT kReadableDepth = d3dl::DXGI_FORMAT_R32_TYPELESS;
constexpr d3dl::DXGI_FORMAT kBackBuffer = d3dl::DXGI_FORMAT_UNKNOWN;  // the plan's backBufferFormat
// ColourStorage targets get a storage view (UAV) unless their format is sRGB,
// which cannot be a storage image.
bool HasStorageView(TargetViews views, d3dl::DXGI_FORMAT f) {
  return views == TargetViews::ColourStorage && !d3dl::FormatIsSrgb(f);
}
// One row per target: its name, format, size rule and when the plan needs it
// (the original's InitDynamicResolution rules, then the port's additions).
// The fast TAA path reads velocity from the motion-blur alpha: one velocity
// target is enough there. TAAU reads velocity 0 and writes its history; the
// secondary upscale reads the history or the primary spatial upscale's output.
constexpr RenderTargetRow kTargets[] = {
    {"g_ColorDynamic", kColor, SizeRule::Dynamic, [](Plan p) { return p.dynamic && p.motionBlur; }},
    {"g_DepthDynamic", kDepth, SizeRule::Dynamic, [](Plan p) { return p.dynamic; }},
    {"g_VelocityDynamic[0]", kVelocity, SizeRule::Dynamic,
     [](Plan p) { return p.dynamic && (p.motionBlur || p.temporal != TemporalMode::None); }},
    {"g_VelocityDynamic[1]", kVelocity, SizeRule::Dynamic, [](Plan p) { return p.dynamic && p.TAA() && !p.motionBlur; }},
    {"g_FinalRTDynamic[0]", kColor, SizeRule::Dynamic, [](Plan p) { return p.dynamic; }},
    {"g_FinalRTDynamic[1]", kColor, SizeRule::Dynamic, [](Plan p) { return p.dynamic && p.TAA(); }},
    {"g_ColorFull", kColor, SizeRule::Full, [](Plan p) { return !p.dynamic && p.motionBlur; }},
    {"g_VelocityFull", kVelocity, SizeRule::Full, [](Plan p) { return !p.dynamic && p.motionBlur; }},
    {"g_DepthFull", kDepth, SizeRule::Full, [](Plan p) { return !p.dynamic; }},
    {"upscale history[0]", kHistory, SizeRule::Output, [](Plan p) { return p.dynamic && p.TAAU(); },
     TargetViews::ColourStorage},
    {"upscale history[1]", kHistory, SizeRule::Output, [](Plan p) { return p.dynamic && p.TAAU(); },
     TargetViews::ColourStorage},
    {"upscale output", kColor, SizeRule::Output, [](Plan p) { return p.dynamic && p.Secondary() && !p.TAAU(); },
     TargetViews::ColourStorage},
    {"upscale sharpen input", kColor, SizeRule::Output, [](Plan p) { return p.dynamic && p.sharpenPass; },
     TargetViews::ColourStorage},
    // Deferred shading: the dynamic RT's size on both paths.
    {"g_GBufferDiffuse", kSrgb, SizeRule::Dynamic, [](Plan p) { return p.deferred; }},
    {"g_GBufferSpecular", kSrgb, SizeRule::Dynamic, [](Plan p) { return p.deferred; }},
    {"g_GBufferNormal", d3dl::DXGI_FORMAT_R10G10B10A2_UNORM, SizeRule::Dynamic, [](Plan p) { return p.deferred; }},
    {"g_GBufferAO", d3dl::DXGI_FORMAT_R8_UNORM, SizeRule::Dynamic, [](Plan p) { return p.deferred && p.ssao; }},
    {"g_SpotShadowMaps", kReadableDepth, SizeRule::Fixed, [](Plan p) { return p.shadowSlices > 0; },
     TargetViews::DepthArray},
    // The zoom box's copy of the back buffer (CopyResource), read by its magnified quad.
    {"zoom_box_copy", kBackBuffer, SizeRule::Full, [](Plan p) { return p.zoomBox; }, TargetViews::CopyRead},
};
static_assert(std::size(kTargets) == size_t(RT::Count));
}  // namespace

d3dl::HRESULT RenderTarget::Create(d3dl::Device* device, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT fmt,
                                   const char* name, TargetViews kind, uint32_t arraySlices) {
  Release();
  const bool depth = fmt == d3dl::DXGI_FORMAT_D32_FLOAT || fmt == kReadableDepth;
  d3dl::TEXTURE2D_DESC d;
  d.Width = w;
  d.Height = h;
  d.MipLevels = 1;
  d.ArraySize = kind == TargetViews::DepthArray ? arraySlices : 1;
  d.Format = fmt;
  if (kind == TargetViews::CopyRead) d.BindFlags = d3dl::BIND_SHADER_RESOURCE;
  else d.BindFlags = depth ? d3dl::BIND_DEPTH_STENCIL : (d3dl::BIND_RENDER_TARGET | d3dl::BIND_SHADER_RESOURCE);
  if (fmt == kReadableDepth) d.BindFlags |= d3dl::BIND_SHADER_RESOURCE;
  if (HasStorageView(kind, fmt)) d.BindFlags |= d3dl::BIND_UNORDERED_ACCESS;
  d3dl::HRESULT hr = device->CreateTexture2D(&d, nullptr, texture.ReleaseAndGetAddressOf());
  if (d3dl::FAILED(hr)) return hr;
  texture->SetDebugName(name);
  width = w;
  height = h;
  format = fmt;
  views = kind;
  slices = kind == TargetViews::DepthArray ? arraySlices : 0;
  hr = CreateViews(device);
  if (d3dl::FAILED(hr)) Release();
  return hr;
}

d3dl::HRESULT RenderTarget::CreateViews(d3dl::Device* device) {
  d3dl::Texture2D* t = texture.Get();
  if (views == TargetViews::CopyRead) return device->CreateShaderResourceView(t, nullptr, srv.ReleaseAndGetAddressOf());
  if (format == d3dl::DXGI_FORMAT_D32_FLOAT) return device->CreateDepthStencilView(t, nullptr, dsv.ReleaseAndGetAddressOf());
  if (format != kReadableDepth) {
    d3dl::HRESULT hr = device->CreateRenderTargetView(t, nullptr, rtv.ReleaseAndGetAddressOf());
    if (d3dl::SUCCEEDED(hr)) hr = device->CreateShaderResourceView(t, nullptr, srv.ReleaseAndGetAddressOf());
    if (d3dl::SUCCEEDED(hr) && HasStorageView(views, format))
      hr = device->CreateUnorderedAccessView(t, nullptr, uav.ReleaseAndGetAddressOf());
    return hr;
  }
  // Readable depth: D32_FLOAT DSVs (one per slice of an array), an R32_FLOAT SRV.
  const bool array = views == TargetViews::DepthArray;
  d3dl::SHADER_RESOURCE_VIEW_DESC sv;
  sv.Format = d3dl::DXGI_FORMAT_R32_FLOAT;
  sv.ViewDimension = array ? d3dl::SRV_DIMENSION_TEXTURE2DARRAY : d3dl::SRV_DIMENSION_TEXTURE2D;
  if (array) sv.Array = {0, slices};
  d3dl::HRESULT hr = device->CreateShaderResourceView(t, &sv, srv.ReleaseAndGetAddressOf());
  d3dl::DEPTH_STENCIL_VIEW_DESC dv;
  dv.Format = d3dl::DXGI_FORMAT_D32_FLOAT;
  dv.ViewDimension = array ? d3dl::DSV_DIMENSION_TEXTURE2DARRAY : d3dl::DSV_DIMENSION_TEXTURE2D;
  if (!array) return d3dl::FAILED(hr) ? hr : device->CreateDepthStencilView(t, &dv, dsv.ReleaseAndGetAddressOf());
  sliceDsv.resize(slices);
  for (uint32_t i = 0; i < slices && d3dl::SUCCEEDED(hr); ++i) {
    dv.Array = {i, 1};
    hr = device->CreateDepthStencilView(t, &dv, sliceDsv[i].ReleaseAndGetAddressOf());
  }
  return hr;
}

void RenderTarget::Release() {
  sliceDsv.clear();
  dsv = nullptr;
  uav = nullptr;
  srv = nullptr;
  rtv = nullptr;
  texture = nullptr;
  width = height = slices = 0;
  format = d3dl::DXGI_FORMAT_UNKNOWN;
  views = TargetViews::ByFormat;
}

uint64_t RenderTarget::Bytes() const {
  return Valid() ? uint64_t(width) * height * std::max(slices, 1u) * d3dl::FormatBytesPerElement(format) : 0;
}

const char* RenderTargetSet::Name(RT rt) { return kTargets[int(rt)].name; }
d3dl::DXGI_FORMAT RenderTargetSet::Format(RT rt, const RenderTargetPlan& plan) {
  const d3dl::DXGI_FORMAT f = kTargets[int(rt)].format;
  // Depth read by TAAU or by the deferred passes: typeless.
  const bool readDepth = (rt == RT::DepthDynamic && (plan.TAAU() || plan.deferred)) || (rt == RT::DepthFull && plan.deferred);
  if (readDepth) return kReadableDepth;
  if (f == kBackBuffer) return plan.backBufferFormat;
  return plan.srgbColour && f == kColor ? d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB : f;
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
    case SizeRule::Fixed: *w = *h = shadowMapSize; break;
  }
}

bool RenderTargetPlan::SameButRewrittenEachFrame(const RenderTargetPlan& other) const {
  RenderTargetPlan a = *this, b = other;
  for (RenderTargetPlan* p : {&a, &b}) {
    p->shadowSlices = p->shadowMapSize = 0;
    p->zoomBox = false;
    p->backBufferFormat = d3dl::DXGI_FORMAT_UNKNOWN;
  }
  return a == b;
}

bool RenderTargetSet::Allocate(d3dl::Device* device, const RenderTargetPlan& plan, uint32_t dynW, uint32_t dynH) {
  bool ok = true;
  for (int i = 0; i < int(RT::Count); ++i) {
    const RT rt = RT(i);
    RenderTarget& t = m_Targets[i];
    if (!Needed(rt, plan)) {
      t.Release();
      continue;
    }
    uint32_t w = 0, h = 0;
    plan.Size(kTargets[i].size, dynW, dynH, &w, &h);
    const d3dl::DXGI_FORMAT fmt = Format(rt, plan);
    const TargetViews views = kTargets[i].views;
    const uint32_t slices = views == TargetViews::DepthArray ? plan.shadowSlices : 0;
    if (t.Valid() && t.width == w && t.height == h && t.format == fmt && t.views == views && t.slices == slices) continue;
    if (ok) ok = d3dl::SUCCEEDED(t.Create(device, w, h, fmt, Name(rt), views, slices));
    else t.Release();
  }
  m_Plan = plan;
  return ok;
}

void RenderTargetSet::ZeroContents(d3dl::DeviceContext* ctx) {
  constexpr float kZero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (RenderTarget& t : m_Targets) {
    if (t.rtv) ctx->ClearRenderTargetView(t.rtv.Get(), kZero);
    if (t.dsv) ctx->ClearDepthStencilView(t.dsv.Get(), d3dl::CLEAR_DEPTH, 1.0f, 0);
    for (const auto& slice : t.sliceDsv) ctx->ClearDepthStencilView(slice.Get(), d3dl::CLEAR_DEPTH, 1.0f, 0);
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
