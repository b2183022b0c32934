# Runs a command that must fail: checks its exit code is EXIT_CODE, that its
# standard error matches REGEX and carries no stack trace, and that it wrote no
# output file (NO_FILE). Arguments: EXE, ARGS (a |-separated list), EXIT_CODE,
# REGEX, NO_FILE.
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE "${NO_FILE}" "${NO_FILE}.part")
execute_process(COMMAND ${EXE} ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL EXIT_CODE)
  message(FATAL_ERROR "exit code ${code}, expected ${EXIT_CODE}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT err MATCHES "${REGEX}")
  message(FATAL_ERROR "stderr does not match '${REGEX}':\n${err}")
endif()
if(err MATCHES "terminate called|what\\(\\)|Aborted|Segmentation")
  message(FATAL_ERROR "crash output on stderr:\n${err}")
endif()
if(EXISTS "${NO_FILE}" OR EXISTS "${NO_FILE}.part")
  message(FATAL_ERROR "an output file was written: ${NO_FILE}")
endif()
