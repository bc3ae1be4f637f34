# Runs a Python test script against the colordecimation package in the build tree.
#   cmake -DCONFIG=<ColorDecimationPythonTestConfig.cmake> -DSCRIPT=<script.py> -P RunPythonTest.cmake
# CONFIG is written by cmake/ColorDecimationPython.cmake (interpreter and package folder).
if (NOT EXISTS "${CONFIG}")
  message(FATAL_ERROR "Missing ${CONFIG}: configure the project first.")
endif ()
include("${CONFIG}")
if (NOT COLORDECIMATION_WRAP_PYTHON)
  message(FATAL_ERROR "The Python wrapping is off (COLORDECIMATION_WRAP_PYTHON).")
endif ()
if (NOT COLORDECIMATION_PYTHON_EXECUTABLE)
  message(FATAL_ERROR "No interpreter able to import vtkmodules: set "
    "COLORDECIMATION_PYTHON_EXECUTABLE.")
endif ()
set(path "${COLORDECIMATION_PYTHON_BUILD_DIR}")
if (DEFINED ENV{PYTHONPATH} AND NOT "$ENV{PYTHONPATH}" STREQUAL "")
  string(APPEND path ":$ENV{PYTHONPATH}")
endif ()
set(ENV{PYTHONPATH} "${path}")
execute_process(
  COMMAND "${COLORDECIMATION_PYTHON_EXECUTABLE}" "${SCRIPT}"
  RESULT_VARIABLE result)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "${SCRIPT} failed (${result}) with PYTHONPATH=${path}")
endif ()
