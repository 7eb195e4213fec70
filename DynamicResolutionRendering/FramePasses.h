// The passes of the original's OnD3D11FrameRender, one function each, in
// frame order: clear, scene, motion blur, scale (the resolve filters), zoom
// box. They read the frame's decisions (FrameSetup) and the render-target
// table; the coordinator (DynamicResolutionRendering.cpp) makes the decisions.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "DeviceResources.h"
#include "FrameProfiler.h"
#include "Options.h"
#include "RenderTargets.h"
#include "ShaderLibrary.h"
#include "TexGenUtils.h"
#include "ZoomBox.h"
#include "d3dl/D3DLike.h"
#include "scene/Scene.h"

namespace drr {

// Constants of PostProcessDynamic.hlsl (cbPostProcessDynamic).
struct DynamicConstants {
  float ratioCurr[2], ratioPrev[2];
  float jitterCurr[2], jitterPrev[2];
  float dynSize[2], invDynSize[2];
  float noiseOffset[2], backBufferSize[2];
  float clearColor[4];
  uint32_t fixes;  // FixSet bits (Shaders/FixList.hlsli)
  uint32_t pad[3];
};
static_assert(sizeof(DynamicConstants) == 96);

// Constants of PostProcess.hlsl (cbPostProcess), the full-resolution path.
struct FullConstants {
  float size[2], invSize[2];
  float clearColor[4];
  uint32_t fixes;  // FixSet bits (Shaders/FixList.hlsli)
  float pad[7];
};
static_assert(sizeof(FullConstants) == 64);

// Constants of the upscalers (Shaders/UpscaleCommon.hlsli, cbUpscale at b1).
struct UpscaleConstants {
  float outputSize[2], invOutputSize[2];
  float jitterPx[2];      // TAAU: this frame's jitter in dynamic pixels (y down)
  float historyValid;     // TAAU: 0 on a reset
  float sharpness;        // unsharp amount of Directional and Gaussian Unsharp
  float sourceSize[2], invSourceSize[2];  // the secondary upscale's source
  float temporalParams[4];  // max history weight still / moving, clip gamma still / moving
  // TAAU: a sample's weight falls as (1 - d^2 / (2.2 sigma)^2)^2, d in output
  // pixels, sigma still / moving; and the output pixels per frame counted as fully moving.
  float sampleSigma[2];
  float motionPixels;
  float pad;
};
static_assert(sizeof(UpscaleConstants) == 80);

// TAAU's sub-pixel jitter: Halton(2, 3) points 1..kUpsampleJitterLength,
// centred on 0 (dynamic pixels, each axis in (-0.5, 0.5)).
constexpr uint32_t kUpsampleJitterLength = 16;
glm::vec2 UpsampleJitter(uint32_t index);

// What the coordinator decided for this frame.
struct FrameSetup {
  bool dynamic = true, taa = false, motionBlur = true, psClear = true, markOutside = false;
  Filter filter = Filter::TAA;
  FixSet fixes;
  int cur = 0, prev = 0;  // final/velocity targets written and read as history
  // The original's paused TAA with target 1 current: the resolve reads target 0
  // as current and 1 as history, with their jitters and ratios swapped.
  bool pausedSwap = false;
  d3dl::VIEWPORT sceneViewport{}, backBufferViewport{};
  DynamicConstants dc{};
  FullConstants fc{};
  // Upscaling (Docs/Upscaling.md). outputViewport: what the primary upscale
  // (spatial or TAAU) writes, the back buffer's unless the secondary upscale runs.
  bool taau = false, secondary = false, holdJitter = false;
  int historyCur = 0, historyPrev = 0;  // TAAU's output-resolution history pair
  bool historyValid = false;
  bool computeUpscale = false;  // the upscalers as compute passes (ComputeUpscale.h)
  d3dl::VIEWPORT outputViewport{};
  UpscaleConstants uc{};
};

// Where the scene draws (colour, velocity when needed, depth).
struct SceneTargets {
  d3dl::RenderTargetView* rtv[2] = {nullptr, nullptr};
  uint32_t count = 1;
  d3dl::DepthStencilView* dsv = nullptr;
  d3dl::Texture2D* colour = nullptr;
  d3dl::Texture2D* velocity = nullptr;
};
// The TAA ping-pong: which final/velocity target this frame writes, whether
// the other one holds a frame of the current allocation, and the jitter
// (fractions of the viewport) and RT ratios of this frame and the last.
struct TemporalHistory {
  int current = 0;
  bool valid = false;
  glm::vec2 jitterCurr{0.f}, jitterPrev{0.f}, ratioCurr{1.f}, ratioPrev{1.f};
  // TAAU: which history target this frame writes and the next jitter index;
  // both restart when the history is invalid (valid is shared with TAA).
  int upsampleCurrent = 0;
  uint32_t jitterIndex = 0;
  // This frame's jitter (the original's pair: (0,0)/(0.5,0.5) px, or
  // -0.25/+0.25 px symmetric, in clip-space directions: x right, y up) and
  // ratios; s.cur and s.prev; the viewport is already in s.
  void Advance(FrameSetup& s, glm::vec2 ratio, bool symmetric);
};
// The constants of both post-processing paths for this frame (the fixes from s.fixes).
void FillConstants(FrameSetup& s, const TemporalHistory& h, glm::vec2 dynamicRT, glm::vec2 backBuffer);

SceneTargets ChooseSceneTargets(RenderTargetSet& targets, const FrameSetup& setup, const BackBuffer& bb);

class ComputeUpscale;

class FramePasses {
 public:
  FramePasses();
  ~FramePasses();
  // The passes time themselves and count their runs in profiler.
  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, FrameProfiler* profiler, std::string* error);
  // Loads every post-processing shader, replacing the old set only when all
  // succeeded; *compiled counts those compiled from HLSL.
  bool LoadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error, size_t* compiled);
  void Release();

  void Clear(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const SceneTargets& t);
  void Scene(d3dl::DeviceContext* ctx, const FrameSetup& s, const SceneTargets& t, drr::Scene& scene,
             const SceneRenderParams& params);
  void MotionBlur(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const BackBuffer& bb);
  void Scale(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const BackBuffer& bb);
  void Zoom(d3dl::DeviceContext* ctx, const BackBuffer& bb, float centreX, float centreY);
  // Upscaling passes, run by Scale (Docs/Upscaling.md).
  void TemporalUpsample(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const BackBuffer& bb);
  void SecondaryUpscale(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const BackBuffer& bb);
  void Sharpen(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, d3dl::RenderTargetView* target);

  ZoomBox& GetZoomBox() { return m_ZoomBox; }
  uint64_t GetZoomBoxBytes() const { return m_ZoomBox.Bytes(); }

 private:
  struct Shaders;  // FramePasses.cpp: the post shaders, by name
  void SetConstants(d3dl::DeviceContext* ctx, const void* data, size_t size);
  void DrawFullScreen(d3dl::DeviceContext* ctx, d3dl::VertexShader* vs, d3dl::PixelShader* ps);
  d3dl::PixelShader* ResolveShader(const FrameSetup& s, const char** pass) const;
  void Resolve(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, d3dl::RenderTargetView* target);
  void SetUpscaleConstants(d3dl::DeviceContext* ctx, const UpscaleConstants& uc);
  void CountPass(const char* name) { m_Profiler->CountPass(name); }

  d3dl::Device* m_Device = nullptr;
  std::unique_ptr<Shaders> m_Shaders;
  d3dl::ComPtr<d3dl::Buffer> m_CB, m_UpscaleCB;
  d3dl::ComPtr<d3dl::SamplerState> m_SamplerPoint, m_SamplerLinear, m_SamplerLinearWrap;
  d3dl::ComPtr<d3dl::DepthStencilState> m_NoDepth;
  d3dl::ComPtr<d3dl::RasterizerState> m_NoCull;
  CubicFilterLookupTable m_CubicLookup;
  NoiseTexture m_Noise;
  ZoomBox m_ZoomBox;
  FrameProfiler* m_Profiler = nullptr;
  std::unique_ptr<ComputeUpscale> m_Compute;  // Scale's passes as compute when FrameSetup::computeUpscale
};

}  // namespace drr
