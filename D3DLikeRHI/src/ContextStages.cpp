// Hull, domain and geometry stages: the HS/DS/GS setters (the same per-stage
// state as VS/PS), and what a draw's checks look at of the bound state
// (ValidateDraw.cpp decides).
#include "Context.h"
#include "Validate.h"
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

// The bound state a draw's checks look at (ValidateDraw).
DrawInputs ContextImpl::DrawInputsOf(bool indexed) const {
  const ShaderBase* hs = state_.stages[ShaderStage::Hull].shader.Get();
  const ShaderBase* ds = state_.stages[ShaderStage::Domain].shader.Get();
  const ShaderBase* gs = state_.stages[ShaderStage::Geometry].shader.Get();
  const RasterizerStageState& rs = state_.rs;
  DrawInputs in;
  in.indexed = indexed;
  in.vertexShader = state_.stages[ShaderStage::Vertex].shader.Get() != nullptr;
  in.target = state_.om.numRenderTargets != 0 || state_.om.depthStencilView.Get() != nullptr;
  in.indexBuffer = state_.ia.indexBuffer.Get() != nullptr;
  in.topology = state_.ia.topology;
  in.hull = hs != nullptr;
  in.domain = ds != nullptr;
  in.geometry = gs != nullptr;
  if (hs && ds) in.tessellatorOutput = TessellatorOutput(hs->refl, ds->refl);
  if (gs) in.geometryInput = gs->refl.geometryInput;
  in.emptyViewport = rs.numViewports && (rs.viewport.Width <= 0.0f || rs.viewport.Height <= 0.0f);
  return in;
}

}  // namespace d3dl::impl
