/**
 * @file Decimator.h
 * @brief The decimation loop: vertices keyed by their cheapest valid outgoing half-edge
 * collapse, collapsed one at a time from a min-heap (Greedy) or in passes (Batched) until
 * the triangle target is met.
 *
 * Pipeline (in the order Run performs it):
 * 0. meshes of LargeMeshVertices points or more are renumbered in a spatial order
 *    (SpatialOrder.h) for cache locality; everything below runs under the new ids (the
 *    input's arrays read through the map, not copied), and the mesh and per-vertex state are
 *    mapped back to the input's ids at the end;
 * 1. HalfEdgeMesh::Build: connectivity, locking of non-manifold places;
 * 2. the normalised frame: bounding-box centre at the origin, mean edge length 1 (SPEC.md);
 * 3. InitializeVertexMetrics: area-weighted quadrics and visual importance;
 * 4. every vertex costed (Evaluate, on NumberOfThreads threads: EvaluateAll) and, with the
 *    Greedy schedule, pushed on the VertexHeap;
 * 5. Greedy (CollapseGreedily): pop, check CollapseRules, collapse, merge the metric state
 *    (Q and I accumulate into v1), re-cost v1, v0's former neighbours (their 1-ring changed)
 *    and those neighbours of v1 whose chosen target was v1 (its quadric grew).
 *    Batched (CollapseInBatches): take the cheapest BatchFraction of the vertices' chosen
 *    collapses (SelectCheapest, Selection.h), in cost order; make each in turn unless a
 *    collapse before it in this pass affected its vertex or its target (its key is stale) or
 *    the rules forbid it (it is re-costed over its legal collapses); then re-cost every
 *    affected vertex at once, in memory order and on several threads (the scans of a pass
 *    read the list of live vertices, which shrinks with the mesh). The affected vertices
 *    are those Greedy re-costs, so a batch of one is exactly Greedy (tested); larger batches
 *    trade the strict global order for locality and parallelism. The collapses of a pass run
 *    by blocks of vertex ids on several threads, then by wide blocks, then the rest on one
 *    (see CollapseInBatches below). The batch is known in advance, so its neighbourhoods are
 *    prefetched a few collapses ahead.
 *
 * The Greedy loop is bound by memory latency, not arithmetic: each collapse happens
 * somewhere else on the surface and re-costs the 2-ring around it, which is seldom in cache.
 * Three things keep that in check: the spatial order (a neighbourhood spans few cache
 * lines), the walk of PrefetchNeighborhood (the rings of all of v0's neighbours are fetched
 * side by side, so their misses overlap instead of queuing) and the heap's lazy increases
 * (VertexHeap.h).
 *
 * Costing is lazy about legality: a vertex is keyed by its cheapest *admissible* target (the
 * boundary rule and locks only), which is a lower bound of its cheapest *valid* one. When a
 * popped vertex's best collapse turns out illegal, the vertex is re-costed over its legal
 * collapses only and pushed back. Because keys never exceed the true priority, the vertex
 * that is collapsed is always the one with the lowest valid cost, exactly as an eager check of
 * every candidate would choose, at a fraction of the work. The same argument lets the other
 * neighbours of v1 keep their keys: their 1-ring is unchanged and the only cost that moved,
 * towards v1, can only have grown (Q(v1) gained Q(v0) evaluated at p1, which is >= 0).
 *
 * Vertices with no collapse left stay in the heap and are dropped when they reach the top.
 *
 * High-valence vertices (more than LargeRing neighbours, such as the poles of a latitude-
 * longitude sphere) are keyed by a cheap lower bound of their cost, (1 + Q)(1 + I), and get
 * the exact cost, whose colour error is quadratic in the valence, only when they reach the
 * top of the heap: by the same argument the collapse order is unchanged.
 *
 * Data layout: what costing reads of a neighbour (position, colour, the constant term of its
 * quadric) sits in one 32-byte record per vertex, so a neighbour costs one cache line. The
 * flip guard reads each face slot's input normal from one 12-byte record.
 *
 * The comparison metric, ErrorMetric::ColorQuadric (ColorQuadric.h), replaces the 48-byte
 * VertexMetric by a 112-byte 6-D quadric per vertex, in Garland and Heckbert's frame (the
 * bounding box scaled into the unit cube, colour times ColorWeight). Half-edge collapses cost
 * (Q0 + Q1)(x1) and keep the same lazy argument (Q(v1) only grows). With OptimalPlacement the
 * collapse of v0 into v1 is a full collapse: v1 moves to the minimiser of Q0 + Q1 (its colour
 * brought back into the displayable range, the better endpoint when the 6x6 system is
 * singular or its solution lies far from the edge), the rules check the moved triangles of
 * both vertices, and the whole new 1-ring of v1 is re-costed. Colours are measured in RGB or,
 * with ColorSpace::CIELab, in CIELab / 100 (ColorSpace.h), for every metric.
 */
