// Buffers: the storage chosen from the description, initial data, and
// destruction into the deferred list. CreateBuffer checks its arguments with
// ValidateCreateBuffer first.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {
namespace {
constexpr VkBufferUsageFlags kDeviceBufferUsage =
    VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
    VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;  // SRV/UAV, indirect arguments
constexpr VkBufferUsageFlags kStagingUsage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

Storage StorageOf(const BUFFER_DESC& d) {
  if (d.BindFlags & BIND_CONSTANT_BUFFER)
    return d.Usage == USAGE_DYNAMIC ? Storage::DynamicConstants : Storage::Constants;
  if (d.Usage == USAGE_DYNAMIC) return Storage::Ring;
  if (d.Usage == USAGE_STAGING) return Storage::Staging;
  return Storage::DeviceLocal;
}
}  // namespace

BufferImpl::BufferImpl(DeviceImpl* d, const BUFFER_DESC& desc) : Child(d), desc_(desc), storage_(StorageOf(desc)) {}

BufferImpl::~BufferImpl() {
  if (discardListed_ && dev_->context()) dev_->context()->ForgetDiscardedConstants(this);
  dev_->Defer(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer_));
  dev_->Defer(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(memory_));
}

void BufferImpl::OnDebugName() { dev_->SetName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer_), name_); }

HRESULT BufferImpl::Init(const SUBRESOURCE_DATA* init) {
  const void* data = init ? init->pSysMem : nullptr;
  const UINT size = desc_.ByteWidth;
  switch (storage_) {
    case Storage::Constants:
    case Storage::DynamicConstants:
      shadow_.assign(size, 0);
      if (data) std::memcpy(shadow_.data(), data, size);
      return S_OK;
    case Storage::Ring:
      if (!data) return S_OK;
      if (!NewRingSlice(16)) return E_OUTOFMEMORY;
      std::memcpy(ring_.ptr, data, size);
      return S_OK;
    case Storage::Staging:
      if (!dev_->CreateBufferRaw(size, kStagingUsage, true, &buffer_, &memory_, &mapped_)) return E_OUTOFMEMORY;
      if (data) std::memcpy(mapped_, data, size);
      return S_OK;
    case Storage::DeviceLocal: break;
  }
  return InitDeviceLocal(init);
}

// A device-local buffer; initial data is staged in the ring and copied by the
// frame's upload command buffer.
HRESULT BufferImpl::InitDeviceLocal(const SUBRESOURCE_DATA* init) {
  const UINT size = desc_.ByteWidth;
  if (!dev_->CreateBufferRaw(size, kDeviceBufferUsage, false, &buffer_, &memory_, nullptr)) return E_OUTOFMEMORY;
  if (!init) return S_OK;
  RingAlloc a;
  if (!dev_->AllocateRing(size, 16, &a)) return E_OUTOFMEMORY;
  std::memcpy(a.ptr, init->pSysMem, size);
  VkBufferCopy region{a.offset, 0, size};
  vkCmdCopyBuffer(dev_->UploadCmd(), a.buffer, buffer_, 1, &region);
  // The upload batch ends with a barrier to ALL_COMMANDS (Queue.cpp).
  sync_.pending = true;
  sync_.writeStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  sync_.visible = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  return S_OK;
}

HRESULT DeviceImpl::CreateBuffer(const BUFFER_DESC* desc, const SUBRESOURCE_DATA* init, Buffer** out) {
  if (out) *out = nullptr;
  const HRESULT valid = ValidateCreateBuffer(*this, desc, init, out);
  if (FAILED(valid)) return valid;
  auto* b = new BufferImpl(this, *desc);
  const HRESULT hr = b->Init(init);
  if (FAILED(hr)) {
    b->Release();
    return hr;
  }
  *out = b;
  return S_OK;
}

ResourceInfo DescribeResource(Resource* r) {
  ResourceInfo info;
  if (const BufferImpl* b = AsBuffer(r)) {
    const BUFFER_DESC& d = b->desc();
    info.dimension = RESOURCE_DIMENSION_BUFFER;
    info.byteWidth = d.ByteWidth;
    info.structureStride = d.StructureByteStride;
    info.usage = d.Usage;
    info.bindFlags = d.BindFlags;
    info.cpuAccessFlags = d.CPUAccessFlags;
    info.miscFlags = d.MiscFlags;
  } else if (const TextureCore* t = AsTexture(r)) {
    const TEXTURE2D_DESC& d = t->desc;
    info.dimension = t->dim;
    info.format = d.Format;
    info.width = d.Width;
    info.height = d.Height;
    info.arraySize = d.ArraySize;
    info.mipLevels = d.MipLevels;
    info.samples = d.SampleDesc.Count;
    info.usage = d.Usage;
    info.bindFlags = d.BindFlags;
    info.cpuAccessFlags = d.CPUAccessFlags;
    info.miscFlags = d.MiscFlags;
    info.depth = (t->aspect & VK_IMAGE_ASPECT_DEPTH_BIT) != 0;
    info.stencil = (t->aspect & VK_IMAGE_ASPECT_STENCIL_BIT) != 0;
  }
  return info;
}

}  // namespace d3dl::impl
