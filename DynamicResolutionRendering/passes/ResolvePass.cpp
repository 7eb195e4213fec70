#include "passes/Passes.h"

namespace drr {

bool LoadFilterShaders(ShaderLoad& load, bool temporalUpsample, FilterShaders* shaders) {
  FilterShaders next;
  for (int i = 0; i < int(Filter::Count); ++i) {
    const FilterInfo& info = GetFilterInfo(Filter(i));
    if ((info.kind == FilterKind::TemporalUpsample) != temporalUpsample) continue;
    for (const char* name : {info.shader, info.fastShader})
      if (name && !next.count(name) && !load.Load({}, {{name, &next[name]}})) return false;
  }
  *shaders = std::move(next);  // all loaded: F4 keeps the old set on any error
  return true;
}

// The filter's shader; the fast variants read the velocity that motion blur
// left in the colour's alpha.
d3dl::PixelShader* FilterShader(const FilterShaders& shaders, const FrameSetup& s) {
  const FilterInfo& info = GetFilterInfo(s.filter);
  return shaders.at(s.motionBlur && info.fastShader ? info.fastShader : info.shader).Get();
}

bool ResolvePass::Init(d3dl::Device* device, std::string* error) {
  if (d3dl::FAILED(m_CubicLookup.Create(device)) || d3dl::FAILED(m_Noise.Create(device))) {
    *error = "cannot create the lookup/noise textures";
    return false;
  }
  return true;
}

bool ResolvePass::LoadShaders(ShaderLoad& load) { return LoadFilterShaders(load, false, &m_Shaders); }

void ResolvePass::Release() {
  m_Shaders.clear();
  m_CubicLookup.Release();
  m_Noise.Release();
}

bool ResolvePass::Record(PassFrame& f) {
  const FrameSetup& s = f.Setup();
  RenderTargetSet& rts = f.RTs();
  // Into the sharpening pass's input, the secondary upscale's source or the back buffer.
  RenderTarget& out = rts[f.plan->Runs(PassId::Sharpen) ? RT::UpscaleSharpenInput : RT::UpscaleOutput];
  Target(f.ctx, f.plan->Runs(PassId::Sharpen) || s.secondary ? out.rtv.Get() : f.backBuffer.rtv, s.outputViewport);
  DynamicConstants rc = s.resolve;
  const FilterInfo& filter = GetFilterInfo(s.filter);
  if (filter.noisePerFrame) {
    // The original draws a new offset (two rand() calls) each Noise frame.
    const auto offset = m_Noise.NextOffset();
    rc.noiseOffset[0] = offset[0];
    rc.noiseOffset[1] = offset[1];
  }
  UploadUpscale(f.ctx, s.uc);
  BindSamplers(f.ctx, filter.linearSampler);
  const bool velocityTAA = s.TAA() && !s.motionBlur;
  DrawDynamic(f.ctx, FilterShader(m_Shaders, s), rc,
              {rts.Final(s.resolveCur).srv.Get(), s.TAA() ? rts.Final(s.resolvePrev).srv.Get() : nullptr,
               velocityTAA ? rts.Velocity(s.resolveCur).srv.Get() : nullptr,
               velocityTAA ? rts.Velocity(s.resolvePrev).srv.Get() : nullptr, m_Noise.GetSRV(),
               m_CubicLookup.GetSRV()});
  return true;
}

}  // namespace drr
