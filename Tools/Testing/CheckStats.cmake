# Checks the JSON written by color-decimate --stats (a ctest helper).
#
#   cmake -DSTATS=file.json -DINPUT_POINTS=N -DINPUT_TRIANGLES=N -DREDUCTION=R -DMETRIC=name
#         [-DSCHEDULE=greedy|batched] [-DTHREADS=N | -DMIN_THREADS=N]
#         [-DSETTINGS=key=value;key=value...]
#         [-DCHECK_FILE=mesh -DMESH_CHECK=ColorDecimationMeshCheck]
#         -P CheckStats.cmake
#
# Every required key must be there with a plausible value, and a phase breakdown; "threads" must be THREADS, or at
# least MIN_THREADS (at least 1 without either); with CHECK_FILE, the output counts in the
# JSON must be those of the mesh file (read by MESH_CHECK). METRIC and SCHEDULE are checked
# when given; each SETTINGS key must have that value in the JSON's "settings".
if (NOT EXISTS "${STATS}")
  message(FATAL_ERROR "${STATS} was not written")
endif ()
file(READ "${STATS}" json)
message(STATUS "${STATS}:\n${json}")

foreach (key IN ITEMS filter_seconds input_triangles output_triangles input_points output_points
    peak_rss_bytes reduction metric schedule threads state_memory_bytes)
  string(JSON value ERROR_VARIABLE problem GET "${json}" ${key})
  if (problem)
    message(FATAL_ERROR "key '${key}' missing: ${problem}")
  endif ()
  set(${key} "${value}")
endforeach ()

# The filter's phase breakdown: a non-empty list of {name, seconds}.
string(JSON phases ERROR_VARIABLE problem LENGTH "${json}" phases)
if (problem OR phases LESS 1)
  message(FATAL_ERROR "no phase breakdown ('phases'): ${problem}")
endif ()
math(EXPR last "${phases} - 1")
foreach (i RANGE ${last})
  foreach (key IN ITEMS name seconds)
    string(JSON value ERROR_VARIABLE problem GET "${json}" phases ${i} ${key})
    if (problem)
      message(FATAL_ERROR "phase ${i} has no '${key}': ${problem}")
    endif ()
  endforeach ()
endforeach ()

function (expect condition_text)
  if (NOT (${ARGN}))
    message(FATAL_ERROR "implausible statistics: ${condition_text}")
  endif ()
endfunction ()

# CMake's math() is integer-only: decimals are compared in millionths.
function (to_millionths text out)
  if (NOT text MATCHES "^([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "'${text}' is not a plain decimal number")
  endif ()
  set(whole "${CMAKE_MATCH_1}")
  set(fraction "${CMAKE_MATCH_3}000000")
  string(SUBSTRING "${fraction}" 0 6 fraction)
  string(REGEX REPLACE "^0+([0-9])" "\\1" fraction "${fraction}")
  math(EXPR value "${whole} * 1000000 + ${fraction}")
  set(${out} ${value} PARENT_SCOPE)
endfunction ()
expect("input_points = ${INPUT_POINTS}" input_points EQUAL INPUT_POINTS)
expect("input_triangles = ${INPUT_TRIANGLES}" input_triangles EQUAL INPUT_TRIANGLES)
if (DEFINED METRIC)
  expect("metric = ${METRIC}" metric STREQUAL METRIC)
endif ()
if (DEFINED SCHEDULE)
  expect("schedule = ${SCHEDULE}" schedule STREQUAL SCHEDULE)
endif ()
foreach (setting IN LISTS SETTINGS)
  string(REGEX MATCH "^([^=]+)=(.*)$" matched "${setting}")
  string(JSON value ERROR_VARIABLE problem GET "${json}" settings ${CMAKE_MATCH_1})
  if (problem)
    message(FATAL_ERROR "setting '${CMAKE_MATCH_1}' missing: ${problem}")
  endif ()
  set(wanted "${CMAKE_MATCH_2}")
  if (wanted MATCHES "^-?[0-9.]+$")
    expect("settings.${CMAKE_MATCH_1} = ${wanted} (got ${value})" value EQUAL wanted)
  else ()
    expect("settings.${CMAKE_MATCH_1} = ${wanted} (got ${value})" value STREQUAL wanted)
  endif ()
endforeach ()
to_millionths("${REDUCTION}" target)
math(EXPR kept "${INPUT_TRIANGLES} - (${INPUT_TRIANGLES} * ${target}) / 1000000")
math(EXPR kept_high "${kept} + 4")
math(EXPR kept_low "${kept} - 4")
expect("output_triangles (${output_triangles}) near ${kept}"
  output_triangles GREATER_EQUAL kept_low AND output_triangles LESS_EQUAL kept_high)
expect("0 < output_points (${output_points}) < input_points"
  output_points GREATER 0 AND output_points LESS input_points)
to_millionths("${reduction}" actual)
math(EXPR from_counts "1000000 - (${output_triangles} * 1000000) / ${input_triangles}")
math(EXPR off_target "${actual} - ${target}")
math(EXPR off_counts "${actual} - ${from_counts}")
expect("reduction (${reduction}) within 0.01 of the target ${REDUCTION}"
  off_target GREATER -10000 AND off_target LESS 10000)
expect("reduction (${reduction}) = 1 - output_triangles / input_triangles"
  off_counts GREATER_EQUAL -2 AND off_counts LESS_EQUAL 2)
expect("filter_seconds (${filter_seconds}) in (0, 120)"
  filter_seconds GREATER 0 AND filter_seconds LESS 120)
expect("peak_rss_bytes (${peak_rss_bytes}) > 1 MB" peak_rss_bytes GREATER 1000000)
if (DEFINED THREADS)
  expect("threads (${threads}) = ${THREADS}" threads EQUAL THREADS)
else ()
  if (NOT DEFINED MIN_THREADS)
    set(MIN_THREADS 1)
  endif ()
  expect("threads (${threads}) >= ${MIN_THREADS}" threads GREATER_EQUAL MIN_THREADS)
endif ()
expect("state_memory_bytes (${state_memory_bytes}) > 0 and < peak_rss_bytes"
  state_memory_bytes GREATER 0 AND state_memory_bytes LESS peak_rss_bytes)

if (DEFINED CHECK_FILE)
  execute_process(COMMAND "${MESH_CHECK}" "${CHECK_FILE}"
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT status STREQUAL "0")
    message(FATAL_ERROR "cannot read ${CHECK_FILE}: ${out}${err}")
  endif ()
  if (NOT out MATCHES "points=([0-9]+) triangles=([0-9]+)")
    message(FATAL_ERROR "unexpected MeshCheck output: ${out}")
  endif ()
  expect("output_points = ${CMAKE_MATCH_1} (in the file)" output_points EQUAL CMAKE_MATCH_1)
  expect("output_triangles = ${CMAKE_MATCH_2} (in the file)" output_triangles EQUAL CMAKE_MATCH_2)
endif ()
