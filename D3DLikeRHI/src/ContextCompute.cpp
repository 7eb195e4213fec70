// Compute shaders and UAVs: the CS setters, UAV bindings (compute and
// pixel stage), Dispatch/DispatchIndirect with their commit on the compute
// bind point, and the UAV clears. Barriers come from the same per-resource
// layout/access tracking as draws (Barriers.cpp): every UAV use counts as a
// write, so dependent dispatches and draws are ordered as D3D11 orders them.
#include <cmath>

#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {

void ContextImpl::CSSetShader(ComputeShader* s) { SetShader(ShaderStage::Compute, static_cast<ComputeShaderImpl*>(s)); }
void ContextImpl::CSSetConstantBuffers(UINT s, UINT n, Buffer* const* b) { SetCBs(ShaderStage::Compute, s, n, b); }
void ContextImpl::CSSetShaderResources(UINT s, UINT n, ShaderResourceView* const* v) {
  SetSRVs(ShaderStage::Compute, s, n, v);
}
void ContextImpl::CSSetSamplers(UINT s, UINT n, SamplerState* const* v) { SetSamplers(ShaderStage::Compute, s, n, v); }

// Stores the views; SRVs of their resources bound to this context are
// unbound (D3D11 hazard rule).
void ContextImpl::SetUavs(Bound<UAVImpl>* slots, const char* fn, UINT start, UINT num,
                          UnorderedAccessView* const* views) {
  for (UINT i = 0; i < num; ++i) {
    auto* v = static_cast<UAVImpl*>(views ? views[i] : nullptr);
    const ViewInfo info = v ? DescribeView(v->v) : ViewInfo{};
    if (!ValidateUavBinding(*dev_, fn, v ? &info : nullptr, start + i)) v = nullptr;
    Bind(slots[start + i], v);
  }
  UnbindAliasedSRVs();
}

void ContextImpl::CSSetUnorderedAccessViews(UINT start, UINT num, UnorderedAccessView* const* views, const UINT*) {
  if (!ValidateSlots(*dev_, "CS", "SetUnorderedAccessViews", start, num, kMaxUnorderedAccessSlots)) return;
  SetUavs(Stage(ShaderStage::Compute).uavs, "CSSetUnorderedAccessViews", start, num, views);
  dirty_ |= kComputeDescriptors;
}

void ContextImpl::OMSetRenderTargetsAndUnorderedAccessViews(UINT numRTVs, RenderTargetView* const* rtvs,
                                                            DepthStencilView* dsv, UINT uavStart, UINT numUAVs,
                                                            UnorderedAccessView* const* uavs, const UINT*) {
  if (!ValidateOMUavs(*dev_, numRTVs, uavStart, numUAVs)) return;
  if (numRTVs != KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL) OMSetRenderTargets(numRTVs, rtvs, dsv);
  if (numUAVs == KEEP_UNORDERED_ACCESS_VIEWS) return;
  // Slots outside [uavStart, uavStart + numUAVs) are unbound, as in D3D11.
  UnorderedAccessView* all[kMaxUnorderedAccessSlots] = {};
  for (UINT i = 0; i < numUAVs && uavs; ++i) all[uavStart + i] = uavs[i];
  SetUavs(Stage(ShaderStage::Pixel).uavs, "OMSetRenderTargetsAndUnorderedAccessViews", 0, kMaxUnorderedAccessSlots, all);
  dirty_ |= kDescriptors | kUavs;
}

// Every UAV the program declares has a view of the declared kind bound.
// The program's UAV slots against the validation layer (ValidateShaderUavs);
// logs once and returns false when the draw or dispatch must be skipped.
bool ContextImpl::CheckUavs(const ProgramLayout& p, ShaderStage stage) {
  ShaderUavInputs in;
  in.declared = p.HasUavs();
  in.storesSupported = stage == ShaderStage::Compute || dev_->features().fragmentStores;
  for (const auto& s : p.uavImages)
    if (const UAVImpl* v = UavAt(stage, s.slot); !v || !v->v.tex) in.allBound = false;
  for (const auto& s : p.uavBuffers)
    if (const UAVImpl* v = UavAt(stage, s.slot); !v || !v->v.buf) in.allBound = false;
  OnceError error;
  if (ValidateShaderUavs(in, &error)) return true;
  ErrorOnce(error);
  return false;
}

