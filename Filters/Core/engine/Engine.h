/**
 * @file Engine.h
 * @brief The mechanism shared by the schedules: the set-up, the choice of each vertex's
 * cheapest collapse (costing), the legality check, the collapse itself with the merge of the
 * metric's state, and the vertices a collapse affects (docs/ALGORITHM.md, sections 6 and 10).
 *
 * EngineBase holds what does not depend on the metric: the mesh, the frame and the hot
 * records, the input normals for the rules, each vertex's chosen target. Engine<Metric> adds
 * the metric, a policy type (metric/AttributeQuadric.h, metric/HalfEdgeColor.h,
 * metric/ColorQuadricMetric.h) that gives
 * the cost of every member of a ring, merges the state of a collapse, and says whether
 * collapses move the survivor. The schedules (schedule/Greedy.h, schedule/Batched.h) are loops
 * over an Engine<Metric>; templates keep the per-candidate calls inlined.
 *
 * Costing is lazy about legality: a vertex is keyed by its cheapest *admissible* target (the
 * boundary rule and locks only), a lower bound of its cheapest *valid* one; a schedule that
 * finds the chosen collapse illegal re-costs the vertex over its legal collapses only
 * (Evaluate with exact = true).
 */
#ifndef colordecimation_Engine_h
#define colordecimation_Engine_h

