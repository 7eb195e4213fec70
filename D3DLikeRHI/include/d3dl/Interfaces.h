// D3DLikeRHI public interfaces: ID3D11Device / ID3D11DeviceContext /
// IDXGISwapChain with the "ID3D11" prefix dropped. Objects are reference
// counted like COM objects (AddRef/Release, see ComPtr.h); an object whose
// count drops to zero while the GPU may still use it is destroyed only after
// the fence of the last frame that used it has signalled.
#pragma once

#include "d3dl/Types.h"

struct GLFWwindow;

namespace d3dl {

class Device;

class Unknown {
 public:
  virtual UINT AddRef() = 0;
  virtual UINT Release() = 0;

 protected:
  virtual ~Unknown() = default;
};

class DeviceChild : public Unknown {
 public:
  // Name shown by validation messages and RenderDoc (VK_EXT_debug_utils).
  virtual void SetDebugName(const char* name) = 0;
};

class Resource : public DeviceChild {
 public:
  virtual RESOURCE_DIMENSION GetType() const = 0;
};

class Buffer : public Resource {
 public:
  virtual void GetDesc(BUFFER_DESC* desc) const = 0;
};

class Texture1D : public Resource {
 public:
  virtual void GetDesc(TEXTURE1D_DESC* desc) const = 0;
};

class Texture2D : public Resource {
 public:
  virtual void GetDesc(TEXTURE2D_DESC* desc) const = 0;
};

class View : public DeviceChild {
 public:
  // Returns the viewed resource with a reference added (as D3D11 does).
  virtual void GetResource(Resource** resource) const = 0;
};

class ShaderResourceView : public View {};
class RenderTargetView : public View {};
class DepthStencilView : public View {};

class SamplerState : public DeviceChild {
 public:
  virtual void GetDesc(SAMPLER_DESC* desc) const = 0;
};
class BlendState : public DeviceChild {
 public:
  virtual void GetDesc(BLEND_DESC* desc) const = 0;
};
class DepthStencilState : public DeviceChild {
 public:
  virtual void GetDesc(DEPTH_STENCIL_DESC* desc) const = 0;
};
class RasterizerState : public DeviceChild {
 public:
  virtual void GetDesc(RASTERIZER_DESC* desc) const = 0;
};

class InputLayout : public DeviceChild {};
class VertexShader : public DeviceChild {};
class PixelShader : public DeviceChild {};
// Tessellation and geometry shaders.
class HullShader : public DeviceChild {};
class DomainShader : public DeviceChild {};
class GeometryShader : public DeviceChild {};

// Views a shader writes (u# registers of compute and pixel shaders), and
// compute shaders.
class UnorderedAccessView : public View {};
class ComputeShader : public DeviceChild {};

class Query : public DeviceChild {
 public:
  virtual void GetDesc(QUERY_DESC* desc) const = 0;
  virtual UINT GetDataSize() const = 0;
};

// ---------------------------------------------------------------------------
// Immediate context. Setters only record state; state is committed at draw
// time. Work is submitted by Flush() or SwapChain::Present().
class CommandList;

class DeviceContext : public Unknown {
 public:
  // Input assembler
  virtual void IASetInputLayout(InputLayout* layout) = 0;
  virtual void IASetVertexBuffers(UINT startSlot, UINT numBuffers, Buffer* const* buffers,
                                  const UINT* strides, const UINT* offsets) = 0;
  virtual void IASetIndexBuffer(Buffer* buffer, DXGI_FORMAT format, UINT offset) = 0;
  virtual void IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY topology) = 0;

