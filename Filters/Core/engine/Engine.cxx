#include "engine/Engine.h"

#include "mesh/Components.h"
#include "mesh/Orientation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace colordecimation
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double MaximumDriftAngle = 75.0; ///< degrees (section 5)

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

EngineBase::EngineBase(const DecimatorOptions& options)
  : Options(options)
  , RuleOptions(MakeRuleOptions(options))
{
}

EngineBase::~EngineBase() = default;

int EngineBase::ThreadCount(size_t items) const
{
  return ThreadsFor(items, this->Options.NumberOfThreads, MinimumThreadWork);
}

void EngineBase::SetUp(const DecimatorInput& input, bool useColor, bool movesVertices,
                       DecimatorStatistics& stats)
{
  const int32_t n = input.NumberOfPoints;
  this->ComputeOrder(input);
  stats.Phases.Lap("spatial order");
  this->BuildMesh(input, movesVertices, stats);
  stats.Phases.Lap("connectivity");
  const int32_t* source = this->Renumbered ? this->Order.OldVertex.data() : nullptr;
  this->Geometry = MeasureFrame(this->Mesh, input.Points, source, stats.Build.IsolatedVertices > 0,
                                this->ThreadCount(size_t(n)));
  stats.MeanEdgeLength = this->Geometry.MeanEdgeLength;
  this->UseColor = useColor;
  FillHotRecords(this->Geometry, n, input.Points, useColor ? input.Colors : nullptr, source,
                 this->Options.Space, this->ThreadCount(size_t(n)), this->Hot);
  if (input.ReleaseInput && !this->Options.PruneComponents)
  {
    input.ReleaseInput(); // the rest reads the engine's own copies
  }
  stats.Phases.Lap("frame");
  // Each face slot's input normal bounds how far collapses may turn it, in total.
  CollapseRules::ComputeReferenceNormals(this->Mesh, this->Positions(), HotStride,
                                         this->ReferenceNormals,
                                         this->ThreadCount(size_t(input.NumberOfTriangles)));
  stats.Phases.Lap("reference normals");
  this->Record.Clear();
  this->Record.InputPoints = n;
  this->Record.InputTriangles = input.NumberOfTriangles;
  this->Recorded.clear();
  this->ThreadsUsed = 1;
}

void EngineBase::FindRemovablePieces(DecimatorStatistics& stats)
{
  const HalfEdgeMesh& mesh = this->Mesh;
  const SeamMap& seams = this->Seams;
  const bool boundary = this->Options.PreserveBoundary;
  this->Found = FindSmallPieces(
    mesh,
    [&](int32_t v)
    {
      return mesh.IsFixed(v) || seams.GetRole(v) != SeamMap::None ||
        (boundary && !mesh.IsLocked(v) && mesh.IsBoundaryVertex(v));
    },
    this->ThreadCount(size_t(mesh.GetNumberOfFaceSlots())));
  this->SmallPieces = PieceQueue();
  this->LargestPieceError = 0;
  this->PieceBytes = 0;
  stats.Phases.Lap("pieces");
}

void EngineBase::RemovePieces(double cost, int64_t target, DecimatorStatistics& stats)
{
  std::vector<int32_t> faces, vertices;
  while (!this->SmallPieces.IsEmpty() && this->SmallPieces.NextCost() <= cost &&
         this->Mesh.GetNumberOfLiveFaces() > target)
  {
    const double squared = this->SmallPieces.NextSquaredError();
    const double bound = this->Errors.GetBound();
    const double pieceCost = this->SmallPieces.NextCost();
    this->SmallPieces.Pop(this->Mesh, faces, vertices);
    if (this->Options.MaximumError > 0 && squared > bound * bound)
    {
      continue; // kept
    }
    const auto n = static_cast<int64_t>(faces.size());
    if (n == 0 || n > INT16_MAX * static_cast<int64_t>(vertices.size()))
    {
      continue; // none left, or more faces than the record's rows can count (hostile input)
    }
    this->Mesh.RemoveComponent(faces.data(), static_cast<int32_t>(n));
    for (const int32_t v : vertices)
    {
      this->Best[v] = -1;
    }
    if (this->Options.RecordCollapses)
    {
      this->RecordPiece(vertices, n, pieceCost, squared);
    }
    this->LargestPieceError = std::max(this->LargestPieceError, squared);
    ++stats.PrunedComponents;
    stats.PrunedTriangles += n;
  }
}

void EngineBase::RecordPiece(const std::vector<int32_t>& vertices, int64_t faces, double cost,
                             double squaredError)
{
  // One entry a vertex, into no survivor (-1); the faces shared out in chunks that fit the
  // entries' 16 bits, all but the first marked as continuing the step (CollapseRecord::Append).
  int64_t left = faces;
  for (size_t i = 0; i < vertices.size(); ++i)
  {
    const auto share = static_cast<int16_t>(std::min<int64_t>(left, INT16_MAX));
    left -= share;
    this->Recorded.push_back(
      { vertices[i], -1, share, static_cast<int16_t>(i > 0 ? 1 : 0), -1, cost, squaredError });
  }
}