#include "engine/Frame.h"
#include "engine/Options.h"
#include "lod/CollapseRecord.h"
#include "mesh/HalfEdgeMesh.h"
#include "mesh/Seams.h"
#include "mesh/SpatialOrder.h"
#include "metric/Ring.h"
#include "rules/CollapseRules.h"
#include "rules/ErrorBound.h"
#include "schedule/PieceQueue.h"
#include "util/Buffer.h"
#include "util/Parallel.h"
#include "util/Prefetch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace colordecimation
{

/// How many items ahead each stage of a prefetch pipeline works (the vertex, its first face,
/// its neighbours' records; the evaluations' pipeline goes on along the fan, NearestAhead).
constexpr size_t FarAhead = 16, MiddleAhead = 8, NearAhead = 4, NearestAhead = 2;

/// A vertex's chosen collapse.
struct Choice
{
  int32_t Target = -1;
  double Cost = 0;
  bool Bound = false; ///< Cost is only a lower bound (Evaluate's allowBound)
};

class VTKCOLORDECIMATION_EXPORT EngineBase
{
public:
  explicit EngineBase(const DecimatorOptions& options);
  virtual ~EngineBase();

  /**
   * The set-up before the metric's state: the spatial order of a large mesh, the connectivity
   * (built again with each piece wound one way if the input's winding disagrees; the input's
   * fixed points locked), the frame and the hot records (with colour when
   * useColor), and the input normals that bound each face's drift. movesVertices: the
   * metric's collapses move the survivor (every seam is then locked, section 15).
   */
  void SetUp(const DecimatorInput& input, bool useColor, bool movesVertices,
             DecimatorStatistics& stats);
  /// After the schedule: free what the output does not need and map the mesh back to the
  /// input's ids (keepHot: the hot records are kept, e.g. for moved vertices).
  void Finish(bool keepHot);
  /// The plane sums of the errors (rules/ErrorBound.h), under MaximumError or for a record.
  void InitializeErrors(DecimatorStatistics& stats);

  /**
   * Remove the small pieces whose cost is at most `cost` (schedule/PieceQueue.h) while more
   * than `target` faces are left (the last may take the count below it, as a level of the
   * record would). A piece beyond MaximumError is kept (a piece is apart from the rest: the
   * run goes on, as a level of the record skips it).
   */
  void RemovePieces(double cost, int64_t target, DecimatorStatistics& stats);
  /// The largest squared error (frame units) of the pieces removed so far.
  double GetLargestPieceError() const { return this->LargestPieceError; }
  /// The faces of the pieces that may be removed, and the bytes their queue held.
  size_t GetPieceFaces() const { return this->SmallPieces.FaceTotal(); }
  size_t GetPieceBytes() const { return this->PieceBytes; }

  /// Threads worth starting for this many items of work: NumberOfThreads at most,
  /// MinimumThreadWork items per thread.
  int ThreadCount(size_t items) const;

  const DecimatorOptions& GetOptions() const { return this->Options; }
  HalfEdgeMesh& GetMesh() { return this->Mesh; }
  const HalfEdgeMesh& GetMesh() const { return this->Mesh; }
  const Buffer<HotVertex>& GetHot() const { return this->Hot; }
  const Frame& GetFrame() const { return this->Geometry; }
  bool IsRenumbered() const { return this->Renumbered; }
  /// The attribute seams (mesh/Seams.h; empty without seams or with PreserveSeams off).
  const SeamMap& GetSeams() const { return this->Seams; }
  /// Whether v is a twinned seam vertex: it collapses with its twin, as a pair (section 15).
  bool IsTwinned(int32_t v) const { return this->Seams.GetRole(v) == SeamMap::Twinned; }
  bool IsLarge() const { return this->Large; }
  /// The most threads EvaluateAll started.
  int GetThreadsUsed() const { return this->ThreadsUsed; }
  /// The current colour of v as RGB in [0,1].
  void GetOutputColor(int32_t v, double rgb[3]) const;
  /// Whether input triangle t was reversed to wind its piece one way (section 10).
  bool IsFlipped(int32_t t) const { return !this->Flipped.empty() && this->Flipped[t] != 0; }
  /// Whether a MaximumError bound applies.
  bool HasErrorBound() const { return this->Errors.IsEnabled(); }
  /// Hint that the error of a collapse from or into v is about to be measured.
  void PrefetchError(int32_t v) const { this->Errors.Prefetch(v); }
  /// A squared error of ErrorBound (frame units) as a distance in the input's units.
  double ToInputDistance(double squaredError) const
  {
    return std::sqrt(squaredError) / this->Geometry.Scale;
  }

  // What the facade (Decimator) asks of the metric after a run.
  /// The cost of v0 -> v1 on the current mesh (no legality check), or a negative value if
  /// they are not neighbours.
  virtual double CollapseCost(int32_t v0, int32_t v1) = 0;
  /// Whether vertex v was moved (and recoloured) by a full collapse.
  virtual bool IsMoved(int32_t v) const = 0;
  virtual bool HasMovedVertices() const = 0;
  virtual size_t MetricBytesPerVertex() const = 0;

  /// Each vertex's chosen target, -1 if none (the schedules read it).
  LargeVector<int32_t> Best;
  /// What each vertex's key is (Best's cost, a bound or the cost of the cheapest legal one).
  enum KeyKind : uint8_t
  {
    CheapestKey = 0, ///< the cost of the cheapest admissible collapse
    BoundKey = 1,    ///< a lower bound of it, to be made exact (Greedy)
    LegalKey = 2     ///< the cost of the cheapest legal collapse (an exact evaluation)
  };
  LargeVector<uint8_t> KeyKinds;
  /// With RecordCollapses: the collapses made, in order (the schedules append to it); Finish
  /// turns them into the record.
  LargeVector<RecordedCollapse> Recorded;
  /// The record of the run, by input ids (after Finish).
  const CollapseRecord& GetRecord() const { return this->Record; }

  static constexpr size_t MinimumThreadWork = 4096;
  /// From this many points on, the arrays are far larger than the cache: the mesh is
  /// renumbered and neighbourhoods are prefetched (section 10).
  static constexpr int32_t LargeMeshVertices = 65536;

protected:
  /// The 1-ring of v0 with the targets admissible for a collapse (a boundary vertex only
  /// collapses along its boundary: to its first or last neighbour).
  void GatherRing(int32_t v0, Ring& ring) const;
  /// Hint that the walk of a fan reaches the face after half-edge h's (h in a live face): the
  /// record of the neighbour h's face adds and that next face.
  void PrefetchFanStep(int32_t h) const;
  /// A seam vertex's boundary candidates less those SeamMap::Admits refuses (section 15).
  void RestrictToSeams(int32_t v0, Ring& ring) const;
  const float* Positions() const { return this->Hot.empty() ? nullptr : this->Hot[0].P; }
  /// Map one per-vertex array of a renumbered run back to the input's ids (left as it is when
  /// it does not hold one value per vertex, e.g. released).
  template <typename Values>
  void RestoreValues(Values& values) const
  {
    const auto n = static_cast<int64_t>(this->Order.OldVertex.size());
    if (static_cast<int64_t>(values.size()) == n)
    {
      Permute(values, n, this->Order.OldVertex.data(), 1,
              this->ThreadCount(this->Order.OldFace.size()));
    }
  }
  /// Free the metric's state (what the output does not need, see KeepVertexState).
  virtual void ReleaseMetric() = 0;
  /// Map what is left of the metric's state back to the input's ids.
  virtual void RestoreMetric() = 0;

  DecimatorOptions Options;
  CollapseRuleOptions RuleOptions;
  HalfEdgeMesh Mesh;
  Buffer<HotVertex> Hot;
  Frame Geometry;
  bool UseColor = false;
  bool Large = false;      ///< at least LargeMeshVertices points
  bool Renumbered = false; ///< the run works under SpatialOrder's ids
  SpatialOrder Order;
  Buffer<PackedNormal> ReferenceNormals; ///< the input normal of every face slot (CollapseRules)
  ErrorBound Errors;                     ///< the planes of MaximumError (empty without a bound)
  SeamMap Seams;                         ///< the attribute seams (section 15)
  std::vector<uint8_t> Flipped;          ///< per input triangle: reversed (empty: none was)
  CollapseRecord Record;                 ///< with RecordCollapses, after Finish
  mutable int ThreadsUsed = 1;
  /// With PieceWeight: the pieces a run may remove, found before the metric's state (Found),
  /// then costed (SmallPieces).
  Pieces Found;
  PieceQueue SmallPieces;
  double LargestPieceError = 0;
  size_t PieceBytes = 0;
  /// The pieces that may be removed whole: none with a fixed or seam vertex, nor, with
  /// PreserveBoundary, a boundary one.
  void FindRemovablePieces(DecimatorStatistics& stats);

private:
  /// Append a removed piece's vertices to Recorded, as one step (section 16).
  void RecordPiece(const std::vector<int32_t>& vertices, int64_t faces, double cost,
                   double squaredError);
  void ComputeOrder(const DecimatorInput& input);
  /// The connectivity, then the seams and locked vertices (FindSeamsAndLocks).
  void BuildMesh(const DecimatorInput& input, bool movesVertices, DecimatorStatistics& stats);
  /// The seams of the built mesh (section 15), then the input's fixed points locked.
  void FindSeamsAndLocks(const DecimatorInput& input, bool movesVertices,
                         DecimatorStatistics& stats);
};

/**
 * The engine over one metric. Each thread that costs vertices or collapses has a Workspace;
 * Workspace(0) is the calling thread's.
 */
template <typename Metric>
class Engine final : public EngineBase
{
public:
  using Placement = typename Metric::Placement;

  /// What costing one vertex and collapsing write to: one per thread.
  struct Workspace
  {
    explicit Workspace(const CollapseRules& rules)
      : Rules(rules)
    {
    }
    Ring CurrentRing;
    std::vector<double> Costs;
    std::vector<int> Order;
    typename Metric::Scratch Scratch;
    CollapseRules Rules;                  ///< its own copy (the rules keep scratch)
    std::vector<int32_t> FormerNeighbors; ///< v0's neighbours before the last collapse
    // The mirror side of a seam pair (section 15): its ring, costs and scratch.
    Ring MirrorRing;
    std::vector<double> MirrorCosts;
    typename Metric::Scratch MirrorScratch;
    std::vector<int32_t> SeamScratch;
    Ring PairRing; ///< ChooseNewNeighbor's one candidate
    double PairCosts[4] = {};
    int64_t NewNeighborChoices = 0;    ///< made by EvaluateAll through ChooseNewNeighbor
    int64_t NewNeighborMismatches = 0; ///< of them, unlike Evaluate's (VerifyNewNeighbors)
  };

  explicit Engine(const DecimatorOptions& options)
    : EngineBase(options)
    , TheMetric(options)
    , Main(CollapseRules(this->RuleOptions))
  {
  }

  /// Set-up (EngineBase::SetUp), then the metric's initial state, then the error planes.
  void Start(const DecimatorInput& input, DecimatorStatistics& stats)
  {
    this->SetUp(input, Metric::ReadsColor && input.Colors, this->TheMetric.MovesVertices(), stats);
    const bool pieces = Metric::CostsPieces && this->Options.PieceWeight > 0;
    if (pieces)
    {
      this->FindRemovablePieces(stats); // before the metric's state, the larger memory
    }
    this->TheMetric.Initialize(this->Mesh, this->Geometry, this->Hot, this->UseColor,
                               this->ThreadCount(3 * size_t(input.NumberOfTriangles)));
    this->Main.Rules.SetReferenceNormals(this->ReferenceNormals.data());
    stats.Phases.Lap("metric state");
    this->InitializeErrors(stats); // after the metric's: its pages come first (docs/BENCHMARK.md)
    if (pieces)
    {
      this->CostPieces(stats);
    }
  }
  /// After the schedule: the workers and input normals freed, the order restored.
  void Stop()
  {
    this->Workers.clear();
    this->SmallPieces = PieceQueue();
    this->Main.Rules.SetReferenceNormals(nullptr);
    this->Finish(this->TheMetric.AnyMoved());
  }

  Metric& GetMetric() { return this->TheMetric; }
  const Metric& GetMetric() const { return this->TheMetric; }
  Workspace& GetWorkspace(int t) { return t == 0 ? this->Main : this->Workers[t - 1]; }
  /// Make sure there is a workspace for each of `threads` threads.
  void AddWorkers(int threads)
  {
    while (this->Workers.size() < static_cast<size_t>(threads - 1))
    {
      this->Workers.push_back(this->Main); // its own scratch; the same rules and normals
      this->Workers.back().NewNeighborChoices = this->Workers.back().NewNeighborMismatches = 0;
    }
  }
  int GetNumberOfWorkspaces() const { return 1 + static_cast<int>(this->Workers.size()); }

  /**
   * Cheapest admissible (exact = false) or legal (exact = true) collapse of v0. With
   * allowBound, a vertex the metric keys by a bound (KeysByBound) gets that lower bound.
   */
  Choice Evaluate(int32_t v0, bool exact, bool allowBound, Workspace& ws) const;
  /**
   * Evaluate each listed vertex (none twice) into Best, KeyKinds and keys[v], on up to
   * ThreadCount threads; locked and removed vertices get no choice. A vertex v for which
   * newNeighbor(v) gives a vertex v1 (not -1) is first offered to ChooseNewNeighbor(v, v1).
   * inIdOrder: the vertices come in id order with few gaps (their fans' faces then come in
   * order too, which the hardware streams without the prefetches along the fans).
   */
  template <typename NewNeighbor>
  void EvaluateAll(const int32_t* vertices, size_t count, bool exact, bool allowBound, double* keys,
                   const NewNeighbor& newNeighbor, bool inIdOrder = false);
  void EvaluateAll(const int32_t* vertices, size_t count, bool exact, bool allowBound, double* keys)
  {
    this->EvaluateAll(vertices, count, exact, allowBound, keys, [](int32_t) { return -1; });
  }
  /// Every vertex's choice into Best and KeyKinds; returns the keys (by vertex).
  LargeVector<double> EvaluateEveryVertex(bool allowBound);
  /// Fetch what evaluating vertices[i + a few] reads into the cache; alongFan: the second and
  /// third faces of their fans too.
  void PrefetchEvaluation(const int32_t* vertices, size_t i, size_t end, bool alongFan) const;

  /// The rules' verdict on v0 -> v1; `moves`: the metric's placement moves v1 (into place).
  bool IsCollapseLegal(int32_t v0, int32_t v1, bool& moves, Placement& place, Workspace& ws) const;
  /**
   * For a twinned v0 whose v0 -> v1 is legal: whether the mirror collapse twin(v0) ->
   * MirrorTarget(v1) is legal too and independent of it (SeamMap::AreApart), with its `moves`
   * and `place` (section 15).
   */
  bool IsMirrorLegal(int32_t v0, int32_t v1, bool& moves, Placement& place, Workspace& ws) const;
  /// A seam pair (section 15): v0 -> v1 and its mirror twin(v0) -> MirrorTarget(v1).
  struct Pair
  {
    int32_t From[2];
    int32_t To[2];
    bool Moves[2] = { false, false };
    Placement Place[2];
    double SquaredError[2] = { 0, 0 };
  };
  enum class PairVerdict
  {
    Legal,   ///< both collapses pass the rules (and MaximumError)
    Illegal, ///< one fails the rules
    Exceeds  ///< both pass the rules, one exceeds MaximumError
  };
  /// The verdict on the seam pair of a twinned v0 -> v1, filled into `pair`.
  PairVerdict CheckPair(int32_t v0, int32_t v1, Pair& pair, Workspace& ws) const;

  /**
   * Whether v0 -> v1 (checked legal, with its `moves` and `place`) keeps within MaximumError;
   * its squared error, in the frame's units, into squaredError. Only with HasErrorBound().
   */
  bool IsWithinErrorBound(int32_t v0, int32_t v1, bool moves, const Placement& place,
                          double& squaredError) const;
  /// Merge v0's state into v1 and collapse (ws.FormerNeighbors: v0's neighbours before); the
  /// number of faces removed (`counted`: the mesh counts them itself; see HalfEdgeMesh).
  int ApplyCollapse(int32_t v0, int32_t v1, bool moves, const Placement& place, Workspace& ws,
                    bool counted);
  /// The vertices whose chosen collapse or its cost the collapse into v1 may have changed.
  template <typename Function>
  void ForEachAffected(int32_t v1, const std::vector<int32_t>& formerNeighbors, Function&& f) const
  {
    this->ForEachAffected(v1, formerNeighbors, f, f);
  }
  /// The same, v0's former neighbours (other than v1) given to `former`, the others to `f`.
  template <typename Function, typename Former>
  void ForEachAffected(int32_t v1, const std::vector<int32_t>& formerNeighbors, Function&& f,
                       Former&& former) const;
  /**
   * For u, a former neighbour of a v0 just collapsed into v1 and nothing else changed around it
   * since its last evaluation: when the metric's costs are by pair (CostsByPair), u's key is
   * its cheapest collapse's cost (CheapestKey), u is not on a boundary nor a seam, and its choice
   * was neither v0 nor v1, its choice is updated with
   * the cost of u -> v1 alone (the other candidates' costs have not changed), as Evaluate would
   * choose; returns whether it was. Writes only u's Best and keys[u].
   */
  bool ChooseNewNeighbor(int32_t u, int32_t v1, double* keys, Workspace& ws);

  double CollapseCost(int32_t v0, int32_t v1) override;
  bool IsMoved(int32_t v) const override { return this->TheMetric.IsMoved(v); }
  bool HasMovedVertices() const override { return this->TheMetric.AnyMoved(); }
  size_t MetricBytesPerVertex() const override { return Metric::BytesPerVertex(); }

protected:
  void ReleaseMetric() override { this->TheMetric.Release(); }
  void RestoreMetric() override
  {
    this->TheMetric.Restore([this](auto& values) { this->RestoreValues(values); });
  }

private:
  /// The found pieces' costs and errors, into SmallPieces.
  void CostPieces(DecimatorStatistics& stats);
  /// Piece p of Found: its cost (PieceWeight times the metric's) and squared error.
  void CostPiece(size_t p, std::vector<int32_t>& vertices, double& cost, double& error) const;
  /// Costs of the ring of v0 into ws.Costs.
  void CostRing(int32_t v0, bool withColorError, Workspace& ws) const;
  Choice Cheapest(const Ring& ring, const std::vector<double>& costs) const;
  Choice CheapestLegal(int32_t v0, Workspace& ws) const;
  /// A twinned v0: the cost of each candidate's mirror collapse added to it, candidates without
  /// one dropped (section 15: the cost of a seam collapse counts both sides).
  void AddMirrorCosts(int32_t v0, Workspace& ws) const;

  Metric TheMetric;
  Workspace Main;
  std::vector<Workspace> Workers;
};

} // namespace colordecimation

#include "engine/Engine.txx"

#endif
