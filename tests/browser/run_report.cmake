# Writes a report with the feran command and checks it in the browser.
# Arguments: FERAN, NODE, MODEL, OUT (prefix of the outputs), OPTIONS and SECTIONS
# (|-separated), CHECK (check_report.mjs), WORKDIR (where node finds node_modules).
string(REPLACE "|" ";" options "${OPTIONS}")
string(REPLACE "|" ";" sections "${SECTIONS}")
file(REMOVE "${OUT}.html")
execute_process(COMMAND ${FERAN} report ${MODEL} ${options} -o ${OUT}.html RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "feran report: exit code ${code}: ${err}")
endif()
execute_process(COMMAND ${NODE} ${CHECK} ${OUT}.html ${OUT} ${sections} WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "browser check failed (${code}):\n${err}")
endif()
