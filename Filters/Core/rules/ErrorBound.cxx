#include "rules/ErrorBound.h"

#include "mesh/FaceWalk.h"
#include "mesh/HalfEdgeMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colordecimation
{

namespace
{
/// Face f's area-weighted plane quadric added to those of its corners that the walk owns.
template <typename PlaneSum>
void AddFacePlane(const HalfEdgeMesh& mesh, const float* positions, int stride, int32_t f,
                  const FaceWalk& walk, PlaneSum* planes)
{
  int32_t ids[3];
  mesh.GetFace(f, ids);
  if (!(walk.Owns(ids[0]) || walk.Owns(ids[1]) || walk.Owns(ids[2])))
  {
    return;
  }
  double p[3][3];
  for (int k = 0; k < 3; ++k)
  {
    std::copy(positions + size_t(stride) * ids[k], positions + size_t(stride) * ids[k] + 3, p[k]);
  }
  const double e1[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
  const double e2[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
  double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                  e1[0] * e2[1] - e1[1] * e2[0] };
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(length > 0.0))
  {
    return; // no plane
  }
  for (double& c : n)
  {
    c /= length;
  }
  const double area = 0.5 * length;
  const double d = -(n[0] * p[0][0] + n[1] * p[0][1] + n[2] * p[0][2]);
  for (const int32_t v : ids)
  {
    if (!walk.Owns(v))
    {
      continue;
    }
    PlaneSum& q = planes[v];
    q.A[0] += area * n[0] * n[0];
    q.A[1] += area * n[0] * n[1];
    q.A[2] += area * n[0] * n[2];
    q.A[3] += area * n[1] * n[1];
    q.A[4] += area * n[1] * n[2];
    q.A[5] += area * n[2] * n[2];
    for (int k = 0; k < 3; ++k)
    {
      q.B[k] += area * d * n[k];
    }
    q.C += area * d * d;
    q.Area += area;
  }
}

/// The mean squared distance q / area of the planes' points: 0 without area or where rounding
/// took q below 0, and the largest double where it is no finite number (the products of huge
/// coordinates overflowed): an error no finite bound admits, which the infinite
/// bound of a record does admit, so that a run with a record makes the collapses a run without
/// one makes, and which the record can hold (its errors are finite).
double MeanSquared(double q, double area)
{
  constexpr double largest = std::numeric_limits<double>::max();
  if (!(area > 0.0))
  {
    return 0.0;
  }
  const double mean = std::max(q, 0.0) / area; // NaN stays NaN
  return mean <= largest ? mean : largest;
}
} // namespace

void ErrorBound::Initialize(const HalfEdgeMesh& mesh, const float* positions, int stride,
                            double bound, int threads)
{
  this->Bound = bound > 0.0 ? bound : 0.0;
  this->Planes = Buffer<PlaneSum>();
  if (!this->IsEnabled())
  {
    return;
  }
  // Each thread zeroes, then sums, the planes of its own range of vertices (mesh/FaceWalk.h).
  const size_t n = static_cast<size_t>(mesh.GetNumberOfVertices());
  this->Planes.resize(n);
  PlaneSum* planes = this->Planes.data();
  const HalfEdgeMesh* faces = &mesh;
  ForEachVertexRange(
    mesh, threads,
    [planes, faces, positions, stride](const FaceWalk& walk)
    {
      std::fill(planes + walk.First, planes + walk.Last, PlaneSum{});
      ForEachLiveFace(*faces, walk,
                      [&](int32_t f) { AddFacePlane(*faces, positions, stride, f, walk, planes); });
    });
}

void ErrorBound::PlaneSum::Add(const PlaneSum& other)
{
  for (int k = 0; k < 6; ++k)
  {
    this->A[k] += other.A[k];
  }
  for (int k = 0; k < 3; ++k)
  {
    this->B[k] += other.B[k];
  }
  this->C += other.C;
  this->Area += other.Area;
}

double ErrorBound::PlaneSum::Mean(const double x[3]) const
{
  const double* a = this->A;
  const double ax0 = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
  const double ax1 = a[1] * x[0] + a[3] * x[1] + a[4] * x[2];
  const double ax2 = a[2] * x[0] + a[4] * x[1] + a[5] * x[2];
  const double q = x[0] * ax0 + x[1] * ax1 + x[2] * ax2 +
    2.0 * (this->B[0] * x[0] + this->B[1] * x[1] + this->B[2] * x[2]) + this->C;
  return MeanSquared(q, this->Area);
}

double ErrorBound::SquaredError(int32_t v0, int32_t v1, const double x[3]) const
{
  // The two plane sums evaluated in one expression, without a temporary sum: the order of its
  // additions fixes the rounding of the bound's decisions.
  const PlaneSum& q0 = this->Planes[v0];
  const PlaneSum& q1 = this->Planes[v1];
  double a[6];
  for (int k = 0; k < 6; ++k)
  {
    a[k] = q0.A[k] + q1.A[k];
  }
  const double ax0 = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
  const double ax1 = a[1] * x[0] + a[3] * x[1] + a[4] * x[2];
  const double ax2 = a[2] * x[0] + a[4] * x[1] + a[5] * x[2];
  const double q = x[0] * ax0 + x[1] * ax1 + x[2] * ax2 +
    2.0 * ((q0.B[0] + q1.B[0]) * x[0] + (q0.B[1] + q1.B[1]) * x[1] + (q0.B[2] + q1.B[2]) * x[2]) +
    q0.C + q1.C;
  return MeanSquared(q, q0.Area + q1.Area);
}

double ErrorBound::PieceSquaredError(const int32_t* vertices, size_t count, const double x[3]) const
{
  PlaneSum sum{};
  for (size_t i = 0; i < count; ++i)
  {
    sum.Add(this->Planes[vertices[i]]);
  }
  return sum.Mean(x);
}

void ErrorBound::Merge(int32_t v0, int32_t v1)
{
  this->Planes[v1].Add(this->Planes[v0]);
}

} // namespace colordecimation
