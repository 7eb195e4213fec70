// The passes of the frame, one class each, in frame order; each is defined in
// its own file of this folder (named after the class). The deferred ones
// share DeferredShared (their constants and the shadow maps).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "TexGenUtils.h"
#include "passes/Deferred.h"
#include "passes/FullScreenPass.h"

namespace drr {

// Test aid: everything outside the viewport marked (magenta, a huge velocity).
class MarkOutsidePass : public Pass {
 protected:
  bool Record(PassFrame& f) override;
};

// None (debug) shows the whole RT: its final target zeroed.
class ClearFinalNonePass : public Pass {
 protected:
  bool Record(PassFrame& f) override;
};

// Depth with the API (it may be hierarchical); colour and velocity with a
// full-screen pixel shader (ClearPS) or the API (ClearAPI).
class ClearPass : public FullScreenPass {
 public:
  using FullScreenPass::FullScreenPass;
  bool LoadShaders(ShaderLoad& load) override;
  void Release() override;

 protected:
  bool Record(PassFrame& f) override;

 private:
  d3dl::ComPtr<d3dl::PixelShader> m_Clear, m_ClearVelocity, m_FullClear, m_FullClearVelocity;
};

// The forward scene into colour (+ velocity) and depth.
class ScenePass : public Pass {
 protected:
  bool Record(PassFrame& f) override;
};

class MotionBlurPass : public FullScreenPass {
 public:
  using FullScreenPass::FullScreenPass;
  bool LoadShaders(ShaderLoad& load) override;
  void Release() override;

 protected:
  bool Record(PassFrame& f) override;

 private:
  d3dl::ComPtr<d3dl::PixelShader> m_Dynamic, m_Full;
};

// The filters' shaders by name (ResolveFilters.cpp), of one kind or all others.
using FilterShaders = std::map<std::string, d3dl::ComPtr<d3dl::PixelShader>>;
bool LoadFilterShaders(ShaderLoad& load, bool temporalUpsample, FilterShaders* shaders);
d3dl::PixelShader* FilterShader(const FilterShaders& shaders, const FrameSetup& s);

// The resolve filter (spatial or the original's TAA) into the back buffer,
// the sharpening pass's input or the secondary upscale's source.
class ResolvePass : public FullScreenPass {
 public:
  using FullScreenPass::FullScreenPass;
  bool Init(d3dl::Device* device, std::string* error) override;
  bool LoadShaders(ShaderLoad& load) override;
  void Release() override;

 protected:
  bool Record(PassFrame& f) override;

 private:
  FilterShaders m_Shaders;
  CubicFilterLookupTable m_CubicLookup;
  NoiseTexture m_Noise;
};

// TAAU: this frame's colour, velocity and depth and the last history into
// the new history and, unless the secondary upscale follows, the back buffer.
class TemporalUpsamplePass : public FullScreenPass {
 public:
  using FullScreenPass::FullScreenPass;
  bool LoadShaders(ShaderLoad& load) override;
  void Release() override { m_Shaders.clear(); }

 protected:
  bool Record(PassFrame& f) override;

 private:
  FilterShaders m_Shaders;
};

// Contrast-limited sharpening of the edge-adaptive upscale's output.
class SharpenPass : public ShaderPass {
 public:
  explicit SharpenPass(FullScreenKit& kit) : ShaderPass(kit, "UpscaleSpatial_SharpenPS") {}

 protected:
  bool Record(PassFrame& f) override;
};

// The static secondary spatial upscale (Catmull-Rom) to the back buffer.
class SecondaryUpscalePass : public ShaderPass {
 public:
  explicit SecondaryUpscalePass(FullScreenKit& kit) : ShaderPass(kit, "UpscaleSpatial_SecondaryPS") {}

 protected:
  bool Record(PassFrame& f) override;
};

// The panel and the text at back-buffer resolution (PassFrame::gui).
class GuiPass : public Pass {
 protected:
  bool Record(PassFrame& f) override { return f.gui && f.gui(f.ctx); }
};

}  // namespace drr
