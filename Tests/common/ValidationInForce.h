// The failure text of a test run under validation (D3DL_VALIDATION) on a
// machine where VK_LAYER_KHRONOS_validation is not installed. The device then
// runs without the layer, and the test would pass with nothing checked, so
// every rendering fixture fails it with this text.
#pragma once

// The text itself comes from Tests/common/CMakeLists.txt, which the
// layer-guard ctests match against a test's output.
#ifndef DRR_VALIDATION_LAYER_MISSING
#error "DRR_VALIDATION_LAYER_MISSING is defined by the drr_test_headers target"
#endif

namespace drrtest {

inline constexpr char kValidationLayerMissing[] =
    DRR_VALIDATION_LAYER_MISSING " (Debian package vulkan-validationlayers)";

}  // namespace drrtest