#ifndef colordecimation_Decimator_h
#define colordecimation_Decimator_h

#include "CollapseRules.h"
#include "ColorMetric.h"
#include "ColorQuadric.h"
#include "ColorSpace.h"
#include "HalfEdgeMesh.h"
#include "Prefetch.h"
#include "Selection.h"
#include "SpatialOrder.h"
#include "VertexHeap.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>
#include <functional>
#include <vector>

namespace colordecimation
{

enum class ErrorMetric
{
  HalfEdgeColor = 0, ///< (1 + Q)(1 + I)(1 + C): the paper's metric
  Geometry = 1,      ///< Q alone (half-edge QEM), colour ignored
  ColorQuadric = 2   ///< Garland-Heckbert's 6-D colour quadric (ColorQuadric.h)
};

/// The order in which collapses are made.
enum class CollapseSchedule
{
  /**
   * One at a time, always the cheapest valid collapse of the whole mesh (the paper's
   * order): a min-heap of vertices, the affected neighbours re-costed after each collapse.
   */
  Greedy = 0,
  /**
   * In passes: the cheapest BatchFraction of the vertices' chosen collapses, in cost order,
   * each made unless a collapse earlier in the pass made its cost stale (a neighbour
   * collapsed) or the rules forbid it; then every affected vertex is re-costed, on
   * NumberOfThreads threads. The same cost, rules and re-costing as Greedy; the order is
   * greedy within each batch. Cache-friendly (re-costing sweeps memory in order) and
   * parallel; the result does not depend on the number of threads.
   */
  Batched = 1
};

struct DecimatorOptions
{
  ErrorMetric Metric = ErrorMetric::HalfEdgeColor;
  bool PreserveBoundary = false;
  double MaximumNormalAngle = 90.0; ///< degrees
  double GeometryWeight = 1.0;      ///< w in Q' = w Q (SPEC.md, Frame); not ColorQuadric
  /// Where colour is measured (every colour term of every metric); see ColorSpace.h.
  ColorSpace Space = ColorSpace::RGB;
  /// ColorQuadric: the colour coordinates of R^6 are multiplied by this weight.
  double ColorWeight = 1.0;
  /**
   * ColorQuadric: off, half-edge collapses (v1 stays, cost (Q0 + Q1)(x1)); on, full
   * collapses: the surviving vertex moves to the minimiser of Q0 + Q1 in R^6 (position and
   * colour; colour clamped to the displayable range, endpoints when the system is singular).
   */
  bool OptimalPlacement = false;
  /**
   * Weight of Garland-Heckbert's boundary constraint planes (0: none, the paper's metric):
   * each boundary edge adds to its vertices' quadric the plane through it perpendicular to
   * its triangle, times this weight times the edge's squared length (in the metric's frame:
   * mean edge length 1 for HalfEdgeColor and Geometry, the unit cube for ColorQuadric).
   */
  double BoundaryWeight = 0.0;
  /// Key vertices of more than LargeRing neighbours by a lower bound until they reach the top
  /// of the heap (same result, less work; off only to test that claim).
  bool BoundHighValence = true;
  /**
   * Decimate meshes of at least LargeMeshVertices points in a spatial order
   * (SpatialOrder.h) for cache locality, mapped back to the input's ids at the end. The same
   * collapses up to the order of equal costs; off only to test that claim.
   */
  bool Renumber = true;
  /**
   * Whether Run leaves the per-vertex state (GetMetrics, GetColorQuadrics,
   * GetNormalizedPosition) for every vertex, by input id. Without it, only what the output
   * needs is kept (the mesh, and the moved vertices' records): a renumbered mesh saves mapping
   * the rest back. The filter does without.
   */
  bool KeepVertexState = true;
  CollapseSchedule Schedule = CollapseSchedule::Greedy;
  /// Batched: the share of the candidate collapses that each pass considers, in (0, 1].
  double BatchFraction = 0.25;
  /// Batched: blocks of 2^BlockShift vertex ids, wide blocks of 2^(BlockShift + 3), for the
  /// collapses on several threads (clamped to [4, 24]). The result depends on it, never on the
  /// number of threads; tests make it small so that small meshes have many blocks.
  int BlockShift = 14;
  /// Batched, for tests: after each pass, count the block flags that differ from flags
  /// computed afresh (DecimatorStatistics::StaleBlockFlags).
  bool VerifyBlockFlags = false;
  /// Threads that cost vertices (the initial costs; Batched: the re-costing passes); 0: one
  /// per hardware thread. The result is the same for any number.
  int NumberOfThreads = 0;
};

struct DecimatorInput
{
  int32_t NumberOfPoints = 0;
  const double* Points = nullptr; ///< 3 per point, original coordinates
  const float* Colors = nullptr;  ///< 3 per point, RGB in [0,1]; null: no colour
  int32_t NumberOfTriangles = 0;
  const int32_t* Triangles = nullptr; ///< 3 point ids per triangle, no repeated id
  const uint8_t* Fixed = nullptr;     ///< optional, 1 per point: non-zero points never collapse
};

struct DecimatorStatistics
{
  MeshBuildReport Build;
  int64_t InputTriangles = 0;
  int64_t TargetTriangles = 0;
  int64_t OutputTriangles = 0;
  int64_t Collapses = 0;
  int64_t RejectedPops = 0;    ///< chosen collapses that failed the rules and were re-costed
  int64_t Passes = 0;          ///< Batched: re-costing passes
  int Threads = 1;             ///< the most threads that costed vertices at once
  int CollapseThreads = 1;     ///< Batched: the most threads that collapsed blocks at once
  int WideCollapseThreads = 1; ///< Batched: the same for the wide blocks
  int64_t StaleBlockFlags = 0; ///< Batched with VerifyBlockFlags: should be 0
  double MeanEdgeLength = 0;   ///< of the input, in its own units (the frame's unit)
  bool Aborted = false;
  size_t StateBytes = 0; ///< bytes held by the decimator's arrays
  size_t MetricBytesPerVertex = sizeof(VertexMetric);
};

class VTKCOLORDECIMATION_EXPORT Decimator
{
public:
  explicit Decimator(const DecimatorOptions& options);

