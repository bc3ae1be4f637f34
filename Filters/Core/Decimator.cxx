#include "Decimator.h"

#include "Parallel.h"
#include "Prefetch.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>

namespace colordecimation
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double MaximumDriftAngle = 75.0; ///< degrees
constexpr double Infinity = std::numeric_limits<double>::infinity();

/**
 * The bounding box of the points (lo, hi) and the mean length of the mesh's edges, on
 * `threads` threads: the edges are summed in fixed chunks, and the chunks in order, so the
 * mean has the same bits for any number of threads. The mesh's vertex v is the point
 * source[v] (v if source is null).
 */
double MeasureInput(const HalfEdgeMesh& mesh, const double* points, const int32_t* source,
                    int threads, double lo[3], double hi[3])
{
  const int32_t n = mesh.GetNumberOfVertices();
  threads = std::max(threads, 1);
  std::vector<double> boxes(6 * threads, 0.0); // lo and hi of each thread's range
  double* box = boxes.data();
  ParallelFor(size_t(n), threads,
              [points, box](size_t begin, size_t end, int t)
              {
                // (the box does not depend on the order of the points)
                double* b = box + 6 * t;
                for (size_t v = begin; v < end; ++v)
                {
                  for (int k = 0; k < 3; ++k)
                  {
                    const double x = points[3 * v + k];
                    b[k] = (v == begin || x < b[k]) ? x : b[k];
                    b[3 + k] = (v == begin || x > b[3 + k]) ? x : b[3 + k];
                  }
                }
              });
  bool first = true;
  for (int t = 0; t < threads; ++t)
  {
    const size_t begin = size_t(n) * t / threads, end = size_t(n) * (t + 1) / threads;
    if (begin == end)
    {
      continue; // an empty range found nothing
    }
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = (first || box[6 * t + k] < lo[k]) ? box[6 * t + k] : lo[k];
      hi[k] = (first || box[6 * t + 3 + k] > hi[k]) ? box[6 * t + 3 + k] : hi[k];
    }
    first = false;
  }

  constexpr int32_t Chunk = 1 << 16; // half-edges
  const int32_t numHalfEdges = 3 * mesh.GetNumberOfFaceSlots();
  const int32_t chunks = (numHalfEdges + Chunk - 1) / Chunk;
  std::vector<double> sums(chunks, 0.0);
  std::vector<int64_t> counts(chunks, 0);
  double* sum = sums.data();
  int64_t* count = counts.data();
  const HalfEdgeMesh* m = &mesh;
  const auto point = [points, source](int32_t v)
  { return points + 3 * size_t(source ? source[v] : v); };
  ParallelFor(size_t(chunks), threads,
              [m, point, numHalfEdges, sum, count](size_t begin, size_t end, int)
              {
                for (size_t c = begin; c < end; ++c)
                {
                  const int32_t last = std::min<int32_t>(numHalfEdges, int32_t(c + 1) * Chunk);
                  double chunkSum = 0;
                  int64_t chunkCount = 0;
                  for (int32_t h = int32_t(c) * Chunk; h < last; ++h)
                  {
                    const int32_t twin = m->Twin(h);
                    if (twin >= 0 && twin < h)
                    {
                      continue; // each interior edge once
                    }
                    chunkSum += Distance3(point(m->Origin(h)), point(m->Target(h)));
                    ++chunkCount;
                  }
                  sum[c] = chunkSum;
                  count[c] = chunkCount;
                }
              });
  double edgeSum = 0;
  int64_t edgeCount = 0;
  for (int32_t c = 0; c < chunks; ++c)
  {
    edgeSum += sum[c];
    edgeCount += count[c];
  }
  return edgeCount ? edgeSum / double(edgeCount) : 0.0;
}

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
  , Main(CollapseRules(MakeRuleOptions(options)))
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
  // 0. Locality: a large mesh is decimated in a spatial order (SpatialOrder.h), under new
  // vertex and face ids, and mapped back to its own ids at the end. The input's arrays are read
  // through the map (source[v]: the input's id of vertex v), not copied.
  SpatialOrder order;
  const bool large = input.NumberOfPoints >= LargeMeshVertices;
  this->Renumbered = this->Options.Renumber && large;
  if (this->Renumbered)
  {
    ComputeSpatialOrder(input.NumberOfPoints, input.Points, input.NumberOfTriangles,
                        input.Triangles, order, this->ThreadCount(size_t(input.NumberOfPoints)));
  }
  const int32_t* source = this->Renumbered ? order.OldVertex.data() : nullptr;

  DecimatorStatistics stats;
  const int32_t n = input.NumberOfPoints;
  stats.InputTriangles = input.NumberOfTriangles;
  stats.TargetTriangles = std::max<int64_t>(targetTriangles, 0);

  // 1. Connectivity.
  stats.Build = this->Mesh.Build(n, input.Triangles, input.NumberOfTriangles,
                                 this->ThreadCount(3 * size_t(input.NumberOfTriangles)),
                                 this->Renumbered ? order.OldFace.data() : nullptr,
                                 this->Renumbered ? order.NewVertex.data() : nullptr);
  order.NewVertex = std::vector<int32_t>();
  if (input.Fixed)
  {
    for (int32_t v = 0; v < n; ++v)
    {
      if (input.Fixed[source ? source[v] : v])
      {
        this->Mesh.Lock(v);
      }
    }
  }

  // 2. The normalised frame: bounding-box centre, mean edge length 1.
  double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
  stats.MeanEdgeLength =
    MeasureInput(this->Mesh, input.Points, source, this->ThreadCount(size_t(n)), lo, hi);
  const double scale = (stats.MeanEdgeLength > 0 && std::isfinite(stats.MeanEdgeLength))
    ? 1.0 / stats.MeanEdgeLength
    : 1.0;
  this->QuadricMetric = this->Options.Metric == ErrorMetric::ColorQuadric;
  this->Placement = this->QuadricMetric && this->Options.OptimalPlacement;
  this->UseColor = this->Options.Metric != ErrorMetric::Geometry && input.Colors;
  const bool lab = this->UseColor && this->Options.Space == ColorSpace::CIELab;
  this->FrameScale = scale;
  for (int k = 0; k < 3; ++k)
  {
    this->FrameCentre[k] = 0.5 * (lo[k] + hi[k]);
  }
  this->Hot.resize(n);
  HotVertex* hotRecords = this->Hot.data();
  const double centre[3] = { this->FrameCentre[0], this->FrameCentre[1], this->FrameCentre[2] };
  const double* inputPoints = input.Points;
  const float* inputColors = this->UseColor ? input.Colors : nullptr;
  ParallelFor(size_t(n), this->ThreadCount(size_t(n)),
              [hotRecords, centre, scale, inputPoints, inputColors, source, lab](size_t begin,
                                                                                 size_t end, int)
              {
                for (size_t v = begin; v < end; ++v)
                {
                  HotVertex& hot = hotRecords[v];
                  const size_t i = source ? size_t(source[v]) : v;
                  for (int k = 0; k < 3; ++k)
                  {
                    hot.P[k] = static_cast<float>((inputPoints[3 * i + k] - centre[k]) * scale);
                    hot.C[k] = inputColors ? inputColors[3 * i + k] : 0.0f;
                  }
                  if (lab)
                  {
                    const double rgb[3] = { hot.C[0], hot.C[1], hot.C[2] };
                    double c[3];
                    RGBToMetricColor(ColorSpace::CIELab, rgb, c);
                    for (int k = 0; k < 3; ++k)
                    {
                      hot.C[k] = static_cast<float>(c[k]);
                    }
                  }
                  hot.QC = 0;
                  hot.Spare = 0;
                }
              });

  // 3. Per-vertex metric state.
  this->AnyMoved = false;
  this->Moved.clear();
  if (this->QuadricMetric)
  {
    // GH98's frame: the bounding box scaled uniformly into the unit cube.
    const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
    this->CubeScale = extent > 0 && std::isfinite(extent) ? 1.0 / (scale * extent) : 1.0;
    this->Metrics.clear();
    InitializeColorQuadrics(this->Mesh, this->Positions(), HotStride, this->CubeScale,
                            this->UseColor ? this->Hot[0].C : nullptr, HotStride,
                            std::max(this->Options.ColorWeight, 0.0),
                            std::max(this->Options.BoundaryWeight, 0.0), this->ColorQuadrics);
    if (this->Placement)
    {
      this->Moved.assign(n, 0);
    }
  }
  else
  {
    this->ColorQuadrics.clear();
    this->Metrics.resize(size_t(n)); // written by the threads
    InitializeVertexMetrics(this->Mesh, this->Positions(),
                            this->UseColor ? this->Hot[0].C : nullptr, this->Metrics.data(),
                            HotStride, HotStride, std::max(this->Options.BoundaryWeight, 0.0),
                            this->ThreadCount(3 * size_t(input.NumberOfTriangles)));
  }

  // Each face slot's input normal bounds how far collapses may turn it, in total.
  CollapseRules::ComputeReferenceNormals(this->Mesh, this->Positions(), HotStride,
                                         this->ReferenceNormals,
                                         this->ThreadCount(size_t(input.NumberOfTriangles)));
  this->Main.Rules.SetReferenceNormals(this->ReferenceNormals.data());
  // Everything below reads the mesh, the hot records and the metric state only.

  this->ThreadsUsed = 1;
  this->CollapseThreadsUsed = 1;
  this->WideCollapseThreadsUsed = 1;
  // 4-5. Cost every vertex, then collapse: one at a time in the heap's order (the paper's),
  // or in batches of independent collapses, each followed by a re-costing pass.
  if (this->Options.Schedule == CollapseSchedule::Batched)
  {
    this->CollapseInBatches(stats, progress);
  }
  else
  {
    this->CollapseGreedily(stats, large, progress);
  }
  stats.Threads = this->ThreadsUsed;
  stats.CollapseThreads = this->CollapseThreadsUsed;
  stats.WideCollapseThreads = this->WideCollapseThreadsUsed;
  this->Workers.clear();
  this->AnyMoved = std::find(this->Moved.begin(), this->Moved.end(), 1) != this->Moved.end();
  this->Main.Rules.SetReferenceNormals(nullptr);
  this->ReferenceNormals = Buffer<float>();
  if (!order.Empty())
  {
    this->RestoreOrder(order);
  }
  stats.OutputTriangles = this->Mesh.GetNumberOfLiveFaces();
  // Connectivity 24 B/triangle + 5 B/vertex; reference normals 12 B/triangle; metric 48;
  // hot record 32; Greedy: heap 16 per entry + 20 per vertex; Batched: key 8, stamp 4, the
  // batch (at most a quarter of the vertices, 16 B each, collected by the threads and then
  // copied) 8, the list of affected vertices 4, the list of live vertices and its shrunk
  // copy 8, and the block flags 1; choice 4 + 1.
  // ColorQuadric: 112 instead of 48 for the metric, and 1 more for the moved flags.
  stats.MetricBytesPerVertex = this->QuadricMetric ? sizeof(ColorQuadric) : sizeof(VertexMetric);
  const size_t ordering = this->Options.Schedule == CollapseSchedule::Batched ? 33 : 36;
  stats.StateBytes = (24 + 12) * size_t(input.NumberOfTriangles) +
    size_t(n) *
      (5 + stats.MetricBytesPerVertex + sizeof(HotVertex) + ordering + 4 + 1 +
       (this->Placement ? 1 : 0));
  if (!order.Empty())
  {
    // The maps back to the input's ids, kept to the end.
    stats.StateBytes += 4 * size_t(input.NumberOfTriangles) + 4 * size_t(n);
  }
  return stats;
}

