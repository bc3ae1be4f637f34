# The installed CMake package: find_package(ColorDecimation) in another project.
#
# vtk_module_build(INSTALL_EXPORT ColorDecimation CMAKE_DESTINATION lib/cmake/colordecimation)
# already installs the module's targets (ColorDecimation-targets.cmake) and properties
# (ColorDecimation-vtk-module-properties.cmake) there. This file adds, in the same folder:
#   - ColorDecimation-vtk-module-find-packages.cmake (vtk_module_export_find_packages),
#   - ColorDecimationConfig.cmake (finds VTK, includes the files above),
#   - ColorDecimationConfigVersion.cmake (SameMajorVersion).
# The same files are written into the build tree's lib/cmake/colordecimation, so a project
# can also use a build tree (ColorDecimation_DIR=<build>/lib/cmake/colordecimation).
include_guard(GLOBAL)
include(CMakePackageConfigHelpers)

set(COLORDECIMATION_CMAKE_DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/colordecimation")
file(RELATIVE_PATH COLORDECIMATION_CMAKE_RELATIVE_PREFIX
  "/prefix/${COLORDECIMATION_CMAKE_DESTINATION}" "/prefix")

vtk_module_export_find_packages(
  CMAKE_DESTINATION "${COLORDECIMATION_CMAKE_DESTINATION}"
  FILE_NAME         "ColorDecimation-vtk-module-find-packages.cmake"
  MODULES           ${colordecimation_modules})

# Components (module names without namespace) and the VTK components they need.
set(colordecimation_components)
set(colordecimation_vtk_dependencies)
foreach (_module IN LISTS colordecimation_modules)
  string(REGEX REPLACE "^[^:]*::" "" _component "${_module}")
  list(APPEND colordecimation_components "${_component}")
  foreach (_kind IN ITEMS depends private_depends)
    vtk_module_get_property("${_module}" PROPERTY "INTERFACE_vtk_module_${_kind}"
      VARIABLE _depends)
    foreach (_depend IN LISTS _depends)
      if (_depend MATCHES "^VTK::(.*)$")
        list(APPEND colordecimation_vtk_dependencies "${CMAKE_MATCH_1}")
      endif ()
    endforeach ()
  endforeach ()
endforeach ()
list(REMOVE_DUPLICATES colordecimation_vtk_dependencies)
if (NOT DEFINED COLORDECIMATION_PYTHON_DESTINATION OR NOT COLORDECIMATION_WRAP_PYTHON)
  set(COLORDECIMATION_PYTHON_DESTINATION "")
endif ()

set(_colordecimation_config_dir "${CMAKE_BINARY_DIR}/${COLORDECIMATION_CMAKE_DESTINATION}")
configure_file(
  "${CMAKE_CURRENT_LIST_DIR}/ColorDecimationConfig.cmake.in"
  "${_colordecimation_config_dir}/ColorDecimationConfig.cmake"
  @ONLY)
write_basic_package_version_file(
  "${_colordecimation_config_dir}/ColorDecimationConfigVersion.cmake"
  VERSION       "${PROJECT_VERSION}"
  COMPATIBILITY SameMajorVersion)
install(
  FILES
    "${_colordecimation_config_dir}/ColorDecimationConfig.cmake"
    "${_colordecimation_config_dir}/ColorDecimationConfigVersion.cmake"
  DESTINATION "${COLORDECIMATION_CMAKE_DESTINATION}"
  COMPONENT   development)

# What Testing/Install reads (it is configured before this file runs).
file(WRITE "${CMAKE_BINARY_DIR}/CMakeFiles/ColorDecimationInstallTestConfig.cmake"
"set(COLORDECIMATION_CMAKE_DESTINATION \"${COLORDECIMATION_CMAKE_DESTINATION}\")
set(COLORDECIMATION_WITH_PARAVIEW \"${COLORDECIMATION_WITH_PARAVIEW}\")
set(VTK_DIR \"${VTK_DIR}\")
set(ParaView_DIR \"${ParaView_DIR}\")
set(CMAKE_GENERATOR \"${CMAKE_GENERATOR}\")
set(CMAKE_CXX_COMPILER \"${CMAKE_CXX_COMPILER}\")
set(CMAKE_C_COMPILER \"${CMAKE_C_COMPILER}\")
set(CMAKE_BUILD_TYPE \"${CMAKE_BUILD_TYPE}\")
")
