// Private declarations of the Vulkan backend of D3DLikeRHI. Nothing here is
// visible to users of the library; every .cpp of src/ includes this header.
#pragma once

#include <vulkan/vulkan.h>

#include <algorithm>
#include <atomic>
#include <cstdarg>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "d3dl/D3DLike.h"

namespace d3dl::impl {

class DeviceImpl;
class ContextImpl;

// ---------------------------------------------------------------------------
// Formats (Formats.cpp)
struct FormatInfo {
  DXGI_FORMAT dxgi;
  VkFormat vk;
  uint32_t bytes;  // per texel, or per 4x4 block
  bool bc;
  bool depth;
  bool integer;
  const char* name;
};
const FormatInfo* GetFormatInfo(DXGI_FORMAT f);  // nullptr when not in the table
VkFormat ToVkFormat(DXGI_FORMAT f);
VkCompareOp ToVkCompare(COMPARISON_FUNC f);

// ---------------------------------------------------------------------------
// Synchronisation state of one image subresource or one buffer (Barriers.cpp).
struct SyncState {
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 writeStages = 0;  // stages of the last write / layout transition
  VkAccessFlags2 writeAccess = 0;         // access of the last write (0: transition only)
  VkPipelineStageFlags2 visible = 0;      // stages the last write is already visible to
  VkPipelineStageFlags2 readStages = 0;   // reads since the last write
  bool pending = false;                   // a write/transition happened
};

struct Usage {
  VkPipelineStageFlags2 stages;
  VkAccessFlags2 access;
  VkImageLayout layout;
  bool write;
};

namespace usage {
inline constexpr VkPipelineStageFlags2 kShaderStages =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
inline constexpr Usage ShaderRead{kShaderStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, false};
inline constexpr Usage ColorAttachment{
    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true};
inline constexpr Usage DepthAttachment{
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
    VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, true};
inline constexpr Usage TransferSrc{VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                                   VK_ACCESS_2_TRANSFER_READ_BIT,
                                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, false};
inline constexpr Usage TransferDst{
    VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
    VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, true};
inline constexpr Usage Present{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
                               VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, false};
inline constexpr Usage VertexRead{VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT |
                                      VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT,
                                  VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT |
                                      VK_ACCESS_2_INDEX_READ_BIT,
                                  VK_IMAGE_LAYOUT_UNDEFINED, false};
inline constexpr Usage BufferCopySrc{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                                     VK_IMAGE_LAYOUT_UNDEFINED, false};
inline constexpr Usage BufferCopyDst{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                     VK_IMAGE_LAYOUT_UNDEFINED, true};
}  // namespace usage

// Computes the barrier needed before `u` and updates `s`. Returns false if
// no barrier is needed. srcStage/srcAccess/dstStage/dstAccess/old/newLayout out.
struct BarrierInfo {
  VkPipelineStageFlags2 srcStage, dstStage;
  VkAccessFlags2 srcAccess, dstAccess;
  VkImageLayout oldLayout, newLayout;
};
bool Transition(SyncState& s, const Usage& u, BarrierInfo* out);

// ---------------------------------------------------------------------------
// Object base: COM-like reference count; the destructor of each object hands
// its Vulkan handles to the device's deferred-destruction list.
class ObjectRoot {
 public:
  explicit ObjectRoot(DeviceImpl* dev);
  virtual ~ObjectRoot();
  DeviceImpl* dev() const { return dev_; }
  uint64_t uid() const { return uid_; }

 protected:
  DeviceImpl* dev_;
  uint64_t uid_;
  std::string name_;
};

template <class Iface>
class Object : public Iface, public ObjectRoot {
 public:
  explicit Object(DeviceImpl* d) : ObjectRoot(d) {}
  UINT AddRef() override { return ++refs_; }
  UINT Release() override {
    UINT r = --refs_;
    if (r == 0) delete this;
    return r;
  }
  UINT RefCount() const { return refs_.load(); }

 protected:
  std::atomic<UINT> refs_{1};
};

template <class Iface>
class Child : public Object<Iface> {
 public:
  using Object<Iface>::Object;
  void SetDebugName(const char* name) override {
    this->name_ = name ? name : "";
    OnDebugName();
  }
  const std::string& DebugName() const { return this->name_; }