void Decimator::RestoreOrder(const SpatialOrder& order)
{
  // The heap and the choices refer to the renumbered ids and are of no use after Run: freed
  // first, so that each copy made while mapping back is smaller than what they held.
  this->Heap.Release();
  this->Best = std::vector<int32_t>();
  this->Bounded = std::vector<uint8_t>();
  if (!this->Options.KeepVertexState)
  {
    // What the output needs: the moved vertices' points and colours (hot records). The rest
    // goes first, so that the copies the mapping makes take its room.
    this->Metrics = Buffer<VertexMetric>();
    this->ColorQuadrics = std::vector<ColorQuadric>();
    if (!this->AnyMoved)
    {
      this->Hot = Buffer<HotVertex>();
    }
  }
  const auto n = static_cast<int64_t>(order.OldVertex.size());
  const int threads = this->ThreadCount(order.OldFace.size());
  this->Mesh.Renumber(order.OldVertex.data(), order.OldFace.data(), threads);
  auto restore = [&order, n, threads](auto& values)
  {
    if (static_cast<int64_t>(values.size()) == n)
    {
      Permute(values, n, order.OldVertex.data(), 1, threads);
    }
  };
  restore(this->Hot);
  restore(this->Metrics);
  restore(this->ColorQuadrics);
  restore(this->Moved);
}

void Decimator::PrefetchEvaluation(const int32_t* vertices, size_t i, size_t end) const
{
  // The vertex records a few evaluations ahead, then its first face, then the records of
  // that face's other two corners (two of its neighbours); the rest of the fan is usually
  // on the same lines.
  if (i + FarAhead < end)
  {
    const int32_t v = vertices[i + FarAhead];
    this->Mesh.PrefetchVertex(v);
    COLORDECIMATION_PREFETCH(this->Hot.data() + v);
    if (!this->Metrics.empty())
    {
      this->PrefetchMetric(v);
    }
  }
  if (i + MiddleAhead < end)
  {
    this->Mesh.PrefetchFirstFace(vertices[i + MiddleAhead]);
  }
  if (i + NearAhead < end)
  {
    const int32_t h = this->Mesh.Outgoing(vertices[i + NearAhead]);
    if (h >= 0)
    {
      COLORDECIMATION_PREFETCH(this->Hot.data() + this->Mesh.Target(h));
      COLORDECIMATION_PREFETCH(this->Hot.data() + this->Mesh.Origin(HalfEdgeMesh::Prev(h)));
    }
  }
}

