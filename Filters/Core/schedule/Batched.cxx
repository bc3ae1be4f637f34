#include "schedule/Batched.h"

#include "metric/AttributeQuadric.h"
#include "metric/ColorQuadricMetric.h"
#include "metric/HalfEdgeColor.h"
#include "schedule/Blocks.h"
#include "schedule/Selection.h"
#include "util/Buffer.h"

#include <cmath>
#include <numeric>

namespace colordecimation
{
namespace
{
/// A block is swept into the cache before its collapses (WarmBlock) when it has a candidate per
/// this many vertex ids at least: each candidate reads a two-ring of some twenty vertices and
/// faces, so most of the block's lines are read either way.
constexpr size_t WarmDensity = 16;
/// A candidate in a block costs about this many plain evaluations (the rules, the collapse, or a
/// skip), so that a pass's last few thousand candidates still share the cores.
constexpr size_t CandidateWork = 3;

/// The stamp of a vertex touched once in the pass, as a former neighbour of the v0 of a collapse
/// into v1: NewNeighborStamp + v1 (below -MaxNewNeighbor, clear of the passes and of the
/// rejected ones' -pass). The re-costing offers it to ChooseNewNeighbor.
constexpr int32_t NewNeighborStamp = INT32_MIN;
constexpr int32_t MaxNewNeighbor = int32_t(1) << 30; ///< vertices beyond: no such stamps

inline bool IsNewNeighborStamp(int32_t stamp)
{
  return stamp < -MaxNewNeighbor;
}

/// Whether a stamp marks its vertex as touched in `pass` (its key stale).
inline bool Touched(int32_t stamp, int32_t pass)
{
  return stamp == pass || IsNewNeighborStamp(stamp);
}

/// What one thread's collapses of a pass produced.
struct Lane
{
  std::vector<int32_t> Rejected;   ///< vertices whose choice the rules forbade
  std::vector<Candidate> Deferred; ///< candidates reaching out of their block
  std::vector<int32_t> StaleTwins; ///< twins of affected seam vertices, stamped in Gather
  Buffer<Candidate> SortRoom;      ///< scratch of SortByKey
  int64_t Collapses = 0, Rejections = 0, RemovedFaces = 0;
  double LargestSquaredError = 0; ///< under MaximumError: of the collapses made
  bool Exceeded = false;          ///< a candidate beyond MaximumError was skipped
  /// With RecordCollapses: the collapses made, in the order made, each with its block (Block).
  LargeVector<RecordedCollapse> Record;
  int32_t Block = -1; ///< the block being collapsed (-1: the deferred ones)
  void ClearPass()
  {
    this->Rejected.clear();
    this->Deferred.clear();
    this->Record.clear();
    this->StaleTwins.clear();
    this->Collapses = this->Rejections = this->RemovedFaces = 0;
  }
};

template <typename Metric>
class BatchedSchedule
{
public:
  using Workspace = typename Engine<Metric>::Workspace;

  explicit BatchedSchedule(Engine<Metric>& engine)
    : E(engine)
    , Blocks(engine.GetOptions().BlockShift)
  {
  }

