#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "passes/Deferred.h"

namespace drr {

namespace {
// SSAO (Shaders/SSAO.hlsl): the disc radius as a fraction of the scene's
// bounding-box diagonal, the strength, the tangent-plane bias (fraction of
// the radius) and the samples per pixel.
constexpr float kSSAORadiusOfScene = 0.012f;
constexpr float kSSAOStrength = 2.0f;
constexpr float kSSAOBias = 0.05f;
constexpr uint32_t kSSAOSamples = 12;
// Spot shadows: the near plane as a fraction of the radius.
constexpr float kShadowNearOfRadius = 0.01f;
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

bool DeferredShared::Init(d3dl::Device* device, std::string* error) {
  d3dl::SAMPLER_DESC cmp;
  cmp.Filter = d3dl::FILTER_COMPARISON_MIN_MAG_LINEAR_MIP_POINT;
  cmp.ComparisonFunc = d3dl::COMPARISON_LESS_EQUAL;
  cmp.MinLOD = 0.0f;
  if (!m_CB.Create(device) || d3dl::FAILED(device->CreateSamplerState(&cmp, m_ShadowSampler.GetAddressOf()))) {
    *error = "cannot create the deferred shading states";
    return false;
  }
  return true;
}

void DeferredShared::Release() {
  m_CB.Release();
  m_ShadowSampler = nullptr;
}

void DeferredShared::BeginFrame() {
  m_Constants = {};
  m_ShadowDraws = 0;
  m_ShadowScaleUsed = 0.0f;
  m_ShadowedSpots = 0;
}

// The RHI's dummy for an unbound slot is a colour format, which the
// depth-compare rule of Vulkan refuses.
void DeferredShared::Placeholder(const PassFrame& f) {
  const RenderTarget& maps = f.RTs()[RT::SpotShadowMaps];
  if (!maps.sliceDsv.empty()) f.ctx->ClearDepthStencilView(maps.sliceDsv[0].Get(), d3dl::CLEAR_DEPTH, 1.0f, 0);
}

d3dl::ShaderResourceView* DeferredShared::Depth(const PassFrame& f) const {
  return f.RTs()[f.Setup().dynamic ? RT::DepthDynamic : RT::DepthFull].srv.Get();
}

void DeferredShared::FillConstants(const PassFrame& f) {
  DeferredConstants& c = m_Constants;
  const SceneRenderParams& p = f.plan->scene;
  const DeferredFrame& d = f.plan->deferredFrame;
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
  const glm::vec2 vp(f.Setup().sceneViewport.Width, f.Setup().sceneViewport.Height);
  const RenderTarget& diffuse = f.RTs()[RT::GBufferDiffuse];
  const glm::vec2 rt(float(diffuse.width), float(diffuse.height));
  c.viewport = glm::vec4(vp, 1.0f / vp);
  c.rtSize = glm::vec4(rt, 1.0f / rt);
  c.ratio = glm::vec4(d.ratio, p.proj[1][1], 0.0f);
  const Scene& scene = *f.sceneData;
  const float diagonal = glm::length(scene.BoundsMax() - scene.BoundsMin());
  c.ssao = glm::vec4(kSSAORadiusOfScene * diagonal, kSSAOStrength, kSSAOBias, d.ssao ? 1.0f : 0.0f);
  const uint32_t slices = f.RTs()[RT::SpotShadowMaps].slices;
  uint32_t count = 0, slice = 0;
  for (const SceneLight& l : scene.Lights()) {
    if (count == kMaxDeferredLights || !d.localLights) break;
    const bool spot = l.type == LightType::Spot;
    const float outer = std::cos(glm::radians(l.angleDeg));
    const float inner = std::cos(glm::radians(l.angleDeg * kSpotInnerOfOuter));
    const float shadowSlice = spot && l.shadow && slice < slices ? float(slice) : -1.0f;
    slice += spot && l.shadow;
    c.lights[count++] = {glm::vec4(l.position, l.radius), glm::vec4(l.color, spot ? 1.0f : 0.0f),
                         glm::vec4(l.direction, outer), glm::vec4(shadowSlice, inner, 0.0f, 0.0f)};
  }
  c.counts[0] = count;
  c.counts[1] = kSSAOSamples;
  m_CB.Upload(f.ctx, c);
}

}  // namespace drr
