#include "metric/AttributeQuadric.h"

#include "mesh/FaceWalk.h"
#include "mesh/HalfEdgeMesh.h"
#include "metric/Quadric.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colordecimation
{
double AttributeQuadric::Evaluate(const double dx[3], const double ds[3]) const
{
  const double ax = this->A00 * dx[0] + this->A01 * dx[1] + this->A02 * dx[2];
  const double ay = this->A01 * dx[0] + this->A11 * dx[1] + this->A12 * dx[2];
  const double az = this->A02 * dx[0] + this->A12 * dx[1] + this->A22 * dx[2];
  double q = dx[0] * ax + dx[1] * ay + dx[2] * az + this->C;
  for (int i = 0; i < 3; ++i)
  {
    const double gx = this->G[i][0] * dx[0] + this->G[i][1] * dx[1] + this->G[i][2] * dx[2];
    q += ds[i] * (this->W * ds[i] - 2.0 * gx - 2.0 * this->D[i]) + 2.0 * this->B[i] * dx[i];
  }
  return q;
}

void AttributeQuadric::AddShifted(const AttributeQuadric& other, const double dx[3],
                                  const double ds[3])
{
  // other(y + d): the same quadratic part; B' = B + A dx - sum_k ds_k G_k,
  // D'_k = D_k + G_k . dx - W ds_k, C' = other(d).
  const double ax = other.A00 * dx[0] + other.A01 * dx[1] + other.A02 * dx[2];
  const double ay = other.A01 * dx[0] + other.A11 * dx[1] + other.A12 * dx[2];
  const double az = other.A02 * dx[0] + other.A12 * dx[1] + other.A22 * dx[2];
  double b[3] = { other.B[0] + ax, other.B[1] + ay, other.B[2] + az };
  for (int k = 0; k < 3; ++k)
  {
    for (int i = 0; i < 3; ++i)
    {
      b[i] -= ds[k] * other.G[k][i];
    }
    const double gx = other.G[k][0] * dx[0] + other.G[k][1] * dx[1] + other.G[k][2] * dx[2];
    this->D[k] = static_cast<float>(this->D[k] + other.D[k] + gx - other.W * ds[k]);
    for (int i = 0; i < 3; ++i)
    {
      this->G[k][i] += other.G[k][i];
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    this->B[i] = static_cast<float>(this->B[i] + b[i]);
  }
  // other(d) >= 0 in exact arithmetic; rounded, it can come out a hair below 0 (a flat region,
  // a linear colour). Clamped, C never falls: a collapse never makes its kept vertex cheaper to
  // reach, the premise of the engine's re-costing (ForEachAffected, ChooseNewNeighbor).
  this->C = static_cast<float>(this->C + std::max(other.Evaluate(dx, ds), 0.0));
  this->A00 += other.A00;
  this->A01 += other.A01;
  this->A02 += other.A02;
  this->A11 += other.A11;
  this->A12 += other.A12;
  this->A22 += other.A22;
  this->W += other.W;
}

namespace
{
/// The gradients of the three channels over the triangle (x: corners, s: their colours), by
/// barycentric coordinates; false for a degenerate triangle.
bool ColorGradients(const double x[3][3], const double s[3][3], double g[3][3])
{
  double e1[3], e2[3];
  for (int i = 0; i < 3; ++i)
  {
    e1[i] = x[1][i] - x[0][i];
    e2[i] = x[2][i] - x[0][i];
  }
  const double d00 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
  const double d01 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
  const double d11 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
  const double denom = d00 * d11 - d01 * d01;
  if (!(denom > 0))
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    const double a1 = s[1][k] - s[0][k], a2 = s[2][k] - s[0][k];
    for (int i = 0; i < 3; ++i)
    {
      const double u = (d11 * e1[i] - d01 * e2[i]) / denom; // gradient of the 1st coordinate
      const double v = (d00 * e2[i] - d01 * e1[i]) / denom; // of the 2nd
      g[k][i] = u * a1 + v * a2;
    }
  }
  return true;
}

/// The boundary edges of face f: the plane through each, perpendicular to the face, added to
/// its ends that the walk owns.
void AddBoundaryPlanes(const HalfEdgeMesh& mesh, int32_t f, const int32_t tri[3],
                       const double x[3][3], const double n[3], double boundaryWeight,
                       const FaceWalk& walk, AttributeQuadric* quadrics)
{
  for (int c = 0; c < 3; ++c)
  {
    if (mesh.Twin(3 * f + c) >= 0)
    {
      continue;
    }
    const double* a = x[c];
    const double* b = x[(c + 1) % 3];
    const double e[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    double m[3], weight;
    if (!BoundaryPlane(e, n, boundaryWeight, m, weight))
    {
      continue;
    }
    for (const int32_t v : { tri[c], tri[(c + 1) % 3] })
    {
      if (walk.Owns(v))
      {
        quadrics[v].AddPlane(m, weight);
      }
    }
  }
}

/// Face f's terms added to the quadrics of its corners that the walk owns.
void AddFaceQuadrics(const HalfEdgeMesh& mesh, int32_t f, const float* positions,
                     int positionStride, const float* colors, int colorStride, double colorScale,
                     const AttributeQuadricWeights& weights, const FaceWalk& walk,
                     AttributeQuadric* quadrics)
{
  int32_t tri[3];
  mesh.GetFace(f, tri);
  if (!(walk.Owns(tri[0]) || walk.Owns(tri[1]) || walk.Owns(tri[2])))
  {
    return;
  }
  double x[3][3], s[3][3];
  for (int c = 0; c < 3; ++c)
  {
    for (int k = 0; k < 3; ++k)
    {
      x[c][k] = positions[size_t(positionStride) * tri[c] + k];
      s[c][k] = colors ? colorScale * colors[size_t(colorStride) * tri[c] + k] : 0.0;
    }
  }
  const double e1[3] = { x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2] };
  const double e2[3] = { x[2][0] - x[0][0], x[2][1] - x[0][1], x[2][2] - x[0][2] };
  double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                  e1[0] * e2[1] - e1[1] * e2[0] };
  const double twiceArea = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double g[3][3];
  if (!(twiceArea > 0.0) || !ColorGradients(x, s, g))
  {
    return;
  }
  for (double& component : n)
  {
    component /= twiceArea;
  }
  for (const int32_t v : tri)
  {
    if (walk.Owns(v))
    {
      quadrics[v].AddTriangle(n, g, 0.5 * twiceArea, weights);
    }
  }
  if (weights.Boundary > 0.0)
  {
    AddBoundaryPlanes(mesh, f, tri, x, n, weights.Boundary, walk, quadrics);
  }
}
} // namespace

