#include "schedule/Greedy.h"

#include "metric/AttributeQuadric.h"
#include "metric/ColorQuadricMetric.h"
#include "metric/HalfEdgeColor.h"
#include "schedule/VertexHeap.h"

namespace colordecimation
{
namespace
{

/**
 * The heap loop. A popped vertex whose key was a lower bound is costed exactly and pushed
 * back; one whose chosen collapse fails the rules is re-costed over its legal collapses and
 * pushed back; otherwise it collapses and the vertices it affects are re-costed. Vertices with
 * no collapse left stay in the heap until they reach the top.
 */
template <typename Metric>
class GreedySchedule
{
public:
  explicit GreedySchedule(Engine<Metric>& engine)
    : E(engine)
  {
  }

  void Run(DecimatorStatistics& stats, const ProgressFunction& progress)
  {
    this->PushEveryVertex();
    stats.Phases.Lap("first costing");
    const int64_t startFaces = this->E.GetMesh().GetNumberOfLiveFaces();
    const int64_t toRemove = std::max<int64_t>(startFaces - stats.TargetTriangles, 1);
    int64_t nextReport = 0;
    while (this->E.GetMesh().GetNumberOfLiveFaces() > stats.TargetTriangles &&
           !this->Heap.Empty() && !stats.ErrorBoundReached)
    {
      // The pieces cheaper than the collapse at the top go first (its key is a lower bound).
      this->E.RemovePieces(this->Heap.TopKey(), stats.TargetTriangles, stats);
      if (this->E.GetMesh().GetNumberOfLiveFaces() <= stats.TargetTriangles)
      {
        break;
      }
      if (!this->Step(stats))
      {
        continue; // progress is reported after collapses only
      }
      if (progress && stats.Collapses >= nextReport)
      {
        nextReport = stats.Collapses + 8192;
        const double done =
          double(startFaces - this->E.GetMesh().GetNumberOfLiveFaces()) / toRemove;
        if (!progress(std::min(done, 1.0)))
        {
          stats.Aborted = true;
          break;
        }
      }
    }
    stats.ActualError = this->E.ToInputDistance(this->LargestSquaredError);
    stats.Phases.Lap("collapses");
  }

private:
  void PushEveryVertex()
  {
    const int32_t n = this->E.GetMesh().GetNumberOfVertices();
    this->Heap.Reset(n);
    const LargeVector<double> keys = this->E.EvaluateEveryVertex(true);
    for (int32_t v = 0; v < n; ++v)
    {
      if (this->E.Best[v] >= 0)
      {
        this->Heap.Set(v, keys[v]);
      }
    }
  }

  /// The vertex at the top: dropped, re-keyed, or collapsed (then true).
  bool Step(DecimatorStatistics& stats)
  {
    const int32_t v0 = this->Heap.Top();
    const int32_t v1 = this->E.Best[v0];
    if (v1 < 0)
    {
      this->Heap.Pop(); // no collapse left for v0 (removed lazily)
      return false;
    }
    if (this->E.KeyKinds[v0] == Engine<Metric>::BoundKey)
    {
      // Its key was a lower bound (a high-valence vertex): cost it exactly, and back it goes.
      this->E.KeyKinds[v0] = Engine<Metric>::CheapestKey;
      this->Requeue(v0, false);
      return false;
    }
    if (this->E.IsTwinned(v0))
    {
      return this->StepSeam(v0, v1, stats);
    }
    if (this->E.IsLarge())
    {
      this->PrefetchNeighborhood(v0);
    }
    auto& ws = this->E.GetWorkspace(0);
    typename Metric::Placement place;
    bool moves = false;
    if (!this->E.IsCollapseLegal(v0, v1, moves, place, ws))
    {
      ++stats.RejectedPops;
      this->Requeue(v0, true); // over its legal collapses only
      return false;
    }
    double squared = 0;
    if (this->E.HasErrorBound() && !this->KeepsWithinBound(v0, v1, moves, place, squared))
    {
      stats.ErrorBoundReached = true; // the run stops before this collapse
      return false;
    }
    const double cost = this->Heap.TopKey();
    this->Heap.Pop();
    const int removed = this->E.ApplyCollapse(v0, v1, moves, place, ws, true);
    ++stats.Collapses;
    if (this->E.GetOptions().RecordCollapses)
    {
      this->E.Recorded.push_back({ v0, v1, int16_t(removed), 0, 0, cost, squared });
    }
    this->E.ForEachAffected(v1, ws.FormerNeighbors, [this](int32_t u) { this->Update(u); });
    return true;
  }