  /**
   * Decimate until at most `targetTriangles` remain or no valid collapse is left.
   * `progress(fraction)` is called now and then; returning false aborts (the mesh is left
   * valid, decimated as far as it got).
   */
  DecimatorStatistics Run(const DecimatorInput& input, int64_t targetTriangles,
                          const std::function<bool(double)>& progress = nullptr);

  const HalfEdgeMesh& GetMesh() const { return this->Mesh; }
  /// The per-vertex state of HalfEdgeColor and Geometry (empty with ColorQuadric, or without
  /// KeepVertexState).
  const Buffer<VertexMetric>& GetMetrics() const { return this->Metrics; }
  /// The per-vertex state of ColorQuadric (each centred at its vertex's point of R^6).
  const std::vector<ColorQuadric>& GetColorQuadrics() const { return this->ColorQuadrics; }

  /// Whether a collapse moved a surviving vertex (ColorQuadric with OptimalPlacement).
  bool HasMovedVertices() const { return this->AnyMoved; }
  /// Whether vertex v was moved (and recoloured) by a full collapse.
  bool IsMoved(int32_t v) const { return !this->Moved.empty() && this->Moved[v] != 0; }
  /// The current position of v in the input's units (for moved vertices; float precision).
  void GetOutputPosition(int32_t v, double p[3]) const;
  /// The current colour of v as RGB in [0,1] (for moved vertices).
  void GetOutputColor(int32_t v, double rgb[3]) const;
  /// Position of v in the normalised frame.
  const float* GetNormalizedPosition(int32_t v) const { return this->Hot[v].P; }
  /// Positions in the normalised frame (3 floats per vertex; a copy).
  std::vector<float> GetNormalizedPositions() const;

