// GPU timers on timestamp + disjoint queries, as the original's GPUTimer /
// AveragedGPUTimer: a pipeline of 4 outstanding query sets read back without
// stalling, at most one result per frame, and the mean of blocks of N results
// (0 until the first block completes, as the original).
#pragma once

#include <array>
#include <cstdint>

#include "ResolutionController.h"  // BlockAverage
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
  // As the original's GetInterval: reads back the oldest query set if it has
  // finished and returns true with its time in ms; a disjoint (or otherwise
  // unusable) interval is consumed and returns false. One call per frame.
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
  explicit AveragedGPUTimer(uint32_t averageCount = 10) : m_Average(averageCount) {}
  d3dl::HRESULT Init(d3dl::Device* device) { return m_Timer.Init(device); }
  void Release() { m_Timer.Release(); }
  void Start(d3dl::DeviceContext* ctx) { m_Timer.Start(ctx); }
  void Stop(d3dl::DeviceContext* ctx) { m_Timer.Stop(ctx); }
  // Polls the timer once; returns true when a new average is available.
  bool Update(d3dl::DeviceContext* ctx);
  // Mean of the last complete block; 0 before the first (the original's value).
  double AverageMs() const { return m_Average.Value(); }
  double LastMs() const { return m_Last; }       // latest single result
  // The last Update completed a block (what the original's
  // HaveUpdatedAveragedIntervalTime returns).
  bool NewAverage() const { return m_NewAverage; }
  // Results that arrived in the last Update (0: LastMs is an older one).
  uint32_t NewResults() const { return m_NewResults; }
  // Frames between the Start of LastMs's measurement and the Update that read it.
  uint32_t LastDelayFrames() const { return m_Timer.LastDelay(); }
  bool HasResult() const { return m_Average.HasValue(); }  // a first full block arrived
  uint64_t ResultCount() const { return m_Results; }

 private:
  GPUTimer m_Timer;
  BlockAverage m_Average;
  double m_Last = 0.0;
  uint64_t m_Results = 0;
  uint32_t m_NewResults = 0;
  bool m_NewAverage = false;
};

}  // namespace drr
