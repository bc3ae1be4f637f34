# Python wrapping of the module: the `colordecimation` package.
#
#   from colordecimation import vtkColorHalfEdgeDecimation
#
# The package holds the wrapped module (vtkColorDecimation, a Python extension built by
# vtk_module_wrap_python) and an __init__.py that re-exports its classes. It is placed in
# the build tree under ${COLORDECIMATION_PYTHON_DESTINATION} and installed there under the
# prefix. The extension loads VTK's own Python modules (vtkmodules.*) when imported, so it
# is used with the interpreter VTK was wrapped for (python3-vtk9's /usr/bin/python3 on
# Debian, or ParaView's pvpython in the ParaView flavour).
#
# Variables:
#   COLORDECIMATION_WRAP_PYTHON         (option) build the wrapping; ON when VTK has Python.
#   COLORDECIMATION_PYTHON_DESTINATION  (cache) where the package goes, relative to the
#                                       prefix; default from vtk_module_python_default_
#                                       destination (lib/python3.X/site-packages).
#   COLORDECIMATION_PYTHON_EXECUTABLE   (cache) interpreter for the tests: one that can
#                                       import vtkmodules.
include_guard(GLOBAL)

set(_colordecimation_python_default OFF)
if (VTK_WRAP_PYTHON)
  set(_colordecimation_python_default ON)
endif ()
option(COLORDECIMATION_WRAP_PYTHON "Build the Python wrapping (package colordecimation)"
  "${_colordecimation_python_default}")
if (COLORDECIMATION_WRAP_PYTHON AND NOT VTK_WRAP_PYTHON)
  message(WARNING "COLORDECIMATION_WRAP_PYTHON is ON but this VTK has no Python wrapping: "
    "turned off.")
  set(COLORDECIMATION_WRAP_PYTHON OFF)
endif ()

# What the tests read (Testing/Python, Testing/Install): written even when off.
set(_colordecimation_python_test_config
  "${CMAKE_BINARY_DIR}/CMakeFiles/ColorDecimationPythonTestConfig.cmake")

if (NOT COLORDECIMATION_WRAP_PYTHON)
  file(WRITE "${_colordecimation_python_test_config}"
    "set(COLORDECIMATION_WRAP_PYTHON OFF)\n")
  return ()
endif ()

# The wrapping tools and VTK's Python (finds Python3 with the version VTK was wrapped for).
find_package(VTK REQUIRED COMPONENTS Python WrappingPythonCore)

vtk_module_python_default_destination(_colordecimation_python_default_destination)
set(COLORDECIMATION_PYTHON_DESTINATION "${_colordecimation_python_default_destination}"
  CACHE STRING "Where the colordecimation Python package is installed (relative to the prefix)")
mark_as_advanced(COLORDECIMATION_PYTHON_DESTINATION)

# With LIBRARY_DESTINATION, vtk_module_wrap_python gives the extension an install RPATH
# relative to its own folder ($ORIGIN/<package folder to libdir>): the installed package loads
# the installed library from any prefix, with no LD_LIBRARY_PATH (Testing/Install checks it).
vtk_module_wrap_python(
  MODULES             ${colordecimation_modules}
  TARGET              ColorDecimation::ColorDecimationPython
  WRAPPED_MODULES     colordecimation_python_wrapped_modules
  BUILD_STATIC        OFF
  INSTALL_HEADERS     ON
  INSTALL_EXPORT      ColorDecimationPython
  PYTHON_PACKAGE      "colordecimation"
  MODULE_DESTINATION  "${COLORDECIMATION_PYTHON_DESTINATION}"
  CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/colordecimation"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}")

# The package's __init__.py, in the build tree and installed beside the extension.
set(_colordecimation_python_init
  "${CMAKE_BINARY_DIR}/${COLORDECIMATION_PYTHON_DESTINATION}/colordecimation/__init__.py")
file(WRITE "${_colordecimation_python_init}"
"\"\"\"Colour-aware mesh decimation for VTK by half-edge collapses (by default Hoppe's
attribute quadric; SetPaperDefaults() gives Kim, Choi and Lee's method).

    from colordecimation import vtkColorHalfEdgeDecimation

The classes come from the wrapped VTK module ColorDecimation::FiltersColorDecimation
(the extension colordecimation.vtkColorDecimation); importing this package imports the
vtkmodules it depends on.
\"\"\"
from .vtkColorDecimation import *  # noqa: F401,F403

__version__ = \"${PROJECT_VERSION}\"
")
install(
  FILES       "${_colordecimation_python_init}"
  DESTINATION "${COLORDECIMATION_PYTHON_DESTINATION}/colordecimation"
  COMPONENT   python)

# Targets of the Python wrapping (the interface target ColorDecimation::ColorDecimationPython;
# its name also names a generated header, ColorDecimationPython.h: "Python" would shadow
# Python.h in the include folder).
install(
  EXPORT      ColorDecimationPython
  NAMESPACE   ColorDecimation::
  FILE        ColorDecimationPython-targets.cmake
  DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/colordecimation"
  COMPONENT   development)

# An interpreter that can import vtkmodules (for the tests): Python3_EXECUTABLE when it can
# (it is the one VTK's package found), else the python3 installed beside VTK.
if (NOT COLORDECIMATION_PYTHON_EXECUTABLE)
  set(_colordecimation_python_candidates)
  if (Python3_EXECUTABLE)
    list(APPEND _colordecimation_python_candidates "${Python3_EXECUTABLE}")
  endif ()
  if (VTK_PREFIX_PATH)
    foreach (_name IN ITEMS "python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}" python3)
      if (EXISTS "${VTK_PREFIX_PATH}/bin/${_name}")
        list(APPEND _colordecimation_python_candidates "${VTK_PREFIX_PATH}/bin/${_name}")
      endif ()
    endforeach ()
  endif ()
  set(_colordecimation_python_found "")
  foreach (_candidate IN LISTS _colordecimation_python_candidates)
    execute_process(
      COMMAND "${_candidate}" -c "import vtkmodules.vtkCommonExecutionModel"
      RESULT_VARIABLE _colordecimation_python_result
      OUTPUT_QUIET ERROR_QUIET)
    if (_colordecimation_python_result EQUAL 0)
      set(_colordecimation_python_found "${_candidate}")
      break ()
    endif ()
  endforeach ()
  if (NOT _colordecimation_python_found)
    message(WARNING "No Python interpreter that imports vtkmodules was found (tried: "
      "${_colordecimation_python_candidates}); set COLORDECIMATION_PYTHON_EXECUTABLE to "
      "run the Python tests.")
  endif ()
  set(COLORDECIMATION_PYTHON_EXECUTABLE "${_colordecimation_python_found}"
    CACHE FILEPATH "Python interpreter (able to import vtkmodules) for the Python tests" FORCE)
endif ()
message(STATUS "ColorDecimation: Python package 'colordecimation' in "
  "${COLORDECIMATION_PYTHON_DESTINATION} (tests use ${COLORDECIMATION_PYTHON_EXECUTABLE})")

file(WRITE "${_colordecimation_python_test_config}"
"set(COLORDECIMATION_WRAP_PYTHON ON)
set(COLORDECIMATION_PYTHON_EXECUTABLE \"${COLORDECIMATION_PYTHON_EXECUTABLE}\")
set(COLORDECIMATION_PYTHON_DESTINATION \"${COLORDECIMATION_PYTHON_DESTINATION}\")
set(COLORDECIMATION_PYTHON_BUILD_DIR \"${CMAKE_BINARY_DIR}/${COLORDECIMATION_PYTHON_DESTINATION}\")
")
