# HLSL -> SPIR-V at build time with glslang's HLSL front end.
#
# D3D register slots map to Vulkan bindings (descriptor set 0) by ONE formula,
# the same one D3DLikeRHI/include/d3dl/Bindings.h states and the RHI tests check:
#
#   binding = 72 * stage + classBase + slot
#   stage:     VS = 0, PS = 1, HS = 2, DS = 3, GS = 4, CS = 5
#   classBase: b# (cbuffer) = 0   (slots 0..13)
#              t# (texture, StructuredBuffer, ByteAddressBuffer) = 16  (slots 0..31)
#              s# (sampler) = 48  (slots 0..15)
#              u# (RWTexture2D, RWStructuredBuffer, RWByteAddressBuffer) = 64 (slots 0..7)
#
# It is applied with glslang's per-stage binding shifts, so the HLSL keeps its
# register(b0)/register(t3)/register(s1)/register(u2) annotations unchanged.
# --hlsl-iomap classes resources by register class (t, u) rather than by SPIR-V
# kind, so a StructuredBuffer in t# and a RWStructuredBuffer in u# shift apart.
set(D3DL_STAGE_STRIDE 72)
set(D3DL_CBUFFER_BASE 0)
set(D3DL_TEXTURE_BASE 16)
set(D3DL_SAMPLER_BASE 48)
set(D3DL_UAV_BASE 64)

# d3dl_hlsl_shift_args(<out-var> <stage: vert|frag|tesc|tese|geom|comp>)
# (glslang's names of the VS, PS, HS, DS, GS and CS stages)
function(d3dl_hlsl_shift_args out stage)
  if(stage STREQUAL "vert")
    set(index 0)
  elseif(stage STREQUAL "frag")
    set(index 1)
  elseif(stage STREQUAL "tesc")
    set(index 2)
  elseif(stage STREQUAL "tese")
    set(index 3)
  elseif(stage STREQUAL "geom")
    set(index 4)
  elseif(stage STREQUAL "comp")
    set(index 5)
  else()
    message(FATAL_ERROR "d3dl: unsupported shader stage '${stage}'")
  endif()
  math(EXPR base "${D3DL_STAGE_STRIDE} * ${index}")
  math(EXPR cb "${base} + ${D3DL_CBUFFER_BASE}")
  math(EXPR tex "${base} + ${D3DL_TEXTURE_BASE}")
  math(EXPR smp "${base} + ${D3DL_SAMPLER_BASE}")
  math(EXPR uav "${base} + ${D3DL_UAV_BASE}")
  set(${out}
      --hlsl-iomap
      --shift-UBO-binding ${stage} ${cb}
      --shift-texture-binding ${stage} ${tex}
      --shift-sampler-binding ${stage} ${smp}
      --shift-UAV-binding ${stage} ${uav}
      PARENT_SCOPE)
endfunction()

# SPIR-V 1.3: glslang's HLSL front end declares StructuredBuffer and
# (RW)ByteAddressBuffer with the BufferBlock decoration, which SPIR-V 1.4 and
# later reject; nothing the shaders use needs a later version.
# d3dl_compile_hlsl(OUTPUT <spv> SOURCE <hlsl> ENTRY <name> STAGE <vert|frag|tesc|tese|geom|comp>
#                   [DEFINES A=1 B ...] [DEPENDS extra headers...] [NO_SEMANTICS])
# Produces one .spv; only this shader rebuilds when its source or headers change.
# NO_SEMANTICS leaves out -fhlsl_functionality1 (no HLSL semantic strings in
# the SPIR-V): for shaders handed to raw Vulkan, which must not see them.
function(d3dl_compile_hlsl)
  cmake_parse_arguments(A "NO_SEMANTICS" "OUTPUT;SOURCE;ENTRY;STAGE" "DEFINES;DEPENDS" ${ARGN})
  set(semantics -fhlsl_functionality1)
  set(flags "")
  if(A_NO_SEMANTICS)
    set(semantics "")
    set(flags "no-semantics")
  endif()
  d3dl_hlsl_shift_args(shifts ${A_STAGE})
  set(defs)
  foreach(d IN LISTS A_DEFINES)
    list(APPEND defs "-D${d}")
  endforeach()
  get_filename_component(src_dir ${A_SOURCE} DIRECTORY)
  # Remembered for the manifest that the runtime-compiler test replays.
  string(JOIN "," joined_defines ${A_DEFINES})
  set_property(GLOBAL APPEND PROPERTY D3DL_HLSL_MANIFEST
               "${A_SOURCE}|${A_ENTRY}|${A_STAGE}|${joined_defines}|${A_OUTPUT}|${flags}")
  add_custom_command(
    OUTPUT ${A_OUTPUT}
    COMMAND ${GLSLANG_VALIDATOR} -D -V --target-env vulkan1.3 --target-env spirv1.3 ${semantics}
            --hlsl-offsets -S ${A_STAGE} -e ${A_ENTRY} ${shifts} ${defs}
            -I${src_dir} -o ${A_OUTPUT} ${A_SOURCE}
    DEPENDS ${A_SOURCE} ${A_DEPENDS}
    COMMENT "HLSL ${A_ENTRY} (${A_STAGE}) -> ${A_OUTPUT}"
    VERBATIM)
endfunction()

# Writes build/shader_manifest.txt: one line per compiled shader,
# "source|entry|stage|DEF=1,DEF2|output.spv|flags". Call once, after every unit.
function(d3dl_write_hlsl_manifest)
  get_property(entries GLOBAL PROPERTY D3DL_HLSL_MANIFEST)
  string(JOIN "\n" text ${entries})
  file(WRITE ${CMAKE_BINARY_DIR}/shader_manifest.txt "${text}\n")
endfunction()
