// The deferred renderer's passes (Docs/Deferred.md), in place of the forward
// scene pass when --renderer deferred: spot-light shadow maps (their own
// dynamic scale), the G-buffer (the scene with its materials written, not
// lit), screen-space ambient occlusion at the dynamic resolution, and the
// lighting pass into the scene's colour target, so every pass after the
// scene is the forward path's. DeferredShared holds what they pass on: the
// constants and the comparison sampler; the shadow-map array is a row of the
// render-target table (RT::SpotShadowMaps).
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "passes/FullScreenPass.h"
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

// A spot light's shadow view-projection (right-handed, depth 0..1, as the scene's).
glm::mat4 SpotShadowViewProj(const SceneLight& light);

class DeferredShared {
 public:
  bool Init(d3dl::Device* device, std::string* error);
  void Release();

  // The shadow-map slices in use (none with the placeholder) and the last frame's depth-only draws.
  uint32_t ShadowSlices() const { return m_ShadowedSpots; }
  uint32_t ShadowMapDraws() const { return m_ShadowDraws; }
  float ShadowScaleUsed() const { return m_ShadowScaleUsed; }  // last frame's used fraction of the size

 private:
  friend class ShadowMapPass;
  friend class GBufferPass;
  friend class SSAOPass;
  friend class LightingPass;
  // A new frame: constants zeroed, no shadow drawn yet.
  void BeginFrame();
  // The lighting pass's comparison sampler needs a depth view even when no
  // spot reads it: the table's 1x1 slice, cleared.
  void Placeholder(const PassFrame& f);
  // Everything but the shadow fields, then the upload.
  void FillConstants(const PassFrame& f);
  d3dl::ShaderResourceView* Depth(const PassFrame& f) const;

  DeferredConstants m_Constants{};
  ConstantBuffer<DeferredConstants> m_CB;
  d3dl::ComPtr<d3dl::SamplerState> m_ShadowSampler;
  uint32_t m_ShadowDraws = 0;
  float m_ShadowScaleUsed = 0.0f;
  uint32_t m_ShadowedSpots = 0;  // slices in use (the array keeps a 1x1 placeholder without them)
};

// Each shadowed spot's slice: cleared whole, drawn inside its dynamic
// viewport (the top-left shadowScale of the map), as the scene's RT is.
class ShadowMapPass : public Pass {
 public:
  explicit ShadowMapPass(DeferredShared& shared) : m_Shared(shared) {}

 protected:
  bool Record(PassFrame& f) override;

 private:
  DeferredShared& m_Shared;
};

// The scene's materials into diffuse, specular, normal (and velocity).
class GBufferPass : public Pass {
 public:
  explicit GBufferPass(DeferredShared& shared) : m_Shared(shared) {}

 protected:
  bool Record(PassFrame& f) override;

 private:
  DeferredShared& m_Shared;
};

// The deferred full-screen passes: the deferred constants at b0.
class SSAOPass : public ShaderPass {
 public:
  SSAOPass(FullScreenKit& kit, DeferredShared& shared) : ShaderPass(kit, "Deferred_SSAOPS"), m_Shared(shared) {}

 protected:
  bool Record(PassFrame& f) override;

 private:
  DeferredShared& m_Shared;
};

class LightingPass : public ShaderPass {
 public:
  LightingPass(FullScreenKit& kit, DeferredShared& shared)
      : ShaderPass(kit, "Deferred_LightingPS"), m_Shared(shared) {}

 protected:
  bool Record(PassFrame& f) override;

 private:
  DeferredShared& m_Shared;
};

}  // namespace drr
