// The render targets of the sample, as one table: which exist in which mode
// (dynamic or full resolution, motion blur, TAA), their names (the original's
// g_* globals), formats and sizes. Allocation, release, the report and the
// GUI read the same table.
#pragma once

#include <cstdint>

#include "d3dl/D3DLike.h"

namespace drr {

// A texture with the views its bind flags allow: colour formats get an RTV
// and an SRV, D32_FLOAT a DSV, R32_TYPELESS (depth read by TAAU) a DSV and an
// R32_FLOAT SRV.
struct RenderTarget {
  d3dl::ComPtr<d3dl::Texture2D> texture;
  d3dl::ComPtr<d3dl::RenderTargetView> rtv;
  d3dl::ComPtr<d3dl::ShaderResourceView> srv;
  d3dl::ComPtr<d3dl::DepthStencilView> dsv;
  uint32_t width = 0, height = 0;
  d3dl::DXGI_FORMAT format = d3dl::DXGI_FORMAT_UNKNOWN;

  d3dl::HRESULT Create(d3dl::Device* device, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT fmt, const char* name);
  void Release();
  bool Valid() const { return texture.Get() != nullptr; }
  uint64_t Bytes() const;
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
  Count
};

// How a target is sized: as the dynamic RT (DynamicResolution's oversized
// RT), the back buffer, or the primary upscale's output (the back buffer's
// times the secondary screen percentage).
enum class SizeRule { Dynamic, Full, Output };

// What decides which targets exist and their sizes; a change re-allocates.
struct RenderTargetPlan {
  bool dynamic = false, superSampling = false, motionBlur = false, taa = false;
  bool srgbColour = false;  // fix srgb-targets: sRGB colour targets instead of the original's UNORM
  uint32_t backBufferW = 0, backBufferH = 0;
  // Upscaling (Docs/Upscaling.md): TAAU on, and the output size of the primary
  // upscale (the back buffer's times the secondary screen percentage).
  bool taau = false, sharpenPass = false;
  uint32_t outputW = 0, outputH = 0;
  bool deferred = false, ssao = false;  // --renderer deferred; its SSAO
  bool Secondary() const { return outputW != 0 && (outputW != backBufferW || outputH != backBufferH); }
  void Size(SizeRule rule, uint32_t dynW, uint32_t dynH, uint32_t* w, uint32_t* h) const;
  bool operator==(const RenderTargetPlan&) const = default;
};

// A row of the target table (RenderTargets.cpp).
struct RenderTargetRow {
  const char* name;  // the original's g_* global
  d3dl::DXGI_FORMAT format;
  SizeRule size;
  bool (*needed)(const RenderTargetPlan& plan);
};

class RenderTargetSet {
 public:
  // Creates the targets the plan needs: dynamic ones at dynW x dynH (the
  // oversized RT of DynamicResolution), full ones at the back-buffer size.
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
  // reads (Needed), and the zoom box's copy only while it is shown.
  static uint64_t OriginalBytes(uint32_t backW, uint32_t backH, uint32_t dynW, uint32_t dynH);

  static const char* Name(RT rt);  // "g_FinalRTDynamic[0]"
  static d3dl::DXGI_FORMAT Format(RT rt, bool srgbColour = false);
  static const RenderTargetRow& Row(RT rt);
  // Whether the plan needs rt: its row's test.
  static bool Needed(RT rt, const RenderTargetPlan& plan);

 private:
  RenderTarget m_Targets[int(RT::Count)];
  RenderTargetPlan m_Plan;
};

}  // namespace drr
