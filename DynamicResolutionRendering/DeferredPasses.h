// The deferred renderer's passes (Docs/Deferred.md), run in place of
// FramePasses::Scene when --renderer deferred: spot-light shadow maps (their
// own dynamic scale), the G-buffer (the scene with its materials written, not
// lit), screen-space ambient occlusion at the dynamic resolution, and the
// lighting pass into the scene's colour target, so every pass after the scene
// is the forward path's.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "FrameProfiler.h"
#include "FramePasses.h"
#include "RenderTargets.h"
#include "ShaderLibrary.h"
#include "d3dl/D3DLike.h"
#include "scene/Scene.h"

namespace drr {

// Mirrors DeferredLight / cbuffer DeferredConstants in Shaders/DeferredCommon.hlsli.
struct DeferredLight {
  glm::vec4 positionRadius, colorType, directionCos, shadow;
};
constexpr uint32_t kMaxDeferredLights = 32;
constexpr uint32_t kMaxShadowSlices = 4;
struct DeferredConstants {
  glm::mat4 invViewProj, viewProj;
  glm::vec4 eye;
  glm::vec4 lightDiffuse, lightAmbient, lightSpecular, lightDirection;
  glm::vec4 unlitAmbient;
  glm::vec4 viewport, rtSize, ratio;
  glm::vec4 ssao;  // radius, strength, bias, AO target read
  uint32_t counts[4];  // lights, SSAO samples
  glm::vec4 shadow;    // used fraction, 1 / size, compare bias
  DeferredLight lights[kMaxDeferredLights];
  glm::mat4 shadowViewProj[kMaxShadowSlices];
};
static_assert(sizeof(DeferredConstants) == 2 * 64 + 10 * 16 + 16 + 16 + kMaxDeferredLights * 64 + kMaxShadowSlices * 64);

// What the coordinator decided for the deferred part of this frame.
struct DeferredFrame {
  bool ssao = true;
  bool localLights = true;      // the scene's LIGHT entries (and their shadow maps)
  float shadowScale = 1.0f;     // the shadow maps' dynamic scale (ShadowMapScale)
  uint32_t shadowMapSize = 1024;
  glm::vec2 ratio{1.0f};        // viewport / G-buffer size: DynamicResolution's RT scale
};

// A spot light's shadow view-projection (right-handed, depth 0..1, as the scene's).
glm::mat4 SpotShadowViewProj(const SceneLight& light);

class DeferredPasses {
 public:
  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error);
  bool LoadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error);
  void Release();

  // Shadows, G-buffer, SSAO and lighting into t.rtv[0] inside s.sceneViewport
  // (scene timer and pass counts in the profiler).
  void Render(d3dl::DeviceContext* ctx, const FrameSetup& s, const SceneTargets& t, RenderTargetSet& rts,
              Scene& scene, const SceneRenderParams& params, const DeferredFrame& f, FrameProfiler& profiler);

  // The shadow-map array's bytes (a 1x1 placeholder without shadowed spots) and the slices in use.
  uint64_t ShadowMapBytes() const;
  uint32_t ShadowSlices() const { return m_ShadowedSpots; }
  uint32_t ShadowMapDraws() const { return m_ShadowDraws; }  // last frame's depth-only draws
  uint32_t ShadowMapSize() const { return m_ShadowSize; }
  float ShadowScaleUsed() const { return m_ShadowScaleUsed; }  // last frame's used fraction of the size

 private:
  bool EnsureShadowMaps(uint32_t slices, uint32_t size);
  void Shadows(d3dl::DeviceContext* ctx, Scene& scene, const DeferredFrame& f, DeferredConstants& c);
  void FillConstants(const FrameSetup& s, RenderTargetSet& rts, Scene& scene, const SceneRenderParams& params,
                     const DeferredFrame& f, DeferredConstants& c) const;
  void FullScreen(d3dl::DeviceContext* ctx, d3dl::PixelShader* ps);

  d3dl::Device* m_Device = nullptr;
  d3dl::ComPtr<d3dl::VertexShader> m_FullScreenVS;
  d3dl::ComPtr<d3dl::PixelShader> m_SSAO, m_Lighting;
  d3dl::ComPtr<d3dl::Buffer> m_CB;
  d3dl::ComPtr<d3dl::SamplerState> m_ShadowSampler;
  d3dl::ComPtr<d3dl::DepthStencilState> m_NoDepth;
  d3dl::ComPtr<d3dl::RasterizerState> m_NoCull;
  d3dl::ComPtr<d3dl::Texture2D> m_ShadowMaps;
  d3dl::ComPtr<d3dl::ShaderResourceView> m_ShadowSRV;
  d3dl::ComPtr<d3dl::DepthStencilView> m_ShadowDSV[kMaxShadowSlices];
  uint32_t m_ShadowSlices = 0, m_ShadowSize = 0, m_ShadowDraws = 0;
  float m_ShadowScaleUsed = 0.0f;
  uint32_t m_ShadowedSpots = 0;  // slices in use (the array keeps a 1x1 placeholder without them)
};

}  // namespace drr