// Barriers of the program's views: sampled textures (compute only; draws do
// theirs in UseDrawResources), buffer SRVs, and UAVs (always a write).
void ContextImpl::UseShaderViews(const ProgramLayout& p, ShaderStage stage) {
  const bool cs = stage == ShaderStage::Compute;
  const VkPipelineStageFlags2 reads = cs ? usage::kComputeStage : usage::kShaderStages;
  const VkPipelineStageFlags2 writes = cs ? usage::kComputeStage : VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
  if (cs)
    for (const auto& s : p.srvs)
      if (SRVImpl* v = Stage(s.stage).shaderResources[s.slot].Get(); v && v->v.tex) {
        UseTexture(v->v.tex, v->v.range(), usage::SampledRead(reads));
        NoteUse(v->v.tex->use, false);
      }
  for (const auto& s : p.bufferSrvs)
    if (SRVImpl* v = Stage(s.stage).shaderResources[s.slot].Get(); v && v->v.buf) {
      UseBuffer(v->v.buf->vkBuffer(), v->v.buf->sync(), usage::StorageBufferRead(reads));
      NoteUse(v->v.buf->use, false);
    }
  for (const auto& s : p.uavImages) {
    const ViewCore& v = UavAt(stage, s.slot)->v;
    UseTexture(v.tex, OneSubresource(v.baseMip, 0), usage::StorageWrite(writes, true));
    NoteUse(v.tex->use, true);
  }
  for (const auto& s : p.uavBuffers) {
    BufferImpl* b = UavAt(stage, s.slot)->v.buf;
    UseBuffer(b->vkBuffer(), b->sync(), usage::StorageWrite(writes, false));
    NoteUse(b->use, true);
  }
}