  // Vertex shader stage
  virtual void VSSetShader(VertexShader* shader) = 0;
  virtual void VSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) = 0;
  virtual void VSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) = 0;
  virtual void VSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) = 0;

  // Pixel shader stage
  virtual void PSSetShader(PixelShader* shader) = 0;
  virtual void PSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) = 0;
  virtual void PSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) = 0;
  virtual void PSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) = 0;

  // Hull, domain and geometry shaders with
  // their constant buffers, shader resources and samplers, as VS*/PS*. A
  // hull shader needs a domain shader and a patch-list topology, and the
  // reverse; a geometry shader's input primitive matches the topology (or
  // the tessellator's output).
  virtual void HSSetShader(HullShader* shader) = 0;
  virtual void HSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) = 0;
  virtual void HSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) = 0;
  virtual void HSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) = 0;
  virtual void DSSetShader(DomainShader* shader) = 0;
  virtual void DSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) = 0;
  virtual void DSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) = 0;
  virtual void DSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) = 0;
  virtual void GSSetShader(GeometryShader* shader) = 0;
  virtual void GSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) = 0;
  virtual void GSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) = 0;
  virtual void GSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) = 0;

  // Rasterizer
  virtual void RSSetViewports(UINT num, const VIEWPORT* viewports) = 0;
  virtual void RSSetScissorRects(UINT num, const RECT* rects) = 0;
  virtual void RSSetState(RasterizerState* state) = 0;  // nullptr = default state

  // Output merger (nullptr states = D3D11 defaults)
  virtual void OMSetRenderTargets(UINT num, RenderTargetView* const* rtvs, DepthStencilView* dsv) = 0;
  virtual void OMSetBlendState(BlendState* state, const float blendFactor[4], UINT sampleMask) = 0;
  virtual void OMSetDepthStencilState(DepthStencilState* state, UINT stencilRef) = 0;
  // Returns the bound views with references added (nullptr where unbound).
  virtual void OMGetRenderTargets(UINT num, RenderTargetView** rtvs, DepthStencilView** dsv) = 0;

  // Clears
  virtual void ClearRenderTargetView(RenderTargetView* rtv, const float color[4]) = 0;
  virtual void ClearDepthStencilView(DepthStencilView* dsv, UINT clearFlags, float depth,
                                     uint8_t stencil) = 0;
  // D3D11.1 ClearView: clears only the given rectangles (all of it if numRects == 0).
  virtual void ClearView(View* view, const float color[4], const RECT* rects, UINT numRects) = 0;

  // Draws
  virtual void Draw(UINT vertexCount, UINT startVertex) = 0;
  virtual void DrawIndexed(UINT indexCount, UINT startIndex, int32_t baseVertex) = 0;
  virtual void DrawInstanced(UINT vertexCountPerInstance, UINT instanceCount, UINT startVertex,
                             UINT startInstance) = 0;
  virtual void DrawIndexedInstanced(UINT indexCountPerInstance, UINT instanceCount,
                                    UINT startIndex, int32_t baseVertex, UINT startInstance) = 0;
  // The arguments come from a RESOURCE_MISC_DRAWINDIRECT_ARGS buffer at
  // `alignedByteOffset` (a multiple of 4), read when the GPU runs the draw:
  // four UINTs (VertexCountPerInstance, InstanceCount, StartVertexLocation,
  // StartInstanceLocation), or five for the indexed draw (IndexCountPerInstance,
  // InstanceCount, StartIndexLocation, INT BaseVertexLocation,
  // StartInstanceLocation). Bad arguments log one error and drop the call.
  virtual void DrawInstancedIndirect(Buffer* args, UINT alignedByteOffset) = 0;
  virtual void DrawIndexedInstancedIndirect(Buffer* args, UINT alignedByteOffset) = 0;

  // Resource access
  virtual HRESULT Map(Resource* resource, UINT subresource, MAP mapType, UINT mapFlags,
                      MAPPED_SUBRESOURCE* mapped) = 0;
  virtual void Unmap(Resource* resource, UINT subresource) = 0;
  virtual void UpdateSubresource(Resource* dst, UINT dstSubresource, const BOX* dstBox,
                                 const void* srcData, UINT srcRowPitch, UINT srcDepthPitch) = 0;
  virtual void CopyResource(Resource* dst, Resource* src) = 0;
  virtual void CopySubresourceRegion(Resource* dst, UINT dstSubresource, UINT dstX, UINT dstY,
                                     UINT dstZ, Resource* src, UINT srcSubresource,
                                     const BOX* srcBox) = 0;
  virtual void GenerateMips(ShaderResourceView* srv) = 0;

  // Queries
  virtual void Begin(Query* query) = 0;
  virtual void End(Query* query) = 0;
  // S_OK with data written, S_FALSE when not ready, an error for bad arguments.
  virtual HRESULT GetData(Query* query, void* data, UINT dataSize, UINT flags) = 0;

  // Debug labels (ID3DUserDefinedAnnotation): Vulkan debug-utils labels.
  virtual void BeginEvent(const char* name) = 0;
  virtual void EndEvent() = 0;

  // Compute shaders and UAVs (ContextCompute.cpp). Dispatches and draws
  // see each other's writes in call order, as in D3D11: the barriers are
  // inserted automatically. A resource bound as a UAV is unbound from every
  // SRV slot; an SRV of a resource bound as a UAV is bound as null.
  virtual void CSSetShader(ComputeShader* shader) = 0;
  virtual void CSSetConstantBuffers(UINT startSlot, UINT num, Buffer* const* buffers) = 0;
  virtual void CSSetShaderResources(UINT startSlot, UINT num, ShaderResourceView* const* views) = 0;
  virtual void CSSetSamplers(UINT startSlot, UINT num, SamplerState* const* samplers) = 0;
  // initialCounts (append/consume counters) are not supported and ignored.
  virtual void CSSetUnorderedAccessViews(UINT startSlot, UINT num, UnorderedAccessView* const* views,
                                         const UINT* initialCounts) = 0;
  virtual void Dispatch(UINT groupsX, UINT groupsY, UINT groupsZ) = 0;
  // Three UINTs at `offset` of a RESOURCE_MISC_DRAWINDIRECT_ARGS buffer (as
  // the indirect draws).
  virtual void DispatchIndirect(Buffer* args, UINT offset) = 0;
  virtual void ClearUnorderedAccessViewUint(UnorderedAccessView* uav, const UINT values[4]) = 0;
  virtual void ClearUnorderedAccessViewFloat(UnorderedAccessView* uav, const float values[4]) = 0;
  // Pixel-shader UAVs share the slots with the render targets: uavStartSlot >=
  // numRTVs. KEEP_* leaves that half as it is.
  virtual void OMSetRenderTargetsAndUnorderedAccessViews(UINT numRTVs, RenderTargetView* const* rtvs,
                                                         DepthStencilView* dsv, UINT uavStartSlot,
                                                         UINT numUAVs, UnorderedAccessView* const* uavs,
                                                         const UINT* initialCounts) = 0;

  // Unbinds everything and restores default states.
  virtual void ClearState() = 0;
  // Submits the recorded work (a frame boundary for the constant ring and
  // deferred destruction when no swap chain presents).
  virtual void Flush() = 0;

  // ---- Multisample resolve
  // Averages the samples of multisampled `src` subresource into single-sampled
  // `dst` (same size; `format` names the typed format both are read as).
  // Integer and depth formats are rejected, as in D3D11.
  virtual void ResolveSubresource(Resource* dst, UINT dstSubresource, Resource* src,
                                  UINT srcSubresource, DXGI_FORMAT format) = 0;
  // ---- Deferred contexts (D3D11 semantics; threading rules in
  // Docs/D3D11-to-Vulkan.md). Each context is used by one thread at a time.
  virtual DEVICE_CONTEXT_TYPE GetType() = 0;
  // Deferred contexts only: ends the recording as a command list. FALSE resets
  // the context to default state, TRUE keeps its state for the next list.
  virtual HRESULT FinishCommandList(BOOL restoreDeferredContextState, CommandList** commandList) = 0;
  // Immediate context only: runs the list (any number of times, until it is
  // released). Afterwards the context's state is its prior state (TRUE) or the
  // default state (FALSE).
  virtual void ExecuteCommandList(CommandList* commandList, BOOL restoreContextState) = 0;
};

