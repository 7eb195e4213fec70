// The port's upscalers as compute passes (--upscale-shader compute,
// Docs/Upscaling.md): TAAU, the six r.Upscale.Quality levels, the
// edge-adaptive upscale and its sharpening, and the secondary upscale, each
// a dispatch of 8x8 tiles (Shaders/Upscale*CS.hlsl) whose arithmetic is the
// pixel shaders' (Shaders/Upscale*Math.hlsli). They read the same targets as
// the pixel passes and leave the same results in them. The upscale targets
// (TAAU's history, the secondary upscale's and the sharpening's sources)
// have storage views and are written directly; a target without one (the
// sRGB back buffer, sRGB colour targets) is written through a storage
// scratch texture in a copy-compatible UNORM format, the shader encoding
// what the target's own writes would (sRGB, BGRA order), and the scratch's
// bits are then copied into it.
#pragma once

#include <map>
#include <string>

#include "DeviceResources.h"
#include "FrameProfiler.h"
#include "RenderTargets.h"
#include "ShaderLibrary.h"
#include "d3dl/D3DLike.h"

namespace drr {

struct DynamicConstants;
struct FrameSetup;
struct UpscaleConstants;

class ComputeUpscale {
 public:
  // Loads the compute shaders and tries the scratch formats; false (with the
  // reason in *whyNot) when the device cannot run them, and Record then
  // declines every frame.
  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* whyNot);
  // F4: recompiles from source; keeps the old set on any error.
  bool LoadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error, size_t* compiled);
  void Release();

  // Records the frame's upscale passes (Scale's: TAAU or the spatial filter,
  // the sharpening, the secondary upscale). False when the compute path is
  // unavailable: the caller then records the pixel passes; the first such
  // frame prints a one-line notice. The passes are counted in profiler
  // under the pixel passes' names.
  bool Record(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const BackBuffer& bb,
              FrameProfiler* profiler);

 private:
  // A storage texture a dispatch writes for a target without a storage view.
  struct Scratch {
    d3dl::ComPtr<d3dl::Texture2D> texture;
    d3dl::ComPtr<d3dl::UnorderedAccessView> uav;
  };
  // Where a dispatch's result goes: the target's storage view, or else the
  // scratch slot that holds it first (re-made at the target's size) and the
  // target the scratch is copied into.
  struct Destination {
    d3dl::Texture2D* target = nullptr;
    Scratch* scratch = nullptr;
    d3dl::UnorderedAccessView* storage = nullptr;
    bool written = true;  // false: bound but not written (TAAU's image before the secondary upscale)
  };
  static Destination ToTarget(RenderTarget& rt, Scratch* scratch);
  bool CreateStates(d3dl::Device* device);
  // slot holds a storage texture of w x h in format (re-created when it differs).
  bool MakeScratch(Scratch& slot, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT format);
  // One dispatch over the first destination's size: constants (the frame's,
  // uc for the upscale ones), t0.. = srvs, u0.. = the destinations' storage
  // views or scratches; then each scratch is copied into its target.
  void Dispatch(d3dl::DeviceContext* ctx, const char* shader, const FrameSetup& s, const UpscaleConstants& uc,
                d3dl::ShaderResourceView* const* srvs, uint32_t srvCount, const Destination* out, uint32_t outCount);
  // The compute shader `name`, or its version without the tile when the
  // viewport has more texels per output pixel than the tile has room for.
  d3dl::ComputeShader* ShaderFor(const std::string& name, const DynamicConstants& dc,
                                 const UpscaleConstants& uc) const;
  void Temporal(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const BackBuffer& bb);
  void Spatial(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const Destination& out);
  void Sharpen(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const Destination& out);
  void Secondary(d3dl::DeviceContext* ctx, const FrameSetup& s, RenderTargetSet& rts, const BackBuffer& bb);

  d3dl::Device* m_Device = nullptr;
  FrameProfiler* m_Profiler = nullptr;  // this frame's (Record)
  std::string m_Unavailable;  // why the compute path cannot run ("" when it can)
  bool m_NoticePrinted = false;
  std::map<std::string, d3dl::ComPtr<d3dl::ComputeShader>> m_Shaders;  // by shader name
  d3dl::ComPtr<d3dl::Buffer> m_DynamicCB, m_UpscaleCB, m_ComputeCB;
  d3dl::ComPtr<d3dl::SamplerState> m_Linear;
  Scratch m_History, m_Output, m_Final;  // TAAU's history; output-size and back-buffer-size colour
};

}  // namespace drr
