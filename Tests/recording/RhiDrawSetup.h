// The D3DLikeRHI objects both RHI benchmarks (RhiRecorder.cpp on the immediate
// context, DeferredBenchmark.cpp on deferred contexts) draw with: a device
// without window surfaces, a kTargetSize RGBA8 target and its staging copy,
// the per-draw constant buffer, the BenchDraw shaders and a no-cull state.
#pragma once

#include <string>
#include <vector>

#include "Recorder.h"
#include "d3dl/D3DLike.h"

namespace drrbench {

struct RhiDrawSetup {
  d3dl::ComPtr<d3dl::Device> device;
  d3dl::ComPtr<d3dl::DeviceContext> context;
  d3dl::ComPtr<d3dl::Texture2D> target, staging;
  d3dl::ComPtr<d3dl::RenderTargetView> rtv;
  d3dl::ComPtr<d3dl::Buffer> constants;
  d3dl::ComPtr<d3dl::VertexShader> vs;
  d3dl::ComPtr<d3dl::PixelShader> ps;
  d3dl::ComPtr<d3dl::RasterizerState> rs;

  ~RhiDrawSetup();
  bool Init(const char* applicationName, std::string* error);
  // Binds the target, viewport, state and shaders the draws use on `ctx`.
  void BindDrawState(d3dl::DeviceContext* ctx) const;
  // Draws [first, last) of n, each after a Map(WRITE_DISCARD) of its constants.
  void RecordDraws(d3dl::DeviceContext* ctx, uint32_t first, uint32_t last, uint32_t n) const;
  // RGBA8 pixels of the staging copy (empty if it cannot be mapped).
  std::vector<uint8_t> ReadStaging() const;
  // Validation messages and logged errors since the device was created.
  uint64_t Messages() const;
};

}  // namespace drrbench
