/**
 * @file ColorMetric.h
 * @brief The cost terms of the half-edge colour metric (paper eq. 13-17, SPEC.md).
 *
 * For a half-edge collapse v0 -> v1:
 * - geometric term  Q(v0->v1) = (Q(v0) + Q(v1))(p1)                      (eq. 9)
 * - visual importance I(v0) = sum_i |c0-ci| / max_i |c0-ci|, 0 if max = 0   (eq. 14)
 * - colour error C(v0->v1) = sum_i | |c0-ci| |p0-pi| - |c1-ci| |p1-pi| |   (eq. 16 mended)
 *   over the current 1-ring i of v0 (for i = v1 the second product is 0)
 * - cost E = (1 + Q) (1 + I) (1 + C)                                      (eq. 17)
 *
 * Colours are RGB in [0,1]; positions are in the normalised frame (mean edge length 1).
 * Everything is computed in double.
 */
#ifndef colordecimation_ColorMetric_h
#define colordecimation_ColorMetric_h

#include "Quadric.h"
#include "vtkColorDecimationModule.h" // for export macro

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

inline double Distance3(const double* a, const double* b)
{
  const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
  return std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
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
 * The 1-ring of v0 as the cost needs it: neighbour ids, positions and colours, and which
 * neighbours are admissible collapse targets. Reused between calls (no allocation once grown).
 */
struct Ring
{
  int Size = 0;
  std::vector<int32_t> Vertex;
  std::vector<double> P; ///< 3 per neighbour
  std::vector<double> C; ///< 3 per neighbour
  std::vector<uint8_t> IsCandidate;
  std::vector<double> Product; ///< |c0-ci| |p0-pi|, filled by CollapseColorErrors

  void Clear() { this->Size = 0; }
  void Add(int32_t v, const double p[3], const double c[3], bool candidate)
  {
    if (static_cast<size_t>(this->Size) == this->Vertex.size())
    {
      const size_t n = 2 * this->Vertex.size() + 16;
      this->Vertex.resize(n);
      this->P.resize(3 * n);
      this->C.resize(3 * n);
      this->IsCandidate.resize(n);
      this->Product.resize(n);
    }
    const int k = this->Size++;
    this->Vertex[k] = v;
    for (int j = 0; j < 3; ++j)
    {
      this->P[3 * k + j] = p[j];
      this->C[3 * k + j] = c[j];
    }
    this->IsCandidate[k] = candidate ? 1 : 0;
  }
};

/**
 * eq. 16 (mended) for the collapse of v0 (position p0, colour c0) onto the ring member j.
 * O(ring size). Used by tests and as the reference for CollapseColorErrors.
 */
VTKCOLORDECIMATION_EXPORT double CollapseColorError(const double p0[3], const double c0[3],
                                                    const Ring& ring, int j);

/**
 * eq. 16 (mended) for every candidate j of the ring at once, written to `errors[j]`
 * (non-candidates are left untouched). The products |c0-ci| |p0-pi| are shared by all j.
 */
VTKCOLORDECIMATION_EXPORT void CollapseColorErrors(const double p0[3], const double c0[3],
                                                   Ring& ring, double* errors);

/**
 * Initial per-vertex state on the input mesh: the area-weighted quadric of the triangles
 * around each vertex (eq. 8) and the visual importance (eq. 14). `positions` and `colors`
 * hold 3 floats per vertex; `colors` may be null (importance 0).
 */
VTKCOLORDECIMATION_EXPORT void InitializeVertexMetrics(const HalfEdgeMesh& mesh,
                                                       const float* positions, const float* colors,
                                                       std::vector<VertexMetric>& metrics);

} // namespace colordecimation

#endif
