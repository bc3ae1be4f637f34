/**
 * @file Decimator.h
 * @brief The decimation as one call: Run() sets up the engine for the chosen metric, runs the
 * chosen schedule until the triangle target is met, and keeps the result for the caller.
 *
 * The method is specified in docs/ALGORITHM.md. The pieces, in the order a run uses them:
 * - engine/Engine.h: set-up (mesh/SpatialOrder.h, mesh/HalfEdgeMesh.h, mesh/Seams.h,
 *   engine/Frame.h), costing, the rules (rules/CollapseRules.h), the collapse and the merge,
 *   the affected vertices, the mapping back to the input's ids;
 * - the metric, a policy of the engine: metric/AttributeQuadric.h (the default: a quadric of
 *   position and colour per vertex, with a colour-gradient term), metric/HalfEdgeColor.h (the
 *   paper's cost, and the quadric alone) or metric/ColorQuadricMetric.h (Garland and
 *   Heckbert's colour quadric);
 * - the schedule, a loop over the engine: schedule/Greedy.h (a min-heap, the paper's order) or
 *   schedule/Batched.h (passes by blocks on several threads);
 * - the stop rules: the target, MaximumError (rules/ErrorBound.h), and after the schedule the
 *   removal of small pieces (mesh/Components.h);
 * - optionally, the record of the collapses made, which holds every coarser level of detail
 *   (lod/CollapseRecord.h).
 */
#ifndef colordecimation_Decimator_h
#define colordecimation_Decimator_h

#include "engine/Options.h"
#include "lod/CollapseRecord.h"
#include "mesh/HalfEdgeMesh.h"
#include "metric/ColorQuadric.h"
#include "metric/HalfEdgeColor.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>
#include <memory>
#include <vector>

namespace colordecimation
{
class EngineBase;

class VTKCOLORDECIMATION_EXPORT Decimator
{
public:
  explicit Decimator(const DecimatorOptions& options);
  ~Decimator();
  Decimator(const Decimator&) = delete;
  Decimator& operator=(const Decimator&) = delete;

  /**
   * Decimate until at most `targetTriangles` remain or no valid collapse is left.
   * `progress(fraction)` is called now and then; returning false aborts (the mesh is left
   * valid, decimated as far as it got).
   */
  DecimatorStatistics Run(const DecimatorInput& input, int64_t targetTriangles,
                          const ProgressFunction& progress = nullptr);

  /// The decimated mesh, by input ids (empty before Run).
  const HalfEdgeMesh& GetMesh() const;
  /// The per-vertex state of HalfEdgeColor and Geometry (empty with ColorQuadric or
  /// AttributeQuadric, or without KeepVertexState).
  const Buffer<VertexMetric>& GetMetrics() const;
  /// The per-vertex state of ColorQuadric (each centred at its vertex's point of R^6).
  const LargeVector<ColorQuadric>& GetColorQuadrics() const;

  /// With RecordCollapses: the collapses made, in order, by input ids (lod/CollapseRecord.h).
  const CollapseRecord& GetRecord() const;

  /**
   * Whether input triangle t was decimated reversed, so that its piece is wound one way (the
   * mesh's face t then runs the other way round from the input's triangle t).
   */
  bool IsFlipped(int32_t t) const;

  /// Whether a collapse moved a surviving vertex (ColorQuadric with OptimalPlacement).
  bool HasMovedVertices() const;
  /// Whether vertex v was moved (and recoloured) by a full collapse.
  bool IsMoved(int32_t v) const;
  /// The current position of v in the input's units (for moved vertices; float precision).
  void GetOutputPosition(int32_t v, double p[3]) const;
  /// The current colour of v as RGB in [0,1] (for moved vertices).
  void GetOutputColor(int32_t v, double rgb[3]) const;
  /// Position of v in the normalised frame.
  const float* GetNormalizedPosition(int32_t v) const;
  /// Positions in the normalised frame (3 floats per vertex; a copy).
  std::vector<float> GetNormalizedPositions() const;

  /**
   * The cost of v0 -> v1 on the current mesh (no legality check), or a negative value if
   * they are not neighbours. For tests.
   */
  double CollapseCost(int32_t v0, int32_t v1);

private:
  template <typename Metric>
  DecimatorStatistics RunWith(const DecimatorInput& input, int64_t targetTriangles,
                              const ProgressFunction& progress);

  DecimatorOptions Options;
  std::unique_ptr<EngineBase> TheEngine; ///< an Engine<Metric> of the options' metric
};

} // namespace colordecimation

#endif
