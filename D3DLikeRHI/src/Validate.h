// Argument validation of the public API, apart from the Vulkan code (like
// sokol's _sg_validate_* or NVRHI's validation layer). Each function logs one
// message naming the offending value, as the call would in D3D11's debug
// layer, and returns whether the call may go on (HRESULT for factories).
// The validators see the device through ValidationDevice (its log, format
// queries, limits and features in plain numbers), resources through
// ResourceInfo (their D3D11 description), views through ViewInfo and queries
// through QueryInfo, never a backend object; the contexts do the casts. What
// they return is in D3D11 terms, and the backend translates it (Views.cpp:
// formats, aspects, view types).
// The Vulkan-side code after them assumes valid arguments.
// ValidateDevice.cpp: object creation. ValidateViews.cpp: views and resolves.
// ValidateContext.cpp: context calls. ValidateBlit.cpp, ValidateDraw.cpp.
#pragma once

#include "Formats.h"
#include "OnceError.h"
#include "Stages.h"
#include "ValidationDevice.h"

namespace d3dl::impl {

// ---- object creation (ValidateDevice.cpp)
// "fn: descName is null" / "fn: outName is null" when either pointer is null.
bool ValidatePointers(ValidationDevice& dev, const char* fn, const void* desc, const char* descName,
                      const void* out, const char* outName);
HRESULT ValidateCreateBuffer(ValidationDevice& dev, const BUFFER_DESC* desc, const SUBRESOURCE_DATA* init,
                             Buffer** out);
// Also completes the description: MipLevels 0 becomes the full chain.
HRESULT ValidateCreateTexture(ValidationDevice& dev, const char* fn, bool is1D, const SUBRESOURCE_DATA* init,
                              TEXTURE2D_DESC* desc);

// The three view kinds: their factory, output parameter and bind flag.
struct ViewKindInfo {
  const char* fn;
  const char* outName;
  UINT bind;
  const char* bindName;
};
inline constexpr ViewKindInfo kSrvKind{"CreateShaderResourceView", "ppSRView", BIND_SHADER_RESOURCE,
                                       "BIND_SHADER_RESOURCE"};
inline constexpr ViewKindInfo kRtvKind{"CreateRenderTargetView", "ppRTView", BIND_RENDER_TARGET,
                                       "BIND_RENDER_TARGET"};
inline constexpr ViewKindInfo kDsvKind{"CreateDepthStencilView", "ppDepthStencilView", BIND_DEPTH_STENCIL,
                                       "BIND_DEPTH_STENCIL"};
// The aspect of a texture a view sees: colour; the depth of a depth
// texture (SRVs); every aspect of the depth image (DSVs: depth, stencil).
enum class ViewAspect : uint8_t { Color, Depth, Attachment };
// The format a view of a texture reads it as (`requested`, or the texture's
// own) and the aspect it sees (ValidateViews.cpp: typeless families, depth views).
struct ViewFormat {
  DXGI_FORMAT format = DXGI_FORMAT_UNKNOWN;
  ViewAspect aspect = ViewAspect::Color;
};
// `r` is the resource the call names (null is logged).
HRESULT ValidateViewResource(ValidationDevice& dev, const ViewKindInfo& kind, const ResourceInfo& r, const void* out,
                             DXGI_FORMAT requested, ViewFormat* format);
// The D3D11 view dimensions of all three kinds in one list (their numbers differ per kind).
enum class ViewDim : uint8_t { Unknown, Tex1D, Tex1DArray, Tex2D, Tex2DArray, Tex2DMS, Tex2DMSArray, Cube, CubeArray, Invalid };
ViewDim FromSrvDimension(SRV_DIMENSION d);
ViewDim FromRtvDimension(RTV_DIMENSION d);
ViewDim FromDsvDimension(DSV_DIMENSION d);
// The dimension (never Unknown or Invalid), mips and array slices a view covers.
struct ViewShape {
  ViewDim dim = ViewDim::Tex2D;
  uint32_t baseMip = 0, mipCount = 1, baseLayer = 0, layerCount = 1;
};
// SRVs: all mips and slices without a description.
HRESULT ValidateSrvShape(ValidationDevice& dev, const ResourceInfo& t, const SHADER_RESOURCE_VIEW_DESC* desc,
                         ViewShape* shape);
// RTVs and DSVs: one mip, the slices of `range` for *ARRAY dimensions;
// `rawDim` is the description's ViewDimension (named when `dim` is Invalid).
HRESULT ValidateTargetShape(ValidationDevice& dev, const ViewKindInfo& kind, const ResourceInfo& t, ViewDim dim,
                            UINT rawDim, UINT mip, const TEX_ARRAY_RANGE& range, ViewShape* shape);

// UAVs and buffer views (ValidateDevice.cpp).
inline constexpr ViewKindInfo kUavKind{"CreateUnorderedAccessView", "ppUAView", BIND_UNORDERED_ACCESS,
                                       "BIND_UNORDERED_ACCESS"};
// What a buffer view names: its resource's elements [first, first + num).
struct BufferViewRequest {
  DXGI_FORMAT format;
  UINT first, num, flags;
  bool raw;  // BUFFEREX_SRV_FLAG_RAW / BUFFER_UAV_FLAG_RAW
};
// The request of a buffer SRV or UAV description (null: the whole structured
// buffer), after checking that its dimension names a buffer.
HRESULT BufferSrvRequest(ValidationDevice& dev, const SHADER_RESOURCE_VIEW_DESC* desc, BufferViewRequest* req);
HRESULT BufferUavRequest(ValidationDevice& dev, const UNORDERED_ACCESS_VIEW_DESC* desc, BufferViewRequest* req);
// A structured or raw view of `r` (a buffer; `req` null: all of it);
// *offset/*range in bytes.
HRESULT ValidateBufferView(ValidationDevice& dev, const ViewKindInfo& kind, const ResourceInfo& r, const void* out,
                           const BufferViewRequest* req, UINT64* offset, UINT64* range);
// A texture UAV: its format and mip (desc may be null).
HRESULT ValidateTextureUav(ValidationDevice& dev, const ResourceInfo& r, const UNORDERED_ACCESS_VIEW_DESC* desc,
                           const void* out, ViewFormat* format, uint32_t* mip);

HRESULT ValidateSamplerDesc(ValidationDevice& dev, const SAMPLER_DESC* desc, SamplerState** out);
HRESULT ValidateBlendDesc(ValidationDevice& dev, const BLEND_DESC* desc, BlendState** out);
HRESULT ValidateDepthStencilDesc(ValidationDevice& dev, const DEPTH_STENCIL_DESC* desc, DepthStencilState** out);
HRESULT ValidateRasterizerDesc(ValidationDevice& dev, const RASTERIZER_DESC* desc, RasterizerState** out);
HRESULT ValidateShaderBytecode(ValidationDevice& dev, const char* fn, const void* code, size_t len, const void* out);
HRESULT ValidateCreateQuery(ValidationDevice& dev, const QUERY_DESC* desc, Query** out);
HRESULT ValidateHeadlessSwapChain(ValidationDevice& dev, const SWAP_CHAIN_DESC& desc);

// ---- context calls (ValidateContext.cpp)
// "<stage><fn>: slots a..b out of range (0..count-1)".
bool ValidateSlots(ValidationDevice& dev, const char* stage, const char* fn, UINT start, UINT num, UINT count);
// Whether a buffer (`desc`; null: unbinding) may be bound; false (logged)
// when it lacks the bind flag (the slot is then unbound).
bool ValidateVertexBuffer(ValidationDevice& dev, const BUFFER_DESC* desc, UINT slot);
bool ValidateConstantBuffer(ValidationDevice& dev, ShaderStage stage, const BUFFER_DESC* desc, UINT slot);
bool ValidateIndexBuffer(ValidationDevice& dev, const BUFFER_DESC* desc, DXGI_FORMAT format);
bool ValidateViewports(ValidationDevice& dev, UINT num, const VIEWPORT* viewports);
bool ValidateScissorRects(ValidationDevice& dev, UINT num, const RECT* rects);
bool ValidateRenderTargets(ValidationDevice& dev, UINT num, RenderTargetView* const* rtvs);
// The sample counts of the `num` render targets (0: an empty slot) and of
// the depth-stencil view (0: none) must agree.
bool ValidateTargetSamples(ValidationDevice& dev, UINT num, const UINT* rtvSamples, UINT dsvSamples);

bool ValidateClearRenderTargetView(ValidationDevice& dev, RenderTargetView* rtv, const float color[4]);
bool ValidateClearDepthStencilView(ValidationDevice& dev, DepthStencilView* dsv);
// Whether `view` can be cleared (logged when not); `renderTarget`: it is a
// render-target view.
bool ValidateClearView(ValidationDevice& dev, const View* view, bool renderTarget, const float color[4],
                       const RECT* rects, UINT numRects);

HRESULT ValidateMap(ValidationDevice& dev, const ResourceInfo& r, UINT sub, MAP type, const MAPPED_SUBRESOURCE* mapped);
// The region to write: [left, right) of a buffer, or a box inside a texture
// mip. False when there is nothing to do (logged when the call is invalid;
// an empty box is a no-op, as in D3D11).
bool ValidateUpdateSubresource(ValidationDevice& dev, const ResourceInfo& dst, UINT sub, const BOX* box,
                               const void* data, UINT rowPitch, BOX* region);
// `same`: source and destination are one resource.
bool ValidateCopySubresourceRegion(ValidationDevice& dev, const ResourceInfo& dst, UINT dstSub, UINT x, UINT y,
                                   const ResourceInfo& src, UINT srcSub, const BOX* box, bool same);
bool ValidateCopyTextureRegion(ValidationDevice& dev, const ResourceInfo& dst, UINT dstSub, UINT x, UINT y,
                               const ResourceInfo& src, UINT srcSub, const BOX* box);
// Whole-resource checks; each subresource of a texture copy is then checked
// with ValidateCopyTextureRegion.
bool ValidateCopyResource(ValidationDevice& dev, const ResourceInfo& dst, const ResourceInfo& src, bool same);
// `srv`: the view (null: none given).
bool ValidateGenerateMips(ValidationDevice& dev, const ViewInfo* srv);

// ResolveSubresource (ValidateViews.cpp): multisampled source, single-sampled
// destination of the same size, `format` in both families, resolvable.
bool ValidateResolveSubresource(ValidationDevice& dev, const ResourceInfo& dst, UINT dstSub, const ResourceInfo& src,
                                UINT srcSub, DXGI_FORMAT format);

// BlitRegion: `dst`/`src` describe the two textures (null ones: UNKNOWN);
// `same`: they are one texture.
bool ValidateBlitRegion(ValidationDevice& dev, const ResourceInfo& dst, const RECT& dstRect, const ResourceInfo& src,
                        const RECT& srcRect, FILTER filter, bool same);
// Whether the blit filters linearly: the filter's magnification half when
// the blit enlarges or keeps the size on both axes, else its minification half.
bool BlitIsLinear(const RECT& dstRect, const RECT& srcRect, FILTER filter);

// "IASetPrimitiveTopology: topology N is not supported" outside 0..5, 33..64.
bool ValidateTopology(ValidationDevice& dev, PRIMITIVE_TOPOLOGY t);

// UAV binding, dispatch and indirect arguments (ValidateContext.cpp).
// Whether a UAV (null: unbinding) may be bound at `slot`; false (logged) when
// it names no resource (the slot is then unbound).
bool ValidateUavBinding(ValidationDevice& dev, const char* fn, const ViewInfo* uav, UINT slot);
bool ValidateDispatch(ValidationDevice& dev, UINT x, UINT y, UINT z);
// DispatchIndirect and the indirect draws (`fn`): `args`, the argument buffer
// (UNKNOWN dimension: null), created with RESOURCE_MISC_DRAWINDIRECT_ARGS, and
// `argBytes` of arguments at `offset`, a multiple of 4, inside it.
bool ValidateIndirectArgs(ValidationDevice& dev, const char* fn, const ResourceInfo& args, UINT offset, UINT argBytes);
// The arguments' sizes in D3D11: 3 UINTs (thread groups), 4 UINTs
// (DrawInstancedIndirect), 5 UINTs (DrawIndexedInstancedIndirect).
inline constexpr UINT kDispatchArgsBytes = 12, kDrawArgsBytes = 16, kDrawIndexedArgsBytes = 20;
// Whether the UAV (null: none given) can be cleared (logged when not);
// `isFloat`: ClearUnorderedAccessViewFloat.
bool ValidateClearUav(ValidationDevice& dev, const ViewInfo* uav, const void* values, bool isFloat);
bool ValidateOMUavs(ValidationDevice& dev, UINT numRTVs, UINT uavStart, UINT numUAVs);
// Whether ClearUnorderedAccessViewUint can write the bits of this view format
// exactly (ContextCompute.cpp).
bool UavClearBitsSupported(DXGI_FORMAT f);

bool ValidateBegin(ValidationDevice& dev, const QUERY_DESC& desc);
// What GetData checks of a query: the size of its data and whether it was ended.
struct QueryInfo {
  UINT dataSize = 0;
  bool ended = false;
};
// `q`: the query (null: none given).
bool ValidateGetData(ValidationDevice& dev, const QueryInfo* q, const void* data, UINT size);

// ---- deferred contexts (ValidateContext.cpp)
HRESULT ValidateCreateDeferredContext(ValidationDevice& dev, UINT flags, DeviceContext** out);
HRESULT ValidateFinishCommandList(ValidationDevice& dev, bool deferredContext, CommandList** out);
// `ownList`: `list` was recorded on this device.
bool ValidateExecuteCommandList(ValidationDevice& dev, bool deferredContext, const CommandList* list, bool ownList);
// Map on a deferred context: DYNAMIC buffers, WRITE_DISCARD, or NO_OVERWRITE
// after a WRITE_DISCARD of the same buffer in the list being recorded.
HRESULT ValidateDeferredMap(ValidationDevice& dev, const ResourceInfo& r, UINT sub, MAP type,
                            const MAPPED_SUBRESOURCE* mapped, bool discardedInList);
// UpdateSubresource on a deferred context: constant buffers only (this port).
bool ValidateDeferredUpdate(ValidationDevice& dev, const ResourceInfo& dst);

// ---- Draw-time checks (ValidateDraw.cpp). What a draw needs of the bound
// state, in D3D11 terms (ContextImpl::DrawInputsOf fills it).
struct DrawInputs {
  bool indexed = false;
  bool vertexShader = false, target = false, indexBuffer = false;
  PRIMITIVE_TOPOLOGY topology = PRIMITIVE_TOPOLOGY_UNDEFINED;
  bool hull = false, domain = false, geometry = false;
  uint32_t tessellatorOutput = 0;  // primitive class the tessellator emits (hull and domain bound)
  uint32_t geometryInput = 0;      // the geometry shader's input primitive class
  bool emptyViewport = false;      // a bound viewport of zero width or height
};
enum class DrawVerdict { Draw, SkipSilently, SkipWithError };
// D3D11 draws nothing when state is missing or the stages do not fit each
// other and the topology (its debug layer reports it; Vulkan would reject the
// pipeline): SkipWithError with *error the problem, checked in a fixed order.
// An empty viewport draws nothing without an error.
DrawVerdict ValidateDraw(const DrawInputs& in, OnceError* error);
// The UAVs a program writes (pixel shader at a draw, compute shader at a
// dispatch): false, with *error, when the stage cannot store on this adapter
// or a declared slot lacks a view of the kind the shader declares.
struct ShaderUavInputs {
  bool declared = false;         // the program writes UAVs
  bool storesSupported = true;   // pixel shaders: fragmentStoresAndAtomics
  bool allBound = true;
};
bool ValidateShaderUavs(const ShaderUavInputs& in, OnceError* error);
// Dispatch: a compute shader must be bound.
bool ValidateDispatchShader(bool computeShaderBound, OnceError* error);

}  // namespace d3dl::impl
