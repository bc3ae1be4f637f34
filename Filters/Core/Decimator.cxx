#include "Decimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colordecimation
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

CollapseRuleOptions MakeRuleOptions(const DecimatorOptions& options)
{
  CollapseRuleOptions rules;
  rules.PreserveBoundary = options.PreserveBoundary;
  const double angle = std::min(std::max(options.MaximumNormalAngle, 0.0), 180.0);
  rules.MinimumNormalCosine = std::cos(angle * Pi / 180.0);
  return rules;
}
} // namespace

Decimator::Decimator(const DecimatorOptions& options)
  : Options(options)
  , Rules(MakeRuleOptions(options))
{
}

DecimatorStatistics Decimator::Run(const DecimatorInput& input, int64_t targetTriangles,
                                   const std::function<bool(double)>& progress)
{
  DecimatorStatistics stats;
  const int32_t n = input.NumberOfPoints;
  stats.InputTriangles = input.NumberOfTriangles;
  stats.TargetTriangles = std::max<int64_t>(targetTriangles, 0);

  // 1. Connectivity.
  stats.Build = this->Mesh.Build(n, input.Triangles, input.NumberOfTriangles);
  if (input.Fixed)
  {
    for (int32_t v = 0; v < n; ++v)
    {
      if (input.Fixed[v])
      {
        this->Mesh.Lock(v);
      }
    }
  }

  // 2. The normalised frame: bounding-box centre, mean edge length 1.
  double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
  for (int32_t v = 0; v < n; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double x = input.Points[3 * v + k];
      lo[k] = (v == 0 || x < lo[k]) ? x : lo[k];
      hi[k] = (v == 0 || x > hi[k]) ? x : hi[k];
    }
  }
  double edgeSum = 0;
  int64_t edgeCount = 0;
  for (int32_t h = 0; h < 3 * input.NumberOfTriangles; ++h)
  {
    const int32_t twin = this->Mesh.Twin(h);
    if (twin >= 0 && twin < h)
    {
      continue; // each interior edge once
    }
    const double* a = input.Points + 3 * this->Mesh.Origin(h);
    const double* b = input.Points + 3 * this->Mesh.Target(h);
    edgeSum += Distance3(a, b);
    ++edgeCount;
  }
  stats.MeanEdgeLength = edgeCount ? edgeSum / edgeCount : 0.0;
  const double scale = (stats.MeanEdgeLength > 0 && std::isfinite(stats.MeanEdgeLength))
    ? 1.0 / stats.MeanEdgeLength
    : 1.0;
  this->P.resize(3 * static_cast<size_t>(n));
  for (int32_t v = 0; v < n; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double centre = 0.5 * (lo[k] + hi[k]);
      this->P[3 * v + k] = static_cast<float>((input.Points[3 * v + k] - centre) * scale);
    }
  }
  this->Colors = this->Options.Metric == ErrorMetric::Geometry ? nullptr : input.Colors;

  // 3. Per-vertex metric state.
  InitializeVertexMetrics(this->Mesh, this->P.data(), this->Colors, this->Metrics);

  // 4. Initial costs.
  this->Heap.Reset(n);
  this->Best.assign(n, -1);
  for (int32_t v = 0; v < n; ++v)
  {
    this->Update(v);
  }

  // 5. Collapse.
  const int64_t toRemove =
    std::max<int64_t>(this->Mesh.GetNumberOfLiveFaces() - stats.TargetTriangles, 1);
  const int64_t startFaces = this->Mesh.GetNumberOfLiveFaces();
  int64_t nextReport = 0;
  while (this->Mesh.GetNumberOfLiveFaces() > stats.TargetTriangles && !this->Heap.Empty())
  {
    const int32_t v0 = this->Heap.Top();
    const int32_t v1 = this->Best[v0];
    if (!this->Rules.IsLegal(this->Mesh, this->P.data(), v0, v1))
    {
      ++stats.RejectedPops;
      const Choice legal = this->Evaluate(v0, true);
      if (legal.Target < 0)
      {
        this->Heap.Remove(v0);
      }
      else
      {
        this->Best[v0] = legal.Target;
        this->Heap.Set(v0, legal.Cost);
      }
      continue;
    }
    this->Heap.Pop();

    // eq. 9 and 15: v1 takes over v0's quadric and importance.
    VertexMetric& m0 = this->Metrics[v0];
    VertexMetric& m1 = this->Metrics[v1];
    const double d[3] = { double(this->P[3 * v1]) - this->P[3 * v0],
                          double(this->P[3 * v1 + 1]) - this->P[3 * v0 + 1],
                          double(this->P[3 * v1 + 2]) - this->P[3 * v0 + 2] };
    m1.Q.AddShifted(m0.Q, d);
    m1.Importance += m0.Importance;
    m1.MaxColorDistance = std::max(m1.MaxColorDistance, m0.MaxColorDistance);

    this->Mesh.Collapse(v0, v1);
    ++stats.Collapses;
    this->Best[v0] = -1;

    // Re-cost v1 and its new 1-ring: their outgoing half-edges changed.
    this->Update(v1);
    this->Mesh.ForEachNeighbor(v1, [this](int32_t u) { this->Update(u); });

    if (progress && stats.Collapses >= nextReport)
    {
      nextReport = stats.Collapses + 8192;
      const double done = double(startFaces - this->Mesh.GetNumberOfLiveFaces()) / toRemove;
      if (!progress(std::min(done, 1.0)))
      {
        stats.Aborted = true;
        break;
      }
    }
  }
  stats.OutputTriangles = this->Mesh.GetNumberOfLiveFaces();
  stats.StateBytes =
    24 * size_t(input.NumberOfTriangles) + size_t(n) * (5 + 12 + sizeof(VertexMetric) + 16 + 4);
  return stats;
}

