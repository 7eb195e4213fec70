// Buffers and textures: creation (with validation of the description),
// initial uploads through the ring, destruction into the deferred list.
#include "Context.h"

namespace d3dl::impl {
namespace {
constexpr VkBufferUsageFlags kDeviceBufferUsage =
    VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
    VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

uint32_t FullMipCount(uint32_t w, uint32_t h) {
  uint32_t m = 1;
  while (w > 1 || h > 1) {
    w = std::max(1u, w / 2);
    h = std::max(1u, h / 2);
    ++m;
  }
  return m;
}

// Rows/pitch of one subresource in a linear buffer (blocks for BC formats).
void LinearLayout(const FormatInfo* f, uint32_t w, uint32_t h, uint32_t* rowPitch,
                  uint32_t* rows) {
  if (f->bc) {
    *rowPitch = ((w + 3) / 4) * f->bytes;
    *rows = (h + 3) / 4;
  } else {
    *rowPitch = w * f->bytes;
    *rows = h;
  }
}
}  // namespace

TextureCore* AsTexture(Resource* r) {
  if (!r) return nullptr;
  switch (r->GetType()) {
    case RESOURCE_DIMENSION_TEXTURE2D:
      return &static_cast<Texture2DImpl*>(static_cast<Texture2D*>(r))->core;
    case RESOURCE_DIMENSION_TEXTURE1D:
      return &static_cast<Texture1DImpl*>(static_cast<Texture1D*>(r))->core;
    default:
      return nullptr;
  }
}

// ---------------------------------------------------------------------------
BufferImpl::BufferImpl(DeviceImpl* d, const BUFFER_DESC& desc) : Child(d), desc_(desc) {}

BufferImpl::~BufferImpl() {
  if (shadowStale && dev_->context()) dev_->context()->ForgetDiscardedConstants(this);
  dev_->Defer(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer));
  dev_->Defer(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(memory));
}

void BufferImpl::OnDebugName() { dev_->SetName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer), name_); }

