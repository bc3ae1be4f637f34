/**
 * @file Components.h
 * @brief Whole connected pieces of a mesh: those a run may remove as it goes (PieceWeight), and
 * their removal after it (PruneComponents; docs/ALGORITHM.md, section 14): the small fragments
 * of a scan, which collapses alone cannot take below a few triangles each.
 */
#ifndef colordecimation_Components_h
#define colordecimation_Components_h

#include "vtkColorDecimationModule.h" // for export macro

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace colordecimation
{
class HalfEdgeMesh;

/// Connected pieces of a mesh: each piece's faces, in face order.
struct Pieces
{
  std::vector<int32_t> Start; ///< piece p has faces Faces[Start[p] .. Start[p + 1])
  std::vector<int32_t> Faces;
  size_t Size() const { return this->Start.empty() ? 0 : this->Start.size() - 1; }
};

/**
 * The connected pieces of the live faces (through shared vertices) that a run may remove:
 * all but the one of most faces (ties: the one with the lowest vertex id), less those with a
 * vertex `keep` marks. Numbered by their lowest vertex id. Holds two ints and a byte per
 * vertex while it runs. The union of the faces runs on `threads` threads (the same pieces).
 */
VTKCOLORDECIMATION_EXPORT Pieces FindSmallPieces(const HalfEdgeMesh& mesh,
                                                 const std::function<bool(int32_t)>& keep,
                                                 int threads = 1);

/// The distinct vertices of the live faces among faces[0 .. count), in increasing order.
VTKCOLORDECIMATION_EXPORT void PieceVertices(const HalfEdgeMesh& mesh, const int32_t* faces,
                                             size_t count, std::vector<int32_t>& vertices);

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
