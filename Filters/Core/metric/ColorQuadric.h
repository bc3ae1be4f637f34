/**
 * @file ColorQuadric.h
 * @brief The colour quadric of Garland and Heckbert (1998), the metric the paper compares
 * against (paper eq. 10-12; docs/ALGORITHM.md, section 9).
 *
 * Each vertex is a point x = (x, y, z, r, g, b) of R^6. A triangle (v1, v2, v3) spans a plane
 * of R^6 with the orthonormal Gram-Schmidt vectors
 *   e1 = (v2 - v1) / |v2 - v1|,
 *   e2 = (v3 - v1 - (e1.(v3 - v1)) e1) / |...|                       (eq. 10, 11)
 * and the squared distance of a point x to that plane is the quadric
 *   D^2(x) = x^T A x + 2 b^T x + c,  A = I - e1 e1^T - e2 e2^T,
 *   b = (v1.e1) e1 + (v1.e2) e2 - v1,  c = v1.v1 - (v1.e1)^2 - (v1.e2)^2   (eq. 12).
 * A vertex holds the sum of the quadrics of its triangles, each weighted by the triangle's
 * area: 21 + 6 + 1 = 28 coefficients (A symmetric), 112 bytes in float.
 *
 * As the 10-float geometric Quadric (Quadric.h), a vertex's quadric is stored *centred at
 * the vertex's own point of R^6* (x is measured from it): a plane through the vertex then has
 * b = 0 and c = 0 exactly, and the coefficients stay of the size of local errors, so that
 * float storage does not lose small errors to cancellation against |x|^2-sized terms.
 * Evaluation, sums and solves are done in double.
 *
 * The frame (chosen by the caller, see Decimator.h): geometry as in GH98, the bounding box
 * scaled uniformly into the unit cube; colour in [0,1] (or CIELab / 100, ColorSpace.h),
 * multiplied by a colour weight.
 */
#ifndef colordecimation_ColorQuadric_h
#define colordecimation_ColorQuadric_h

#include "util/Buffer.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <algorithm>

namespace colordecimation
{
class HalfEdgeMesh;

/// A quadric of R^6: x^T A x + 2 b^T x + c, A symmetric (upper triangle stored row by row).
template <typename T>
struct BasicColorQuadric
{
  static constexpr int Dimension = 6;
  static constexpr int MatrixSize = 21;

  T A[MatrixSize] = {};
  T B[Dimension] = {};
  T C = 0;

  /// Position of A(i, j), i <= j, in A.
  static constexpr int Index(int i, int j)
  {
    return i <= j ? i * Dimension - (i * (i - 1)) / 2 + (j - i)
                  : j * Dimension - (j * (j - 1)) / 2 + (i - j);
  }
  double GetA(int i, int j) const { return this->A[Index(i, j)]; }

  /// Q at offset d from the centre.
  double Evaluate(const double d[Dimension]) const
  {
    double quadratic = 0.0;
    double linear = 0.0;
    int k = 0;
    for (int i = 0; i < Dimension; ++i)
    {
      double row = 0.5 * this->A[k++] * d[i]; // the diagonal counts once in d^T A d
      for (int j = i + 1; j < Dimension; ++j)
      {
        row += this->A[k++] * d[j];
      }
      quadratic += 2.0 * d[i] * row;
      linear += this->B[i] * d[i];
    }
    return quadratic + 2.0 * linear + this->C;
  }

  /// A d (A times an offset).
  void MultiplyA(const double d[Dimension], double out[Dimension]) const
  {
    for (int i = 0; i < Dimension; ++i)
    {
      double sum = 0.0;
      for (int j = 0; j < Dimension; ++j)
      {
        sum += this->A[Index(i, j)] * d[j];
      }
      out[i] = sum;
    }
  }

  /// Add `weight` times `other` (same centre).
  template <typename U>
  void Add(const BasicColorQuadric<U>& other, double weight = 1.0)
  {
    for (int k = 0; k < MatrixSize; ++k)
    {
      this->A[k] = static_cast<T>(this->A[k] + weight * other.A[k]);
    }
    for (int k = 0; k < Dimension; ++k)
    {
      this->B[k] = static_cast<T>(this->B[k] + weight * other.B[k]);
    }
    this->C = static_cast<T>(this->C + weight * other.C);
  }

  /**
   * Add `other`, whose centre lies at offset -d from this one's (d = centre_this -
   * centre_other): re-centred, other has b' = b + A d and c' = other.Evaluate(d).
   */
  template <typename U>
  void AddShifted(const BasicColorQuadric<U>& other, const double d[Dimension])
  {
    double ad[Dimension];
    other.MultiplyA(d, ad);
    const double c = std::max(other.Evaluate(d), 0.0); // as Quadric::AddShifted
    for (int k = 0; k < MatrixSize; ++k)
    {
      this->A[k] = static_cast<T>(this->A[k] + other.A[k]);
    }
    for (int k = 0; k < Dimension; ++k)
    {
      this->B[k] = static_cast<T>(this->B[k] + other.B[k] + ad[k]);
    }
    this->C = static_cast<T>(this->C + c);
  }