  void Run(DecimatorStatistics& stats, const ProgressFunction& progress)
  {
    this->Start();
    stats.Phases.Lap("first costing");
    const HalfEdgeMesh& mesh = this->E.GetMesh();
    const int64_t startFaces = mesh.GetNumberOfLiveFaces();
    const int64_t toRemove = std::max<int64_t>(startFaces - stats.TargetTriangles, 1);
    int32_t pass = 0;
    while (mesh.GetNumberOfLiveFaces() > stats.TargetTriangles && !stats.Aborted)
    {
      // The pieces up to the cost the last pass reached go before the next batch is chosen.
      this->E.RemovePieces(this->BatchTop, stats.TargetTriangles, stats);
      if (mesh.GetNumberOfLiveFaces() <= stats.TargetTriangles)
      {
        break;
      }
      this->Pass = ++pass;
      if (this->SelectBatch(stats) == 0)
      {
        break;
      }
      stats.Phases.Lap("batch selection");
      this->Affected.clear();
      this->Rejected.clear();
      this->CollapseByBlocks(pass, stats);
      stats.Phases.Lap("block collapses");
      this->CollapseDeferred(pass, stats);
      stats.Phases.Lap("deferred collapses");
      ++stats.Passes;
      if (this->E.GetOptions().VerifyBlockFlags)
      {
        stats.StaleBlockFlags += this->Blocks.CountStaleFlags(mesh, this->FlagThreads());
      }
      if (stats.ErrorBoundReached)
      {
        break; // the pass that met MaximumError is the last
      }
      this->Recost(pass);
      if (this->E.GetOptions().VerifyKeys)
      {
        stats.StaleKeys += this->CountStaleKeys();
      }
      stats.Phases.Lap("re-costing");
      if (progress)
      {
        const double done = double(startFaces - mesh.GetNumberOfLiveFaces()) / toRemove;
        stats.Aborted = !progress(std::min(done, 1.0));
      }
    }
    for (int t = 0; t < this->E.GetNumberOfWorkspaces(); ++t)
    {
      stats.NewNeighborChoices += this->E.GetWorkspace(t).NewNeighborChoices;
      stats.NewNeighborMismatches += this->E.GetWorkspace(t).NewNeighborMismatches;
    }
    stats.CollapseThreads = this->CollapseThreadsUsed;
    stats.WideCollapseThreads = this->WideCollapseThreadsUsed;
    stats.ActualError = this->E.ToInputDistance(this->LargestSquaredError);
    stats.Phases.Lap("batch selection"); // the last (empty) selection, or the last pass's end
  }

private:
  void Start();
  /// The batch: the cheapest fraction of the candidates; returns how many candidates there are.
  size_t SelectBatch(const DecimatorStatistics& stats);
  /// Step 1: the blocks of each level on several threads, each passing on what reaches out of
  /// its blocks to the next level; what is left in Deferred.
  void CollapseByBlocks(int32_t pass, DecimatorStatistics& stats);
  void CollapseLevel(const BlockLevel& level, int32_t pass);
  void CollapseBlock(Candidate* begin, Candidate* end, int32_t block, const BlockLevel& level,
                     int32_t pass, Workspace& ws, Lane& lane);
  /// Step 2: the deferred ones, in cost order, on this thread, up to the target.
  void CollapseDeferred(int32_t pass, DecimatorStatistics& stats);
  /// Step 3: re-cost in vertex order, the rejected ones over their legal collapses only.
  void Recost(int32_t pass);
  /// The live vertices keyed by their cheapest collapse whose choice or key a full evaluation
  /// would change (VerifyKeys: none should).
  int64_t CountStaleKeys();
  /// Check v0 -> v1, then collapse it and stamp the affected vertices, or stamp v0 as rejected;
  /// `counted`: the mesh counts the removed faces itself (otherwise the lane does).
  void TryCollapse(int32_t v0, int32_t v1, int32_t pass, Workspace& ws, Lane& lane, bool counted);
  /// The same for a twinned v0, in step 2 only: v0 -> v1 and its mirror, both or neither
  /// (section 15); the block flags of both brought up to date.
  void TrySeamCollapse(int32_t v0, int32_t v1, int32_t pass, Workspace& ws, Lane& lane);
  /// Stamp the vertices the collapse into v1 affected, and the twins of the seam vertices among
  /// them (whose cost holds their mirror): at once in step 2 (serial), in Gather otherwise.
  void StampWithTwins(int32_t v1, int32_t pass, Workspace& ws, Lane& lane, bool serial);
  /// Add a lane's results of a pass to the pass's lists and to the statistics.
  void Gather(Lane& lane, DecimatorStatistics& stats);
  /// With RecordCollapses: the gathered collapses to the engine's record, by block (blocks are
  /// independent, so any prefix of the record is a mesh some order of them reaches).
  void FlushRecord();
  /// Fetch the neighbourhoods of candidates[i + a few] into the cache (block >= 0: reading
  /// the records of that block of `level` only).
  void PrefetchCandidates(const Candidate* candidates, size_t i, size_t count, int32_t block,
                          const BlockLevel& level) const;
  /// Sweep the records of `block` into the cache ahead of its candidates.
  void WarmBlock(int32_t block, const BlockLevel& level, size_t candidates) const;
  int FlagThreads() const
  {
    return this->E.ThreadCount(3 * static_cast<size_t>(this->E.GetMesh().GetNumberOfFaceSlots()));
  }

