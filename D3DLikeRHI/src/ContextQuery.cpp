// Queries (timestamps in per-frame query pools, disjoint, events signalled by
// the frame fence) and debug-utils labels.
#include "Context.h"
#include "Validate.h"

namespace d3dl::impl {

UINT QueryImpl::GetDataSize() const {
  switch (desc.Query) {
    case QUERY_EVENT: return sizeof(BOOL);
    case QUERY_TIMESTAMP: return sizeof(UINT64);
    case QUERY_TIMESTAMP_DISJOINT: return sizeof(QUERY_DATA_TIMESTAMP_DISJOINT);
    case QUERY_PIPELINE_STATISTICS: return sizeof(QUERY_DATA_PIPELINE_STATISTICS);
  }
  return 0;
}

HRESULT DeviceImpl::CreateQuery(const QUERY_DESC* desc, Query** out) {
  if (out) *out = nullptr;
  const HRESULT hr = ValidateCreateQuery(*this, desc, out);
  if (FAILED(hr)) return hr;
  auto* q = new QueryImpl(this);
  q->desc = *desc;
  if (desc->Query == QUERY_PIPELINE_STATISTICS && !CreateStatisticsPool(this, q)) {
    q->Release();
    return E_OUTOFMEMORY;
  }
  *out = q;
  return S_OK;
}

void ContextImpl::Begin(Query* query) {
  auto* q = static_cast<QueryImpl*>(query);
  if (!q || !ValidateBegin(*dev_, q->desc)) return;
  if (q->desc.Query == QUERY_PIPELINE_STATISTICS) return BeginStatistics(q);
  q->begun = true;
}

void ContextImpl::End(Query* query) {
  auto* q = static_cast<QueryImpl*>(query);
  if (!q) return;
  if (q->desc.Query == QUERY_PIPELINE_STATISTICS) return EndStatistics(q);
  q->resolved = false;
  q->serial = dev_->CurrentSerial();
  if (q->desc.Query == QUERY_TIMESTAMP) {
    uint32_t index;
    if (!AllocateTimestamp(q, &index)) {
      ErrorOnce(OnceError::TooManyTimestamps);
      q->resolved = true;
      q->value = 0;
      return;
    }
    q->index = index;
    vkCmdWriteTimestamp2(Cmd(), VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, q->pool, index);
  }
  q->begun = false;
}

namespace {
void FillDisjoint(DeviceImpl& dev, void* data) {
  ADAPTER_DESC ad;
  dev.GetAdapterDesc(&ad);
  auto* d = static_cast<QUERY_DATA_TIMESTAMP_DISJOINT*>(data);
  d->Frequency = ad.TimestampPeriodNs > 0 ? static_cast<UINT64>(1e9 / ad.TimestampPeriodNs + 0.5) : 1000000000ull;
  d->Disjoint = ad.TimestampPeriodNs > 0 ? 0 : 1;
}

// S_FALSE while the timestamp is not available yet.
HRESULT ReadTimestamp(DeviceImpl& dev, QueryImpl* q, void* data) {
  if (!q->resolved) {
    uint64_t v = 0;
    if (vkGetQueryPoolResults(dev.vk(), q->pool, q->index, 1, sizeof(v), &v, sizeof(v), VK_QUERY_RESULT_64_BIT) !=
        VK_SUCCESS)
      return S_FALSE;
    q->value = v;
    q->resolved = true;
  }
  if (data) *static_cast<UINT64*>(data) = q->value;
  return S_OK;
}
}  // namespace

HRESULT ContextImpl::GetData(Query* query, void* data, UINT size, UINT flags) {
  auto* q = static_cast<QueryImpl*>(query);
  const QueryInfo info = q ? QueryInfo{q->GetDataSize(), q->serial != 0} : QueryInfo{};
  if (!ValidateGetData(*dev_, q ? &info : nullptr, data, size)) return E_INVALIDARG;
  if (q->serial >= dev_->CurrentSerial()) {
    if (!(flags & ASYNC_GETDATA_DONOTFLUSH)) Flush();
    return S_FALSE;
  }
  if (dev_->queue().CompletedSerial() < q->serial) return S_FALSE;
  switch (q->desc.Query) {
    case QUERY_EVENT:
      if (data) *static_cast<BOOL*>(data) = 1;
      return S_OK;
    case QUERY_TIMESTAMP_DISJOINT:
      if (data) FillDisjoint(*dev_, data);
      return S_OK;
    case QUERY_TIMESTAMP: return ReadTimestamp(*dev_, q, data);
    case QUERY_PIPELINE_STATISTICS: return ReadStatistics(*dev_, q, data);
  }
  return E_INVALIDARG;
}

void ContextImpl::BeginEvent(const char* name) {
  ++labelDepth_;
  if (!dev_->debugUtils().cmdBeginLabel) return;
  VkDebugUtilsLabelEXT l{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  l.pLabelName = name ? name : "";
  dev_->debugUtils().cmdBeginLabel(Cmd(), &l);
}

void ContextImpl::EndEvent() {
  if (labelDepth_ <= 0) {
    dev_->Log(LogLevel::Warning, "EndEvent without BeginEvent in this frame; ignored");
    return;
  }
  --labelDepth_;
  if (dev_->debugUtils().cmdEndLabel) dev_->debugUtils().cmdEndLabel(Cmd());
}

}  // namespace d3dl::impl
