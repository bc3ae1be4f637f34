/**
 * @file HalfEdgeColor.h
 * @brief The paper's metric (docs/ALGORITHM.md, sections 3 and 4): its per-vertex state, its
 * cost terms, and its policy for the engine.
 *
 * For a half-edge collapse v0 -> v1:
 * - geometric term  Q(v0->v1) = (Q(v0) + Q(v1))(p1)                      (eq. 9)
 * - visual importance I(v0) = sum_i |c0-ci| / max_i |c0-ci|, 0 if max = 0   (eq. 14)
 * - colour error C(v0->v1) = sum_i | |c0-ci| |p0-pi| - |c1-ci| |p1-pi| |   (eq. 16 mended)
 *   over the current 1-ring i of v0 (for i = v1 the second product is 0)
 * - cost E = (1 + Q) (1 + I) (1 + C)                                      (eq. 17)
 * After the collapse v1 holds Q(v0) + Q(v1) and I(v0) + I(v1) (eq. 15).
 *
 * Positions are in the normalised frame (mean edge length 1), colours RGB in [0,1] (or
 * CIELab / 100). Everything is computed in double.
 */
#ifndef colordecimation_HalfEdgeColor_h
#define colordecimation_HalfEdgeColor_h

#include "engine/Frame.h"
#include "engine/Options.h"
#include "metric/Quadric.h"
#include "metric/Ring.h"
#include "util/Buffer.h"
#include "util/Prefetch.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace colordecimation
{
class HalfEdgeMesh;

/// The per-vertex state of the metric: the paper's 12 floats, 48 bytes.
struct VertexMetric
{
  Quadric Q;                  ///< 10 floats, centred at the vertex (see Quadric.h)
  float Importance = 0;       ///< I(v), eq. 14 then accumulated by eq. 15
  float MaxColorDistance = 0; ///< the maximum in eq. 14
};
static_assert(sizeof(VertexMetric) == 48, "the paper's 12 floats per vertex");

/// |ca - cb| |pa - pb|, the colour difference along an edge (eq. 16), with one square root.
inline double ColorLengthProduct(const double* ca, const double* cb, const double* pa,
                                 const double* pb)
{
  return std::sqrt(SquaredDistance3(ca, cb) * SquaredDistance3(pa, pb));
}

/// eq. 14 from the sum and the maximum of the colour distances to the neighbours.
inline double VisualImportance(double sumOfDistances, double maxDistance)
{
  return maxDistance > 0 ? sumOfDistances / maxDistance : 0.0;
}

/// eq. 17.
inline double TotalCost(double quadricError, double importance, double colorError)
{
  return (1.0 + quadricError) * (1.0 + importance) * (1.0 + colorError);
}

/**
 * eq. 16 (mended) for the collapse of v0 (position p0, colour c0) onto the ring member j.
 * O(ring size). Used by tests and as the reference for CollapseColorErrors.
 */
VTKCOLORDECIMATION_EXPORT double CollapseColorError(const double p0[3], const double c0[3],
                                                    const Ring& ring, int j);

/**
 * eq. 16 (mended) for every member j of the ring at once, written to `errors[j]` (at least
 * ring.PaddedSize() entries; the ring must have been padded with Pad()). The products |c0-ci|
 * |p0-pi| are shared by all j; the i = j term needs no special case since |cj-cj| |pj-pj| = 0.
 */
VTKCOLORDECIMATION_EXPORT void CollapseColorErrors(const double p0[3], const double c0[3],
                                                   Ring& ring, double* errors);

/**
 * Initial per-vertex state on the input mesh: the area-weighted quadric of the triangles
 * around each vertex (eq. 8) and the visual importance (eq. 14). Vertex v's position is
 * positions[positionStride * v + 0..2], its colour colors[colorStride * v + 0..2]; `colors` may be
 * null (importance 0).
 *
 * With boundaryWeight > 0 (not in the paper; section 3), each boundary edge also adds,
 * to both its vertices, the plane through the edge perpendicular to its triangle, weighted
 * by boundaryWeight times the edge's squared length (Garland and Heckbert's boundary
 * constraint): collapses that pull a boundary inwards or cut its corners then cost more.
 *
 * With edgeLengthWeight > 0 (not in the paper; section 3), each triangle also adds to its
 * corners edgeLengthWeight times its area times the squared distance from the corner: on flat
 * parts, where the planes cost nothing, the shortest collapses go first and a vertex that
 * absorbed others costs more to collapse into, so flat parts are decimated evenly instead of
 * into fans of needles.
 *
 * On `threads` threads, each owning a range of vertices and adding to them the faces and
 * edges in the same order as one thread would: the result is the same for any number.
 */
VTKCOLORDECIMATION_EXPORT void InitializeVertexMetrics(const HalfEdgeMesh& mesh,
                                                       const float* positions, const float* colors,
                                                       std::vector<VertexMetric>& metrics,
                                                       int positionStride = 3, int colorStride = 3,
                                                       double boundaryWeight = 0.0, int threads = 1,
                                                       double edgeLengthWeight = 0.0);
/// The same into metrics[0, mesh.GetNumberOfVertices()), every record written (the threads
/// clear their own first, so that a fresh array is first touched by all of them).
VTKCOLORDECIMATION_EXPORT void InitializeVertexMetrics(const HalfEdgeMesh& mesh,
                                                       const float* positions, const float* colors,
                                                       VertexMetric* metrics, int positionStride,
                                                       int colorStride, double boundaryWeight,
                                                       int threads, double edgeLengthWeight = 0.0);
/**
 * The cost of every member j of the ring of v0 (hot0: its record, m0: its state), written to
 * costs[0, ring.PaddedSize()): with colorTerms the paper's (1 + wQ)(1 + I)(1 + C), where C is 0
 * unless withColorError (the lower bound (1 + wQ)(1 + I)); without, the quadric error wQ.
 */
VTKCOLORDECIMATION_EXPORT void CostHalfEdgeRing(const HotVertex& hot0, const VertexMetric& m0,
                                                double weight, bool colorTerms, bool withColorError,
                                                Ring& ring, double* costs);

/// Whether the records' colours are not all the same.
VTKCOLORDECIMATION_EXPORT bool ColorsVary(const Buffer<HotVertex>& hot);

/**
 * The half-edge metrics as the engine's policy (engine/Engine.h): the state (48 bytes a
 * vertex), the cost of a ring, and the merge of a collapse. ColorTerms: the paper's cost;
 * without them (ErrorMetric::Geometry), the quadric error alone on the same state.
 */
template <bool ColorTerms>
class HalfEdgeMetric
{
public:
  /// Half-edge collapses never move a vertex: nothing to place, no scratch.
  struct Placement
  {
  };
  struct Scratch
  {
  };
  /// Whether the metric reads the input's colours.
  static constexpr bool ReadsColor = ColorTerms;
  static constexpr bool CostsPieces = false; ///< see AttributeQuadricMetric::PieceCost
  static constexpr bool CostsByPair = false; ///< see AttributeQuadricMetric
  /// Vertices of more neighbours than this are keyed by the lower bound (1 + Q)(1 + I) until
  /// they reach the top of the heap (section 6).
  static constexpr int LargeRing = 16;

  explicit HalfEdgeMetric(const DecimatorOptions& options)
    : GeometryWeight(options.GeometryWeight)
    , BoundaryWeight(std::max(options.BoundaryWeight, 0.0))
    , EdgeLengthWeight(std::max(options.EdgeLengthWeight, 0.0))
    , BoundHighValence(options.BoundHighValence)
  {
  }

  /// The initial state of every vertex (eq. 8 and 14), on `threads` threads. Colours that do
  /// not vary make I and C zero everywhere: then they are not computed at all.
  void Initialize(const HalfEdgeMesh& mesh, const Frame&, Buffer<HotVertex>& hot, bool useColor,
                  int threads)
  {
    this->Hot = &hot;
    this->UseColor = useColor && ColorsVary(hot);
    this->States.resize(hot.size()); // written by the threads
    InitializeVertexMetrics(mesh, hot.empty() ? nullptr : hot[0].P,
                            this->UseColor ? hot[0].C : nullptr, this->States.data(), HotStride,
                            HotStride, this->BoundaryWeight, threads, this->EdgeLengthWeight);
  }

  /// Whether v0, of ringSize neighbours, is keyed by the lower bound of its cost.
  bool KeysByBound(int ringSize) const
  {
    return ColorTerms && this->BoundHighValence && ringSize > LargeRing && this->UseColor;
  }

  void CostRing(int32_t v0, bool withColorError, Ring& ring, double* costs, Scratch&) const
  {
    CostHalfEdgeRing((*this->Hot)[v0], this->States[v0], this->GeometryWeight, ColorTerms,
                     withColorError && this->UseColor, ring, costs);
  }

  /// Hint that v's state is about to be read (a 48-byte record straddles two cache lines one
  /// time in two).
  void Prefetch(int32_t v) const { PrefetchRecord(this->States.data() + v); }

  // Placement: none (see ColorQuadricMetric for a metric that moves vertices).
  static constexpr bool MovesVertices() { return false; }
  bool Place(int32_t, int32_t, Placement&, double[3]) const { return false; }
  bool RingPlacement(int32_t, int, const Scratch&, double[3]) const { return false; }
  bool IsMoved(int32_t) const { return false; }
  bool AnyMoved() const { return false; }

  /// eq. 9 and 15: v1 takes over v0's quadric (re-centred at p1) and importance.
  void Merge(int32_t v0, int32_t v1, bool, const Placement&)
  {
    HotVertex* hot = this->Hot->data();
    VertexMetric& m0 = this->States[v0];
    VertexMetric& m1 = this->States[v1];
    const float* p0 = hot[v0].P;
    const float* p1 = hot[v1].P;
    const double d[3] = { double(p1[0]) - p0[0], double(p1[1]) - p0[1], double(p1[2]) - p0[2] };
    m1.Q.AddShifted(m0.Q, d);
    m1.Importance += m0.Importance;
    m1.MaxColorDistance = std::max(m1.MaxColorDistance, m0.MaxColorDistance);
    hot[v1].QC = m1.Q.C;
  }

  static constexpr size_t BytesPerVertex() { return sizeof(VertexMetric); }
  /// Drop the state (what the output does not need), or map it to the input's ids.
  void Release() { this->States = Buffer<VertexMetric>(); }
  template <typename Map>
  void Restore(const Map& restore)
  {
    restore(this->States);
  }

  Buffer<VertexMetric> States;

private:
  double GeometryWeight;
  double BoundaryWeight;
  double EdgeLengthWeight;
  bool BoundHighValence;
  bool UseColor = false;
  Buffer<HotVertex>* Hot = nullptr;
};

/// The paper's metric, (1 + Q)(1 + I)(1 + C).
using HalfEdgeColorMetric = HalfEdgeMetric<true>;
/// The quadric error alone (ErrorMetric::Geometry).
using GeometryMetric = HalfEdgeMetric<false>;

} // namespace colordecimation

#endif
