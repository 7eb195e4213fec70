# Post-processing, zoom box and GUI shaders of the sample (issue #5).
set(_drr_post_common ${CMAKE_CURRENT_SOURCE_DIR}/CommonPost.hlsli ${CMAKE_CURRENT_SOURCE_DIR}/ClearPS.hlsli)
set(_drr_post_outputs)

# drr_post_shader(<output name> <source> <entry> <stage> [defines...])
function(drr_post_shader name source entry stage)
  set(out ${DRR_SHADER_OUT}/${name}.spv)
  d3dl_compile_hlsl(OUTPUT ${out} SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/${source}
                    ENTRY ${entry} STAGE ${stage} DEFINES ${ARGN}
                    DEPENDS ${_drr_post_common})
  set(_drr_post_outputs ${_drr_post_outputs} ${out} PARENT_SCOPE)
endfunction()

# Full-resolution path
drr_post_shader(PostProcess_FullScreenVS PostProcess.hlsl FullScreenVS vert)
drr_post_shader(PostProcess_MotionBlurPS PostProcess.hlsl MotionBlurPS frag)
drr_post_shader(PostProcess_ClearPS PostProcess.hlsl ClearPS frag)
drr_post_shader(PostProcess_ClearVelocityPS PostProcess.hlsl ClearPS frag CLEAR_VELOCITY)
# Dynamic path
drr_post_shader(PostProcessDynamic_FullScreenVS PostProcessDynamic.hlsl FullScreenVS vert)
drr_post_shader(PostProcessDynamic_MotionBlurPS PostProcessDynamic.hlsl MotionBlurPS frag)
drr_post_shader(PostProcessDynamic_ClearPS PostProcessDynamic.hlsl ClearPS frag)
drr_post_shader(PostProcessDynamic_ClearVelocityPS PostProcessDynamic.hlsl ClearPS frag CLEAR_VELOCITY)
drr_post_shader(PostProcessDynamic_ResolvePS PostProcessDynamic.hlsl ResolvePS frag)
drr_post_shader(PostProcessDynamic_BicubicPS PostProcessDynamic.hlsl BicubicPS frag)
drr_post_shader(PostProcessDynamic_NoisePS PostProcessDynamic.hlsl NoisePS frag)
drr_post_shader(PostProcessDynamic_NoiseOffsetPS PostProcessDynamic.hlsl NoiseOffsetPS frag)
drr_post_shader(PostProcessDynamic_TAAPS PostProcessDynamic.hlsl TAAPS frag)
drr_post_shader(PostProcessDynamic_TAAFastPS PostProcessDynamic.hlsl TAAPS frag TAA_FAST)
drr_post_shader(PostProcessDynamic_TAANoiseOffsetPS PostProcessDynamic.hlsl TAANoiseOffsetPS frag)
drr_post_shader(PostProcessDynamic_TAANoiseOffsetFastPS PostProcessDynamic.hlsl TAANoiseOffsetPS frag TAA_FAST)
drr_post_shader(PostProcessDynamic_TAABasicPS PostProcessDynamic.hlsl TAABasicPS frag)
# Zoom box and GUI
drr_post_shader(ZoomBox_ZoomVS ZoomBox.hlsl ZoomVS vert)
drr_post_shader(ZoomBox_ZoomPS ZoomBox.hlsl ZoomPS frag)
drr_post_shader(ZoomBox_BorderPS ZoomBox.hlsl BorderPS frag)
drr_post_shader(Gui_GuiVS Gui.hlsl GuiVS vert)
drr_post_shader(Gui_GuiPS Gui.hlsl GuiPS frag)

add_custom_target(drr_post_shaders ALL DEPENDS ${_drr_post_outputs})
