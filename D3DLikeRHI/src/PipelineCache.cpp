// Program layouts (descriptor-set layout + pipeline layout derived from the
// reflected bindings of the bound shaders) and graphics pipelines keyed by a
// packed state key. Both are created on first use and cached.
#include "Context.h"
#include "Topology.h"

namespace d3dl::impl {

template <class K>
size_t WordHash::operator()(const K& k) const {
  static_assert(sizeof(K) % 8 == 0, "hashed as 64-bit words");
  uint64_t words[sizeof(K) / 8];
  std::memcpy(words, &k, sizeof(K));
  uint64_t h = 1469598103934665603ull;
  for (uint64_t w : words) {
    h ^= w;
    h *= 1099511628211ull;
    h ^= h >> 29;
  }
  return static_cast<size_t>(h);
}
template size_t WordHash::operator()(const ShaderIds&) const;
template size_t WordHash::operator()(const PipelineKey&) const;

namespace {
ShaderIds IdsOf(const PerStage<ShaderBase*>& shaders) {
  ShaderIds ids{};
  for (ShaderStage s : kGraphicsStages) ids.ids[StageIndex(s)] = shaders[s] ? shaders[s]->cacheId : 0;
  return ids;
}

// The bindings of one stage's shader, sorted into the program's slot lists.
void AddStageBindings(const ShaderReflection& r, ShaderStage stage, ProgramLayout* prog,
                      std::vector<VkDescriptorSetLayoutBinding>* bindings) {
  const uint32_t base = kStageBindingStride * StageIndex(stage);
  for (const auto& b : r.bindings) {
    VkDescriptorSetLayoutBinding lb{};
    lb.binding = b.binding;
    lb.descriptorType = b.type;
    lb.descriptorCount = 1;
    lb.stageFlags = ToVkStage(stage);
    bindings->push_back(lb);
    ProgramLayout::Slot s{static_cast<uint16_t>(b.binding), stage, 0, b.image1D, DummyViewIndex(b.viewType, b.multisampled)};
    if (b.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC) {
      s.slot = static_cast<uint8_t>(b.binding - base - kConstantBufferBase);
      prog->cbs.push_back(s);
    } else if (b.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE) {
      s.slot = static_cast<uint8_t>(b.binding - base - kTextureBase);
      prog->srvs.push_back(s);
    } else if (b.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE) {
      s.slot = static_cast<uint8_t>(b.binding - base - kUnorderedAccessBase);
      prog->uavImages.push_back(s);
    } else if (b.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER && b.binding >= base + kUnorderedAccessBase) {
      s.slot = static_cast<uint8_t>(b.binding - base - kUnorderedAccessBase);
      prog->uavBuffers.push_back(s);
    } else if (b.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) {
      s.slot = static_cast<uint8_t>(b.binding - base - kTextureBase);
      prog->bufferSrvs.push_back(s);
    } else {
      s.slot = static_cast<uint8_t>(b.binding - base - kSamplerBase);
      prog->samplers.push_back(s);
    }
  }
}
}  // namespace

ProgramLayout* PipelineCache::GetProgram(const PerStage<ShaderBase*>& shaders) {
  std::lock_guard<std::mutex> lock(mutex_);
  const ShaderIds key = IdsOf(shaders);
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second.get();

  auto prog = std::make_unique<ProgramLayout>();
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (ShaderStage s : kGraphicsStages)
    if (shaders[s]) AddStageBindings(shaders[s]->refl, s, prog.get(), &bindings);
  if (!CreateLayout(bindings, prog.get())) return nullptr;
  ProgramLayout* p = prog.get();
  programs_[key] = std::move(prog);
  return p;
}

// A set layout with `bindings` and a pipeline layout of that one set; on
// failure neither exists.
bool PipelineCache::CreateLayoutPair(const std::vector<VkDescriptorSetLayoutBinding>& bindings,
                                     VkDescriptorSetLayout* setLayout, VkPipelineLayout* layout) {
  VkDescriptorSetLayoutCreateInfo sci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  sci.bindingCount = static_cast<uint32_t>(bindings.size());
  sci.pBindings = bindings.data();
  if (vkCreateDescriptorSetLayout(dev_->vk(), &sci, nullptr, setLayout) != VK_SUCCESS) return false;
  VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  lci.setLayoutCount = 1;
  lci.pSetLayouts = setLayout;
  if (vkCreatePipelineLayout(dev_->vk(), &lci, nullptr, layout) != VK_SUCCESS) {
    vkDestroyDescriptorSetLayout(dev_->vk(), *setLayout, nullptr);
    *setLayout = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

bool PipelineCache::CreateLayout(const std::vector<VkDescriptorSetLayoutBinding>& bindings, ProgramLayout* prog) {
  if (!CreateLayoutPair(bindings, &prog->setLayout, &prog->layout)) return false;
  prog->bindings = bindings;
  return true;
}

VkPipelineLayout PipelineCache::ListLayout(const ProgramLayout& prog, uint32_t index) {
  std::atomic<VkPipelineLayout>& twin = prog.listLayouts[index % ProgramLayout::kListLayouts];
  if (VkPipelineLayout l = twin.load(std::memory_order_acquire)) return l;
  std::lock_guard<std::mutex> lock(mutex_);
  if (VkPipelineLayout l = twin.load(std::memory_order_relaxed)) return l;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout l = VK_NULL_HANDLE;
  if (!CreateLayoutPair(prog.bindings, &setLayout, &l)) return prog.layout;
  prog.listSetLayouts[index % ProgramLayout::kListLayouts] = setLayout;
  twin.store(l, std::memory_order_release);
  return l;
}

VkDescriptorSetLayout PipelineCache::ListSetLayout(const ProgramLayout& prog, uint32_t index) {
  if (ListLayout(prog, index) == prog.layout) return prog.setLayout;  // no twin: the shared pair
  return prog.listSetLayouts[index % ProgramLayout::kListLayouts];  // published by ListLayout's release store, read after its acquire
}

void PipelineCache::DeferLayouts(const ProgramLayout& prog) {
  dev_->Defer(VK_OBJECT_TYPE_PIPELINE_LAYOUT, reinterpret_cast<uint64_t>(prog.layout));
  for (const auto& twin : prog.listLayouts)
    dev_->Defer(VK_OBJECT_TYPE_PIPELINE_LAYOUT, reinterpret_cast<uint64_t>(twin.load()));
  for (VkDescriptorSetLayout twin : prog.listSetLayouts)
    dev_->Defer(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, reinterpret_cast<uint64_t>(twin));
  dev_->Defer(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, reinterpret_cast<uint64_t>(prog.setLayout));
}

void PipelineCache::DestroyLayouts(const ProgramLayout& prog) {
  vkDestroyPipelineLayout(dev_->vk(), prog.layout, nullptr);
  for (const auto& twin : prog.listLayouts) vkDestroyPipelineLayout(dev_->vk(), twin.load(), nullptr);
  for (VkDescriptorSetLayout twin : prog.listSetLayouts) vkDestroyDescriptorSetLayout(dev_->vk(), twin, nullptr);
  vkDestroyDescriptorSetLayout(dev_->vk(), prog.setLayout, nullptr);
}

// ---------------------------------------------------------------------------
// Compute layouts and pipelines, keyed by the shader alone (no other state
// enters a compute pipeline).
ProgramLayout* PipelineCache::GetComputeProgram(ShaderBase* cs) {
  std::lock_guard<std::mutex> lock(mutex_);  // deferred contexts dispatch from several threads
  auto it = computePrograms_.find(cs->cacheId);
  if (it != computePrograms_.end()) return it->second.get();
  auto prog = std::make_unique<ProgramLayout>();
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  AddStageBindings(cs->refl, ShaderStage::Compute, prog.get(), &bindings);
  if (!CreateLayout(bindings, prog.get())) return nullptr;
  ProgramLayout* p = prog.get();
  computePrograms_[cs->cacheId] = std::move(prog);
  return p;
}

VkPipeline PipelineCache::GetComputePipeline(ShaderBase* cs, ProgramLayout* prog) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = computePipelines_.find(cs->cacheId);
  if (it != computePipelines_.end()) return it->second;
  VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  ci.stage.module = cs->module;
  ci.stage.pName = cs->refl.entry.c_str();
  ci.layout = prog->layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult r = vkCreateComputePipelines(dev_->vk(), VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline);
  if (r != VK_SUCCESS) {
    dev_->Log(LogLevel::Error, "vkCreateComputePipelines failed (VkResult %d)", r);
    return VK_NULL_HANDLE;
  }
  ++dev_->stats.PipelinesCreated;
  computePipelines_[cs->cacheId] = pipeline;
  return pipeline;
}

namespace {
// Vertex attributes and bindings: every input of the vertex shader from its
// element in the input layout; false (logged) when one has none.
bool VertexInputs(DeviceImpl* dev, const PipelineInputs& in, std::vector<VkVertexInputAttributeDescription>* attrs,
                  std::vector<VkVertexInputBindingDescription>* binds) {
  uint32_t slotsUsed = 0;
  for (const auto& input : in.shaders[ShaderStage::Vertex]->refl.inputs) {
    const InputLayoutImpl::Element* el = nullptr;
    if (in.il)
      for (const auto& e : in.il->elements)
        if (e.semantic == input.semantic && e.index == input.index) el = &e;
    if (!el) {
      dev->Log(LogLevel::Error, "draw: the vertex shader input %s%u has no element in the bound input layout; draw skipped",
               input.semantic.c_str(), input.index);
      return false;
    }
    attrs->push_back({input.location, el->slot, el->format, el->offset});
    if (!(slotsUsed & (1u << el->slot))) {
      slotsUsed |= 1u << el->slot;
      binds->push_back({el->slot, 0, el->perInstance ? VK_VERTEX_INPUT_RATE_INSTANCE : VK_VERTEX_INPUT_RATE_VERTEX});
    }
  }
  return true;
}

// The fixed-function state of a pipeline, filled from a key and its objects.
struct FixedFunction {
  VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  VkPipelineRasterizationStateCreateInfo rs;
  VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  VkPipelineDepthStencilStateCreateInfo ds;
  VkPipelineColorBlendAttachmentState att[SIMULTANEOUS_RENDER_TARGET_COUNT];
  VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  VkDynamicState dyn[6] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR, VK_DYNAMIC_STATE_BLEND_CONSTANTS,
                           VK_DYNAMIC_STATE_STENCIL_REFERENCE, VK_DYNAMIC_STATE_VERTEX_INPUT_BINDING_STRIDE,
                           VK_DYNAMIC_STATE_PRIMITIVE_TOPOLOGY};
  VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  VkPipelineRenderingCreateInfo ri{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  VkPipelineTessellationStateCreateInfo ts{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};

  FixedFunction(const PipelineKey& key, const PipelineInputs& in, bool hasVertexBuffers) : rs(in.raster->ci), ds(in.depth->ci) {
    ia.topology = ClassTopology(key.topologyClass);
    ts.patchControlPoints = key.patchControlPoints;
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    ms.rasterizationSamples = static_cast<VkSampleCountFlagBits>(key.samples);
    ms.pSampleMask = &key.sampleMask;  // one word: D3D11 has at most 32 samples
    ms.alphaToCoverageEnable = in.blend->desc.AlphaToCoverageEnable ? VK_TRUE : VK_FALSE;
    if (key.ds == VK_FORMAT_UNDEFINED) ds.depthTestEnable = ds.depthWriteEnable = ds.stencilTestEnable = VK_FALSE;
    for (uint32_t i = 0; i < key.numRT; ++i) {
      att[i] = in.blend->att[i];
      if (key.rt[i] == VK_FORMAT_UNDEFINED) att[i].colorWriteMask = 0;
    }
    cb.attachmentCount = key.numRT;
    cb.pAttachments = att;
    dy.dynamicStateCount = 6;
    if (!hasVertexBuffers) {  // no vertex buffers: no stride state to set
      dyn[4] = dyn[5];
      --dy.dynamicStateCount;
    }
    dy.pDynamicStates = dyn;
    ri.colorAttachmentCount = key.numRT;
    ri.pColorAttachmentFormats = key.rt;
    ri.depthAttachmentFormat = key.ds;
    if (key.ds == VK_FORMAT_D24_UNORM_S8_UINT) ri.stencilAttachmentFormat = key.ds;
  }
};
}  // namespace

VkPipeline PipelineCache::GetPipeline(const PipelineKey& key, const PipelineInputs& in, ProgramLayout* prog) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++dev_->stats.PipelineCacheLookups;
  auto it = pipelines_.find(key);
  if (it != pipelines_.end()) return it->second;
  VkPipelineShaderStageCreateInfo stages[kGraphicsStageCount]{};
  uint32_t nStages = 0;
  for (ShaderStage s : kGraphicsStages) {
    if (!in.shaders[s]) continue;
    stages[nStages] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[nStages].stage = ToVkStage(s);
    stages[nStages].module = in.shaders[s]->module;
    stages[nStages++].pName = in.shaders[s]->refl.entry.c_str();
  }
  std::vector<VkVertexInputAttributeDescription> attrs;
  std::vector<VkVertexInputBindingDescription> binds;
  if (!VertexInputs(dev_, in, &attrs, &binds)) return VK_NULL_HANDLE;
  VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vi.vertexBindingDescriptionCount = static_cast<uint32_t>(binds.size());
  vi.pVertexBindingDescriptions = binds.data();
  vi.vertexAttributeDescriptionCount = static_cast<uint32_t>(attrs.size());
  vi.pVertexAttributeDescriptions = attrs.data();
  const FixedFunction ff(key, in, !binds.empty());
  VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  ci.pNext = &ff.ri;
  ci.stageCount = nStages;
  ci.pStages = stages;
  ci.pVertexInputState = &vi;
  ci.pInputAssemblyState = &ff.ia;
  ci.pTessellationState = key.topologyClass == kPatchClass ? &ff.ts : nullptr;
  ci.pViewportState = &ff.vp;
  ci.pRasterizationState = &ff.rs;
  ci.pMultisampleState = &ff.ms;
  ci.pDepthStencilState = &ff.ds;
  ci.pColorBlendState = &ff.cb;
  ci.pDynamicState = &ff.dy;
  ci.layout = prog->layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult r = vkCreateGraphicsPipelines(dev_->vk(), VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline);
  if (r != VK_SUCCESS) {
    dev_->Log(LogLevel::Error, "vkCreateGraphicsPipelines failed (VkResult %d)", r);
    return VK_NULL_HANDLE;
  }
  ++dev_->stats.PipelinesCreated;
  pipelines_[key] = pipeline;
  return pipeline;
}

void PipelineCache::ForgetShader(uint64_t cacheId) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (auto it = computePipelines_.find(cacheId); it != computePipelines_.end()) {
    dev_->Defer(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(it->second));
    computePipelines_.erase(it);
  }
  if (auto it = computePrograms_.find(cacheId); it != computePrograms_.end()) {
    DeferLayouts(*it->second);
    computePrograms_.erase(it);
  }
  for (auto it = pipelines_.begin(); it != pipelines_.end();) {
    if (it->first.shaders.Uses(cacheId)) {
      dev_->Defer(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(it->second));
      it = pipelines_.erase(it);
    } else {
      ++it;
    }
  }
  for (auto it = programs_.begin(); it != programs_.end();) {
    if (it->first.Uses(cacheId)) {
      DeferLayouts(*it->second);
      it = programs_.erase(it);
    } else {
      ++it;
    }
  }
}

