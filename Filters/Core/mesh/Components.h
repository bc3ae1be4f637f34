/**
 * @file Components.h
 * @brief Removing whole connected pieces of a decimated mesh, for PruneComponents
 * (docs/ALGORITHM.md, section 14): the small fragments of a scan that collapses alone cannot
 * take below a few triangles each.
 */
#ifndef colordecimation_Components_h
#define colordecimation_Components_h

#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>

namespace colordecimation
{
class HalfEdgeMesh;

/// What PruneComponents removed.
struct PruneReport
{
  int64_t Components = 0;
  int64_t Triangles = 0;
};

/**
 * Remove connected pieces of the live faces (faces connected through shared vertices),
 * smallest area first (ties: fewer triangles first, then the piece of the lower face id),
 * until at most `target` faces are live. Pieces with a vertex that `fixed` marks (one per
 * vertex, may be null) are kept, and so is the last piece left. `points`: 3 doubles per
 * vertex, for the areas.
 */
VTKCOLORDECIMATION_EXPORT PruneReport PruneComponents(HalfEdgeMesh& mesh, const double* points,
                                                      const uint8_t* fixed, int64_t target);

} // namespace colordecimation

#endif
