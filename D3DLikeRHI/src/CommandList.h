// What a deferred context records (ListRecording) and the command list it
// becomes at FinishCommandList (CommandListImpl); ContextDeferred.cpp.
//
// A list is one Vulkan secondary command buffer recorded on the deferred
// context's thread, with its own descriptor pools and ring chunks. Layouts
// are not known while recording: each resource's first use in the list is
// kept as its entry use, and its tracked state at the end as its exit state;
// ExecuteCommandList transitions the resource to the entry use and then makes
// the exit state current. A released list's recording goes back to its
// context's ListRecycler and is reused once the GPU is done with it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "CommandMemory.h"
#include "Pins.h"
#include "Resources.h"

namespace d3dl::impl {

// One image subresource or buffer used by a list.
struct ListSyncEntry {
  SyncState* global = nullptr;  // the resource's current state (immediate context)
  TextureCore* tex = nullptr;   // null for a buffer
  VkBuffer buffer = VK_NULL_HANDLE;
  uint32_t mip = 0, layer = 0;
  Usage entry{};             // first use in the list
  SyncState initial, local;  // right after the entry use; at the end of the list
  bool used = true;          // false: a subresource of a used image, untouched by the list
};

// A constant buffer the list reads before writing it: its contents at
// ExecuteCommandList are copied into `slot` (D3D11 reads them at execution).
struct ListImport {
  BufferImpl* buffer = nullptr;
  RingAlloc slot;
};

// The API objects a list holds a reference to, each once. Most lookups are
// of an object the list already holds (the same shader, state or texture
// draw after draw): a small direct-mapped table of the last object seen per
// slot answers those without the hash set's bucket walk.
class RetainedSet {
 public:
  // True when `object` was not held yet (the caller then adds its reference).
  bool Insert(const void* object) {
    const void*& recent = recent_[(reinterpret_cast<uintptr_t>(object) >> 4) & (kRecent - 1)];
    if (recent == object) return false;
    recent = object;
    return all_.insert(object).second;
  }
  // Forgets every object: a slot left over could hide an object of the next
  // list, which would then hold no reference to it.
  void Clear() {
    all_.clear();
    recent_.fill(nullptr);
  }

 private:
  static constexpr size_t kRecent = 256;  // a power of two
  std::array<const void*, kRecent> recent_{};
  std::unordered_set<const void*> all_;
};

struct ListRecording {
  std::unique_ptr<CommandMemory> memory;  // the pool's host memory, kept across recordings
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;  // secondary
  std::vector<VkDescriptorPool> descPools;
  size_t descPoolCurrent = 0;
  ConstantRing ring;

  std::vector<ListSyncEntry> syncs;
  // A buffer's state -> its entry; an image's first subresource state -> the
  // first of its subresources' consecutive entries.
  std::unordered_map<const SyncState*, uint32_t> syncIndex;
  // Contents of constant and DYNAMIC buffers in this list: the slice of the
  // last Map(WRITE_DISCARD)/UpdateSubresource or the import slot.
  struct Slice {
    RingAlloc ring;
    bool discarded;  // by a Map(WRITE_DISCARD) of this list (NO_OVERWRITE may follow)
    bool written;    // by this list (else an import)
  };
  std::unordered_map<const BufferImpl*, Slice> slices;
  std::vector<ListImport> imports;
  std::unordered_map<GpuUse*, bool> uses;  // -> written
  // API objects the list holds a reference to, dropped with it: every object
  // bound while it was recorded (the context's pins, Pins.h) and the others
  // its commands use (a cleared view, a mapped buffer), those once each.
  RetainedSet retained;
  std::vector<PinTable::Entry> held;

  uint64_t draws = 0;  // added to DEVICE_STATS::DrawCalls at each execution

  // Textures read again exactly as their last read in this list
  // (DeferredContext::UseTexture): such a read changes none of their entries
  // and records no barrier, so it is skipped. A read only adds stages to what
  // an entry has made visible, so only a write or a layout change can undo
  // that; either bumps `readEpoch`, which voids every remembered read. A
  // direct-mapped table keyed by the image's first subresource state.
  struct RepeatedRead {
    const SyncState* sync = nullptr;
    uint64_t epoch = 0;
    SubresourceRange range;
    Usage usage{};
  };
  static constexpr uint32_t kRepeatedReadBits = 6;
  RepeatedRead repeatedReads[1u << kRepeatedReadBits];
  uint64_t readEpoch = 1;  // raised at each reset too: a recycled list remembers nothing

  // Single-entry cache of `slices` (one constant buffer per draw is common);
  // the node stays put until `slices` is cleared.
  const BufferImpl* lastBuffer = nullptr;
  Slice* lastEntry = nullptr;
};

// The recordings of one deferred context, kept for reuse (ListRecycler.cpp):
// a released list's command pool and secondary buffer, descriptor pools, ring
// chunks and container capacity serve a later list of the same context once
// the frame that last executed it has completed, so recording a list
// allocates nothing from Vulkan and touches warm memory. Shared by the
// context and its lists (a list may outlive its context); the mutex is taken
// once per list, never per command.
class ListRecycler {
 public:
  explicit ListRecycler(DeviceImpl* dev) : dev_(dev) {}
  ~ListRecycler();
  // A reset recording whose last execution has completed, else a new one.
  std::unique_ptr<ListRecording> Take();
  // `rec`, whose references are released, may serve again once frame
  // `lastExecuted` has completed (0: never executed). Destroyed instead when
  // the context is gone or enough recordings are parked.
  void Give(std::unique_ptr<ListRecording> rec, uint64_t lastExecuted);
  void Close();  // the context is destroyed

 private:
  struct Parked {
    std::unique_ptr<ListRecording> rec;
    uint64_t lastExecuted;
  };
  std::unique_ptr<ListRecording> Create();
  void Reset(ListRecording& rec);
  DeviceImpl* dev_;
  std::mutex mutex_;
  std::vector<Parked> parked_;
  bool closed_ = false;
};

class CommandListImpl final : public Child<CommandList> {
 public:
  CommandListImpl(DeviceImpl* d, std::unique_ptr<ListRecording> rec, std::shared_ptr<ListRecycler> recycler);
  ~CommandListImpl() override;
  UINT GetContextFlags() override { return 0; }
  ListRecording& rec() { return *recording_; }
  uint64_t lastExecuted = 0;  // frame serial of the last ExecuteCommandList

 private:
  std::unique_ptr<ListRecording> recording_;
  std::shared_ptr<ListRecycler> recycler_;
};

// Drops the references a recording's commands hold.
void ReleaseListReferences(ListRecording& rec);
// Releases the recording's references and hands its Vulkan objects to the
// deferred destruction (after the fence of the frame being recorded).
void DestroyRecording(DeviceImpl* dev, ListRecording& rec);

}  // namespace d3dl::impl
