#include "DeferredPasses.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

namespace drr {

namespace {
constexpr const char* kFullScreenVS = "PostProcessDynamic_FullScreenVS";
constexpr const char* kSSAOPS = "Deferred_SSAOPS";
constexpr const char* kLightingPS = "Deferred_LightingPS";
// SSAO (Shaders/SSAO.hlsl): the disc radius as a fraction of the scene's
// bounding-box diagonal, the strength, the tangent-plane bias (fraction of
// the radius) and the samples per pixel.
constexpr float kSSAORadiusOfScene = 0.012f;
constexpr float kSSAOStrength = 2.0f;
constexpr float kSSAOBias = 0.05f;
constexpr uint32_t kSSAOSamples = 12;
// Spot shadows: the near plane as a fraction of the radius, and the depth
// compare bias (clip z) on top of the raster's slope bias.
constexpr float kShadowNearOfRadius = 0.01f;
constexpr float kShadowCompareBias = 2e-5f;
// The spot's inner cone, where the falloff to the outer angle starts.
constexpr float kSpotInnerOfOuter = 0.8f;
}  // namespace

glm::mat4 SpotShadowViewProj(const SceneLight& l) {
  const glm::vec3 up = std::abs(l.direction.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::mat4 view = glm::lookAtRH(l.position, l.position + l.direction, up);
  const glm::mat4 proj =
      glm::perspectiveRH_ZO(2.0f * glm::radians(l.angleDeg), 1.0f, l.radius * kShadowNearOfRadius, l.radius);
  return proj * view;
}

bool DeferredPasses::Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error) {
  m_Device = device;
  if (!LoadShaders(shaders, false, error)) return false;
  d3dl::BUFFER_DESC cb;
  cb.ByteWidth = sizeof(DeferredConstants);
  cb.Usage = d3dl::USAGE_DYNAMIC;
  cb.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  cb.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  d3dl::SAMPLER_DESC cmp;
  cmp.Filter = d3dl::FILTER_COMPARISON_MIN_MAG_LINEAR_MIP_POINT;
  cmp.ComparisonFunc = d3dl::COMPARISON_LESS_EQUAL;
  cmp.MinLOD = 0.0f;
  d3dl::DEPTH_STENCIL_DESC nd;
  nd.DepthEnable = 0;
  nd.DepthWriteMask = d3dl::DEPTH_WRITE_MASK_ZERO;
  d3dl::RASTERIZER_DESC rd;
  rd.CullMode = d3dl::CULL_NONE;
  if (d3dl::FAILED(device->CreateBuffer(&cb, nullptr, m_CB.GetAddressOf())) ||
      d3dl::FAILED(device->CreateSamplerState(&cmp, m_ShadowSampler.GetAddressOf())) ||
      d3dl::FAILED(device->CreateDepthStencilState(&nd, m_NoDepth.GetAddressOf())) ||
      d3dl::FAILED(device->CreateRasterizerState(&rd, m_NoCull.GetAddressOf()))) {
    *error = "cannot create the deferred shading states";
    return false;
  }
  return true;
}

bool DeferredPasses::LoadShaders(const ShaderLibrary& lib, bool fromSource, std::string* error) {
  d3dl::ComPtr<d3dl::VertexShader> vs;
  d3dl::ComPtr<d3dl::PixelShader> ssao, lighting;
  if (!lib.CreateVertexShader(m_Device, kFullScreenVS, fromSource, vs.GetAddressOf(), nullptr, error) ||
      !lib.CreatePixelShader(m_Device, kSSAOPS, fromSource, ssao.GetAddressOf(), error) ||
      !lib.CreatePixelShader(m_Device, kLightingPS, fromSource, lighting.GetAddressOf(), error))
    return false;
  m_FullScreenVS = vs;  // all loaded: F4 keeps the old set on any error
  m_SSAO = ssao;
  m_Lighting = lighting;
  return true;
}

void DeferredPasses::Release() {
  m_FullScreenVS = nullptr;
  m_SSAO = m_Lighting = nullptr;
  m_CB = nullptr;
  m_ShadowSampler = nullptr;
  m_NoDepth = nullptr;
  m_NoCull = nullptr;
  for (auto& dsv : m_ShadowDSV) dsv = nullptr;
  m_ShadowSRV = nullptr;
  m_ShadowMaps = nullptr;
  m_ShadowSlices = m_ShadowSize = 0;
}

uint64_t DeferredPasses::ShadowMapBytes() const { return uint64_t(m_ShadowSize) * m_ShadowSize * 4 * m_ShadowSlices; }

// One R32_TYPELESS array: a D32_FLOAT DSV per slice, one R32_FLOAT SRV over all.
bool DeferredPasses::EnsureShadowMaps(uint32_t slices, uint32_t size) {
  if (m_ShadowMaps && m_ShadowSlices == slices && m_ShadowSize == size) return true;
  for (auto& dsv : m_ShadowDSV) dsv = nullptr;
  m_ShadowSRV = nullptr;
  m_ShadowMaps = nullptr;
  m_ShadowSlices = m_ShadowSize = 0;
  d3dl::TEXTURE2D_DESC td;
  td.Width = td.Height = size;
  td.MipLevels = 1;
  td.ArraySize = slices;
  td.Format = d3dl::DXGI_FORMAT_R32_TYPELESS;
  td.BindFlags = d3dl::BIND_DEPTH_STENCIL | d3dl::BIND_SHADER_RESOURCE;
  if (d3dl::FAILED(m_Device->CreateTexture2D(&td, nullptr, m_ShadowMaps.GetAddressOf()))) return false;
  m_ShadowMaps->SetDebugName("g_SpotShadowMaps");
  d3dl::SHADER_RESOURCE_VIEW_DESC sv;
  sv.Format = d3dl::DXGI_FORMAT_R32_FLOAT;
  sv.ViewDimension = d3dl::SRV_DIMENSION_TEXTURE2DARRAY;
  sv.Array = {0, slices};
  if (d3dl::FAILED(m_Device->CreateShaderResourceView(m_ShadowMaps.Get(), &sv, m_ShadowSRV.GetAddressOf())))
    return false;
  for (uint32_t i = 0; i < slices; ++i) {
    d3dl::DEPTH_STENCIL_VIEW_DESC dv;
    dv.Format = d3dl::DXGI_FORMAT_D32_FLOAT;
    dv.ViewDimension = d3dl::DSV_DIMENSION_TEXTURE2DARRAY;
    dv.Array = {i, 1};
    if (d3dl::FAILED(m_Device->CreateDepthStencilView(m_ShadowMaps.Get(), &dv, m_ShadowDSV[i].GetAddressOf())))
      return false;
  }
  m_ShadowSlices = slices;
  m_ShadowSize = size;
  return true;
}

// Each shadowed spot's slice: cleared whole, drawn inside its dynamic
// viewport (the top-left shadowScale of the map), as the scene's RT is.
void DeferredPasses::Shadows(d3dl::DeviceContext* ctx, Scene& scene, const DeferredFrame& f, DeferredConstants& c) {
  m_ShadowDraws = 0;
  m_ShadowScaleUsed = 0.0f;
  m_ShadowedSpots = 0;
  if (f.localLights)
    for (const SceneLight& l : scene.Lights()) m_ShadowedSpots += l.shadow;
  if (m_ShadowedSpots == 0) {
    // The lighting pass's comparison sampler needs a depth view even when no
    // spot reads it: the RHI's dummy for an unbound slot is a colour format,
    // which the depth-compare rule of Vulkan refuses. A cleared 1x1 slice.
    if (EnsureShadowMaps(1, 1)) ctx->ClearDepthStencilView(m_ShadowDSV[0].Get(), d3dl::CLEAR_DEPTH, 1.0f, 0);
    return;
  }
  if (!EnsureShadowMaps(m_ShadowedSpots, f.shadowMapSize)) return;
  const float used = std::max(1.0f, std::floor(f.shadowScale * float(m_ShadowSize)));
  const d3dl::VIEWPORT viewport{0, 0, used, used, 0, 1};
  c.shadow = glm::vec4(used / float(m_ShadowSize), 1.0f / float(m_ShadowSize), kShadowCompareBias, 0.0f);
  m_ShadowScaleUsed = c.shadow.x;
  ctx->BeginEvent("ShadowMaps");
  uint32_t slice = 0;
  for (const SceneLight& l : scene.Lights()) {
    if (!l.shadow) continue;
    c.shadowViewProj[slice] = SpotShadowViewProj(l);
    d3dl::DepthStencilView* dsv = m_ShadowDSV[slice].Get();
    ctx->OMSetRenderTargets(0, nullptr, dsv);
    ctx->ClearDepthStencilView(dsv, d3dl::CLEAR_DEPTH, 1.0f, 0);
    ctx->RSSetViewports(1, &viewport);
    m_ShadowDraws += scene.RenderDepth(ctx, c.shadowViewProj[slice]);
    ++slice;
  }
  ctx->EndEvent();
}

void DeferredPasses::FillConstants(const FrameSetup& s, RenderTargetSet& rts, Scene& scene,
                                   const SceneRenderParams& p, const DeferredFrame& f, DeferredConstants& c) const {
  const glm::mat4 jitter = glm::translate(glm::mat4(1.f), glm::vec3(p.jitterNdc, 0.f));
  c.viewProj = jitter * p.proj * p.view;
  c.invViewProj = glm::inverse(c.viewProj);
  c.eye = glm::vec4(p.shadingEye ? *p.shadingEye : glm::vec3(glm::inverse(p.view)[3]), 1.0f);
  const SceneLightingValues lit = SceneLighting(true);
  c.lightDiffuse = lit.diffuse;
  c.lightAmbient = lit.ambient;
  c.lightSpecular = lit.specular;
  c.lightDirection = lit.directionAndPower;
  c.unlitAmbient = SceneLighting(false).ambient;
  const glm::vec2 vp(s.sceneViewport.Width, s.sceneViewport.Height);
  const RenderTarget& diffuse = rts[RT::GBufferDiffuse];
  const glm::vec2 rt(float(diffuse.width), float(diffuse.height));
  c.viewport = glm::vec4(vp, 1.0f / vp);
  c.rtSize = glm::vec4(rt, 1.0f / rt);
  c.ratio = glm::vec4(f.ratio, p.proj[1][1], 0.0f);
  const float diagonal = glm::length(scene.BoundsMax() - scene.BoundsMin());
  c.ssao = glm::vec4(kSSAORadiusOfScene * diagonal, kSSAOStrength, kSSAOBias, f.ssao ? 1.0f : 0.0f);
  uint32_t count = 0, slice = 0;
  for (const SceneLight& l : scene.Lights()) {
    if (count == kMaxDeferredLights || !f.localLights) break;
    const bool spot = l.type == LightType::Spot;
    const float outer = std::cos(glm::radians(l.angleDeg));
    const float inner = std::cos(glm::radians(l.angleDeg * kSpotInnerOfOuter));
    const float shadowSlice = spot && l.shadow && slice < m_ShadowSlices ? float(slice) : -1.0f;
    slice += spot && l.shadow;
    c.lights[count++] = {glm::vec4(l.position, l.radius), glm::vec4(l.color, spot ? 1.0f : 0.0f),
                         glm::vec4(l.direction, outer), glm::vec4(shadowSlice, inner, 0.0f, 0.0f)};
  }
  c.counts[0] = count;
  c.counts[1] = kSSAOSamples;
}

void DeferredPasses::FullScreen(d3dl::DeviceContext* ctx, d3dl::PixelShader* ps) {
  ctx->IASetInputLayout(nullptr);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  ctx->RSSetState(m_NoCull.Get());
  ctx->OMSetDepthStencilState(m_NoDepth.Get(), 0);
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  ctx->VSSetShader(m_FullScreenVS.Get());
  ctx->PSSetShader(ps);
  ctx->PSSetConstantBuffers(0, 1, m_CB.GetAddressOf());
  ctx->Draw(3, 0);
}

void DeferredPasses::Render(d3dl::DeviceContext* ctx, const FrameSetup& s, const SceneTargets& t,
                            RenderTargetSet& rts, Scene& scene, const SceneRenderParams& params,
                            const DeferredFrame& f, FrameProfiler& profiler) {
  ctx->BeginEvent("Deferred");
  profiler.Timers().scene.Start(ctx);
  DeferredConstants c{};
  Shadows(ctx, scene, f, c);
  if (c.shadow.x > 0) profiler.CountPass("ShadowMaps");
  // G-buffer: diffuse, specular, normal, then the velocity the forward path would write.
  d3dl::RenderTargetView* gbuffer[4] = {rts[RT::GBufferDiffuse].rtv.Get(), rts[RT::GBufferSpecular].rtv.Get(),
                                        rts[RT::GBufferNormal].rtv.Get(), t.rtv[1]};
  ctx->OMSetRenderTargets(t.rtv[1] ? 4 : 3, gbuffer, t.dsv);
  ctx->RSSetViewports(1, &s.sceneViewport);
  SceneRenderParams gp = params;
  gp.gbuffer = true;
  gp.writeVelocity = t.rtv[1] != nullptr;
  scene.Render(ctx, gp);
  profiler.CountPass("GBuffer");
  // The passes below read the depth target: unbind it first.
  FillConstants(s, rts, scene, params, f, c);
  d3dl::MAPPED_SUBRESOURCE map;
  if (d3dl::SUCCEEDED(ctx->Map(m_CB.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &map))) {
    std::memcpy(map.pData, &c, sizeof c);
    ctx->Unmap(m_CB.Get(), 0);
  }
  d3dl::ShaderResourceView* depth = rts[s.dynamic ? RT::DepthDynamic : RT::DepthFull].srv.Get();
  if (f.ssao) {
    ctx->BeginEvent("SSAO");
    d3dl::RenderTargetView* ao = rts[RT::GBufferAO].rtv.Get();
    ctx->OMSetRenderTargets(1, &ao, nullptr);
    ctx->RSSetViewports(1, &s.sceneViewport);
    d3dl::ShaderResourceView* srv[2] = {depth, rts[RT::GBufferNormal].srv.Get()};
    ctx->PSSetShaderResources(0, 2, srv);
    FullScreen(ctx, m_SSAO.Get());
    d3dl::ShaderResourceView* none[2] = {};
    ctx->PSSetShaderResources(0, 2, none);
    profiler.CountPass("SSAO");
    ctx->EndEvent();
  }
  ctx->BeginEvent("Lighting");
  d3dl::RenderTargetView* colour = t.rtv[0];
  ctx->OMSetRenderTargets(1, &colour, nullptr);
  ctx->RSSetViewports(1, &s.sceneViewport);
  d3dl::ShaderResourceView* srv[6] = {rts[RT::GBufferDiffuse].srv.Get(), rts[RT::GBufferSpecular].srv.Get(),
                                      rts[RT::GBufferNormal].srv.Get(),
                                      f.ssao ? rts[RT::GBufferAO].srv.Get() : nullptr, depth, m_ShadowSRV.Get()};
  ctx->PSSetShaderResources(0, 6, srv);
  d3dl::SamplerState* cmp = m_ShadowSampler.Get();
  ctx->PSSetSamplers(0, 1, &cmp);
  FullScreen(ctx, m_Lighting.Get());
  d3dl::ShaderResourceView* none[6] = {};
  ctx->PSSetShaderResources(0, 6, none);
  profiler.CountPass("Lighting");
  ctx->EndEvent();
  profiler.Timers().scene.Stop(ctx);
  ctx->EndEvent();
}

}  // namespace drr
