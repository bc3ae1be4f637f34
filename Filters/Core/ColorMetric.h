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

/// Hot all-pairs loops get an AVX2 clone next to the baseline one, picked at load time.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define COLORDECIMATION_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define COLORDECIMATION_VECTOR_CLONES
#endif

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

inline double SquaredDistance3(const double* a, const double* b)
{
  const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
  return d0 * d0 + d1 * d1 + d2 * d2;
}

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
 * The 1-ring of v0 as the cost needs it: neighbour ids, positions and colours (as separate
 * coordinate arrays, so that the all-pairs loops of the cost vectorise), and which neighbours
 * are admissible collapse targets. Reused between calls (no allocation once grown).
 */
struct Ring
{
  int Size = 0;
  std::vector<int32_t> Vertex;
  std::vector<double> X, Y, Z; ///< positions
  std::vector<double> R, G, B; ///< colours
  std::vector<double> QC;      ///< Q(i) at its own position (the quadric's constant term)
  std::vector<uint8_t> IsCandidate;
  std::vector<double> Product; ///< scratch: |c0-ci| |p0-pi|

  /// Size rounded up to a multiple of 4: the arrays hold zeros up to there after Pad().
  int PaddedSize() const { return (this->Size + 3) & ~3; }

  void Clear() { this->Size = 0; }
  void Add(int32_t v, const double p[3], const double c[3], bool candidate, double qc = 0.0)
  {
    if (static_cast<size_t>(this->Size + 4) >= this->Vertex.size())
    {
      this->Grow();
    }
    const int k = this->Size++;
    this->Vertex[k] = v;
    this->X[k] = p[0];
    this->Y[k] = p[1];
    this->Z[k] = p[2];
    this->R[k] = c[0];
    this->G[k] = c[1];
    this->B[k] = c[2];
    this->QC[k] = qc;
    this->IsCandidate[k] = candidate ? 1 : 0;
  }
  /// Zero the entries between Size and PaddedSize (so whole vector lanes can be computed).
  void Pad()
  {
    for (int k = this->Size; k < this->PaddedSize(); ++k)
    {
      this->X[k] = this->Y[k] = this->Z[k] = this->R[k] = this->G[k] = this->B[k] = 0.0;
      this->QC[k] = this->Product[k] = 0.0;
      this->IsCandidate[k] = 0;
    }
  }
  void GetPosition(int k, double p[3]) const
  {
    p[0] = this->X[k];
    p[1] = this->Y[k];
    p[2] = this->Z[k];
  }
  void GetColor(int k, double c[3]) const
  {
    c[0] = this->R[k];
    c[1] = this->G[k];
    c[2] = this->B[k];
  }

private:
  void Grow()
  {
    const size_t n = 2 * this->Vertex.size() + 16; // a multiple of 4
    this->Vertex.resize(n);
    for (auto* v :
         { &this->X, &this->Y, &this->Z, &this->R, &this->G, &this->B, &this->QC, &this->Product })
    {
      v->resize(n);
    }
    this->IsCandidate.resize(n);
  }
};

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
 * With boundaryWeight > 0 (not in the paper; off by default), each boundary edge also adds,
 * to both its vertices, the plane through the edge perpendicular to its triangle, weighted
 * by boundaryWeight times the edge's squared length (Garland and Heckbert's boundary
 * constraint): collapses that pull a boundary inwards or cut its corners then cost more.
 *
 * On `threads` threads, each owning a range of vertices and adding to them the faces and
 * edges in the same order as one thread would: the result is the same for any number.
 */
VTKCOLORDECIMATION_EXPORT void InitializeVertexMetrics(const HalfEdgeMesh& mesh,
                                                       const float* positions, const float* colors,
                                                       std::vector<VertexMetric>& metrics,
                                                       int positionStride = 3, int colorStride = 3,
                                                       double boundaryWeight = 0.0,
                                                       int threads = 1);
/// The same into metrics[0, mesh.GetNumberOfVertices()), every record written (the threads
/// clear their own first, so that a fresh array is first touched by all of them).
VTKCOLORDECIMATION_EXPORT void InitializeVertexMetrics(const HalfEdgeMesh& mesh,
                                                       const float* positions, const float* colors,
                                                       VertexMetric* metrics, int positionStride,
                                                       int colorStride, double boundaryWeight,
                                                       int threads);

} // namespace colordecimation

#endif