void Decimator::Update(int32_t v)
{
  if (this->Mesh.IsLocked(v) || this->Mesh.IsRemoved(v))
  {
    return;
  }
  const Choice best = this->Evaluate(v, false);
  if (best.Target < 0)
  {
    this->Heap.Remove(v);
    return;
  }
  this->Best[v] = best.Target;
  this->Heap.Set(v, best.Cost);
}

void Decimator::GatherRing(int32_t v0)
{
  Ring& ring = this->CurrentRing;
  ring.Clear();
  const bool boundary = this->Mesh.IsBoundaryVertex(v0);
  static const double black[3] = { 0, 0, 0 };
  this->Mesh.ForEachNeighbor(
    v0,
    [&](int32_t u)
    {
      const double p[3] = { this->P[3 * u], this->P[3 * u + 1], this->P[3 * u + 2] };
      double c[3] = { 0, 0, 0 };
      if (this->Colors)
      {
        c[0] = this->Colors[3 * u];
        c[1] = this->Colors[3 * u + 1];
        c[2] = this->Colors[3 * u + 2];
      }
      // A boundary vertex only collapses along its boundary: to the first or last neighbour.
      const bool candidate = !this->Mesh.IsLocked(u) && (!boundary || ring.Size == 0);
      ring.Add(u, p, this->Colors ? c : black, candidate);
    });
  if (boundary && ring.Size > 0)
  {
    ring.IsCandidate[ring.Size - 1] = !this->Mesh.IsLocked(ring.Vertex[ring.Size - 1]);
  }
}

void Decimator::CostRing(int32_t v0)
{
  Ring& ring = this->CurrentRing;
  if (this->Costs.size() < static_cast<size_t>(ring.Size))
  {
    this->Costs.resize(2 * ring.Size);
  }
  const double p0[3] = { this->P[3 * v0], this->P[3 * v0 + 1], this->P[3 * v0 + 2] };
  const VertexMetric& m0 = this->Metrics[v0];
  const bool useColor = this->Options.Metric == ErrorMetric::HalfEdgeColor;
  if (useColor)
  {
    double c0[3] = { 0, 0, 0 };
    if (this->Colors)
    {
      c0[0] = this->Colors[3 * v0];
      c0[1] = this->Colors[3 * v0 + 1];
      c0[2] = this->Colors[3 * v0 + 2];
    }
    CollapseColorErrors(p0, c0, ring, this->Costs.data());
  }
  for (int j = 0; j < ring.Size; ++j)
  {
    if (!ring.IsCandidate[j])
    {
      continue;
    }
    const double d[3] = { ring.P[3 * j] - p0[0], ring.P[3 * j + 1] - p0[1],
                          ring.P[3 * j + 2] - p0[2] };
    const double q = this->Options.GeometryWeight *
      std::max(0.0, m0.Q.Evaluate(d) + double(this->Metrics[ring.Vertex[j]].Q.C));
    this->Costs[j] = useColor ? TotalCost(q, m0.Importance, this->Costs[j]) : q;
  }
}

Decimator::Choice Decimator::Evaluate(int32_t v0, bool exact)
{
  Choice choice;
  if (!this->Mesh.IsCollapsible(v0) ||
      (this->Options.PreserveBoundary && this->Mesh.IsBoundaryVertex(v0)))
  {
    return choice;
  }
  this->GatherRing(v0);
  this->CostRing(v0);
  const Ring& ring = this->CurrentRing;
  if (!exact)
  {
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < ring.Size; ++j)
    {
      if (ring.IsCandidate[j] && this->Costs[j] < best)
      {
        best = this->Costs[j];
        choice.Target = ring.Vertex[j];
      }
    }
    choice.Cost = best;
    return choice;
  }
  this->Order.clear();
  for (int j = 0; j < ring.Size; ++j)
  {
    if (ring.IsCandidate[j])
    {
      this->Order.push_back(j);
    }
  }
  std::sort(this->Order.begin(), this->Order.end(),
            [this](int a, int b) { return this->Costs[a] < this->Costs[b]; });
  for (int j : this->Order)
  {
    if (this->Rules.IsLegal(this->Mesh, this->P.data(), v0, ring.Vertex[j]))
    {
      choice.Target = ring.Vertex[j];
      choice.Cost = this->Costs[j];
      break;
    }
  }
  return choice;
}

double Decimator::CollapseCost(int32_t v0, int32_t v1)
{
  if (!this->Mesh.IsCollapsible(v0))
  {
    return -1;
  }
  this->GatherRing(v0);
  for (int j = 0; j < this->CurrentRing.Size; ++j)
  {
    this->CurrentRing.IsCandidate[j] = this->CurrentRing.Vertex[j] == v1;
  }
  this->CostRing(v0);
  for (int j = 0; j < this->CurrentRing.Size; ++j)
  {
    if (this->CurrentRing.Vertex[j] == v1)
    {
      return this->Costs[j];
    }
  }
  return -1;
}

} // namespace colordecimation