  /**
   * The cost of v0 -> v1 on the current mesh (no legality check), or a negative value if
   * they are not neighbours. For tests.
   */
  double CollapseCost(int32_t v0, int32_t v1);

private:
  struct Choice
  {
    int32_t Target = -1;
    double Cost = 0;
    bool Bound = false; ///< Cost is only a lower bound (see Evaluate)
  };
  /**
   * Cheapest admissible (exact = false) or legal (exact = true) collapse of v0. With
   * allowBound, a vertex of more than LargeRing neighbours under the paper's metric gets the
   * lower bound (1 + Q)(1 + I) instead (C >= 0): O(k) instead of the O(k^2) colour error.
   */
  /// What costing one vertex writes to: one per thread.
  struct Workspace
  {
    explicit Workspace(const CollapseRules& rules)
      : Rules(rules)
    {
    }
    Ring CurrentRing;
    std::vector<double> Costs;
    std::vector<int> Order;
    std::vector<double> Placements;       ///< ColorQuadric with OptimalPlacement: 6 per ring member
    CollapseRules Rules;                  ///< its own copy (the rules keep scratch)
    std::vector<int32_t> FormerNeighbors; ///< v0's neighbours before the last collapse
    // Batched: what this thread's collapses of a pass produced.
    std::vector<int32_t> Rejected;   ///< vertices whose choice the rules forbade
    std::vector<Candidate> Deferred; ///< candidates reaching out of their block
    Buffer<Candidate> SortRoom;      ///< scratch of SortByKey
    int64_t Collapses = 0, Rejections = 0, RemovedFaces = 0;
    void ClearPass()
    {
      this->Rejected.clear();
      this->Deferred.clear();
      this->Collapses = this->Rejections = this->RemovedFaces = 0;
    }
  };
  Choice Evaluate(int32_t v0, bool exact, bool allowBound, Workspace& ws) const;
  /**
   * Evaluate each listed vertex (none twice) into Best, Bounded and keys[v], on up to
   * ThreadCount threads; locked and removed vertices get no choice.
   */
  void EvaluateAll(const int32_t* vertices, size_t count, bool exact, bool allowBound,
                   double* keys);
  /// Step 4: every vertex's choice into Best and Bounded; returns the keys (by vertex).
  std::vector<double> EvaluateEveryVertex(bool allowBound);
  /// Threads worth starting for this many items of work (vertices to cost, half-edges to pair,
  /// candidates to collapse...): NumberOfThreads at most, MinimumThreadWork items per thread.
  int ThreadCount(size_t items) const;
  /// Make sure there is a workspace for each of `threads` threads.
  void AddWorkers(int threads);
  static constexpr size_t MinimumThreadWork = 4096;
  /// An exact evaluation costs about this many plain ones (measured on the kitchen scan).
  static constexpr size_t ExactEvaluationWork = 6;
  /// So does a candidate in a block (the rules, the collapse, or a skip; kitchen scan: 0.45 to
  /// 0.65 us against 0.2 for a plain evaluation), so a pass's last few thousand candidates
  /// still share the cores.
  static constexpr size_t CandidateWork = 3;
  /// Batched: how many collapses ahead each prefetch stage works.
  static constexpr size_t FarAhead = 16, MiddleAhead = 8, NearAhead = 4;
  /// Batched: a block is swept into the cache (WarmBlock) when it has a candidate per this
  /// many vertex ids at least. Each candidate reads a two-ring of some twenty vertices and
  /// faces, so that most of the block's lines are read either way (kitchen scan: the blocks
  /// of the first 11 passes of 28 and some of the next four; sweeping every block measured
  /// the same, and a threshold of one candidate per 4 ids, which few blocks reach, gained
  /// nothing).
  static constexpr size_t WarmDensity = 16;
  /// Greedy: cost the vertex at the top exactly (exact: over its legal collapses only) and
  /// give it its new key, or take it out of the heap if it has no collapse left.
  void Requeue(int32_t v0, bool exact);
  /// Step 5, Greedy: the heap of vertices, one collapse at a time.
  void CollapseGreedily(DecimatorStatistics& stats, bool prefetch,
                        const std::function<bool(double)>& progress);
  /**
   * Step 5, Batched (CollapseSchedule::Batched). Each pass groups the batch by block (ranges
   * of 2^SmallBlocks.Shift vertex ids, a fixed partition) and runs the blocks on several
   * threads (CollapseBlocks): in each block, in cost order, the collapses whose whole
   * neighbourhood lies inside it (IsInsideBlock); no two threads ever touch the same face or
   * vertex. Those that reach out of their block are deferred to the wide blocks (2^3 small ones
   * each), which run the same way, then to the shifted wide blocks (the same size, moved by half
   * a block, so that the wide blocks' borders lie inside them); what reaches out of those is
   * made afterwards on this thread, in cost order. Then the affected vertices are re-costed.
   * The outcome depends on the blocks, never on the threads.
   */
  void CollapseInBatches(DecimatorStatistics& stats, const std::function<bool(double)>& progress);
  /// A partition of the vertex ids into blocks of 2^Shift ids, the first Offset ids short
  /// (block b: from b 2^Shift - Offset on), and its bit in Interior.
  struct BlockLevel
  {
    int Shift;
    int32_t Offset;
    uint8_t Flag;
    /// The flags of the other partitions whose blocks a block of this one does not lie inside:
    /// the flags a collapse inside it may change.
    uint8_t OtherFlags;
    int32_t BlockOf(int32_t v) const
    {
      return static_cast<int32_t>((static_cast<uint32_t>(v) + uint32_t(this->Offset)) >>
                                  this->Shift);
    }
  };
  /// Blocks of 2^Options.BlockShift ids (16384 by default), wide ones of eight of them, and
  /// wide ones shifted by half their size (the small blocks lie inside both kinds).
  BlockLevel SmallBlocks = { 14, 0, 1, 0 };
  BlockLevel WideBlocks = { 17, 0, 2, 1 | 4 };
  BlockLevel ShiftedBlocks = { 17, 1 << 16, 4, 1 | 2 };
  uint8_t AllBlockFlags() const
  {
    return static_cast<uint8_t>(this->SmallBlocks.Flag | this->WideBlocks.Flag |
                                this->ShiftedBlocks.Flag);
  }
  /// The flags of the partitions where u and v lie in different blocks.
  uint8_t BlockCrossings(int32_t u, int32_t v) const
  {
    uint8_t crossings = 0;
    for (const BlockLevel* level : { &this->SmallBlocks, &this->WideBlocks, &this->ShiftedBlocks })
    {
      crossings |= level->BlockOf(u) != level->BlockOf(v) ? level->Flag : 0;
    }
    return crossings;
  }
  /// The blocks of `level` on several threads (blockStart: where each block's candidates start
  /// in the batch); what reaches out of its block goes to the workspace's Deferred.
  void CollapseBlocks(std::vector<Candidate>& batch, const std::vector<size_t>& blockStart,
                      const BlockLevel& level, int32_t pass);
  void CollapseBlock(Candidate* begin, Candidate* end, int32_t block, const BlockLevel& level,
                     int32_t pass, Workspace& ws);
  /// Fetch the neighbourhoods of candidates[i + a few] into the cache (block >= 0: reading
  /// the records of that block of `level` only).
  void PrefetchCandidates(const Candidate* candidates, size_t i, size_t count, int32_t block,
                          const BlockLevel& level) const;
  /// Sweep the records of `block` (its vertices and faces) into the cache ahead of its
  /// candidates, when it has one per WarmDensity ids at least and BlockFaces is set.
  void WarmBlock(int32_t block, const BlockLevel& level, size_t candidates) const;
  /// Whether every vertex of every face the collapse v0 -> v1 reads or writes is in `block`.
  bool IsInsideBlock(int32_t v0, int32_t v1, int32_t block, const BlockLevel& level) const;
  /// Interior[v] for every vertex (on several threads): for each level, whether all of v's
  /// neighbours are in v's block.
  void FlagEveryInterior();
  /// How many live, unlocked vertices' Interior flags differ from those FlagEveryInterior
  /// would compute now.
  int64_t CountStaleFlags();
  /// The given flags of Interior anew for the listed vertices (after collapses that crossed
  /// blocks of those levels).
  void FlagInterior(const int32_t* vertices, size_t count, uint8_t flags);
  /// Batched: check v0 -> v1, then collapse it and stamp the affected vertices, or stamp v0
  /// as rejected, counting either in ws; `counted`: the mesh counts the removed faces itself
  /// (otherwise they are added to ws.RemovedFaces).
  void TryCollapse(int32_t v0, int32_t v1, int32_t pass, Workspace& ws, bool counted);
  /// The rules' verdict on v0 -> v1; with OptimalPlacement, y is the placement and `moves`
  /// whether it differs from v1's point.
  bool IsCollapseLegal(int32_t v0, int32_t v1, bool& moves, double y[6], Workspace& ws) const;
  /// Merge v0's metric state into v1 and collapse (ws.FormerNeighbors: v0's neighbours
  /// before); the number of faces removed.
  int ApplyCollapse(int32_t v0, int32_t v1, bool moves, const double y[6], Workspace& ws,
                    bool counted);
  /// The vertices whose chosen collapse or its cost the collapse into v1 may have changed.
  template <typename Function>
  void ForEachAffected(int32_t v1, const std::vector<int32_t>& formerNeighbors, Function&& f) const;
  static constexpr int LargeRing = 16;
  /**
   * From this many points on, the decimation's arrays (about 200 bytes per point) are far
   * larger than the cache: the mesh is renumbered and neighbourhoods are prefetched. Below,
   * both cost more than they save (measured: the prefetch walk adds 10 % to the loop on a
   * 41k-point mesh and saves 5 % on a 163k-point one, 15 % on a 655k-point one).
   */
  static constexpr int32_t LargeMeshVertices = 65536;
  /// Map the decimated mesh and the per-vertex state back to the input's ids.
  void RestoreOrder(const SpatialOrder& order);
  void GatherRing(int32_t v0, Ring& ring) const;
  void CostRing(int32_t v0, bool withColorError, Workspace& ws) const;
  void Update(int32_t v);
  /**
   * Bring what re-costing the 2-ring of v0 will read into the cache, walking the rings of all
   * of v0's neighbours side by side so that their cache misses overlap instead of queuing.
   */
  void PrefetchNeighborhood(int32_t v0);
  /// Fetch what evaluating vertices[i + a few] reads into the cache.
  void PrefetchEvaluation(const int32_t* vertices, size_t i, size_t end) const;
  /// Hint that v's metric record is about to be read: both of its ends, since a 48-byte record
  /// straddles two cache lines one time in two.
  void PrefetchMetric(int32_t v) const
  {
    const char* record = reinterpret_cast<const char*>(this->Metrics.data() + v);
    COLORDECIMATION_PREFETCH(record);
    COLORDECIMATION_PREFETCH(record + sizeof(VertexMetric) - 1);
  }
  /// ColorQuadric: cost of every ring member (and, with OptimalPlacement, its placement).
  void CostRingColorQuadric(int32_t v0, Workspace& ws) const;
  /**
   * ColorQuadric with OptimalPlacement: the cost of the full collapse of v0 and v1 and the
   * new vertex's offset y from v0's point of R^6 (d01: v1's offset from v0's point).
   */
  double PlaceCollapse(int32_t v0, int32_t v1, const double d01[6], double y[6]) const;
  /// The offset of v1 from v0 in R^6 (the colour quadric's frame).
  void Offset6(int32_t v0, int32_t v1, double d[6]) const;
  /// A placement offset y from v0 as a position in the normalised frame.
  void PlacementPosition(int32_t v0, const double y[6], double p[3]) const;
  /// ColorQuadric: merge v0 into v1 (placement y from v0 when `moved`).
  void MergeColorQuadric(int32_t v0, int32_t v1, bool moved, const double y[6]);