HRESULT DeviceImpl::CreateBuffer(const BUFFER_DESC* desc, const SUBRESOURCE_DATA* init,
                                 Buffer** out) {
  if (out) *out = nullptr;
  if (!desc || !out) {
    Log(LogLevel::Error, "CreateBuffer: %s is null", desc ? "ppBuffer" : "pDesc");
    return E_INVALIDARG;
  }
  const BUFFER_DESC& d = *desc;
  if (d.ByteWidth == 0) {
    Log(LogLevel::Error, "CreateBuffer: ByteWidth is 0");
    return E_INVALIDARG;
  }
  if (d.BindFlags & (BIND_SHADER_RESOURCE | BIND_RENDER_TARGET | BIND_DEPTH_STENCIL)) {
    Log(LogLevel::Error, "CreateBuffer: BindFlags 0x%x: buffer views are not supported", d.BindFlags);
    return E_INVALIDARG;
  }
  const bool isCB = d.BindFlags & BIND_CONSTANT_BUFFER;
  if (isCB && (d.BindFlags & ~static_cast<UINT>(BIND_CONSTANT_BUFFER))) {
    Log(LogLevel::Error, "CreateBuffer: BIND_CONSTANT_BUFFER cannot be combined with other bind flags (0x%x)", d.BindFlags);
    return E_INVALIDARG;
  }
  if (isCB && (d.ByteWidth % 16 != 0 || d.ByteWidth > 65536 ||
               d.ByteWidth > props_.limits.maxUniformBufferRange)) {
    Log(LogLevel::Error, "CreateBuffer: constant buffer ByteWidth %u must be a multiple of 16 and <= 65536", d.ByteWidth);
    return E_INVALIDARG;
  }
  if (d.Usage > USAGE_STAGING) {
    Log(LogLevel::Error, "CreateBuffer: invalid Usage %u", d.Usage);
    return E_INVALIDARG;
  }
  if (d.Usage == USAGE_IMMUTABLE && (!init || !init->pSysMem)) {
    Log(LogLevel::Error, "CreateBuffer: USAGE_IMMUTABLE needs initial data");
    return E_INVALIDARG;
  }
  if (d.Usage == USAGE_DYNAMIC && !(d.CPUAccessFlags & CPU_ACCESS_WRITE)) {
    Log(LogLevel::Error, "CreateBuffer: USAGE_DYNAMIC needs CPU_ACCESS_WRITE");
    return E_INVALIDARG;
  }
  if (d.Usage == USAGE_STAGING && (d.BindFlags || !d.CPUAccessFlags)) {
    Log(LogLevel::Error, "CreateBuffer: USAGE_STAGING needs BindFlags 0 and CPU access (BindFlags 0x%x)", d.BindFlags);
    return E_INVALIDARG;
  }
  if (d.Usage != USAGE_STAGING && d.Usage != USAGE_DYNAMIC && d.CPUAccessFlags) {
    Log(LogLevel::Error, "CreateBuffer: CPUAccessFlags 0x%x need USAGE_DYNAMIC or USAGE_STAGING", d.CPUAccessFlags);
    return E_INVALIDARG;
  }
  if (!isCB && d.Usage != USAGE_STAGING && !(d.BindFlags & (BIND_VERTEX_BUFFER | BIND_INDEX_BUFFER))) {
    Log(LogLevel::Error, "CreateBuffer: BindFlags 0x%x: need a vertex, index or constant buffer binding", d.BindFlags);
    return E_INVALIDARG;
  }
  if (init && !init->pSysMem) {
    Log(LogLevel::Error, "CreateBuffer: pInitialData->pSysMem is null");
    return E_INVALIDARG;
  }

  auto* b = new BufferImpl(this, d);
  if (isCB) {
    b->isConstant = true;
    b->isDynamicConstant = d.Usage == USAGE_DYNAMIC;
    b->shadow.assign(d.ByteWidth, 0);
    if (init) std::memcpy(b->shadow.data(), init->pSysMem, d.ByteWidth);
  } else if (d.Usage == USAGE_DYNAMIC) {
    b->isRing = true;
    if (init) {
      if (!AllocateRing(d.ByteWidth, 16, &b->ring)) {
        b->Release();
        return E_OUTOFMEMORY;
      }
      std::memcpy(b->ring.ptr, init->pSysMem, d.ByteWidth);
      b->ringSerial = serial_;
    }
  } else if (d.Usage == USAGE_STAGING) {
    if (!CreateBufferRaw(d.ByteWidth,
                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, true,
                         &b->buffer, &b->memory, &b->mapped)) {
      b->Release();
      return E_OUTOFMEMORY;
    }
    if (init) std::memcpy(b->mapped, init->pSysMem, d.ByteWidth);
  } else {
    if (!CreateBufferRaw(d.ByteWidth, kDeviceBufferUsage, false, &b->buffer, &b->memory, nullptr)) {
      b->Release();
      return E_OUTOFMEMORY;
    }
    if (init) {
      RingAlloc a;
      if (!AllocateRing(d.ByteWidth, 16, &a)) {
        b->Release();
        return E_OUTOFMEMORY;
      }
      std::memcpy(a.ptr, init->pSysMem, d.ByteWidth);
      VkBufferCopy region{a.offset, 0, d.ByteWidth};
      vkCmdCopyBuffer(UploadCmd(), a.buffer, b->buffer, 1, &region);
      // The upload batch ends with a barrier to ALL_COMMANDS (Frame.cpp).
      b->sync.pending = true;
      b->sync.writeStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
      b->sync.visible = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    }
  }
  *out = b;
  return S_OK;
}

// ---------------------------------------------------------------------------
template <class Iface, RESOURCE_DIMENSION Dim>
TextureImpl<Iface, Dim>::~TextureImpl() {
  for (auto& img : core.images) {
    if (!img.owned) continue;
    this->dev_->Defer(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(img.image));
    this->dev_->Defer(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(img.memory));
  }
  this->dev_->Defer(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(core.stagingBuffer));
  this->dev_->Defer(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(core.stagingMemory));
}

