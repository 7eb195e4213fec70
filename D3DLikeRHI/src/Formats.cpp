// DXGI_FORMAT <-> VkFormat table, HRESULT names and small enum conversions.
#include <cctype>

#include "Formats.h"
#include "Objects.h"

namespace d3dl {
namespace {
using impl::FormatInfo;
constexpr FormatInfo kFormats[] = {
    {DXGI_FORMAT_R32G32B32A32_FLOAT, VK_FORMAT_R32G32B32A32_SFLOAT, 16, false, false, false, "R32G32B32A32_FLOAT"},
    {DXGI_FORMAT_R32G32B32_FLOAT, VK_FORMAT_R32G32B32_SFLOAT, 12, false, false, false, "R32G32B32_FLOAT"},
    {DXGI_FORMAT_R16G16B16A16_FLOAT, VK_FORMAT_R16G16B16A16_SFLOAT, 8, false, false, false, "R16G16B16A16_FLOAT", DXGI_FORMAT_R16G16B16A16_TYPELESS},
    {DXGI_FORMAT_R16G16B16A16_UNORM, VK_FORMAT_R16G16B16A16_UNORM, 8, false, false, false, "R16G16B16A16_UNORM", DXGI_FORMAT_R16G16B16A16_TYPELESS},
    {DXGI_FORMAT_R32G32_FLOAT, VK_FORMAT_R32G32_SFLOAT, 8, false, false, false, "R32G32_FLOAT"},
    {DXGI_FORMAT_R10G10B10A2_TYPELESS, VK_FORMAT_A2B10G10R10_UNORM_PACK32, 4, false, false, false, "R10G10B10A2_TYPELESS", DXGI_FORMAT_R10G10B10A2_TYPELESS, true},
    {DXGI_FORMAT_R10G10B10A2_UNORM, VK_FORMAT_A2B10G10R10_UNORM_PACK32, 4, false, false, false, "R10G10B10A2_UNORM", DXGI_FORMAT_R10G10B10A2_TYPELESS},
    {DXGI_FORMAT_R11G11B10_FLOAT, VK_FORMAT_B10G11R11_UFLOAT_PACK32, 4, false, false, false, "R11G11B10_FLOAT"},
    {DXGI_FORMAT_R8G8B8A8_TYPELESS, VK_FORMAT_R8G8B8A8_UNORM, 4, false, false, false, "R8G8B8A8_TYPELESS", DXGI_FORMAT_R8G8B8A8_TYPELESS, true},
    {DXGI_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM, 4, false, false, false, "R8G8B8A8_UNORM", DXGI_FORMAT_R8G8B8A8_TYPELESS},
    {DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, VK_FORMAT_R8G8B8A8_SRGB, 4, false, false, false, "R8G8B8A8_UNORM_SRGB", DXGI_FORMAT_R8G8B8A8_TYPELESS},
    {DXGI_FORMAT_R8G8B8A8_UINT, VK_FORMAT_R8G8B8A8_UINT, 4, false, false, true, "R8G8B8A8_UINT", DXGI_FORMAT_R8G8B8A8_TYPELESS},
    {DXGI_FORMAT_R16G16_FLOAT, VK_FORMAT_R16G16_SFLOAT, 4, false, false, false, "R16G16_FLOAT"},
    {DXGI_FORMAT_R32_TYPELESS, VK_FORMAT_R32_SFLOAT, 4, false, false, false, "R32_TYPELESS", DXGI_FORMAT_R32_TYPELESS, true, VK_FORMAT_D32_SFLOAT},
    {DXGI_FORMAT_D32_FLOAT, VK_FORMAT_D32_SFLOAT, 4, false, true, false, "D32_FLOAT", DXGI_FORMAT_R32_TYPELESS, false, VK_FORMAT_D32_SFLOAT},
    {DXGI_FORMAT_R32_FLOAT, VK_FORMAT_R32_SFLOAT, 4, false, false, false, "R32_FLOAT", DXGI_FORMAT_R32_TYPELESS},
    {DXGI_FORMAT_R32_UINT, VK_FORMAT_R32_UINT, 4, false, false, true, "R32_UINT", DXGI_FORMAT_R32_TYPELESS},
    {DXGI_FORMAT_R24G8_TYPELESS, VK_FORMAT_D24_UNORM_S8_UINT, 4, false, false, false, "R24G8_TYPELESS", DXGI_FORMAT_R24G8_TYPELESS, true, VK_FORMAT_D24_UNORM_S8_UINT, true},
    {DXGI_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT, 4, false, true, false, "D24_UNORM_S8_UINT", DXGI_FORMAT_R24G8_TYPELESS, false, VK_FORMAT_D24_UNORM_S8_UINT, true},
    {DXGI_FORMAT_R24_UNORM_X8_TYPELESS, VK_FORMAT_D24_UNORM_S8_UINT, 4, false, false, false, "R24_UNORM_X8_TYPELESS", DXGI_FORMAT_R24G8_TYPELESS},
    {DXGI_FORMAT_R8G8_UNORM, VK_FORMAT_R8G8_UNORM, 2, false, false, false, "R8G8_UNORM"},
    {DXGI_FORMAT_R16_FLOAT, VK_FORMAT_R16_SFLOAT, 2, false, false, false, "R16_FLOAT"},
    {DXGI_FORMAT_R16_UINT, VK_FORMAT_R16_UINT, 2, false, false, true, "R16_UINT"},
    {DXGI_FORMAT_R8_UNORM, VK_FORMAT_R8_UNORM, 1, false, false, false, "R8_UNORM"},
    {DXGI_FORMAT_BC1_UNORM, VK_FORMAT_BC1_RGBA_UNORM_BLOCK, 8, true, false, false, "BC1_UNORM", DXGI_FORMAT_BC1_UNORM},
    {DXGI_FORMAT_BC1_UNORM_SRGB, VK_FORMAT_BC1_RGBA_SRGB_BLOCK, 8, true, false, false, "BC1_UNORM_SRGB", DXGI_FORMAT_BC1_UNORM},
    {DXGI_FORMAT_BC2_UNORM, VK_FORMAT_BC2_UNORM_BLOCK, 16, true, false, false, "BC2_UNORM", DXGI_FORMAT_BC2_UNORM},
    {DXGI_FORMAT_BC2_UNORM_SRGB, VK_FORMAT_BC2_SRGB_BLOCK, 16, true, false, false, "BC2_UNORM_SRGB", DXGI_FORMAT_BC2_UNORM},
    {DXGI_FORMAT_BC3_UNORM, VK_FORMAT_BC3_UNORM_BLOCK, 16, true, false, false, "BC3_UNORM", DXGI_FORMAT_BC3_UNORM},
    {DXGI_FORMAT_BC3_UNORM_SRGB, VK_FORMAT_BC3_SRGB_BLOCK, 16, true, false, false, "BC3_UNORM_SRGB", DXGI_FORMAT_BC3_UNORM},
    {DXGI_FORMAT_BC4_UNORM, VK_FORMAT_BC4_UNORM_BLOCK, 8, true, false, false, "BC4_UNORM"},
    {DXGI_FORMAT_BC4_SNORM, VK_FORMAT_BC4_SNORM_BLOCK, 8, true, false, false, "BC4_SNORM"},
    {DXGI_FORMAT_BC5_UNORM, VK_FORMAT_BC5_UNORM_BLOCK, 16, true, false, false, "BC5_UNORM"},
    {DXGI_FORMAT_BC5_SNORM, VK_FORMAT_BC5_SNORM_BLOCK, 16, true, false, false, "BC5_SNORM"},
    {DXGI_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_B8G8R8A8_UNORM, 4, false, false, false, "B8G8R8A8_UNORM", DXGI_FORMAT_B8G8R8A8_UNORM},
    {DXGI_FORMAT_B8G8R8A8_UNORM_SRGB, VK_FORMAT_B8G8R8A8_SRGB, 4, false, false, false, "B8G8R8A8_UNORM_SRGB", DXGI_FORMAT_B8G8R8A8_UNORM},
};
}  // namespace

const char* HResultName(HRESULT hr) {
  switch (hr) {
    case S_OK: return "S_OK";
    case S_FALSE: return "S_FALSE";
    case E_NOTIMPL: return "E_NOTIMPL";
    case E_FAIL: return "E_FAIL";
    case E_OUTOFMEMORY: return "E_OUTOFMEMORY";
    case E_INVALIDARG: return "E_INVALIDARG";
    case DXGI_ERROR_UNSUPPORTED: return "DXGI_ERROR_UNSUPPORTED";
    case DXGI_ERROR_DEVICE_REMOVED: return "DXGI_ERROR_DEVICE_REMOVED";
    case DXGI_ERROR_WAS_STILL_DRAWING: return "DXGI_ERROR_WAS_STILL_DRAWING";
    case DXGI_STATUS_OCCLUDED: return "DXGI_STATUS_OCCLUDED";
    default: return "HRESULT(unknown)";
  }
}

UINT FormatBytesPerElement(DXGI_FORMAT format) {
  const auto* f = impl::GetFormatInfo(format);
  return f ? f->bytes : 0;
}
bool FormatIsBlockCompressed(DXGI_FORMAT format) {
  const auto* f = impl::GetFormatInfo(format);
  return f && f->bc;
}
const char* FormatName(DXGI_FORMAT format) {
  if (format == DXGI_FORMAT_UNKNOWN) return "UNKNOWN";
  const auto* f = impl::GetFormatInfo(format);
  return f ? f->name : "UNSUPPORTED_FORMAT";
}

namespace impl {
bool SameFamily(const FormatInfo& tex, const FormatInfo& view) {
  if (tex.dxgi == view.dxgi) return true;
  return tex.family != DXGI_FORMAT_UNKNOWN && tex.family == view.family;
}
VkFormat DepthImageFormat(const FormatInfo& f) {
  return f.depthVk;
}
const FormatInfo* GetFormatInfo(DXGI_FORMAT f) {
  for (const auto& e : kFormats)
    if (e.dxgi == f) return &e;
  return nullptr;
}
VkFormat ToVkFormat(DXGI_FORMAT f) {
  const auto* e = GetFormatInfo(f);
  return e ? e->vk : VK_FORMAT_UNDEFINED;
}
VkCompareOp ToVkCompare(COMPARISON_FUNC f) {
  switch (f) {
    case COMPARISON_NEVER: return VK_COMPARE_OP_NEVER;
    case COMPARISON_LESS: return VK_COMPARE_OP_LESS;
    case COMPARISON_EQUAL: return VK_COMPARE_OP_EQUAL;
    case COMPARISON_LESS_EQUAL: return VK_COMPARE_OP_LESS_OR_EQUAL;
    case COMPARISON_GREATER: return VK_COMPARE_OP_GREATER;
    case COMPARISON_NOT_EQUAL: return VK_COMPARE_OP_NOT_EQUAL;
    case COMPARISON_GREATER_EQUAL: return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case COMPARISON_ALWAYS: return VK_COMPARE_OP_ALWAYS;
  }
  return VK_COMPARE_OP_ALWAYS;
}
std::string ToUpper(const char* s) {
  std::string r = s ? s : "";
  for (auto& c : r) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return r;
}
}  // namespace impl
}  // namespace d3dl