  Engine<Metric>& E;
  BlockPartition Blocks;
  LargeVector<double> Keys;
  /// Stamp[v] == pass: v was affected by a collapse of this pass (its key is stale) or its
  /// chosen collapse was found illegal; either way it waits for the re-costing, and does not
  /// collapse in this pass. A new-neighbour stamp (IsNewNeighborStamp) likewise; the re-costing
  /// turns it into the pass's.
  LargeVector<int32_t> Stamp;
  std::vector<Lane> Lanes; ///< one per workspace of the engine
  std::vector<Candidate> Batch, Deferred;
  std::vector<size_t> BlockStart;
  std::vector<int32_t> Affected, Rejected;
  LargeVector<RecordedCollapse> Recorded; ///< gathered from the lanes, to be flushed
  /// The vertices that may have a collapse, in vertex order: the collapsible ones, less those
  /// collapsed away after each pass, so that the scans of a pass shrink with the mesh.
  std::vector<int32_t> Live, Kept;
  int CollapseThreadsUsed = 1;
  int WideCollapseThreadsUsed = 1;
  double LargestSquaredError = 0; ///< of the collapses made, under MaximumError
  double BatchTop = 0;            ///< the largest key of the batches chosen so far
  int32_t Pass = 0;               ///< the pass under way (Gather stamps the stale twins with it)
};

template <typename Metric>
void BatchedSchedule<Metric>::Start()
{
  const HalfEdgeMesh& mesh = this->E.GetMesh();
  const int32_t n = mesh.GetNumberOfVertices();
  this->Keys = this->E.EvaluateEveryVertex(false);
  this->Stamp.assign(n, 0);
  this->Blocks.FlagEveryInterior(mesh, this->FlagThreads());
  if (this->E.IsRenumbered())
  {
    this->Blocks.FindBlockFaces(mesh); // faces in order of their smallest vertex
  }
  CollectInOrder(
    static_cast<size_t>(n), this->E.ThreadCount(static_cast<size_t>(n)),
    [&mesh](size_t v, int32_t& u)
    {
      u = static_cast<int32_t>(v);
      return mesh.IsCollapsible(u);
    },
    this->Live);
}

template <typename Metric>
size_t BatchedSchedule<Metric>::SelectBatch(const DecimatorStatistics& stats)
{
  // No more than the collapses still needed (each removes two triangles, one on a boundary), so
  // that the block phase, which does not stop half-way, ends at the target or one triangle
  // below at the lowest. The batch comes in vertex order, hence grouped by block.
  const int64_t needed = (this->E.GetMesh().GetNumberOfLiveFaces() - stats.TargetTriangles + 1) / 2;
  const double fraction = this->E.GetOptions().BatchFraction;
  const int32_t* best = this->E.Best.data();
  const double* key = this->Keys.data();
  this->Batch.clear();
  const size_t candidates = SelectCheapest(
    this->Live.size(), this->Live.data(),
    [best, key](int32_t v, double& k)
    {
      k = OrderableKey(key[v]);
      return best[v] >= 0;
    },
    [needed, fraction](size_t count)
    {
      return static_cast<size_t>(std::max<int64_t>(
        1,
        std::min<int64_t>(needed,
                          static_cast<int64_t>(std::ceil(fraction * static_cast<double>(count))))));
    },
    this->E.ThreadCount(this->Live.size()), this->Batch);
  for (const Candidate& c : this->Batch)
  {
    this->BatchTop = std::max(this->BatchTop, c.Key);
  }
  return candidates;
}

template <typename Metric>
void BatchedSchedule<Metric>::CollapseByBlocks(int32_t pass, DecimatorStatistics& stats)
{
  const int32_t n = this->E.GetMesh().GetNumberOfVertices();
  for (const BlockLevel& level : this->Blocks)
  {
    if (level.Flag != this->Blocks.Small().Flag)
    {
      // The batch comes in vertex order, those deferred do not.
      std::sort(this->Batch.begin(), this->Batch.end(),
                [](const Candidate& a, const Candidate& b) { return a.Vertex < b.Vertex; });
    }
    this->BlockStart.assign(size_t(level.BlockOf(n)) + 2, 0);
    for (const Candidate& c : this->Batch)
    {
      ++this->BlockStart[size_t(level.BlockOf(c.Vertex)) + 1];
    }
    std::partial_sum(this->BlockStart.begin(), this->BlockStart.end(), this->BlockStart.begin());
    this->CollapseLevel(level, pass);
    this->Deferred.clear();
    for (Lane& lane : this->Lanes)
    {
      this->Gather(lane, stats);
    }
    this->Batch.swap(this->Deferred);
    this->FlushRecord();
  }
  this->Deferred.swap(this->Batch);
}

template <typename Metric>
void BatchedSchedule<Metric>::CollapseLevel(const BlockLevel& level, int32_t pass)
{
  const int32_t blocks = static_cast<int32_t>(this->BlockStart.size()) - 1;
  // A thread is worth it for some thousands of candidates only; either way the blocks are
  // the same, and so is the result.
  const int threads = this->E.ThreadCount(CandidateWork * this->Batch.size());
  int& used = level.Flag != this->Blocks.Small().Flag ? this->WideCollapseThreadsUsed
                                                      : this->CollapseThreadsUsed;
  used = std::max(used, threads);
  this->E.AddWorkers(threads);
  // Every lane starts the pass empty, those of idle threads too (they are gathered).
  this->Lanes.resize(size_t(this->E.GetNumberOfWorkspaces()));
  for (Lane& lane : this->Lanes)
  {
    lane.ClearPass();
  }
  // Each thread collapses its own run of neighbouring blocks, then takes those left in the
  // others' runs (the blocks are independent: where one runs does not change what it gives).
  ParallelForChunks(size_t(blocks), threads, 1,
                    [this, level, pass](size_t begin, size_t end, int t)
                    {
                      for (auto block = static_cast<int32_t>(begin);
                           block < static_cast<int32_t>(end); ++block)
                      {
                        this->CollapseBlock(this->Batch.data() + this->BlockStart[block],
                                            this->Batch.data() + this->BlockStart[block + 1], block,
                                            level, pass, this->E.GetWorkspace(t), this->Lanes[t]);
                      }
                    });
}

template <typename Metric>
void BatchedSchedule<Metric>::CollapseBlock(Candidate* begin, Candidate* end, int32_t block,
                                            const BlockLevel& level, int32_t pass, Workspace& ws,
                                            Lane& lane)
{
  SortByKey(begin, end, lane.SortRoom); // cost order (they come in vertex order)
  lane.Block = block;
  const int32_t* stamp = this->Stamp.data();
  const size_t count = static_cast<size_t>(end - begin);
  this->WarmBlock(block, level, count);
  for (size_t i = 0; i < count; ++i)
  {
    this->PrefetchCandidates(begin, i, count, block, level);
    const int32_t v0 = begin[i].Vertex;
    const int32_t v1 = this->E.Best[v0];
    if (Touched(stamp[v0], pass) || v1 < 0)
    {
      continue; // its key is stale: a neighbour collapsed in this pass
    }
    if (this->E.IsTwinned(v0) ||
        !this->Blocks.IsInsideBlock(this->E.GetMesh(), v0, v1, block, level))
    {
      // Reaching out of the block, or a seam pair, whose mirror may lie in another block.
      lane.Deferred.push_back(begin[i]);
      continue;
    }
    if (Touched(stamp[v1], pass))
    {
      continue;
    }
    const int64_t collapses = lane.Collapses;
    this->TryCollapse(v0, v1, pass, ws, lane, false);
    if (level.OtherFlags != 0 && lane.Collapses != collapses)
    {
      // v0's former neighbours may now have a neighbour in a block of another level (or no
      // longer have one). They are in this block, so no other thread writes their flags; the
      // faces around them are written by collapses of this block only (another block's
      // collapses touch faces whose vertices are all in that block).
      this->Blocks.FlagAfterCollapse(this->E.GetMesh(), v0, v1, ws.FormerNeighbors.data(),
                                     ws.FormerNeighbors.size(), level.OtherFlags);
    }
  }
}

template <typename Metric>
void BatchedSchedule<Metric>::CollapseDeferred(int32_t pass, DecimatorStatistics& stats)
{
  std::sort(this->Deferred.begin(), this->Deferred.end());
  Workspace& ws = this->E.GetWorkspace(0);
  Lane& lane = this->Lanes[0];
  lane.ClearPass();
  lane.Block = -1;
  const HalfEdgeMesh& mesh = this->E.GetMesh();
  for (size_t i = 0; i < this->Deferred.size(); ++i)
  {
    if (mesh.GetNumberOfLiveFaces() <= stats.TargetTriangles)
    {
      break;
    }
    this->PrefetchCandidates(this->Deferred.data(), i, this->Deferred.size(), -1,
                             this->Blocks.Small());
    const int32_t v0 = this->Deferred[i].Vertex;
    const int32_t v1 = this->E.Best[v0];
    if (Touched(this->Stamp[v0], pass) || v1 < 0 || Touched(this->Stamp[v1], pass))
    {
      continue;
    }
    if (this->E.IsTwinned(v0))
    {
      this->TrySeamCollapse(v0, v1, pass, ws, lane);
      continue;
    }
    const int64_t collapses = lane.Collapses;
    this->TryCollapse(v0, v1, pass, ws, lane, true);
    if (lane.Collapses != collapses)
    {
      // v0's former neighbours (v1 among them) may now have one in another block, or no longer
      // have one (a collapse inside a block never changes that block's flags: all it touches
      // is in the block).
      this->Blocks.FlagAfterCollapse(mesh, v0, v1, ws.FormerNeighbors.data(),
                                     ws.FormerNeighbors.size(), this->Blocks.AllFlags());
    }
  }
  this->Gather(lane, stats); // the mesh counted these faces itself: lane.RemovedFaces is 0
  this->FlushRecord();
}

template <typename Metric>
void BatchedSchedule<Metric>::Recost(int32_t pass)
{
  // The affected ones are those stamped with this pass, once the rejected ones are stamped
  // apart (with -pass, which no pass matches); locked ones, which never have a collapse, are
  // not listed.
  for (int32_t v : this->Rejected)
  {
    this->Stamp[v] = -pass;
  }
  // One scan of the live vertices keeps those not collapsed away and lists the affected ones
  // (never collapsed away: a stamped vertex is not collapsed).
  this->Kept.clear();
  const int32_t* before = this->Live.data();
  const int32_t* stamp = this->Stamp.data();
  const HalfEdgeMesh* mesh = &this->E.GetMesh();
  CollectInOrder(
    this->Live.size(), this->E.ThreadCount(this->Live.size()),
    [mesh, before, stamp, pass](size_t i, int32_t& u)
    {
      u = before[i];
      const int alive = mesh->IsRemoved(u) ? 0 : 1;
      return alive | ((alive & (Touched(stamp[u], pass) ? 1 : 0)) << 1);
    },
    this->Kept, this->Affected);
  this->Live.swap(this->Kept);
  // A vertex touched once, as a former neighbour of a v0 collapsed into v1, is offered to
  // ChooseNewNeighbor(v, v1) first (its stamp becomes the pass's).
  int32_t* stamps = this->Stamp.data();
  this->E.EvaluateAll(this->Affected.data(), this->Affected.size(), false, false, this->Keys.data(),
                      [stamps, pass](int32_t v)
                      {
                        const int32_t s = stamps[v];
                        if (!IsNewNeighborStamp(s))
                        {
                          return -1;
                        }
                        stamps[v] = pass;
                        return s - NewNeighborStamp;
                      });
  this->E.EvaluateAll(this->Rejected.data(), this->Rejected.size(), true, false, this->Keys.data());
}

template <typename Metric>
int64_t BatchedSchedule<Metric>::CountStaleKeys()
{
  int64_t stale = 0;
  for (const int32_t v : this->Live)
  {
    if (this->E.KeyKinds[v] == EngineBase::CheapestKey && this->E.GetMesh().IsCollapsible(v))
    {
      const Choice full = this->E.Evaluate(v, false, false, this->E.GetWorkspace(0));
      stale += full.Target != this->E.Best[v] || (full.Target >= 0 && full.Cost != this->Keys[v]);
    }
  }
  return stale;
}

template <typename Metric>
void BatchedSchedule<Metric>::TryCollapse(int32_t v0, int32_t v1, int32_t pass, Workspace& ws,
                                          Lane& lane, bool counted)
{
  int32_t* stamp = this->Stamp.data();
  typename Metric::Placement place;
  bool moves = false;
  if (!this->E.IsCollapseLegal(v0, v1, moves, place, ws))
  {
    stamp[v0] = pass;
    lane.Rejected.push_back(v0);
    ++lane.Rejections;
    return;
  }
  double squared = 0;
  if (this->E.HasErrorBound())
  {
    if (!this->E.IsWithinErrorBound(v0, v1, moves, place, squared))
    {
      lane.Exceeded = true; // skipped, and the run stops after this pass
      return;
    }
    lane.LargestSquaredError = std::max(lane.LargestSquaredError, squared);
  }
  const int removed = this->E.ApplyCollapse(v0, v1, moves, place, ws, counted);
  lane.RemovedFaces += counted ? 0 : removed; // what the mesh has not counted itself
  ++lane.Collapses;
  if (this->E.GetOptions().RecordCollapses)
  {
    lane.Record.push_back({ v0, v1, int16_t(removed), 0, lane.Block, this->Keys[v0], squared });
  }
  if (this->E.GetSeams().Empty())
  {
    // A former neighbour of v0 touched for the first time in this pass remembers v1: when the
    // metric's costs are by pair, the re-costing may only need the cost towards v1.
    const bool byPair = Metric::CostsByPair && this->Stamp.size() <= size_t(MaxNewNeighbor);
    this->E.ForEachAffected(
      v1, ws.FormerNeighbors, [pass, stamp](int32_t u) { stamp[u] = pass; },
      [pass, stamp, byPair, v1](int32_t u)
      { stamp[u] = byPair && !Touched(stamp[u], pass) ? NewNeighborStamp + v1 : pass; });
  }
  else
  {
    this->StampWithTwins(v1, pass, ws, lane, counted);
  }
}

template <typename Metric>
void BatchedSchedule<Metric>::TrySeamCollapse(int32_t v0, int32_t v1, int32_t pass, Workspace& ws,
                                              Lane& lane)
{
  int32_t* stamp = this->Stamp.data();
  const int32_t t0 = this->E.GetSeams().GetTwin(v0), m1 = this->E.GetSeams().MirrorTarget(v1);
  if (m1 < 0 || Touched(stamp[t0], pass) || Touched(stamp[m1], pass))
  {
    return; // the mirror's key is stale: a neighbour collapsed in this pass
  }
  typename Engine<Metric>::Pair pair;
  const auto verdict = this->E.CheckPair(v0, v1, pair, ws);
  if (verdict == Engine<Metric>::PairVerdict::Illegal)
  {
    stamp[v0] = pass;
    lane.Rejected.push_back(v0);
    ++lane.Rejections;
    return;
  }
  if (verdict == Engine<Metric>::PairVerdict::Exceeds)
  {
    lane.Exceeded = true; // skipped, and the run stops after this pass
    return;
  }
  lane.LargestSquaredError =
    std::max(lane.LargestSquaredError, std::max(pair.SquaredError[0], pair.SquaredError[1]));
  for (int side = 0; side < 2; ++side)
  {
    const int removed = this->E.ApplyCollapse(pair.From[side], pair.To[side], pair.Moves[side],
                                              pair.Place[side], ws, true);
    ++lane.Collapses;
    if (this->E.GetOptions().RecordCollapses)
    {
      lane.Record.push_back({ pair.From[side], pair.To[side], int16_t(removed), int16_t(side),
                              lane.Block, this->Keys[v0], pair.SquaredError[side] });
    }
    this->StampWithTwins(pair.To[side], pass, ws, lane, true);
    this->Blocks.FlagAfterCollapse(this->E.GetMesh(), pair.From[side], pair.To[side],
                                   ws.FormerNeighbors.data(), ws.FormerNeighbors.size(),
                                   this->Blocks.AllFlags());
  }
}

template <typename Metric>
void BatchedSchedule<Metric>::StampWithTwins(int32_t v1, int32_t pass, Workspace& ws, Lane& lane,
                                             bool serial)
{
  int32_t* stamp = this->Stamp.data();
  const SeamMap& seams = this->E.GetSeams();
  this->E.ForEachAffected(v1, ws.FormerNeighbors,
                          [pass, stamp, &seams, &lane, serial](int32_t u)
                          {
                            stamp[u] = pass;
                            const int32_t twin = seams.GetTwin(u);
                            if (twin >= 0 && serial)
                            {
                              stamp[twin] = pass;
                            }
                            else if (twin >= 0)
                            {
                              lane.StaleTwins.push_back(twin); // maybe in another block
                            }
                          });
}

template <typename Metric>
void BatchedSchedule<Metric>::Gather(Lane& lane, DecimatorStatistics& stats)
{
  for (const int32_t twin : lane.StaleTwins)
  {
    this->Stamp[twin] = this->Pass;
  }
  this->Rejected.insert(this->Rejected.end(), lane.Rejected.begin(), lane.Rejected.end());
  this->Deferred.insert(this->Deferred.end(), lane.Deferred.begin(), lane.Deferred.end());
  stats.Collapses += lane.Collapses;
  stats.RejectedPops += lane.Rejections;
  stats.ErrorBoundReached = stats.ErrorBoundReached || lane.Exceeded;
  this->LargestSquaredError = std::max(this->LargestSquaredError, lane.LargestSquaredError);
  this->E.GetMesh().RemoveLiveFaces(lane.RemovedFaces);
  this->Recorded.insert(this->Recorded.end(), lane.Record.begin(), lane.Record.end());
}

template <typename Metric>
void BatchedSchedule<Metric>::FlushRecord()
{
  std::stable_sort(this->Recorded.begin(), this->Recorded.end(),
                   [](const RecordedCollapse& a, const RecordedCollapse& b)
                   { return a.Block < b.Block; });
  this->E.Recorded.insert(this->E.Recorded.end(), this->Recorded.begin(), this->Recorded.end());
  this->Recorded.clear();
}

template <typename Metric>
void BatchedSchedule<Metric>::PrefetchCandidates(const Candidate* candidates, size_t i,
                                                 size_t count, int32_t block,
                                                 const BlockLevel& level) const
{
  // The candidates are known in advance: their neighbourhoods are fetched a few collapses
  // ahead, in three stages (the vertex, its first face and target, the target's first face
  // and both metric records, which the collapse merges), none of which waits. In a block
  // (block >= 0) only the block's records are read.
  const HalfEdgeMesh& mesh = this->E.GetMesh();
  const HotVertex* hot = this->E.GetHot().data();
  const int32_t* best = this->E.Best.data();
  const auto mayRead = [block, &level](int32_t v)
  { return block < 0 || level.BlockOf(v) == block; };
  if (i + FarAhead < count)
  {
    const int32_t v = candidates[i + FarAhead].Vertex;
    mesh.PrefetchVertex(v);
    COLORDECIMATION_PREFETCH(this->Stamp.data() + v);
    COLORDECIMATION_PREFETCH(best + v);
  }
  if (i + MiddleAhead < count)
  {
    const int32_t v = candidates[i + MiddleAhead].Vertex;
    mesh.PrefetchFirstFace(v);
    const int32_t target = best[v];
    if (target >= 0 && mayRead(target))
    {
      mesh.PrefetchVertex(target);
      COLORDECIMATION_PREFETCH(this->Stamp.data() + target);
    }
    COLORDECIMATION_PREFETCH(hot + v);
  }
  if (i + NearAhead < count)
  {
    const int32_t v = candidates[i + NearAhead].Vertex;
    const int32_t target = best[v];
    this->E.GetMetric().Prefetch(v);
    this->E.PrefetchError(v);
    if (target >= 0 && mayRead(target))
    {
      mesh.PrefetchFirstFace(target);
      COLORDECIMATION_PREFETCH(hot + target);
      this->E.GetMetric().Prefetch(target);
      this->E.PrefetchError(target);
    }
  }
}

template <typename Metric>
void BatchedSchedule<Metric>::WarmBlock(int32_t block, const BlockLevel& level,
                                        size_t candidates) const
{
  // The candidates come in cost order, and so, in no order the hardware can foresee, do the
  // two-rings the rules walk; swept in address order first, the block's records stream in.
  // The sweep takes the vertex records the rules and the block test read, and the block's
  // faces (fans reaching back into the block before are partly left out).
  const HalfEdgeMesh& mesh = this->E.GetMesh();
  BlockRange range;
  if (candidates * WarmDensity < (size_t(1) << level.Shift) ||
      !this->Blocks.WarmRange(block, level, size_t(mesh.GetNumberOfVertices()), range))
  {
    return;
  }
  const HotVertex* hot = this->E.GetHot().data();
  PrefetchRange(hot + range.FirstVertex, hot + range.EndVertex);
  mesh.PrefetchFaces(range.FirstFace, range.EndFace);
  for (size_t v = range.FirstVertex; v < range.EndVertex; v += 16) // 16 ids to a line
  {
    COLORDECIMATION_PREFETCH(this->E.Best.data() + v);
    COLORDECIMATION_PREFETCH(this->Stamp.data() + v);
    mesh.PrefetchVertex(int32_t(v));
  }
}

} // namespace

template <typename Metric>
void CollapseInBatches(Engine<Metric>& engine, DecimatorStatistics& stats,
                       const ProgressFunction& progress)
{
  BatchedSchedule<Metric>(engine).Run(stats, progress);
}

template void CollapseInBatches(Engine<HalfEdgeColorMetric>&, DecimatorStatistics&,
                                const ProgressFunction&);
template void CollapseInBatches(Engine<GeometryMetric>&, DecimatorStatistics&,
                                const ProgressFunction&);
template void CollapseInBatches(Engine<ColorQuadricMetric>&, DecimatorStatistics&,
                                const ProgressFunction&);
template void CollapseInBatches(Engine<AttributeQuadricMetric>&, DecimatorStatistics&,
                                const ProgressFunction&);

} // namespace colordecimation