 protected:
  virtual void OnDebugName() {}
};

// ---------------------------------------------------------------------------
// Constant ring (ConstantRing.cpp): per-frame linear allocator in host-visible,
// persistently mapped memory.
struct RingAlloc {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  uint8_t* ptr = nullptr;
};

class ConstantRing {
 public:
  struct Chunk {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    uint8_t* ptr = nullptr;
    VkDeviceSize size = 0;
  };
  void Init(DeviceImpl* dev) { dev_ = dev; }
  void Destroy();
  void Reset();  // the frame that used these chunks has completed
  bool Allocate(VkDeviceSize size, VkDeviceSize align, RingAlloc* out);
  // Hot path of Allocate (one per constant-buffer Map): succeeds only when the
  // current chunk has room. `align` is a power of two (all callers; Vulkan
  // guarantees it for minUniformBufferOffsetAlignment).
  bool TryAllocate(VkDeviceSize size, VkDeviceSize align, RingAlloc* out) {
    if (current_ >= chunks_.size() || size == 0) return false;
    const Chunk& c = chunks_[current_];
    const VkDeviceSize off = (offset_ + align - 1) & ~(align - 1);
    if (off + size > c.size) return false;
    out->buffer = c.buffer;
    out->offset = off;
    out->ptr = c.ptr + off;
    offset_ = off + size;
    return true;
  }
  uint64_t bytesAllocated = 0;

 private:
  bool NewChunk(VkDeviceSize minSize);
  DeviceImpl* dev_ = nullptr;
  std::vector<Chunk> chunks_;
  size_t current_ = 0;
  VkDeviceSize offset_ = 0;
};

// ---------------------------------------------------------------------------
// Resources (Resources.cpp)
class BufferImpl final : public Child<Buffer> {
 public:
  BufferImpl(DeviceImpl* d, const BUFFER_DESC& desc);
  ~BufferImpl() override;
  RESOURCE_DIMENSION GetType() const override { return RESOURCE_DIMENSION_BUFFER; }
  void GetDesc(BUFFER_DESC* desc) const override {
    if (desc) *desc = desc_;
  }
  void OnDebugName() override;

  // Ensures the ring holds this frame's copy of a constant buffer.
  inline void EnsureUploaded();
  // Map(WRITE_DISCARD) of a DYNAMIC constant buffer writes straight into a
  // ring slice; the shadow is refreshed from it only when the slice is about
  // to die (frame end) or when a partial write needs the old contents.
  void SyncShadow() {
    if (!shadowStale) return;
    std::memcpy(shadow.data(), ring.ptr, desc_.ByteWidth);
    shadowStale = false;
  }

  BUFFER_DESC desc_;
  bool isConstant = false;  // CPU shadow + ring copy
  bool isDynamicConstant = false;  // isConstant && USAGE_DYNAMIC: Map(WRITE_DISCARD) hot path
  bool shadowStale = false;  // `ring` (this frame) is newer than `shadow`
  bool isRing = false;      // DYNAMIC vertex/index buffer living in the ring
  std::vector<uint8_t> shadow;
  RingAlloc ring{};
  uint64_t ringSerial = 0;  // frame serial of `ring` (0 = none)
  // Device-local or staging storage.
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  uint8_t* mapped = nullptr;  // staging buffers
  SyncState sync;
  uint64_t lastUseSerial = 0;
  uint64_t lastWriteSerial = 0;
};

struct SubresourceLayout {  // staging textures: where a subresource lives in the buffer
  VkDeviceSize offset;
  uint32_t rowPitch, rows, width, height;
};

struct TextureImage {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  bool owned = true;
  std::vector<SyncState> sync;  // per subresource (layer * mips + mip)
};

// Shared by Texture1D/Texture2D (1-D textures are stored with Height = 1).
struct TextureCore {
  RESOURCE_DIMENSION dim = RESOURCE_DIMENSION_TEXTURE2D;
  TEXTURE2D_DESC desc{};
  const FormatInfo* fmt = nullptr;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  std::vector<TextureImage> images;  // swap-chain proxies have several
  uint32_t current = 0;
  bool staging = false;
  VkBuffer stagingBuffer = VK_NULL_HANDLE;
  VkDeviceMemory stagingMemory = VK_NULL_HANDLE;
  uint8_t* mapped = nullptr;
  std::vector<SubresourceLayout> subs;
  SyncState stagingSync;
  RingAlloc mapRing{};  // DYNAMIC textures: slice being written
  uint64_t lastUseSerial = 0;
  uint64_t lastWriteSerial = 0;
  int boundAsTarget = 0;  // number of OM bindings
  class SwapChainImplBase* swapChain = nullptr;
  std::vector<struct ViewCore*> registeredViews;  // swap-chain proxies: views to rebuild
  uint64_t uid = 0;

