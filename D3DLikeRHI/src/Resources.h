// Buffers and textures (Resources.cpp, Textures.cpp): where their data lives
// and the synchronisation state of their Vulkan objects.
#pragma once

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <vector>

#include "Formats.h"
#include "Objects.h"
#include "Ring.h"
#include "Sync.h"

namespace d3dl::impl {

// Where a resource's data lives, decided once at creation from its Usage and
// BindFlags. Map, Unmap, UpdateSubresource and the copies switch over it.
enum class Storage : uint8_t {
  DeviceLocal,       // own VkBuffer / VkImage in device memory (DEFAULT, IMMUTABLE)
  Staging,           // host-visible, persistently mapped buffer (STAGING)
  Ring,              // DYNAMIC vertex/index buffers: a ring slice per WRITE_DISCARD;
                     // DYNAMIC textures: an image written from a ring slice at Unmap
  Constants,         // constant buffers: a CPU shadow, copied into the ring once per frame
  DynamicConstants,  // DYNAMIC constant buffers: also Map(WRITE_DISCARD) into a ring slice
};

// Frames that last used and last wrote a resource (0 = never): what a
// CPU access has to wait for.
struct GpuUse {
  uint64_t lastUse = 0;
  uint64_t lastWrite = 0;
  void Read(uint64_t serial) { lastUse = serial; }
  void Write(uint64_t serial) { lastUse = lastWrite = serial; }
};

class BufferImpl final : public Child<Buffer> {
 public:
  BufferImpl(DeviceImpl* d, const BUFFER_DESC& desc);
  ~BufferImpl() override;
  RESOURCE_DIMENSION GetType() const override { return RESOURCE_DIMENSION_BUFFER; }
  void GetDesc(BUFFER_DESC* desc) const override {
    if (desc) *desc = desc_;
  }
  void OnDebugName() override;
  // Creates the storage and writes the initial data (`init` may be null).
  HRESULT Init(const SUBRESOURCE_DATA* init);

  const BUFFER_DESC& desc() const { return desc_; }
  UINT size() const { return desc_.ByteWidth; }
  Storage storage() const { return storage_; }
  bool IsConstantBuffer() const {
    return storage_ == Storage::Constants || storage_ == Storage::DynamicConstants;
  }
  bool HasBindFlag(BIND_FLAG f) const { return (desc_.BindFlags & f) != 0; }

  // DeviceLocal and Staging storage: the buffer's own VkBuffer.
  VkBuffer vkBuffer() const { return buffer_; }
  SyncState& sync() { return sync_; }
  uint8_t* mapped() const { return mapped_; }  // Staging
  GpuUse use;

  // Ring storage: a constant buffer's copy for this frame, or the data of a
  // DYNAMIC buffer's last WRITE_DISCARD.
  const RingAlloc& ring() const { return ring_; }
  bool RingFromFrame(uint64_t serial) const { return ringSerial_ == serial; }
  // A fresh slice in this frame's ring; false (slice kept) when out of memory.
  inline bool NewRingSlice(VkDeviceSize align);

  // Constant buffers: the CPU shadow keeps the contents across frames (the
  // ring slices are recycled); EnsureUploaded copies it into this frame's ring.
  inline void EnsureUploaded();
  uint8_t* shadow() { return shadow_.data(); }
  void ShadowChanged() { ringSerial_ = 0; }  // copied into the ring again at the next draw
  // Map(WRITE_DISCARD) of a DYNAMIC constant buffer writes straight into a
  // ring slice; the shadow is refreshed from it only when the slice is about
  // to die (frame end) or when a partial write needs the old contents.
  bool shadowStale() const { return shadowStale_; }
  void MarkShadowStale() { shadowStale_ = true; }
  // In the immediate context's list of buffers discarded this frame (the
  // shadow may be synced earlier, by a list's execution or a partial write,
  // while the entry stays: the destructor must remove it then too).
  bool discardListed() const { return discardListed_; }
  void SetDiscardListed(bool listed) { discardListed_ = listed; }
  void SyncShadow() {
    if (!shadowStale_) return;
    std::memcpy(shadow_.data(), ring_.ptr, desc_.ByteWidth);
    shadowStale_ = false;
  }

