// The base of the full-screen passes: one triangle over the viewport with no
// depth, no blending and no culling (FullScreenKit, shared by all of them),
// the post-processing vertex shaders, the original's three samplers, the
// typed constant buffers, and the SRV unbinding after each draw.
#pragma once

#include <initializer_list>
#include <string>

#include "ConstantBuffer.h"
#include "FrameConstants.h"
#include "passes/Pass.h"

namespace drr {

// What the full-screen passes share: states, samplers, vertex shaders and
// the post-processing constant buffers (b0 dynamic or full, b1 upscale).
struct FullScreenKit {
  d3dl::ComPtr<d3dl::DepthStencilState> noDepth;
  d3dl::ComPtr<d3dl::RasterizerState> noCull;
  // The original's three: point (which filters on minification), linear and
  // linear-wrap (noise and the cubic lookup).
  d3dl::ComPtr<d3dl::SamplerState> point, linear, linearWrap;
  d3dl::ComPtr<d3dl::VertexShader> dynamicVS, fullVS;  // PostProcessDynamic's and PostProcess's
  ConstantBuffer<DynamicConstants> dynamic;
  ConstantBuffer<FullConstants> full;
  ConstantBuffer<UpscaleConstants> upscale;

  bool Init(d3dl::Device* device, std::string* error);
  bool LoadShaders(ShaderLoad& load);
  void Release();
};

class FullScreenPass : public Pass {
 public:
  explicit FullScreenPass(FullScreenKit& kit) : m_Kit(kit) {}

 protected:
  // One render target and the viewport.
  static void Target(d3dl::DeviceContext* ctx, d3dl::RenderTargetView* rtv, const d3dl::VIEWPORT& viewport);
  // s0 point (or linear), s1 linear, s2 linear-wrap.
  void BindSamplers(d3dl::DeviceContext* ctx, bool linearS0 = false) const;
  // b1: the upscalers' constants.
  void UploadUpscale(d3dl::DeviceContext* ctx, const UpscaleConstants& uc) const;
  // Binds srvs at t0.., draws one triangle with cb0 at b0, unbinds t0..t6.
  void Draw(d3dl::DeviceContext* ctx, d3dl::VertexShader* vs, d3dl::PixelShader* ps, d3dl::Buffer* cb0,
            std::initializer_list<d3dl::ShaderResourceView*> srvs = {}) const;
  // The dynamic path's draw: PostProcessDynamic's vertex shader, s.dc at b0.
  void DrawDynamic(d3dl::DeviceContext* ctx, d3dl::PixelShader* ps, const DynamicConstants& dc,
                   std::initializer_list<d3dl::ShaderResourceView*> srvs = {}) const;
  // The full-resolution path's: PostProcess's vertex shader, s.fc at b0.
  void DrawFull(d3dl::DeviceContext* ctx, d3dl::PixelShader* ps, const FullConstants& fc,
                std::initializer_list<d3dl::ShaderResourceView*> srvs = {}) const;

  FullScreenKit& m_Kit;
};

// A full-screen pass with one pixel shader of its own, by name.
class ShaderPass : public FullScreenPass {
 public:
  ShaderPass(FullScreenKit& kit, const char* pixelShader) : FullScreenPass(kit), m_Name(pixelShader) {}
  bool LoadShaders(ShaderLoad& load) override { return load.Load({}, {{m_Name, &m_PS}}); }
  void Release() override { m_PS = nullptr; }

 protected:
  const char* m_Name;
  d3dl::ComPtr<d3dl::PixelShader> m_PS;
};

}  // namespace drr