void Decimator::PrefetchNeighborhood(int32_t v0)
{
  constexpr int MaxWalks = 16;
  constexpr int MaxSteps = 16;
  int32_t start[MaxWalks], h[MaxWalks];
  int count = 0;
  this->Mesh.ForEachNeighbor(v0,
                             [&](int32_t u)
                             {
                               if (count < MaxWalks)
                               {
                                 // The metric state of whichever metric runs.
                                 if (this->QuadricMetric)
                                 {
                                   COLORDECIMATION_PREFETCH(this->ColorQuadrics.data() + u);
                                 }
                                 else
                                 {
                                   this->PrefetchMetric(u);
                                 }
                                 COLORDECIMATION_PREFETCH(this->Best.data() + u);
                                 if (this->Stamp.empty())
                                 {
                                   this->Heap.Prefetch(u);
                                 }
                                 else
                                 {
                                   COLORDECIMATION_PREFETCH(this->Stamp.data() + u);
                                 }
                                 start[count++] = u;
                               }
                             });
  int active = 0;
  for (int i = 0; i < count; ++i)
  {
    const int32_t first = this->Mesh.Outgoing(start[i]);
    if (first >= 0)
    {
      start[active] = first;
      h[active] = first;
      ++active;
    }
  }
  for (int step = 0; step < MaxSteps && active > 0; ++step)
  {
    for (int i = 0; i < active;)
    {
      COLORDECIMATION_PREFETCH(this->Hot.data() + this->Mesh.Target(h[i]));
      const int32_t next = this->Mesh.Twin(HalfEdgeMesh::Prev(h[i]));
      if (next < 0 || next == start[i])
      {
        --active;
        start[i] = start[active];
        h[i] = h[active];
        continue;
      }
      h[i] = next;
      ++i;
    }
  }
}

void Decimator::Update(int32_t v)
{
  if (this->Mesh.IsLocked(v) || this->Mesh.IsRemoved(v))
  {
    return;
  }
  const Choice best = this->Evaluate(v, false, true, this->Main);
  this->Best[v] = best.Target;
  this->Bounded[v] = best.Bound ? 1 : 0;
  if (best.Target < 0)
  {
    return; // left in the heap, if it is there, and dropped when it comes to the top
  }
  this->Heap.Set(v, best.Cost);
}

int Decimator::ThreadCount(size_t items) const
{
  return ThreadsFor(items, this->Options.NumberOfThreads, MinimumThreadWork);
}

void Decimator::EvaluateAll(const int32_t* vertices, size_t count, bool exact, bool allowBound,
                            double* keys)
{
  // Each evaluation reads the mesh and the per-vertex state, and writes its own vertex's
  // entries only: the vertices can be shared among threads in any way, with the same result.
  auto evaluate = [this, vertices, exact, allowBound, keys](Workspace& ws, size_t begin, size_t end)
  {
    for (size_t i = begin; i < end; ++i)
    {
      this->PrefetchEvaluation(vertices, i, end);
      const int32_t v = vertices[i];
      Choice choice;
      if (!this->Mesh.IsLocked(v) && !this->Mesh.IsRemoved(v))
      {
        choice = this->Evaluate(v, exact, allowBound, ws);
      }
      this->Best[v] = choice.Target;
      this->Bounded[v] = choice.Bound ? 1 : 0;
      keys[v] = choice.Cost;
    }
  };
  // An exact evaluation runs the rules on its choices until one is legal: some times the work.
  const int threads = this->ThreadCount(exact ? ExactEvaluationWork * count : count);
  this->ThreadsUsed = std::max(this->ThreadsUsed, threads);
  this->AddWorkers(threads);
  ParallelFor(count, threads,
              [this, evaluate](size_t begin, size_t end, int t)
              { evaluate(t == 0 ? this->Main : this->Workers[t - 1], begin, end); });
}

void Decimator::AddWorkers(int threads)
{
  while (this->Workers.size() < static_cast<size_t>(threads - 1))
  {
    this->Workers.push_back(this->Main); // its own scratch; the same rules and normals
  }
}

std::vector<double> Decimator::EvaluateEveryVertex(bool allowBound)
{
  const int32_t n = this->Mesh.GetNumberOfVertices();
  this->Best.assign(n, -1);
  this->Bounded.assign(n, 0);
  std::vector<int32_t> all(n);
  std::iota(all.begin(), all.end(), 0);
  std::vector<double> keys(n);
  this->EvaluateAll(all.data(), all.size(), false, allowBound, keys.data());
  return keys;
}

bool Decimator::IsCollapseLegal(int32_t v0, int32_t v1, bool& moves, double y[6],
                                Workspace& ws) const
{
  // A full collapse (ColorQuadric with OptimalPlacement) puts v1 at the placement y.
  moves = false;
  if (this->Placement)
  {
    double d01[6];
    this->Offset6(v0, v1, d01);
    this->PlaceCollapse(v0, v1, d01, y);
    moves = !std::equal(y, y + 6, d01);
    if (moves)
    {
      double newPosition[3];
      this->PlacementPosition(v0, y, newPosition);
      return ws.Rules.IsLegal(this->Mesh, this->Positions(), v0, v1, HotStride, newPosition);
    }
  }
  return ws.Rules.IsLegal(this->Mesh, this->Positions(), v0, v1, HotStride);
}

int Decimator::ApplyCollapse(int32_t v0, int32_t v1, bool moves, const double y[6], Workspace& ws,
                             bool counted)
{
  if (this->QuadricMetric)
  {
    this->MergeColorQuadric(v0, v1, moves, y);
  }
  else
  {
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
  }
  ws.FormerNeighbors.clear();
  this->Mesh.ForEachNeighbor(v0, [&ws](int32_t u) { ws.FormerNeighbors.push_back(u); });
  this->Best[v0] = -1;
  return counted ? this->Mesh.Collapse(v0, v1) : this->Mesh.CollapseUncounted(v0, v1);
}

template <typename Function>
void Decimator::ForEachAffected(int32_t v1, const std::vector<int32_t>& formerNeighbors,
                                Function&& f) const
{
  // v1 and v0's former neighbours have a new 1-ring. The other neighbours of v1 only saw their
  // cost towards v1 grow: only those whose choice was v1 are affected. After a full collapse
  // every cost towards v1 may have changed (its point and quadric both did): its whole new
  // 1-ring, which holds v0's former neighbours, is affected.
  f(v1);
  if (this->Placement)
  {
    this->Mesh.ForEachNeighbor(v1, f);
    return;
  }
  for (int32_t u : formerNeighbors)
  {
    if (u != v1)
    {
      f(u);
    }
  }
  this->Mesh.ForEachNeighbor(v1,
                             [this, v1, &formerNeighbors, &f](int32_t u)
                             {
                               if (this->Best[u] == v1 &&
                                   std::find(formerNeighbors.begin(), formerNeighbors.end(), u) ==
                                     formerNeighbors.end())
                               {
                                 f(u);
                               }
                             });
}

