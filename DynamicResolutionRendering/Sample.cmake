# The sample application (issue #5): DynamicResolutionRendering executable,
# drr_sample (everything but main, for in-process tests) and drr_options
# (command-line parser, no GPU).
set(DRR_SAMPLE_DIR ${CMAKE_CURRENT_LIST_DIR})

add_library(drr_options STATIC ${DRR_SAMPLE_DIR}/Options.cpp ${DRR_SAMPLE_DIR}/Json.cpp)
target_include_directories(drr_options PUBLIC ${DRR_SAMPLE_DIR})
target_compile_features(drr_options PUBLIC cxx_std_20)
target_link_libraries(drr_options PUBLIC drr_core)  # ControlMode, ControlLaw and their names

# The RHI, the scene renderer and the controller core are declared by other
# units (some after this file is included), so the GPU targets are defined at
# the end of this directory.
function(drr_define_sample_targets)
  if(NOT TARGET D3DLikeRHI OR NOT TARGET drr_scene OR NOT TARGET drr_core)
    message(STATUS "Sample: D3DLikeRHI, drr_scene or drr_core not available yet; "
                   "the DynamicResolutionRendering executable is not built")
    return()
  endif()
  add_library(drr_sample STATIC
    ${DRR_SAMPLE_DIR}/DynamicResolutionRendering.cpp
    ${DRR_SAMPLE_DIR}/GPUTimer.cpp
    ${DRR_SAMPLE_DIR}/TexGenUtils.cpp
    ${DRR_SAMPLE_DIR}/ZoomBox.cpp
    ${DRR_SAMPLE_DIR}/Utility.cpp
    ${DRR_SAMPLE_DIR}/GuiRenderer.cpp)
  target_include_directories(drr_sample PUBLIC ${DRR_SAMPLE_DIR})
  target_link_libraries(drr_sample PUBLIC drr_options drr_core drr_scene D3DLikeRHI glfw glm::glm
                        drr_imageio PkgConfig::IMGUI)
  target_compile_definitions(drr_sample PRIVATE
    DRR_DEFAULT_SHADER_DIR="${DRR_SHADER_OUT}"
    DRR_DEFAULT_SCENE="${DRR_ARENA_DIR}/scene_description.txt"
    DRR_SHADER_SOURCE_DIR="${CMAKE_SOURCE_DIR}/Shaders")
  set(deps drr_post_shaders)
  foreach(t drr_arena drr_scene_shaders)
    if(TARGET ${t})
      list(APPEND deps ${t})
    endif()
  endforeach()
  add_dependencies(drr_sample ${deps})

  add_executable(DynamicResolutionRendering ${DRR_SAMPLE_DIR}/Main.cpp)
  target_link_libraries(DynamicResolutionRendering PRIVATE drr_sample)
  set_target_properties(DynamicResolutionRendering PROPERTIES
    RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/DynamicResolutionRendering)
endfunction()
cmake_language(DEFER CALL drr_define_sample_targets)
