/**
 * @file AttributeQuadric.h
 * @brief Hoppe's quadric for appearance attributes ("New quadric metric for simplifying
 * meshes with appearance attributes", 1999), evaluated at the kept vertex of a half-edge
 * collapse (docs/ALGORITHM.md, section 12).
 *
 * For a triangle of area a, with unit normal n and, for each colour channel k, the gradient
 * g_k of the channel interpolated linearly over it, the quadric of a point x with colour s is
 *   a * ( (n.(x - x0))^2 + sum_k (s0_k + g_k.(x - x0) - s_k)^2 )
 * (x0, s0: a corner): the squared distance to the triangle's plane plus the squared difference
 * from the triangle's colour at x. A vertex holds the sum over its triangles. Positions are in
 * the normalised frame (mean edge length 1, section 2), colours times ColorWeight: a colour
 * difference of 1 / ColorWeight weighs as a distance of one mean edge length, whatever the
 * mesh's units.
 *
 * As a quadric of R^6 it has the structure [[A, -G^T], [-G, w I]]: 23 floats (92 bytes) instead
 * of the 28 of the general colour quadric. It is stored centred at its vertex's own point of
 * R^6, so the initial quadric has no linear and constant terms.
 */
#ifndef colordecimation_AttributeQuadric_h
#define colordecimation_AttributeQuadric_h

#include "engine/Frame.h"
#include "engine/Options.h"
#include "metric/Ring.h"
#include "util/Buffer.h"
#include "util/Prefetch.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>

namespace colordecimation
{
class HalfEdgeMesh;

/// The weights of a triangle's terms (section 12).
struct AttributeQuadricWeights
{
  double Boundary = 0;   ///< the boundary planes, times the squared edge length
  double EdgeLength = 0; ///< the isotropic edge-length term, times the area
  double Geometry = 1;   ///< the plane term, times the area
};

/// Q(dx, ds) = dx^T A dx - 2 sum_k ds_k (G_k . dx) + W |ds|^2 + 2 B . dx - 2 D . ds + C, for the
/// offset (dx, ds) from the centre.
struct VTKCOLORDECIMATION_EXPORT AttributeQuadric
{
  float A00 = 0, A01 = 0, A02 = 0, A11 = 0, A12 = 0, A22 = 0;
  float G[3][3] = {}; ///< G[k]: the area-weighted gradient of channel k
  float W = 0;        ///< the area (the colour block is W I)
  float B[3] = {};
  float D[3] = {};
  float C = 0;

