# ctest driver: runs the quick bench under validation, then checks its outputs.
# -DEXE=... -DCHECK=... -DOUT=...
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${EXE}" --bench --quick --validation --out "${OUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the quick bench exited with ${rc}")
endif()
execute_process(COMMAND "${CHECK}" "${OUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the quick bench outputs failed the checks (${rc})")
endif()
