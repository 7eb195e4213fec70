// The device (VkDevice.cpp, DeviceSetup.cpp): instance, adapter, logical
// device, memory, deferred destruction, and the factories of every object.
#pragma once

#include <memory>

#include "PipelineCache.h"
#include "Queue.h"
#include "Resources.h"
#include "ValidationDevice.h"

namespace d3dl::impl {

// Optional features and extensions found on the adapter.
struct DeviceFeatures {
  bool debugUtils = false, minmax = false, depthClamp = false, swapchain = false;
  bool surface = false;  // VK_KHR_surface enabled on the instance
  bool anisotropy = false, bc = false, fillNonSolid = false, mirrorOnce = false;
  // Optional stages and pipeline statistics queries.
  bool tessellation = false, geometry = false, pipelineStatistics = false;
  bool cubeArray = false, independentBlend = false;  // cube-array views, per-target blend
  bool fragmentStores = false;  // pixel-shader UAVs (fragmentStoresAndAtomics)
};

// Bound where the shader expects a resource but none is bound.
struct DummyResources {
  VkBuffer uniform = VK_NULL_HANDLE;  // zeroed; also the vertex buffer and buffer SRV of unbound slots
  VkDeviceSize uniformSize = 0;
  VkImageView view2D = VK_NULL_HANDLE, view1D = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  // A zero view per declared image shape (1-D/2-D,
  // arrays, cubes, multisampled), indexed by DummyViewIndex; null where the
  // adapter cannot make it (then view1D/view2D are bound).
  VkImageView views[9] = {};
};
// VkImageViewType 0..6 (1D, 2D, 3D, CUBE, 1D_ARRAY, 2D_ARRAY, CUBE_ARRAY);
// 7, 8: multisampled 2D and 2D_ARRAY.
inline uint8_t DummyViewIndex(VkImageViewType type, bool ms) {
  if (ms) return type == VK_IMAGE_VIEW_TYPE_2D_ARRAY ? 8 : 7;
  return static_cast<uint8_t>(type);
}

// VK_EXT_debug_utils entry points (null without the extension).
struct DebugUtils {
  PFN_vkCmdBeginDebugUtilsLabelEXT cmdBeginLabel = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT cmdEndLabel = nullptr;
  PFN_vkSetDebugUtilsObjectNameEXT setObjectName = nullptr;
};

class DeviceImpl final : public Device, public ValidationDevice {
 public:
  DeviceImpl();
  ~DeviceImpl();
  HRESULT Init(const DEVICE_CREATE_DESC& desc);

  UINT AddRef() override { return ++externalRefs_; }
  UINT Release() override;

  HRESULT CreateBuffer(const BUFFER_DESC*, const SUBRESOURCE_DATA*, Buffer**) override;
  HRESULT CreateTexture1D(const TEXTURE1D_DESC*, const SUBRESOURCE_DATA*, Texture1D**) override;
  HRESULT CreateTexture2D(const TEXTURE2D_DESC*, const SUBRESOURCE_DATA*, Texture2D**) override;
  HRESULT CreateShaderResourceView(Resource*, const SHADER_RESOURCE_VIEW_DESC*,
                                   ShaderResourceView**) override;
  HRESULT CreateRenderTargetView(Resource*, const RENDER_TARGET_VIEW_DESC*,
                                 RenderTargetView**) override;
  HRESULT CreateDepthStencilView(Resource*, const DEPTH_STENCIL_VIEW_DESC*,
                                 DepthStencilView**) override;
  HRESULT CreateSamplerState(const SAMPLER_DESC*, SamplerState**) override;
  HRESULT CreateBlendState(const BLEND_DESC*, BlendState**) override;
  HRESULT CreateDepthStencilState(const DEPTH_STENCIL_DESC*, DepthStencilState**) override;
  HRESULT CreateRasterizerState(const RASTERIZER_DESC*, RasterizerState**) override;
  HRESULT CreateVertexShader(const void*, size_t, VertexShader**) override;
  HRESULT CreatePixelShader(const void*, size_t, PixelShader**) override;
  HRESULT CreateHullShader(const void*, size_t, HullShader**) override;
  HRESULT CreateDomainShader(const void*, size_t, DomainShader**) override;
  HRESULT CreateGeometryShader(const void*, size_t, GeometryShader**) override;
  HRESULT CreateInputLayout(const INPUT_ELEMENT_DESC*, UINT, const void*, size_t,
                            InputLayout**) override;
  HRESULT CreateQuery(const QUERY_DESC*, Query**) override;
  HRESULT CreateUnorderedAccessView(Resource*, const UNORDERED_ACCESS_VIEW_DESC*,
                                    UnorderedAccessView**) override;
  HRESULT CreateComputeShader(const void*, size_t, ComputeShader**) override;
  HRESULT CreateSwapChainForWindow(GLFWwindow*, const SWAP_CHAIN_DESC*, SwapChain**) override;
  HRESULT CreateHeadlessSwapChain(const SWAP_CHAIN_DESC*, SwapChain**) override;
  void GetImmediateContext(DeviceContext** context) override;
  HRESULT CreateDeferredContext(UINT contextFlags, DeviceContext** context) override;  // ContextDeferred.cpp
  void GetAdapterDesc(ADAPTER_DESC* desc) const override {
    if (desc) *desc = adapter_;
  }
  void GetStats(DEVICE_STATS* stats) const override;
  bool CheckFormatSupport(DXGI_FORMAT format, UINT bindFlags) const override;
  void WaitIdle() override;
  // Multisampling support (Textures.cpp)
  HRESULT CheckMultisampleQualityLevels(DXGI_FORMAT format, UINT sampleCount, UINT* numQualityLevels) const override;

