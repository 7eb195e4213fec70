// D3DLikeRHI: a thin Direct3D-11-style API over Vulkan 1.3. Include this.
// Backend extensions without a D3D11 equivalent have headers of their own
// (d3dl/BlitExtension.h).
#pragma once

#include "d3dl/Bindings.h"
#include "d3dl/ComPtr.h"
#include "d3dl/Interfaces.h"
#include "d3dl/Types.h"
