# One run of color-decimate-run with a method of meshoptimizer's WebAssembly build, checked
# (a ctest helper). Prints "SKIPPED: ..." (the test's SKIP_REGULAR_EXPRESSION) and stops when
# the tool exits with status 4: node or the npm package is missing.
#
#   cmake -DRUN=color-decimate-run -DMESH_CHECK=ColorDecimationMeshCheck -DMETHOD=meshopt-attr
#         -DINPUT=demo:ico5:sharp -DOUTPUT=out.vtp -DREDUCTION=0.75 -DTARGET=5120
#         [-DSAME_POINTS=ON] -P CheckMeshOptimizerJS.cmake
#
# Checks: the JSON names the package's function and says the time was measured inside node;
# OUTPUT has TARGET triangles within 3 %, and colours; with SAME_POINTS, every output point is
# an input point with its colour, bit for bit.
foreach (_name IN ITEMS RUN MESH_CHECK METHOD INPUT OUTPUT REDUCTION TARGET)
  if (NOT DEFINED ${_name})
    message(FATAL_ERROR "CheckMeshOptimizerJS.cmake: ${_name} not given")
  endif ()
endforeach ()

execute_process(COMMAND "${RUN}" "${INPUT}" "${OUTPUT}" --method "${METHOD}"
    --reduction "${REDUCTION}"
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
message(STATUS "exit status: ${status}\n--- output ---\n${out}${err}--------------")
if (status STREQUAL "4")
  message(STATUS "SKIPPED: ${err}")
  return ()
endif ()
if (NOT status STREQUAL "0")
  message(FATAL_ERROR "color-decimate-run failed (exit status '${status}')")
endif ()
if (NOT out MATCHES "\"function\": \"simplifyWith[A-Za-z +]+\".*\"seconds_measured\": \"inside node")
  message(FATAL_ERROR "the JSON does not name the function or where the time was measured")
endif ()

math(EXPR low "${TARGET} * 97 / 100")
math(EXPR high "${TARGET} * 103 / 100")
set(check "${MESH_CHECK}" "${OUTPUT}" --triangles-between ${low} ${high} --colors)
if (SAME_POINTS)
  list(APPEND check --colors-from "${INPUT}")
endif ()
execute_process(COMMAND ${check} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if (NOT status STREQUAL "0")
  message(FATAL_ERROR "the output fails the mesh check")
endif ()