  double Evaluate(const double dx[3], const double ds[3]) const;
  /// Add `other`, centred at (x_other, s_other), to this quadric: dx = x_this - x_other and
  /// ds = s_this - s_other (this centre in other's frame).
  void AddShifted(const AttributeQuadric& other, const double dx[3], const double ds[3]);
  /// Add weight * m m^T to the geometric block (a plane through the centre). Inline: the
  /// set-up adds seven planes a corner.
  void AddPlane(const double m[3], double weight)
  {
    this->A00 = static_cast<float>(this->A00 + weight * m[0] * m[0]);
    this->A01 = static_cast<float>(this->A01 + weight * m[0] * m[1]);
    this->A02 = static_cast<float>(this->A02 + weight * m[0] * m[2]);
    this->A11 = static_cast<float>(this->A11 + weight * m[1] * m[1]);
    this->A12 = static_cast<float>(this->A12 + weight * m[1] * m[2]);
    this->A22 = static_cast<float>(this->A22 + weight * m[2] * m[2]);
  }
  /// A triangle's terms at its corner (the plane and the colour field pass through it):
  /// area * (geometry n n^T + edgeLength I + sum_k g_k g_k^T), area * g_k, area.
  void AddTriangle(const double n[3], const double g[3][3], double area,
                   const AttributeQuadricWeights& weights)
  {
    constexpr double axis[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    this->AddPlane(n, weights.Geometry * area);
    if (weights.EdgeLength > 0)
    {
      for (const double* a : axis)
      {
        this->AddPlane(a, weights.EdgeLength * area);
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      this->AddPlane(g[k], area);
      for (int i = 0; i < 3; ++i)
      {
        this->G[k][i] = static_cast<float>(this->G[k][i] + area * g[k][i]);
      }
    }
    this->W = static_cast<float>(this->W + area);
  }
};
static_assert(sizeof(AttributeQuadric) == 92, "23 floats per vertex");

/**
 * The initial quadrics of the vertices (colours times colorScale; colors may be null), with
 * Garland and Heckbert's boundary planes and the edge-length term as weighted, on `threads`
 * threads (the same quadrics bit for bit for any number).
 */
VTKCOLORDECIMATION_EXPORT void InitializeAttributeQuadrics(
  const HalfEdgeMesh& mesh, const float* positions, int positionStride, const float* colors,
  int colorStride, double colorScale, const AttributeQuadricWeights& weights,
  Buffer<AttributeQuadric>& quadrics, int threads = 1);

/// The attribute quadric as the engine's policy: half-edge collapses at cost Q0(x1) + k c1, the
/// error the collapse adds at v0 plus k times the error v1 holds already (its constant c1;
/// k = KeptVertexErrorWeight: 1 gives (Q0 + Q1)(x1), Garland and Heckbert's total error).
class VTKCOLORDECIMATION_EXPORT AttributeQuadricMetric
{
public:
  struct Placement
  {
  };
  struct Scratch
  {
  };
  static constexpr bool ReadsColor = true;
  static constexpr bool CostsPieces = true;
  /// The cost of v0 -> v1 reads the states of v0 and v1 alone, not v0's ring (ChooseNewNeighbor).
  static constexpr bool CostsByPair = true;

  explicit AttributeQuadricMetric(const DecimatorOptions& options);

  void Initialize(const HalfEdgeMesh& mesh, const Frame& frame, Buffer<HotVertex>& hot,
                  bool useColor, int threads);
  static constexpr bool KeysByBound(int) { return false; }
  void CostRing(int32_t v0, bool withColorError, Ring& ring, double* costs, Scratch&) const;
  void Prefetch(int32_t v) const { PrefetchRecord(this->States.data() + v); }

  static constexpr bool MovesVertices() { return false; }
  bool Place(int32_t, int32_t, Placement&, double[3]) const { return false; }
  bool RingPlacement(int32_t, int, const Scratch&, double[3]) const { return false; }
  bool IsMoved(int32_t) const { return false; }
  bool AnyMoved() const { return false; }
  /**
   * The cost of removing a whole piece (section 14), as if all its vertices collapsed into
   * the best of them (into `best`): their quadrics summed, plus the area their points would
   * travel, GeometryWeight * sum of W_v |x_v - x_best|^2 (the plane terms do not see a piece
   * shrink within its plane), at the vertex where that is least, and never below 0. `spread`: that
   * travel divided by the area, the mean squared distance moved.
   */
  double PieceCost(const int32_t* vertices, size_t count, int32_t& best, double& spread) const;
  /// v1 takes over v0's quadric, re-centred at v1's point.
  void Merge(int32_t v0, int32_t v1, bool, const Placement&);

  static constexpr size_t BytesPerVertex() { return sizeof(AttributeQuadric); }
  /// The scale s that SceneRelativeWeights applied in Initialize (1: none).
  double GetSceneWeightScale() const { return this->Scale; }
  void Release() { this->States = Buffer<AttributeQuadric>(); }
  template <typename Map>
  void Restore(const Map& restore)
  {
    restore(this->States);
  }

  Buffer<AttributeQuadric> States;

private:
  /// The offset of v1's point of R^6 from v0's.
  void Offset(int32_t v0, int32_t v1, double dx[3], double ds[3]) const;

  Buffer<HotVertex>* Hot = nullptr;
  double GivenColorWeight;    ///< as the options give them,
  double GivenBoundaryWeight; ///< before SceneRelativeWeights scales them
  bool SceneRelative;
  double Scale = 1;   ///< what SceneRelativeWeights applied (engine/Frame.h)
  double ColorWeight; ///< what the run uses
  double KeptErrorWeight;
  AttributeQuadricWeights Weights;
  bool UseColor = false;
};

} // namespace colordecimation

#endif