template <class Iface, RESOURCE_DIMENSION Dim>
void TextureImpl<Iface, Dim>::OnDebugName() {
  for (auto& img : core.images)
    this->dev_->SetName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(img.image), this->name_);
  if (core.stagingBuffer)
    this->dev_->SetName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(core.stagingBuffer),
                        this->name_);
}

template <class Iface, RESOURCE_DIMENSION Dim>
template <class D>
void TextureImpl<Iface, Dim>::FillDesc(D* d) const {
  if constexpr (std::is_same_v<D, TEXTURE1D_DESC>) {
    d->Width = core.desc.Width;
    d->MipLevels = core.desc.MipLevels;
    d->ArraySize = core.desc.ArraySize;
    d->Format = core.desc.Format;
    d->Usage = core.desc.Usage;
    d->BindFlags = core.desc.BindFlags;
    d->CPUAccessFlags = core.desc.CPUAccessFlags;
    d->MiscFlags = core.desc.MiscFlags;
  } else {
    *d = core.desc;
  }
}

template class TextureImpl<Texture2D, RESOURCE_DIMENSION_TEXTURE2D>;
template class TextureImpl<Texture1D, RESOURCE_DIMENSION_TEXTURE1D>;

// Validates `d` (fills MipLevels = 0) and sets up the core's format fields.
static HRESULT ValidateTexture(DeviceImpl* dev, TEXTURE2D_DESC& d, bool is1D, TextureCore& core) {
  const char* fn = is1D ? "CreateTexture1D" : "CreateTexture2D";
  const auto& lim = dev->props().limits;
  uint32_t maxDim = is1D ? lim.maxImageDimension1D : lim.maxImageDimension2D;
  if (d.Width == 0 || d.Height == 0 || d.Width > maxDim || d.Height > maxDim) {
    dev->Log(LogLevel::Error, "%s: size %ux%u is invalid (1..%u)", fn, d.Width, d.Height, maxDim);
    return E_INVALIDARG;
  }
  if (d.ArraySize == 0 || d.ArraySize > lim.maxImageArrayLayers) {
    dev->Log(LogLevel::Error, "%s: ArraySize %u is invalid", fn, d.ArraySize);
    return E_INVALIDARG;
  }
  if (d.SampleDesc.Count != 1) {
    dev->Log(LogLevel::Error, "%s: SampleDesc.Count %u: multisampling is not supported", fn, d.SampleDesc.Count);
    return E_INVALIDARG;
  }
  const FormatInfo* f = GetFormatInfo(d.Format);
  if (!f) {
    dev->Log(LogLevel::Error, "%s: Format %u (%s) is not supported", fn, d.Format, FormatName(d.Format));
    return E_INVALIDARG;
  }
  if (f->bc && !dev->supportsBC()) {
    dev->Log(LogLevel::Error, "%s: Format %s: the adapter has no BC support", fn, f->name);
    return DXGI_ERROR_UNSUPPORTED;
  }
  if (f->bc && ((d.Width % 4) || (d.Height % 4)) && !(d.Width < 4 && d.Height < 4)) {
    dev->Log(LogLevel::Error, "%s: %s needs a size multiple of 4 (got %ux%u)", fn, f->name, d.Width, d.Height);
    return E_INVALIDARG;
  }
  uint32_t full = FullMipCount(d.Width, d.Height);
  if (d.MipLevels == 0) d.MipLevels = full;
  if (d.MipLevels > full) {
    dev->Log(LogLevel::Error, "%s: MipLevels %u exceeds the full chain of %u for %ux%u", fn, d.MipLevels, full, d.Width, d.Height);
    return E_INVALIDARG;
  }
  if (d.Usage > USAGE_STAGING) {
    dev->Log(LogLevel::Error, "%s: invalid Usage %u", fn, d.Usage);
    return E_INVALIDARG;
  }
  if (d.Usage == USAGE_STAGING) {
    if (d.BindFlags) {
      dev->Log(LogLevel::Error, "%s: USAGE_STAGING textures cannot have BindFlags (0x%x)", fn, d.BindFlags);
      return E_INVALIDARG;
    }
    if (!(d.CPUAccessFlags & (CPU_ACCESS_READ | CPU_ACCESS_WRITE))) {
      dev->Log(LogLevel::Error, "%s: USAGE_STAGING needs CPUAccessFlags", fn);
      return E_INVALIDARG;
    }
  } else if (d.Usage == USAGE_DYNAMIC) {
    if (!(d.CPUAccessFlags & CPU_ACCESS_WRITE) || (d.CPUAccessFlags & CPU_ACCESS_READ)) {
      dev->Log(LogLevel::Error, "%s: USAGE_DYNAMIC needs CPUAccessFlags = CPU_ACCESS_WRITE (0x%x)", fn, d.CPUAccessFlags);
      return E_INVALIDARG;
    }
  } else if (d.CPUAccessFlags) {
    dev->Log(LogLevel::Error, "%s: CPUAccessFlags 0x%x need USAGE_DYNAMIC or USAGE_STAGING", fn, d.CPUAccessFlags);
    return E_INVALIDARG;
  }
  if (d.BindFlags & (BIND_VERTEX_BUFFER | BIND_INDEX_BUFFER | BIND_CONSTANT_BUFFER)) {
    dev->Log(LogLevel::Error, "%s: BindFlags 0x%x include buffer bindings", fn, d.BindFlags);
    return E_INVALIDARG;
  }
  if ((d.BindFlags & BIND_DEPTH_STENCIL) && (d.BindFlags & BIND_RENDER_TARGET)) {
    dev->Log(LogLevel::Error, "%s: BIND_DEPTH_STENCIL and BIND_RENDER_TARGET together", fn);
    return E_INVALIDARG;
  }
  if ((d.BindFlags & BIND_DEPTH_STENCIL) && d.Format != DXGI_FORMAT_D32_FLOAT &&
      d.Format != DXGI_FORMAT_R32_TYPELESS) {
    dev->Log(LogLevel::Error, "%s: BIND_DEPTH_STENCIL needs D32_FLOAT or R32_TYPELESS (got %s)", fn, f->name);
    return E_INVALIDARG;
  }
  if (f->depth && (d.BindFlags & BIND_RENDER_TARGET)) {
    dev->Log(LogLevel::Error, "%s: %s cannot be a render target", fn, f->name);
    return E_INVALIDARG;
  }
  if ((d.MiscFlags & RESOURCE_MISC_GENERATE_MIPS) &&
      (d.BindFlags & (BIND_RENDER_TARGET | BIND_SHADER_RESOURCE)) !=
          (BIND_RENDER_TARGET | BIND_SHADER_RESOURCE)) {
    dev->Log(LogLevel::Error, "%s: RESOURCE_MISC_GENERATE_MIPS needs BIND_RENDER_TARGET | BIND_SHADER_RESOURCE", fn);
    return E_INVALIDARG;
  }
  if (d.Usage != USAGE_STAGING && !dev->CheckFormatSupport(d.Format, d.BindFlags)) {
    dev->Log(LogLevel::Error, "%s: Format %s does not support BindFlags 0x%x on this adapter", fn, f->name, d.BindFlags);
    return E_INVALIDARG;
  }
  core.desc = d;
  core.fmt = f;
  core.format = f->vk;
  core.aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  if (f->depth || (d.Format == DXGI_FORMAT_R32_TYPELESS && (d.BindFlags & BIND_DEPTH_STENCIL))) {
    core.format = VK_FORMAT_D32_SFLOAT;
    core.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  }
  core.staging = d.Usage == USAGE_STAGING;
  return S_OK;
}

