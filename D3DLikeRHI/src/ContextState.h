// Bound state of a context, grouped as D3D11 groups its pipeline: input
// assembler, one block per shader stage, rasterizer, output merger. Slots
// hold references (ComPtr), as D3D11 does; nullptr states mean the defaults.
#pragma once

#include "PipelineCache.h"
#include "Views.h"

namespace d3dl::impl {

struct InputAssemblerState {
  struct VertexBuffer {
    ComPtr<BufferImpl> buffer;
    UINT stride = 0;
    UINT offset = 0;
  };
  ComPtr<InputLayoutImpl> layout;
  VertexBuffer vertexBuffers[IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT];
  ComPtr<BufferImpl> indexBuffer;
  VkIndexType indexType = VK_INDEX_TYPE_UINT16;
  UINT indexOffset = 0;
  PRIMITIVE_TOPOLOGY topology = PRIMITIVE_TOPOLOGY_UNDEFINED;
};

struct ShaderStageState {
  ComPtr<ShaderBase> shader;
  ComPtr<BufferImpl> constantBuffers[kMaxConstantBufferSlots];
  ComPtr<SRVImpl> shaderResources[kMaxTextureSlots];
  ComPtr<SamplerImpl> samplers[kMaxSamplerSlots];
};

struct RasterizerStageState {
  ComPtr<RasterizerImpl> state;
  VIEWPORT viewport{};  // only the first viewport and scissor rectangle are used
  UINT numViewports = 0;
  RECT scissor{};
  UINT numScissors = 0;
};

struct OutputMergerState {
  ComPtr<RTVImpl> renderTargets[SIMULTANEOUS_RENDER_TARGET_COUNT];
  UINT numRenderTargets = 0;  // highest bound slot + 1
  ComPtr<DSVImpl> depthStencilView;
  ComPtr<BlendImpl> blend;
  float blendFactor[4] = {1, 1, 1, 1};
  ComPtr<DepthStencilImpl> depthStencil;
  UINT stencilRef = 0;
  UINT sampleMask = 0xffffffffu;  // OMSetBlendState's: which samples of MSAA targets are written
};

// Compute and unordered access: the compute stage is not a graphics stage
// (not in kStages) and keeps its own block with its UAV slots; the pixel
// shader's UAVs (OMSetRenderTargetsAndUnorderedAccessViews) sit beside the OM.
struct ComputeState {
  ShaderStageState stage;
  ComPtr<UAVImpl> uavs[kMaxUnorderedAccessSlots];
};
struct PixelUavState {
  ComPtr<UAVImpl> uavs[kMaxUnorderedAccessSlots];
};

struct ContextState {
  InputAssemblerState ia;
  PerStage<ShaderStageState> stages;
  RasterizerStageState rs;
  OutputMergerState om;
  ComputeState cs;        // compute and unordered access
  PixelUavState psUavs;   // compute and unordered access
};

// What changed since the last commit: Commit re-records only that.
enum Dirty : uint32_t {
  kPipeline = 1u << 0,
  kVertexBuffers = 1u << 1,
  kIndexBuffer = 1u << 2,
  kViewport = 1u << 3,
  kScissor = 1u << 4,
  kBlendConst = 1u << 5,
  kStencilRef = 1u << 6,
  kDescriptors = 1u << 7,  // SRV/sampler/CB identity
  kConstants = 1u << 8,    // only constant data changed
  kSrvLayouts = 1u << 9,   // some texture changed layout: re-check SRVs
  kProgram = 1u << 10,
  kTopology = 1u << 11,
  kCbSlots = 1u << 12,     // a CB slot was (re)bound: the hot CB list is out of date
  kUavs = 1u << 20,        // pixel-shader UAVs: barriers before the next draw (compute and unordered access)
  kAll = 0xffffffffu,
};

// Errors a context logs only once (draws that keep failing the same way).
enum class OnceError : uint32_t {
  NoVertexShader,
  NoRenderTarget,
  NoIndexBuffer,
  NoTopology,
  ProgramLayoutFailed,
  PipelineFailed,
  StaleDynamicBuffer,
  IndexBufferNeverMapped,
  DescriptorSetFailed,
  TooManyTimestamps,
  // Tessellation and geometry stages (CheckStageTopology)
  HullWithoutDomain,
  DomainWithoutHull,
  PatchListWithoutHull,
  HullWithoutPatchList,
  GeometryInputMismatch,
  // Compute and unordered access
  NoComputeShader,
  UnboundUav,
  NoFragmentStores,
};
const char* OnceErrorMessage(OnceError e);

}  // namespace d3dl::impl