  /// Step for a twinned v0 (section 15): v0 -> v1 and its mirror twin(v0) -> MirrorTarget(v1),
  /// both made or neither; then the vertices both affect are re-costed.
  bool StepSeam(int32_t v0, int32_t v1, DecimatorStatistics& stats)
  {
    auto& ws = this->E.GetWorkspace(0);
    typename Engine<Metric>::Pair pair;
    const auto verdict = this->E.CheckPair(v0, v1, pair, ws);
    if (verdict == Engine<Metric>::PairVerdict::Illegal)
    {
      ++stats.RejectedPops;
      this->Requeue(v0, true);
      return false;
    }
    if (verdict == Engine<Metric>::PairVerdict::Exceeds)
    {
      stats.ErrorBoundReached = true; // the run stops before this pair
      return false;
    }
    this->LargestSquaredError =
      std::max(this->LargestSquaredError, std::max(pair.SquaredError[0], pair.SquaredError[1]));
    const double cost = this->Heap.TopKey();
    this->Heap.Pop();
    this->Pending.clear();
    for (int side = 0; side < 2; ++side)
    {
      const int removed = this->E.ApplyCollapse(pair.From[side], pair.To[side], pair.Moves[side],
                                                pair.Place[side], ws, true);
      this->E.ForEachAffected(pair.To[side], ws.FormerNeighbors,
                              [this](int32_t u) { this->Pending.push_back(u); });
      if (this->E.GetOptions().RecordCollapses)
      {
        this->E.Recorded.push_back({ pair.From[side], pair.To[side], int16_t(removed),
                                     int16_t(side), 0, cost, pair.SquaredError[side] });
      }
    }
    stats.Collapses += 2;
    for (const int32_t u : this->Pending)
    {
      this->Update(u);
    }
    return true;
  }

  /// Whether v0 -> v1 keeps within MaximumError (its squared error into `squared`); the
  /// largest error so far is kept.
  bool KeepsWithinBound(int32_t v0, int32_t v1, bool moves, const typename Metric::Placement& place,
                        double& squared)
  {
    if (!this->E.IsWithinErrorBound(v0, v1, moves, place, squared))
    {
      return false;
    }
    this->LargestSquaredError = std::max(this->LargestSquaredError, squared);
    return true;
  }

  /// A vertex the collapse affected, and its twin, whose cost holds its mirror (section 15).
  void Update(int32_t v)
  {
    this->UpdateOne(v);
    const int32_t twin = this->E.GetSeams().GetTwin(v);
    if (twin >= 0)
    {
      this->UpdateOne(twin);
    }
  }

  /// One vertex's new choice, keyed by a bound where the metric allows.
  void UpdateOne(int32_t v)
  {
    const HalfEdgeMesh& mesh = this->E.GetMesh();
    if (mesh.IsLocked(v) || mesh.IsRemoved(v))
    {
      return;
    }
    const Choice best = this->E.Evaluate(v, false, true, this->E.GetWorkspace(0));
    this->E.Best[v] = best.Target;
    this->E.KeyKinds[v] = best.Bound ? Engine<Metric>::BoundKey : Engine<Metric>::CheapestKey;
    if (best.Target < 0)
    {
      return; // left in the heap, if it is there, and dropped when it comes to the top
    }
    this->Heap.Set(v, best.Cost);
  }

  /// Cost the vertex at the top exactly (exact: over its legal collapses only) and give it its
  /// new key, or take it out of the heap if it has no collapse left.
  void Requeue(int32_t v0, bool exact)
  {
    const Choice choice = this->E.Evaluate(v0, exact, false, this->E.GetWorkspace(0));
    this->E.Best[v0] = choice.Target;
    if (choice.Target < 0)
    {
      this->Heap.Remove(v0);
    }
    else
    {
      this->Heap.Set(v0, choice.Cost);
    }
  }

  /// Bring what re-costing the 2-ring of v0 will read into the cache, walking the rings of all
  /// of v0's neighbours side by side so that their cache misses overlap instead of queuing.
  void PrefetchNeighborhood(int32_t v0);

  Engine<Metric>& E;
  VertexHeap Heap;
  double LargestSquaredError = 0; ///< of the collapses made, under MaximumError
  std::vector<int32_t> Pending;   ///< StepSeam: the vertices its two collapses affect
};

template <typename Metric>
void GreedySchedule<Metric>::PrefetchNeighborhood(int32_t v0)
{
  constexpr int MaxWalks = 16;
  constexpr int MaxSteps = 16;
  const HalfEdgeMesh& mesh = this->E.GetMesh();
  const HotVertex* hot = this->E.GetHot().data();
  int32_t start[MaxWalks], h[MaxWalks];
  int count = 0;
  mesh.ForEachNeighbor(v0,
                       [&](int32_t u)
                       {
                         if (count < MaxWalks)
                         {
                           this->E.GetMetric().Prefetch(u);
                           COLORDECIMATION_PREFETCH(this->E.Best.data() + u);
                           this->Heap.Prefetch(u);
                           start[count++] = u;
                         }
                       });
  int active = 0;
  for (int i = 0; i < count; ++i)
  {
    const int32_t first = mesh.Outgoing(start[i]);
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
      COLORDECIMATION_PREFETCH(hot + mesh.Target(h[i]));
      const int32_t next = mesh.Twin(HalfEdgeMesh::Prev(h[i]));
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

} // namespace

template <typename Metric>
void CollapseGreedily(Engine<Metric>& engine, DecimatorStatistics& stats,
                      const ProgressFunction& progress)
{
  GreedySchedule<Metric>(engine).Run(stats, progress);
}

template void CollapseGreedily(Engine<HalfEdgeColorMetric>&, DecimatorStatistics&,
                               const ProgressFunction&);
template void CollapseGreedily(Engine<GeometryMetric>&, DecimatorStatistics&,
                               const ProgressFunction&);
template void CollapseGreedily(Engine<ColorQuadricMetric>&, DecimatorStatistics&,
                               const ProgressFunction&);
template void CollapseGreedily(Engine<AttributeQuadricMetric>&, DecimatorStatistics&,
                               const ProgressFunction&);

} // namespace colordecimation