// Recorded commands of a deferred context (ID3D11CommandList).
class CommandList : public DeviceChild {
 public:
  virtual UINT GetContextFlags() = 0;
};

// ---------------------------------------------------------------------------
class SwapChain : public Unknown {
 public:
  // syncInterval 0 = no vsync (mailbox/immediate where available), 1 = vsync (FIFO).
  // Returns S_OK, or DXGI_STATUS_OCCLUDED while the window is minimised (nothing shown).
  virtual HRESULT Present(UINT syncInterval, UINT flags) = 0;
  // The current back buffer (index is ignored except 0, as in FLIP_DISCARD).
  virtual HRESULT GetBuffer(UINT index, Texture2D** backBuffer) = 0;
  // width/height 0 = the window's current framebuffer size. All references to
  // the old back buffers must have been released (as in DXGI).
  virtual HRESULT ResizeBuffers(UINT bufferCount, UINT width, UINT height, DXGI_FORMAT format,
                                UINT flags) = 0;
  virtual void GetDesc(SWAP_CHAIN_DESC* desc) const = 0;
  virtual bool IsHeadless() const = 0;
};

// ---------------------------------------------------------------------------
class Device : public Unknown {
 public:
  virtual HRESULT CreateBuffer(const BUFFER_DESC* desc, const SUBRESOURCE_DATA* initialData,
                               Buffer** buffer) = 0;
  virtual HRESULT CreateTexture1D(const TEXTURE1D_DESC* desc, const SUBRESOURCE_DATA* initialData,
                                  Texture1D** texture) = 0;
  // initialData: one entry per subresource (mip-major within each array slice).
  virtual HRESULT CreateTexture2D(const TEXTURE2D_DESC* desc, const SUBRESOURCE_DATA* initialData,
                                  Texture2D** texture) = 0;
  // desc may be nullptr: a view of the whole resource in its own format.
  virtual HRESULT CreateShaderResourceView(Resource* resource,
                                           const SHADER_RESOURCE_VIEW_DESC* desc,
                                           ShaderResourceView** view) = 0;
  virtual HRESULT CreateRenderTargetView(Resource* resource, const RENDER_TARGET_VIEW_DESC* desc,
                                         RenderTargetView** view) = 0;
  virtual HRESULT CreateDepthStencilView(Resource* resource, const DEPTH_STENCIL_VIEW_DESC* desc,
                                         DepthStencilView** view) = 0;

