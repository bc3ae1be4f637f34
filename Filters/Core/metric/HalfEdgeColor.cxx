#include "metric/HalfEdgeColor.h"

#include "mesh/FaceWalk.h"
#include "mesh/HalfEdgeMesh.h"

#include <algorithm>

namespace colordecimation
{

double CollapseColorError(const double p0[3], const double c0[3], const Ring& ring, int j)
{
  double p1[3], c1[3];
  ring.GetPosition(j, p1);
  ring.GetColor(j, c1);
  double error = 0;
  for (int i = 0; i < ring.Size; ++i)
  {
    double pi[3], ci[3];
    ring.GetPosition(i, pi);
    ring.GetColor(i, ci);
    const double before = ColorLengthProduct(c0, ci, p0, pi);
    const double after = (i == j) ? 0.0 : ColorLengthProduct(c1, ci, p1, pi);
    error += std::abs(before - after);
  }
  return error;
}

COLORDECIMATION_VECTOR_CLONES
void CollapseColorErrors(const double p0[3], const double c0[3], Ring& ring, double* errors)
{
  const int n = ring.Size;
  const int padded = ring.PaddedSize();
  const double* x = ring.X.data();
  const double* y = ring.Y.data();
  const double* z = ring.Z.data();
  const double* r = ring.R.data();
  const double* g = ring.G.data();
  const double* b = ring.B.data();
  double* product = ring.Product.data();
  // In locals, which the stores below cannot change (so that the loop is vectorised).
  const double px = p0[0], py = p0[1], pz = p0[2], cr = c0[0], cg = c0[1], cb = c0[2];
  for (int i = 0; i < padded; ++i)
  {
    const double dx = x[i] - px, dy = y[i] - py, dz = z[i] - pz;
    const double dr = r[i] - cr, dg = g[i] - cg, db = b[i] - cb;
    product[i] = std::sqrt((dr * dr + dg * dg + db * db) * (dx * dx + dy * dy + dz * dz));
  }
  std::fill(errors, errors + padded, 0.0);
  // errors[j] = sum over i of |product[i] - after(i, j)|, after(i, j) being the colour-length
  // product of i and j (0 for i = j, where the differences are zero). Row by row, each row a
  // vectorised loop over every j (padded entries included, whose results are not read): every
  // errors[j] sums its terms in the order of i, as the plain loop of CollapseColorError does,
  // and after(i, j) has the same bits as after(j, i) (the differences only change sign).
  for (int i = 0; i < n; ++i)
  {
    const double xi = x[i], yi = y[i], zi = z[i], ri = r[i], gi = g[i], bi = b[i];
    const double before = product[i];
    for (int k = 0; k < padded; ++k)
    {
      const double dx = x[k] - xi, dy = y[k] - yi, dz = z[k] - zi;
      const double dr = r[k] - ri, dg = g[k] - gi, db = b[k] - bi;
      const double after = std::sqrt((dr * dr + dg * dg + db * db) * (dx * dx + dy * dy + dz * dz));
      errors[k] += std::abs(before - after);
    }
  }
}

namespace
{
/// The weights of the terms a face adds besides its plane.
struct QuadricWeights
{
  double Boundary;   ///< of the boundary planes
  double EdgeLength; ///< of the isotropic edge-length term
};

/// The plane terms of face f (eq. 8, and the boundary planes) added to those of its corners
/// that the walk owns.
void AddFacePlanes(const HalfEdgeMesh& mesh, const float* positions, int positionStride,
                   const QuadricWeights& weights, int32_t f, const FaceWalk& walk,
                   VertexMetric* metrics)
{
  int32_t tri[3];
  mesh.GetFace(f, tri);
  const auto owned = [&walk](int32_t v) { return walk.Owns(v); };
  if (!owned(tri[0]) && !owned(tri[1]) && !owned(tri[2]))
  {
    return;
  }
  const float* a = positions + positionStride * tri[0];
  const float* b = positions + positionStride * tri[1];
  const float* c = positions + positionStride * tri[2];
  const double e1[3] = { double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2] };
  const double e2[3] = { double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2] };
  double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                  e1[0] * e2[1] - e1[1] * e2[0] };
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(length > 0))
  {
    return;
  }
  const double area = 0.5 * length;
  for (double& x : n)
  {
    x /= length;
  }
  // The plane passes through the corner, where the quadric is centred: only A is non-zero.
  // The edge-length term, weight times the area times the squared distance from the corner.
  for (int k = 0; k < 3; ++k)
  {
    if (owned(tri[k]))
    {
      metrics[tri[k]].Q.AddPlaneThroughCentre(n, area);
      if (weights.EdgeLength > 0)
      {
        metrics[tri[k]].Q.AddIsotropic(weights.EdgeLength * area);
      }
    }
  }
  const double boundaryWeight = weights.Boundary;
  if (!(boundaryWeight > 0))
  {
    return;
  }
  // Boundary edges: the plane through the edge, perpendicular to the triangle.
  const float* corner[3] = { a, b, c };
  for (int k = 0; k < 3; ++k)
  {
    if (mesh.Twin(3 * f + k) >= 0)
    {
      continue;
    }
    const float* p = corner[k];
    const float* q = corner[(k + 1) % 3];
    const double e[3] = { double(q[0]) - p[0], double(q[1]) - p[1], double(q[2]) - p[2] };
    double m[3], w;
    if (!BoundaryPlane(e, n, boundaryWeight, m, w))
    {
      continue;
    }
    for (const int32_t v : { tri[k], tri[(k + 1) % 3] })
    {
      if (owned(v))
      {
        metrics[v].Q.AddPlaneThroughCentre(m, w);
      }
    }
  }
}
/// eq. 8: each triangle's plane, weighted by its area, on each of its corners it owns.
void AddAllFacePlanes(const HalfEdgeMesh& mesh, const float* positions, int positionStride,
                      const QuadricWeights& weights, const FaceWalk& walk, VertexMetric* state)
{
  ForEachLiveFace(mesh, walk,
                  [&](int32_t f)
                  { AddFacePlanes(mesh, positions, positionStride, weights, f, walk, state); });
}

