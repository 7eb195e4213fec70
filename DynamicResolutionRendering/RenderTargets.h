// The render targets of the sample, as one table: which exist in which mode
// (dynamic or full resolution, motion blur, TAA), their names (the original's
// g_* globals), formats and sizes. Allocation, release, the report and the
// GUI read the same table.
#pragma once

#include <cstdint>
#include <vector>

#include "TemporalMode.h"
#include "d3dl/D3DLike.h"

namespace drr {

// How a target is viewed: by its format (colour formats get an RTV and an
// SRV, D32_FLOAT a DSV, R32_TYPELESS, depth read by a pass, a D32_FLOAT DSV
// and an R32_FLOAT SRV); as a depth array (R32_TYPELESS: a D32_FLOAT DSV per
// slice, one R32_FLOAT SRV over the slices); as a copy destination read
// by a shader (an SRV only); or as colour the compute upscalers may also
// write (an RTV, an SRV and, unless the format is sRGB, a UAV).
enum class TargetViews { ByFormat, DepthArray, CopyRead, ColourStorage };

// A texture with the views its TargetViews give.
struct RenderTarget {
  d3dl::ComPtr<d3dl::Texture2D> texture;
  d3dl::ComPtr<d3dl::RenderTargetView> rtv;
  d3dl::ComPtr<d3dl::ShaderResourceView> srv;
  d3dl::ComPtr<d3dl::DepthStencilView> dsv;
  d3dl::ComPtr<d3dl::UnorderedAccessView> uav;  // ColourStorage in a non-sRGB format
  std::vector<d3dl::ComPtr<d3dl::DepthStencilView>> sliceDsv;  // DepthArray: one per slice
  uint32_t width = 0, height = 0;
  uint32_t slices = 0;  // DepthArray: the array's size; 0 otherwise
  d3dl::DXGI_FORMAT format = d3dl::DXGI_FORMAT_UNKNOWN;
  TargetViews views = TargetViews::ByFormat;

  d3dl::HRESULT Create(d3dl::Device* device, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT fmt, const char* name,
                       TargetViews kind = TargetViews::ByFormat, uint32_t arraySlices = 0);
  void Release();
  bool Valid() const { return texture.Get() != nullptr; }
  uint64_t Bytes() const;