  uint32_t MipLevels() const { return desc.MipLevels; }
  uint32_t SubCount() const { return desc.MipLevels * desc.ArraySize; }
  TextureImage& Cur() { return images[current]; }
  uint32_t MipWidth(uint32_t m) const { return std::max(1u, desc.Width >> m); }
  uint32_t MipHeight(uint32_t m) const { return std::max(1u, desc.Height >> m); }
};

template <class Iface, RESOURCE_DIMENSION Dim>
class TextureImpl final : public Child<Iface> {
 public:
  explicit TextureImpl(DeviceImpl* d) : Child<Iface>(d) { core.dim = Dim; core.uid = this->uid(); }
  ~TextureImpl() override;
  RESOURCE_DIMENSION GetType() const override { return Dim; }
  void OnDebugName() override;
  TextureCore core;

  template <class D>
  void FillDesc(D* d) const;
  void GetDesc(std::conditional_t<Dim == RESOURCE_DIMENSION_TEXTURE1D, TEXTURE1D_DESC,
                                  TEXTURE2D_DESC>* desc) const override {
    if (desc) FillDesc(desc);
  }
};
using Texture2DImpl = TextureImpl<Texture2D, RESOURCE_DIMENSION_TEXTURE2D>;
using Texture1DImpl = TextureImpl<Texture1D, RESOURCE_DIMENSION_TEXTURE1D>;

bool CreateTextureImage(DeviceImpl* dev, TextureCore& core, TextureImage* out);
TextureCore* AsTexture(Resource* r);

// ---------------------------------------------------------------------------
// Views (Views.cpp)
struct ViewCore {
  Resource* resource = nullptr;  // holds a reference
  TextureCore* tex = nullptr;
  VkFormat format = VK_FORMAT_UNDEFINED;
  DXGI_FORMAT dxgiFormat = DXGI_FORMAT_UNKNOWN;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  uint32_t baseMip = 0, mipCount = 1, baseLayer = 0, layerCount = 1;
  std::vector<VkImageView> views;  // one per image of the texture
  VkImageView Current() const { return views[tex->current]; }
};

enum class ViewKind { SRV, RTV, DSV };
// (Re)creates the VkImageViews of a view, one per image of its texture.
bool RebuildViews(DeviceImpl* dev, ViewCore& v);


template <class Iface, ViewKind Kind>
class ViewImpl final : public Child<Iface> {
 public:
  explicit ViewImpl(DeviceImpl* d) : Child<Iface>(d) {}
  ~ViewImpl() override;
  void GetResource(Resource** r) const override {
    if (!r) return;
    *r = v.resource;
    if (*r) (*r)->AddRef();
  }
  void OnDebugName() override;
  ViewCore v;
};
using SRVImpl = ViewImpl<ShaderResourceView, ViewKind::SRV>;
using RTVImpl = ViewImpl<RenderTargetView, ViewKind::RTV>;
using DSVImpl = ViewImpl<DepthStencilView, ViewKind::DSV>;

// ---------------------------------------------------------------------------
// States (States.cpp)
class SamplerImpl final : public Child<SamplerState> {
 public:
  using Child::Child;
  ~SamplerImpl() override;
  void GetDesc(SAMPLER_DESC* d) const override {
    if (d) *d = desc;
  }
  void OnDebugName() override;
  SAMPLER_DESC desc{};
  VkSampler sampler = VK_NULL_HANDLE;
};

class BlendImpl final : public Child<BlendState> {
 public:
  using Child::Child;
  void GetDesc(BLEND_DESC* d) const override {
    if (d) *d = desc;
  }
  BLEND_DESC desc{};
  VkPipelineColorBlendAttachmentState att[SIMULTANEOUS_RENDER_TARGET_COUNT]{};
};

class DepthStencilImpl final : public Child<DepthStencilState> {
 public:
  using Child::Child;
  void GetDesc(DEPTH_STENCIL_DESC* d) const override {
    if (d) *d = desc;
  }
  DEPTH_STENCIL_DESC desc{};
  VkPipelineDepthStencilStateCreateInfo ci{};
};

class RasterizerImpl final : public Child<RasterizerState> {
 public:
  using Child::Child;
  void GetDesc(RASTERIZER_DESC* d) const override {
    if (d) *d = desc;
  }
  RASTERIZER_DESC desc{};
  VkPipelineRasterizationStateCreateInfo ci{};
};

void FillBlendState(const BLEND_DESC& d, VkPipelineColorBlendAttachmentState* out);
void FillDepthState(const DEPTH_STENCIL_DESC& d, VkPipelineDepthStencilStateCreateInfo* out);
void FillRasterState(const RASTERIZER_DESC& d, bool depthClamp,
                     VkPipelineRasterizationStateCreateInfo* out);

// ---------------------------------------------------------------------------
// Shaders (Shaders.cpp)
struct ReflectedBinding {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  uint32_t blockSize = 0;  // uniform buffers: bytes declared by the shader
  bool image1D = false;    // sampled images: Texture1D
  std::string name;
};
struct ReflectedInput {
  uint32_t location = 0;
  std::string semantic;  // upper case, without the trailing index
  uint32_t index = 0;
};
struct ShaderReflection {
  VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
  std::string entry;
  std::vector<ReflectedBinding> bindings;
  std::vector<ReflectedInput> inputs;  // vertex shaders
  uint32_t outputLocations = 0;        // bit mask
};
// Parses SPIR-V words. Returns false with a message for malformed code.
bool ReflectSpirv(const uint32_t* words, size_t wordCount, ShaderReflection* out,
                  std::string* error);

template <class Iface>
class ShaderImpl final : public Child<Iface> {
 public:
  using Child<Iface>::Child;
  ~ShaderImpl() override;
  void OnDebugName() override;
  VkShaderModule module = VK_NULL_HANDLE;
  ShaderReflection refl;
};
using VertexShaderImpl = ShaderImpl<VertexShader>;
using PixelShaderImpl = ShaderImpl<PixelShader>;

class InputLayoutImpl final : public Child<InputLayout> {
 public:
  using Child::Child;
  struct Element {
    std::string semantic;  // upper case
    uint32_t index;
    VkFormat format;
    uint32_t slot;
    uint32_t offset;
    bool perInstance;
  };
  std::vector<Element> elements;
  uint32_t slotMask = 0;
};

// ---------------------------------------------------------------------------
// Pipeline cache (PipelineCache.cpp)
struct ProgramLayout {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  struct Slot {
    uint16_t binding;
    uint8_t stage;  // 0 VS, 1 PS
    uint8_t slot;
    uint8_t image1D;
  };
  std::vector<Slot> cbs, srvs, samplers;  // sorted by binding
};

struct PipelineKey {
  uint64_t vs, ps, il, blend, depth, raster;
  uint32_t topologyClass, numRT;
  VkFormat rt[SIMULTANEOUS_RENDER_TARGET_COUNT];
  VkFormat ds;
  uint32_t pad;
  bool operator==(const PipelineKey& o) const { return std::memcmp(this, &o, sizeof(*this)) == 0; }
};
struct PipelineKeyHash {
  size_t operator()(const PipelineKey& k) const;
};

struct PipelineInputs {  // objects behind a key, for creation
  VertexShaderImpl* vs;
  PixelShaderImpl* ps;
  InputLayoutImpl* il;
  BlendImpl* blend;
  DepthStencilImpl* depth;
  RasterizerImpl* raster;
  PRIMITIVE_TOPOLOGY topology;
};

class PipelineCache {
 public:
  void Init(DeviceImpl* dev) { dev_ = dev; }
  void Destroy();
  ProgramLayout* GetProgram(VertexShaderImpl* vs, PixelShaderImpl* ps);
  VkPipeline GetPipeline(const PipelineKey& key, const PipelineInputs& in, ProgramLayout* prog);
  void ForgetShader(uint64_t uid);