void InitializeAttributeQuadrics(const HalfEdgeMesh& mesh, const float* positions,
                                 int positionStride, const float* colors, int colorStride,
                                 double colorScale, const AttributeQuadricWeights& weights,
                                 Buffer<AttributeQuadric>& quadrics, int threads)
{
  // Each thread zeroes, then sums, the quadrics of its own range of vertices (mesh/FaceWalk.h).
  quadrics.resize(static_cast<size_t>(mesh.GetNumberOfVertices()));
  AttributeQuadric* q = quadrics.data();
  const HalfEdgeMesh* faces = &mesh;
  const AttributeQuadricWeights w = weights;
  ForEachVertexRange(mesh, threads,
                     [=](const FaceWalk& walk)
                     {
                       std::fill(q + walk.First, q + walk.Last, AttributeQuadric());
                       ForEachLiveFace(*faces, walk,
                                       [&](int32_t f)
                                       {
                                         AddFaceQuadrics(*faces, f, positions, positionStride,
                                                         colors, colorStride, colorScale, w, walk,
                                                         q);
                                       });
                     });
}

AttributeQuadricMetric::AttributeQuadricMetric(const DecimatorOptions& options)
  : GivenColorWeight(std::max(options.ColorWeight, 0.0))
  , GivenBoundaryWeight(std::max(options.BoundaryWeight, 0.0))
  , SceneRelative(options.SceneRelativeWeights)
  , ColorWeight(GivenColorWeight)
  , KeptErrorWeight(std::max(options.KeptVertexErrorWeight, 0.0))
  , Weights{ std::max(options.BoundaryWeight, 0.0), std::max(options.EdgeLengthWeight, 0.0),
             std::max(options.GeometryWeight, 0.0) }
{
}

void AttributeQuadricMetric::Initialize(const HalfEdgeMesh& mesh, const Frame& frame,
                                        Buffer<HotVertex>& hot, bool useColor, int threads)
{
  this->Scale = this->SceneRelative ? SceneWeightScale(frame) : 1.0;
  this->ColorWeight = this->GivenColorWeight * this->Scale;
  this->Weights.Boundary = this->GivenBoundaryWeight * this->Scale * this->Scale;
  this->Hot = &hot;
  this->UseColor = useColor;
  InitializeAttributeQuadrics(mesh, hot.empty() ? nullptr : hot[0].P, HotStride,
                              useColor && !hot.empty() ? hot[0].C : nullptr, HotStride,
                              this->ColorWeight, this->Weights, this->States, threads);
}

void AttributeQuadricMetric::Offset(int32_t v0, int32_t v1, double dx[3], double ds[3]) const
{
  const HotVertex& a = (*this->Hot)[v0];
  const HotVertex& b = (*this->Hot)[v1];
  for (int k = 0; k < 3; ++k)
  {
    dx[k] = double(b.P[k]) - a.P[k];
    ds[k] = this->ColorWeight * (double(b.C[k]) - a.C[k]);
  }
}

