// The template and inline parts of Engine.h (included at its end).

namespace colordecimation
{

inline void EngineBase::GatherRing(int32_t v0, Ring& ring) const
{
  ring.Clear();
  const bool boundary = this->Mesh.IsBoundaryVertex(v0);
  this->Mesh.ForEachNeighbor(v0,
                             [&](int32_t u)
                             {
                               const HotVertex& hot = this->Hot[u];
                               const double p[3] = { hot.P[0], hot.P[1], hot.P[2] };
                               const double c[3] = { hot.C[0], hot.C[1], hot.C[2] };
                               // A boundary vertex only collapses along its boundary: to the
                               // first or last neighbour.
                               const bool candidate =
                                 !this->Mesh.IsLocked(u) && (!boundary || ring.Size == 0);
                               ring.Add(u, p, c, candidate, hot.QC);
                             });
  if (boundary && ring.Size > 0)
  {
    ring.IsCandidate[ring.Size - 1] = !this->Mesh.IsLocked(ring.Vertex[ring.Size - 1]);
    if (this->Seams.GetRole(v0) != SeamMap::None)
    {
      this->RestrictToSeams(v0, ring);
    }
  }
  ring.Pad();
}

inline void EngineBase::PrefetchFanStep(int32_t h) const
{
  const int32_t p = HalfEdgeMesh::Prev(h);
  COLORDECIMATION_PREFETCH(this->Hot.data() + this->Mesh.Origin(p));
  const int32_t next = this->Mesh.Twin(p);
  if (next >= 0)
  {
    this->Mesh.PrefetchFaces(next / 3, next / 3 + 1);
  }
}

inline void EngineBase::RestrictToSeams(int32_t v0, Ring& ring) const
{
  for (const int k : { 0, ring.Size - 1 })
  {
    if (ring.IsCandidate[k] && !this->Seams.Admits(this->Mesh, v0, ring.Vertex[k]))
    {
      ring.IsCandidate[k] = 0;
    }
  }
}

template <typename Metric>
void Engine<Metric>::CostRing(int32_t v0, bool withColorError, Workspace& ws) const
{
  const size_t n = static_cast<size_t>(ws.CurrentRing.PaddedSize());
  if (ws.Costs.size() < n)
  {
    ws.Costs.resize(2 * n);
  }
  this->TheMetric.CostRing(v0, withColorError, ws.CurrentRing, ws.Costs.data(), ws.Scratch);
}

template <typename Metric>
Choice Engine<Metric>::Evaluate(int32_t v0, bool exact, bool allowBound, Workspace& ws) const
{
  Choice choice;
  if (!this->Mesh.IsCollapsible(v0) ||
      (this->Options.PreserveBoundary && this->Mesh.IsBoundaryVertex(v0)))
  {
    return choice;
  }
  this->TheMetric.Prefetch(v0);
  this->GatherRing(v0, ws.CurrentRing);
  choice.Bound = allowBound && !exact && this->TheMetric.KeysByBound(ws.CurrentRing.Size);
  this->CostRing(v0, !choice.Bound, ws);
  if (this->IsTwinned(v0))
  {
    this->AddMirrorCosts(v0, ws);
  }
  if (!exact)
  {
    const Choice cheapest = this->Cheapest(ws.CurrentRing, ws.Costs);
    choice.Target = cheapest.Target;
    choice.Cost = cheapest.Cost;
    return choice;
  }
  return this->CheapestLegal(v0, ws);
}

template <typename Metric>
void Engine<Metric>::AddMirrorCosts(int32_t v0, Workspace& ws) const
{
  Ring& ring = ws.CurrentRing;
  const int32_t t0 = this->Seams.GetTwin(v0);
  if (std::find(ring.IsCandidate.begin(), ring.IsCandidate.begin() + ring.Size, 1) ==
      ring.IsCandidate.begin() + ring.Size)
  {
    return; // no candidate (Admits found t0 locked, or no mirror edge)
  }
  Ring& mirror = ws.MirrorRing;
  this->GatherRing(t0, mirror);
  if (ws.MirrorCosts.size() < static_cast<size_t>(mirror.PaddedSize()))
  {
    ws.MirrorCosts.resize(2 * static_cast<size_t>(mirror.PaddedSize()));
  }
  this->TheMetric.CostRing(t0, true, mirror, ws.MirrorCosts.data(), ws.MirrorScratch);
  for (int j = 0; j < ring.Size; ++j)
  {
    const int32_t m1 = ring.IsCandidate[j] ? this->Seams.MirrorTarget(ring.Vertex[j]) : -1;
    int k = 0;
    while (k < mirror.Size && (mirror.Vertex[k] != m1 || !mirror.IsCandidate[k]))
    {
      ++k;
    }
    if (k < mirror.Size)
    {
      ws.Costs[j] += ws.MirrorCosts[k];
    }
    else
    {
      ring.IsCandidate[j] = 0;
    }
  }
}

template <typename Metric>
Choice Engine<Metric>::Cheapest(const Ring& ring, const std::vector<double>& costs) const
{
  // Equal costs go to the lowest vertex id, not to the first in the fan: the choice does not
  // depend on where the walk around v0 starts (which a neighbour's collapse may move), and
  // ChooseNewNeighbor can update it without the walk.
  Choice choice;
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j < ring.Size; ++j)
  {
    if (ring.IsCandidate[j] &&
        (costs[j] < best || (costs[j] == best && ring.Vertex[j] < choice.Target)))
    {
      best = costs[j];
      choice.Target = ring.Vertex[j];
    }
  }
  choice.Cost = best;
  return choice;
}