 private:
  DeviceImpl* dev_ = nullptr;
  std::unordered_map<uint64_t, std::unique_ptr<ProgramLayout>> programs_;  // key vs^ps
  std::unordered_map<PipelineKey, VkPipeline, PipelineKeyHash> pipelines_;
  std::vector<std::pair<uint64_t, uint64_t>> programIds_;
};

// ---------------------------------------------------------------------------
// Frames (Frame.cpp)
struct Garbage {
  VkObjectType type;
  uint64_t handle;
};

class QueryImpl;

struct FrameSlot {
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkCommandBuffer uploadCmd = VK_NULL_HANDLE;
  bool uploadUsed = false;
  VkFence fence = VK_NULL_HANDLE;
  uint64_t serial = 0;  // frame recorded in this slot
  bool submitted = false;
  std::vector<Garbage> garbage;
  ConstantRing ring;
  std::vector<VkDescriptorPool> descPools;
  size_t descPoolCurrent = 0;
  VkQueryPool queryPool = VK_NULL_HANDLE;
  uint32_t queriesUsed = 0;
  std::vector<QueryImpl*> queries;  // referenced until resolved
  VkSemaphore acquireSemaphore = VK_NULL_HANDLE;
};

// ---------------------------------------------------------------------------
class SwapChainImplBase {
 public:
  virtual ~SwapChainImplBase() = default;
};
// Creates a back-buffer proxy texture (RTV + SRV + copy source) with `count`
// owned images; swap chains replace/extend its images.
Texture2DImpl* CreateBackBufferProxy(DeviceImpl* dev, uint32_t w, uint32_t h, DXGI_FORMAT format,
                                     uint32_t count, SwapChainImplBase* owner);

// ---------------------------------------------------------------------------
// Device (VkDevice.cpp)
class DeviceImpl final : public Device {
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
  HRESULT CreateInputLayout(const INPUT_ELEMENT_DESC*, UINT, const void*, size_t,
                            InputLayout**) override;
  HRESULT CreateQuery(const QUERY_DESC*, Query**) override;
  HRESULT CreateSwapChainForWindow(GLFWwindow*, const SWAP_CHAIN_DESC*, SwapChain**) override;
  HRESULT CreateHeadlessSwapChain(const SWAP_CHAIN_DESC*, SwapChain**) override;
  void GetImmediateContext(DeviceContext** context) override;
  void GetAdapterDesc(ADAPTER_DESC* desc) const override { if (desc) *desc = adapter_; }
  void GetStats(DEVICE_STATS* stats) const override;
  bool CheckFormatSupport(DXGI_FORMAT format, UINT bindFlags) const override;
  void WaitIdle() override;

