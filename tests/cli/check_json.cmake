# Runs feran with --json and checks that the documented keys are present
# (docs/output-format.md). Arguments: EXE, ARGS (|-separated), JSON (output path),
# KEYS (|-separated; each a space-separated path of members and array indices).
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE "${JSON}")
execute_process(COMMAND ${EXE} ${args} --json ${JSON} --quiet RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "exit code ${code}: ${err}")
endif()
file(READ "${JSON}" text)
string(REPLACE "|" ";" keys "${KEYS}")
foreach(key ${keys})
  string(REPLACE " " ";" path "${key}")
  string(JSON value ERROR_VARIABLE error GET "${text}" ${path})
  if(error)
    message(FATAL_ERROR "missing '${key}' in ${JSON}: ${error}")
  endif()
endforeach()