void Decimator::Requeue(int32_t v0, bool exact)
{
  const Choice choice = this->Evaluate(v0, exact, false, this->Main);
  this->Best[v0] = choice.Target;
  if (choice.Target < 0)
  {
    this->Heap.Remove(v0);
  }
  else
  {
    this->Heap.Set(v0, choice.Cost);
  }
}

void Decimator::CollapseGreedily(DecimatorStatistics& stats, bool prefetch,
                                 const std::function<bool(double)>& progress)
{
  const int32_t n = this->Mesh.GetNumberOfVertices();
  this->Heap.Reset(n);
  {
    const std::vector<double> keys = this->EvaluateEveryVertex(true);
    for (int32_t v = 0; v < n; ++v)
    {
      if (this->Best[v] >= 0)
      {
        this->Heap.Set(v, keys[v]);
      }
    }
  }

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
    if (this->Bounded[v0])
    {
      // Its key was a lower bound (a high-valence vertex): cost it exactly, and back it goes.
      this->Bounded[v0] = 0;
      this->Requeue(v0, false);
      continue;
    }
    if (prefetch)
    {
      this->PrefetchNeighborhood(v0);
    }
    double y[6];
    bool moves = false;
    if (!this->IsCollapseLegal(v0, v1, moves, y, this->Main))
    {
      ++stats.RejectedPops;
      this->Requeue(v0, true); // over its legal collapses only
      continue;
    }
    this->Heap.Pop();
    this->ApplyCollapse(v0, v1, moves, y, this->Main, true);
    ++stats.Collapses;
    this->ForEachAffected(v1, this->Main.FormerNeighbors, [this](int32_t u) { this->Update(u); });

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
}

void Decimator::CollapseInBatches(DecimatorStatistics& stats,
                                  const std::function<bool(double)>& progress)
{
  const int32_t n = this->Mesh.GetNumberOfVertices();
  std::vector<double> keys = this->EvaluateEveryVertex(false);
  // Stamp[v] == pass: v was affected by a collapse of this pass (its key is stale) or its
  // chosen collapse was found illegal; either way it waits for the re-costing.
  this->Stamp.assign(n, 0);
  const int shift = std::min(std::max(this->Options.BlockShift, 4), 24);
  this->SmallBlocks = { shift, 0, 1, 0 };
  this->WideBlocks = { shift + 3, 0, 2, 1 | 4 };
  this->ShiftedBlocks = { shift + 3, int32_t(1) << (shift + 2), 4, 1 | 2 };
  this->FlagEveryInterior();
  this->BlockFaces.clear();
  if (this->Renumbered)
  {
    // The faces come in order of their smallest vertex and none is collapsed yet: a binary
    // search for each block, from the previous block's answer on.
    const int32_t faces = this->Mesh.GetNumberOfFaceSlots();
    const HalfEdgeMesh& mesh = this->Mesh;
    auto smallest = [&mesh](int32_t f)
    {
      int32_t ids[3];
      mesh.GetFace(f, ids);
      return std::min(ids[0], std::min(ids[1], ids[2]));
    };
    const int32_t blocks = (n >> shift) + 1;
    this->BlockFaces.resize(size_t(blocks) + 1);
    int32_t first = 0;
    for (int32_t b = 0; b <= blocks; ++b)
    {
      const int64_t v = std::min<int64_t>(int64_t(b) << shift, n);
      int32_t lo = first, hi = faces;
      while (lo < hi)
      {
        const int32_t mid = lo + (hi - lo) / 2;
        if (smallest(mid) < v)
        {
          lo = mid + 1;
        }
        else
        {
          hi = mid;
        }
      }
      this->BlockFaces[b] = first = lo;
    }
  }
  // Blocks: ranges of 2^Shift ids (neighbours on the surface in the spatial order), fixed
  // partitions, so that the result does not depend on the number of threads.
  std::vector<Candidate> batch, deferred;
  std::vector<size_t> blockStart;
  std::vector<int32_t> affected, rejected;
  // The vertices that may have a collapse, in vertex order: the collapsible ones, less those
  // collapsed away after each pass, so that the scans of a pass shrink with the mesh.
  std::vector<int32_t> live, kept;
  CollectInOrder(
    static_cast<size_t>(n), this->ThreadCount(static_cast<size_t>(n)),
    [this](size_t v, int32_t& u)
    {
      u = static_cast<int32_t>(v);
      return this->Mesh.IsCollapsible(u);
    },
    live);
  const int64_t startFaces = this->Mesh.GetNumberOfLiveFaces();
  const int64_t toRemove = std::max<int64_t>(startFaces - stats.TargetTriangles, 1);
  int32_t pass = 0;
  while (this->Mesh.GetNumberOfLiveFaces() > stats.TargetTriangles && !stats.Aborted)
  {
    ++pass;
    // The batch: the cheapest fraction of the candidates (the vertices with a chosen collapse),
    // no more than the collapses still needed (each removes two triangles, one on a
    // boundary), so that the block phase, which does not stop half-way, ends at the target or
    // one triangle below at the lowest. It comes in vertex order, hence grouped by block.
    const int64_t needed = (this->Mesh.GetNumberOfLiveFaces() - stats.TargetTriangles + 1) / 2;
    const double fraction = this->Options.BatchFraction;
    const int32_t* best = this->Best.data();
    const double* key = keys.data();
    batch.clear();
    const size_t candidates = SelectCheapest(
      live.size(), live.data(),
      [best, key](int32_t v, double& k)
      {
        k = OrderableKey(key[v]);
        return best[v] >= 0;
      },
      [needed, fraction](size_t count)
      {
        return static_cast<size_t>(std::max<int64_t>(
          1,
          std::min<int64_t>(
            needed, static_cast<int64_t>(std::ceil(fraction * static_cast<double>(count))))));
      },
      this->ThreadCount(live.size()), batch);
    if (candidates == 0)
    {
      break;
    }
    affected.clear();
    rejected.clear();
    auto gather = [&](Workspace& ws)
    {
      rejected.insert(rejected.end(), ws.Rejected.begin(), ws.Rejected.end());
      deferred.insert(deferred.end(), ws.Deferred.begin(), ws.Deferred.end());
      stats.Collapses += ws.Collapses;
      stats.RejectedPops += ws.Rejections;
      this->Mesh.RemoveLiveFaces(ws.RemovedFaces);
    };
    // 1. The blocks, on several threads: the collapses whose whole neighbourhood lies in their
    // block, first in small blocks, then those deferred from them in wide ones, then those
    // deferred from these in shifted wide ones; the others are deferred again. Each block
    // sorts its own candidates by cost.
    for (const BlockLevel& level : { this->SmallBlocks, this->WideBlocks, this->ShiftedBlocks })
    {
      if (level.Flag != this->SmallBlocks.Flag) // the batch comes in vertex order, those
                                                // deferred do not
      {
        std::sort(batch.begin(), batch.end(),
                  [](const Candidate& a, const Candidate& b) { return a.Vertex < b.Vertex; });
      }
      blockStart.assign(size_t(level.BlockOf(n)) + 2, 0);
      for (const Candidate& c : batch)
      {
        ++blockStart[size_t(level.BlockOf(c.Vertex)) + 1];
      }
      std::partial_sum(blockStart.begin(), blockStart.end(), blockStart.begin());
      this->CollapseBlocks(batch, blockStart, level, pass);
      deferred.clear();
      gather(this->Main);
      for (Workspace& ws : this->Workers)
      {
        gather(ws);
      }
      batch.swap(deferred);
    }
    deferred.swap(batch);

    // 2. The deferred ones, in cost order, on this thread, up to the target.
    std::sort(deferred.begin(), deferred.end());
    Workspace& ws = this->Main;
    ws.ClearPass();
    for (size_t i = 0; i < deferred.size(); ++i)
    {
      if (this->Mesh.GetNumberOfLiveFaces() <= stats.TargetTriangles)
      {
        break;
      }
      this->PrefetchCandidates(deferred.data(), i, deferred.size(), -1, this->SmallBlocks);
      const int32_t v0 = deferred[i].Vertex;
      const int32_t v1 = this->Best[v0];
      if (this->Stamp[v0] == pass || v1 < 0 || this->Stamp[v1] == pass)
      {
        continue;
      }
      const int64_t collapses = ws.Collapses;
      this->TryCollapse(v0, v1, pass, ws, true);
      if (ws.Collapses != collapses)
      {
        // v0's former neighbours (v1 among them) may now have one in another block, or no
        // longer have one (a collapse inside a block never changes that block's flags: all it
        // touches is in the block).
        this->FlagInterior(ws.FormerNeighbors.data(), ws.FormerNeighbors.size(),
                           this->AllBlockFlags());
      }
    }
    gather(ws); // the mesh counted these faces itself: ws.RemovedFaces is 0
    ++stats.Passes;
    if (this->Options.VerifyBlockFlags)
    {
      stats.StaleBlockFlags += this->CountStaleFlags();
    }
    // 3. Re-cost in vertex order (neighbours in memory are neighbours on the surface); the
    // rejected ones over their legal collapses only. The affected ones are those stamped with
    // this pass, once the rejected ones are stamped apart (with -pass, which no pass matches);
    // locked ones, which never have a collapse, are not listed.
    for (int32_t v : rejected)
    {
      this->Stamp[v] = -pass;
    }
    // One scan of the live vertices keeps those not collapsed away and lists the affected ones
    // (never collapsed away: a stamped vertex is not collapsed).
    kept.clear();
    const int32_t* before = live.data();
    const int32_t* stamp = this->Stamp.data();
    CollectInOrder(
      live.size(), this->ThreadCount(live.size()),
      [this, before, stamp, pass](size_t i, int32_t& u)
      {
        u = before[i];
        const int alive = this->Mesh.IsRemoved(u) ? 0 : 1;
        return alive | ((alive & (stamp[u] == pass ? 1 : 0)) << 1);
      },
      kept, affected);
    live.swap(kept);
    this->EvaluateAll(affected.data(), affected.size(), false, false, keys.data());
    this->EvaluateAll(rejected.data(), rejected.size(), true, false, keys.data());
    if (progress)
    {
      const double done = double(startFaces - this->Mesh.GetNumberOfLiveFaces()) / toRemove;
      stats.Aborted = !progress(std::min(done, 1.0));
    }
  }
  this->Stamp = std::vector<int32_t>();
  this->Interior = std::vector<uint8_t>();
  this->BlockFaces = std::vector<int32_t>();
}

