/**
 * @file ColorQuadricMetric.h
 * @brief Garland and Heckbert's colour quadric as the engine's policy (docs/ALGORITHM.md,
 * section 9): the comparison metric.
 *
 * Every vertex is a point (x, y, z, r, g, b) of R^6: geometry with the bounding box scaled
 * into the unit cube, colour times ColorWeight. Its state is the 112-byte ColorQuadric of its
 * triangles (ColorQuadric.h), centred at its own point. A half-edge collapse v0 -> v1 costs
 * (Q0 + Q1)(x1) and v1 keeps Q0 + Q1 (Q(v1) only grows, so the engine's lazy argument holds).
 * With OptimalPlacement the collapse is a full one: v1 moves to the minimiser of Q0 + Q1 (its
 * colour brought back into the displayable range; the better endpoint when the 6x6 system is
 * singular or its solution lies far from the edge), and every cost towards v1 may change.
 */
#ifndef colordecimation_ColorQuadricMetric_h
#define colordecimation_ColorQuadricMetric_h

#include "engine/Frame.h"
#include "engine/Options.h"
#include "metric/ColorQuadric.h"
#include "metric/Ring.h"
#include "util/Buffer.h"
#include "util/Prefetch.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>
#include <vector>

namespace colordecimation
{
class HalfEdgeMesh;

class VTKCOLORDECIMATION_EXPORT ColorQuadricMetric
{
public:
  /// Where a full collapse puts the merged vertex: its offset from v0's point of R^6.
  struct Placement
  {
    double Y[6];
  };
  /// Per thread: the placement of every ring member (6 per member) while costing a ring.
  struct Scratch
  {
    std::vector<double> Placements;
  };
  static constexpr bool ReadsColor = true;
  static constexpr bool CostsPieces = false; ///< see AttributeQuadricMetric::PieceCost
  static constexpr bool CostsByPair = false; ///< see AttributeQuadricMetric

  explicit ColorQuadricMetric(const DecimatorOptions& options);

  /// The frame of R^6 and the initial quadric of every vertex.
  void Initialize(const HalfEdgeMesh& mesh, const Frame& frame, Buffer<HotVertex>& hot,
                  bool useColor, int threads);

  static constexpr bool KeysByBound(int) { return false; }
  /// The cost of every ring member (and, with OptimalPlacement, its placement into scratch).
  void CostRing(int32_t v0, bool withColorError, Ring& ring, double* costs, Scratch& scratch) const;
  void Prefetch(int32_t v) const { PrefetchRecord(this->States.data() + v); }

  /// Whether collapses may move the survivor (OptimalPlacement).
  bool MovesVertices() const { return this->Placing; }
  /**
   * The placement of v0 -> v1 into `place`; true when it moves v1, then with the new position
   * (normalised frame) in newPosition.
   */
  bool Place(int32_t v0, int32_t v1, Placement& place, double newPosition[3]) const;
  /// With OptimalPlacement, the position that ring member j's collapse (CostRing's scratch)
  /// puts v1 at; false without.
  bool RingPlacement(int32_t v0, int j, const Scratch& scratch, double p[3]) const;
  bool IsMoved(int32_t v) const { return !this->Moved.empty() && this->Moved[v] != 0; }
  bool AnyMoved() const;

  /// Merge v0 into v1 (moved to the placement when `moves`).
  void Merge(int32_t v0, int32_t v1, bool moves, const Placement& place);

  static constexpr size_t BytesPerVertex() { return sizeof(ColorQuadric); }
  void Release() { this->States = LargeVector<ColorQuadric>(); }
  template <typename Map>
  void Restore(const Map& restore)
  {
    restore(this->States);
    restore(this->Moved);
  }

  LargeVector<ColorQuadric> States;

private:
  /// The offset of v1 from v0 in R^6.
  void Offset6(int32_t v0, int32_t v1, double d[6]) const;
  /// A placement offset y from v0 as a position in the normalised frame (rounded to float as
  /// it will be stored, so that the rules see that point).
  void PlacementPosition(int32_t v0, const double y[6], double p[3]) const;
  /// The cost of the full collapse of v0 and v1 and the new vertex's offset y from v0's point
  /// (d01: v1's offset from v0's point).
  double PlaceCollapse(int32_t v0, int32_t v1, const double d01[6], double y[6]) const;
  /// The minimiser's offset y made displayable and storable (colour clamped, then both rounded
  /// as they will be stored); its cost.
  double SnapPlacement(int32_t v0, const ColorQuadricD& q, const double d01[6], double y[6]) const;
  /// The better endpoint when there is no placement: v1's point unless v0's is better by more
  /// than the rounding of the evaluation.
  double BetterEndpoint(int32_t v1, const ColorQuadricD& q, const double d01[6], double y[6]) const;

  const HalfEdgeMesh* Mesh = nullptr;
  Buffer<HotVertex>* Hot = nullptr;
  double CubeScale = 1.0; ///< normalised frame -> GH98's unit-cube frame
  double ColorWeight;
  double BoundaryWeight;
  bool Placing;
  bool PreserveBoundary;
  ColorSpace Space;
  bool UseColor = false;
  LargeVector<uint8_t> Moved;
};

} // namespace colordecimation

#endif