  // Logging
  void Log(LogLevel level, const char* fmt, ...) __attribute__((format(printf, 3, 4)));
  void OnValidationMessage(const char* msg);

  // Memory
  bool AllocateMemory(const VkMemoryRequirements& req, VkMemoryPropertyFlags want,
                      VkMemoryPropertyFlags fallback, VkDeviceMemory* out,
                      VkMemoryPropertyFlags* got = nullptr);
  bool CreateBufferRaw(VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                       VkBuffer* buf, VkDeviceMemory* mem, uint8_t** mapped);
  void SetName(VkObjectType type, uint64_t handle, const std::string& name);

  // Deferred destruction (Frame.cpp)
  void Defer(VkObjectType type, uint64_t handle);
  void DestroyNow(const Garbage& g);
  void ChildCreated() { ++internalRefs_; }
  void ChildDestroyed();

  // Frames (Frame.cpp)
  void InitFrames();
  void DestroyFrames();
  VkCommandBuffer Cmd() const { return frames_[slot_].cmd; }
  VkCommandBuffer UploadCmd();  // begun lazily, submitted before Cmd()
  FrameSlot& Frame() { return frames_[slot_]; }
  uint64_t CurrentSerial() const { return serial_; }
  uint64_t CompletedSerial();  // polls fences
  // Ends and submits the current frame, then begins the next one.
  void SubmitFrame(const std::vector<VkSemaphore>& wait = {},
                   const std::vector<VkSemaphore>& signal = {});
  void WaitForSerial(uint64_t serial);
  // Semaphores the next submission waits for (swap-chain acquires).
  void AddPendingWait(VkSemaphore s) { pendingWaits_.push_back(s); }
  inline bool AllocateRing(VkDeviceSize size, VkDeviceSize align, RingAlloc* out);
  VkDescriptorSet AllocateSet(VkDescriptorSetLayout layout);
  bool AllocateTimestamp(QueryImpl* q, uint32_t* index);

