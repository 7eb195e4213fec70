# Image error metrics and report plots (CPU only), used by the --bench mode.
add_library(drr_analysis STATIC
  ${CMAKE_CURRENT_LIST_DIR}/analysis/ImageMetrics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/analysis/Plot.cpp)
target_include_directories(drr_analysis PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(drr_analysis PUBLIC drr_imageio PRIVATE PkgConfig::IMGUI)