  virtual HRESULT CreateSamplerState(const SAMPLER_DESC* desc, SamplerState** state) = 0;
  virtual HRESULT CreateBlendState(const BLEND_DESC* desc, BlendState** state) = 0;
  virtual HRESULT CreateDepthStencilState(const DEPTH_STENCIL_DESC* desc,
                                          DepthStencilState** state) = 0;
  virtual HRESULT CreateRasterizerState(const RASTERIZER_DESC* desc, RasterizerState** state) = 0;

  // Shaders are SPIR-V words (bytecode size in bytes, a multiple of 4), compiled
  // from HLSL with the binding shifts of Bindings.h and -fhlsl_functionality1
  // (so vertex inputs keep their semantic names for CreateInputLayout).
  virtual HRESULT CreateVertexShader(const void* bytecode, size_t bytecodeLength,
                                     VertexShader** shader) = 0;
  virtual HRESULT CreatePixelShader(const void* bytecode, size_t bytecodeLength,
                                    PixelShader** shader) = 0;
  // Tessellation and geometry shaders (SPIR-V as above, compiled as tesc,
  // tese and geom). E_NOTIMPL with a message when the adapter lacks
  // tessellationShader / geometryShader.
  virtual HRESULT CreateHullShader(const void* bytecode, size_t bytecodeLength,
                                   HullShader** shader) = 0;
  virtual HRESULT CreateDomainShader(const void* bytecode, size_t bytecodeLength,
                                     DomainShader** shader) = 0;
  virtual HRESULT CreateGeometryShader(const void* bytecode, size_t bytecodeLength,
                                       GeometryShader** shader) = 0;
  // Matches elements to the vertex shader's inputs by semantic name and index.
  virtual HRESULT CreateInputLayout(const INPUT_ELEMENT_DESC* elements, UINT numElements,
                                    const void* vsBytecode, size_t vsBytecodeLength,
                                    InputLayout** layout) = 0;

  virtual HRESULT CreateQuery(const QUERY_DESC* desc, Query** query) = 0;

  // A view a shader writes through (u#). desc may be nullptr for a texture (mip 0
  // in its own format) and for a structured buffer (all of it).
  virtual HRESULT CreateUnorderedAccessView(Resource* resource, const UNORDERED_ACCESS_VIEW_DESC* desc,
                                            UnorderedAccessView** view) = 0;
  virtual HRESULT CreateComputeShader(const void* bytecode, size_t bytecodeLength,
                                      ComputeShader** shader) = 0;

  // Swap chains. A headless swap chain renders into an offscreen image that
  // can be read back with CopyResource into a STAGING texture and Map(READ).
  virtual HRESULT CreateSwapChainForWindow(GLFWwindow* window, const SWAP_CHAIN_DESC* desc,
                                           SwapChain** swapChain) = 0;
  virtual HRESULT CreateHeadlessSwapChain(const SWAP_CHAIN_DESC* desc, SwapChain** swapChain) = 0;

  virtual void GetImmediateContext(DeviceContext** context) = 0;
  // ---- Deferred contexts: contextFlags must be 0 (as in D3D11).
  virtual HRESULT CreateDeferredContext(UINT contextFlags, DeviceContext** context) = 0;
  virtual void GetAdapterDesc(ADAPTER_DESC* desc) const = 0;
  virtual void GetStats(DEVICE_STATS* stats) const = 0;
  // Whether the format can be used with the given BIND_* flags on this adapter.
  virtual bool CheckFormatSupport(DXGI_FORMAT format, UINT bindFlags) const = 0;
  // Waits until the GPU has finished all submitted work.
  virtual void WaitIdle() = 0;

  // ---- Multisampling support
  // *numQualityLevels = 1 when `format` can be a `sampleCount`-sample render
  // target (or depth-stencil) texture on this adapter, else 0 (Quality must be 0).
  virtual HRESULT CheckMultisampleQualityLevels(DXGI_FORMAT format, UINT sampleCount,
                                                UINT* numQualityLevels) const = 0;
};

// Creates the Vulkan instance, picks an adapter and creates the device and
// its immediate context. On failure the log callback says why.
HRESULT CreateDevice(const DEVICE_CREATE_DESC* desc, Device** device, DeviceContext** context);
// Devices of this process not yet destroyed (vkDestroyDevice not yet called):
// 0 after a clean shutdown; otherwise some object still holds its device.
UINT LiveDeviceCount();

}  // namespace d3dl
