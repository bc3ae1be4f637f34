/**
 * @file CollapseRules.h
 * @brief When a half-edge collapse v0 -> v1 is allowed (docs/ALGORITHM.md, section 5).
 *
 * Topology (the link condition, after pmp-library's is_collapse_legal):
 * - both vertices unlocked (manifold neighbourhood) and adjacent;
 * - a boundary v0 collapses only along a boundary edge, and never when boundaries are
 *   preserved;
 * - a triangle on the edge must not have its two other edges on the boundary;
 * - the two vertices opposite the edge (vl, vr) differ, are unlocked, and keep a valence of at
 *   least 3 (interior) so no two triangles come to share all three vertices;
 * - v0 and v1 share no neighbour other than vl and vr (otherwise an edge would become
 *   non-manifold).
 * Geometry: no triangle of v0 that survives may become degenerate or turn its normal by more
 * than the configured angle in one collapse, nor (when reference triangles are given) drift
 * further than a second angle from the normal of the input triangle that first held its face
 * slot. The second test stops small turns from adding up, over many collapses, into a
 * triangle that faces away from the input surface.
 */
#ifndef colordecimation_CollapseRules_h
#define colordecimation_CollapseRules_h

#include "util/Buffer.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>
#include <vector>

namespace colordecimation
{
class HalfEdgeMesh;

struct CollapseRuleOptions
{
  bool PreserveBoundary = false;
  /// cos(maximum normal angle): a surviving triangle's normal may turn by at most that angle
  /// in one collapse.
  double MinimumNormalCosine = 0.0;
  /// cos(maximum drift): nor may it end up further than that from the normal of the input
  /// triangle of its face slot (see SetReferenceNormals). -1 disables the test.
  double MinimumDriftCosine = -1.0;
};

/**
 * A direction in 4 bytes: the octahedral map (the unit vector divided by its L1 norm, the
 * lower half folded over the upper), 16 bits a coordinate. Unpacked, it is within 1e-4 radians
 * of the packed direction (the drift guard's reference normals: 4 bytes a triangle).
 */
struct PackedNormal
{
  int16_t U;
  int16_t V;
};

/// `n` packed (any length; zero, NaN or infinite: "no direction").
VTKCOLORDECIMATION_EXPORT PackedNormal PackNormal(const double n[3]);
/// The direction of a PackedNormal, with L1 norm 1 (zero for "no direction").
VTKCOLORDECIMATION_EXPORT void UnpackNormal(PackedNormal packed, double n[3]);

/// Why a collapse was refused (for tests and statistics).
enum class CollapseVerdict
{
  Legal,
  NotCollapsible, ///< a vertex is locked, removed, or the two are not adjacent
  Boundary,       ///< boundary rule
  LinkCondition,  ///< the link condition or the valence rule
  Degenerate,     ///< a triangle would lose its area
  Flip            ///< a triangle normal would turn too far
};

class VTKCOLORDECIMATION_EXPORT CollapseRules
{
public:
  explicit CollapseRules(const CollapseRuleOptions& options)
    : Options(options)
  {
  }

  const CollapseRuleOptions& GetOptions() const { return this->Options; }

  /**
   * The input triangles' normals (one PackedNormal per face slot; see
   * ComputeReferenceNormals), which bound the drift of each face slot's normal. Null (the
   * default) disables that test. The array must outlive the checks.
   */
  void SetReferenceNormals(const PackedNormal* normals) { this->ReferenceNormals = normals; }

  /**
   * The normal of every live face slot of `mesh` (none where the triangle is degenerate), for
   * SetReferenceNormals. Kept per face slot rather than recomputed from the input's corners,
   * so that the check reads one record instead of three vertices that may long have been
   * collapsed away, and stays right when collapses move vertices. On `threads` threads (each
   * face is computed alone: the same result for any number).
   */
  static void ComputeReferenceNormals(const HalfEdgeMesh& mesh, const float* positions, int stride,
                                      Buffer<PackedNormal>& normals, int threads = 1);

  /**
   * Full check of v0 -> v1. The position of vertex v is positions[stride * v + 0..2] (so that
   * positions can live inside a larger per-vertex record).
   */
  CollapseVerdict Check(const HalfEdgeMesh& mesh, const float* positions, int32_t v0, int32_t v1,
                        int stride = 3);

  bool IsLegal(const HalfEdgeMesh& mesh, const float* positions, int32_t v0, int32_t v1,
               int stride = 3)
  {
    return this->Check(mesh, positions, v0, v1, stride) == CollapseVerdict::Legal;
  }

  /**
   * Full check of a collapse v0 -> v1 after which v1 sits at `newPosition` (a full collapse
   * with a placement; the same frame as `positions`).
   */
  CollapseVerdict Check(const HalfEdgeMesh& mesh, const float* positions, int32_t v0, int32_t v1,
                        int stride, const double newPosition[3]);

  bool IsLegal(const HalfEdgeMesh& mesh, const float* positions, int32_t v0, int32_t v1, int stride,
               const double newPosition[3])
  {
    return this->Check(mesh, positions, v0, v1, stride, newPosition) == CollapseVerdict::Legal;
  }

  /// The topological part alone.
  CollapseVerdict CheckTopology(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1);

  /// The geometric part alone: triangles of v0 moved onto p1 stay non-degenerate, unflipped.
  CollapseVerdict CheckGeometry(const HalfEdgeMesh& mesh, const float* positions, int32_t v0,
                                int32_t v1, int stride = 3) const;

  /**
   * The geometric part for a collapse that puts the merged vertex at `newPosition`: the
   * surviving triangles of v0 and, when newPosition is not p1, those of v1, with that corner
   * moved to newPosition, stay non-degenerate and unflipped. With newPosition = p1 this is
   * the check above.
   */
  CollapseVerdict CheckGeometry(const HalfEdgeMesh& mesh, const float* positions, int32_t v0,
                                int32_t v1, int stride, const double newPosition[3]) const;

private:
  /// The triangles of `centre` that do not use `other`, with centre moved to `newPosition`.
  CollapseVerdict CheckFan(const HalfEdgeMesh& mesh, const float* positions, int stride,
                           int32_t centre, int32_t other, const double newPosition[3]) const;

  CollapseRuleOptions Options;
  const PackedNormal* ReferenceNormals = nullptr;
  std::vector<int32_t> Neighbors; ///< scratch, reused
};

} // namespace colordecimation

#endif
