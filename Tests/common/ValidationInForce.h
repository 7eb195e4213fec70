// The failure text of a test run under validation (D3DL_VALIDATION) on a
// machine where VK_LAYER_KHRONOS_validation is not installed. The device then
// runs without the layer, and the test would pass with nothing checked, so
// every rendering fixture fails it with this text.
#pragma once

namespace drrtest {

inline constexpr char kValidationLayerMissing[] =
    "D3DL_VALIDATION asks for validation, but VK_LAYER_KHRONOS_validation is not installed "
    "(Debian package vulkan-validationlayers)";

}  // namespace drrtest
