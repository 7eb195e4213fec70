// Deferred contexts and command lists (CommandList.h). A deferred context
// (ContextDeferred.h) is a context whose commands go into a secondary command buffer of the
// list being recorded, on the calling thread; its barriers, ring slices and
// descriptor sets stay inside the list, and everything about the list being
// recorded (`rec_`) stays in this file. The immediate context executes lists
// (ContextImmediate.cpp).
#include "ContextDeferred.h"
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {
namespace {
constexpr VkDeviceSize kDynamicAlign = 256;  // vertex/index slices, as MapRingBuffer

// The state of a resource right after the barrier into its entry use `u`.
SyncState StateAfterEntry(const Usage& u) {
  SyncState s;
  s.layout = u.layout;
  s.pending = true;
  s.writeStages = u.stages;
  s.writeAccess = u.write ? u.access : 0;
  s.visible = u.write ? 0 : u.stages;
  s.readStages = u.write ? 0 : u.stages;
  return s;
}

uint32_t RepeatedReadSlot(const SyncState* sync) {
  const uint64_t h = (reinterpret_cast<uintptr_t>(sync) >> 4) * 0x9E3779B97F4A7C15ull;
  return static_cast<uint32_t>(h >> (64 - ListRecording::kRepeatedReadBits));
}

bool IsRepeatedRead(const ListRecording::RepeatedRead& last, uint64_t epoch, const SyncState* sync,
                    const SubresourceRange& r, const Usage& u) {
  return last.epoch == epoch && last.sync == sync && last.range == r && last.usage == u;
}
}  // namespace

// ---------------------------------------------------------------------------
// Creation, command lists
HRESULT DeviceImpl::CreateDeferredContext(UINT flags, DeviceContext** context) {
  const HRESULT hr = ValidateCreateDeferredContext(*this, flags, context);
  if (FAILED(hr)) return hr;
  *context = new DeferredContext(this);
  return S_OK;
}

CommandListImpl::CommandListImpl(DeviceImpl* d, std::unique_ptr<ListRecording> rec,
                                 std::shared_ptr<ListRecycler> recycler)
    : Child<CommandList>(d), recording_(std::move(rec)), recycler_(std::move(recycler)) {}

// Destruction releases the references at once; the Vulkan objects serve a later list of the same
// context once the frame that last executed this one has completed.
CommandListImpl::~CommandListImpl() {
  ReleaseListReferences(*recording_);
  recycler_->Give(std::move(recording_), lastExecuted);
}

void ReleaseListReferences(ListRecording& rec) {
  for (const auto& h : rec.held) h.release(h.object);
  rec.held.clear();
  rec.retained.Clear();
}

void DestroyRecording(DeviceImpl* dev, ListRecording& rec) {
  ReleaseListReferences(rec);
  rec.ring.DeferDestroy();
  for (VkDescriptorPool p : rec.descPools) dev->Defer(VK_OBJECT_TYPE_DESCRIPTOR_POOL, reinterpret_cast<uint64_t>(p));
  rec.descPools.clear();
  dev->Defer(VK_OBJECT_TYPE_COMMAND_POOL, reinterpret_cast<uint64_t>(rec.pool), rec.memory.release());  // frees rec.cmd
  rec.pool = VK_NULL_HANDLE;
}

DeferredContext::DeferredContext(DeviceImpl* dev)
    : ContextImpl(dev),
      listLayoutIndex_(dev->NextDeferredContextIndex()),
      recycler_(std::make_shared<ListRecycler>(dev)) {
  dev_->ChildCreated();
  EndList();  // no list yet: the first bind or command takes one
}

DeferredContext::~DeferredContext() {
  ClearState();
  if (rec_) DestroyRecording(dev_, *rec_);  // an unfinished list, never submitted
  recycler_->Close();             // its lists may outlive it: they destroy theirs
}

UINT DeferredContext::Release() {
  const UINT r = --refs_;
  if (r == 0) {
    DeviceImpl* dev = dev_;
    delete this;
    dev->ChildDestroyed();  // last: it may shut the device down
  }
  return r;
}

void DeferredContext::Reject(const char* fn, bool portLimit) {
  if (portLimit)
    dev_->Log(LogLevel::Error, "%s: not supported on deferred contexts by this port (use the immediate context)", fn);
  else
    dev_->Log(LogLevel::Error, "%s: not allowed on a deferred context", fn);
}


// Constant buffers only (ValidateDeferredUpdate), into a slice of the list.
void DeferredContext::UpdateSubresource(Resource* dst, UINT sub, const BOX* box, const void* data, UINT rowPitch,
                                        UINT) {
  BOX region;
  const ResourceInfo info = DescribeResource(dst);
  if (!ValidateUpdateSubresource(*dev_, info, sub, box, data, rowPitch, &region)) return;
  if (ValidateDeferredUpdate(*dev_, info)) UpdateConstantsInList(AsBuffer(dst), box, data);
}

// A new list: its own command pool, secondary buffer, descriptor pools and
// ring (recycled from an earlier list of this context when one is free,
// which resets them here, on this context's thread). The list's state was
// made dirty when the last one ended (EndList).
void DeferredContext::OpenList() {
  rec_ = recycler_->Take();
  drawCount_ = &rec_->draws;
  // Executed outside rendering scopes (it begins its own): nothing inherited.
  VkCommandBufferInheritanceInfo inherit{VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_INFO};
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_SIMULTANEOUS_USE_BIT;  // a list may run twice in one frame
  bi.pInheritanceInfo = &inherit;
  vkBeginCommandBuffer(rec_->cmd, &bi);
  cmd_ = rec_->cmd;
}

// After a list's end: nothing is bound in the next list's command buffer.
// Its recording is taken later, by OpenList.
void DeferredContext::EndList() {
  cmd_ = VK_NULL_HANDLE;
  drawCount_ = &closedDraws_;
  rendering_ = false;
  labelDepth_ = 0;
  MarkDirtyAll();
}

HRESULT DeferredContext::FinishCommandList(BOOL restoreState, CommandList** out) {
  const HRESULT hr = ValidateFinishCommandList(*dev_, true, out);
  if (FAILED(hr)) return hr;
  if (!rec_) OpenList();  // an empty list
  EndRendering();
  FlushBarriers();
  while (labelDepth_ > 0) EndEvent();
  vkEndCommandBuffer(cmd_);
  pins_.DropAll([this](const PinTable::Entry& e) { Unpinned(e); });  // the list holds what was bound
  std::unique_ptr<ListRecording> done = std::move(rec_);
  EndList();
  if (restoreState)
    PinBoundState();  // the context's own references to the state it keeps
  else
    ClearState();
  *out = new CommandListImpl(dev_, std::move(done), recycler_);
  return S_OK;
}

void DeferredContext::ExecuteCommandList(CommandList* list, BOOL) { ValidateExecuteCommandList(*dev_, true, list, OwnList(list)); }

// ---------------------------------------------------------------------------
// Recording: synchronisation state local to the list
ListSyncEntry& DeferredContext::ListEntry(SyncState* global, const Usage& u, bool* first) {
  ListRecording& r = Rec();
  auto [it, added] = r.syncIndex.emplace(global, static_cast<uint32_t>(r.syncs.size()));
  *first = added;
  if (added) {
    ListSyncEntry e;
    e.global = global;
    e.entry = u;
    e.initial = e.local = StateAfterEntry(u);
    r.syncs.push_back(e);
  }
  return r.syncs[it->second];
}

// The list's entries of every subresource of `img`, made together at the
// image's first use in the list (unused until touched): one lookup per
// texture and use, not one per subresource.
uint32_t DeferredContext::ListImageEntries(TextureCore* t, TextureImage& img) {
  ListRecording& r = Rec();
  const auto [it, added] = r.syncIndex.emplace(img.sync.data(), static_cast<uint32_t>(r.syncs.size()));
  if (added) {
    const uint32_t mips = t->desc.MipLevels;
    for (uint32_t k = 0; k < img.sync.size(); ++k) {
      ListSyncEntry e;
      e.global = &img.sync[k];
      e.tex = t;
      e.mip = k % mips;
      e.layer = k / mips;
      e.used = false;
      r.syncs.push_back(e);
    }
  }
  return it->second;
}

void DeferredContext::UseTexture(TextureCore* t, const SubresourceRange& r, const Usage& u) {
  if (u.layout != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) dirty_ |= kSrvLayouts;
  TextureImage& img = t->Cur();
  ListRecording& rec = Rec();
  ListRecording::RepeatedRead& last = rec.repeatedReads[RepeatedReadSlot(img.sync.data())];
  if (!u.write && IsRepeatedRead(last, rec.readEpoch, img.sync.data(), r, u)) return;
  const uint32_t mipCount = t->desc.MipLevels;
  const uint32_t base = ListImageEntries(t, img);
  bool undoesReads = u.write;
  for (uint32_t l = r.baseLayer; l < r.baseLayer + r.layers; ++l) {
    for (uint32_t m = r.baseMip; m < r.baseMip + r.mips; ++m) {
      ListSyncEntry& e = rec.syncs[base + l * mipCount + m];
      if (!e.used) {  // the immediate context records this barrier at execution
        e.used = true;
        e.entry = u;
        e.initial = e.local = StateAfterEntry(u);
        continue;
      }
      undoesReads |= e.local.layout != u.layout && u.layout != VK_IMAGE_LAYOUT_UNDEFINED;
      BarrierInfo info;
      if (Transition(e.local, u, &info)) barriers_.AddImage(img.image, t->aspect, m, l, info);
    }
  }
  if (undoesReads)
    ++rec.readEpoch;
  else if (!u.write)
    last = {img.sync.data(), rec.readEpoch, r, u};
}

void DeferredContext::UseBuffer(VkBuffer buf, SyncState& s, const Usage& u) {
  bool first;
  ListSyncEntry& e = ListEntry(&s, u, &first);
  // A write (a UAV, a fill) may feed a later draw's vertex or index reads:
  // the next draw re-checks their barriers, as on the immediate context.
  if (u.write) dirty_ |= kVertexBuffers | kIndexBuffer;
  if (first) {
    e.buffer = buf;
    return;
  }
  BarrierInfo info;
  if (!Transition(e.local, u, &info)) return;
  barriers_.AddBuffer(buf, info);
}

void DeferredContext::NoteUse(GpuUse& u, bool write) {
  auto [it, added] = Rec().uses.emplace(&u, write);
  if (!added) it->second = it->second || write;
}

template <class T>
void DeferredContext::Retain(T* object) {
  if (!object || !Rec().retained.Insert(object)) return;
  object->AddRef();
  rec_->held.push_back({object, [](void* p) { static_cast<T*>(p)->Release(); }});
}

void DeferredContext::Hold(Unknown* object) { Retain(object); }

void DeferredContext::Unpinned(const PinTable::Entry& e) {
  if (rec_)
    rec_->held.push_back(e);
  else
    e.release(e.object);
}

// ---------------------------------------------------------------------------
// Recording: buffer contents in the list's own ring
ListRecording::Slice* DeferredContext::NewListSlice(BufferImpl* b, bool discarded, bool written) {
  const VkDeviceSize align = b->IsConstantBuffer() ? dev_->uboAlign() : kDynamicAlign;
  ListRecording& r = Rec();
  RingAlloc a;
  if (!r.ring.TryAllocate(b->size(), align, &a) && !r.ring.Allocate(b->size(), align, &a)) return nullptr;
  ListRecording::Slice* e = r.lastBuffer == b ? r.lastEntry : nullptr;
  if (!e) {
    auto [it, added] = r.slices.try_emplace(b);
    if (added) Retain(b);
    e = &it->second;
  }
  *e = {a, discarded, written};
  r.lastBuffer = b;
  r.lastEntry = e;
  return e;
}

// The buffer's contents in this list so far (null: not yet), through the
// single-entry cache (one constant buffer per draw is common).
ListRecording::Slice* DeferredContext::FindListSlice(const BufferImpl* b) {
  ListRecording& r = Rec();
  if (r.lastBuffer == b) return r.lastEntry;
  const auto it = r.slices.find(b);
  if (it == r.slices.end()) return nullptr;
  r.lastBuffer = b;
  r.lastEntry = &it->second;
  return r.lastEntry;
}

namespace {
const RingAlloc kNoSlice{};
}  // namespace

const RingAlloc& DeferredContext::CbRing(BufferImpl* b) {
  if (const ListRecording::Slice* e = FindListSlice(b)) return e->ring;
  // Read before written in this list: its contents at execution.
  const ListRecording::Slice* e = NewListSlice(b, false, false);
  if (!e) return kNoSlice;
  rec_->imports.push_back({b, e->ring});
  return e->ring;
}

const RingAlloc& DeferredContext::DynRing(const BufferImpl* b) {
  const ListRecording::Slice* e = FindListSlice(b);
  return e ? e->ring : kNoSlice;
}

HRESULT DeferredContext::Map(Resource* resource, UINT sub, MAP type, UINT, MAPPED_SUBRESOURCE* mapped) {
  BufferImpl* b = AsBuffer(resource);
  ListRecording::Slice* e = b ? FindListSlice(b) : nullptr;
  const HRESULT hr = ValidateDeferredMap(*dev_, DescribeResource(resource), sub, type, mapped, e && e->discarded);
  if (mapped) *mapped = {};
  if (FAILED(hr)) return hr;
  if (type == MAP_WRITE_DISCARD && !(e = NewListSlice(b, true, true))) return E_OUTOFMEMORY;
  mapped->pData = e->ring.ptr;
  mapped->RowPitch = mapped->DepthPitch = b->size();
  return S_OK;
}

void DeferredContext::Unmap(Resource* resource, UINT) {
  const BufferImpl* b = AsBuffer(resource);
  if (!b) return;
  dirty_ |= b->IsConstantBuffer() ? uint32_t(kConstants) : uint32_t(kVertexBuffers | kIndexBuffer);
}

// A new slice with the whole buffer: the list's latest contents (or the
// shadow at recording time, for a partial update of a buffer the list did
// not write yet) under the updated range.
void DeferredContext::UpdateConstantsInList(BufferImpl* b, const BOX* box, const void* data) {
  const ListRecording::Slice* prior = FindListSlice(b);
  const uint8_t* base = prior ? prior->ring.ptr : b->shadow();
  const UINT lo = box ? box->left : 0, hi = box ? box->right : b->size();
  std::vector<uint8_t> bytes(base, base + b->size());
  std::memcpy(bytes.data() + lo, data, hi - lo);
  const ListRecording::Slice* e = NewListSlice(b, false, true);
  if (!e) return;
  std::memcpy(e->ring.ptr, bytes.data(), b->size());
  dirty_ |= kConstants;
}

}  // namespace d3dl::impl
