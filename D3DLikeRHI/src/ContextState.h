// Bound state of a context, grouped as D3D11 groups its pipeline: input
// assembler, one block per shader stage, rasterizer, output merger. Slots
// keep their objects alive, as D3D11's do, through the context's PinTable
// (Pins.h); nullptr states mean the defaults.
#pragma once

#include "OnceError.h"
#include "Pins.h"
#include "PipelineCache.h"
#include "Views.h"

namespace d3dl::impl {

struct InputAssemblerState {
  struct VertexBuffer {
    Bound<BufferImpl> buffer;
    UINT stride = 0;
    UINT offset = 0;
  };
  Bound<InputLayoutImpl> layout;
  VertexBuffer vertexBuffers[IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT];
  Bound<BufferImpl> indexBuffer;
  VkIndexType indexType = VK_INDEX_TYPE_UINT16;
  UINT indexOffset = 0;
  PRIMITIVE_TOPOLOGY topology = PRIMITIVE_TOPOLOGY_UNDEFINED;
};

struct ShaderStageState {
  Bound<ShaderBase> shader;
  Bound<BufferImpl> constantBuffers[kMaxConstantBufferSlots];
  Bound<SRVImpl> shaderResources[kMaxTextureSlots];
  Bound<SamplerImpl> samplers[kMaxSamplerSlots];
  // u# slots: bound only for the compute stage (CSSetUnorderedAccessViews)
  // and the pixel stage (OMSetRenderTargetsAndUnorderedAccessViews).
  Bound<UAVImpl> uavs[kMaxUnorderedAccessSlots];
};

struct RasterizerStageState {
  Bound<RasterizerImpl> state;
  VIEWPORT viewport{};  // only the first viewport and scissor rectangle are used
  UINT numViewports = 0;
  RECT scissor{};
  UINT numScissors = 0;
};

struct OutputMergerState {
  Bound<RTVImpl> renderTargets[SIMULTANEOUS_RENDER_TARGET_COUNT];
  UINT numRenderTargets = 0;  // highest bound slot + 1
  Bound<DSVImpl> depthStencilView;
  Bound<BlendImpl> blend;
  float blendFactor[4] = {1, 1, 1, 1};
  Bound<DepthStencilImpl> depthStencil;
  UINT stencilRef = 0;
  UINT sampleMask = 0xffffffffu;  // OMSetBlendState's: which samples of MSAA targets are written
};

struct ContextState {
  InputAssemblerState ia;
  PerStage<ShaderStageState> stages;  // compute included (ShaderStage::Compute)
  RasterizerStageState rs;
  OutputMergerState om;
};

// Calls `f` with every slot of `state` that holds an object (a Bound<T>).
template <class F>
void ForEachBound(const ContextState& state, F&& f) {
  auto visit = [&f](const auto& slot) {
    if (slot) f(slot);
  };
  visit(state.ia.layout);
  for (const auto& v : state.ia.vertexBuffers) visit(v.buffer);
  visit(state.ia.indexBuffer);
  for (const ShaderStageState& s : state.stages) {
    visit(s.shader);
    for (const auto& b : s.constantBuffers) visit(b);
    for (const auto& v : s.shaderResources) visit(v);
    for (const auto& v : s.samplers) visit(v);
    for (const auto& v : s.uavs) visit(v);
  }
  visit(state.rs.state);
  for (const auto& v : state.om.renderTargets) visit(v);
  visit(state.om.depthStencilView);
  visit(state.om.blend);
  visit(state.om.depthStencil);
}

// What changed since the last commit, in one mask: Commit re-records only
// the graphics bits that are set, CommitCompute only the compute ones.
enum Dirty : uint32_t {
  // Graphics bind point.
  kPipeline = 1u << 0,
  kVertexBuffers = 1u << 1,
  kIndexBuffer = 1u << 2,
  kViewport = 1u << 3,
  kScissor = 1u << 4,
  kBlendConst = 1u << 5,
  kStencilRef = 1u << 6,
  kDescriptors = 1u << 7,  // SRV/sampler/CB/UAV identity
  kConstants = 1u << 8,    // only constant data changed
  kSrvLayouts = 1u << 9,   // some texture changed layout: re-check SRVs
  kProgram = 1u << 10,
  kTopology = 1u << 11,
  kCbSlots = 1u << 12,     // a CB slot was (re)bound: the hot CB list is out of date
  kUavs = 1u << 13,        // pixel-shader UAVs: barriers before the next draw
  kGraphicsDirty = (1u << 14) - 1,
  // Compute bind point: the graphics bit of the same meaning, shifted.
  kComputeShift = 14,
  kComputeProgram = kProgram << kComputeShift,
  kComputePipeline = kPipeline << kComputeShift,
  kComputeDescriptors = kDescriptors << kComputeShift,
  kComputeCbSlots = kCbSlots << kComputeShift,
  kComputeDirty = kGraphicsDirty << kComputeShift,
  kAll = kGraphicsDirty | kComputeDirty,
};
// The bits a change to `stage`'s state sets: the graphics ones, or for the
// compute stage their compute counterparts.
constexpr uint32_t DirtyBits(ShaderStage stage, uint32_t graphicsBits) {
  return stage == ShaderStage::Compute ? graphicsBits << kComputeShift : graphicsBits;
}


}  // namespace d3dl::impl
