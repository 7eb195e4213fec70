// Hull, domain and geometry stages: the HS/DS/GS setters (the same per-stage
// state as VS/PS) and the draw-time check that the bound stages fit each
// other and the primitive topology (what Vulkan pipeline creation requires).
#include "Context.h"
#include "Topology.h"

namespace d3dl::impl {

void ContextImpl::HSSetShader(HullShader* s) { SetShader(ShaderStage::Hull, static_cast<HullShaderImpl*>(s)); }
void ContextImpl::HSSetConstantBuffers(UINT s, UINT n, Buffer* const* b) { SetCBs(ShaderStage::Hull, s, n, b); }
void ContextImpl::HSSetShaderResources(UINT s, UINT n, ShaderResourceView* const* v) { SetSRVs(ShaderStage::Hull, s, n, v); }
void ContextImpl::HSSetSamplers(UINT s, UINT n, SamplerState* const* v) { SetSamplers(ShaderStage::Hull, s, n, v); }

void ContextImpl::DSSetShader(DomainShader* s) { SetShader(ShaderStage::Domain, static_cast<DomainShaderImpl*>(s)); }
void ContextImpl::DSSetConstantBuffers(UINT s, UINT n, Buffer* const* b) { SetCBs(ShaderStage::Domain, s, n, b); }
void ContextImpl::DSSetShaderResources(UINT s, UINT n, ShaderResourceView* const* v) { SetSRVs(ShaderStage::Domain, s, n, v); }
void ContextImpl::DSSetSamplers(UINT s, UINT n, SamplerState* const* v) { SetSamplers(ShaderStage::Domain, s, n, v); }

void ContextImpl::GSSetShader(GeometryShader* s) { SetShader(ShaderStage::Geometry, static_cast<GeometryShaderImpl*>(s)); }
void ContextImpl::GSSetConstantBuffers(UINT s, UINT n, Buffer* const* b) { SetCBs(ShaderStage::Geometry, s, n, b); }
void ContextImpl::GSSetShaderResources(UINT s, UINT n, ShaderResourceView* const* v) { SetSRVs(ShaderStage::Geometry, s, n, v); }
void ContextImpl::GSSetSamplers(UINT s, UINT n, SamplerState* const* v) { SetSamplers(ShaderStage::Geometry, s, n, v); }

namespace {
// The primitive class the tessellator emits: the domain declared by either
// stage, points when either asks for point mode.
uint32_t TessellatorOutput(const ShaderReflection& hs, const ShaderReflection& ds) {
  if (hs.tessellationPointMode || ds.tessellationPointMode) return kPointClass;
  return hs.tessellationDomain != kNoPrimitive ? hs.tessellationDomain : ds.tessellationDomain;
}
}  // namespace

// D3D11 draws nothing for these combinations and its debug layer reports
// them; Vulkan would reject the pipeline. One error per kind and context.
bool ContextImpl::CheckStageTopology() {
  const ShaderBase* hs = state_.stages[ShaderStage::Hull].shader.Get();
  const ShaderBase* ds = state_.stages[ShaderStage::Domain].shader.Get();
  const ShaderBase* gs = state_.stages[ShaderStage::Geometry].shader.Get();
  const bool patches = IsPatchList(state_.ia.topology);
  if (hs && !ds) return ErrorOnce(OnceError::HullWithoutDomain), false;
  if (ds && !hs) return ErrorOnce(OnceError::DomainWithoutHull), false;
  if (patches && !hs) return ErrorOnce(OnceError::PatchListWithoutHull), false;
  if (hs && !patches) return ErrorOnce(OnceError::HullWithoutPatchList), false;
  if (!gs) return true;
  const uint32_t input = hs ? TessellatorOutput(hs->refl, ds->refl) : TopologyClass(state_.ia.topology);
  if (gs->refl.geometryInput != input) return ErrorOnce(OnceError::GeometryInputMismatch), false;
  return true;
}

}  // namespace d3dl::impl
