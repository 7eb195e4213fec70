// Every pass of the frame, one object per PassId, and the loop that records
// a frame plan's passes in order inside the original's timer stages.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>

#include "passes/Deferred.h"
#include "passes/FullScreenPass.h"
#include "passes/ZoomBoxPass.h"

namespace drr {

class ComputeUpscale;

class PassRegistry {
 public:
  PassRegistry();
  ~PassRegistry();
  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error);
  // Every pass's shaders; a pass keeps its old set on an error. *postCompiled
  // counts the post-processing shaders compiled from HLSL (clear to the
  // secondary upscale and their vertex shaders).
  bool LoadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error, size_t* postCompiled);
  void Release();

  // The plan's passes in order; each stage inside its GPU timer, then
  // afterStage(stage) (the frame log's captures).
  void Record(PassFrame& frame, const std::function<void(PassStage)>& afterStage);

  const DeferredShared& Deferred() const { return m_Deferred; }

 private:
  d3dl::Device* m_Device = nullptr;
  FullScreenKit m_Kit;
  DeferredShared m_Deferred;
  std::array<std::unique_ptr<Pass>, size_t(PassId::Count)> m_Passes;
  bool RecordedAsCompute(PassFrame& frame, PassStage stage);

  // The Scale stage as compute passes when FrameSetup::computeUpscale; it
  // declines (and the pixel passes run) where the device cannot.
  std::unique_ptr<ComputeUpscale> m_Compute;
};

}  // namespace drr
