#include "FramePasses.h"

#include <cstring>

#include "ComputeUpscale.h"

namespace drr {

namespace {
constexpr float kZero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
constexpr float kMarkerColor[4] = {1.0f, 0.0f, 1.0f, 1.0f};      // magenta, never in the Arena
constexpr float kMarkerVelocity[4] = {0.5f, -0.5f, 0.0f, 0.0f};  // a huge velocity

void UnbindPixelSRVs(d3dl::DeviceContext* ctx) {
  d3dl::ShaderResourceView* none[7] = {};  // t6: the upscalers' depth
  ctx->PSSetShaderResources(0, 7, none);
}

// Upscaling tuning (Docs/Upscaling.md).
constexpr float kUnsharpAmount = 0.5f;          // Directional and Gaussian Unsharp
// TAAU, tuned on the Arena's moving cinematic camera at 0.5 and 0.71
// (Docs/Upscaling.md): history is worth most where nothing moves; each
// resampling of a moving history blurs it, so there the current frame counts more.
constexpr float kHistoryWeightStill = 32.0f;    // most frames' worth of history, still pixels
constexpr float kHistoryWeightMoving = 1.5f;    // ... pixels moving kMotionPixels a frame or more
constexpr float kMotionPixels = 0.25f;          // output pixels per frame counted as fully moving
constexpr float kClipGammaStill = 2.0f;         // neighbourhood box half-size in sigmas
constexpr float kClipGammaMoving = 1.25f;
constexpr float kSampleSigmaStill = 0.4f;       // output pixels: sharp where history accumulates
constexpr float kSampleSigmaMoving = 0.55f;     // smoother where the current frame dominates

float RadicalInverse(uint32_t i, uint32_t base) {
  float f = 1.0f, r = 0.0f;
  for (; i > 0; i /= base) {
    f /= float(base);
    r += f * float(i % base);
  }
  return r;
}
}  // namespace

// The post-processing shaders, each by its name in Shaders/CMakeLists.txt.
struct FramePasses::Shaders {
  d3dl::ComPtr<d3dl::VertexShader> dynamicVS, fullVS;
  d3dl::ComPtr<d3dl::PixelShader> clear, clearVelocity, motionBlur, fullClear, fullClearVelocity, fullMotionBlur;
  d3dl::ComPtr<d3dl::PixelShader> secondary;  // the secondary spatial upscale
  d3dl::ComPtr<d3dl::PixelShader> sharpen;    // after the edge-adaptive upscale
  std::map<std::string, d3dl::ComPtr<d3dl::PixelShader>> resolve;  // the filters' (ResolveFilters.cpp)

