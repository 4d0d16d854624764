# ssimarch trace SCENE --format step -o OUT, then occt_step_check OUT 5 (every intersection's
# curve is an edge OCCT can measure).
execute_process(COMMAND ${SSIMARCH} trace ${SCENE} --format step -o ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ssimarch trace failed (${rc})")
endif()
execute_process(COMMAND ${CHECK} ${OUT} 4 RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "OpenCASCADE did not read ${OUT} cleanly: ${out}")
endif()