 private:
  d3dl::HRESULT CreateViews(d3dl::Device* device);
};

// The original's render targets, in the order the report lists them.
enum class RT : int {
  ColorDynamic,
  DepthDynamic,
  VelocityDynamic0,
  VelocityDynamic1,
  FinalDynamic0,
  FinalDynamic1,
  ColorFull,
  VelocityFull,
  DepthFull,
  // Port additions on the dynamic path, at the output size (Docs/Upscaling.md):
  // the TAAU history pair, and the primary upscale's output ahead of the
  // secondary upscale.
  UpscaleHistory0,
  UpscaleHistory1,
  UpscaleOutput,
  UpscaleSharpenInput,  // the edge-adaptive upscale's output, read by its sharpening pass
  // Deferred shading (Docs/Deferred.md): the G-buffer in the 3DMark 11
  // formats, at the dynamic RT's size on both paths; the scene's depth target
  // becomes R32_TYPELESS (a DSV and an R32_FLOAT SRV) with it.
  GBufferDiffuse,
  GBufferSpecular,
  GBufferNormal,
  GBufferAO,  // written by SSAO; absent with --no-ssao
  // Deferred: the spot lights' shadow maps, one R32_TYPELESS array of a slice
  // per shadowed spot (a cleared 1x1 slice without one: the lighting pass's
  // comparison sampler needs a depth view).
  SpotShadowMaps,
  // The zoom box's copy of the back buffer (its size and format), while it is shown.
  ZoomBoxCopy,
  Count
};

// How a target is sized: as the dynamic RT (DynamicResolution's oversized
// RT), the back buffer, the primary upscale's output (the back buffer's
// times the secondary screen percentage), or fixed by an option whatever the
// back buffer (the shadow maps: the plan's shadowMapSize, square).
enum class SizeRule { Dynamic, Full, Output, Fixed };

// What decides which targets exist and their sizes; a change re-allocates.
struct RenderTargetPlan {
  bool dynamic = false, superSampling = false, motionBlur = false;
  TemporalMode temporal = TemporalMode::None;  // FramePlan::temporal
  bool srgbColour = false;  // fix srgb-targets: sRGB colour targets instead of the original's UNORM
  uint32_t backBufferW = 0, backBufferH = 0;
  // Upscaling (Docs/Upscaling.md): the edge-adaptive sharpening pass, and the
  // output size of the primary upscale (the back buffer's times the secondary
  // screen percentage).
  bool sharpenPass = false;
  uint32_t outputW = 0, outputH = 0;
  bool deferred = false, ssao = false;  // --renderer deferred; its SSAO
  // Deferred: the shadow-map array's slices and size (1 and 1 for the
  // placeholder without shadowed spots; 0 without deferred shading).
  uint32_t shadowSlices = 0, shadowMapSize = 0;
  bool zoomBox = false;  // the zoom box is shown: its copy of the back buffer
  d3dl::DXGI_FORMAT backBufferFormat = d3dl::DXGI_FORMAT_UNKNOWN;
  bool TAA() const { return temporal == TemporalMode::TAA; }
  bool TAAU() const { return temporal == TemporalMode::TAAU; }
  bool Secondary() const { return outputW != 0 && (outputW != backBufferW || outputH != backBufferH); }
  void Size(SizeRule rule, uint32_t dynW, uint32_t dynH, uint32_t* w, uint32_t* h) const;
  bool operator==(const RenderTargetPlan&) const = default;
  // Whether the plans differ at most in the targets a pass rewrites whole
  // every frame (the shadow maps, the zoom box's copy): those are made or
  // freed alone, and no other target, history or controller restarts.
  bool SameButRewrittenEachFrame(const RenderTargetPlan& other) const;
};

// A row of the target table (RenderTargets.cpp).
struct RenderTargetRow {
  const char* name;  // the original's g_* global
  d3dl::DXGI_FORMAT format;  // UNKNOWN: the back buffer's (RenderTargetPlan::backBufferFormat)
  SizeRule size;
  bool (*needed)(const RenderTargetPlan& plan);
  TargetViews views = TargetViews::ByFormat;  // DepthArray: RenderTargetPlan::shadowSlices slices
};

class RenderTargetSet {
 public:
  // Creates the targets the plan needs: dynamic ones at dynW x dynH (the
  // oversized RT of DynamicResolution), full ones at the back-buffer size.
  // A target already there with the same size, format and views is kept;
  // one the plan does not need is released.
  bool Allocate(d3dl::Device* device, const RenderTargetPlan& plan, uint32_t dynW, uint32_t dynH);
  void Release();
  // Zeroes every allocated target (depth to 1). D3D11 on Windows hands out
  // zeroed memory, and the original's resolves read past the viewport into
  // texels no pass has written; a Vulkan image starts undefined.
  void ZeroContents(d3dl::DeviceContext* ctx);
  const RenderTargetPlan& Plan() const { return m_Plan; }  // {} once released

  RenderTarget& operator[](RT rt) { return m_Targets[int(rt)]; }
  const RenderTarget& operator[](RT rt) const { return m_Targets[int(rt)]; }
  RenderTarget& Final(int i) { return (*this)[i ? RT::FinalDynamic1 : RT::FinalDynamic0]; }
  RenderTarget& Velocity(int i) { return (*this)[i ? RT::VelocityDynamic1 : RT::VelocityDynamic0]; }
  RenderTarget& UpscaleHistory(int i) { return (*this)[i ? RT::UpscaleHistory1 : RT::UpscaleHistory0]; }
  uint64_t Bytes() const;
  // What the original allocates for the same back buffer and dynamic RT: all
  // of its targets whatever the mode (g_Color, g_Velocity, DXUT's depth and the
  // zoom box's copy at the back buffer's size; depth, colour, two velocities,
  // two finals at the dynamic size). The port allocates only what the mode
  // reads (Needed), and the zoom box's copy only while it is shown. The
  // original has no shadow maps.
  static uint64_t OriginalBytes(uint32_t backW, uint32_t backH, uint32_t dynW, uint32_t dynH);

  static const char* Name(RT rt);  // "g_FinalRTDynamic[0]"
  // The format the plan gives rt: the row's, sRGB colour with srgb-targets,
  // typeless depth where a pass reads it, the back buffer's for the zoom copy.
  static d3dl::DXGI_FORMAT Format(RT rt, const RenderTargetPlan& plan);
  static const RenderTargetRow& Row(RT rt);
  // Whether the plan needs rt: its row's test.
  static bool Needed(RT rt, const RenderTargetPlan& plan);

 private:
  RenderTarget m_Targets[int(RT::Count)];
  RenderTargetPlan m_Plan;
};

}  // namespace drr