template <typename Metric>
Choice Engine<Metric>::CheapestLegal(int32_t v0, Workspace& ws) const
{
  const Ring& ring = ws.CurrentRing;
  ws.Order.clear();
  for (int j = 0; j < ring.Size; ++j)
  {
    if (ring.IsCandidate[j])
    {
      ws.Order.push_back(j);
    }
  }
  // Cost order, equal costs by vertex id (as Cheapest takes them).
  std::sort(ws.Order.begin(), ws.Order.end(),
            [&ws, &ring](int a, int b)
            {
              return ws.Costs[a] < ws.Costs[b] ||
                (ws.Costs[a] == ws.Costs[b] && ring.Vertex[a] < ring.Vertex[b]);
            });
  Choice choice;
  for (int j : ws.Order)
  {
    double p[3];
    bool legal = this->TheMetric.RingPlacement(v0, j, ws.Scratch, p)
      ? ws.Rules.IsLegal(this->Mesh, this->Positions(), v0, ring.Vertex[j], HotStride, p)
      : ws.Rules.IsLegal(this->Mesh, this->Positions(), v0, ring.Vertex[j], HotStride);
    if (legal && this->IsTwinned(v0))
    {
      bool mirrorMoves = false; // a seam pair: its mirror must be legal too (section 15)
      Placement mirrorPlace;
      legal = this->IsMirrorLegal(v0, ring.Vertex[j], mirrorMoves, mirrorPlace, ws);
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

template <typename Metric>
template <typename NewNeighbor>
void Engine<Metric>::EvaluateAll(const int32_t* vertices, size_t count, bool exact, bool allowBound,
                                 double* keys, const NewNeighbor& newNeighbor, bool inIdOrder)
{
  // Each evaluation reads the mesh and the per-vertex state, and writes its own vertex's
  // entries only: the vertices can be shared among threads in any way, with the same result.
  auto evaluate = [this, vertices, exact, allowBound, keys, newNeighbor,
                   inIdOrder](Workspace& ws, size_t begin, size_t end)
  {
    for (size_t i = begin; i < end; ++i)
    {
      this->PrefetchEvaluation(vertices, i, end, !inIdOrder);
      const int32_t v = vertices[i];
      const int32_t v1 = newNeighbor(v);
      if (v1 >= 0 && this->ChooseNewNeighbor(v, v1, keys, ws))
      {
        ++ws.NewNeighborChoices;
        if (this->Options.VerifyNewNeighbors)
        {
          const Choice full = this->Evaluate(v, false, false, ws);
          ws.NewNeighborMismatches += full.Target != this->Best[v] || full.Cost != keys[v];
        }
        continue;
      }
      Choice choice;
      if (!this->Mesh.IsLocked(v) && !this->Mesh.IsRemoved(v))
      {
        choice = this->Evaluate(v, exact, allowBound, ws);
      }
      this->Best[v] = choice.Target;
      this->KeyKinds[v] = choice.Bound ? BoundKey : exact ? LegalKey : CheapestKey;
      keys[v] = choice.Cost;
    }
  };
  // An exact evaluation runs the rules on its choices until one is legal: some times the work.
  constexpr size_t ExactEvaluationWork = 6;
  const int threads = this->ThreadCount(exact ? ExactEvaluationWork * count : count);
  this->ThreadsUsed = std::max(this->ThreadsUsed, threads);
  this->AddWorkers(threads);
  // Each thread its own range, then the chunks left of the others': a core of a virtual machine
  // is often slower than the other for a while, and the faster one waited (docs/BENCHMARK.md).
  constexpr size_t EvaluationChunk = 2048;
  ParallelForChunks(count, threads, EvaluationChunk,
                    [this, evaluate](size_t begin, size_t end, int t)
                    { evaluate(this->GetWorkspace(t), begin, end); });
}

template <typename Metric>
LargeVector<double> Engine<Metric>::EvaluateEveryVertex(bool allowBound)
{
  const int32_t n = this->Mesh.GetNumberOfVertices();
  this->Best.assign(n, -1);
  this->KeyKinds.assign(n, CheapestKey);
  std::vector<int32_t> all(n);
  for (int32_t v = 0; v < n; ++v)
  {
    all[v] = v;
  }
  LargeVector<double> keys(n);
  this->EvaluateAll(
    all.data(), all.size(), false, allowBound, keys.data(), [](int32_t) { return -1; }, true);
  return keys;
}

template <typename Metric>
void Engine<Metric>::PrefetchEvaluation(const int32_t* vertices, size_t i, size_t end,
                                        bool alongFan) const
{
  // The vertex records a few evaluations ahead, then its first face, then the records of that
  // face's other two corners (two of its neighbours). Along the fan (the walk of GatherRing, a
  // chain of dependent loads), the second face with those, and later the third face and the
  // third neighbour (the second face's far corner). Each stage reads only what an earlier one
  // fetched.
  if (i + FarAhead < end)
  {
    const int32_t v = vertices[i + FarAhead];
    this->Mesh.PrefetchVertex(v);
    COLORDECIMATION_PREFETCH(this->Hot.data() + v);
    this->TheMetric.Prefetch(v);
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
      if (alongFan)
      {
        this->PrefetchFanStep(h);
      }
      else
      {
        COLORDECIMATION_PREFETCH(this->Hot.data() + this->Mesh.Origin(HalfEdgeMesh::Prev(h)));
      }
    }
  }
  if (alongFan && i + NearestAhead < end)
  {
    const int32_t h = this->Mesh.FanHalfEdge(vertices[i + NearestAhead], 1);
    if (h >= 0)
    {
      this->PrefetchFanStep(h);
    }
  }
}

template <typename Metric>
bool Engine<Metric>::IsCollapseLegal(int32_t v0, int32_t v1, bool& moves, Placement& place,
                                     Workspace& ws) const
{
  // A full collapse puts v1 at the metric's placement.
  double newPosition[3];
  moves = this->TheMetric.Place(v0, v1, place, newPosition);
  return moves ? ws.Rules.IsLegal(this->Mesh, this->Positions(), v0, v1, HotStride, newPosition)
               : ws.Rules.IsLegal(this->Mesh, this->Positions(), v0, v1, HotStride);
}

template <typename Metric>
typename Engine<Metric>::PairVerdict Engine<Metric>::CheckPair(int32_t v0, int32_t v1, Pair& pair,
                                                               Workspace& ws) const
{
  pair.From[0] = v0;
  pair.To[0] = v1;
  pair.From[1] = this->Seams.GetTwin(v0);
  pair.To[1] = this->Seams.MirrorTarget(v1);
  if (!this->IsCollapseLegal(v0, v1, pair.Moves[0], pair.Place[0], ws) ||
      !this->IsMirrorLegal(v0, v1, pair.Moves[1], pair.Place[1], ws))
  {
    return PairVerdict::Illegal;
  }
  for (int side = 0; side < 2 && this->HasErrorBound(); ++side)
  {
    if (!this->IsWithinErrorBound(pair.From[side], pair.To[side], pair.Moves[side],
                                  pair.Place[side], pair.SquaredError[side]))
    {
      return PairVerdict::Exceeds;
    }
  }
  return PairVerdict::Legal;
}

template <typename Metric>
bool Engine<Metric>::IsMirrorLegal(int32_t v0, int32_t v1, bool& moves, Placement& place,
                                   Workspace& ws) const
{
  const int32_t t0 = this->Seams.GetTwin(v0), m1 = this->Seams.MirrorTarget(v1);
  return t0 >= 0 && m1 >= 0 && SeamMap::AreApart(this->Mesh, v0, v1, t0, m1, ws.SeamScratch) &&
    this->IsCollapseLegal(t0, m1, moves, place, ws);
}

template <typename Metric>
bool Engine<Metric>::IsWithinErrorBound(int32_t v0, int32_t v1, bool moves, const Placement& place,
                                        double& squaredError) const
{
  double x[3];
  if (moves)
  {
    Placement again = place;
    this->TheMetric.Place(v0, v1, again, x);
  }
  else
  {
    const float* p = this->Hot[v1].P;
    std::copy(p, p + 3, x);
  }
  squaredError = this->Errors.SquaredError(v0, v1, x);
  const double bound = this->Errors.GetBound();
  return squaredError <= bound * bound;
}

template <typename Metric>
int Engine<Metric>::ApplyCollapse(int32_t v0, int32_t v1, bool moves, const Placement& place,
                                  Workspace& ws, bool counted)
{
  this->TheMetric.Merge(v0, v1, moves, place);
  if (this->Errors.IsEnabled())
  {
    this->Errors.Merge(v0, v1);
  }
  ws.FormerNeighbors.clear();
  this->Mesh.ForEachNeighbor(v0, [&ws](int32_t u) { ws.FormerNeighbors.push_back(u); });
  this->Best[v0] = -1;
  return counted ? this->Mesh.Collapse(v0, v1) : this->Mesh.CollapseUncounted(v0, v1);
}

template <typename Metric>
template <typename Function, typename Former>
void Engine<Metric>::ForEachAffected(int32_t v1, const std::vector<int32_t>& formerNeighbors,
                                     Function&& f, Former&& former) const
{
  // v1 and v0's former neighbours have a new 1-ring. The other neighbours u of v1 only saw
  // their cost towards v1 grow: only those whose choice was v1 are affected, or, on a seam,
  // whose twin's choice mirrors v1 (the twin's key holds u's cost towards v1; the schedules
  // re-cost the twins of affected seam vertices). After a full collapse every cost towards v1
  // may have changed (its point and quadric both did): its whole new 1-ring, which holds v0's
  // former neighbours, is affected.
  f(v1);
  if (this->TheMetric.MovesVertices())
  {
    this->Mesh.ForEachNeighbor(v1, f);
    return;
  }
  for (int32_t u : formerNeighbors)
  {
    if (u != v1)
    {
      former(u);
    }
  }
  const auto holdsCostTowardsV1 = [this, v1](int32_t u)
  {
    const int32_t twin = this->Seams.GetTwin(u);
    const int32_t mirrored = twin >= 0 ? this->Best[twin] : -1;
    return this->Best[u] == v1 || (mirrored >= 0 && this->Seams.MirrorTarget(mirrored) == v1);
  };
  this->Mesh.ForEachNeighbor(v1,
                             [&formerNeighbors, &f, &holdsCostTowardsV1](int32_t u)
                             {
                               if (holdsCostTowardsV1(u) &&
                                   std::find(formerNeighbors.begin(), formerNeighbors.end(), u) ==
                                     formerNeighbors.end())
                               {
                                 f(u);
                               }
                             });
}

template <typename Metric>
bool Engine<Metric>::ChooseNewNeighbor(int32_t u, int32_t v1, double* keys, Workspace& ws)
{
  const int32_t best = this->Best[u];
  if (!Metric::CostsByPair || best < 0 || best == v1 || this->Mesh.IsRemoved(best) ||
      this->KeyKinds[u] != CheapestKey || !this->Mesh.IsCollapsible(u) ||
      this->Mesh.IsBoundaryVertex(u) || this->IsTwinned(u))
  {
    return false; // v0 was its choice, its cost towards v1 grew, or its ring decides
  }
  if (this->Mesh.IsLocked(v1))
  {
    return true; // no candidate of u: its choice stands
  }
  // The one cost, by the code that costs whole rings (the same arithmetic, bit for bit).
  Ring& ring = ws.PairRing;
  ring.Clear();
  const HotVertex& hot = this->Hot[v1];
  const double p[3] = { hot.P[0], hot.P[1], hot.P[2] };
  const double c[3] = { hot.C[0], hot.C[1], hot.C[2] };
  ring.Add(v1, p, c, true, hot.QC);
  ring.Pad();
  this->TheMetric.CostRing(u, true, ring, ws.PairCosts, ws.Scratch);
  const double cost = ws.PairCosts[0];
  if (cost < keys[u] || (cost == keys[u] && v1 < best)) // as Cheapest breaks ties
  {
    this->Best[u] = v1;
    keys[u] = cost;
  }
  return true;
}

template <typename Metric>
double Engine<Metric>::CollapseCost(int32_t v0, int32_t v1)
{
  if (!this->Mesh.IsCollapsible(v0))
  {
    return -1;
  }
  Workspace& ws = this->Main;
  Ring& ring = ws.CurrentRing;
  this->GatherRing(v0, ring);
  for (int j = 0; j < ring.Size; ++j)
  {
    ring.IsCandidate[j] = ring.Vertex[j] == v1;
  }
  this->CostRing(v0, true, ws);
  for (int j = 0; j < ring.Size; ++j)
  {
    if (ring.Vertex[j] == v1)
    {
      return ws.Costs[j];
    }
  }
  return -1;
}

template <typename Metric>
void Engine<Metric>::CostPieces(DecimatorStatistics& stats)
{
  if constexpr (Metric::CostsPieces)
  {
    // Each piece is costed from its own vertices' states, which nothing writes meanwhile: the
    // pieces can be shared among threads in any way, with the same costs.
    const size_t count = this->Found.Size();
    std::vector<double> costs(count), errors(count, 0.0);
    double* cost = costs.data();
    double* error = errors.data();
    ParallelFor(count, this->ThreadCount(this->Found.Faces.size()),
                [this, cost, error](size_t begin, size_t end, int)
                {
                  std::vector<int32_t> vertices;
                  for (size_t p = begin; p < end; ++p)
                  {
                    this->CostPiece(p, vertices, cost[p], error[p]);
                  }
                });
    this->SmallPieces.Reset(std::move(this->Found), std::move(costs), std::move(errors));
    this->Found = Pieces();
    this->PieceBytes = this->SmallPieces.Bytes();
    stats.Phases.Lap("pieces");
  }
}

template <typename Metric>
void Engine<Metric>::CostPiece(size_t p, std::vector<int32_t>& vertices, double& cost,
                               double& error) const
{
  const int32_t first = this->Found.Start[p];
  PieceVertices(this->Mesh, this->Found.Faces.data() + first,
                size_t(this->Found.Start[p + 1] - first), vertices);
  int32_t best = vertices.front();
  double spread = 0;
  cost = this->Options.PieceWeight *
    this->TheMetric.PieceCost(vertices.data(), vertices.size(), best, spread);
  if (this->Errors.IsEnabled())
  {
    // Removed, its surface is gone: at least as far as its points would travel.
    const float* x = this->Hot[best].P;
    const double at[3] = { x[0], x[1], x[2] };
    error = std::max(this->Errors.PieceSquaredError(vertices.data(), vertices.size(), at), spread);
  }
}

} // namespace colordecimation
