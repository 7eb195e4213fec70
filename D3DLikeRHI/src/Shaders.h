// Shader modules of every stage, their SPIR-V reflection (Reflection.cpp)
// and input layouts (Shaders.cpp, InputLayout.cpp).
#pragma once

#include <string>
#include <vector>

#include "Objects.h"
#include "Stages.h"

namespace d3dl::impl {

struct ReflectedBinding {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  uint32_t blockSize = 0;  // uniform buffers: bytes declared by the shader
  bool image1D = false;    // sampled images: Texture1D
  // Sampled images: the view type the shader declares (array, cube) and
  // whether it is multisampled: which dummy an unbound slot reads.
  VkImageViewType viewType = VK_IMAGE_VIEW_TYPE_2D;
  bool multisampled = false;
  std::string name;
};
struct ReflectedInput {
  uint32_t location = 0;
  std::string semantic;  // upper case, without the trailing index
  uint32_t index = 0;
};
// Primitive classes, as the pipeline cache groups topologies (Topology.h).
inline constexpr uint32_t kNoPrimitive = ~0u;
struct ShaderReflection {
  ShaderStage stage = ShaderStage::Vertex;
  std::string entry;
  std::vector<ReflectedBinding> bindings;
  std::vector<ReflectedInput> inputs;  // vertex shaders
  uint32_t outputLocations = 0;        // bit mask
  // Tessellation and geometry: the primitive class a geometry shader takes
  // (with adjacency flagged); the class of the domain a hull or domain shader
  // declares (isolines: lines, triangles and quads: triangles) and its point
  // mode (kNoPrimitive / false: not declared by this stage).
  uint32_t geometryInput = kNoPrimitive;
  bool geometryAdjacency = false;
  uint32_t tessellationDomain = kNoPrimitive;
  bool tessellationPointMode = false;
};
// Parses SPIR-V words. Returns false with a message for malformed code.
bool ReflectSpirv(const uint32_t* words, size_t wordCount, ShaderReflection* out,
                  std::string* error);
// Splits "TEXCOORD1" into "TEXCOORD" and 1 (index 0 without trailing digits).
void SplitSemanticIndex(std::string* semantic, uint32_t* index);

// What the pipeline cache and the context need of a shader of any stage.
// Reference counted like the API object it belongs to, so that bound-state
// slots can hold the shader of any stage.
class ShaderBase {
 public:
  virtual UINT AddRef() = 0;
  virtual UINT Release() = 0;
  uint64_t cacheId = 0;  // the object's uid: the pipeline cache's key
  VkShaderModule module = VK_NULL_HANDLE;
  ShaderReflection refl;

 protected:
  ~ShaderBase() = default;
};

template <class Iface>
class ShaderImpl final : public Child<Iface>, public ShaderBase {
 public:
  explicit ShaderImpl(DeviceImpl* d) : Child<Iface>(d) { cacheId = this->uid(); }
  ~ShaderImpl() override;
  UINT AddRef() override { return Child<Iface>::AddRef(); }
  UINT Release() override { return Child<Iface>::Release(); }
  void OnDebugName() override;
};
using VertexShaderImpl = ShaderImpl<VertexShader>;
using PixelShaderImpl = ShaderImpl<PixelShader>;
using HullShaderImpl = ShaderImpl<HullShader>;
using DomainShaderImpl = ShaderImpl<DomainShader>;
using GeometryShaderImpl = ShaderImpl<GeometryShader>;
using ComputeShaderImpl = ShaderImpl<ComputeShader>;

class InputLayoutImpl final : public Child<InputLayout> {
 public:
  using Child::Child;
  struct Element {
    std::string semantic;  // upper case
    uint32_t index;
    VkFormat format;
    uint32_t slot;
    uint32_t offset;
    bool perInstance;
  };
  std::vector<Element> elements;
  uint32_t slotMask = 0;
};

}  // namespace d3dl::impl
