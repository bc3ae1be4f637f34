# Which VTK to build against.
#
# Two flavours are supported on Debian 12: plain VTK 9.1 (libvtk9-dev) and ParaView 5.11's
# VTK 9.2 (paraview-dev). They cannot be installed together. ParaView is used when it is
# found (or when COLORDECIMATION_FLAVOUR is set to ParaView); the ParaView plugin is only
# built in that flavour.
set(COLORDECIMATION_FLAVOUR "Auto" CACHE STRING "VTK flavour: Auto, VTK or ParaView")
set_property(CACHE COLORDECIMATION_FLAVOUR PROPERTY STRINGS Auto VTK ParaView)

set(colordecimation_vtk_components
  CommonCore
  CommonDataModel
  CommonExecutionModel
  CommonSystem
  FiltersCore
  FiltersGeneral
  FiltersGeometry
  FiltersSources
  IOGeometry
  IOImage
  IOLegacy
  IOPLY
  IOXML
  ImagingCore
  InteractionStyle
  RenderingCore
  RenderingFreeType
  RenderingOpenGL2)

set(COLORDECIMATION_WITH_PARAVIEW OFF)
if (NOT COLORDECIMATION_FLAVOUR STREQUAL "VTK")
  if (COLORDECIMATION_FLAVOUR STREQUAL "ParaView")
    find_package(ParaView REQUIRED)
  else ()
    find_package(ParaView QUIET)
  endif ()
  if (ParaView_FOUND)
    set(COLORDECIMATION_WITH_PARAVIEW ON)
  endif ()
endif ()

find_package(VTK REQUIRED COMPONENTS ${colordecimation_vtk_components}
  OPTIONAL_COMPONENTS TestingRendering)
message(STATUS "ColorDecimation: VTK ${VTK_VERSION}"
  " (ParaView flavour: ${COLORDECIMATION_WITH_PARAVIEW})")
