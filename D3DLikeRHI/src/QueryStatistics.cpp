// QUERY_PIPELINE_STATISTICS: a Vulkan pipeline-statistics query in a pool of
// its own. Begin/End end the rendering scope (the query is begun and ended
// outside render pass instances, as Vulkan requires of a query that spans
// them); a frame end (Flush, Present) ends an active one early.
#include <iterator>

#include "Context.h"

namespace d3dl::impl {
namespace {
// Vulkan writes the enabled counters in bit order, which is the field order
// of QUERY_DATA_PIPELINE_STATISTICS.
constexpr VkQueryPipelineStatisticFlagBits kCounterBits[] = {
    VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_VERTICES_BIT,
    VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT,
    VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT,
    VK_QUERY_PIPELINE_STATISTIC_GEOMETRY_SHADER_INVOCATIONS_BIT,
    VK_QUERY_PIPELINE_STATISTIC_GEOMETRY_SHADER_PRIMITIVES_BIT,
    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT,
    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT,
    VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT,
    VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_CONTROL_SHADER_PATCHES_BIT,
    VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT,
    VK_QUERY_PIPELINE_STATISTIC_COMPUTE_SHADER_INVOCATIONS_BIT,
};
constexpr uint32_t kCounterCount = std::size(kCounterBits);
static_assert(sizeof(QUERY_DATA_PIPELINE_STATISTICS) == kCounterCount * sizeof(UINT64));

// The counters the adapter can count: the stage counters only with the stage.
VkQueryPipelineStatisticFlags SupportedCounters(const DeviceFeatures& f) {
  VkQueryPipelineStatisticFlags flags = 0;
  for (VkQueryPipelineStatisticFlagBits bit : kCounterBits) flags |= bit;
  if (!f.geometry)
    flags &= ~(VK_QUERY_PIPELINE_STATISTIC_GEOMETRY_SHADER_INVOCATIONS_BIT |
               VK_QUERY_PIPELINE_STATISTIC_GEOMETRY_SHADER_PRIMITIVES_BIT);
  if (!f.tessellation)
    flags &= ~(VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_CONTROL_SHADER_PATCHES_BIT |
               VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT);
  return flags;
}
}  // namespace

QueryImpl::~QueryImpl() {
  if (statsPool) dev_->Defer(VK_OBJECT_TYPE_QUERY_POOL, reinterpret_cast<uint64_t>(statsPool));
}

bool CreateStatisticsPool(DeviceImpl* dev, QueryImpl* q) {
  VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  ci.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
  ci.queryCount = 1;
  ci.pipelineStatistics = SupportedCounters(dev->features());
  if (vkCreateQueryPool(dev->vk(), &ci, nullptr, &q->statsPool) != VK_SUCCESS) {
    dev->Log(LogLevel::Error, "CreateQuery: vkCreateQueryPool (pipeline statistics) failed");
    return false;
  }
  q->statsFlags = ci.pipelineStatistics;
  return true;
}

void ContextImpl::BeginStatistics(QueryImpl* q) {
  if (activeStatistics_) {
    dev_->Log(LogLevel::Error, "Begin: another QUERY_PIPELINE_STATISTICS query is active (Vulkan allows one at a time); ignored");
    return;
  }
  EndRendering();
  vkCmdResetQueryPool(Cmd(), q->statsPool, 0, 1);
  vkCmdBeginQuery(Cmd(), q->statsPool, 0, 0);
  q->begun = true;
  q->statsCut = false;
  q->resolved = false;
  q->AddRef();
  activeStatistics_ = q;
}

void ContextImpl::EndStatistics(QueryImpl* q) {
  if (q != activeStatistics_) {
    if (!q->statsCut) dev_->Log(LogLevel::Error, "End: the QUERY_PIPELINE_STATISTICS query was not begun; ignored");
    q->statsCut = false;
    return;
  }
  EndRendering();
  vkCmdEndQuery(Cmd(), q->statsPool, 0);
  q->serial = dev_->CurrentSerial();
  q->begun = false;
  activeStatistics_ = nullptr;
  q->Release();
}

void ContextImpl::CutStatisticsAtFrameEnd() {
  QueryImpl* q = activeStatistics_;
  if (!q) return;
  dev_->Log(LogLevel::Warning,
            "a QUERY_PIPELINE_STATISTICS query is active at a Flush/Present: it counts only the work before it");
  EndStatistics(q);
  q->statsCut = true;
}

// S_FALSE while the counters are not available yet.
HRESULT ReadStatistics(DeviceImpl& dev, QueryImpl* q, void* data) {
  if (!q->resolved) {
    uint64_t values[kCounterCount] = {};
    if (vkGetQueryPoolResults(dev.vk(), q->statsPool, 0, 1, sizeof(values), values, sizeof(values),
                              VK_QUERY_RESULT_64_BIT) != VK_SUCCESS)
      return S_FALSE;
    uint64_t fields[kCounterCount] = {};
    uint32_t next = 0;
    for (uint32_t i = 0; i < kCounterCount; ++i)
      if (q->statsFlags & kCounterBits[i]) fields[i] = values[next++];
    std::memcpy(&q->stats, fields, sizeof(fields));
    q->resolved = true;
  }
  if (data) std::memcpy(data, &q->stats, sizeof(q->stats));
  return S_OK;
}

}  // namespace d3dl::impl
