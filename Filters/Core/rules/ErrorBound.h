/**
 * @file ErrorBound.h
 * @brief The geometric error of a collapse, for MaximumError (docs/ALGORITHM.md, section 14).
 *
 * Every vertex holds the area-weighted sum of the plane quadrics of the input triangles that
 * met at it, and of those of the vertices merged into it. The error of a collapse into v1 at
 * position x is the root of that sum of v0 and v1 at x divided by their summed area: the
 * area-weighted root-mean-square distance from x to those planes. It is a distance (in the
 * frame's units here; the caller scales it), independent of the metric that orders the
 * collapses. Only set up when a bound is asked for; in double precision.
 */
#ifndef colordecimation_ErrorBound_h
#define colordecimation_ErrorBound_h

#include "util/Buffer.h"
#include "util/Prefetch.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstddef>
#include <cstdint>

namespace colordecimation
{
class HalfEdgeMesh;

class VTKCOLORDECIMATION_EXPORT ErrorBound
{
public:
  /// The planes of the mesh's live faces (positions: 3 floats every `stride`), with the bound
  /// `bound` (in the positions' units); no bound when bound <= 0.
  void Initialize(const HalfEdgeMesh& mesh, const float* positions, int stride, double bound,
                  int threads = 1);
  bool IsEnabled() const { return this->Bound > 0.0; }
  /// Bytes held per vertex when enabled.
  static constexpr size_t BytesPerVertex = 11 * sizeof(double);
  double GetBound() const { return this->Bound; }

  /// The squared error of collapsing v0 into v1 placed at x.
  double SquaredError(int32_t v0, int32_t v1, const double x[3]) const;
  /// The squared error of collapsing all the listed vertices into one placed at x (a whole
  /// piece removed, section 14).
  double PieceSquaredError(const int32_t* vertices, size_t count, const double x[3]) const;
  /// v1 takes v0's planes.
  void Merge(int32_t v0, int32_t v1);
  /// Free the state.
  void Release() { this->Planes = Buffer<PlaneSum>(); }
  /// Hint that v's plane sum is about to be read (its 88 bytes span two cache lines).
  void Prefetch(int32_t v) const
  {
    if (!this->Planes.empty())
    {
      const char* p = reinterpret_cast<const char*>(this->Planes.data() + v);
      COLORDECIMATION_PREFETCH(p);
      COLORDECIMATION_PREFETCH(p + sizeof(PlaneSum) - 1);
    }
  }

private:
  /// Q(x) = x^T A x + 2 b.x + c (A symmetric) and the area it sums.
  struct PlaneSum
  {
    double A[6]; ///< a00 a01 a02 a11 a12 a22
    double B[3];
    double C;
    double Area;
    void Add(const PlaneSum& other);
    /// Q(x) / Area (0 without area).
    double Mean(const double x[3]) const;
  };
  Buffer<PlaneSum> Planes;
  double Bound = 0.0;
};

} // namespace colordecimation

#endif
