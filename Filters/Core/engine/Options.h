/**
 * @file Options.h
 * @brief What a decimation run is given (options, input) and what it reports (statistics).
 *
 * The method is specified in docs/ALGORITHM.md; the section numbers below refer to it.
 */
#ifndef colordecimation_Options_h
#define colordecimation_Options_h

#include "mesh/HalfEdgeMesh.h"
#include "metric/ColorSpace.h"
#include "util/PhaseTimes.h"

#include <cstddef>
#include <cstdint>
#include <functional>

namespace colordecimation
{

enum class ErrorMetric
{
  HalfEdgeColor = 0,   ///< (1 + Q)(1 + I)(1 + C): the paper's metric (section 4)
  Geometry = 1,        ///< Q alone (half-edge QEM), colour ignored
  ColorQuadric = 2,    ///< Garland-Heckbert's 6-D colour quadric (section 9)
  AttributeQuadric = 3 ///< Hoppe's attribute quadric at the kept vertex (section 12)
};

/// The order in which collapses are made.
enum class CollapseSchedule
{
  /// One at a time, always the cheapest valid collapse of the whole mesh (section 6).
  Greedy = 0,
  /// In passes of the cheapest BatchFraction of the chosen collapses, by blocks of the mesh on
  /// several threads (section 7). The result does not depend on the number of threads.
  Batched = 1
};

/// Called now and then with the fraction of the run done (the set-up's phases its first
/// fifth, the collapses the rest); returning false aborts the run.
using ProgressFunction = std::function<bool(double)>;

/// The core's options. Their defaults are the paper's method (section 4); the VTK filter sets
/// every one from its own properties, whose defaults differ (docs/ALGORITHM.md, section 13).
struct DecimatorOptions
{
  ErrorMetric Metric = ErrorMetric::HalfEdgeColor;
  bool PreserveBoundary = false;
  double MaximumNormalAngle = 90.0; ///< degrees (section 5)
  double GeometryWeight = 1.0;      ///< w in Q' = w Q (section 2); not ColorQuadric
  /// Where colour is measured (every colour term of every metric; section 8).
  ColorSpace Space = ColorSpace::RGB;
  /// ColorQuadric and AttributeQuadric: the colour coordinates are multiplied by this weight.
  double ColorWeight = 1.0;
  /// AttributeQuadric: the weight, in the cost of v0 -> v1, of the error v1 holds already (its
  /// quadric's constant; section 12). 1: the total error (Q0 + Q1)(x1); 0: the error the
  /// collapse adds, Q0(x1), as meshoptimizer's.
  double KeptVertexErrorWeight = 1.0;
  /// ColorQuadric: full collapses, the survivor moved to the minimiser of Q0 + Q1 (section 9).
  bool OptimalPlacement = false;
  /// Weight of Garland-Heckbert's boundary constraint planes (0: none, the paper's metric;
  /// section 3).
  double BoundaryWeight = 0.0;
  /// AttributeQuadric: ColorWeight and BoundaryWeight apply as given to a mesh whose
  /// bounding-box diagonal is at most SceneReferenceDiagonal mean edge lengths; on a more finely
  /// sampled one ColorWeight is scaled by s = SceneWeightScale (engine/Frame.h) and
  /// BoundaryWeight by s^2 (section 12).
  bool SceneRelativeWeights = false;
  /// Weight of the edge-length term of the quadrics (0: none, the paper's metric; section 3):
  /// flat parts are decimated evenly instead of into fans. Not ColorQuadric.
  double EdgeLengthWeight = 0.0;
  /// Key vertices of more than LargeRing neighbours by a lower bound until they reach the top
  /// of the heap (section 6: the same result, less work; off only to test that claim).
  bool BoundHighValence = true;
  /// Decimate meshes of at least LargeMeshVertices points in a spatial order (section 10;
  /// the same collapses up to the order of equal costs; off only to test that claim).
  bool Renumber = true;
  /**
   * Whether Run leaves the per-vertex state (GetMetrics, GetColorQuadrics,
   * GetNormalizedPosition) for every vertex, by input id. Without it, only what the output
   * needs is kept (the mesh, and the moved vertices' records). The filter does without.
   */
  bool KeepVertexState = true;
  CollapseSchedule Schedule = CollapseSchedule::Greedy;
  /// Batched: the share of the candidate collapses that each pass considers, in (0, 1].
  double BatchFraction = 0.25;
  /// Batched: blocks of 2^BlockShift vertex ids, wide blocks of 2^(BlockShift + 3), clamped to
  /// [4, 24]. The result depends on it, never on the number of threads; tests make it small
  /// so that small meshes have many blocks.
  int BlockShift = 14;
  /// Batched, for tests: after each pass, count the block flags that differ from flags
  /// computed afresh (DecimatorStatistics::StaleBlockFlags).
  bool VerifyBlockFlags = false;
  /// Batched, for tests: check each choice made by ChooseNewNeighbor against a full evaluation
  /// (DecimatorStatistics::NewNeighborMismatches).
  bool VerifyNewNeighbors = false;
  /// Batched, for tests: after each pass's re-costing, count the live vertices keyed by their
  /// cheapest collapse whose choice or key differs from a full evaluation
  /// (DecimatorStatistics::StaleKeys).
  bool VerifyKeys = false;
  /// Threads of the parallel phases; 0: one per hardware thread. The result is the same for
  /// any number.
  int NumberOfThreads = 0;
  /// Stop before the first collapse whose geometric error (rules/ErrorBound.h) exceeds this
  /// distance, in the input's units (section 14); <= 0: no bound.
  double MaximumError = 0.0;
  /// Remove small connected pieces whole during the run, when their cost (the metric's cost of
  /// collapsing each into one vertex) times this weight is at most that of the collapses being
  /// made (schedule/PieceQueue.h; section 14). 0: never. With the AttributeQuadric metric only.
  double PieceWeight = 0.0;
  /// When collapses alone leave more than the target, remove whole connected pieces, smallest
  /// area first (mesh/Components.h; section 14). Not after an abort or at MaximumError.
  bool PruneComponents = false;
  /// Collapse the two sides of attribute seams (boundary vertices at bit-identical positions
  /// with their own point data) together, so that they stay closed (mesh/Seams.h; section 15).
  bool PreserveSeams = true;
  /// Keep the collapses made, in order, for levels of detail (lod/CollapseRecord.h; section
  /// 16). Each collapse's geometric error is then measured even without MaximumError.
  bool RecordCollapses = false;
};

struct DecimatorInput
{
  int32_t NumberOfPoints = 0;
  const double* Points = nullptr; ///< 3 per point, original coordinates
  const float* Colors = nullptr;  ///< 3 per point, RGB in [0,1]; null: no colour
  int32_t NumberOfTriangles = 0;
  const int32_t* Triangles = nullptr; ///< 3 point ids per triangle, no repeated id
  const uint8_t* Fixed = nullptr;     ///< optional, 1 per point: non-zero points never collapse
  /**
   * Optional: called once the run has read Points, Colors and Triangles for the last time
   * (after the frame of its set-up), so that the caller can free them before the decimation
   * state grows. Not called with PruneComponents, which reads the points at the end. After
   * it, this input cannot be run again.
   */
  std::function<void()> ReleaseInput;
};

struct DecimatorStatistics
{
  MeshBuildReport Build;
  int64_t InputTriangles = 0;
  int64_t TargetTriangles = 0;
  int64_t OutputTriangles = 0;
  int64_t Collapses = 0;
  int64_t RejectedPops = 0;          ///< chosen collapses that failed the rules and were re-costed
  int64_t Passes = 0;                ///< Batched: re-costing passes
  int Threads = 1;                   ///< the most threads that costed vertices at once
  int CollapseThreads = 1;           ///< Batched: the most threads that collapsed blocks at once
  int WideCollapseThreads = 1;       ///< Batched: the same for the wide blocks
  int64_t StaleBlockFlags = 0;       ///< Batched with VerifyBlockFlags: should be 0
  int64_t NewNeighborChoices = 0;    ///< Batched: re-costings by one new neighbour's cost alone
  int64_t NewNeighborMismatches = 0; ///< of them, with VerifyNewNeighbors: should be 0
  int64_t StaleKeys = 0;             ///< Batched with VerifyKeys: should be 0
  double MeanEdgeLength = 0;         ///< of the input, in its own units (the frame's unit)
  /// The scale s that SceneRelativeWeights applied to the weights (1: none; section 12).
  double SceneWeightScale = 1;
  bool Aborted = false;
  /// With MaximumError: the largest geometric error of the collapses made (input units), and
  /// whether the run stopped at the bound.
  double ActualError = 0;
  bool ErrorBoundReached = false;
  int64_t ReorientedTriangles = 0; ///< reversed to wind their piece one way (section 10)
  int64_t PrunedComponents = 0;    ///< pieces removed whole (PieceWeight, PruneComponents)
  int64_t PrunedTriangles = 0;     ///< their triangles
  int64_t SeamVertices = 0;        ///< vertices on attribute seams (section 15)
  int64_t SeamLockedVertices = 0;  ///< of those, locked (more than one twin)
  size_t StateBytes = 0;           ///< bytes held by the decimator's arrays
  size_t MetricBytesPerVertex = 0; ///< the metric's per-vertex state
  PhaseTimes Phases;               ///< wall-clock seconds of each phase of the run
};

} // namespace colordecimation

#endif
