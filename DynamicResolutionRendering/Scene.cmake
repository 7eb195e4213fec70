# Scene unit (issue #4): scene description, Assimp/OpenImageIO loaders, the
# Arena generator, the model probe and the scene renderer.
set(DRR_SCENE_DIR ${CMAKE_CURRENT_LIST_DIR}/scene)

# Debian's OpenImageIO CMake package lists /usr/include/opencv4 (from its
# build) among its include directories although libopencv-dev is not a
# dependency; drop include paths that do not exist so generation does not fail.
if(TARGET OpenImageIO::OpenImageIO)
  get_target_property(_oiio_inc OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
  if(_oiio_inc)
    set(_oiio_keep)
    foreach(_d IN LISTS _oiio_inc)
      if(EXISTS "${_d}" OR _d MATCHES "^\\$<")
        list(APPEND _oiio_keep "${_d}")
      endif()
    endforeach()
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_keep}")
  endif()
endif()

# CPU side: no GPU, usable by tools and tests on any machine.
add_library(drr_scene_cpu STATIC
  ${DRR_SCENE_DIR}/SceneDescription.cpp
  ${DRR_SCENE_DIR}/ModelLoader.cpp
  ${DRR_SCENE_DIR}/TextureLoader.cpp)
target_include_directories(drr_scene_cpu PUBLIC ${CMAKE_CURRENT_LIST_DIR}
  ${CMAKE_SOURCE_DIR}/D3DLikeRHI/include)  # header-only use of d3dl/Types.h (DXGI_FORMAT)
target_link_libraries(drr_scene_cpu PUBLIC glm::glm assimp::assimp drr_imageio)

add_executable(drr_model_probe ${DRR_SCENE_DIR}/ModelProbe.cpp)
target_link_libraries(drr_model_probe PRIVATE drr_scene_cpu)

# The Arena generator and the generated default scenes (build time).
add_executable(drr_arenagen ${CMAKE_CURRENT_LIST_DIR}/tools/ArenaGen.cpp)
target_link_libraries(drr_arenagen PRIVATE glm::glm OpenImageIO::OpenImageIO)
set(DRR_ARENA_DIR ${CMAKE_BINARY_DIR}/Media/Arena CACHE INTERNAL "")
set(DRR_ARENA_LARGE_DIR ${CMAKE_BINARY_DIR}/Media/ArenaLarge CACHE INTERNAL "")
add_custom_command(
  OUTPUT ${DRR_ARENA_DIR}/scene_description.txt
  COMMAND drr_arenagen --detail small --out ${DRR_ARENA_DIR}
  DEPENDS drr_arenagen
  COMMENT "Generating the small Arena into ${DRR_ARENA_DIR}"
  VERBATIM)
add_custom_command(
  OUTPUT ${DRR_ARENA_LARGE_DIR}/scene_description.txt
  COMMAND drr_arenagen --detail large --out ${DRR_ARENA_LARGE_DIR}
  DEPENDS drr_arenagen
  COMMENT "Generating the large Arena into ${DRR_ARENA_LARGE_DIR}"
  VERBATIM)
add_custom_target(drr_arena ALL DEPENDS ${DRR_ARENA_DIR}/scene_description.txt)
add_custom_target(drr_arena_large ALL DEPENDS ${DRR_ARENA_LARGE_DIR}/scene_description.txt)

# GPU side: the renderer (needs the RHI).
if(TARGET D3DLikeRHI AND EXISTS ${DRR_SCENE_DIR}/Scene.cpp)
  add_library(drr_scene STATIC ${DRR_SCENE_DIR}/Scene.cpp)
  target_link_libraries(drr_scene PUBLIC drr_scene_cpu D3DLikeRHI)
  target_compile_definitions(drr_scene PRIVATE
    DRR_SCENE_SHADER_DIR="${DRR_SHADER_OUT}"
    DRR_SCENE_HLSL="${CMAKE_SOURCE_DIR}/Shaders/SceneShaders.hlsl")
  if(TARGET drr_scene_shaders)
    add_dependencies(drr_scene drr_scene_shaders)
  endif()
endif()
