/**
 * @file Orientation.h
 * @brief Consistent winding of each connected piece of a triangle soup, so that input whose
 * triangles are wound both ways (merged scans, some exports) is decimated as the surface it is
 * (docs/ALGORITHM.md, section 10).
 */
#ifndef colordecimation_Orientation_h
#define colordecimation_Orientation_h

#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>
#include <vector>

namespace colordecimation
{

/**
 * Reverse triangles so that across every edge shared by exactly two triangles the two run it
 * in opposite directions, as far as each piece (triangles connected through such edges) is
 * orientable; in each piece the winding of the majority of its triangles is kept. Edges of
 * one or of three and more triangles do not connect. Writes the triangles so oriented into
 * `oriented` (3 ids each) and returns one flag per triangle, 1 where it was reversed (as
 * vtkPolyDataNormals' consistency step would, without choosing an outside).
 */
VTKCOLORDECIMATION_EXPORT std::vector<uint8_t> OrientTriangles(const int32_t* triangles,
                                                               int32_t numTriangles,
                                                               std::vector<int32_t>& oriented);

} // namespace colordecimation

#endif
