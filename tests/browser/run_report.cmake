# Writes the reports of reports.txt with the feran command, then checks them all in
# the browser at once (check_report.mjs). Arguments: FERAN, NODE, EXAMPLES (the
# examples folder), HERE (tests/browser), OUT (the output folder), WORKDIR (where node
# finds node_modules).
file(STRINGS ${HERE}/reports.txt lines REGEX "^[^#]")
set(check_args "")
foreach(line ${lines})
  string(REPLACE "{OUT}" "${OUT}" line "${line}")
  string(REPLACE "{HERE}" "${HERE}" line "${line}")
  string(REPLACE "|" ";" fields "${line}")
  list(GET fields 0 name)
  list(GET fields 1 model)
  list(GET fields 2 options)
  list(GET fields 3 sections)
  string(STRIP "${name}" name)
  string(STRIP "${model}" model)
  string(STRIP "${options}" options)
  string(STRIP "${sections}" sections)
  separate_arguments(options UNIX_COMMAND "${options}")
  file(REMOVE "${OUT}/${name}.html")
  execute_process(COMMAND ${FERAN} report ${EXAMPLES}/${model} ${options} -o ${OUT}/${name}.html -q
                  RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "feran report ${model}: exit code ${code}: ${err}")
  endif()
  list(APPEND check_args ${OUT}/${name}.html ${OUT}/${name} ${sections})
endforeach()
execute_process(COMMAND ${NODE} ${HERE}/check_report.mjs ${check_args} WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "browser check failed (${code}):\n${err}")
endif()
