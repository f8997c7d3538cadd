# Writes the sagrid(1) man page, gzipped, from the binary's own --help: help2man turns the
# top-level help into NAME/SYNOPSIS/DESCRIPTION/OPTIONS, and a COMMANDS section holds each
# subcommand's --help verbatim. Run at install time (cmake -P), so the page always matches the
# binary being installed and a build pays nothing for it.
#   cmake -DSAGRID=<binary> -DOUTPUT=<dir>/sagrid.1.gz -P SagridManPage.cmake
if(NOT SAGRID OR NOT OUTPUT)
  message(FATAL_ERROR "usage: cmake -DSAGRID=<binary> -DOUTPUT=<file.1.gz> -P SagridManPage.cmake")
endif()
find_program(HELP2MAN help2man)
if(NOT HELP2MAN)
  message(FATAL_ERROR "help2man is needed for the man page: apt-get install help2man "
                      "(packaging/install_deps.sh installs it)")
endif()

execute_process(COMMAND ${SAGRID} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SAGRID} --help failed (${rc})")
endif()

# CLI11 lists subcommands after "Subcommands:", one per line: two spaces, the name, its summary.
string(REGEX REPLACE ".*\n(SUBCOMMANDS|Subcommands):\n" "" listing "${help}")
string(REPLACE "\n" ";" listing_lines "${listing}")
set(commands "")
foreach(line IN LISTS listing_lines)
  if(line MATCHES "^  ([a-z0-9][a-z0-9-]*)( |$)")
    list(APPEND commands ${CMAKE_MATCH_1})
  endif()
endforeach()

get_filename_component(out_dir "${OUTPUT}" DIRECTORY)
get_filename_component(out_name "${OUTPUT}" NAME_WE)
file(MAKE_DIRECTORY "${out_dir}")
set(include_file "${out_dir}/${out_name}.h2m")
set(page "${out_dir}/${out_name}.1")

set(text "[COMMANDS]\nEach command has its own options; `sagrid COMMAND --help` prints them.\n")
foreach(command IN LISTS commands)
  execute_process(COMMAND ${SAGRID} ${command} --help OUTPUT_VARIABLE sub RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${SAGRID} ${command} --help failed (${rc})")
  endif()
  string(REPLACE "${SAGRID}" "sagrid" sub "${sub}")  # CLI11's usage line shows argv[0]
  # roff: a backslash is \e; a line starting with . or ' would be a request.
  string(REPLACE "\\" "\\e" sub "${sub}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" sub "${sub}")
  string(APPEND text ".SS \"sagrid ${command}\"\n.nf\n${sub}.fi\n")
endforeach()
string(APPEND text "[FILES]\n.TP\n.I /usr/share/sagrid/models\n"
  "Default models (weights and model cards); a resources/models folder in the working "
  "directory is used first, --models overrides both.\n"
  ".TP\n.I /usr/share/sagrid/samples\nSample meshes to try the commands on.\n"
  "[SEE ALSO]\nThe README of the SAGrid repository.\n")
file(WRITE "${include_file}" "${text}")

execute_process(
  COMMAND ${HELP2MAN} --no-info --no-discard-stderr --section=1 --include=${include_file}
          "--name=simulation affordance points on 3D meshes" --output=${page} ${SAGRID}
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man failed: ${err}")
endif()
execute_process(COMMAND gzip -9nf ${page} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT EXISTS "${page}.gz")
  message(FATAL_ERROR "gzip ${page} failed")
endif()
if(NOT "${page}.gz" STREQUAL "${OUTPUT}")
  file(RENAME "${page}.gz" "${OUTPUT}")
endif()
file(REMOVE "${include_file}")