  /// What costing reads of a vertex, in one record (8 floats).
  struct HotVertex
  {
    float P[3];  ///< position, normalised frame
    float C[3];  ///< colour, RGB in [0,1] (0 without colour)
    float QC;    ///< copy of Metrics[v].Q.C: Q(v) at its own position
    float Spare; ///< keeps the record at 32 bytes
  };
  static constexpr int HotStride = sizeof(HotVertex) / sizeof(float);
  const float* Positions() const { return this->Hot.empty() ? nullptr : this->Hot[0].P; }

  DecimatorOptions Options;
  bool QuadricMetric = false; ///< Options.Metric == ColorQuadric
  bool Placement = false;     ///< ColorQuadric with OptimalPlacement
  double CubeScale = 1.0;     ///< normalised frame -> GH98's unit-cube frame
  double FrameCentre[3] = { 0, 0, 0 };
  double FrameScale = 1.0; ///< input units -> normalised frame
  std::vector<ColorQuadric> ColorQuadrics;
  std::vector<uint8_t> Moved;
  bool AnyMoved = false;
  Workspace Main;                  ///< the calling thread's
  std::vector<Workspace> Workers;  ///< the other threads' (during Run only)
  int ThreadsUsed = 1;             ///< the most threads EvaluateAll started in this Run
  int CollapseThreadsUsed = 1;     ///< the most threads CollapseBlocks started in this Run
  int WideCollapseThreadsUsed = 1; ///< the same, on wide blocks
  Buffer<float> ReferenceNormals;  ///< the input normal of every face slot (CollapseRules)
  HalfEdgeMesh Mesh;
  Buffer<HotVertex> Hot;
  bool UseColor = false;
  Buffer<VertexMetric> Metrics;
  VertexHeap Heap;
  std::vector<int32_t> Best;    ///< vertex -> its chosen target, -1 if none
  std::vector<uint8_t> Bounded; ///< vertex -> its heap key is a lower bound, to be made exact
  std::vector<int32_t> Stamp;   ///< Batched: vertex -> the last pass that made its key stale
  /// Batched: vertex -> for each block level (its Flag), all its neighbours are in its block (a
  /// collapse inside a block never changes that level's flag; one across blocks may, either
  /// way, for v0's former neighbours: FlagInterior)
  std::vector<uint8_t> Interior;
  /// Batched, on a renumbered mesh: BlockFaces[b] is the first face of small block b, i.e.
  /// the first whose smallest vertex is in it or after it (the faces come in that order,
  /// SpatialOrder.h); one entry per block and one more. Empty otherwise: no block is swept.
  std::vector<int32_t> BlockFaces;
  bool Renumbered = false; ///< Run works under SpatialOrder's ids
};

} // namespace colordecimation

#endif