  struct VS {
    const char* name;
    d3dl::ComPtr<d3dl::VertexShader> Shaders::*member;
  };
  struct PS {
    const char* name;
    d3dl::ComPtr<d3dl::PixelShader> Shaders::*member;
  };
  static constexpr VS kVertex[] = {{"PostProcessDynamic_FullScreenVS", &Shaders::dynamicVS},
                                   {"PostProcess_FullScreenVS", &Shaders::fullVS}};
  static constexpr PS kPixel[] = {
      {"PostProcessDynamic_ClearPS", &Shaders::clear},
      {"PostProcessDynamic_ClearVelocityPS", &Shaders::clearVelocity},
      {"PostProcessDynamic_MotionBlurPS", &Shaders::motionBlur},
      {"PostProcess_ClearPS", &Shaders::fullClear},
      {"PostProcess_ClearVelocityPS", &Shaders::fullClearVelocity},
      {"PostProcess_MotionBlurPS", &Shaders::fullMotionBlur},
      {"UpscaleSpatial_SecondaryPS", &Shaders::secondary},
      {"UpscaleSpatial_SharpenPS", &Shaders::sharpen},
  };
};

FramePasses::FramePasses() = default;
FramePasses::~FramePasses() = default;

bool FramePasses::Init(d3dl::Device* device, const ShaderLibrary& shaders, FrameProfiler* profiler,
                       std::string* error) {
  m_Device = device;
  m_Profiler = profiler;
  size_t compiled = 0;
  if (!LoadShaders(shaders, false, error, &compiled)) return false;
  d3dl::BUFFER_DESC cb;
  cb.ByteWidth = sizeof(DynamicConstants);
  cb.Usage = d3dl::USAGE_DYNAMIC;
  cb.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  cb.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  d3dl::SAMPLER_DESC point;
  point.Filter = d3dl::FILTER_MIN_LINEAR_MAG_MIP_POINT;
  point.MinLOD = 0.0f;  // the original's zeroed descriptions
  point.ComparisonFunc = d3dl::COMPARISON_ALWAYS;
  d3dl::SAMPLER_DESC linear = point;
  linear.Filter = d3dl::FILTER_MIN_MAG_MIP_LINEAR;
  // The original's three: point (which filters on minification), linear and
  // linear-wrap (noise and the cubic lookup).
  d3dl::SAMPLER_DESC wrap = linear;
  wrap.AddressU = wrap.AddressV = wrap.AddressW = d3dl::TEXTURE_ADDRESS_WRAP;
  d3dl::DEPTH_STENCIL_DESC nd;
  nd.DepthEnable = 0;
  nd.DepthWriteMask = d3dl::DEPTH_WRITE_MASK_ZERO;
  d3dl::RASTERIZER_DESC rd;
  rd.CullMode = d3dl::CULL_NONE;
  d3dl::BUFFER_DESC ucb = cb;
  ucb.ByteWidth = sizeof(UpscaleConstants);
  if (d3dl::FAILED(device->CreateBuffer(&cb, nullptr, m_CB.GetAddressOf())) ||
      d3dl::FAILED(device->CreateBuffer(&ucb, nullptr, m_UpscaleCB.GetAddressOf())) ||
      d3dl::FAILED(device->CreateSamplerState(&point, m_SamplerPoint.GetAddressOf())) ||
      d3dl::FAILED(device->CreateSamplerState(&linear, m_SamplerLinear.GetAddressOf())) ||
      d3dl::FAILED(device->CreateSamplerState(&wrap, m_SamplerLinearWrap.GetAddressOf())) ||
      d3dl::FAILED(device->CreateDepthStencilState(&nd, m_NoDepth.GetAddressOf())) ||
      d3dl::FAILED(device->CreateRasterizerState(&rd, m_NoCull.GetAddressOf()))) {
    *error = "cannot create the post-processing states";
    return false;
  }
  if (d3dl::FAILED(m_CubicLookup.Create(device)) || d3dl::FAILED(m_Noise.Create(device))) {
    *error = "cannot create the lookup/noise textures";
    return false;
  }
  m_Compute = std::make_unique<ComputeUpscale>();
  std::string computeUnavailable;  // then its Record declines, with a notice, and Scale records pixel shaders
  m_Compute->Init(device, shaders, &computeUnavailable);
  return m_ZoomBox.Init(device, shaders, error);
}

bool FramePasses::LoadShaders(const ShaderLibrary& lib, bool fromSource, std::string* error, size_t* compiled) {
  auto next = std::make_unique<Shaders>();
  *compiled = 0;
  for (const Shaders::VS& v : Shaders::kVertex) {
    bool c = false;
    if (!lib.CreateVertexShader(m_Device, v.name, fromSource, ((*next).*v.member).GetAddressOf(), nullptr, error, &c))
      return false;
    *compiled += c;
  }
  for (const Shaders::PS& p : Shaders::kPixel) {
    bool c = false;
    if (!lib.CreatePixelShader(m_Device, p.name, fromSource, ((*next).*p.member).GetAddressOf(), error, &c))
      return false;
    *compiled += c;
  }
  for (int f = 0; f < int(Filter::Count); ++f) {
    const FilterInfo& info = GetFilterInfo(Filter(f));
    for (const char* name : {info.shader, info.fastShader}) {
      if (!name || next->resolve.count(name)) continue;
      bool c = false;
      if (!lib.CreatePixelShader(m_Device, name, fromSource, next->resolve[name].GetAddressOf(), error, &c))
        return false;
      *compiled += c;
    }
  }
  size_t computeCompiled = 0;
  if (m_Compute && !m_Compute->LoadShaders(lib, fromSource, error, &computeCompiled)) return false;
  *compiled += computeCompiled;
  m_Shaders = std::move(next);  // all loaded: F4 keeps the old set on any error
  return true;
}

void FramePasses::Release() {
  if (m_Compute) m_Compute->Release();
  m_ZoomBox.Release();
  m_CubicLookup.Release();
  m_Noise.Release();
  m_Shaders.reset();
  m_CB = nullptr;
  m_UpscaleCB = nullptr;
  m_SamplerPoint = m_SamplerLinear = m_SamplerLinearWrap = nullptr;
  m_NoDepth = nullptr;
  m_NoCull = nullptr;
}

void FramePasses::SetConstants(d3dl::DeviceContext* ctx, const void* data, size_t size) {
  d3dl::MAPPED_SUBRESOURCE m;
  if (d3dl::SUCCEEDED(ctx->Map(m_CB.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &m))) {
    std::memcpy(m.pData, data, size);
    ctx->Unmap(m_CB.Get(), 0);
  }
}

void FramePasses::DrawFullScreen(d3dl::DeviceContext* ctx, d3dl::VertexShader* vs, d3dl::PixelShader* ps) {
  ctx->IASetInputLayout(nullptr);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  ctx->RSSetState(m_NoCull.Get());
  ctx->OMSetDepthStencilState(m_NoDepth.Get(), 0);
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  ctx->VSSetShader(vs);
  ctx->VSSetConstantBuffers(0, 1, m_CB.GetAddressOf());
  ctx->PSSetConstantBuffers(0, 1, m_CB.GetAddressOf());
  ctx->PSSetShader(ps);
  ctx->Draw(3, 0);
}

void TemporalHistory::Advance(FrameSetup& s, glm::vec2 ratio, bool symmetric) {
  jitterPrev = jitterCurr;
  ratioPrev = ratioCurr;
  ratioCurr = ratio;
  jitterCurr = glm::vec2(0.f);
  if (s.taa) {
    // The original's pairs move the scene right and up (+x, +y in clip
    // space); in this struct's y-down pixels the y component changes sign.
    static const glm::vec2 kAsymmetric[2] = {{0.0f, 0.0f}, {0.5f, -0.5f}};
    static const glm::vec2 kSymmetric[2] = {{-0.25f, 0.25f}, {0.25f, -0.25f}};
    const glm::vec2 px = (symmetric ? kSymmetric : kAsymmetric)[current];
    jitterCurr = px / glm::vec2(s.sceneViewport.Width, s.sceneViewport.Height);
  }
  if (s.taau) {
    // Halton jitter; held while paused, since the scene then redraws with its last matrices.
    if (!valid) jitterIndex = 0;
    const glm::vec2 px = UpsampleJitter((s.holdJitter ? jitterIndex + kUpsampleJitterLength - 1 : jitterIndex++) %
                                        kUpsampleJitterLength);
    jitterCurr = px / glm::vec2(s.sceneViewport.Width, s.sceneViewport.Height);
    upsampleCurrent = valid ? 1 - upsampleCurrent : 0;
    s.historyCur = upsampleCurrent;
    s.historyPrev = 1 - upsampleCurrent;
    s.historyValid = valid;
  }
  if (!valid) {
    jitterPrev = jitterCurr;
    ratioPrev = ratioCurr;
  }
  s.cur = current;
  s.prev = (s.taa && valid) ? 1 - current : current;
}

void FillConstants(FrameSetup& s, const TemporalHistory& h, glm::vec2 dyn, glm::vec2 bb) {
  constexpr float kClearColor[4] = {0.0f, 0.1f, 0.1f, 1.0f};
  DynamicConstants& dc = s.dc;
  dc = {{h.ratioCurr.x, h.ratioCurr.y}, {h.ratioPrev.x, h.ratioPrev.y}, {h.jitterCurr.x, h.jitterCurr.y},
        {h.jitterPrev.x, h.jitterPrev.y}, {dyn.x, dyn.y}, {1.0f / dyn.x, 1.0f / dyn.y}, {}, {bb.x, bb.y}, {}, 0, {}};
  std::memcpy(dc.clearColor, kClearColor, sizeof kClearColor);
  s.fc = {{bb.x, bb.y}, {1.0f / bb.x, 1.0f / bb.y}, {}, 0, {}};
  std::memcpy(s.fc.clearColor, kClearColor, sizeof kClearColor);
  dc.fixes = s.fc.fixes = s.fixes.bits;
  const glm::vec2 out(s.outputViewport.Width, s.outputViewport.Height);
  const glm::vec2 jitterPx = h.jitterCurr * glm::vec2(s.sceneViewport.Width, s.sceneViewport.Height);
  s.uc = {{out.x, out.y}, {1.0f / out.x, 1.0f / out.y}, {s.taau ? jitterPx.x : 0.0f, s.taau ? jitterPx.y : 0.0f},
          s.historyValid ? 1.0f : 0.0f, kUnsharpAmount, {out.x, out.y}, {1.0f / out.x, 1.0f / out.y},
          {kHistoryWeightStill, kHistoryWeightMoving, kClipGammaStill, kClipGammaMoving},
          {kSampleSigmaStill, kSampleSigmaMoving}, kMotionPixels, 0.0f};
}

glm::vec2 UpsampleJitter(uint32_t index) {
  return glm::vec2(RadicalInverse(index + 1, 2), RadicalInverse(index + 1, 3)) - 0.5f;
}

SceneTargets ChooseSceneTargets(RenderTargetSet& rts, const FrameSetup& s, const BackBuffer& bb) {
  SceneTargets t;
  if (s.dynamic) {
    RenderTarget& colour = s.motionBlur ? rts[RT::ColorDynamic] : rts.Final(s.cur);
    t.rtv[0] = colour.rtv.Get();
    t.colour = colour.texture.Get();
    if (s.motionBlur || s.taa || s.taau) {
      RenderTarget& velocity = rts.Velocity((s.taa && !s.motionBlur) ? s.cur : 0);
      t.rtv[1] = velocity.rtv.Get();
      t.velocity = velocity.texture.Get();
    }
    t.dsv = rts[RT::DepthDynamic].dsv.Get();
  } else {
    t.rtv[0] = s.motionBlur ? rts[RT::ColorFull].rtv.Get() : bb.rtv;
    t.colour = s.motionBlur ? rts[RT::ColorFull].texture.Get() : bb.texture;
    if (s.motionBlur) {
      t.rtv[1] = rts[RT::VelocityFull].rtv.Get();
      t.velocity = rts[RT::VelocityFull].texture.Get();
    }
    t.dsv = rts[RT::DepthFull].dsv.Get();
  }
  t.count = t.rtv[1] ? 2 : 1;
  return t;
}

void FramePasses::Clear(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const SceneTargets& t) {
  // Test aid: mark everything outside the viewport.
  if (s.dynamic && s.markOutside) {
    ctx->ClearRenderTargetView(t.rtv[0], kMarkerColor);
    if (t.rtv[1]) ctx->ClearRenderTargetView(t.rtv[1], kMarkerVelocity);
    ctx->ClearRenderTargetView(rts.Final(s.cur).rtv.Get(), kMarkerColor);
  }
  // None (debug) shows the whole RT. With the fix its final target is zeroed
  // before the scene; the original zeroes it after (MotionBlur).
  if (s.dynamic && KindOf(s.filter) == FilterKind::Debug && s.fixes.Has(Fix::NoneShowsRT)) {
    ctx->ClearRenderTargetView(rts.Final(s.cur).rtv.Get(), kZero);
    CountPass("ClearFinalNone");
  }
  // Depth always with the API (it may be hierarchical).
  ctx->BeginEvent("Clear");
  m_Profiler->Timers().clear.Start(ctx);
  ctx->ClearDepthStencilView(t.dsv, d3dl::CLEAR_DEPTH, 1.0f, 0);
  if (s.psClear) {
    ctx->OMSetRenderTargets(t.count, t.rtv, nullptr);
    ctx->RSSetViewports(1, &s.sceneViewport);
    const bool velocity = t.count == 2;
    if (s.dynamic) {
      SetConstants(ctx, &s.dc, sizeof s.dc);
      DrawFullScreen(ctx, m_Shaders->dynamicVS.Get(),
                     velocity ? m_Shaders->clearVelocity.Get() : m_Shaders->clear.Get());
    } else {
      SetConstants(ctx, &s.fc, sizeof s.fc);
      DrawFullScreen(ctx, m_Shaders->fullVS.Get(),
                     velocity ? m_Shaders->fullClearVelocity.Get() : m_Shaders->fullClear.Get());
    }
    CountPass("ClearPS");
  } else {
    // The API clear covers the whole views, not just the viewport.
    if (t.rtv[1]) ctx->ClearRenderTargetView(t.rtv[1], kZero);
    ctx->ClearRenderTargetView(t.rtv[0], s.dc.clearColor);
    CountPass("ClearAPI");
  }
  m_Profiler->Timers().clear.Stop(ctx);
  ctx->EndEvent();
}

void FramePasses::Scene(d3dl::DeviceContext* ctx, const FrameSetup& s, const SceneTargets& t, drr::Scene& scene,
                        const SceneRenderParams& params) {
  ctx->BeginEvent("Scene");
  m_Profiler->Timers().scene.Start(ctx);
  ctx->OMSetRenderTargets(t.count, t.rtv, t.dsv);
  ctx->RSSetViewports(1, &s.sceneViewport);
  scene.Render(ctx, params);
  m_Profiler->Timers().scene.Stop(ctx);
  ctx->EndEvent();
  CountPass("Scene");
}

void FramePasses::MotionBlur(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                             const BackBuffer& bb) {
  m_Profiler->Timers().postP.Start(ctx);
  // None (debug): the original zeroes the final target here, after the scene
  // drew into it (so without motion blur None shows black; fix none-shows-rt).
  if (s.dynamic && KindOf(s.filter) == FilterKind::Debug && !s.fixes.Has(Fix::NoneShowsRT)) {
    ctx->ClearRenderTargetView(rts.Final(s.cur).rtv.Get(), kZero);
    CountPass("ClearFinalNone");
  }
  if (s.motionBlur) {
    ctx->BeginEvent("MotionBlur");
    // Into the final target (dynamic) or the back buffer (full resolution).
    d3dl::RenderTargetView* rtv = s.dynamic ? rts.Final(s.cur).rtv.Get() : bb.rtv;
    ctx->OMSetRenderTargets(1, &rtv, nullptr);
    ctx->RSSetViewports(1, &s.sceneViewport);
    if (s.dynamic) SetConstants(ctx, &s.dc, sizeof s.dc);
    else SetConstants(ctx, &s.fc, sizeof s.fc);
    const RenderTarget& colour = rts[s.dynamic ? RT::ColorDynamic : RT::ColorFull];
    const RenderTarget& velocity = rts[s.dynamic ? RT::VelocityDynamic0 : RT::VelocityFull];
    d3dl::ShaderResourceView* srv[3] = {colour.srv.Get(), nullptr, velocity.srv.Get()};
    ctx->PSSetShaderResources(0, 3, srv);
    d3dl::SamplerState* samplers[2] = {m_SamplerPoint.Get(), m_SamplerLinear.Get()};
    ctx->PSSetSamplers(0, 2, samplers);
    if (s.dynamic) DrawFullScreen(ctx, m_Shaders->dynamicVS.Get(), m_Shaders->motionBlur.Get());
    else DrawFullScreen(ctx, m_Shaders->fullVS.Get(), m_Shaders->fullMotionBlur.Get());
    CountPass(s.dynamic ? "MotionBlurDynamic" : "MotionBlurFull");
    UnbindPixelSRVs(ctx);
    ctx->EndEvent();
  }
  m_Profiler->Timers().postP.Stop(ctx);
}

// The resolve filter's shader; the fast TAA variants read the velocity that
// motion blur left in the colour's alpha.
d3dl::PixelShader* FramePasses::ResolveShader(const FrameSetup& s, const char** pass) const {
  const FilterInfo& info = GetFilterInfo(s.filter);
  const bool fast = s.motionBlur && info.fastShader;
  *pass = fast ? info.fastPass : info.pass;
  return m_Shaders->resolve.at(fast ? info.fastShader : info.shader).Get();
}

void FramePasses::Scale(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const BackBuffer& bb) {
  m_Profiler->Timers().scale.Start(ctx);
  if (s.dynamic && !(s.computeUpscale && m_Compute->Record(ctx, s, rts, bb, m_Profiler))) {
    d3dl::RenderTargetView* out = s.secondary ? rts[RT::UpscaleOutput].rtv.Get() : bb.rtv;
    if (s.taau) {
      TemporalUpsample(ctx, s, rts, bb);
    } else if (HasSharpenPass(s.filter)) {
      Resolve(ctx, s, rts, rts[RT::UpscaleSharpenInput].rtv.Get());
      Sharpen(ctx, s, rts, out);
    } else {
      Resolve(ctx, s, rts, out);
    }
    if (s.secondary) SecondaryUpscale(ctx, s, rts, bb);
  }
  m_Profiler->Timers().scale.Stop(ctx);
}

// The resolve filter into target (the back buffer, or the secondary upscale's source).
void FramePasses::Resolve(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                          d3dl::RenderTargetView* target) {
  ctx->BeginEvent("Scale");
  ctx->OMSetRenderTargets(1, &target, nullptr);
  ctx->RSSetViewports(1, &s.outputViewport);
  DynamicConstants rc = s.dc;
  const FilterInfo& filter = GetFilterInfo(s.filter);
  if (filter.kind == FilterKind::Debug) rc.ratioCurr[0] = rc.ratioCurr[1] = rc.ratioPrev[0] = rc.ratioPrev[1] = 1.0f;
  if (filter.noisePerFrame) {
    // The original draws a new offset (two rand() calls) each Noise frame.
    const auto offset = m_Noise.NextOffset();
    rc.noiseOffset[0] = offset[0];
    rc.noiseOffset[1] = offset[1];
  }
  const int cur = s.pausedSwap ? s.prev : s.cur, prev = s.pausedSwap ? s.cur : s.prev;
  if (s.pausedSwap) {
    std::swap(rc.ratioCurr, rc.ratioPrev);
    std::swap(rc.jitterCurr, rc.jitterPrev);
  }
  SetConstants(ctx, &rc, sizeof rc);
  SetUpscaleConstants(ctx, s.uc);
  const bool velocityTAA = s.taa && !s.motionBlur;
  d3dl::ShaderResourceView* srv[6] = {rts.Final(cur).srv.Get(),
                                      s.taa ? rts.Final(prev).srv.Get() : nullptr,
                                      velocityTAA ? rts.Velocity(cur).srv.Get() : nullptr,
                                      velocityTAA ? rts.Velocity(prev).srv.Get() : nullptr,
                                      m_Noise.GetSRV(),
                                      m_CubicLookup.GetSRV()};
  ctx->PSSetShaderResources(0, 6, srv);
  d3dl::SamplerState* samplers[3] = {
      filter.linearSampler ? m_SamplerLinear.Get() : m_SamplerPoint.Get(), m_SamplerLinear.Get(),
      m_SamplerLinearWrap.Get()};
  ctx->PSSetSamplers(0, 3, samplers);
  const char* pass = nullptr;
  d3dl::PixelShader* ps = ResolveShader(s, &pass);
  DrawFullScreen(ctx, m_Shaders->dynamicVS.Get(), ps);
  UnbindPixelSRVs(ctx);
  CountPass(pass);
  ctx->EndEvent();
}

// Contrast-limited sharpening of the edge-adaptive upscale's output.
void FramePasses::Sharpen(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                          d3dl::RenderTargetView* target) {
  ctx->BeginEvent("Sharpen");
  ctx->OMSetRenderTargets(1, &target, nullptr);
  ctx->RSSetViewports(1, &s.outputViewport);
  SetConstants(ctx, &s.dc, sizeof s.dc);
  SetUpscaleConstants(ctx, s.uc);
  d3dl::ShaderResourceView* source = rts[RT::UpscaleSharpenInput].srv.Get();
  ctx->PSSetShaderResources(0, 1, &source);
  DrawFullScreen(ctx, m_Shaders->dynamicVS.Get(), m_Shaders->sharpen.Get());
  UnbindPixelSRVs(ctx);
  CountPass("Sharpen");
  ctx->EndEvent();
}

void FramePasses::SetUpscaleConstants(d3dl::DeviceContext* ctx, const UpscaleConstants& uc) {
  d3dl::MAPPED_SUBRESOURCE m;
  if (d3dl::SUCCEEDED(ctx->Map(m_UpscaleCB.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &m))) {
    std::memcpy(m.pData, &uc, sizeof uc);
    ctx->Unmap(m_UpscaleCB.Get(), 0);
  }
  ctx->PSSetConstantBuffers(1, 1, m_UpscaleCB.GetAddressOf());
}

// TAAU: this frame's colour, velocity and depth (dynamic) and the last
// history (output size) into the new history and, unless the secondary
// upscale follows, the back buffer in the same draw.
void FramePasses::TemporalUpsample(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                                   const BackBuffer& bb) {
  ctx->BeginEvent("TemporalUpsample");
  d3dl::RenderTargetView* rtv[2] = {rts.UpscaleHistory(s.historyCur).rtv.Get(), bb.rtv};
  ctx->OMSetRenderTargets(s.secondary ? 1 : 2, rtv, nullptr);
  ctx->RSSetViewports(1, &s.outputViewport);
  SetConstants(ctx, &s.dc, sizeof s.dc);
  SetUpscaleConstants(ctx, s.uc);
  d3dl::ShaderResourceView* srv[7] = {rts.Final(s.cur).srv.Get(), rts.UpscaleHistory(s.historyPrev).srv.Get(),
                                      rts.Velocity(0).srv.Get(), nullptr, nullptr, nullptr,
                                      rts[RT::DepthDynamic].srv.Get()};
  ctx->PSSetShaderResources(0, 7, srv);
  d3dl::SamplerState* samplers[3] = {m_SamplerPoint.Get(), m_SamplerLinear.Get(), m_SamplerLinearWrap.Get()};
  ctx->PSSetSamplers(0, 3, samplers);
  const char* pass = nullptr;
  DrawFullScreen(ctx, m_Shaders->dynamicVS.Get(), ResolveShader(s, &pass));
  UnbindPixelSRVs(ctx);
  CountPass(pass);
  ctx->EndEvent();
}

// The static secondary spatial upscale: the primary upscale's output (or
// TAAU's new history) to the back buffer, Catmull-Rom.
void FramePasses::SecondaryUpscale(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts,
                                   const BackBuffer& bb) {
  ctx->BeginEvent("SecondaryUpscale");
  d3dl::RenderTargetView* rtv = bb.rtv;
  ctx->OMSetRenderTargets(1, &rtv, nullptr);
  ctx->RSSetViewports(1, &s.backBufferViewport);
  SetConstants(ctx, &s.dc, sizeof s.dc);
  SetUpscaleConstants(ctx, s.uc);
  d3dl::ShaderResourceView* source =
      s.taau ? rts.UpscaleHistory(s.historyCur).srv.Get() : rts[RT::UpscaleOutput].srv.Get();
  ctx->PSSetShaderResources(0, 1, &source);
  d3dl::SamplerState* samplers[3] = {m_SamplerPoint.Get(), m_SamplerLinear.Get(), m_SamplerLinearWrap.Get()};
  ctx->PSSetSamplers(0, 3, samplers);
  DrawFullScreen(ctx, m_Shaders->dynamicVS.Get(), m_Shaders->secondary.Get());
  UnbindPixelSRVs(ctx);
  CountPass("SecondaryUpscale");
  ctx->EndEvent();
}

void FramePasses::Zoom(d3dl::DeviceContext* ctx, const BackBuffer& bb, float centreX, float centreY) {
  ctx->BeginEvent("ZoomBox");
  ctx->OMSetRenderTargets(0, nullptr, nullptr);
  m_ZoomBox.Render(ctx, bb.texture, bb.rtv, bb.width, bb.height, centreX, centreY);
  ctx->EndEvent();
  CountPass("ZoomBox");
}

}  // namespace drr
