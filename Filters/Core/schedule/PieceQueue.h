/**
 * @file PieceQueue.h
 * @brief Small connected pieces removed whole, in cost order among the collapses
 * (docs/ALGORITHM.md, section 14): the fragments of a scan, which collapses cannot take below a
 * few triangles each, go when removing one costs less than the collapses being made.
 *
 * The pieces (mesh/Components.h: all but the largest, none with a fixed or seam vertex, nor,
 * with PreserveBoundary, a boundary one) are costed once, at the start, by the metric: the
 * cost of collapsing every vertex of the piece into its best one and of the area moving there
 * (AttributeQuadricMetric::PieceCost), times PieceWeight. A piece's vertices only ever collapse
 * into each other, so those sums, like the piece itself, stay what they were at the start. The
 * schedules ask for the pieces up to the cost they have reached (Greedy before each collapse,
 * Batched before each pass); a piece beyond MaximumError is kept.
 */
#ifndef colordecimation_PieceQueue_h
#define colordecimation_PieceQueue_h

#include "mesh/Components.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstddef>
#include <cstdint>
#include <vector>

namespace colordecimation
{
class HalfEdgeMesh;

class VTKCOLORDECIMATION_EXPORT PieceQueue
{
public:
  /// The pieces with one cost and one squared error (rules/ErrorBound.h) each, ordered by cost
  /// (ties: the piece's number); a NaN cost never comes up.
  void Reset(Pieces pieces, std::vector<double> costs, std::vector<double> squaredErrors);
  bool IsEmpty() const { return this->Next >= this->Order.size(); }
  double NextCost() const { return this->Costs[this->Order[this->Next]]; }
  double NextSquaredError() const { return this->SquaredErrors[this->Order[this->Next]]; }
  /// The next piece's live faces and their vertices; it leaves the queue.
  void Pop(const HalfEdgeMesh& mesh, std::vector<int32_t>& faces, std::vector<int32_t>& vertices);
  size_t Bytes() const;
  /// The faces of all its pieces, removed or not.
  size_t FaceTotal() const { return this->P.Faces.size(); }

private:
  Pieces P;
  std::vector<double> Costs, SquaredErrors;
  std::vector<int32_t> Order;
  size_t Next = 0;
};

} // namespace colordecimation

#endif
