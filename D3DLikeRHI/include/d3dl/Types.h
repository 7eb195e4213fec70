// D3DLikeRHI public types: plain D3D11-style enums and *_DESC structs, one
// header per concern (each can be included alone):
//   Base.h          integer types, HRESULT codes
//   Formats.h       DXGI_FORMAT and format queries
//   ResourceDesc.h  buffer and texture descriptions, flags, BOX, RECT
//   ViewDesc.h      shader-resource, render-target, depth-stencil, UAV views
//   StateDesc.h     sampler, blend, depth-stencil, rasterizer, input assembler
//   DeviceTypes.h   device creation and diagnostics, Map, queries, swap chain
//
// Enum values are Direct3D 11's own numbers, so code and constants from the
// D3D11 documentation (filter bit layout, formats) carry over unchanged.
#pragma once

#include "d3dl/Base.h"
#include "d3dl/DeviceTypes.h"
#include "d3dl/Formats.h"
#include "d3dl/ResourceDesc.h"
#include "d3dl/StateDesc.h"
#include "d3dl/ViewDesc.h"
