# Runs a command and checks its exit status and its output (a ctest helper).
#
#   cmake [-DEXPECT=success|failure] [-DEXIT_CODE=N] [-DREGEX=re] [-DFORBID=re]
#         [-DMAKE_FILE=path -DMAKE_FILE_KIND=junk|points-only]
#         [-DCHECK_FILE=path -DCHECK_FILE_REGEX=re]
#         -P RunCheck.cmake -- COMMAND [ARG ...]
#
# EXPECT: success (exit 0, the default) or failure (exit status not 0; EXIT_CODE pins it).
# REGEX must match and FORBID must not match the command's stdout + stderr.
# MAKE_FILE is written before the command runs: "junk" is text that is no mesh format,
# "points-only" a legacy VTK polydata with three vertices and no triangle.
# CHECK_FILE must exist after the command and match CHECK_FILE_REGEX.
set(command)
set(after_separator FALSE)
foreach (i RANGE 1 ${CMAKE_ARGC})
  if (i EQUAL CMAKE_ARGC)
    break ()
  endif ()
  if (after_separator)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif (CMAKE_ARGV${i} STREQUAL "--")
    set(after_separator TRUE)
  endif ()
endforeach ()
if (NOT command)
  message(FATAL_ERROR "RunCheck.cmake: no command given after --")
endif ()
if (NOT DEFINED EXPECT)
  set(EXPECT success)
endif ()

if (DEFINED MAKE_FILE)
  if (MAKE_FILE_KIND STREQUAL "junk")
    file(WRITE "${MAKE_FILE}" "this is plain text, not a mesh\n1 2 3\n")
  elseif (MAKE_FILE_KIND STREQUAL "points-only")
    file(WRITE "${MAKE_FILE}"
      "# vtk DataFile Version 3.0\npoints and no triangle\nASCII\nDATASET POLYDATA\n"
      "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nVERTICES 1 4\n3 0 1 2\n")
  else ()
    message(FATAL_ERROR "RunCheck.cmake: unknown MAKE_FILE_KIND '${MAKE_FILE_KIND}'")
  endif ()
endif ()

execute_process(COMMAND ${command}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
set(all "${out}${err}")
message(STATUS "command: ${command}\nexit status: ${status}\n--- output ---\n${all}--------------")

if (EXPECT STREQUAL "success")
  if (NOT status STREQUAL "0")
    message(FATAL_ERROR "expected success, got exit status '${status}'")
  endif ()
elseif (EXPECT STREQUAL "failure")
  if (status STREQUAL "0")
    message(FATAL_ERROR "expected a failure, but the command succeeded")
  endif ()
  if (NOT status MATCHES "^[0-9]+$")
    message(FATAL_ERROR "expected a clean non-zero exit, got '${status}' (a crash?)")
  endif ()
  if (DEFINED EXIT_CODE AND NOT status EQUAL EXIT_CODE)
    message(FATAL_ERROR "expected exit status ${EXIT_CODE}, got ${status}")
  endif ()
else ()
  message(FATAL_ERROR "RunCheck.cmake: EXPECT must be success or failure")
endif ()
if (DEFINED REGEX AND NOT all MATCHES "${REGEX}")
  message(FATAL_ERROR "the output does not match '${REGEX}'")
endif ()
if (DEFINED FORBID AND all MATCHES "${FORBID}")
  message(FATAL_ERROR "the output matches '${FORBID}', which it must not")
endif ()
if (DEFINED CHECK_FILE)
  if (NOT EXISTS "${CHECK_FILE}")
    message(FATAL_ERROR "${CHECK_FILE} was not written")
  endif ()
  file(READ "${CHECK_FILE}" content)
  if (DEFINED CHECK_FILE_REGEX AND NOT content MATCHES "${CHECK_FILE_REGEX}")
    message(FATAL_ERROR "${CHECK_FILE} does not match '${CHECK_FILE_REGEX}'")
  endif ()
endif ()
