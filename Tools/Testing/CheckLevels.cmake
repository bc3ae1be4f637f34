# Checks the "levels" list of color-decimate --lod --stats (a ctest helper).
#
#   cmake -DSTATS=file.json -DREDUCTIONS=r1;r2;... -DOUTPUTS=f1;f2;... [-DFROM_RECORD=ON]
#         [-DMESH_CHECK=ColorDecimationMeshCheck] -P CheckLevels.cmake
#
# One level per reduction, in the order given, each naming its file (which must exist) and
# reporting points, triangles, collapses and its times (with MESH_CHECK, the points and
# triangles of its file). With --lod the top-level "output" is
# null (no OUTPUT file is written); with --from-record (FROM_RECORD) so are the decimation's
# figures, since none ran, and the method's keys, which the record does not hold.
if (NOT EXISTS "${STATS}")
  message(FATAL_ERROR "${STATS} was not written")
endif ()
file(READ "${STATS}" json)
message(STATUS "${STATS}:\n${json}")
string(JSON count ERROR_VARIABLE problem LENGTH "${json}" levels)
list(LENGTH REDUCTIONS expected)
if (problem OR NOT count EQUAL expected)
  message(FATAL_ERROR "expected ${expected} levels, got '${count}' ${problem}")
endif ()
math(EXPR last "${count} - 1")
foreach (i RANGE ${last})
  list(GET REDUCTIONS ${i} reduction)
  list(GET OUTPUTS ${i} output)
  string(JSON asked GET "${json}" levels ${i} target_reduction)
  string(JSON path GET "${json}" levels ${i} output)
  if (NOT asked EQUAL reduction AND NOT asked STREQUAL reduction)
    message(FATAL_ERROR "level ${i}: target_reduction ${asked}, expected ${reduction}")
  endif ()
  if (NOT path STREQUAL output OR NOT EXISTS "${output}")
    message(FATAL_ERROR "level ${i}: output '${path}', expected '${output}' (written)")
  endif ()
  foreach (key IN ITEMS output_points output_triangles collapses extract_seconds write_seconds
      reduction actual_error)
    string(JSON value ERROR_VARIABLE problem GET "${json}" levels ${i} ${key})
    if (problem)
      message(FATAL_ERROR "level ${i}: key '${key}' missing")
    endif ()
    set(${key} "${value}")
  endforeach ()
  if (MESH_CHECK)
    execute_process(COMMAND "${MESH_CHECK}" "${output}" RESULT_VARIABLE status
      OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if (NOT status STREQUAL "0" OR NOT out MATCHES "points=([0-9]+) triangles=([0-9]+)")
      message(FATAL_ERROR "level ${i}: cannot read ${output}: ${out}${err}")
    endif ()
    if (NOT output_points EQUAL CMAKE_MATCH_1 OR NOT output_triangles EQUAL CMAKE_MATCH_2)
      message(FATAL_ERROR "level ${i}: ${output_points} points and ${output_triangles} "
        "triangles reported, ${CMAKE_MATCH_1} and ${CMAKE_MATCH_2} in ${output}")
    endif ()
  endif ()
endforeach ()

set(nulls)
if (FROM_RECORD)
  list(APPEND nulls reduction collapses output_triangles filter_seconds phases metric schedule
    scene_weight_scale paper settings)
else ()
  list(APPEND nulls output)
endif ()
foreach (key IN LISTS nulls)
  string(JSON type ERROR_VARIABLE problem TYPE "${json}" ${key})
  if (problem OR NOT type STREQUAL "NULL")
    message(FATAL_ERROR "top-level '${key}' is ${type} ${problem}, expected null")
  endif ()
endforeach ()