bool CreateTextureImage(DeviceImpl* dev, TextureCore& core, TextureImage* out) {
  const TEXTURE2D_DESC& d = core.desc;
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.imageType = core.dim == RESOURCE_DIMENSION_TEXTURE1D ? VK_IMAGE_TYPE_1D : VK_IMAGE_TYPE_2D;
  ici.format = core.format;
  ici.extent = {d.Width, d.Height, 1};
  ici.mipLevels = d.MipLevels;
  ici.arrayLayers = d.ArraySize;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (d.BindFlags & BIND_SHADER_RESOURCE) ici.usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
  if (d.BindFlags & BIND_RENDER_TARGET) ici.usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if (d.BindFlags & BIND_DEPTH_STENCIL) ici.usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  // SRV/RTV may use the sRGB/UNORM sibling of the format.
  if (!core.fmt->depth && d.Format != DXGI_FORMAT_R32_TYPELESS) ici.flags |= VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
  if (vkCreateImage(dev->vk(), &ici, nullptr, &out->image) != VK_SUCCESS) {
    dev->Log(LogLevel::Error, "vkCreateImage failed for %ux%u %s", d.Width, d.Height, core.fmt->name);
    return false;
  }
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(dev->vk(), out->image, &req);
  if (!dev->AllocateMemory(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, &out->memory)) {
    vkDestroyImage(dev->vk(), out->image, nullptr);
    out->image = VK_NULL_HANDLE;
    return false;
  }
  vkBindImageMemory(dev->vk(), out->image, out->memory, 0);
  out->owned = true;
  out->sync.assign(core.SubCount(), SyncState{});
  return true;
}

