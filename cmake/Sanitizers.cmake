# DRR_SANITIZE=ON: the whole project and its tests with AddressSanitizer and
# UndefinedBehaviorSanitizer (CI's sanitizer job, .ci/run). Undefined
# behaviour stops the program (no recovery), so a test that triggers it fails.
option(DRR_SANITIZE "Build with -fsanitize=address,undefined" OFF)
if(DRR_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

# Debian's glslang is built without RTTI; UBSan's vptr check needs the
# type_info of the classes it checks, so the units that use glslang's classes
# are compiled without that one check. Call after add_subdirectory(D3DLikeRHI).
function(drr_sanitize_glslang_units)
  if(DRR_SANITIZE)
    set_source_files_properties(${ARGN} DIRECTORY ${CMAKE_SOURCE_DIR}/D3DLikeRHI
      PROPERTIES COMPILE_OPTIONS -fno-sanitize=vptr)
  endif()
endfunction()
