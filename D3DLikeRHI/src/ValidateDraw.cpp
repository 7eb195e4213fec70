// Draw- and dispatch-time checks of the bound state (see Validate.h): on
// D3D11 terms only, the context reports each kind of error once.
#include "Topology.h"
#include "Validate.h"

namespace d3dl::impl {

namespace {
// The hull, domain and geometry stages against each other and the topology.
DrawVerdict ValidateStages(const DrawInputs& in, OnceError* error) {
  const bool patches = IsPatchList(in.topology);
  auto fail = [&](OnceError e) {
    *error = e;
    return DrawVerdict::SkipWithError;
  };
  if (in.hull && !in.domain) return fail(OnceError::HullWithoutDomain);
  if (in.domain && !in.hull) return fail(OnceError::DomainWithoutHull);
  if (patches && !in.hull) return fail(OnceError::PatchListWithoutHull);
  if (in.hull && !patches) return fail(OnceError::HullWithoutPatchList);
  if (!in.geometry) return DrawVerdict::Draw;
  const uint32_t input = in.hull ? in.tessellatorOutput : TopologyClass(in.topology);
  if (in.geometryInput != input) return fail(OnceError::GeometryInputMismatch);
  return DrawVerdict::Draw;
}
}  // namespace

DrawVerdict ValidateDraw(const DrawInputs& in, OnceError* error) {
  OnceError missing;
  if (!in.vertexShader)
    missing = OnceError::NoVertexShader;
  else if (!in.target)
    missing = OnceError::NoRenderTarget;
  else if (in.indexed && !in.indexBuffer)
    missing = OnceError::NoIndexBuffer;
  else if (in.topology == PRIMITIVE_TOPOLOGY_UNDEFINED)
    missing = OnceError::NoTopology;
  else {
    const DrawVerdict stages = ValidateStages(in, error);
    if (stages != DrawVerdict::Draw) return stages;
    return in.emptyViewport ? DrawVerdict::SkipSilently : DrawVerdict::Draw;
  }
  *error = missing;
  return DrawVerdict::SkipWithError;
}

bool ValidateShaderUavs(const ShaderUavInputs& in, OnceError* error) {
  if (!in.declared) return true;
  if (!in.storesSupported)
    *error = OnceError::NoFragmentStores;
  else if (!in.allBound)
    *error = OnceError::UnboundUav;
  else
    return true;
  return false;
}

bool ValidateDispatchShader(bool computeShaderBound, OnceError* error) {
  if (computeShaderBound) return true;
  *error = OnceError::NoComputeShader;
  return false;
}

}  // namespace d3dl::impl