static bool CreateStagingStorage(DeviceImpl* dev, TextureCore& core) {
  VkDeviceSize total = 0;
  core.subs.clear();
  for (uint32_t l = 0; l < core.desc.ArraySize; ++l)
    for (uint32_t m = 0; m < core.desc.MipLevels; ++m) {
      SubresourceLayout s{};
      s.width = core.MipWidth(m);
      s.height = core.MipHeight(m);
      LinearLayout(core.fmt, s.width, s.height, &s.rowPitch, &s.rows);
      total = (total + 15) / 16 * 16;
      s.offset = total;
      total += VkDeviceSize(s.rowPitch) * s.rows;
      core.subs.push_back(s);
    }
  return dev->CreateBufferRaw(total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              true, &core.stagingBuffer, &core.stagingMemory, &core.mapped);
}

// Initial data: staged in the ring, copied by the upload command buffer.
static HRESULT UploadInitialData(DeviceImpl* dev, TextureCore& core, const SUBRESOURCE_DATA* init,
                                 const char* fn) {
  const uint32_t subCount = core.SubCount();
  for (uint32_t i = 0; i < subCount; ++i)
    if (!init[i].pSysMem) {
      dev->Log(LogLevel::Error, "%s: pInitialData[%u].pSysMem is null", fn, i);
      return E_INVALIDARG;
    }
  if (core.staging) {
    for (uint32_t i = 0; i < subCount; ++i) {
      const auto& s = core.subs[i];
      uint32_t srcPitch = init[i].SysMemPitch ? init[i].SysMemPitch : s.rowPitch;
      for (uint32_t r = 0; r < s.rows; ++r)
        std::memcpy(core.mapped + s.offset + VkDeviceSize(r) * s.rowPitch,
                    static_cast<const uint8_t*>(init[i].pSysMem) + size_t(r) * srcPitch, s.rowPitch);
    }
    return S_OK;
  }
  VkCommandBuffer cb = dev->UploadCmd();
  TextureImage& img = core.images[0];
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = VK_PIPELINE_STAGE_2_NONE;
  b.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  b.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = img.image;
  b.subresourceRange = {core.aspect, 0, core.desc.MipLevels, 0, core.desc.ArraySize};
  VkDependencyInfo di{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  di.imageMemoryBarrierCount = 1;
  di.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cb, &di);
  for (uint32_t l = 0; l < core.desc.ArraySize; ++l)
    for (uint32_t m = 0; m < core.desc.MipLevels; ++m) {
      uint32_t i = l * core.desc.MipLevels + m;
      uint32_t w = core.MipWidth(m), h = core.MipHeight(m), pitch, rows;
      LinearLayout(core.fmt, w, h, &pitch, &rows);
      uint32_t srcPitch = init[i].SysMemPitch ? init[i].SysMemPitch : pitch;
      if (srcPitch < pitch) {
        dev->Log(LogLevel::Error, "%s: pInitialData[%u].SysMemPitch %u is smaller than a row (%u bytes)", fn, i, srcPitch, pitch);
        return E_INVALIDARG;
      }
      RingAlloc a;
      if (!dev->AllocateRing(VkDeviceSize(pitch) * rows, 16, &a)) return E_OUTOFMEMORY;
      for (uint32_t r = 0; r < rows; ++r)
        std::memcpy(a.ptr + size_t(r) * pitch,
                    static_cast<const uint8_t*>(init[i].pSysMem) + size_t(r) * srcPitch, pitch);
      VkBufferImageCopy region{};
      region.bufferOffset = a.offset;
      region.imageSubresource = {core.aspect, m, l, 1};
      region.imageExtent = {w, h, 1};
      vkCmdCopyBufferToImage(cb, a.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    }
  VkImageLayout finalLayout = (core.desc.BindFlags & BIND_SHADER_RESOURCE)
                                  ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                  : VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  b.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  b.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
  b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.newLayout = finalLayout;
  vkCmdPipelineBarrier2(cb, &di);
  for (auto& s : img.sync) {
    s.layout = finalLayout;
    s.pending = true;
    s.writeStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    s.writeAccess = 0;
    s.visible = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    s.readStages = 0;
  }
  return S_OK;
}

static HRESULT CreateTextureCommon(DeviceImpl* dev, TextureCore& core, TEXTURE2D_DESC d,
                                   const SUBRESOURCE_DATA* init, bool is1D) {
  const char* fn = is1D ? "CreateTexture1D" : "CreateTexture2D";
  HRESULT hr = ValidateTexture(dev, d, is1D, core);
  if (FAILED(hr)) return hr;
  if (d.Usage == USAGE_IMMUTABLE && !init) {
    dev->Log(LogLevel::Error, "%s: USAGE_IMMUTABLE needs initial data", fn);
    return E_INVALIDARG;
  }
  if (core.staging) {
    if (!CreateStagingStorage(dev, core)) return E_OUTOFMEMORY;
  } else {
    core.images.resize(1);
    if (!CreateTextureImage(dev, core, &core.images[0])) return E_OUTOFMEMORY;
  }
  if (init) return UploadInitialData(dev, core, init, fn);
  return S_OK;
}

HRESULT DeviceImpl::CreateTexture2D(const TEXTURE2D_DESC* desc, const SUBRESOURCE_DATA* init,
                                    Texture2D** out) {
  if (out) *out = nullptr;
  if (!desc || !out) {
    Log(LogLevel::Error, "CreateTexture2D: %s is null", desc ? "ppTexture2D" : "pDesc");
    return E_INVALIDARG;
  }
  auto* t = new Texture2DImpl(this);
  HRESULT hr = CreateTextureCommon(this, t->core, *desc, init, false);
  if (FAILED(hr)) {
    t->Release();
    return hr;
  }
  *out = t;
  return S_OK;
}

HRESULT DeviceImpl::CreateTexture1D(const TEXTURE1D_DESC* desc, const SUBRESOURCE_DATA* init,
                                    Texture1D** out) {
  if (out) *out = nullptr;
  if (!desc || !out) {
    Log(LogLevel::Error, "CreateTexture1D: %s is null", desc ? "ppTexture1D" : "pDesc");
    return E_INVALIDARG;
  }
  TEXTURE2D_DESC d;
  d.Width = desc->Width;
  d.Height = 1;
  d.MipLevels = desc->MipLevels;
  d.ArraySize = desc->ArraySize;
  d.Format = desc->Format;
  d.Usage = desc->Usage;
  d.BindFlags = desc->BindFlags;
  d.CPUAccessFlags = desc->CPUAccessFlags;
  d.MiscFlags = desc->MiscFlags;
  if (d.BindFlags & (BIND_DEPTH_STENCIL)) {
    Log(LogLevel::Error, "CreateTexture1D: BIND_DEPTH_STENCIL is not supported for 1-D textures");
    return E_INVALIDARG;
  }
  auto* t = new Texture1DImpl(this);
  HRESULT hr = CreateTextureCommon(this, t->core, d, init, true);
  if (FAILED(hr)) {
    t->Release();
    return hr;
  }
  *out = t;
  return S_OK;
}

}  // namespace d3dl::impl