// Dispatch-time commit: program, barriers (outside any rendering scope),
// pipeline and descriptor set on the compute bind point.
bool ContextImpl::CommitCompute() {
  ShaderBase* cs = Stage(ShaderStage::Compute).shader.Get();
  OnceError error;
  if (!ValidateDispatchShader(cs != nullptr, &error)) return ErrorOnce(error), false;
  if (dirty_ & kComputeProgram) {
    computeProgram_ = dev_->pipelines().GetComputeProgram(cs);
    if (!computeProgram_) return ErrorOnce(OnceError::ProgramLayoutFailed), false;
    dirty_ |= kComputeDescriptors | kComputePipeline;
  }
  const ProgramLayout& p = *computeProgram_;
  // UAV slots change only with kComputeDescriptors (a failed check leaves it set).
  if ((dirty_ & kComputeDescriptors) && !CheckUavs(p, ShaderStage::Compute)) return false;
  UseShaderViews(p, ShaderStage::Compute);
  EndRendering();
  FlushBarriers();
  if (dirty_ & kComputePipeline) {
    VkPipeline pipeline = dev_->pipelines().GetComputePipeline(cs, computeProgram_);
    if (!pipeline) return ErrorOnce(OnceError::PipelineFailed), false;
    if (pipeline != computePipeline_) vkCmdBindPipeline(Cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    computePipeline_ = pipeline;
  }
  // Only constant data changed since the last dispatch: the same set, new offsets.
  const bool sameSet = !(dirty_ & (kComputeDescriptors | kComputeCbSlots)) && computeDesc_.hotLayout;
  if (!(sameSet && RebindWithNewOffsets(Cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, computeDesc_)) &&
      !BindSet(Cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, p, computeDesc_, (dirty_ & kComputeDescriptors) != 0))
    return false;
  dirty_ &= ~uint32_t(kComputeDirty);
  return true;
}

void ContextImpl::Dispatch(UINT x, UINT y, UINT z) {
  if (!ValidateDispatch(*dev_, x, y, z) || !CommitCompute()) return;
  vkCmdDispatch(Cmd(), x, y, z);
}

void ContextImpl::DispatchIndirect(Buffer* args, UINT offset) {
  BufferImpl* b = UseIndirectArgs("DispatchIndirect", args, offset, kDispatchArgsBytes);
  if (!b || !CommitCompute()) return;
  vkCmdDispatchIndirect(Cmd(), b->vkBuffer(), offset);
}

// ---------------------------------------------------------------------------
// UAV clears: transfer clears outside any rendering scope.
namespace {
float HalfToFloat(uint32_t h) {
  const uint32_t sign = (h >> 15) & 1, exp = (h >> 10) & 0x1f, man = h & 0x3ff;
  float v = exp == 0 ? std::ldexp(float(man), -24)
            : exp == 31 ? (man ? NAN : INFINITY)
                        : std::ldexp(float(man | 0x400), int(exp) - 25);
  return sign ? -v : v;
}

// The clear colour whose stored bits are the low bits of `values` (D3D11's
// ClearUnorderedAccessViewUint); false for formats without such a mapping.
bool ClearColorFromBits(VkFormat f, const UINT values[4], VkClearColorValue* out) {
  for (int i = 0; i < 4; ++i) {
    const uint32_t v = values[i];
    switch (f) {
      case VK_FORMAT_R8G8B8A8_UNORM: case VK_FORMAT_B8G8R8A8_UNORM: case VK_FORMAT_R8_UNORM: case VK_FORMAT_R8G8_UNORM:
        out->float32[i] = float(v & 0xffu) / 255.0f;
        break;
      case VK_FORMAT_R16G16B16A16_UNORM: out->float32[i] = float(v & 0xffffu) / 65535.0f; break;
      case VK_FORMAT_R32_SFLOAT: case VK_FORMAT_R32G32_SFLOAT: case VK_FORMAT_R32G32B32A32_SFLOAT:
        std::memcpy(&out->float32[i], &v, 4);
        break;
      case VK_FORMAT_R16_SFLOAT: case VK_FORMAT_R16G16_SFLOAT: case VK_FORMAT_R16G16B16A16_SFLOAT:
        out->float32[i] = HalfToFloat(v & 0xffffu);
        break;
      case VK_FORMAT_R8G8B8A8_UINT: out->uint32[i] = v & 0xffu; break;
      case VK_FORMAT_R16_UINT: out->uint32[i] = v & 0xffffu; break;
      case VK_FORMAT_R32_UINT: out->uint32[i] = v; break;
      default: return false;
    }
  }
  return true;
}
}  // namespace

bool UavClearBitsSupported(DXGI_FORMAT f) {
  const UINT zero[4] = {};
  VkClearColorValue ignored;
  return ClearColorFromBits(ToVkFormat(f), zero, &ignored);
}

void ContextImpl::ClearUav(UAVImpl* uav, const VkClearColorValue& value, uint32_t fill) {
  const ViewCore& v = uav->v;
  EndRendering();
  Hold(uav);
  if (v.buf) {
    UseBuffer(v.buf->vkBuffer(), v.buf->sync(), usage::BufferFillDst);
    FlushBarriers();
    vkCmdFillBuffer(Cmd(), v.buf->vkBuffer(), v.bufOffset, v.bufRange, fill);
    NoteUse(v.buf->use, true);
    return;
  }
  UseTexture(v.tex, OneSubresource(v.baseMip, 0), usage::TransferDst);
  FlushBarriers();
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, v.baseMip, 1, 0, 1};
  vkCmdClearColorImage(Cmd(), v.tex->Cur().image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value, 1, &range);
  NoteUse(v.tex->use, true);
}

void ContextImpl::ClearUnorderedAccessViewUint(UnorderedAccessView* uav, const UINT values[4]) {
  auto* v = static_cast<UAVImpl*>(uav);
  const ViewInfo info = v ? DescribeView(v->v) : ViewInfo{};
  if (!ValidateClearUav(*dev_, v ? &info : nullptr, values, false)) return;
  VkClearColorValue color{};
  if (v->v.tex) ClearColorFromBits(v->v.format, values, &color);
  ClearUav(v, color, values[0]);  // raw and structured buffers: the first value, as in D3D11
}

void ContextImpl::ClearUnorderedAccessViewFloat(UnorderedAccessView* uav, const float values[4]) {
  auto* v = static_cast<UAVImpl*>(uav);
  const ViewInfo info = v ? DescribeView(v->v) : ViewInfo{};
  if (!ValidateClearUav(*dev_, v ? &info : nullptr, values, true)) return;
  VkClearColorValue color{};
  std::memcpy(color.float32, values, sizeof(color.float32));
  ClearUav(v, color, 0);
}

}  // namespace d3dl::impl
