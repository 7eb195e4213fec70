// Program layouts (descriptor-set + pipeline layout of a set of shaders) and
// graphics pipelines keyed by a packed state key (PipelineCache.cpp).
#pragma once

#include <atomic>
#include <cstring>
#include <memory>
#include <mutex>
#include <type_traits>
#include <unordered_map>

#include "Shaders.h"
#include "States.h"

namespace d3dl::impl {

struct ProgramLayout {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  // Twins of `layout` and `setLayout` (identically defined, so compatible
  // with them) that deferred contexts allocate and bind descriptor sets with,
  // made on first use (PipelineCache::ListLayout). Mesa's lavapipe takes a
  // reference on the pipeline layout at every vkCmdBindDescriptorSets and on
  // the set layout at every vkAllocateDescriptorSets, and drops them at
  // reset: with shared layouts, two recording threads increment the same
  // counters, their cache lines moving between cores at every draw.
  static constexpr uint32_t kListLayouts = 4;
  mutable std::atomic<VkPipelineLayout> listLayouts[kListLayouts] = {};
  mutable VkDescriptorSetLayout listSetLayouts[kListLayouts] = {};  // written before listLayouts[i]
  std::vector<VkDescriptorSetLayoutBinding> bindings;                // setLayout's, for the twins
  struct Slot {
    uint16_t binding;
    ShaderStage stage;
    uint8_t slot;
    bool image1D;
    uint8_t dummy;  // DummyViewIndex of the declared image (unbound SRVs)
  };
  std::vector<Slot> cbs, srvs, samplers;  // sorted by binding
  // Shader storage: StructuredBuffer/ByteAddressBuffer (t#),
  // RWTexture2D (u#) and RW structured/raw buffers (u#).
  std::vector<Slot> bufferSrvs, uavImages, uavBuffers;
  bool HasUavs() const { return !uavImages.empty() || !uavBuffers.empty(); }
  bool Empty() const {
    return cbs.empty() && srvs.empty() && samplers.empty() && bufferSrvs.empty() && !HasUavs();
  }
};

// Cache ids of the bound shader of each stage (0: none).
struct ShaderIds {
  uint64_t ids[kGraphicsStageCount];
  bool operator==(const ShaderIds& o) const { return std::memcmp(ids, o.ids, sizeof(ids)) == 0; }
  bool Uses(uint64_t id) const {
    for (uint64_t i : ids)
      if (i == id) return true;
    return false;
  }
};

struct PipelineKey {
  ShaderIds shaders;
  uint64_t il, blend, depth, raster;  // uids; 0: none (il) or the context's default state object
  uint32_t topologyClass, numRT;
  VkFormat rt[SIMULTANEOUS_RENDER_TARGET_COUNT];
  VkFormat ds;
  uint32_t patchControlPoints;  // patch lists: 1..32, else 0
  uint32_t samples;     // rasterization samples: the bound targets' SampleDesc.Count
  uint32_t sampleMask;  // OMSetBlendState's mask, its low `samples` bits (all ones when single-sampled)
  bool operator==(const PipelineKey& o) const { return std::memcmp(this, &o, sizeof(*this)) == 0; }
};
// Compared with memcmp and hashed as 64-bit words (WordHash): no padding
// bytes, whose values would be undefined.
static_assert(std::has_unique_object_representations_v<PipelineKey>);
static_assert(std::has_unique_object_representations_v<ShaderIds>);
// FNV-style hash of a key made of 64-bit words.
struct WordHash {
  template <class K>
  size_t operator()(const K& k) const;
};

struct PipelineInputs {  // objects behind a key, for creation
  PerStage<ShaderBase*> shaders;
  InputLayoutImpl* il;
  BlendImpl* blend;
  DepthStencilImpl* depth;
  RasterizerImpl* raster;
};

class PipelineCache {
 public:
  void Init(DeviceImpl* dev) { dev_ = dev; }
  void Destroy();
  ProgramLayout* GetProgram(const PerStage<ShaderBase*>& shaders);
  VkPipeline GetPipeline(const PipelineKey& key, const PipelineInputs& in, ProgramLayout* prog);
  void ForgetShader(uint64_t cacheId);
  // Compute: one layout and one pipeline per compute shader (its cache id).
  ProgramLayout* GetComputeProgram(ShaderBase* cs);
  VkPipeline GetComputePipeline(ShaderBase* cs, ProgramLayout* prog);
  // The pipeline layout deferred context `index` binds `prog`'s sets with
  // (`prog.layout` itself if its twin cannot be made).
  VkPipelineLayout ListLayout(const ProgramLayout& prog, uint32_t index);
  // The set layout that ListLayout(prog, index)'s sets are allocated with.
  VkDescriptorSetLayout ListSetLayout(const ProgramLayout& prog, uint32_t index);

 private:
  void DeferLayouts(const ProgramLayout& prog);
  void DestroyLayouts(const ProgramLayout& prog);
  bool CreateLayout(const std::vector<VkDescriptorSetLayoutBinding>& bindings, ProgramLayout* prog);
  bool CreateLayoutPair(const std::vector<VkDescriptorSetLayoutBinding>& bindings, VkDescriptorSetLayout* setLayout,
                        VkPipelineLayout* layout);
  DeviceImpl* dev_ = nullptr;
  std::unordered_map<uint64_t, std::unique_ptr<ProgramLayout>> computePrograms_;
  std::unordered_map<uint64_t, VkPipeline> computePipelines_;
  std::unordered_map<ShaderIds, std::unique_ptr<ProgramLayout>, WordHash> programs_;
  std::unordered_map<PipelineKey, VkPipeline, WordHash> pipelines_;
  // Deferred contexts: contexts on several threads share the cache.
  std::mutex mutex_;
};

// One context's memo in front of the shared cache. The shared cache takes a
// mutex on every lookup; with two recording threads that mutex's cache line
// moves between the cores at each draw that changes its program or pipeline
// (Docs/Threads.md measures it). A context asks its own memo first: a
// two-way set-associative table it alone reads and writes, filled from the
// shared cache on a miss. Two ways, because with one a pair of keys that
// share a slot and alternate draw by draw (two materials scattered over a
// scene) missed at every change and took the mutex each time. It can never
// return a destroyed object: every key is made of object uids, which are
// never reused (or of 0 for a default state, whose description never
// changes), and the shared cache destroys a pipeline or layout only with a
// shader whose uid is then in no live key.
class PipelineCacheFront {
 public:
  ProgramLayout* GetProgram(PipelineCache& cache, const PerStage<ShaderBase*>& shaders);
  VkPipeline GetPipeline(PipelineCache& cache, const PipelineKey& key, const PipelineInputs& in, ProgramLayout* prog);

 private:
  template <class Key, class Value, size_t Sets>
  struct TwoWay {
    struct Entry {
      Key key{};
      Value value{};  // null: an empty entry
    };
    struct Set {
      Entry ways[2];
      uint8_t victim = 0;  // the way the next miss replaces (round robin)
    };
    Set sets[Sets];
    // The entry holding key, or null.
    Value Find(size_t hash, const Key& key) const {
      for (const Entry& e : sets[hash % Sets].ways)
        if (e.value && e.key == key) return e.value;
      return Value{};
    }
    void Insert(size_t hash, const Key& key, Value value) {
      Set& s = sets[hash % Sets];
      s.ways[s.victim] = {key, value};
      s.victim ^= 1;
    }
  };
  TwoWay<ShaderIds, ProgramLayout*, 16> programs_;
  TwoWay<PipelineKey, VkPipeline, 32> pipelines_;
};

}  // namespace d3dl::impl
