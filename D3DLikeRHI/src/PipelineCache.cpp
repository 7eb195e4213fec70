// Program layouts (descriptor-set layout + pipeline layout derived from the
// reflected bindings of a VS+PS pair) and graphics pipelines keyed by a
// packed state key. Both are created on first use and cached.
#include "Context.h"

namespace d3dl::impl {

size_t PipelineKeyHash::operator()(const PipelineKey& k) const {
  const auto* p = reinterpret_cast<const uint64_t*>(&k);
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < sizeof(PipelineKey) / 8; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
    h ^= h >> 29;
  }
  return static_cast<size_t>(h);
}
static_assert(sizeof(PipelineKey) % 8 == 0, "PipelineKey is hashed as 64-bit words");

static uint64_t ProgramKey(uint64_t vs, uint64_t ps) { return (vs << 32) ^ ps; }

ProgramLayout* PipelineCache::GetProgram(VertexShaderImpl* vs, PixelShaderImpl* ps) {
  const uint64_t key = ProgramKey(vs->uid(), ps ? ps->uid() : 0);
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second.get();

  auto prog = std::make_unique<ProgramLayout>();
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  auto add = [&](const ShaderReflection& r, uint32_t stage) {
    const uint32_t base = kStageBindingStride * stage;
    for (const auto& b : r.bindings) {
      VkDescriptorSetLayoutBinding lb{};
      lb.binding = b.binding;
      lb.descriptorType = b.type;
      lb.descriptorCount = 1;
      lb.stageFlags = stage == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
      bindings.push_back(lb);
      ProgramLayout::Slot s{static_cast<uint16_t>(b.binding), static_cast<uint8_t>(stage), 0,
                            static_cast<uint8_t>(b.image1D)};
      if (b.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC) {
        s.slot = static_cast<uint8_t>(b.binding - base - kConstantBufferBase);
        prog->cbs.push_back(s);
      } else if (b.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE) {
        s.slot = static_cast<uint8_t>(b.binding - base - kTextureBase);
        prog->srvs.push_back(s);
      } else {
        s.slot = static_cast<uint8_t>(b.binding - base - kSamplerBase);
        prog->samplers.push_back(s);
      }
    }
  };
  add(vs->refl, 0);
  if (ps) add(ps->refl, 1);
  VkDescriptorSetLayoutCreateInfo sci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  sci.bindingCount = static_cast<uint32_t>(bindings.size());
  sci.pBindings = bindings.data();
  if (vkCreateDescriptorSetLayout(dev_->vk(), &sci, nullptr, &prog->setLayout) != VK_SUCCESS) return nullptr;
  VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  lci.setLayoutCount = 1;
  lci.pSetLayouts = &prog->setLayout;
  if (vkCreatePipelineLayout(dev_->vk(), &lci, nullptr, &prog->layout) != VK_SUCCESS) {
    vkDestroyDescriptorSetLayout(dev_->vk(), prog->setLayout, nullptr);
    return nullptr;
  }
  ProgramLayout* p = prog.get();
  programs_[key] = std::move(prog);
  programIds_.push_back({vs->uid(), ps ? ps->uid() : 0});
  return p;
}

