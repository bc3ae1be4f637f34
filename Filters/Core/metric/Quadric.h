/**
 * @file Quadric.h
 * @brief The geometric error quadric of Garland-Heckbert (paper eq. 3-9), 10 floats.
 *
 * Q(x) = x^T A x + 2 b^T x + c with A symmetric. Each vertex stores its quadric *centred at
 * its own position* p (x is measured from p). A plane through p then has b = 0 and c = 0
 * exactly, and the coefficients stay of the size of local errors, so that single precision
 * storage does not lose the small quadric errors of a million-triangle scan to cancellation
 * against |p|^2-sized terms. Evaluation and accumulation are done in double.
 */
#ifndef colordecimation_Quadric_h
#define colordecimation_Quadric_h

#include <algorithm>
#include <cmath>

namespace colordecimation
{

/**
 * Garland and Heckbert's boundary plane of a boundary edge e (its vector) of a triangle
 * with unit normal n: the plane through the edge perpendicular to the triangle. Writes its
 * unit normal m and its weight, boundaryWeight |e|^2; false when the edge is degenerate.
 */
inline bool BoundaryPlane(const double e[3], const double n[3], double boundaryWeight, double m[3],
                          double& weight)
{
  m[0] = e[1] * n[2] - e[2] * n[1];
  m[1] = e[2] * n[0] - e[0] * n[2];
  m[2] = e[0] * n[1] - e[1] * n[0];
  const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (!(length > 0.0))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    m[i] /= length;
  }
  weight = boundaryWeight * (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  return true;
}

struct Quadric
{
  // A = [a00 a01 a02; a01 a11 a12; a02 a12 a22]
  float A00 = 0, A01 = 0, A02 = 0, A11 = 0, A12 = 0, A22 = 0;
  float B0 = 0, B1 = 0, B2 = 0;
  float C = 0;

  /// Add `weight * n n^T` (a plane through the centre with normal n).
  void AddPlaneThroughCentre(const double n[3], double weight)
  {
    this->A00 = static_cast<float>(this->A00 + weight * n[0] * n[0]);
    this->A01 = static_cast<float>(this->A01 + weight * n[0] * n[1]);
    this->A02 = static_cast<float>(this->A02 + weight * n[0] * n[2]);
    this->A11 = static_cast<float>(this->A11 + weight * n[1] * n[1]);
    this->A12 = static_cast<float>(this->A12 + weight * n[1] * n[2]);
    this->A22 = static_cast<float>(this->A22 + weight * n[2] * n[2]);
  }

  /// Add `weight * I`: weight times the squared distance from the centre.
  void AddIsotropic(double weight)
  {
    this->A00 = static_cast<float>(this->A00 + weight);
    this->A11 = static_cast<float>(this->A11 + weight);
    this->A22 = static_cast<float>(this->A22 + weight);
  }

  /// Q evaluated at offset d from the centre.
  double Evaluate(const double d[3]) const
  {
    const double ad0 = this->A00 * d[0] + this->A01 * d[1] + this->A02 * d[2];
    const double ad1 = this->A01 * d[0] + this->A11 * d[1] + this->A12 * d[2];
    const double ad2 = this->A02 * d[0] + this->A12 * d[1] + this->A22 * d[2];
    return d[0] * ad0 + d[1] * ad1 + d[2] * ad2 +
      2.0 * (this->B0 * d[0] + this->B1 * d[1] + this->B2 * d[2]) + this->C;
  }

  /**
   * Add `other`, centred at p_other, to this quadric, centred at p_this; d = p_this - p_other
   * (this centre in other's frame): other re-centred has b' = b + A d and c' =
   * other.Evaluate(d).
   */
  void AddShifted(const Quadric& other, const double d[3])
  {
    const double ad0 = other.A00 * d[0] + other.A01 * d[1] + other.A02 * d[2];
    const double ad1 = other.A01 * d[0] + other.A11 * d[1] + other.A12 * d[2];
    const double ad2 = other.A02 * d[0] + other.A12 * d[1] + other.A22 * d[2];
    // other(d) >= 0 in exact arithmetic, a hair below 0 if rounded: clamped, C never falls (the
    // premise of the engine's re-costing, see AttributeQuadric::AddShifted).
    const double c = std::max(other.Evaluate(d), 0.0);
    this->A00 += other.A00;
    this->A01 += other.A01;
    this->A02 += other.A02;
    this->A11 += other.A11;
    this->A12 += other.A12;
    this->A22 += other.A22;
    this->B0 = static_cast<float>(this->B0 + other.B0 + ad0);
    this->B1 = static_cast<float>(this->B1 + other.B1 + ad1);
    this->B2 = static_cast<float>(this->B2 + other.B2 + ad2);
    this->C = static_cast<float>(this->C + c);
  }
};

} // namespace colordecimation

#endif
