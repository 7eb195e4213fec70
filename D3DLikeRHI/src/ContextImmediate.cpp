// The immediate context's own part: its frames of command buffers, begun at
// creation, the ring slices it draws from, and the execution of command lists
// recorded on deferred contexts (the common part is in Context*.cpp).
#include "ContextImmediate.h"
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {
namespace {
bool SameState(const SyncState& a, const SyncState& b) {
  return a.layout == b.layout && a.writeStages == b.writeStages && a.writeAccess == b.writeAccess &&
         a.visible == b.visible && a.readStages == b.readStages && a.pending == b.pending;
}
}  // namespace

ImmediateContext::ImmediateContext(DeviceImpl* dev) : ContextImpl(dev) {
  CreateCommandFrames();
  BeginCommandFrame();
}

// A slice mapped in an earlier frame has been recycled: its contents are undefined.
const RingAlloc& ImmediateContext::DynRing(const BufferImpl* b) {
  const RingAlloc& ring = b->ring();
  if (!b->RingFromFrame(dev_->CurrentSerial()) && ring.buffer) ErrorOnce(OnceError::StaleDynamicBuffer);
  return ring;
}

HRESULT ImmediateContext::FinishCommandList(BOOL, CommandList** out) {
  return ValidateFinishCommandList(*dev_, false, out);
}

void ImmediateContext::ExecuteCommandList(CommandList* commandList, BOOL restoreState) {
  if (!ValidateExecuteCommandList(*dev_, false, commandList, OwnList(commandList))) return;
  auto* list = static_cast<CommandListImpl*>(commandList);
  ListRecording& r = list->rec();
  EndRendering();
  CopyImports(*list);
  for (const ListSyncEntry& e : r.syncs) {
    if (!e.used) continue;
    if (e.tex)
      UseTexture(e.tex, OneSubresource(e.mip, e.layer), e.entry);
    else
      UseBuffer(e.buffer, *e.global, e.entry);
  }
  FlushBarriers();
  vkCmdExecuteCommands(Cmd(), 1, &r.cmd);
  for (const ListSyncEntry& e : r.syncs)
    if (e.used && !SameState(e.local, e.initial)) *e.global = e.local;  // the list changed it
  const uint64_t serial = dev_->CurrentSerial();
  for (const auto& [use, written] : r.uses) written ? use->Write(serial) : use->Read(serial);
  list->lastExecuted = serial;
  dev_->stats.DrawCalls += r.draws;
  ExportConstants(r);
  if (!restoreState) ClearState();
  MarkDirtyAll();  // the secondary buffer left the primary's bindings undefined
}

// Constant buffers the list reads without writing them hold their contents
// at execution. A slot still read by an earlier execution on the GPU is
// overwritten only after it (when the contents differ).
void ImmediateContext::CopyImports(CommandListImpl& list) {
  ListRecording& r = list.rec();
  if (r.imports.empty()) return;
  bool differs = false;
  for (const ListImport& im : r.imports) {
    im.buffer->SyncShadow();
    differs = differs || std::memcmp(im.slot.ptr, im.buffer->shadow(), im.buffer->size()) != 0;
  }
  const uint64_t last = list.lastExecuted;
  if (differs && last && dev_->queue().CompletedSerial() < last) {
    if (last >= dev_->CurrentSerial()) Flush();
    dev_->queue().WaitForSerial(last);
  }
  for (const ListImport& im : r.imports) std::memcpy(im.slot.ptr, im.buffer->shadow(), im.buffer->size());
}

// Constant buffers the list wrote hold the list's last contents afterwards,
// as if its updates had run on this context.
void ImmediateContext::ExportConstants(ListRecording& r) {
  for (auto& [buffer, slice] : r.slices) {
    if (!slice.written || !buffer->IsConstantBuffer()) continue;
    auto* b = const_cast<BufferImpl*>(buffer);  // retained by the list
    b->SyncShadow();  // drops a stale mark of this context's own discard
    std::memcpy(b->shadow(), slice.ring.ptr, b->size());
    b->ShadowChanged();
  }
  dirty_ |= kConstants;
}

}  // namespace d3dl::impl
