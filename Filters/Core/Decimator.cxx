#include "Decimator.h"

#include "engine/Engine.h"
#include "mesh/Components.h"
#include "metric/AttributeQuadric.h"
#include "metric/ColorQuadricMetric.h"
#include "schedule/Batched.h"
#include "schedule/Greedy.h"

#include <algorithm>
#include <type_traits>

namespace colordecimation
{
namespace
{
/// The state of a metric of the type the engine runs, or null.
template <typename Metric>
const Metric* MetricOf(const EngineBase* engine)
{
  const auto* typed = dynamic_cast<const Engine<Metric>*>(engine);
  return typed ? &typed->GetMetric() : nullptr;
}

/**
 * Bytes held by the decimator's arrays. Connectivity 24 B/triangle + 5 B/vertex; reference
 * normals 4 B/triangle; the metric's state; hot record 32; Greedy: heap 16 per entry + 20 per
 * vertex; Batched: key 8, stamp 4, the batch (at most a quarter of the vertices, 16 B each,
 * collected by the threads and then copied) 8, the list of affected vertices 4, the list of
 * live vertices and its shrunk copy 8, and the block flags 1; choice 4 + 1; moved flags 1 for
 * a metric that moves vertices; the planes of MaximumError; the flags of reversed triangles, 1
 * per triangle, when the input was oriented; the seams' roles and twins, 5 per vertex, when the
 * input has seams; the maps back from the spatial order, kept to the end.
 */
size_t StateBytes(const DecimatorOptions& options, const DecimatorInput& input, size_t metricBytes,
                  bool moves, bool renumbered, bool reoriented, bool seams)
{
  const size_t n = size_t(input.NumberOfPoints), triangles = size_t(input.NumberOfTriangles);
  const size_t ordering = options.Schedule == CollapseSchedule::Batched ? 33 : 36;
  const size_t bound = options.MaximumError > 0 ? ErrorBound::BytesPerVertex : 0;
  size_t bytes = (24 + sizeof(PackedNormal) + (reoriented ? 1 : 0)) * triangles +
    n *
      (5 + metricBytes + sizeof(HotVertex) + ordering + 4 + 1 + (moves ? 1 : 0) + bound +
       (seams ? 5 : 0));
  if (renumbered)
  {
    bytes += 4 * triangles + 4 * n;
  }
  return bytes;
}

/// The share of the progress the set-up reports, a step for each of its phases (Engine::Start's
/// laps: six, or eight with the pieces) and the rest at its end; the collapses report the rest.
constexpr double SetUpShare = 0.2;
constexpr int SetUpSteps = 8;

/// The engine's set-up, reporting its phases' progress; false when an abort was asked during
/// it (the set-up still ends: the output is written from its mesh).
template <typename Metric>
bool StartReporting(Engine<Metric>& engine, const DecimatorInput& input, DecimatorStatistics& stats,
                    const ProgressFunction& progress)
{
  if (!progress)
  {
    engine.Start(input, stats);
    return true;
  }
  bool go = true;
  int steps = 0;
  const auto report = [&](int step)
  {
    steps = std::min(step, SetUpSteps);
    go = go && progress(SetUpShare * steps / SetUpSteps);
  };
  struct Observed // the observer refers to this frame: it goes with it, also on an exception
  {
    PhaseTimes& Phases;
    ~Observed() { this->Phases.SetObserver(nullptr); }
  } observed{ stats.Phases };
  stats.Phases.SetObserver([&] { report(steps + 1); });
  engine.Start(input, stats);
  report(SetUpSteps);
  return go;
}

/// The schedule's collapses, reporting the rest of the progress.
template <typename Metric>
void Collapse(Engine<Metric>& engine, CollapseSchedule schedule, DecimatorStatistics& stats,
              const ProgressFunction& progress)
{
  ProgressFunction collapsing;
  if (progress)
  {
    collapsing = [&progress](double done)
    { return progress(SetUpShare + (1.0 - SetUpShare) * done); };
  }
  if (schedule == CollapseSchedule::Batched)
  {
    CollapseInBatches(engine, stats, collapsing);
  }
  else
  {
    CollapseGreedily(engine, stats, collapsing);
  }
}
} // namespace

Decimator::Decimator(const DecimatorOptions& options)
  : Options(options)
{
}

Decimator::~Decimator() = default;

DecimatorStatistics Decimator::Run(const DecimatorInput& input, int64_t targetTriangles,
                                   const ProgressFunction& progress)
{
  switch (this->Options.Metric)
  {
    case ErrorMetric::Geometry:
      return this->RunWith<GeometryMetric>(input, targetTriangles, progress);
    case ErrorMetric::ColorQuadric:
      return this->RunWith<ColorQuadricMetric>(input, targetTriangles, progress);
    case ErrorMetric::AttributeQuadric:
      return this->RunWith<AttributeQuadricMetric>(input, targetTriangles, progress);
    default:
      return this->RunWith<HalfEdgeColorMetric>(input, targetTriangles, progress);
  }
}

template <typename Metric>
DecimatorStatistics Decimator::RunWith(const DecimatorInput& input, int64_t targetTriangles,
                                       const ProgressFunction& progress)
{
  auto engine = std::make_unique<Engine<Metric>>(this->Options);
  DecimatorStatistics stats;
  stats.InputTriangles = input.NumberOfTriangles;
  stats.TargetTriangles = std::max<int64_t>(targetTriangles, 0);
  stats.Phases.Start();
  const bool go = StartReporting(*engine, input, stats, progress);
  if constexpr (std::is_same_v<Metric, AttributeQuadricMetric>)
  {
    stats.SceneWeightScale = engine->GetMetric().GetSceneWeightScale();
  }
  if (this->Options.RecordCollapses)
  {
    // Every collapse removes a triangle at least, a removed piece has a row for each of its
    // points (at most three a face): room made once, never moved (the pages not written to
    // are never touched).
    engine->Recorded.reserve(
      size_t(std::max<int64_t>(input.NumberOfTriangles - stats.TargetTriangles, 0) + 64) +
      3 * engine->GetPieceFaces());
  }
  if (go)
  {
    Collapse(*engine, this->Options.Schedule, stats, progress);
  }
  stats.Aborted = stats.Aborted || !go;
  // The schedule's figure is its collapses'; the pieces removed whole count too.
  stats.ActualError =
    std::max(stats.ActualError, engine->ToInputDistance(engine->GetLargestPieceError()));
  stats.Threads = engine->GetThreadsUsed();
  const bool renumbered = engine->IsRenumbered();
  engine->Stop();
  stats.Phases.Lap("restore order");
  if (this->Options.PruneComponents && !stats.Aborted && !stats.ErrorBoundReached)
  {
    const PruneReport pruned =
      PruneComponents(engine->GetMesh(), input.Points, input.Fixed, stats.TargetTriangles);
    stats.PrunedComponents += pruned.Components; // after those PieceWeight removed
    stats.PrunedTriangles += pruned.Triangles;
    stats.Phases.Lap("prune");
  }
  stats.OutputTriangles = engine->GetMesh().GetNumberOfLiveFaces();
  stats.MetricBytesPerVertex = Metric::BytesPerVertex();
  const size_t pieceBytes = engine->GetPieceBytes();
  stats.StateBytes =
    StateBytes(this->Options, input, Metric::BytesPerVertex(), engine->GetMetric().MovesVertices(),
               renumbered, stats.ReorientedTriangles > 0,
               stats.SeamVertices > stats.SeamLockedVertices) +
    pieceBytes;
  if (this->Options.RecordCollapses)
  {
    // The record (32 B a row, and as much again while the schedule collects it) and the
    // error planes it measures with.
    stats.StateBytes += 64 * engine->GetRecord().Size() +
      (this->Options.MaximumError > 0 ? 0
                                      : ErrorBound::BytesPerVertex * size_t(input.NumberOfPoints));
  }
  this->TheEngine = std::move(engine);
  return stats;
}

const HalfEdgeMesh& Decimator::GetMesh() const
{
  static const HalfEdgeMesh empty;
  return this->TheEngine ? this->TheEngine->GetMesh() : empty;
}

const Buffer<VertexMetric>& Decimator::GetMetrics() const
{
  static const Buffer<VertexMetric> none;
  if (const auto* metric = MetricOf<HalfEdgeColorMetric>(this->TheEngine.get()))
  {
    return metric->States;
  }
  const auto* geometry = MetricOf<GeometryMetric>(this->TheEngine.get());
  return geometry ? geometry->States : none;
}

const LargeVector<ColorQuadric>& Decimator::GetColorQuadrics() const
{
  static const LargeVector<ColorQuadric> none;
  const auto* metric = MetricOf<ColorQuadricMetric>(this->TheEngine.get());
  return metric ? metric->States : none;
}

const CollapseRecord& Decimator::GetRecord() const
{
  static const CollapseRecord none;
  return this->TheEngine ? this->TheEngine->GetRecord() : none;
}

bool Decimator::IsFlipped(int32_t t) const
{
  return this->TheEngine && this->TheEngine->IsFlipped(t);
}

bool Decimator::HasMovedVertices() const
{
  return this->TheEngine && this->TheEngine->HasMovedVertices();
}

bool Decimator::IsMoved(int32_t v) const
{
  return this->TheEngine && this->TheEngine->IsMoved(v);
}

void Decimator::GetOutputPosition(int32_t v, double p[3]) const
{
  this->TheEngine->GetFrame().ToInput(this->TheEngine->GetHot()[v].P, p);
}

void Decimator::GetOutputColor(int32_t v, double rgb[3]) const
{
  this->TheEngine->GetOutputColor(v, rgb);
}

const float* Decimator::GetNormalizedPosition(int32_t v) const
{
  return this->TheEngine->GetHot()[v].P;
}

std::vector<float> Decimator::GetNormalizedPositions() const
{
  std::vector<float> positions;
  if (!this->TheEngine)
  {
    return positions;
  }
  const Buffer<HotVertex>& hot = this->TheEngine->GetHot();
  positions.resize(3 * hot.size());
  for (size_t v = 0; v < hot.size(); ++v)
  {
    std::copy(hot[v].P, hot[v].P + 3, positions.begin() + 3 * v);
  }
  return positions;
}

double Decimator::CollapseCost(int32_t v0, int32_t v1)
{
  return this->TheEngine ? this->TheEngine->CollapseCost(v0, v1) : -1.0;
}

} // namespace colordecimation
