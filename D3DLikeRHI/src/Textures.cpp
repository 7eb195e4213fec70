// Textures: device images or staging buffers, initial uploads through the
// ring, destruction into the deferred list. CreateTexture1D/2D check their
// arguments with ValidateCreateTexture first.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {

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

template <class Iface, RESOURCE_DIMENSION Dim>
TextureImpl<Iface, Dim>::~TextureImpl() {
  for (auto& img : core.images) {
    if (!img.owned) continue;
    this->dev_->Defer(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(img.image));
    this->dev_->Defer(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(img.memory));
  }
  this->dev_->Defer(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(core.staging.buffer));
  this->dev_->Defer(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(core.staging.memory));
}

template <class Iface, RESOURCE_DIMENSION Dim>
void TextureImpl<Iface, Dim>::OnDebugName() {
  for (auto& img : core.images)
    this->dev_->SetName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(img.image), this->name_);
  if (core.staging.buffer)
    this->dev_->SetName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(core.staging.buffer), this->name_);
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
// The member template is not part of the class's explicit instantiation:
// GetDesc, defined in the header, may be emitted in any unit.
template void Texture2DImpl::FillDesc<TEXTURE2D_DESC>(TEXTURE2D_DESC*) const;
template void Texture1DImpl::FillDesc<TEXTURE1D_DESC>(TEXTURE1D_DESC*) const;

namespace {
VkImageUsageFlags ImageUsage(const TEXTURE2D_DESC& d) {
  VkImageUsageFlags u = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (d.BindFlags & BIND_SHADER_RESOURCE) u |= VK_IMAGE_USAGE_SAMPLED_BIT;
  if (d.BindFlags & BIND_RENDER_TARGET) u |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if (d.BindFlags & BIND_DEPTH_STENCIL) u |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if (d.BindFlags & BIND_UNORDERED_ACCESS) u |= VK_IMAGE_USAGE_STORAGE_BIT;
  return u;
}
// Colour views may use another member of the format's family (typeless
// groups, sRGB/UNORM); cube maps need CUBE_COMPATIBLE for cube views.
VkImageCreateFlags ImageFlags(VkImageAspectFlags aspect, const TEXTURE2D_DESC& d) {
  VkImageCreateFlags f = 0;
  if (aspect == VK_IMAGE_ASPECT_COLOR_BIT) f |= VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
  if (d.MiscFlags & RESOURCE_MISC_TEXTURECUBE) f |= VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  return f;
}
// The image format and aspect of a texture description.
void ImageFormat(const TEXTURE2D_DESC& d, const FormatInfo& f, VkFormat* format, VkImageAspectFlags* aspect) {
  const VkFormat depth = (d.BindFlags & BIND_DEPTH_STENCIL) || f.depth ? DepthImageFormat(f) : VK_FORMAT_UNDEFINED;
  *format = depth ? depth : f.vk;
  *aspect = !depth ? VK_IMAGE_ASPECT_COLOR_BIT
                   : f.stencil ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT : VK_IMAGE_ASPECT_DEPTH_BIT;
}
}  // namespace

UINT DeviceImpl::SampledSampleCounts(const TEXTURE2D_DESC& d) const {
  return ImageSampleCounts(const_cast<DeviceImpl*>(this), d);
}

VkSampleCountFlags ImageSampleCounts(DeviceImpl* dev, const TEXTURE2D_DESC& d) {
  const FormatInfo* f = GetFormatInfo(d.Format);
  if (!f) return 0;
  VkFormat format;
  VkImageAspectFlags aspect;
  ImageFormat(d, *f, &format, &aspect);
  VkImageFormatProperties p{};
  if (vkGetPhysicalDeviceImageFormatProperties(dev->phys(), format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
                                               ImageUsage(d), ImageFlags(aspect, d), &p) != VK_SUCCESS)
    return 0;
  return p.sampleCounts;
}