  // Accessors
  VkDevice vk() const { return device_; }
  VkPhysicalDevice phys() const { return phys_; }
  VkInstance instance() const { return instance_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  ContextImpl* context() const { return context_.get(); }
  PipelineCache& pipelines() { return pipelines_; }
  const VkPhysicalDeviceProperties& props() const { return props_; }
  VkDeviceSize uboAlign() const { return uboAlign_; }
  bool hasDebugUtils() const { return debugUtils_; }
  bool hasMinmax() const { return minmax_; }
  bool hasDepthClamp() const { return depthClamp_; }
  bool hasSwapchain() const { return swapchainExt_; }
  uint32_t framesInFlight() const { return static_cast<uint32_t>(frames_.size()); }
  uint64_t NextUid() { return ++uidCounter_; }

  // Dummies bound where the shader expects a resource but none is bound.
  VkBuffer dummyUniform = VK_NULL_HANDLE;
  VkDeviceSize dummyUniformSize = 0;
  VkImageView dummyImageView2D = VK_NULL_HANDLE, dummyImageView1D = VK_NULL_HANDLE;
  VkSampler dummySampler = VK_NULL_HANDLE;
  VkBuffer dummyVertex = VK_NULL_HANDLE;

  DEVICE_STATS stats{};
  uint64_t objectsDestroyed = 0;
  PFN_vkCmdBeginDebugUtilsLabelEXT cmdBeginLabel = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT cmdEndLabel = nullptr;
  PFN_vkSetDebugUtilsObjectNameEXT setObjectName = nullptr;
  PFN_vkQueueBeginDebugUtilsLabelEXT queueBeginLabel = nullptr;

 private:
  bool CreateInstance(const DEVICE_CREATE_DESC& desc, ValidationMode mode);
  bool PickAdapter(const DEVICE_CREATE_DESC& desc);
  bool CreateLogicalDevice();
  bool CreateDummies();
  void BeginFrame();
  void RecycleSlot(FrameSlot& f);
  void Shutdown();

  std::atomic<UINT> externalRefs_{1};
  std::atomic<UINT> internalRefs_{0};
  bool orphaned_ = false;
  LogCallback log_ = nullptr;
  void* logUser_ = nullptr;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice phys_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkPhysicalDeviceProperties props_{};
  VkPhysicalDeviceMemoryProperties memProps_{};
  VkDeviceSize uboAlign_ = 256;
  bool debugUtils_ = false, minmax_ = false, depthClamp_ = false, swapchainExt_ = false;
  bool surfaceExt_ = false;  // VK_KHR_surface enabled on the instance
  bool anisotropy_ = false, bc_ = false, fillNonSolid_ = false, mirrorOnce_ = false;
  ADAPTER_DESC adapter_{};
  std::unique_ptr<ContextImpl> context_;
  PipelineCache pipelines_;
  std::vector<FrameSlot> frames_;
  uint32_t slot_ = 0;
  uint64_t serial_ = 1;
  std::vector<VkSemaphore> pendingWaits_;
  uint64_t completed_ = 0;
  std::atomic<uint64_t> uidCounter_{0};
  std::vector<Garbage> dummyGarbage_;
  bool shuttingDown_ = false;
  bool AllocateRingSlow(VkDeviceSize size, VkDeviceSize align, RingAlloc* out);

 public:
  bool anisotropy() const { return anisotropy_; }
  bool mirrorOnce() const { return mirrorOnce_; }
  bool fillModeNonSolid() const { return fillNonSolid_; }
  bool supportsBC() const { return bc_; }
};

std::string ToUpper(const char* s);

// Hot-path helpers, inline because they run once per draw.
inline bool DeviceImpl::AllocateRing(VkDeviceSize size, VkDeviceSize align, RingAlloc* out) {
  if (frames_[slot_].ring.TryAllocate(size, align, out)) return true;
  return AllocateRingSlow(size, align, out);  // a new chunk: keeps the stats
}

inline void BufferImpl::EnsureUploaded() {
  if (ringSerial == dev_->CurrentSerial()) return;
  RingAlloc a;
  if (!dev_->AllocateRing(desc_.ByteWidth, dev_->uboAlign(), &a)) return;
  std::memcpy(a.ptr, shadow.data(), desc_.ByteWidth);
  ring = a;
  ringSerial = dev_->CurrentSerial();
}

inline BufferImpl* AsBuffer(Resource* r) {
  if (!r || r->GetType() != RESOURCE_DIMENSION_BUFFER) return nullptr;
  return static_cast<BufferImpl*>(static_cast<Buffer*>(r));
}

}  // namespace d3dl::impl