namespace
{
/// Q0(xj) + keptWeight * c(j) for every member j of the ring, padded members included (Q(j) is
/// centred at xj: its constant c(j) is all it gives there): one loop without branches over the
/// coefficients held in locals, so that it is vectorised.
COLORDECIMATION_VECTOR_CLONES
void CostAttributeRing(const AttributeQuadric& q0, const HotVertex& hot0, double w,
                       double keptWeight, const Ring& ring, double* costs)
{
  const double a00 = q0.A00, a01 = q0.A01, a02 = q0.A02, a11 = q0.A11, a12 = q0.A12, a22 = q0.A22,
               c = q0.C, qw = q0.W;
  const double g00 = q0.G[0][0], g01 = q0.G[0][1], g02 = q0.G[0][2], g10 = q0.G[1][0],
               g11 = q0.G[1][1], g12 = q0.G[1][2], g20 = q0.G[2][0], g21 = q0.G[2][1],
               g22 = q0.G[2][2];
  const double b0 = q0.B[0], b1 = q0.B[1], b2 = q0.B[2], d0 = q0.D[0], d1 = q0.D[1], d2 = q0.D[2];
  const double px = hot0.P[0], py = hot0.P[1], pz = hot0.P[2];
  const double cr = hot0.C[0], cg = hot0.C[1], cb = hot0.C[2];
  const double* x = ring.X.data();
  const double* y = ring.Y.data();
  const double* z = ring.Z.data();
  const double* r = ring.R.data();
  const double* g = ring.G.data();
  const double* b = ring.B.data();
  const double* qc = ring.QC.data();
  const int n = ring.PaddedSize();
  for (int j = 0; j < n; ++j)
  {
    const double dx = x[j] - px, dy = y[j] - py, dz = z[j] - pz;
    const double sr = w * (r[j] - cr), sg = w * (g[j] - cg), sb = w * (b[j] - cb);
    const double geometric = dx * (a00 * dx + a01 * dy + a02 * dz) +
      dy * (a01 * dx + a11 * dy + a12 * dz) + dz * (a02 * dx + a12 * dy + a22 * dz) +
      2.0 * (b0 * dx + b1 * dy + b2 * dz);
    const double color = sr * (qw * sr - 2.0 * (g00 * dx + g01 * dy + g02 * dz + d0)) +
      sg * (qw * sg - 2.0 * (g10 * dx + g11 * dy + g12 * dz + d1)) +
      sb * (qw * sb - 2.0 * (g20 * dx + g21 * dy + g22 * dz + d2));
    // An overflowed constant (inf) counts as the largest double: 0 * inf would be NaN.
    const double kept = keptWeight * std::min(qc[j], std::numeric_limits<double>::max());
    const double q = geometric + color + c + kept;
    costs[j] = q > 0.0 ? q : 0.0; // std::max(0.0, q), NaN to 0 too
  }
}
} // namespace

void AttributeQuadricMetric::CostRing(int32_t v0, bool, Ring& ring, double* costs, Scratch&) const
{
  CostAttributeRing(this->States[v0], (*this->Hot)[v0], this->ColorWeight, this->KeptErrorWeight,
                    ring, costs);
}

double AttributeQuadricMetric::PieceCost(const int32_t* vertices, size_t count, int32_t& best,
                                         double& spread) const
{
  const int32_t centre = vertices[0];
  AttributeQuadric sum = this->States[centre];
  double dx[3], ds[3];
  // The moments of the area at the points, about the centre: sum W, sum W d, sum W |d|^2.
  double area = 0, first[3] = { 0, 0, 0 }, second = 0;
  for (size_t i = 0; i < count; ++i)
  {
    this->Offset(centre, vertices[i], dx, ds);
    const double w = this->States[vertices[i]].W;
    area += w;
    second += w * (dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
    for (int k = 0; k < 3; ++k)
    {
      first[k] += w * dx[k];
    }
    if (i > 0)
    {
      this->Offset(vertices[i], centre, dx, ds);
      sum.AddShifted(this->States[vertices[i]], dx, ds);
    }
  }
  double least = std::numeric_limits<double>::infinity(), travel = 0;
  best = centre;
  for (size_t i = 0; i < count; ++i)
  {
    this->Offset(centre, vertices[i], dx, ds);
    // sum of W_v |d_v - d|^2 = second - 2 d . first + |d|^2 area
    const double moved = second - 2.0 * (dx[0] * first[0] + dx[1] * first[1] + dx[2] * first[2]) +
      (dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]) * area;
    const double cost =
      std::max(sum.Evaluate(dx, ds), 0.0) + this->Weights.Geometry * std::max(moved, 0.0);
    if (cost < least)
    {
      least = cost;
      best = vertices[i];
      travel = std::max(moved, 0.0);
    }
  }
  spread = area > 0 ? travel / area : 0.0;
  return least;
}

void AttributeQuadricMetric::Merge(int32_t v0, int32_t v1, bool, const Placement&)
{
  double dx[3], ds[3];
  this->Offset(v0, v1, dx, ds);
  AttributeQuadric& q1 = this->States[v1];
  q1.AddShifted(this->States[v0], dx, ds);
  (*this->Hot)[v1].QC = q1.C;
}

} // namespace colordecimation