  /// Move the centre by s (new centre = old centre + s); Q itself is unchanged.
  void Recentre(const double s[Dimension])
  {
    double as[Dimension];
    this->MultiplyA(s, as);
    const double c = this->Evaluate(s);
    for (int k = 0; k < Dimension; ++k)
    {
      this->B[k] = static_cast<T>(this->B[k] + as[k]);
    }
    this->C = static_cast<T>(c);
  }

  /// Add weight (I - e1 e1^T - e2 e2^T): the plane spanned by e1, e2 through the centre.
  void AddPlaneThroughCentre(const double e1[Dimension], const double e2[Dimension], double weight)
  {
    int k = 0;
    for (int i = 0; i < Dimension; ++i)
    {
      for (int j = i; j < Dimension; ++j, ++k)
      {
        const double identity = i == j ? 1.0 : 0.0;
        this->A[k] =
          static_cast<T>(this->A[k] + weight * (identity - e1[i] * e1[j] - e2[i] * e2[j]));
      }
    }
  }

  /// Add weight n n^T: the squared distance to the hyperplane through the centre with unit
  /// normal n.
  void AddHyperplaneThroughCentre(const double n[Dimension], double weight)
  {
    int k = 0;
    for (int i = 0; i < Dimension; ++i)
    {
      for (int j = i; j < Dimension; ++j, ++k)
      {
        this->A[k] = static_cast<T>(this->A[k] + weight * n[i] * n[j]);
      }
    }
  }

  template <typename U>
  void Assign(const BasicColorQuadric<U>& other)
  {
    for (int k = 0; k < MatrixSize; ++k)
    {
      this->A[k] = static_cast<T>(other.A[k]);
    }
    for (int k = 0; k < Dimension; ++k)
    {
      this->B[k] = static_cast<T>(other.B[k]);
    }
    this->C = static_cast<T>(other.C);
  }
};

/// The per-vertex state of the colour quadric metric: 28 floats, 112 bytes.
using ColorQuadric = BasicColorQuadric<float>;
/// For sums, solves and tests.
using ColorQuadricD = BasicColorQuadric<double>;
static_assert(sizeof(ColorQuadric) == 112, "GH98's 28 floats per vertex");

/**
 * The Gram-Schmidt vectors e1, e2 of the triangle (v1, v2, v3) of R^6 (eq. 10, 11). Returns
 * false when the triangle is degenerate in R^6 (then e1, e2 are not set).
 */
VTKCOLORDECIMATION_EXPORT bool TriangleFrame(const double v1[6], const double v2[6],
                                             const double v3[6], double e1[6], double e2[6]);

/**
 * The (unweighted) quadric of the plane of R^6 through the triangle (v1, v2, v3), in global
 * coordinates (centre at the origin), eq. 12. Returns false, leaving q unchanged, when the
 * triangle is degenerate in R^6.
 */
VTKCOLORDECIMATION_EXPORT bool TriangleColorQuadric(const double v1[6], const double v2[6],
                                                    const double v3[6], ColorQuadricD& q);

/**
 * The minimiser of q: the solution y of A y = -b (an offset from q's centre), by an LDL^T
 * factorisation without pivoting. Returns false, leaving y unset, when A is singular or
 * ill-conditioned: a pivot at or below `tolerance` times the largest diagonal entry of A
 * (A is positive semi-definite, so a small pivot means a direction that the quadric barely
 * constrains).
 */
VTKCOLORDECIMATION_EXPORT bool MinimizeColorQuadric(const ColorQuadricD& q, double y[6],
                                                    double tolerance = 1e-6);

/**
 * The initial colour quadrics of the vertices of `mesh`: for each live triangle, its plane's
 * quadric (eq. 12) weighted by the triangle's area, added to each corner and centred there
 * (so only A is non-zero: the plane passes through every corner). A vertex v's point of R^6
 * is (positionScale * positions[positionStride * v + 0..2], colorScale *
 * colors[colorStride * v + 0..2]); `colors` may be null (colour 0). The area is measured on
 * the scaled positions. With boundaryWeight > 0, each boundary edge also adds, to both its
 * vertices, the quadric of the geometric hyperplane through the edge perpendicular to its
 * triangle (colour components 0), weighted by boundaryWeight times the edge's squared
 * length (Garland and Heckbert's boundary constraint).
 */
VTKCOLORDECIMATION_EXPORT void InitializeColorQuadrics(const HalfEdgeMesh& mesh,
                                                       const float* positions, int positionStride,
                                                       double positionScale, const float* colors,
                                                       int colorStride, double colorScale,
                                                       double boundaryWeight,
                                                       LargeVector<ColorQuadric>& quadrics);

} // namespace colordecimation

#endif
