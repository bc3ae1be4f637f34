#include "metric/ColorQuadric.h"

#include "mesh/HalfEdgeMesh.h"
#include "metric/Quadric.h"

#include <algorithm>
#include <cmath>

namespace colordecimation
{
namespace
{
constexpr int N = 6;

double Dot(const double* a, const double* b)
{
  double sum = 0.0;
  for (int k = 0; k < N; ++k)
  {
    sum += a[k] * b[k];
  }
  return sum;
}

/// e1, e2 from the edge vectors d2 = v2 - v1 and d3 = v3 - v1.
bool FrameFromEdges(const double d2[N], const double d3[N], double e1[N], double e2[N])
{
  const double l2 = std::sqrt(Dot(d2, d2));
  if (!(l2 > 0.0))
  {
    return false;
  }
  for (int k = 0; k < N; ++k)
  {
    e1[k] = d2[k] / l2;
  }
  const double along = Dot(e1, d3);
  double u[N];
  for (int k = 0; k < N; ++k)
  {
    u[k] = d3[k] - along * e1[k];
  }
  const double lu = std::sqrt(Dot(u, u));
  // Collinear corners (up to rounding of the subtraction above): no plane.
  if (!(lu > 1e-12 * std::sqrt(Dot(d3, d3))) || !(lu > 0.0))
  {
    return false;
  }
  for (int k = 0; k < N; ++k)
  {
    e2[k] = u[k] / lu;
  }
  return true;
}
} // namespace

bool TriangleFrame(const double v1[6], const double v2[6], const double v3[6], double e1[6],
                   double e2[6])
{
  double d2[N], d3[N];
  for (int k = 0; k < N; ++k)
  {
    d2[k] = v2[k] - v1[k];
    d3[k] = v3[k] - v1[k];
  }
  return FrameFromEdges(d2, d3, e1, e2);
}

bool TriangleColorQuadric(const double v1[6], const double v2[6], const double v3[6],
                          ColorQuadricD& q)
{
  double e1[N], e2[N];
  if (!TriangleFrame(v1, v2, v3, e1, e2))
  {
    return false;
  }
  q = ColorQuadricD();
  q.AddPlaneThroughCentre(e1, e2, 1.0);
  const double p1 = Dot(v1, e1);
  const double p2 = Dot(v1, e2);
  for (int k = 0; k < N; ++k)
  {
    q.B[k] = p1 * e1[k] + p2 * e2[k] - v1[k];
  }
  q.C = Dot(v1, v1) - p1 * p1 - p2 * p2;
  return true;
}

bool MinimizeColorQuadric(const ColorQuadricD& q, double y[6], double tolerance)
{
  // LDL^T of A (A symmetric positive semi-definite): L unit lower triangular, D diagonal.
  double l[N][N] = {};
  double d[N];
  double largest = 0.0;
  for (int i = 0; i < N; ++i)
  {
    largest = std::max(largest, std::abs(q.GetA(i, i)));
  }
  if (!(largest > 0.0) || !std::isfinite(largest))
  {
    return false;
  }
  const double floor = tolerance * largest;
  for (int j = 0; j < N; ++j)
  {
    double dj = q.GetA(j, j);
    for (int k = 0; k < j; ++k)
    {
      dj -= l[j][k] * l[j][k] * d[k];
    }
    if (!(dj > floor))
    {
      return false;
    }
    d[j] = dj;
    for (int i = j + 1; i < N; ++i)
    {
      double s = q.GetA(i, j);
      for (int k = 0; k < j; ++k)
      {
        s -= l[i][k] * l[j][k] * d[k];
      }
      l[i][j] = s / dj;
    }
  }
  // L z = -b, D w = z, L^T y = w.
  double z[N];
  for (int i = 0; i < N; ++i)
  {
    double s = -q.B[i];
    for (int k = 0; k < i; ++k)
    {
      s -= l[i][k] * z[k];
    }
    z[i] = s;
  }
  for (int i = N - 1; i >= 0; --i)
  {
    double s = z[i] / d[i];
    for (int k = i + 1; k < N; ++k)
    {
      s -= l[k][i] * y[k];
    }
    y[i] = s;
  }
  for (int i = 0; i < N; ++i)
  {
    if (!std::isfinite(y[i]))
    {
      return false;
    }
  }
  return true;
}

namespace
{
/// The boundary edges of face f (corners x, normal n in the geometric part): the hyperplane
/// through each edge, perpendicular to the face, added to both its ends.
void AddBoundaryPlanes(const HalfEdgeMesh& mesh, int32_t f, const int32_t tri[3],
                       const double x[3][N], const double n[3], double boundaryWeight,
                       LargeVector<ColorQuadric>& quadrics)
{
  for (int c = 0; c < 3; ++c)
  {
    const int32_t h = 3 * f + c;
    if (mesh.Twin(h) >= 0)
    {
      continue;
    }
    const double* a = x[c];
    const double* b = x[(c + 1) % 3];
    const double e[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    double m[N] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 }; // no colour part
    double weight;
    if (!BoundaryPlane(e, n, boundaryWeight, m, weight))
    {
      continue;
    }
    ColorQuadric constraint;
    constraint.AddHyperplaneThroughCentre(m, weight);
    quadrics[tri[c]].Add(constraint);
    quadrics[tri[(c + 1) % 3]].Add(constraint);
  }
}
} // namespace

void InitializeColorQuadrics(const HalfEdgeMesh& mesh, const float* positions, int positionStride,
                             double positionScale, const float* colors, int colorStride,
                             double colorScale, double boundaryWeight,
                             LargeVector<ColorQuadric>& quadrics)
{
  quadrics.assign(mesh.GetNumberOfVertices(), ColorQuadric());
  auto point = [&](int32_t v, double x[N])
  {
    const float* p = positions + static_cast<size_t>(positionStride) * v;
    for (int k = 0; k < 3; ++k)
    {
      x[k] = positionScale * p[k];
    }
    for (int k = 0; k < 3; ++k)
    {
      x[3 + k] = colors ? colorScale * colors[static_cast<size_t>(colorStride) * v + k] : 0.0;
    }
  };
  const int32_t numFaces = mesh.GetNumberOfFaceSlots();
  for (int32_t f = 0; f < numFaces; ++f)
  {
    if (!mesh.IsFaceAlive(f))
    {
      continue;
    }
    int32_t tri[3];
    mesh.GetFace(f, tri);
    double x[3][N];
    for (int c = 0; c < 3; ++c)
    {
      point(tri[c], x[c]);
    }
    double d2[N], d3[N];
    for (int k = 0; k < N; ++k)
    {
      d2[k] = x[1][k] - x[0][k];
      d3[k] = x[2][k] - x[0][k];
    }
    const double n[3] = { d2[1] * d3[2] - d2[2] * d3[1], d2[2] * d3[0] - d2[0] * d3[2],
                          d2[0] * d3[1] - d2[1] * d3[0] };
    const double twiceArea = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double e1[N], e2[N];
    if (!(twiceArea > 0.0) || !FrameFromEdges(d2, d3, e1, e2))
    {
      continue;
    }
    ColorQuadric q;
    q.AddPlaneThroughCentre(e1, e2, 0.5 * twiceArea);
    for (int c = 0; c < 3; ++c)
    {
      quadrics[tri[c]].Add(q);
    }
    if (boundaryWeight > 0.0)
    {
      AddBoundaryPlanes(mesh, f, tri, x, n, boundaryWeight, quadrics);
    }
  }
}

} // namespace colordecimation
