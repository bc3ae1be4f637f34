#include "ColorMetric.h"

#include "HalfEdgeMesh.h"

#include <algorithm>

namespace colordecimation
{

double CollapseColorError(const double p0[3], const double c0[3], const Ring& ring, int j)
{
  const double* p1 = &ring.P[3 * j];
  const double* c1 = &ring.C[3 * j];
  double error = 0;
  for (int i = 0; i < ring.Size; ++i)
  {
    const double* pi = &ring.P[3 * i];
    const double* ci = &ring.C[3 * i];
    const double before = Distance3(c0, ci) * Distance3(p0, pi);
    const double after = (i == j) ? 0.0 : Distance3(c1, ci) * Distance3(p1, pi);
    error += std::abs(before - after);
  }
  return error;
}

void CollapseColorErrors(const double p0[3], const double c0[3], Ring& ring, double* errors)
{
  const int n = ring.Size;
  for (int i = 0; i < n; ++i)
  {
    ring.Product[i] = Distance3(c0, &ring.C[3 * i]) * Distance3(p0, &ring.P[3 * i]);
  }
  for (int j = 0; j < n; ++j)
  {
    if (!ring.IsCandidate[j])
    {
      continue;
    }
    const double* p1 = &ring.P[3 * j];
    const double* c1 = &ring.C[3 * j];
    double error = ring.Product[j];
    for (int i = 0; i < n; ++i)
    {
      if (i != j)
      {
        const double after = Distance3(c1, &ring.C[3 * i]) * Distance3(p1, &ring.P[3 * i]);
        error += std::abs(ring.Product[i] - after);
      }
    }
    errors[j] = error;
  }
}

void InitializeVertexMetrics(const HalfEdgeMesh& mesh, const float* positions, const float* colors,
                             std::vector<VertexMetric>& metrics)
{
  const int32_t numVertices = mesh.GetNumberOfVertices();
  metrics.assign(numVertices, VertexMetric());

  // eq. 8: each triangle's plane, weighted by its area, on each of its corners. The plane
  // passes through the corner, where the quadric is centred, so only A is non-zero.
  const int32_t numFaces = mesh.GetNumberOfFaceSlots();
  for (int32_t f = 0; f < numFaces; ++f)
  {
    if (!mesh.IsFaceAlive(f))
    {
      continue;
    }
    const int32_t* tri = mesh.GetFace(f);
    const float* a = positions + 3 * tri[0];
    const float* b = positions + 3 * tri[1];
    const float* c = positions + 3 * tri[2];
    const double e1[3] = { double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2] };
    const double e2[3] = { double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2] };
    double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                    e1[0] * e2[1] - e1[1] * e2[0] };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0))
    {
      continue;
    }
    const double area = 0.5 * length;
    for (double& x : n)
    {
      x /= length;
    }
    for (int k = 0; k < 3; ++k)
    {
      metrics[tri[k]].Q.AddPlaneThroughCentre(n, area);
    }
  }

  if (!colors)
  {
    return;
  }
  // eq. 14: each edge once (a boundary edge has one half-edge, an interior edge two).
  std::vector<double> sum(numVertices, 0.0);
  std::vector<double> maximum(numVertices, 0.0);
  const int32_t numHalfEdges = 3 * numFaces;
  for (int32_t h = 0; h < numHalfEdges; ++h)
  {
    const int32_t twin = mesh.Twin(h);
    if (mesh.Origin(h) < 0 || (twin >= 0 && twin < h))
    {
      continue;
    }
    const int32_t a = mesh.Origin(h);
    const int32_t b = mesh.Target(h);
    const double ca[3] = { colors[3 * a], colors[3 * a + 1], colors[3 * a + 2] };
    const double cb[3] = { colors[3 * b], colors[3 * b + 1], colors[3 * b + 2] };
    const double d = Distance3(ca, cb);
    sum[a] += d;
    sum[b] += d;
    maximum[a] = std::max(maximum[a], d);
    maximum[b] = std::max(maximum[b], d);
  }
  for (int32_t v = 0; v < numVertices; ++v)
  {
    metrics[v].Importance = static_cast<float>(VisualImportance(sum[v], maximum[v]));
    metrics[v].MaxColorDistance = static_cast<float>(maximum[v]);
  }
}

} // namespace colordecimation