/// eq. 14: each edge once (a boundary edge has one half-edge, an interior edge two); the sum
/// and the maximum kept in double until the end.
void AddVisualImportance(const HalfEdgeMesh& mesh, const float* colors, int colorStride,
                         const FaceWalk& walk, VertexMetric* state)
{
  const int32_t first = walk.First, last = walk.Last;
  const int32_t numHalfEdges = 3 * walk.NumFaces;
  std::vector<double> sum(size_t(last - first), 0.0), maximum(size_t(last - first), 0.0);
  for (int32_t h = 0; h < numHalfEdges; ++h)
  {
    if (h % 3 == 0)
    {
      const int32_t f = walk.From(h / 3);
      if (f == walk.NumFaces)
      {
        break;
      }
      h = 3 * f;
    }
    const int32_t twin = mesh.Twin(h);
    const int32_t a = mesh.Origin(h);
    if (a < 0 || (twin >= 0 && twin < h))
    {
      continue;
    }
    const int32_t b = mesh.Target(h);
    const bool ownsA = a >= first && a < last, ownsB = b >= first && b < last;
    if (!ownsA && !ownsB)
    {
      continue;
    }
    const float* fa = colors + colorStride * a;
    const float* fb = colors + colorStride * b;
    const double ca[3] = { fa[0], fa[1], fa[2] };
    const double cb[3] = { fb[0], fb[1], fb[2] };
    const double d = Distance3(ca, cb);
    for (const int32_t v : { a, b })
    {
      if (v >= first && v < last)
      {
        sum[v - first] += d;
        maximum[v - first] = std::max(maximum[v - first], d);
      }
    }
  }
  for (int32_t v = first; v < last; ++v)
  {
    state[v].Importance = static_cast<float>(VisualImportance(sum[v - first], maximum[v - first]));
    state[v].MaxColorDistance = static_cast<float>(maximum[v - first]);
  }
}
} // namespace

