// Queries (timestamps in per-frame query pools, disjoint, events signalled by
// the frame fence) and debug-utils labels.
#include "Context.h"

namespace d3dl::impl {

UINT QueryImpl::GetDataSize() const {
  switch (desc.Query) {
    case QUERY_EVENT: return sizeof(BOOL);
    case QUERY_TIMESTAMP: return sizeof(UINT64);
    case QUERY_TIMESTAMP_DISJOINT: return sizeof(QUERY_DATA_TIMESTAMP_DISJOINT);
  }
  return 0;
}

HRESULT DeviceImpl::CreateQuery(const QUERY_DESC* desc, Query** out) {
  if (out) *out = nullptr;
  if (!desc || !out) {
    Log(LogLevel::Error, "CreateQuery: %s is null", desc ? "ppQuery" : "pQueryDesc");
    return E_INVALIDARG;
  }
  if (desc->Query != QUERY_EVENT && desc->Query != QUERY_TIMESTAMP && desc->Query != QUERY_TIMESTAMP_DISJOINT) {
    Log(LogLevel::Error, "CreateQuery: query type %u is not supported", desc->Query);
    return E_INVALIDARG;
  }
  auto* q = new QueryImpl(this);
  q->desc = *desc;
  *out = q;
  return S_OK;
}

void ContextImpl::Begin(Query* query) {
  auto* q = static_cast<QueryImpl*>(query);
  if (!q) return;
  if (q->desc.Query != QUERY_TIMESTAMP_DISJOINT) {
    dev_->Log(LogLevel::Warning, "Begin: query type %u has no Begin (only End)", q->desc.Query);
    return;
  }
  q->begun = true;
}

void ContextImpl::End(Query* query) {
  auto* q = static_cast<QueryImpl*>(query);
  if (!q) return;
  q->resolved = false;
  q->serial = dev_->CurrentSerial();
  if (q->desc.Query == QUERY_TIMESTAMP) {
    uint32_t index;
    if (!dev_->AllocateTimestamp(q, &index)) {
      ErrorOnce(1u << 9, "End: more than 1024 timestamps in one frame; extra timestamps read as 0");
      q->resolved = true;
      q->value = 0;
      return;
    }
    q->index = index;
    vkCmdWriteTimestamp2(dev_->Cmd(), VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, q->pool, index);
  }
  q->begun = false;
}

HRESULT ContextImpl::GetData(Query* query, void* data, UINT size, UINT flags) {
  auto* q = static_cast<QueryImpl*>(query);
  if (!q) {
    dev_->Log(LogLevel::Error, "GetData: pAsync is null");
    return E_INVALIDARG;
  }
  if (data && size != q->GetDataSize()) {
    dev_->Log(LogLevel::Error, "GetData: DataSize %u, expected %u", size, q->GetDataSize());
    return E_INVALIDARG;
  }
  if (q->serial == 0) {
    dev_->Log(LogLevel::Error, "GetData: the query was never ended");
    return E_INVALIDARG;
  }
  if (q->serial >= dev_->CurrentSerial()) {
    if (!(flags & ASYNC_GETDATA_DONOTFLUSH)) Flush();
    return S_FALSE;
  }
  if (dev_->CompletedSerial() < q->serial) return S_FALSE;
  switch (q->desc.Query) {
    case QUERY_EVENT:
      if (data) *static_cast<BOOL*>(data) = 1;
      return S_OK;
    case QUERY_TIMESTAMP_DISJOINT: {
      if (data) {
        ADAPTER_DESC ad;
        dev_->GetAdapterDesc(&ad);
        auto* d = static_cast<QUERY_DATA_TIMESTAMP_DISJOINT*>(data);
        d->Frequency = ad.TimestampPeriodNs > 0 ? static_cast<UINT64>(1e9 / ad.TimestampPeriodNs + 0.5) : 1000000000ull;
        d->Disjoint = ad.TimestampPeriodNs > 0 ? 0 : 1;
      }
      return S_OK;
    }
    case QUERY_TIMESTAMP:
      if (!q->resolved) {
        uint64_t v = 0;
        if (vkGetQueryPoolResults(dev_->vk(), q->pool, q->index, 1, sizeof(v), &v, sizeof(v),
                                  VK_QUERY_RESULT_64_BIT) != VK_SUCCESS)
          return S_FALSE;
        q->value = v;
        q->resolved = true;
      }
      if (data) *static_cast<UINT64*>(data) = q->value;
      return S_OK;
  }
  return E_INVALIDARG;
}

void ContextImpl::BeginEvent(const char* name) {
  ++labelDepth_;
  if (!dev_->cmdBeginLabel) return;
  VkDebugUtilsLabelEXT l{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  l.pLabelName = name ? name : "";
  dev_->cmdBeginLabel(dev_->Cmd(), &l);
}

void ContextImpl::EndEvent() {
  if (labelDepth_ <= 0) {
    dev_->Log(LogLevel::Warning, "EndEvent without BeginEvent in this frame; ignored");
    return;
  }
  --labelDepth_;
  if (dev_->cmdEndLabel) dev_->cmdEndLabel(dev_->Cmd());
}

}  // namespace d3dl::impl