void Decimator::CollapseBlocks(std::vector<Candidate>& batch, const std::vector<size_t>& blockStart,
                               const BlockLevel& level, int32_t pass)
{
  const int32_t blocks = static_cast<int32_t>(blockStart.size()) - 1;
  std::atomic<int32_t> nextBlock(0);
  auto work = [this, &batch, &blockStart, &nextBlock, blocks, level, pass](Workspace& ws)
  {
    for (int32_t block = nextBlock++; block < blocks; block = nextBlock++)
    {
      this->CollapseBlock(batch.data() + blockStart[block], batch.data() + blockStart[block + 1],
                          block, level, pass, ws);
    }
  };
  // A thread is worth it for some thousands of candidates only; either way the blocks are
  // the same, and so is the result.
  const int threads = this->ThreadCount(CandidateWork * batch.size());
  int& used = level.Flag != this->SmallBlocks.Flag ? this->WideCollapseThreadsUsed
                                                   : this->CollapseThreadsUsed;
  used = std::max(used, threads);
  this->AddWorkers(threads);
  // Every workspace starts the pass empty, those of idle threads too (they are gathered).
  this->Main.ClearPass();
  for (Workspace& ws : this->Workers)
  {
    ws.ClearPass();
  }
  // One call per thread (the ranges are unused): the threads take the blocks in turn.
  ParallelFor(size_t(threads), threads,
              [this, work](size_t, size_t, int t)
              { work(t == 0 ? this->Main : this->Workers[t - 1]); });
}

void Decimator::CollapseBlock(Candidate* begin, Candidate* end, int32_t block,
                              const BlockLevel& level, int32_t pass, Workspace& ws)
{
  SortByKey(begin, end, ws.SortRoom); // cost order (the block's candidates come in vertex order)
  int32_t* stamp = this->Stamp.data();
  const size_t count = static_cast<size_t>(end - begin);
  this->WarmBlock(block, level, count);
  for (size_t i = 0; i < count; ++i)
  {
    this->PrefetchCandidates(begin, i, count, block, level);
    const int32_t v0 = begin[i].Vertex;
    const int32_t v1 = this->Best[v0];
    if (stamp[v0] == pass || v1 < 0)
    {
      continue; // its key is stale: a neighbour collapsed in this pass
    }
    if (!this->IsInsideBlock(v0, v1, block, level))
    {
      ws.Deferred.push_back(begin[i]);
      continue;
    }
    if (stamp[v1] == pass)
    {
      continue;
    }
    const int64_t collapses = ws.Collapses;
    this->TryCollapse(v0, v1, pass, ws, false);
    if (level.OtherFlags != 0 && ws.Collapses != collapses)
    {
      // v0's former neighbours may now have a neighbour in another finer block (or no longer
      // have one). All of them and their fans are in this block: no other thread reads or
      // writes them.
      this->FlagInterior(ws.FormerNeighbors.data(), ws.FormerNeighbors.size(), level.OtherFlags);
    }
  }
}

void Decimator::FlagInterior(const int32_t* vertices, size_t count, uint8_t flags)
{
  for (size_t i = 0; i < count; ++i)
  {
    const int32_t v = vertices[i];
    uint8_t outside = 0; // the flags of the levels where v has a neighbour in another block
    this->Mesh.ForEachNeighbor(
      v, [this, &outside, v](int32_t u) { outside |= this->BlockCrossings(u, v); });
    this->Interior[v] = static_cast<uint8_t>((this->Interior[v] & ~flags) | (flags & ~outside));
  }
}

