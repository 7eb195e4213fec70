// D3DLikeRHI public types, part 1: the integer types and HRESULT codes every
// other header uses (Direct3D 11's own values).
#pragma once

#include <cstddef>
#include <cstdint>

namespace d3dl {

using HRESULT = int32_t;
using UINT = uint32_t;
using UINT64 = uint64_t;
using BOOL = int32_t;

inline constexpr HRESULT S_OK = 0;
inline constexpr HRESULT S_FALSE = 1;  // query data not ready yet
inline constexpr HRESULT E_NOTIMPL = static_cast<HRESULT>(0x80004001u);
inline constexpr HRESULT E_FAIL = static_cast<HRESULT>(0x80004005u);
inline constexpr HRESULT E_OUTOFMEMORY = static_cast<HRESULT>(0x8007000Eu);
inline constexpr HRESULT E_INVALIDARG = static_cast<HRESULT>(0x80070057u);
inline constexpr HRESULT DXGI_ERROR_UNSUPPORTED = static_cast<HRESULT>(0x887A0004u);
inline constexpr HRESULT DXGI_ERROR_DEVICE_REMOVED = static_cast<HRESULT>(0x887A0005u);
inline constexpr HRESULT DXGI_ERROR_WAS_STILL_DRAWING = static_cast<HRESULT>(0x887A000Au);
inline constexpr HRESULT DXGI_STATUS_OCCLUDED = static_cast<HRESULT>(0x087A0001u);

inline constexpr bool SUCCEEDED(HRESULT hr) { return hr >= 0; }
inline constexpr bool FAILED(HRESULT hr) { return hr < 0; }

// A call made on the wrong kind of context (FinishCommandList on the
// immediate context, GetData on a deferred one).
inline constexpr HRESULT DXGI_ERROR_INVALID_CALL = static_cast<HRESULT>(0x887A0001u);

// Human-readable name of an HRESULT ("E_INVALIDARG", ...).
const char* HResultName(HRESULT hr);

}  // namespace d3dl
