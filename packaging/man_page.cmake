# Writes the manual page prism.1 (gzipped, OUTPUT) with help2man from the
# program's --help texts: `prism --help` for the synopsis and the commands,
# and, in a COMMANDS section help2man takes from an --include file, each
# command's own `prism COMMAND --help`. The commands are those `prism --help`
# lists, so a new one is documented without a change here.
# Run at build time: cmake -DPRISM=... -DHELP2MAN=... -DGZIP=... -DOUTPUT=... -P man_page.cmake

# The program run as `prism` (found on PATH), so that its usage lines say
# `prism` and not the build folder's path.
get_filename_component(bin_dir "${PRISM}" DIRECTORY)
set(ENV{PATH} "${bin_dir}:$ENV{PATH}")

function(help_of out)
  execute_process(COMMAND prism ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE status
    ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "prism ${ARGN} --help failed (${status}): ${errors}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# The commands: the first word of each line under "Subcommands:".
help_of(top)
string(REGEX REPLACE ".*\nSubcommands:\n" "" listing "${top}")
string(REPLACE "\n" ";" listing "${listing}")
set(commands "")
foreach(line IN LISTS listing)
  if(line MATCHES "^  ([a-z][a-z0-9_-]*)")
    list(APPEND commands "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(NOT commands)
  message(FATAL_ERROR "no commands found in `prism --help`:\n${top}")
endif()

# roff text, shown as it is: backslashes and minus signs escaped, no line
# taken for a request.
function(as_roff out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

set(include "[COMMANDS]\nEach command takes its own options, listed by \\fBprism \\fICOMMAND\\fB \\-\\-help\\fR:\n")
foreach(command IN LISTS commands)
  help_of(text ${command})
  as_roff(text "${text}")
  string(APPEND include ".SS \"prism ${command}\"\n.nf\n${text}.fi\n")
endforeach()
string(APPEND include "[FILES]\n"
  ".TP\n.I PREFIX/share/prism/scenes\nThe shipped scenes, with the parts and images they include.\n"
  ".TP\n.I PREFIX/share/prism/docs\nThe documentation (Markdown).\n"
  ".TP\n.I LIBDIR/prism\nThe modules prism loads when needed: libprism_oiio.so (picture formats "
  "other than 8\\-bit TIFF and PNG, charts), libprism_mpi.so (rendering under mpirun).\n"
  "[SEE ALSO]\nThe documentation in \\fIPREFIX/share/prism/docs\\fR, starting from "
  "\\fIPREFIX/share/prism/README.md\\fR.\n")
get_filename_component(out_dir "${OUTPUT}" DIRECTORY)
set(include_file "${out_dir}/prism.h2m")
file(WRITE "${include_file}" "${include}")

string(REGEX REPLACE "\\.gz$" "" page "${OUTPUT}")
execute_process(COMMAND "${HELP2MAN}" --no-info --section=1
  "--name=recursive ray tracer with adaptive antialiasing and automatic exposure"
  "--include=${include_file}" "--output=${page}" prism
  RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man failed (${status}): ${errors}")
endif()
execute_process(COMMAND "${GZIP}" -9nf "${page}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gzip ${page} failed (${status})")
endif()