 private:
  HRESULT InitDeviceLocal(const SUBRESOURCE_DATA* init);

  BUFFER_DESC desc_;
  Storage storage_;
  std::vector<uint8_t> shadow_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  uint8_t* mapped_ = nullptr;
  SyncState sync_;
  // What the immediate context writes at every Map(WRITE_DISCARD) and draw of
  // a DYNAMIC constant buffer, on a cache line of its own: deferred contexts
  // on other threads map the same buffer and read its description at every
  // draw, and a store to their line would take it from them each time.
  alignas(64) RingAlloc ring_{};
  uint64_t ringSerial_ = 0;   // frame serial of `ring_` (0 = none)
  bool shadowStale_ = false;  // `ring_` (this frame) is newer than `shadow_`
  bool discardListed_ = false;
};

inline BufferImpl* AsBuffer(Resource* r) {
  if (!r || r->GetType() != RESOURCE_DIMENSION_BUFFER) return nullptr;
  return static_cast<BufferImpl*>(static_cast<Buffer*>(r));
}

// ---------------------------------------------------------------------------
struct SubresourceLayout {  // staging textures: where a subresource lives in the buffer
  VkDeviceSize offset;
  uint32_t rowPitch, rows, width, height;
};

// A STAGING texture's data: one linear host-visible buffer with a tightly
// packed region per subresource.
struct StagingBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  uint8_t* mapped = nullptr;
  std::vector<SubresourceLayout> subs;
  SyncState sync;
};

struct TextureImage {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  bool owned = true;
  std::vector<SyncState> sync;  // per subresource (layer * mips + mip)
};

struct SubIndex {
  uint32_t mip = 0, layer = 0;
};

class SwapChainImplBase;
struct ViewCore;

// Shared by Texture1D/Texture2D (1-D textures are stored with Height = 1).
struct TextureCore {
  RESOURCE_DIMENSION dim = RESOURCE_DIMENSION_TEXTURE2D;
  TEXTURE2D_DESC desc{};
  const FormatInfo* fmt = nullptr;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  Storage storage = Storage::DeviceLocal;
  std::vector<TextureImage> images;  // swap-chain proxies have several
  uint32_t current = 0;
  StagingBuffer staging;  // Storage::Staging
  RingAlloc mapRing{};    // Storage::Ring: the slice written between Map and Unmap
  GpuUse use;
  SwapChainImplBase* swapChain = nullptr;
  std::vector<ViewCore*> registeredViews;  // swap-chain proxies: views to rebuild
  uint64_t uid = 0;

  bool IsStaging() const { return storage == Storage::Staging; }
  uint32_t MipLevels() const { return desc.MipLevels; }
  uint32_t SubCount() const { return desc.MipLevels * desc.ArraySize; }
  TextureImage& Cur() { return images[current]; }
  uint32_t MipWidth(uint32_t m) const { return std::max(1u, desc.Width >> m); }
  uint32_t MipHeight(uint32_t m) const { return std::max(1u, desc.Height >> m); }
  // D3D11 subresource index -> mip and array layer; false when out of range.
  bool DecodeSub(UINT sub, SubIndex* out) const {
    if (sub >= SubCount()) return false;
    out->mip = sub % desc.MipLevels;
    out->layer = sub / desc.MipLevels;
    return true;
  }
};

template <class Iface, RESOURCE_DIMENSION Dim>
class TextureImpl final : public Child<Iface> {
 public:
  explicit TextureImpl(DeviceImpl* d) : Child<Iface>(d) {
    core.dim = Dim;
    core.uid = this->uid();
  }
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

// Creates one device image for the texture's description (with its memory).
bool CreateTextureImage(DeviceImpl* dev, TextureCore& core, TextureImage* out);
// Sample counts the adapter allows for an image of this description (its
// format, bind flags and cube flag): vkGetPhysicalDeviceImageFormatProperties.
VkSampleCountFlags ImageSampleCounts(DeviceImpl* dev, const TEXTURE2D_DESC& d);
TextureCore* AsTexture(Resource* r);

}  // namespace d3dl::impl
