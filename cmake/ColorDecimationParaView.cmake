# The ParaView plugin (ParaView flavour only): Plugin/paraview.plugin.
#
# Built into <build>/lib/paraview-<version>/plugins/ColorDecimation/ColorDecimation.so with a
# plugin list beside it (<build>/lib/paraview-<version>/plugins/colordecimation.plugins.xml);
# installed under the same relative paths. ParaView finds the plugin when its folder is in
# PV_PLUGIN_PATH, or with LoadPlugin / Tools > Manage Plugins (docs/PARAVIEW.md).
include_guard(GLOBAL)
if (NOT COLORDECIMATION_WITH_PARAVIEW)
  return ()
endif ()

set(COLORDECIMATION_PLUGIN_SUBDIRECTORY "paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/plugins")

paraview_plugin_scan(
  PLUGIN_FILES      "${CMAKE_CURRENT_SOURCE_DIR}/Plugin/paraview.plugin"
  ENABLE_BY_DEFAULT ON
  PROVIDES_PLUGINS  colordecimation_plugins
  REQUIRES_MODULES  colordecimation_plugin_required_modules)

foreach (_module IN LISTS colordecimation_plugin_required_modules)
  if (NOT TARGET "${_module}")
    message(FATAL_ERROR "The ColorDecimation plugin needs ${_module}, which was not built.")
  endif ()
endforeach ()

paraview_plugin_build(
  RUNTIME_DESTINATION   "${CMAKE_INSTALL_BINDIR}"
  LIBRARY_DESTINATION   "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY_SUBDIRECTORY  "${COLORDECIMATION_PLUGIN_SUBDIRECTORY}"
  PLUGINS_FILE_NAME     "colordecimation.plugins.xml"
  PLUGINS               ${colordecimation_plugins})

# Where the tests (Testing/ParaView, configured before this file runs) find the plugin.
set(COLORDECIMATION_PLUGIN_DIR
  "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/${COLORDECIMATION_PLUGIN_SUBDIRECTORY}/ColorDecimation")
message(STATUS "ColorDecimation: ParaView plugin in ${COLORDECIMATION_PLUGIN_DIR}")