void Decimator::FlagEveryInterior()
{
  // Each edge is a side of at least one live face: both of its ends learn of a neighbour in
  // another block. Few edges cross blocks: the threads list those ends, each for its own range
  // of faces, and this thread clears their flags. (For a locked vertex this may be stricter
  // than its fan; its flag is never read.)
  const int32_t numFaces = this->Mesh.GetNumberOfFaceSlots();
  const int threads = this->ThreadCount(3 * static_cast<size_t>(numFaces));
  std::vector<std::vector<std::pair<int32_t, uint8_t>>> crossed(threads);
  ParallelFor(static_cast<size_t>(numFaces), threads,
              [this, &crossed](size_t begin, size_t end, int t)
              {
                std::vector<std::pair<int32_t, uint8_t>>& list = crossed[t];
                for (auto f = static_cast<int32_t>(begin); f < static_cast<int32_t>(end); ++f)
                {
                  if (!this->Mesh.IsFaceAlive(f))
                  {
                    continue;
                  }
                  int32_t ids[3];
                  this->Mesh.GetFace(f, ids);
                  for (int k = 0; k < 3; ++k)
                  {
                    const int32_t a = ids[k], b = ids[k == 2 ? 0 : k + 1];
                    const uint8_t crossings = this->BlockCrossings(a, b);
                    if (crossings != 0)
                    {
                      list.emplace_back(a, crossings);
                      list.emplace_back(b, crossings);
                    }
                  }
                }
              });
  this->Interior.assign(this->Mesh.GetNumberOfVertices(), this->AllBlockFlags());
  for (const auto& list : crossed)
  {
    for (const auto& crossing : list)
    {
      this->Interior[crossing.first] &= static_cast<uint8_t>(~crossing.second);
    }
  }
}

int64_t Decimator::CountStaleFlags()
{
  std::vector<uint8_t> kept;
  kept.swap(this->Interior);
  this->FlagEveryInterior();
  int64_t stale = 0;
  for (int32_t v = 0; v < this->Mesh.GetNumberOfVertices(); ++v)
  {
    stale += this->Mesh.IsCollapsible(v) && kept[v] != this->Interior[v] ? 1 : 0;
  }
  this->Interior.swap(kept);
  return stale;
}

void Decimator::PrefetchCandidates(const Candidate* candidates, size_t i, size_t count,
                                   int32_t block, const BlockLevel& level) const
{
  // The candidates are known in advance: their neighbourhoods are fetched a few collapses
  // ahead, in three stages (the vertex, its first face and target, the target's first face
  // and both metric records, which the collapse merges), none of which waits. In a block
  // (block >= 0) only the block's records are read.
  const auto mayRead = [block, &level](int32_t v)
  { return block < 0 || level.BlockOf(v) == block; };
  if (i + FarAhead < count)
  {
    const int32_t v = candidates[i + FarAhead].Vertex;
    this->Mesh.PrefetchVertex(v);
    COLORDECIMATION_PREFETCH(this->Stamp.data() + v);
    COLORDECIMATION_PREFETCH(this->Best.data() + v);
  }
  if (i + MiddleAhead < count)
  {
    const int32_t v = candidates[i + MiddleAhead].Vertex;
    this->Mesh.PrefetchFirstFace(v);
    const int32_t target = this->Best[v];
    if (target >= 0 && mayRead(target))
    {
      this->Mesh.PrefetchVertex(target);
      COLORDECIMATION_PREFETCH(this->Stamp.data() + target);
    }
    COLORDECIMATION_PREFETCH(this->Hot.data() + v);
  }
  if (i + NearAhead < count)
  {
    const int32_t v = candidates[i + NearAhead].Vertex;
    const int32_t target = this->Best[v];
    if (!this->Metrics.empty())
    {
      this->PrefetchMetric(v);
    }
    if (target >= 0 && mayRead(target))
    {
      this->Mesh.PrefetchFirstFace(target);
      COLORDECIMATION_PREFETCH(this->Hot.data() + target);
      if (!this->Metrics.empty())
      {
        this->PrefetchMetric(target);
      }
    }
  }
}

void Decimator::WarmBlock(int32_t block, const BlockLevel& level, size_t candidates) const
{
  // The candidates come in cost order, and so, in no order the hardware can foresee, do the
  // two-rings the rules walk: a cold line after another (kitchen scan: some 1100 cycles a
  // rules check), which the prefetches of PrefetchCandidates, a few records each, only partly
  // hide. Swept in address order first, the block's records stream in (kitchen scan: the
  // block phase 0.55 -> 0.48 s, the run 3-6 % faster). The sweep takes the vertex records the
  // rules and the block test read, and the faces from the block's first to the next block's
  // (fans reaching back into the block before are partly left out). The metrics, read twice
  // a collapse, gained nothing (nor did sweeping the re-costed vertices: those come in vertex
  // order already).
  const size_t size = size_t(1) << level.Shift;
  if (this->BlockFaces.empty() || candidates * WarmDensity < size)
  {
    return;
  }
  const size_t n = size_t(this->Mesh.GetNumberOfVertices());
  const size_t start = std::max(size_t(block) * size, size_t(level.Offset)) - size_t(level.Offset);
  const size_t lo = std::min(start, n), hi = std::min(size_t(block + 1) * size - level.Offset, n);
  // The faces from the first small block's to the one after the last (the small blocks lie
  // inside the block).
  const int smallShift = this->SmallBlocks.Shift;
  const size_t last = this->BlockFaces.size() - 1;
  const int32_t firstFace = this->BlockFaces[std::min(lo >> smallShift, last)];
  const int32_t endFace =
    this->BlockFaces[std::min((hi + (size_t(1) << smallShift) - 1) >> smallShift, last)];
  PrefetchRange(this->Hot.data() + lo, this->Hot.data() + hi);
  this->Mesh.PrefetchFaces(firstFace, endFace);
  for (size_t v = lo; v < hi; v += 16) // 16 ids to a line
  {
    COLORDECIMATION_PREFETCH(this->Best.data() + v);
    COLORDECIMATION_PREFETCH(this->Stamp.data() + v);
    this->Mesh.PrefetchVertex(int32_t(v));
  }
}

bool Decimator::IsInsideBlock(int32_t v0, int32_t v1, int32_t block, const BlockLevel& level) const
{
  // The collapse reads and writes the faces around v0, v1 and their common neighbours (vl
  // and vr), and the records of their vertices: all of them must be in the block, i.e. these
  // four vertices must be interior to it. A locked vl or vr fails the rules without its fan
  // being read.
  const uint8_t* interior = this->Interior.data();
  if (!(interior[v0] & level.Flag) || level.BlockOf(v1) != block || !(interior[v1] & level.Flag))
  {
    return false;
  }
  const int32_t h01 = this->Mesh.FindHalfEdge(v0, v1);
  const int32_t h10 = this->Mesh.FindReverseHalfEdge(v0, v1, h01);
  for (const int32_t h : { h01, h10 })
  {
    if (h < 0)
    {
      continue;
    }
    const int32_t x = this->Mesh.Origin(HalfEdgeMesh::Prev(h)); // vl or vr
    if (!this->Mesh.IsLocked(x) && !(interior[x] & level.Flag))
    {
      return false;
    }
  }
  return true;
}

