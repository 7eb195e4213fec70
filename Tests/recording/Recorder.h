// Two ways of recording the same frame: N draws of one triangle whose
// constants (offset, colour) change every draw; or N dispatches (compute and
// unordered access) with changing constants on one UAV. Used by RecordBenchmark.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace drrbench {

inline constexpr uint32_t kTargetSize = 64;

struct DrawConstants {
  float offset[4];
  float color[4];
};

// Compute and unordered access: constants of dispatch i, and the UAV's size.
struct DispatchConstants {
  uint32_t index, value, pad[2];
};
inline constexpr uint32_t kDispatchWords = 64;  // one thread group
DispatchConstants ConstantsForDispatch(uint32_t i);

// Folder of the compiled benchmark shaders: $DRR_BENCH_SHADER_DIR, else the build's.
std::string BenchShaderDir();

// Deterministic constants for draw i of n (positions spread over the target).
DrawConstants ConstantsForDraw(uint32_t i, uint32_t n);

class Recorder {
 public:
  virtual ~Recorder() = default;
  virtual bool Init(std::string* error) = 0;
  // Records the frame (timed part): the target is cleared, then n draws.
  virtual void Record(uint32_t n) = 0;
  // Submits what Record recorded and waits for it (not timed).
  virtual void SubmitAndWait() = 0;
  // RGBA8 pixels of the target after SubmitAndWait.
  virtual std::vector<uint8_t> ReadBack() = 0;
  virtual uint64_t ValidationMessages() const = 0;
  // Compute and unordered access (timed part): the UAV is cleared to 0, then
  // n dispatches of one group, each with new constants; SubmitAndWait as above.
  virtual void RecordDispatches(uint32_t n) = 0;
  // The UAV's words after SubmitAndWait.
  virtual std::vector<uint32_t> ReadBackWords() = 0;
};

// poolAllocator: host memory of the command pool (null: the driver's own).
Recorder* CreateRawVulkanRecorder(const VkAllocationCallbacks* poolAllocator = nullptr);
Recorder* CreateRhiRecorder();

// drr_rhi_bench --deferred (DeferredBenchmark.cpp): 1 against 2 recording threads.
int DeferredMain(int argc, char** argv);

}  // namespace drrbench