// D3D11 reports quality levels per vendor; Vulkan has only the standard
// pattern, so a supported count has exactly one level (Quality 0).
HRESULT DeviceImpl::CheckMultisampleQualityLevels(DXGI_FORMAT format, UINT count, UINT* levels) const {
  if (!levels) {
    const_cast<DeviceImpl*>(this)->Log(LogLevel::Error, "CheckMultisampleQualityLevels: pNumQualityLevels is null");
    return E_INVALIDARG;
  }
  *levels = 0;
  const FormatInfo* f = GetFormatInfo(format);
  if (!f || f->bc || count == 0 || count > 32 || (count & (count - 1))) return f ? S_OK : E_INVALIDARG;
  TEXTURE2D_DESC d;
  d.Format = format;
  d.BindFlags = (f->depth || (f->typeless && f->depthVk)) ? BIND_DEPTH_STENCIL : BIND_RENDER_TARGET;
  if (!CheckFormatSupport(format, d.BindFlags)) return S_OK;
  if (ImageSampleCounts(const_cast<DeviceImpl*>(this), d) & count) *levels = 1;
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
  ici.samples = static_cast<VkSampleCountFlagBits>(d.SampleDesc.Count);
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = ImageUsage(d);
  ici.flags = ImageFlags(core.aspect, d);
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

namespace {

// The description (validated and completed) decides format, aspect and storage.
void SetupCore(TextureCore& core, const TEXTURE2D_DESC& d) {
  core.desc = d;
  core.fmt = GetFormatInfo(d.Format);
  ImageFormat(d, *core.fmt, &core.format, &core.aspect);
  core.storage = d.Usage == USAGE_STAGING   ? Storage::Staging
                 : d.Usage == USAGE_DYNAMIC ? Storage::Ring
                                            : Storage::DeviceLocal;
}

bool CreateStagingStorage(DeviceImpl* dev, TextureCore& core) {
  StagingBuffer& st = core.staging;
  VkDeviceSize total = 0;
  st.subs.clear();
  for (uint32_t l = 0; l < core.desc.ArraySize; ++l)
    for (uint32_t m = 0; m < core.desc.MipLevels; ++m) {
      SubresourceLayout s{};
      s.width = core.MipWidth(m);
      s.height = core.MipHeight(m);
      const LinearSize ls = LinearLayout(*core.fmt, s.width, s.height);
      s.rowPitch = ls.rowPitch;
      s.rows = ls.rows;
      total = (total + 15) / 16 * 16;
      s.offset = total;
      total += VkDeviceSize(s.rowPitch) * s.rows;
      st.subs.push_back(s);
    }
  return dev->CreateBufferRaw(total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, true,
                              &st.buffer, &st.memory, &st.mapped);
}

// Copies `rows` rows of `pitch` bytes from rows `srcPitch` apart.
void CopyRows(uint8_t* dst, VkDeviceSize dstPitch, const void* src, size_t srcPitch, uint32_t pitch, uint32_t rows) {
  for (uint32_t r = 0; r < rows; ++r)
    std::memcpy(dst + VkDeviceSize(r) * dstPitch, static_cast<const uint8_t*>(src) + r * srcPitch, pitch);
}

void UploadToStaging(TextureCore& core, const SUBRESOURCE_DATA* init) {
  for (uint32_t i = 0; i < core.SubCount(); ++i) {
    const SubresourceLayout& s = core.staging.subs[i];
    const uint32_t srcPitch = init[i].SysMemPitch ? init[i].SysMemPitch : s.rowPitch;
    CopyRows(core.staging.mapped + s.offset, s.rowPitch, init[i].pSysMem, srcPitch, s.rowPitch, s.rows);
  }
}

// The whole image from UNDEFINED to TRANSFER_DST before the uploads, and
// to `finalLayout` (visible to all commands) after them.
void RecordUploadBarrier(VkCommandBuffer cb, const TextureCore& core, bool after, VkImageLayout finalLayout) {
  const TransferInit t = TransferInitBarriers(VK_PIPELINE_STAGE_2_COPY_BIT,
                                              VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT, finalLayout);
  const VkImageMemoryBarrier2 b = ImageBarrier(
      core.images[0].image, {core.aspect, 0, core.desc.MipLevels, 0, core.desc.ArraySize}, after ? t.after : t.before);
  RecordImageBarriers(cb, &b, 1);
}

// Initial data: staged in the ring, copied by the upload command buffer.
HRESULT UploadToImage(DeviceImpl* dev, TextureCore& core, const SUBRESOURCE_DATA* init) {
  VkCommandBuffer cb = dev->UploadCmd();
  TextureImage& img = core.images[0];
  const VkImageLayout finalLayout = (core.desc.BindFlags & BIND_SHADER_RESOURCE)
                                        ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                        : VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  RecordUploadBarrier(cb, core, false, finalLayout);
  for (uint32_t l = 0; l < core.desc.ArraySize; ++l)
    for (uint32_t m = 0; m < core.desc.MipLevels; ++m) {
      const uint32_t i = l * core.desc.MipLevels + m;
      const uint32_t w = core.MipWidth(m), h = core.MipHeight(m);
      const LinearSize ls = LinearLayout(*core.fmt, w, h);
      RingAlloc a;
      if (!dev->AllocateRing(VkDeviceSize(ls.rowPitch) * ls.rows, 16, &a)) return E_OUTOFMEMORY;
      CopyRows(a.ptr, ls.rowPitch, init[i].pSysMem, init[i].SysMemPitch ? init[i].SysMemPitch : ls.rowPitch,
               ls.rowPitch, ls.rows);
      VkBufferImageCopy region{};
      region.bufferOffset = a.offset;
      region.imageSubresource = {core.aspect, m, l, 1};
      region.imageExtent = {w, h, 1};
      vkCmdCopyBufferToImage(cb, a.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    }
  RecordUploadBarrier(cb, core, true, finalLayout);
  for (auto& s : img.sync) {
    s = SyncState{};
    s.layout = finalLayout;
    s.pending = true;
    s.writeStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    s.visible = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  }
  return S_OK;
}

HRESULT InitTexture(DeviceImpl* dev, TextureCore& core, const TEXTURE2D_DESC& d, const SUBRESOURCE_DATA* init) {
  SetupCore(core, d);
  if (core.IsStaging()) {
    if (!CreateStagingStorage(dev, core)) return E_OUTOFMEMORY;
    if (init) UploadToStaging(core, init);
    return S_OK;
  }
  core.images.resize(1);
  if (!CreateTextureImage(dev, core, &core.images[0])) return E_OUTOFMEMORY;
  return init ? UploadToImage(dev, core, init) : S_OK;
}

template <class Impl, class Iface>
HRESULT CreateTexture(DeviceImpl* dev, const char* fn, TEXTURE2D_DESC d, bool is1D, const SUBRESOURCE_DATA* init,
                      Iface** out) {
  const HRESULT valid = ValidateCreateTexture(*dev, fn, is1D, init, &d);
  if (FAILED(valid)) return valid;
  auto* t = new Impl(dev);
  const HRESULT hr = InitTexture(dev, t->core, d, init);
  if (FAILED(hr)) {
    t->Release();
    return hr;
  }
  *out = t;
  return S_OK;
}

}  // namespace

HRESULT DeviceImpl::CreateTexture2D(const TEXTURE2D_DESC* desc, const SUBRESOURCE_DATA* init, Texture2D** out) {
  if (out) *out = nullptr;
  if (!ValidatePointers(*this, "CreateTexture2D", desc, "pDesc", out, "ppTexture2D")) return E_INVALIDARG;
  return CreateTexture<Texture2DImpl>(this, "CreateTexture2D", *desc, false, init, out);
}

HRESULT DeviceImpl::CreateTexture1D(const TEXTURE1D_DESC* desc, const SUBRESOURCE_DATA* init, Texture1D** out) {
  if (out) *out = nullptr;
  if (!ValidatePointers(*this, "CreateTexture1D", desc, "pDesc", out, "ppTexture1D")) return E_INVALIDARG;
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
  return CreateTexture<Texture1DImpl>(this, "CreateTexture1D", d, true, init, out);
}

}  // namespace d3dl::impl