VkPipeline PipelineCache::GetPipeline(const PipelineKey& key, const PipelineInputs& in,
                                      ProgramLayout* prog) {
  auto it = pipelines_.find(key);
  if (it != pipelines_.end()) return it->second;

  VkPipelineShaderStageCreateInfo stages[2]{};
  uint32_t nStages = 0;
  stages[nStages] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stages[nStages].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[nStages].module = in.vs->module;
  stages[nStages++].pName = in.vs->refl.entry.c_str();
  if (in.ps) {
    stages[nStages] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[nStages].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[nStages].module = in.ps->module;
    stages[nStages++].pName = in.ps->refl.entry.c_str();
  }

  std::vector<VkVertexInputAttributeDescription> attrs;
  std::vector<VkVertexInputBindingDescription> binds;
  uint32_t slotsUsed = 0;
  for (const auto& input : in.vs->refl.inputs) {
    const InputLayoutImpl::Element* el = nullptr;
    if (in.il)
      for (const auto& e : in.il->elements)
        if (e.semantic == input.semantic && e.index == input.index) el = &e;
    if (!el) {
      dev_->Log(LogLevel::Error, "draw: the vertex shader input %s%u has no element in the bound input layout; draw skipped",
                input.semantic.c_str(), input.index);
      return VK_NULL_HANDLE;
    }
    attrs.push_back({input.location, el->slot, el->format, el->offset});
    if (!(slotsUsed & (1u << el->slot))) {
      slotsUsed |= 1u << el->slot;
      binds.push_back({el->slot, 0,
                       el->perInstance ? VK_VERTEX_INPUT_RATE_INSTANCE : VK_VERTEX_INPUT_RATE_VERTEX});
    }
  }
  VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vi.vertexBindingDescriptionCount = static_cast<uint32_t>(binds.size());
  vi.pVertexBindingDescriptions = binds.data();
  vi.vertexAttributeDescriptionCount = static_cast<uint32_t>(attrs.size());
  vi.pVertexAttributeDescriptions = attrs.data();

  VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  ia.topology = key.topologyClass == 0   ? VK_PRIMITIVE_TOPOLOGY_POINT_LIST
                : key.topologyClass == 1 ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST
                                         : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  vp.viewportCount = 1;
  vp.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo rs = in.raster->ci;
  VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  ms.alphaToCoverageEnable = in.blend->desc.AlphaToCoverageEnable ? VK_TRUE : VK_FALSE;
  VkPipelineDepthStencilStateCreateInfo ds = in.depth->ci;
  if (key.ds == VK_FORMAT_UNDEFINED) {
    ds.depthTestEnable = ds.depthWriteEnable = ds.stencilTestEnable = VK_FALSE;
  }
  VkPipelineColorBlendAttachmentState att[SIMULTANEOUS_RENDER_TARGET_COUNT];
  for (uint32_t i = 0; i < key.numRT; ++i) {
    att[i] = in.blend->att[i];
    if (key.rt[i] == VK_FORMAT_UNDEFINED) att[i].colorWriteMask = 0;
  }
  VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  cb.attachmentCount = key.numRT;
  cb.pAttachments = att;
  VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                          VK_DYNAMIC_STATE_BLEND_CONSTANTS, VK_DYNAMIC_STATE_STENCIL_REFERENCE,
                          VK_DYNAMIC_STATE_VERTEX_INPUT_BINDING_STRIDE,
                          VK_DYNAMIC_STATE_PRIMITIVE_TOPOLOGY};
  VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dy.dynamicStateCount = sizeof(dyn) / sizeof(dyn[0]);
  if (binds.empty()) {  // no vertex buffers: no stride state to set
    dyn[4] = dyn[5];
    --dy.dynamicStateCount;
  }
  dy.pDynamicStates = dyn;
  VkPipelineRenderingCreateInfo ri{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  ri.colorAttachmentCount = key.numRT;
  ri.pColorAttachmentFormats = key.rt;
  ri.depthAttachmentFormat = key.ds;

  VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  ci.pNext = &ri;
  ci.stageCount = nStages;
  ci.pStages = stages;
  ci.pVertexInputState = &vi;
  ci.pInputAssemblyState = &ia;
  ci.pViewportState = &vp;
  ci.pRasterizationState = &rs;
  ci.pMultisampleState = &ms;
  ci.pDepthStencilState = &ds;
  ci.pColorBlendState = &cb;
  ci.pDynamicState = &dy;
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

void PipelineCache::ForgetShader(uint64_t uid) {
  for (auto it = pipelines_.begin(); it != pipelines_.end();) {
    if (it->first.vs == uid || it->first.ps == uid) {
      dev_->Defer(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(it->second));
      it = pipelines_.erase(it);
    } else {
      ++it;
    }
  }
  for (auto it = programIds_.begin(); it != programIds_.end();) {
    if (it->first == uid || it->second == uid) {
      auto p = programs_.find(ProgramKey(it->first, it->second));
      if (p != programs_.end()) {
        dev_->Defer(VK_OBJECT_TYPE_PIPELINE_LAYOUT, reinterpret_cast<uint64_t>(p->second->layout));
        dev_->Defer(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, reinterpret_cast<uint64_t>(p->second->setLayout));
        programs_.erase(p);
      }
      it = programIds_.erase(it);
    } else {
      ++it;
    }
  }
}

void PipelineCache::Destroy() {
  for (auto& [k, p] : pipelines_) vkDestroyPipeline(dev_->vk(), p, nullptr);
  pipelines_.clear();
  for (auto& [k, p] : programs_) {
    vkDestroyPipelineLayout(dev_->vk(), p->layout, nullptr);
    vkDestroyDescriptorSetLayout(dev_->vk(), p->setLayout, nullptr);
  }
  programs_.clear();
  programIds_.clear();
}

}  // namespace d3dl::impl