void Decimator::TryCollapse(int32_t v0, int32_t v1, int32_t pass, Workspace& ws, bool counted)
{
  int32_t* stamp = this->Stamp.data();
  double y[6];
  bool moves = false;
  if (!this->IsCollapseLegal(v0, v1, moves, y, ws))
  {
    stamp[v0] = pass;
    ws.Rejected.push_back(v0);
    ++ws.Rejections;
    return;
  }
  const int removed = this->ApplyCollapse(v0, v1, moves, y, ws, counted);
  ws.RemovedFaces += counted ? 0 : removed; // what the mesh has not counted itself
  ++ws.Collapses;
  this->ForEachAffected(v1, ws.FormerNeighbors, [pass, stamp](int32_t u) { stamp[u] = pass; });
}

void Decimator::GatherRing(int32_t v0, Ring& ring) const
{
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
void Decimator::CostRing(int32_t v0, bool withColorError, Workspace& ws) const
{
  Ring& ring = ws.CurrentRing;
  const int n = ring.PaddedSize();
  if (ws.Costs.size() < static_cast<size_t>(n))
  {
    ws.Costs.resize(2 * n);
  }
  double* costs = ws.Costs.data();
  const HotVertex& hot0 = this->Hot[v0];
  const double p0[3] = { hot0.P[0], hot0.P[1], hot0.P[2] };
  const bool paperMetric = this->Options.Metric == ErrorMetric::HalfEdgeColor;
  if (paperMetric && withColorError)
  {
    const double c0[3] = { hot0.C[0], hot0.C[1], hot0.C[2] };
    CollapseColorErrors(p0, c0, ring, costs);
  }
  else if (paperMetric)
  {
    std::fill(costs, costs + n, 0.0); // C >= 0: (1 + Q)(1 + I) bounds the cost from below
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
  const auto quadricError = [=](int j)
  {
    const double dx = x[j] - p0[0], dy = y[j] - p0[1], dz = z[j] - p0[2];
    const double quadric = dx * (a00 * dx + a01 * dy + a02 * dz) +
      dy * (a01 * dx + a11 * dy + a12 * dz) + dz * (a02 * dx + a12 * dy + a22 * dz) +
      2.0 * (b0 * dx + b1 * dy + b2 * dz) + c + qc[j];
    return weight * (quadric > 0.0 ? quadric : 0.0); // std::max(0.0, quadric), NaN to 0 too
  };
  // Two loops without branches, so that each is vectorised.
  if (paperMetric)
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

Decimator::Choice Decimator::Evaluate(int32_t v0, bool exact, bool allowBound, Workspace& ws) const
{
  Choice choice;
  if (!this->Mesh.IsCollapsible(v0) ||
      (this->Options.PreserveBoundary && this->Mesh.IsBoundaryVertex(v0)))
  {
    return choice;
  }
  if (this->QuadricMetric)
  {
    this->GatherRing(v0, ws.CurrentRing);
    this->CostRingColorQuadric(v0, ws);
  }
  else
  {
    this->PrefetchMetric(v0);
    this->GatherRing(v0, ws.CurrentRing);
    choice.Bound = allowBound && !exact && this->Options.BoundHighValence &&
      ws.CurrentRing.Size > LargeRing && this->Options.Metric == ErrorMetric::HalfEdgeColor &&
      this->UseColor;
    this->CostRing(v0, !choice.Bound, ws);
  }
  const Ring& ring = ws.CurrentRing;
  if (!exact)
  {
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < ring.Size; ++j)
    {
      if (ring.IsCandidate[j] && ws.Costs[j] < best)
      {
        best = ws.Costs[j];
        choice.Target = ring.Vertex[j];
      }
    }
    choice.Cost = best;
    return choice;
  }
  ws.Order.clear();
  for (int j = 0; j < ring.Size; ++j)
  {
    if (ring.IsCandidate[j])
    {
      ws.Order.push_back(j);
    }
  }
  std::sort(ws.Order.begin(), ws.Order.end(),
            [&ws](int a, int b) { return ws.Costs[a] < ws.Costs[b]; });
  for (int j : ws.Order)
  {
    bool legal;
    if (this->Placement)
    {
      double p[3];
      this->PlacementPosition(v0, &ws.Placements[6 * j], p);
      legal = ws.Rules.IsLegal(this->Mesh, this->Positions(), v0, ring.Vertex[j], HotStride, p);
    }
    else
    {
      legal = ws.Rules.IsLegal(this->Mesh, this->Positions(), v0, ring.Vertex[j], HotStride);
    }
    if (legal)
    {
      choice.Target = ring.Vertex[j];
      choice.Cost = ws.Costs[j];
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
  Workspace& ws = this->Main;
  this->GatherRing(v0, ws.CurrentRing);
  for (int j = 0; j < ws.CurrentRing.Size; ++j)
  {
    ws.CurrentRing.IsCandidate[j] = ws.CurrentRing.Vertex[j] == v1;
  }
  if (this->QuadricMetric)
  {
    this->CostRingColorQuadric(v0, ws);
  }
  else
  {
    this->CostRing(v0, true, ws);
  }
  for (int j = 0; j < ws.CurrentRing.Size; ++j)
  {
    if (ws.CurrentRing.Vertex[j] == v1)
    {
      return ws.Costs[j];
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
// The colour quadric (ColorQuadric.h).

void Decimator::Offset6(int32_t v0, int32_t v1, double d[6]) const
{
  const HotVertex& a = this->Hot[v0];
  const HotVertex& b = this->Hot[v1];
  const double w = std::max(this->Options.ColorWeight, 0.0);
  for (int k = 0; k < 3; ++k)
  {
    d[k] = this->CubeScale * (double(b.P[k]) - a.P[k]);
    d[3 + k] = w * (double(b.C[k]) - a.C[k]);
  }
}

void Decimator::PlacementPosition(int32_t v0, const double y[6], double p[3]) const
{
  const HotVertex& a = this->Hot[v0];
  for (int k = 0; k < 3; ++k)
  {
    // Rounded to float as the position will be stored, so that the rules see that point.
    p[k] = static_cast<float>(a.P[k] + y[k] / this->CubeScale);
  }
}

void Decimator::CostRingColorQuadric(int32_t v0, Workspace& ws) const
{
  Ring& ring = ws.CurrentRing;
  const int n = ring.PaddedSize();
  if (ws.Costs.size() < static_cast<size_t>(n))
  {
    ws.Costs.resize(2 * n);
  }
  if (this->Placement && ws.Placements.size() < 6 * static_cast<size_t>(n))
  {
    ws.Placements.resize(12 * n);
  }
  double* costs = ws.Costs.data();
  const HotVertex& hot0 = this->Hot[v0];
  const double g = this->CubeScale;
  const double w = std::max(this->Options.ColorWeight, 0.0);
  const ColorQuadric& q0 = this->ColorQuadrics[v0];
  for (int j = 0; j < ring.Size; ++j)
  {
    const double d[6] = { g * (ring.X[j] - hot0.P[0]), g * (ring.Y[j] - hot0.P[1]),
                          g * (ring.Z[j] - hot0.P[2]), w * (ring.R[j] - hot0.C[0]),
                          w * (ring.G[j] - hot0.C[1]), w * (ring.B[j] - hot0.C[2]) };
    if (this->Placement)
    {
      costs[j] = ring.IsCandidate[j]
        ? this->PlaceCollapse(v0, ring.Vertex[j], d, &ws.Placements[6 * j])
        : std::numeric_limits<double>::infinity();
    }
    else
    {
      // (Q(v0) + Q(j))(xj): Q(v0) is centred at x0, Q(j) at xj (it contributes its constant).
      costs[j] = std::max(0.0, q0.Evaluate(d) + ring.QC[j]);
    }
  }
  for (int j = ring.Size; j < n; ++j)
  {
    costs[j] = std::numeric_limits<double>::infinity();
  }
}

double Decimator::PlaceCollapse(int32_t v0, int32_t v1, const double d01[6], double y[6]) const
{
  // Q = Q(v0) + Q(v1), centred at x0 (Q(v1) is centred at x1 = x0 + d01).
  ColorQuadricD q;
  q.Assign(this->ColorQuadrics[v0]);
  const double d10[6] = { -d01[0], -d01[1], -d01[2], -d01[3], -d01[4], -d01[5] };
  q.AddShifted(this->ColorQuadrics[v1], d10);

  // Where boundaries are preserved, a boundary v1 stays where it is (a half-edge collapse).
  bool placed = !(this->Options.PreserveBoundary && this->Mesh.IsBoundaryVertex(v1)) &&
    MinimizeColorQuadric(q, y);
  if (placed)
  {
    // Guard against nearly singular systems: the minimiser stays near the edge.
    double far = 0.0, length2 = 0.0;
    for (int k = 0; k < 6; ++k)
    {
      const double m = y[k] - 0.5 * d01[k];
      far += m * m;
      length2 += d01[k] * d01[k];
    }
    placed = far <= 4.0 * length2;
  }
  if (placed)
  {
    const double w = std::max(this->Options.ColorWeight, 0.0);
    const HotVertex& a = this->Hot[v0];
    if (w > 0 && this->UseColor)
    {
      // The colour within the displayable range (in the metric's colour space).
      double c[3] = { a.C[0] + y[3] / w, a.C[1] + y[4] / w, a.C[2] + y[5] / w };
      if (ClampMetricColor(this->Options.Space, c))
      {
        for (int k = 0; k < 3; ++k)
        {
          y[3 + k] = w * (c[k] - a.C[k]);
        }
      }
    }
    else
    {
      // No colour to place: v1 keeps its own.
      std::copy(d01 + 3, d01 + 6, y + 3);
    }
    // As the point will be stored (float), so that the cost is the one of that point.
    double p[3];
    this->PlacementPosition(v0, y, p);
    for (int k = 0; k < 3; ++k)
    {
      y[k] = this->CubeScale * (p[k] - a.P[k]);
    }
    if (w > 0 && this->UseColor)
    {
      for (int k = 0; k < 3; ++k)
      {
        const float c = static_cast<float>(a.C[k] + y[3 + k] / w);
        y[3 + k] = w * (double(c) - a.C[k]);
      }
    }
    return std::max(0.0, q.Evaluate(y));
  }
  // The better endpoint; v1's point (a half-edge collapse) unless v0's is better by more
  // than the rounding of the evaluation (so that ties, as on flat uniform patches, do not
  // move vertices for nothing).
  const double at1 = q.Evaluate(d01);
  const double at0 = q.C;
  double trace = 0.0, length2 = 0.0;
  for (int k = 0; k < 6; ++k)
  {
    trace += std::abs(q.GetA(k, k));
    length2 += d01[k] * d01[k];
  }
  if (at0 < at1 - 1e-6 * trace * length2 &&
      !(this->Options.PreserveBoundary && this->Mesh.IsBoundaryVertex(v1)))
  {
    std::fill(y, y + 6, 0.0);
    return std::max(0.0, at0);
  }
  std::copy(d01, d01 + 6, y);
  return std::max(0.0, at1);
}

void Decimator::MergeColorQuadric(int32_t v0, int32_t v1, bool moved, const double y[6])
{
  ColorQuadric& q1 = this->ColorQuadrics[v1];
  const ColorQuadric& q0 = this->ColorQuadrics[v0];
  HotVertex& a = this->Hot[v0];
  HotVertex& b = this->Hot[v1];
  if (!moved)
  {
    double d01[6];
    this->Offset6(v0, v1, d01);
    q1.AddShifted(q0, d01);
    b.QC = q1.C;
    return;
  }
  // The new point, stored, then both quadrics re-centred there.
  const double w = std::max(this->Options.ColorWeight, 0.0);
  HotVertex placed = b;
  double p[3];
  this->PlacementPosition(v0, y, p);
  for (int k = 0; k < 3; ++k)
  {
    placed.P[k] = static_cast<float>(p[k]);
    if (w > 0 && this->UseColor)
    {
      placed.C[k] = static_cast<float>(a.C[k] + y[3 + k] / w);
    }
  }
  double dn0[6], dn1[6];
  for (int k = 0; k < 3; ++k)
  {
    dn0[k] = this->CubeScale * (double(placed.P[k]) - a.P[k]);
    dn1[k] = this->CubeScale * (double(placed.P[k]) - b.P[k]);
    dn0[3 + k] = w * (double(placed.C[k]) - a.C[k]);
    dn1[3 + k] = w * (double(placed.C[k]) - b.C[k]);
  }
  ColorQuadricD sum;
  sum.AddShifted(q0, dn0);
  sum.AddShifted(q1, dn1);
  q1.Assign(sum);
  b.P[0] = placed.P[0];
  b.P[1] = placed.P[1];
  b.P[2] = placed.P[2];
  b.C[0] = placed.C[0];
  b.C[1] = placed.C[1];
  b.C[2] = placed.C[2];
  b.QC = q1.C;
  this->Moved[v1] = 1;
}

void Decimator::GetOutputPosition(int32_t v, double p[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    p[k] = this->FrameCentre[k] + this->Hot[v].P[k] / this->FrameScale;
  }
}

void Decimator::GetOutputColor(int32_t v, double rgb[3]) const
{
  const double c[3] = { this->Hot[v].C[0], this->Hot[v].C[1], this->Hot[v].C[2] };
  MetricColorToRGB(this->UseColor ? this->Options.Space : ColorSpace::RGB, c, rgb);
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = std::min(std::max(rgb[k], 0.0), 1.0);
  }
}

} // namespace colordecimation
