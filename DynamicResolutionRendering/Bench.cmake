# --bench (issue #6): image error against run time. Needs the sample library,
# which Sample.cmake declares in a deferred call; this unit defers twice so it
# is defined after it.
function(drr_define_bench_targets)
  if(NOT TARGET drr_sample)
    return()
  endif()
  set(dir ${CMAKE_CURRENT_SOURCE_DIR})
  add_library(drr_bench STATIC ${dir}/bench/Bench.cpp ${dir}/bench/BenchReport.cpp)
  target_include_directories(drr_bench PUBLIC ${dir})
  target_link_libraries(drr_bench PUBLIC drr_sample drr_analysis)
  target_link_libraries(DynamicResolutionRendering PRIVATE drr_bench)
  target_compile_definitions(DynamicResolutionRendering PRIVATE DRR_HAVE_BENCH=1)
endfunction()
function(drr_defer_bench_targets)
  cmake_language(DEFER CALL drr_define_bench_targets)
endfunction()
cmake_language(DEFER CALL drr_defer_bench_targets)
