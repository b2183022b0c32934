# Runs the small design study anew into OUT (FERAN, STUDY, OUT).
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND ${FERAN} study ${STUDY} -o ${OUT} --threads 2 RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "feran study: exit code ${code}: ${err}")
endif()
