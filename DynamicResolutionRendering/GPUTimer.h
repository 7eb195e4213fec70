// GPU timers on timestamp + disjoint queries, as the original's GPUTimer /
// AveragedGPUTimer: a pipeline of outstanding query sets read back without
// stalling, and an average over the last N results.
#pragma once

#include <array>
#include <cstdint>

#include "d3dl/D3DLike.h"

namespace drr {

class GPUTimer {
 public:
  static constexpr uint32_t kPipelineDepth = 4;  // outstanding query sets

  d3dl::HRESULT Init(d3dl::Device* device);
  void Release();
  // Start/Stop bracket the GPU work to time. When all query sets are still in
  // flight the measurement of this frame is skipped (never stalls).
  void Start(d3dl::DeviceContext* ctx);
  void Stop(d3dl::DeviceContext* ctx);
  // Reads back the oldest finished query set; returns true with its time in ms.
  // Disjoint intervals are dropped. Call until it returns false.
  bool Poll(d3dl::DeviceContext* ctx, double* ms);
  uint32_t Outstanding() const { return m_Outstanding; }
  // Delay of the result the last successful Poll returned, counted in Start
  // calls (= frames, Start being called once per frame): the number of Start
  // calls made between the Start of that measurement and the Poll, itself
  // included. Polled at the top of frame F, a result of frame F - d has delay d
  // (d >= 1); 0 before the first result.
  uint32_t LastDelay() const { return m_LastDelay; }

 private:
  struct QuerySet {
    d3dl::ComPtr<d3dl::Query> disjoint, begin, end;
    uint64_t startCall = 0;  // value of m_StartCalls when it was started
  };
  std::array<QuerySet, kPipelineDepth> m_Sets{};
  uint32_t m_Next = 0;         // set used by the next Start
  uint32_t m_Oldest = 0;       // oldest set in flight
  uint32_t m_Outstanding = 0;  // sets in flight
  bool m_Active = false;       // between Start and Stop with a set
  bool m_Ready = false;
  uint64_t m_StartCalls = 0;  // every Start call, skipped ones included
  uint32_t m_LastDelay = 0;
};

class AveragedGPUTimer {
 public:
  explicit AveragedGPUTimer(uint32_t averageCount = 10) : m_AverageCount(averageCount) {}
  d3dl::HRESULT Init(d3dl::Device* device) { return m_Timer.Init(device); }
  void Release() { m_Timer.Release(); }
  void Start(d3dl::DeviceContext* ctx) { m_Timer.Start(ctx); }
  void Stop(d3dl::DeviceContext* ctx) { m_Timer.Stop(ctx); }
  // Polls the timer; returns true when a new average is available.
  bool Update(d3dl::DeviceContext* ctx);
  double AverageMs() const { return m_Average; }
  double LastMs() const { return m_Last; }       // latest single result
  // Results that arrived in the last Update (0: LastMs is an older one).
  uint32_t NewResults() const { return m_NewResults; }
  // Frames between the Start of LastMs's measurement and the Update that read it.
  uint32_t LastDelayFrames() const { return m_Timer.LastDelay(); }
  bool HasResult() const { return m_HasResult; }
  uint64_t ResultCount() const { return m_Results; }

 private:
  GPUTimer m_Timer;
  uint32_t m_AverageCount;
  double m_Sum = 0.0;
  uint32_t m_Count = 0;
  double m_Average = 0.0;
  double m_Last = 0.0;
  bool m_HasResult = false;
  uint64_t m_Results = 0;
  uint32_t m_NewResults = 0;
};

}  // namespace drr