void PipelineCache::Destroy() {
  for (auto& [k, p] : pipelines_) vkDestroyPipeline(dev_->vk(), p, nullptr);
  pipelines_.clear();
  for (auto& [k, p] : programs_) DestroyLayouts(*p);
  programs_.clear();
  for (auto& [k, p] : computePipelines_) vkDestroyPipeline(dev_->vk(), p, nullptr);
  computePipelines_.clear();
  for (auto& [k, p] : computePrograms_) DestroyLayouts(*p);
  computePrograms_.clear();
}

ProgramLayout* PipelineCacheFront::GetProgram(PipelineCache& cache, const PerStage<ShaderBase*>& shaders) {
  const ShaderIds key = IdsOf(shaders);
  const size_t hash = WordHash{}(key);
  if (ProgramLayout* hit = programs_.Find(hash, key)) return hit;
  ProgramLayout* p = cache.GetProgram(shaders);
  if (p) programs_.Insert(hash, key, p);
  return p;
}

VkPipeline PipelineCacheFront::GetPipeline(PipelineCache& cache, const PipelineKey& key, const PipelineInputs& in,
                                           ProgramLayout* prog) {
  const size_t hash = WordHash{}(key);
  if (VkPipeline hit = pipelines_.Find(hash, key)) return hit;
  VkPipeline p = cache.GetPipeline(key, in, prog);
  if (p) pipelines_.Insert(hash, key, p);
  return p;
}

}  // namespace d3dl::impl
