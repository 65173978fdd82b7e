# Writes the bash completion of `prism` (OUTPUT) with the program's hidden
# option --bash-completion (app/completion.h), at build time.
execute_process(COMMAND "${PRISM}" --bash-completion
  OUTPUT_FILE "${OUTPUT}.tmp" RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PRISM} --bash-completion failed (${status}): ${errors}")
endif()
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
