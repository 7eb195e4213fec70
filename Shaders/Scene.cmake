# Scene shaders (issue #4): 8 pixel-shader variants (NORMAL_MAP x SPECULAR_MAP x
# WRITE_VELOCITY), scene_ps_n<N>_s<S>_v<V>.spv, and the 4 vertex-shader variants
# whose outputs match them, scene_vs_n<N>_v<V>.spv.
set(_drr_scene_src ${CMAKE_CURRENT_SOURCE_DIR}/SceneShaders.hlsl)
set(_drr_scene_outputs)
foreach(n 0 1)
  foreach(v 0 1)
    set(_out ${DRR_SHADER_OUT}/scene_vs_n${n}_v${v}.spv)
    d3dl_compile_hlsl(OUTPUT ${_out} SOURCE ${_drr_scene_src} ENTRY SceneVS STAGE vert
                      DEFINES NORMAL_MAP=${n} WRITE_VELOCITY=${v})
    list(APPEND _drr_scene_outputs ${_out})
  endforeach()
endforeach()
foreach(n 0 1)
  foreach(s 0 1)
    foreach(v 0 1)
      set(_out ${DRR_SHADER_OUT}/scene_ps_n${n}_s${s}_v${v}.spv)
      d3dl_compile_hlsl(OUTPUT ${_out} SOURCE ${_drr_scene_src} ENTRY ScenePS STAGE frag
                        DEFINES NORMAL_MAP=${n} SPECULAR_MAP=${s} WRITE_VELOCITY=${v})
      list(APPEND _drr_scene_outputs ${_out})
    endforeach()
  endforeach()
endforeach()
add_custom_target(drr_scene_shaders ALL DEPENDS ${_drr_scene_outputs})
