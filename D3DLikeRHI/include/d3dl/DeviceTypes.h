// D3DLikeRHI public types: device creation and diagnostics, context calls
// (Map, clears), queries, the swap chain and the kinds of context.
#pragma once

#include "d3dl/Formats.h"

namespace d3dl {

// Context operations
enum MAP : uint32_t {
  MAP_READ = 1,
  MAP_WRITE = 2,
  MAP_READ_WRITE = 3,
  MAP_WRITE_DISCARD = 4,
  MAP_WRITE_NO_OVERWRITE = 5,
};

enum MAP_FLAG : uint32_t {
  MAP_FLAG_DO_NOT_WAIT = 0x100000,
};

struct MAPPED_SUBRESOURCE {
  void* pData = nullptr;
  UINT RowPitch = 0;
  UINT DepthPitch = 0;
};

enum CLEAR_FLAG : uint32_t {
  CLEAR_DEPTH = 0x1,
  CLEAR_STENCIL = 0x2,
};

// ---------------------------------------------------------------------------
// Queries
enum QUERY : uint32_t {
  QUERY_EVENT = 0,
  QUERY_TIMESTAMP = 2,
  QUERY_TIMESTAMP_DISJOINT = 3,
  QUERY_PIPELINE_STATISTICS = 4,  // Begin/End; QUERY_DATA_PIPELINE_STATISTICS
};

struct QUERY_DESC {
  QUERY Query = QUERY_EVENT;
  UINT MiscFlags = 0;
};

struct QUERY_DATA_TIMESTAMP_DISJOINT {
  UINT64 Frequency = 0;  // ticks per second
  BOOL Disjoint = 0;
};

// Pipeline statistics (D3D11 field order; counters the adapter cannot count
// read as 0: the geometry ones without geometry shaders, HS/DS without
// tessellation). HSInvocations counts patches, as Vulkan does.
struct QUERY_DATA_PIPELINE_STATISTICS {
  UINT64 IAVertices = 0;
  UINT64 IAPrimitives = 0;
  UINT64 VSInvocations = 0;
  UINT64 GSInvocations = 0;
  UINT64 GSPrimitives = 0;
  UINT64 CInvocations = 0;
  UINT64 CPrimitives = 0;
  UINT64 PSInvocations = 0;
  UINT64 HSInvocations = 0;
  UINT64 DSInvocations = 0;
  UINT64 CSInvocations = 0;
};

enum ASYNC_GETDATA_FLAG : uint32_t {
  ASYNC_GETDATA_DONOTFLUSH = 0x1,
};

// ---------------------------------------------------------------------------
// Swap chain
struct SWAP_CHAIN_DESC {
  UINT Width = 0;   // 0 = the window's framebuffer size
  UINT Height = 0;
  DXGI_FORMAT Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  UINT BufferCount = 2;
};

// ---------------------------------------------------------------------------
// Device creation and diagnostics
enum class LogLevel : uint32_t { Info, Warning, Error, Validation };

// Receives every message of the RHI, including Vulkan validation messages
// (LogLevel::Validation). Called from the thread that made the API call.
using LogCallback = void (*)(LogLevel level, const char* message, void* user);

enum class ValidationMode : uint32_t {
  FromEnvironment,  // D3DL_VALIDATION=0|1|sync decides (default: off)
  Off,
  Core,             // VK_LAYER_KHRONOS_validation
  CoreAndSync,      // plus synchronization validation
};

struct DEVICE_CREATE_DESC {
  ValidationMode Validation = ValidationMode::FromEnvironment;
  LogCallback Log = nullptr;  // nullptr = print warnings and errors to stderr
  void* LogUser = nullptr;
  UINT FramesInFlight = 2;    // frames the CPU may record ahead of the GPU
  bool EnableWindowSurfaces = true;  // request the GLFW surface extensions
  const char* AdapterNameFilter = nullptr;  // substring of the adapter name, or D3DL_ADAPTER
  const char* ApplicationName = "D3DLikeRHI";
};

struct ADAPTER_DESC {
  char Description[256] = {};  // "llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H100 ..."
  char Driver[256] = {};       // "Mesa 22.3.6 (LLVM 15.0.6)"
  UINT VendorId = 0;
  UINT DeviceId = 0;
  UINT ApiVersion = 0;
  bool IsSoftware = false;
  bool SupportsBC = false;
  float TimestampPeriodNs = 1.0f;
};

struct DEVICE_STATS {
  // The validation DEVICE_CREATE_DESC asked for (D3DL_VALIDATION resolved),
  // and the one in force: Off when VK_LAYER_KHRONOS_validation is not
  // installed (a warning says so).
  ValidationMode ValidationRequested = ValidationMode::Off;
  ValidationMode Validation = ValidationMode::Off;
  UINT64 ValidationMessages = 0;  // since device creation
  UINT64 PipelinesCreated = 0;
  // Graphics pipeline lookups that a context's own memo could not answer, so
  // that they took the shared cache's lock (each graphics pipeline created is one of them).
  UINT64 PipelineCacheLookups = 0;
  UINT64 DescriptorSetsAllocated = 0;
  UINT64 DrawCalls = 0;
  UINT64 RingBytesAllocated = 0;
  UINT64 FramesSubmitted = 0;
  // Object lifetime: Vulkan handles destroyed or waiting for their frame, API objects alive.
  UINT64 ObjectsDestroyed = 0;             // Vulkan handles actually destroyed
  UINT64 DeferredDestructionsPending = 0;  // handles waiting for a frame fence
  UINT64 LiveObjects = 0;                  // API objects (resources, views, states...) alive
  // Command pools reset for reuse, and of those the ones whose host memory
  // (the backend's allocator) started over from its beginning: every block
  // the driver allocated while recording came back at the reset.
  UINT64 CommandPoolResets = 0;
  UINT64 CommandPoolRewinds = 0;
};

// ---- Deferred contexts (D3D11_DEVICE_CONTEXT_TYPE) -------------------------
enum DEVICE_CONTEXT_TYPE : uint32_t {
  DEVICE_CONTEXT_IMMEDIATE = 0,
  DEVICE_CONTEXT_DEFERRED = 1,
};

}  // namespace d3dl
