// Errors a context logs once (draws that keep failing the same way); the
// draw-time validators (Validate.h) name them, the context logs them.
#pragma once

#include <cstdint>

namespace d3dl::impl {

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
  // Hull, domain and geometry stages that do not fit (CheckStageTopology)
  HullWithoutDomain,
  DomainWithoutHull,
  PatchListWithoutHull,
  HullWithoutPatchList,
  GeometryInputMismatch,
  // Dispatches, UAVs
  NoComputeShader,
  UnboundUav,
  NoFragmentStores,
};
const char* OnceErrorMessage(OnceError e);

}  // namespace d3dl::impl
