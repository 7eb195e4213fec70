#include "GPUTimer.h"

namespace drr {

d3dl::HRESULT GPUTimer::Init(d3dl::Device* device) {
  Release();
  for (auto& s : m_Sets) {
    d3dl::QUERY_DESC d;
    d.Query = d3dl::QUERY_TIMESTAMP_DISJOINT;
    d3dl::HRESULT hr = device->CreateQuery(&d, s.disjoint.ReleaseAndGetAddressOf());
    if (d3dl::FAILED(hr)) return hr;
    d.Query = d3dl::QUERY_TIMESTAMP;
    hr = device->CreateQuery(&d, s.begin.ReleaseAndGetAddressOf());
    if (d3dl::FAILED(hr)) return hr;
    hr = device->CreateQuery(&d, s.end.ReleaseAndGetAddressOf());
    if (d3dl::FAILED(hr)) return hr;
  }
  m_Ready = true;
  return d3dl::S_OK;
}

void GPUTimer::Release() {
  for (auto& s : m_Sets) s = QuerySet{};
  m_Next = m_Oldest = m_Outstanding = 0;
  m_Active = false;
  m_Ready = false;
  m_StartCalls = 0;
  m_LastDelay = 0;
}

void GPUTimer::Start(d3dl::DeviceContext* ctx) {
  m_Active = false;
  const uint64_t call = m_StartCalls++;
  if (!m_Ready || m_Outstanding == kPipelineDepth) return;  // all in flight: skip
  QuerySet& s = m_Sets[m_Next];
  s.startCall = call;
  ctx->Begin(s.disjoint.Get());
  ctx->End(s.begin.Get());
  m_Active = true;
}

void GPUTimer::Stop(d3dl::DeviceContext* ctx) {
  if (!m_Active) return;
  QuerySet& s = m_Sets[m_Next];
  ctx->End(s.end.Get());
  ctx->End(s.disjoint.Get());
  m_Next = (m_Next + 1) % kPipelineDepth;
  ++m_Outstanding;
  m_Active = false;
}

bool GPUTimer::Poll(d3dl::DeviceContext* ctx, double* ms) {
  if (m_Outstanding == 0 || m_Active) return false;
  QuerySet& s = m_Sets[m_Oldest];
  d3dl::QUERY_DATA_TIMESTAMP_DISJOINT dj{};
  uint64_t t0 = 0, t1 = 0;
  if (ctx->GetData(s.begin.Get(), &t0, sizeof(t0), d3dl::ASYNC_GETDATA_DONOTFLUSH) != d3dl::S_OK ||
      ctx->GetData(s.end.Get(), &t1, sizeof(t1), d3dl::ASYNC_GETDATA_DONOTFLUSH) != d3dl::S_OK ||
      ctx->GetData(s.disjoint.Get(), &dj, sizeof(dj), d3dl::ASYNC_GETDATA_DONOTFLUSH) != d3dl::S_OK)
    return false;  // not finished yet: try again next frame
  m_Oldest = (m_Oldest + 1) % kPipelineDepth;
  --m_Outstanding;
  // A zero frequency or a stop before the start cannot come from a valid
  // interval; the original would divide by zero or report 0 ms.
  if (dj.Disjoint || dj.Frequency == 0 || t1 < t0) return false;
  *ms = double(t1 - t0) * 1000.0 / double(dj.Frequency);
  m_LastDelay = uint32_t(m_StartCalls - s.startCall);
  return true;
}

bool AveragedGPUTimer::Update(d3dl::DeviceContext* ctx) {
  double ms = 0.0;
  m_NewResults = 0;
  m_NewAverage = false;
  if (!m_Timer.Poll(ctx, &ms)) return false;
  m_Last = ms;
  ++m_Results;
  m_NewResults = 1;
  m_NewAverage = m_Average.Add(ms);
  return m_NewAverage;
}

}  // namespace drr