void InitializeVertexMetrics(const HalfEdgeMesh& mesh, const float* positions, const float* colors,
                             VertexMetric* state, int positionStride, int colorStride,
                             double boundaryWeight, int threads, double edgeLengthWeight)
{
  const QuadricWeights weights{ boundaryWeight, edgeLengthWeight };
  // Each thread sums the terms of its own range of vertices (mesh/FaceWalk.h).
  const HalfEdgeMesh* faces = &mesh;
  ForEachVertexRange(
    mesh, threads,
    [faces, positions, colors, state, positionStride, colorStride, weights](const FaceWalk& walk)
    {
      std::fill(state + walk.First, state + walk.Last, VertexMetric());
      AddAllFacePlanes(*faces, positions, positionStride, weights, walk, state);
      if (colors)
      {
        AddVisualImportance(*faces, colors, colorStride, walk, state);
      }
    });
}

void InitializeVertexMetrics(const HalfEdgeMesh& mesh, const float* positions, const float* colors,
                             std::vector<VertexMetric>& metrics, int positionStride,
                             int colorStride, double boundaryWeight, int threads,
                             double edgeLengthWeight)
{
  metrics.resize(static_cast<size_t>(mesh.GetNumberOfVertices()));
  InitializeVertexMetrics(mesh, positions, colors, metrics.data(), positionStride, colorStride,
                          boundaryWeight, threads, edgeLengthWeight);
}

bool ColorsVary(const Buffer<HotVertex>& hot)
{
  for (size_t v = 1; v < hot.size(); ++v)
  {
    if (hot[v].C[0] != hot[0].C[0] || hot[v].C[1] != hot[0].C[1] || hot[v].C[2] != hot[0].C[2])
    {
      return true;
    }
  }
  return false;
}

COLORDECIMATION_VECTOR_CLONES
void CostHalfEdgeRing(const HotVertex& hot0, const VertexMetric& m0, double weight, bool colorTerms,
                      bool withColorError, Ring& ring, double* costs)
{
  const int n = ring.PaddedSize();
  const double p0[3] = { hot0.P[0], hot0.P[1], hot0.P[2] };
  if (colorTerms && withColorError)
  {
    const double c0[3] = { hot0.C[0], hot0.C[1], hot0.C[2] };
    CollapseColorErrors(p0, c0, ring, costs);
  }
  else if (colorTerms)
  {
    std::fill(costs, costs + n, 0.0); // C >= 0: (1 + Q)(1 + I) bounds the cost from below
  }
  // (Q(v0) + Q(j))(pj): Q(v0) is centred at p0, Q(j) at pj (so it contributes its constant).
  const Quadric& q0 = m0.Q;
  const double a00 = q0.A00, a01 = q0.A01, a02 = q0.A02, a11 = q0.A11, a12 = q0.A12, a22 = q0.A22,
               b0 = q0.B0, b1 = q0.B1, b2 = q0.B2, c = q0.C;
  const double importance = m0.Importance;
  const double* x = ring.X.data();
  const double* y = ring.Y.data();
  const double* z = ring.Z.data();
  const double* qc = ring.QC.data();
  const auto quadricError = [=](int j)
  {
    const double dx = x[j] - p0[0], dy = y[j] - p0[1], dz = z[j] - p0[2];
    const double quadric = dx * (a00 * dx + a01 * dy + a02 * dz) +
      dy * (a01 * dx + a11 * dy + a12 * dz) + dz * (a02 * dx + a12 * dy + a22 * dz) +
      2.0 * (b0 * dx + b1 * dy + b2 * dz) + c + qc[j];
    return weight * (quadric > 0.0 ? quadric : 0.0); // std::max(0.0, quadric), NaN to 0 too
  };
  // Two loops without branches, so that each is vectorised.
  if (colorTerms)
  {
    for (int j = 0; j < n; ++j)
    {
      costs[j] = TotalCost(quadricError(j), importance, costs[j]);
    }
  }
  else
  {
    for (int j = 0; j < n; ++j)
    {
      costs[j] = quadricError(j);
    }
  }
}

} // namespace colordecimation
