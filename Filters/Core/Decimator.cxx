#include "Decimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colordecimation
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double MaximumDriftAngle = 75.0; ///< degrees

CollapseRuleOptions MakeRuleOptions(const DecimatorOptions& options)
{
  CollapseRuleOptions rules;
  rules.PreserveBoundary = options.PreserveBoundary;
  const double angle = std::min(std::max(options.MaximumNormalAngle, 0.0), 180.0);
  rules.MinimumNormalCosine = std::cos(angle * Pi / 180.0);
  // Total drift from the input triangle's normal: at most 75 degrees (or the per-collapse
  // angle if smaller), so that no triangle comes to face away from the input surface; none
  // when the guard is switched off (180 degrees).
  rules.MinimumDriftCosine =
    angle >= 180.0 ? -1.0 : std::cos(std::min(angle, MaximumDriftAngle) * Pi / 180.0);
  return rules;
}
} // namespace

Decimator::Decimator(const DecimatorOptions& options)
  : Options(options)
  , Rules(MakeRuleOptions(options))
{
}

std::vector<float> Decimator::GetNormalizedPositions() const
{
  std::vector<float> positions(3 * this->Hot.size());
  for (size_t v = 0; v < this->Hot.size(); ++v)
  {
    std::copy(this->Hot[v].P, this->Hot[v].P + 3, positions.begin() + 3 * v);
  }
  return positions;
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
  this->UseColor = this->Options.Metric == ErrorMetric::HalfEdgeColor && input.Colors;
  this->Hot.resize(n);
  for (int32_t v = 0; v < n; ++v)
  {
    HotVertex& hot = this->Hot[v];
    for (int k = 0; k < 3; ++k)
    {
      const double centre = 0.5 * (lo[k] + hi[k]);
      hot.P[k] = static_cast<float>((input.Points[3 * v + k] - centre) * scale);
      hot.C[k] = this->UseColor ? input.Colors[3 * v + k] : 0.0f;
    }
    hot.QC = 0;
    hot.Spare = 0;
  }

  // 3. Per-vertex metric state.
  InitializeVertexMetrics(this->Mesh, this->Positions(), this->UseColor ? this->Hot[0].C : nullptr,
                          this->Metrics, HotStride, HotStride);

  // Each face slot's input normal bounds how far collapses may turn it, in total.
  this->Rules.SetReferenceTriangles(input.Triangles);

  // 4. Initial costs.
  this->Heap.Reset(n);
  this->Best.assign(n, -1);
  for (int32_t v = 0; v < n; ++v)
  {
    this->Update(v);
  }

  // 5. Collapse.
  const int64_t startFaces = this->Mesh.GetNumberOfLiveFaces();
  const int64_t toRemove = std::max<int64_t>(startFaces - stats.TargetTriangles, 1);
  int64_t nextReport = 0;
  while (this->Mesh.GetNumberOfLiveFaces() > stats.TargetTriangles && !this->Heap.Empty())
  {
    const int32_t v0 = this->Heap.Top();
    const int32_t v1 = this->Best[v0];
    if (v1 < 0)
    {
      this->Heap.Pop(); // no collapse left for v0 (removed lazily)
      continue;
    }
    if (!this->Rules.IsLegal(this->Mesh, this->Positions(), v0, v1, HotStride))
    {
      ++stats.RejectedPops;
      const Choice legal = this->Evaluate(v0, true);
      this->Best[v0] = legal.Target;
      if (legal.Target < 0)
      {
        this->Heap.Remove(v0);
      }
      else
      {
        this->Heap.Set(v0, legal.Cost);
      }
      continue;
    }
    this->Heap.Pop();

    // eq. 9 and 15: v1 takes over v0's quadric and importance.
    VertexMetric& m0 = this->Metrics[v0];
    VertexMetric& m1 = this->Metrics[v1];
    const float* p0 = this->Hot[v0].P;
    const float* p1 = this->Hot[v1].P;
    const double d[3] = { double(p1[0]) - p0[0], double(p1[1]) - p0[1], double(p1[2]) - p0[2] };
    m1.Q.AddShifted(m0.Q, d);
    m1.Importance += m0.Importance;
    m1.MaxColorDistance = std::max(m1.MaxColorDistance, m0.MaxColorDistance);
    this->Hot[v1].QC = m1.Q.C;

    this->FormerNeighbors.clear();
    this->Mesh.ForEachNeighbor(v0, [this](int32_t u) { this->FormerNeighbors.push_back(u); });
    this->Mesh.Collapse(v0, v1);
    ++stats.Collapses;
    this->Best[v0] = -1;

    // v1 and v0's former neighbours have a new 1-ring: re-cost them. The other neighbours
    // of v1 only saw their cost towards v1 grow: re-cost those whose choice was v1.
    this->Update(v1);
    for (int32_t u : this->FormerNeighbors)
    {
      if (u != v1)
      {
        this->Update(u);
      }
    }
    this->Mesh.ForEachNeighbor(v1,
                               [this, v1](int32_t u)
                               {
                                 if (this->Best[u] == v1)
                                 {
                                   this->Update(u);
                                 }
                               });

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
  this->Rules.SetReferenceTriangles(nullptr); // the input may not outlive Run
  stats.OutputTriangles = this->Mesh.GetNumberOfLiveFaces();
  // Connectivity 24 B/triangle + 5 B/vertex; metric 48; hot record 32; heap 16; choice 4.
  stats.StateBytes = 24 * size_t(input.NumberOfTriangles) +
    size_t(n) * (5 + sizeof(VertexMetric) + sizeof(HotVertex) + 16 + 4);
  return stats;
}

void Decimator::Update(int32_t v)
{
  if (this->Mesh.IsLocked(v) || this->Mesh.IsRemoved(v))
  {
    return;
  }
  const Choice best = this->Evaluate(v, false);
  this->Best[v] = best.Target;
  if (best.Target < 0)
  {
    return; // left in the heap, if it is there, and dropped when it comes to the top
  }
  this->Heap.Set(v, best.Cost);
}

void Decimator::GatherRing(int32_t v0)
{
  Ring& ring = this->CurrentRing;
  ring.Clear();
  const bool boundary = this->Mesh.IsBoundaryVertex(v0);
  this->Mesh.ForEachNeighbor(v0,
                             [&](int32_t u)
                             {
                               const HotVertex& hot = this->Hot[u];
                               const double p[3] = { hot.P[0], hot.P[1], hot.P[2] };
                               const double c[3] = { hot.C[0], hot.C[1], hot.C[2] };
                               // A boundary vertex only collapses along its boundary: to the first
                               // or last neighbour.
                               const bool candidate =
                                 !this->Mesh.IsLocked(u) && (!boundary || ring.Size == 0);
                               ring.Add(u, p, c, candidate, hot.QC);
                             });
  if (boundary && ring.Size > 0)
  {
    ring.IsCandidate[ring.Size - 1] = !this->Mesh.IsLocked(ring.Vertex[ring.Size - 1]);
  }
  ring.Pad();
}

COLORDECIMATION_VECTOR_CLONES
void Decimator::CostRing(int32_t v0)
{
  Ring& ring = this->CurrentRing;
  const int n = ring.PaddedSize();
  if (this->Costs.size() < static_cast<size_t>(n))
  {
    this->Costs.resize(2 * n);
  }
  double* costs = this->Costs.data();
  const HotVertex& hot0 = this->Hot[v0];
  const double p0[3] = { hot0.P[0], hot0.P[1], hot0.P[2] };
  const bool paperMetric = this->Options.Metric == ErrorMetric::HalfEdgeColor;
  if (paperMetric)
  {
    const double c0[3] = { hot0.C[0], hot0.C[1], hot0.C[2] };
    CollapseColorErrors(p0, c0, ring, costs);
  }
  // (Q(v0) + Q(j))(pj): Q(v0) is centred at p0, Q(j) at pj (so it contributes its constant).
  const Quadric& q0 = this->Metrics[v0].Q;
  const double a00 = q0.A00, a01 = q0.A01, a02 = q0.A02, a11 = q0.A11, a12 = q0.A12, a22 = q0.A22,
               b0 = q0.B0, b1 = q0.B1, b2 = q0.B2, c = q0.C;
  const double weight = this->Options.GeometryWeight;
  const double importance = this->Metrics[v0].Importance;
  const double* x = ring.X.data();
  const double* y = ring.Y.data();
  const double* z = ring.Z.data();
  const double* qc = ring.QC.data();
  for (int j = 0; j < n; ++j)
  {
    const double dx = x[j] - p0[0], dy = y[j] - p0[1], dz = z[j] - p0[2];
    const double quadric = dx * (a00 * dx + a01 * dy + a02 * dz) +
      dy * (a01 * dx + a11 * dy + a12 * dz) + dz * (a02 * dx + a12 * dy + a22 * dz) +
      2.0 * (b0 * dx + b1 * dy + b2 * dz) + c + qc[j];
    const double q = weight * std::max(0.0, quadric);
    costs[j] = paperMetric ? TotalCost(q, importance, costs[j]) : q;
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
  __builtin_prefetch(&this->Metrics[v0]);
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
    if (this->Rules.IsLegal(this->Mesh, this->Positions(), v0, ring.Vertex[j], HotStride))
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