void EngineBase::InitializeErrors(DecimatorStatistics& stats)
{
  // A record measures every collapse's error: an infinite bound, if none is given.
  const double bound = this->Options.MaximumError > 0 ? this->Options.MaximumError
    : this->Options.RecordCollapses                   ? std::numeric_limits<double>::infinity()
                                                      : 0.0;
  this->Errors.Initialize(this->Mesh, this->Positions(), HotStride, bound * this->Geometry.Scale,
                          this->ThreadCount(size_t(this->Mesh.GetNumberOfVertices())));
  stats.Phases.Lap("error planes");
}

void EngineBase::ComputeOrder(const DecimatorInput& input)
{
  // A large mesh is decimated in a spatial order, under new vertex and face ids, and mapped
  // back to its own ids at the end. The input's arrays are read through the map (OldVertex:
  // the input's id of each vertex), not copied.
  this->Large = input.NumberOfPoints >= LargeMeshVertices;
  this->Renumbered = this->Options.Renumber && this->Large;
  this->Order = SpatialOrder();
  if (this->Renumbered)
  {
    ComputeSpatialOrder(input.NumberOfPoints, input.Points, input.NumberOfTriangles,
                        input.Triangles, this->Order,
                        this->ThreadCount(size_t(input.NumberOfPoints)));
  }
}

void EngineBase::BuildMesh(const DecimatorInput& input, bool movesVertices,
                           DecimatorStatistics& stats)
{
  const int32_t n = input.NumberOfPoints;
  const auto build = [this, &input, &stats, n](const int32_t* triangles)
  {
    stats.Build = this->Mesh.Build(n, triangles, input.NumberOfTriangles,
                                   this->ThreadCount(3 * size_t(input.NumberOfTriangles)),
                                   this->Renumbered ? this->Order.OldFace.data() : nullptr,
                                   this->Renumbered ? this->Order.NewVertex.data() : nullptr);
  };
  build(input.Triangles);
  this->Flipped = std::vector<uint8_t>();
  if (stats.Build.MisorientedEdges > 0)
  {
    // Triangles wound both ways: built again, each piece wound one way (section 10).
    std::vector<int32_t> oriented;
    this->Flipped = OrientTriangles(input.Triangles, input.NumberOfTriangles, oriented);
    stats.ReorientedTriangles = std::count(this->Flipped.begin(), this->Flipped.end(), 1);
    if (stats.ReorientedTriangles > 0)
    {
      build(oriented.data());
    }
    else
    {
      this->Flipped = std::vector<uint8_t>(); // only non-orientable places: as built
    }
  }
  this->Order.NewVertex = Buffer<int32_t>();
  this->FindSeamsAndLocks(input, movesVertices, stats);
}

void EngineBase::FindSeamsAndLocks(const DecimatorInput& input, bool movesVertices,
                                   DecimatorStatistics& stats)
{
  // Seams first, so that a fixed point still has its twin (whose pair it then refuses).
  const int32_t n = input.NumberOfPoints;
  const int32_t* source = this->Renumbered ? this->Order.OldVertex.data() : nullptr;
  this->Seams.Release();
  if (this->Options.PreserveSeams)
  {
    // Full collapses would move the two sides apart: their seams are locked.
    const SeamReport seams = this->Seams.Detect(this->Mesh, input.Points, source, movesVertices,
                                                this->ThreadCount(size_t(n)));
    stats.SeamVertices = seams.TwinnedVertices + seams.SharedVertices + seams.LockedVertices;
    stats.SeamLockedVertices = seams.LockedVertices;
  }
  if (input.Fixed)
  {
    for (int32_t v = 0; v < n; ++v)
    {
      if (input.Fixed[source ? source[v] : v])
      {
        this->Mesh.Fix(v);
      }
    }
  }
}

void EngineBase::Finish(bool keepHot)
{
  this->ReferenceNormals = Buffer<PackedNormal>();
  this->Errors.Release();
  this->Seams.Release();
  if (this->Options.RecordCollapses)
  {
    this->Record.Append(this->Recorded.data(), this->Recorded.size(),
                        this->Order.Empty() ? nullptr : this->Order.OldVertex.data(),
                        this->Geometry.Scale);
    this->Recorded = LargeVector<RecordedCollapse>();
  }
  if (this->Order.Empty())
  {
    return;
  }
  // The choices refer to the renumbered ids and are of no use now: freed first, so that each
  // copy made while mapping back is smaller than what they held. Without KeepVertexState the
  // output needs the mesh and the moved vertices' records only.
  this->Best = LargeVector<int32_t>();
  this->KeyKinds = LargeVector<uint8_t>();
  if (!this->Options.KeepVertexState)
  {
    this->ReleaseMetric();
    if (!keepHot)
    {
      this->Hot = Buffer<HotVertex>();
    }
  }
  this->Mesh.Renumber(this->Order.OldVertex.data(), this->Order.OldFace.data(),
                      this->ThreadCount(this->Order.OldFace.size()));
  this->RestoreValues(this->Hot);
  this->RestoreMetric();
  this->Order = SpatialOrder();
}

void EngineBase::GetOutputColor(int32_t v, double rgb[3]) const
{
  const double c[3] = { this->Hot[v].C[0], this->Hot[v].C[1], this->Hot[v].C[2] };
  MetricColorToRGB(this->UseColor ? this->Options.Space : ColorSpace::RGB, c, rgb);
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = std::min(std::max(rgb[k], 0.0), 1.0);
  }
}

} // namespace colordecimation