  // ValidationDevice (VkDevice.cpp); Log is ValidationDevice's.
  uint32_t FormatFeatures(DXGI_FORMAT format) const override;
  UINT SampledSampleCounts(const TEXTURE2D_DESC& desc) const override;  // Textures.cpp
  void OnValidationMessage(const char* msg);

  // Memory
  bool AllocateMemory(const VkMemoryRequirements& req, VkMemoryPropertyFlags want,
                      VkMemoryPropertyFlags fallback, VkDeviceMemory* out);
  bool CreateBufferRaw(VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                       VkBuffer* buf, VkDeviceMemory* mem, uint8_t** mapped);
  void SetName(VkObjectType type, uint64_t handle, const std::string& name);
  // A transient command pool of the graphics queue with one primary buffer.
  // `memory`: the pool's allocator (null: the driver's); destroy the pool with it.
  void CreateCommandBuffer(VkCommandPool* pool, VkCommandBuffer* cmd, const VkAllocationCallbacks* memory = nullptr);

  // Deferred destruction: after the fence of the frame being recorded.
  // `memory`: a command pool's allocator (CommandMemory.h), deleted after the pool.
  void Defer(VkObjectType type, uint64_t handle, CommandMemory* memory = nullptr);
  void DestroyNow(const Garbage& g);
  void ChildCreated() { ++internalRefs_; }
  void ChildDestroyed();

  // The queue's frame being recorded.
  FrameQueue& queue() { return queue_; }
  uint64_t CurrentSerial() const { return queue_.CurrentSerial(); }
  bool AllocateRing(VkDeviceSize size, VkDeviceSize align, RingAlloc* out) {
    return queue_.AllocateRing(size, align, out);
  }
  VkCommandBuffer UploadCmd() { return queue_.UploadCmd(); }

  // Accessors
  VkDevice vk() const { return device_; }
  VkPhysicalDevice phys() const { return phys_; }
  VkInstance instance() const { return instance_; }
  uint32_t queueFamily() const { return queueFamily_; }
  ContextImpl* context() const { return context_.get(); }
  PipelineCache& pipelines() { return pipelines_; }
  const VkPhysicalDeviceProperties& props() const { return props_; }
  VkDeviceSize uboAlign() const { return uboAlign_; }
  const DeviceFeatures& features() const { return features_; }
  const DummyResources& dummies() const { return dummies_; }
  const DebugUtils& debugUtils() const { return debugUtils_; }
  uint64_t NextUid() { return ++uidCounter_; }
  // Deferred contexts in creation order: which twin pipeline layouts they bind with.
  uint32_t NextDeferredContextIndex() { return deferredContexts_++; }

  DEVICE_STATS stats{};
  // A command pool was reset (any context's thread): whether its host memory
  // started over from the beginning (CommandMemory::Rewind).
  void CountCommandPoolReset(bool rewound) {
    ++commandPoolResets_;
    if (rewound) ++commandPoolRewinds_;
  }

 private:
  // DeviceSetup.cpp
  bool CreateInstance(const DEVICE_CREATE_DESC& desc, ValidationMode mode);
  void LoadDebugUtils(bool validation, const VkDebugUtilsMessengerCreateInfoEXT& mci);
  bool PickAdapter(const DEVICE_CREATE_DESC& desc);
  bool CreateLogicalDevice();
  void FillValidationCaps();  // DeviceSetup.cpp
  bool EnableFeatures(VkPhysicalDeviceFeatures2* enable, VkPhysicalDeviceVulkan12Features* e12,
                      VkPhysicalDeviceVulkan13Features* e13);
  void FillAdapterDesc(uint32_t timestampBits);
  bool CreateDummies();
  bool CreateDummyImage(VkImageType type, VkImage* image, VkImageView* view);
  void ClearDummies(const VkImage images[2]);
  bool CreateViewDummies(VkImage image1D);  // Views.cpp
  bool CreateDummyLayers(uint32_t layers, VkSampleCountFlagBits samples, VkImageCreateFlags flags, VkImage* image);
  void Shutdown();

  std::atomic<UINT> externalRefs_{1};
  std::atomic<UINT> internalRefs_{0};
  std::atomic<UINT64> commandPoolResets_{0}, commandPoolRewinds_{0};
  bool orphaned_ = false;
  bool shuttingDown_ = false;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice phys_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkPhysicalDeviceProperties props_{};
  VkPhysicalDeviceMemoryProperties memProps_{};
  VkDeviceSize uboAlign_ = 256;
  DeviceFeatures features_;
  DebugUtils debugUtils_;
  DummyResources dummies_;
  std::vector<Garbage> dummyGarbage_;
  ADAPTER_DESC adapter_{};
  FrameQueue queue_;
  PipelineCache pipelines_;
  std::unique_ptr<ContextImpl> context_;
  std::atomic<uint64_t> uidCounter_{0};
  std::atomic<uint32_t> deferredContexts_{0};
};

// Hot-path helpers, inline because they run once per draw.
inline bool BufferImpl::NewRingSlice(VkDeviceSize align) {
  if (!dev_->AllocateRing(desc_.ByteWidth, align, &ring_)) return false;  // writes only on success
  ringSerial_ = dev_->CurrentSerial();
  return true;
}

inline void BufferImpl::EnsureUploaded() {
  if (ringSerial_ == dev_->CurrentSerial()) return;
  RingAlloc a;
  if (!dev_->AllocateRing(desc_.ByteWidth, dev_->uboAlign(), &a)) return;
  std::memcpy(a.ptr, shadow_.data(), desc_.ByteWidth);
  ring_ = a;
  ringSerial_ = dev_->CurrentSerial();
}

}  // namespace d3dl::impl
