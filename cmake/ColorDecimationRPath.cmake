# Installed programs that run from any prefix.
#
#   colordecimation_install_program(<target>...)
#
# installs each executable into ${CMAKE_INSTALL_BINDIR} with an RPATH relative to itself,
# $ORIGIN/<bindir to libdir> ($ORIGIN/../lib with the usual GNUInstallDirs), so that it finds
# the installed libvtkColorDecimation wherever the prefix is, with no LD_LIBRARY_PATH. The
# folders of libraries linked from outside the system's own (a VTK built in a prefix of its
# own) are kept in the installed RPATH too.
#
# The Python package needs nothing here: vtk_module_wrap_python(LIBRARY_DESTINATION ...)
# (cmake/ColorDecimationPython.cmake) gives the extension an RPATH relative to its own
# folder ($ORIGIN/../../.. from lib/python3/dist-packages/colordecimation).
include_guard(GLOBAL)

function (colordecimation_install_program)
  file(RELATIVE_PATH _colordecimation_bin_to_lib
    "/prefix/${CMAKE_INSTALL_BINDIR}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
  if (APPLE)
    set(_colordecimation_origin "@loader_path")
  else ()
    set(_colordecimation_origin "$ORIGIN")
  endif ()
  foreach (_colordecimation_target IN LISTS ARGN)
    set_property(TARGET "${_colordecimation_target}" APPEND PROPERTY
      INSTALL_RPATH "${_colordecimation_origin}/${_colordecimation_bin_to_lib}")
    set_property(TARGET "${_colordecimation_target}" PROPERTY INSTALL_RPATH_USE_LINK_PATH ON)
    install(TARGETS "${_colordecimation_target}" RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
  endforeach ()
endfunction ()
