# Installs the build tree into a fresh prefix, runs the installed programs from there (the
# CLI decimates a small demo mesh), then configures, builds and runs the consumer project
# against the prefix (and the Python package from the prefix, when wrapped). Nothing runs
# with LD_LIBRARY_PATH: the installed programs and the Python extension find the installed
# library through their RPATH, relative to the prefix.
#   cmake -DBUILD_DIR=<build> -DWORK_DIR=<scratch> -DCONSUMER_DIR=<consumer source>
#         -DPYTHON_SCRIPT=<TestColorDecimationPython.py> -P TestInstall.cmake
cmake_minimum_required(VERSION 3.16)
foreach (var IN ITEMS BUILD_DIR WORK_DIR CONSUMER_DIR PYTHON_SCRIPT)
  if (NOT ${var})
    message(FATAL_ERROR "${var} is not set.")
  endif ()
endforeach ()
set(config "${BUILD_DIR}/CMakeFiles/ColorDecimationInstallTestConfig.cmake")
if (NOT EXISTS "${config}")
  message(FATAL_ERROR "Missing ${config}: cmake/ColorDecimationInstall.cmake did not run.")
endif ()
include("${config}")

function (run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "${step} failed (${result}): ${ARGN}")
  endif ()
endfunction ()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer-build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

run("Install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
set(installed_config "${prefix}/${COLORDECIMATION_CMAKE_DESTINATION}/ColorDecimationConfig.cmake")
if (NOT EXISTS "${installed_config}")
  message(FATAL_ERROR "The install has no ${installed_config}")
endif ()

# The installed programs, from the prefix alone.
unset(ENV{LD_LIBRARY_PATH})
foreach (program IN ITEMS color-decimate color-decimate-bench color-decimate-eval
    color-decimate-metro color-decimate-run)
  if (NOT EXISTS "${prefix}/bin/${program}")
    message(FATAL_ERROR "The install has no ${prefix}/bin/${program}")
  endif ()
  execute_process(COMMAND "${prefix}/bin/${program}" --help
    RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE errors)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "The installed ${program} does not run (${result}): ${errors}")
  endif ()
endforeach ()
set(decimated "${WORK_DIR}/installed-cli-demo.ply")
run("The installed CLI on a demo mesh"
  "${prefix}/bin/color-decimate" demo:ico4:sharp "${decimated}" --reduction 0.75 --quiet)
if (EXISTS "${decimated}")
  file(SIZE "${decimated}" decimated_bytes)
endif ()
if (NOT decimated_bytes GREATER 0)
  message(FATAL_ERROR "The installed CLI wrote no ${decimated}, or an empty one")
endif ()
message(STATUS "The installed CLI wrote ${decimated} (${decimated_bytes} bytes)")

# Only the prefix (and the VTK/ParaView the build used) may be searched: no build tree,
# no package registry.
set(configure_args
  -S "${CONSUMER_DIR}" -B "${consumer_build}" -G "${CMAKE_GENERATOR}"
  "-DCMAKE_PREFIX_PATH=${prefix}"
  "-DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}"
  "-DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}"
  "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  "-DVTK_DIR=${VTK_DIR}")
if (COLORDECIMATION_WITH_PARAVIEW)
  list(APPEND configure_args "-DParaView_DIR=${ParaView_DIR}")
endif ()
run("Configuring the consumer" "${CMAKE_COMMAND}" ${configure_args})
file(STRINGS "${consumer_build}/CMakeCache.txt" found_dir REGEX "^ColorDecimation_DIR:")
string(REGEX REPLACE "^[^=]*=" "" found_dir "${found_dir}")
get_filename_component(found_dir "${found_dir}" REALPATH)
get_filename_component(real_prefix "${prefix}" REALPATH)
string(FIND "${found_dir}" "${real_prefix}/" at)
if (NOT at EQUAL 0)
  message(FATAL_ERROR "The consumer found ColorDecimation in ${found_dir}, not in ${prefix}")
endif ()
file(STRINGS "${consumer_build}/ColorDecimationPackage.txt" package)
message(STATUS "The package says: ${package}")
if (NOT "modules=ColorDecimation::FiltersColorDecimation" IN_LIST package)
  message(FATAL_ERROR "ColorDecimation_MODULES is wrong: ${package}")
endif ()
run("Building the consumer" "${CMAKE_COMMAND}" --build "${consumer_build}")
run("Running the consumer" "${consumer_build}/consumer")

# The Python package from the prefix (it must load the installed library, not the build's).
set(python_config "${BUILD_DIR}/CMakeFiles/ColorDecimationPythonTestConfig.cmake")
if (EXISTS "${python_config}")
  include("${python_config}")
endif ()
if (COLORDECIMATION_WRAP_PYTHON)
  if (NOT COLORDECIMATION_PYTHON_EXECUTABLE)
    message(FATAL_ERROR "No interpreter able to import vtkmodules for the installed package.")
  endif ()
  if (NOT "pythonpath=${prefix}/${COLORDECIMATION_PYTHON_DESTINATION}" IN_LIST package)
    message(FATAL_ERROR "ColorDecimation_PYTHONPATH is not the installed package's folder: ${package}")
  endif ()
  set(ENV{PYTHONPATH} "${prefix}/${COLORDECIMATION_PYTHON_DESTINATION}")
  set(ENV{COLORDECIMATION_EXPECT_PREFIX} "${prefix}")
  run("The installed Python package" "${COLORDECIMATION_PYTHON_EXECUTABLE}" "${PYTHON_SCRIPT}")
else ()
  message(STATUS "Python wrapping off: installed package not tried from Python.")
endif ()
message(STATUS "Install test passed.")
