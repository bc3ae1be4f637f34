/**
 * @file TestHostileMeshes.cxx
 * @brief vtkColorHalfEdgeDecimation on hostile input, through its public API: each case
 * has a defined result (docs/RELIABILITY.md, "Hostile meshes") that it asserts, together with
 * the output invariants of ColorDecimationInvariants.h and NumberOfCollapses <= number of
 * input points (every ctest entry also runs under a TIMEOUT, so an endless loop fails).
 *
 * Usage: TestHostileMeshes CASE (or "all", or "--list").
 */
#include "ColorDecimationInvariants.h"
#include "ColorDecimationMeshes.h"
#include "ColorDecimationTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCharArray.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkColorHalfEdgeLevelOfDetail.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace colordecimation::testing;
using colordecimation::meshes::Pattern;

namespace
{
using Triangles = std::vector<Tri>;

/// The output triangles in input point ids, canonical and sorted, for comparisons.
Triangles OriginalTriangles(vtkPolyData* output)
{
  return CanonicalSorted(GetOriginalTriangles(output));
}

//------------------------------------------------------------------------------
// Running the filter.

/**
 * Decimate `input` (settings applied by `configure`; the invariants, the collapse bound and
 * the input left untouched are checked by Decimate) and print what happened.
 */
RunResult Run(vtkPolyData* input, double targetReduction, const Configure& configure = nullptr)
{
  RunResult run = Decimate(input, targetReduction, configure);
  for (const std::string& text : run.WarningTexts)
  {
    std::cout << "  warning: " << text;
  }
  for (const std::string& text : run.ErrorTexts)
  {
    std::cout << "  error: " << text;
  }
  std::cout << "  " << input->GetNumberOfPoints() << " points, " << GetTriangles(input).size()
            << " triangles -> " << run.Output->GetNumberOfPoints() << " points, "
            << run.Output->GetNumberOfPolys() << " triangles; " << run.Collapses
            << " collapses, reduction " << run.ActualReduction << "\n";
  return run;
}

void ExpectNoMessages(const RunResult& run)
{
  CD_CHECK_MSG(run.Errors == 0, "no error (got " << run.Errors << ")");
  CD_CHECK_MSG(run.Warnings == 0, "no warning (got " << run.Warnings << ")");
}

void ExpectEmptyWithError(const RunResult& run, const std::string& text)
{
  CD_CHECK_MSG(run.Errors == 1, "one error (got " << run.Errors << ")");
  CD_CHECK_MSG(run.HasError(text), "the error says '" + text + "'");
  CD_CHECK_MSG(run.Output->GetNumberOfPoints() == 0 && run.Output->GetNumberOfCells() == 0,
               "empty output");
  CD_CHECK_MSG(run.Collapses == 0, "no collapse (got " << run.Collapses << ")");
}

void ExpectReached(const RunResult& run, double target, double slack = 0.02)
{
  CD_CHECK_MSG(run.ActualReduction >= target - slack,
               "reduction " << run.ActualReduction << " reaches the target " << target
                            << " (within " << slack << ")");
}

/**
 * What is decimated around a place the filter must keep (`what`): the target 0.9 met within
 * 0.01, point and cell data (of a decorated input) copied bit-exactly, no degenerate triangle.
 */
void ExpectDecimatedAround(vtkPolyData* mesh, const RunResult& run, const std::string& what)
{
  CD_CHECK_MSG(std::abs(run.ActualReduction - 0.9) <= 0.01,
               what << " is decimated (" << run.ActualReduction << ")");
  CD_CHECK(CheckPointDataCopied(mesh, run.Output) == 0);
  CD_CHECK(CheckCellDataCopied(mesh, run.Output) == 0);
  CD_CHECK(CountDegenerate(run.Output) == 0);
}

//------------------------------------------------------------------------------
// Meshes.

/// meshes::FromTriangles of points and triangles held as triples.
vtkSmartPointer<vtkPolyData> Make(const std::vector<std::array<double, 3>>& points,
                                  const Triangles& triangles)
{
  std::vector<double> xyz;
  for (const auto& p : points)
  {
    xyz.insert(xyz.end(), p.begin(), p.end());
  }
  std::vector<vtkIdType> ids;
  for (const auto& t : triangles)
  {
    ids.insert(ids.end(), t.begin(), t.end());
  }
  return colordecimation::meshes::FromTriangles(xyz, ids);
}

std::vector<std::array<double, 3>> PointsOf(vtkPolyData* mesh)
{
  std::vector<std::array<double, 3>> points(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    mesh->GetPoint(i, points[i].data());
  }
  return points;
}

/// Attach a cell-data int array (one value per cell).
void AddCellValues(vtkPolyData* mesh, const char* name, const std::vector<int>& values)
{
  vtkNew<vtkIntArray> array;
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  mesh->GetCellData()->AddArray(array);
}

/// Unsigned-char RGB of `mesh` (its active scalars) as doubles 0..255.
std::vector<std::array<double, 3>> RGBOf(vtkPolyData* mesh)
{
  vtkDataArray* scalars = mesh->GetPointData()->GetScalars();
  std::vector<std::array<double, 3>> rgb(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      rgb[i][k] = scalars->GetComponent(i, k);
    }
  }
  return rgb;
}

double TriangleNormalZ(vtkPolyData* mesh, const Tri& t)
{
  double a[3], b[3], c[3], u[3], v[3], n[3];
  mesh->GetPoint(t[0], a);
  mesh->GetPoint(t[1], b);
  mesh->GetPoint(t[2], c);
  vtkMath::Subtract(b, a, u);
  vtkMath::Subtract(c, a, v);
  vtkMath::Cross(u, v, n);
  return n[2];
}

/// Twice the area over the product of the two edges at each corner: the largest sine.
double LargestCornerSine(vtkPolyData* mesh, const Tri& t)
{
  double best = 0;
  for (int k = 0; k < 3; ++k)
  {
    double a[3], b[3], c[3], u[3], v[3], n[3];
    mesh->GetPoint(t[k], a);
    mesh->GetPoint(t[(k + 1) % 3], b);
    mesh->GetPoint(t[(k + 2) % 3], c);
    vtkMath::Subtract(b, a, u);
    vtkMath::Subtract(c, a, v);
    vtkMath::Cross(u, v, n);
    const double denominator = vtkMath::Norm(u) * vtkMath::Norm(v);
    best = std::max(best, denominator > 0 ? vtkMath::Norm(n) / denominator : 0.0);
  }
  return best;
}

//------------------------------------------------------------------------------
// Topology.

/**
 * A fin: a third triangle (a, b, apex) on the interior edge (a, b) of `grid`, `apex` a new
 * point of colour `rgb`. Returns the apex's id.
 */
vtkIdType AddFin(vtkPolyData* grid, vtkIdType a, vtkIdType b, const double apex[3],
                 const unsigned char rgb[3])
{
  const auto edge = std::make_pair(std::min(a, b), std::max(a, b));
  CD_CHECK_MSG(EdgeUses(GetTriangles(grid))[edge] == 2, "the chosen edge is an interior grid edge");
  const vtkIdType x = grid->GetPoints()->InsertNextPoint(apex);
  vtkUnsignedCharArray::SafeDownCast(grid->GetPointData()->GetScalars())->InsertNextTypedTuple(rgb);
  const vtkIdType fin[3] = { a, b, x };
  grid->GetPolys()->InsertNextCell(3, fin);
  return x;
}

/// The edge (a, b) with its fin up to `apex` is kept, the rest of the grid decimated.
void CheckFin(vtkPolyData* mesh, vtkIdType a, vtkIdType b, vtkIdType apex, const std::string& label)
{
  Decorate(mesh);
  CD_CHECK_MSG(AnalyseTopology(GetTriangles(mesh)).NonManifoldEdges == 1, label);
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.Warnings == 1, label << ": " << run.WarningText());
  CD_CHECK_MSG(run.HasWarning("non-manifold"), "a warning about the non-manifold edge");
  const std::set<vtkIdType> ids = OriginalIds(run.Output);
  CD_CHECK_MSG(ids.count(a) && ids.count(b) && ids.count(apex), label << ": the fin's points");
  const Triangles tris = GetOriginalTriangles(run.Output);
  CD_CHECK_MSG(CanonicalSet(tris).count(Canonical({ a, b, apex })) == 1, label << ": the fin");
  const int kept = EdgeUses(tris)[{ std::min(a, b), std::max(a, b) }];
  CD_CHECK_MSG(kept == 3,
               label << ": the three triangles on the non-manifold edge are kept (" << kept << ")");
  const Topology topology = AnalyseTopology(tris);
  CD_CHECK_MSG(topology.NonManifoldEdges == 1 && topology.MisorientedEdges == 0,
               label << ": " << topology);
  ExpectDecimatedAround(mesh, run, label + ": the rest of the grid");
}

/**
 * An edge shared by three triangles (a fin on a grid's interior edge, a diagonal): on a
 * sharp-coloured grid with a tall fin, small and large enough to be decimated renumbered
 * (Decimator.h), and on a smooth-coloured grid with a low fin.
 */
CD_TEST_CASE(NonManifoldEdge)
{
  for (int size : { 30, 300 })
  {
    auto grid = colordecimation::meshes::Grid(size, size, Pattern::SharpRegions);
    const vtkIdType a = (size / 2) * (size + 1) + size / 2, b = a + size + 1 + 1;
    const double apex[3] = { 0.0, 0.0, 1.0 };
    const unsigned char rgb[3] = { 10, 20, 30 };
    const vtkIdType x = AddFin(grid, a, b, apex, rgb);
    CheckFin(grid, a, b, x, "grid " + std::to_string(size));
  }
  const int nx = 40, ny = 30;
  auto grid = colordecimation::meshes::Grid(nx, ny, Pattern::SmoothGradient);
  const vtkIdType a = 15 * (nx + 1) + 20, b = 16 * (nx + 1) + 21; // (i,j)-(i+1,j+1)
  double pa[3], pb[3];
  grid->GetPoint(a, pa);
  grid->GetPoint(b, pb);
  const double apex[3] = { 0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]),
                           0.5 * (pa[2] + pb[2]) + 0.3 };
  unsigned char rgb[3];
  colordecimation::meshes::PatternColor(Pattern::SmoothGradient, apex, rgb);
  const vtkIdType x = AddFin(grid, a, b, apex, rgb);
  CheckFin(grid, a, b, x, "grid 40 x 30, smooth");
}

/**
 * Two grids that share one point: `first`, then `second` with its point `corner` on first's
 * point `shared` and its other points moved by `place`. Cell data "Part": 0 on the triangles
 * of `first`, 1 on those of `second`.
 */
vtkSmartPointer<vtkPolyData> JoinAtCorner(vtkPolyData* first, vtkIdType shared, vtkPolyData* second,
                                          vtkIdType corner,
                                          const std::function<void(double p[3])>& place)
{
  auto points = PointsOf(first);
  Triangles triangles = GetTriangles(first);
  std::vector<int> part(triangles.size(), 0);
  std::vector<vtkIdType> remap(static_cast<size_t>(second->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < second->GetNumberOfPoints(); ++i)
  {
    if (i == corner)
    {
      remap[i] = shared;
      continue;
    }
    std::array<double, 3> p;
    second->GetPoint(i, p.data());
    place(p.data());
    points.push_back(p);
    remap[i] = static_cast<vtkIdType>(points.size() - 1);
  }
  for (const auto& t : GetTriangles(second))
  {
    triangles.push_back({ remap[t[0]], remap[t[1]], remap[t[2]] });
    part.push_back(1);
  }
  auto mesh = Make(points, triangles);
  AddCellValues(mesh, "Part", part);
  return mesh;
}

/// The bow-tie vertex `shared` is kept with triangles of both parts, the rest decimated.
void CheckBowTie(vtkPolyData* mesh, vtkIdType shared, const std::string& label)
{
  Decorate(mesh);
  CD_CHECK_MSG(AnalyseTopology(GetTriangles(mesh)).NonManifoldVertices == 1, label);
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.Warnings == 1, label << ": " << run.WarningText());
  CD_CHECK_MSG(run.HasWarning("non-manifold vertices"), "a warning about the bow-tie");
  CD_CHECK_MSG(OriginalIds(run.Output).count(shared) == 1, label << ": the bow-tie vertex");
  const Topology topology = AnalyseTopology(GetOriginalTriangles(run.Output));
  CD_CHECK_MSG(topology.NonManifoldVertices == 1 && topology.NonManifoldEdges == 0 &&
                 topology.MisorientedEdges == 0 && topology.BoundaryLoops == 2,
               label << ": " << topology);
  // The bow-tie vertex survives with triangles of both grids.
  std::set<int> partsAtCorner;
  vtkIntArray* outPart = vtkIntArray::SafeDownCast(run.Output->GetCellData()->GetArray("Part"));
  const Triangles out = GetOriginalTriangles(run.Output);
  for (size_t c = 0; c < out.size() && outPart; ++c)
  {
    if (out[c][0] == shared || out[c][1] == shared || out[c][2] == shared)
    {
      partsAtCorner.insert(outPart->GetValue(static_cast<vtkIdType>(c)));
    }
  }
  CD_CHECK_MSG(partsAtCorner.size() == 2, label << ": the bow-tie keeps triangles of both grids");
  ExpectDecimatedAround(mesh, run, label + ": both grids");
}

/**
 * Two 20 x 20 grids that share one corner point: a bow-tie vertex. The second is the first
 * turned by 180 degrees about the vertical through the corner (smooth colours), or moved by
 * (2, 2) and mirrored in z (sharp colours).
 */
CD_TEST_CASE(NonManifoldVertex)
{
  auto grid = colordecimation::meshes::Grid(20, 20, Pattern::SmoothGradient);
  const vtkIdType corner = grid->GetNumberOfPoints() - 1; // (1, 1, z)
  double c[3];
  grid->GetPoint(corner, c);
  auto turned = JoinAtCorner(grid, corner, grid, corner,
                             [&c](double p[3])
                             {
                               p[0] = 2 * c[0] - p[0];
                               p[1] = 2 * c[1] - p[1];
                             });
  colordecimation::meshes::ApplyPattern(turned, Pattern::SmoothGradient);
  CheckBowTie(turned, corner, "turned");

  auto moved = JoinAtCorner(grid, corner, grid, 0,
                            [](double p[3])
                            {
                              p[0] += 2;
                              p[1] += 2;
                              p[2] = -p[2];
                            });
  colordecimation::meshes::ApplyPattern(moved, Pattern::SharpRegions);
  CheckBowTie(moved, corner, "moved and mirrored");
}

/// The same triangle twice (same orientation, and once reversed) inside a grid.
CD_TEST_CASE(DuplicateTriangles)
{
  auto grid = colordecimation::meshes::Grid(20, 20, Pattern::FineDetail);
  Triangles triangles = GetTriangles(grid);
  const Tri same = triangles[200];
  const Tri reversed = { triangles[500][0], triangles[500][2], triangles[500][1] };
  triangles.push_back(same);
  triangles.push_back(reversed);
  auto mesh = Make(PointsOf(grid), triangles);
  mesh->GetPointData()->SetScalars(grid->GetPointData()->GetScalars());

  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0, "no error");
  CD_CHECK_MSG(run.HasWarning("non-manifold"), "a warning about the duplicated edges");
  auto sorted = [](Tri t)
  {
    std::sort(t.begin(), t.end());
    return t;
  };
  int copiesOfSame = 0, copiesOfReversed = 0;
  for (const auto& t : OriginalTriangles(run.Output))
  {
    copiesOfSame += sorted(t) == sorted(same) ? 1 : 0;
    copiesOfReversed += sorted(t) == sorted(reversed) ? 1 : 0;
  }
  CD_CHECK_MSG(copiesOfSame == 2,
               "both copies of the duplicated triangle are kept (" << copiesOfSame << ")");
  CD_CHECK_MSG(copiesOfReversed == 2,
               "the triangle and its reversed copy are kept (" << copiesOfReversed << ")");
  CD_CHECK_MSG(run.ActualReduction > 0.7, "the rest of the grid is decimated");
}

/// A triangle and its reversed copy alone: a closed two-faced "pillow".
CD_TEST_CASE(DoubleSidedTriangle)
{
  auto mesh = Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 2, 1 } });
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SmoothGradient);
  for (double target : { 0.5, 1.0 })
  {
    RunResult run = Run(mesh, target);
    ExpectNoMessages(run);
    CD_CHECK_MSG(run.Output->GetNumberOfPolys() == 2 && run.Collapses == 0, "both faces are kept");
  }
}

/// Every triangle with its own three points (a triangle soup): nothing can collapse, and a
/// warning says why (the seams lock the points) and what to do (merge them).
CD_TEST_CASE(TriangleSoup)
{
  auto grid = colordecimation::meshes::Grid(10, 10, Pattern::SharpRegions);
  const auto gridPoints = PointsOf(grid);
  std::vector<std::array<double, 3>> points;
  Triangles triangles;
  for (const auto& t : GetTriangles(grid))
  {
    const vtkIdType base = static_cast<vtkIdType>(points.size());
    for (vtkIdType id : t)
    {
      points.push_back(gridPoints[id]);
    }
    triangles.push_back({ base, base + 1, base + 2 });
  }
  auto mesh = Make(points, triangles);
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SharpRegions);
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.Warnings == 1 && run.HasWarning("a triangle soup") &&
                 run.HasWarning("600 of the 600 triangle edges are open") &&
                 run.HasWarning("merge the coincident points first"),
               "one warning: " << run.WarningText());
  // The same without seams, and with the metric whose placement locks every seam point.
  for (const bool placement : { false, true })
  {
    const RunResult other = Run(mesh, 0.9,
                                [placement](vtkColorHalfEdgeDecimation* f)
                                {
                                  f->SetPreserveSeams(placement);
                                  f->SetOptimalPlacement(placement);
                                  if (placement)
                                  {
                                    f->SetErrorMetricToColorQuadric();
                                  }
                                });
    CD_CHECK_MSG(other.Warnings == 1 && other.HasWarning("600 of the 600 triangle edges"),
                 "placement " << placement << ": " << other.WarningText());
  }
  CD_CHECK_MSG(run.Collapses == 0, "no collapse");
  CD_CHECK_MSG(OriginalTriangles(run.Output) == OriginalTriangles(Run(mesh, 0.0).Output),
               "the output is the input");
  ExpectNoMessages(Run(grid, 0.9)); // its points shared: no warning
}

/// Coincident duplicates of every point, unused: dropped, and the result does not change.
CD_TEST_CASE(DuplicatePoints)
{
  auto grid = colordecimation::meshes::Grid(30, 30, Pattern::SharpRegions);
  auto points = PointsOf(grid);
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i)
  {
    points.push_back(points[i]);
  }
  auto mesh = Make(points, GetTriangles(grid));
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SharpRegions);
  RunResult run = Run(mesh, 0.9);
  ExpectNoMessages(run);
  RunResult reference = Run(grid, 0.9);
  CD_CHECK_MSG(OriginalTriangles(run.Output) == OriginalTriangles(reference.Output),
               "the same triangles as without the duplicates");
  CD_CHECK_MSG(run.Output->GetNumberOfPoints() == reference.Output->GetNumberOfPoints(),
               "the unused duplicates are dropped");
}

/// A flat grid whose second row of points lies on the first (zero-length edges, zero-area
/// triangles) and whose row 10 lies on row 9's line (collinear triangles).
CD_TEST_CASE(ZeroAreaTriangles)
{
  auto grid = colordecimation::meshes::FlatGrid(20, 20, Pattern::SharpRegions);
  auto points = PointsOf(grid);
  for (int i = 0; i <= 20; ++i)
  {
    points[21 + i] = points[i]; // row 1 onto row 0
    // Row 10 onto row 9's line, shifted by half a cell: collinear triangles between them.
    points[10 * 21 + i] = points[9 * 21 + i];
    points[10 * 21 + i][0] += 0.05;
  }
  const Triangles triangles = GetTriangles(grid);
  auto mesh = Make(points, triangles);
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SharpRegions);
  int zeroArea = 0;
  for (const auto& t : triangles)
  {
    zeroArea += LargestCornerSine(mesh, t) < 1e-6 ? 1 : 0;
  }
  CD_CHECK_MSG(zeroArea == 80, "the input has 80 zero-area triangles (" << zeroArea << ")");

  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0, "no error");
  CD_CHECK_MSG(run.ActualReduction > 0.5, "the grid is decimated");
  // No collapse creates a zero-area triangle: those of the output are input triangles.
  const std::set<Tri> input = CanonicalSet(triangles);
  for (const auto& t : OriginalTriangles(run.Output))
  {
    if (LargestCornerSine(mesh, t) < 1e-6)
    {
      CD_CHECK_MSG(input.count(t) == 1,
                   "zero-area output triangle " << t[0] << " " << t[1] << " " << t[2]
                                                << " is an input one");
    }
  }
}

/// Points used by no triangle: dropped from the output.
CD_TEST_CASE(IsolatedPoints)
{
  auto grid = colordecimation::meshes::Torus(40, 20, Pattern::SmoothGradient);
  auto points = PointsOf(grid);
  const vtkIdType used = static_cast<vtkIdType>(points.size());
  for (int k = 0; k < 50; ++k)
  {
    points.push_back({ 0.01 * k, -0.02 * k, 0.03 * k }); // inside the bounding box
  }
  auto mesh = Make(points, GetTriangles(grid));
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SmoothGradient);
  RunResult run = Run(mesh, 0.9);
  ExpectNoMessages(run);
  ExpectReached(run, 0.9);
  vtkIdTypeArray* original =
    vtkIdTypeArray::SafeDownCast(run.Output->GetPointData()->GetArray("vtkOriginalPointIds"));
  bool anyIsolated = false;
  for (vtkIdType i = 0; original && i < original->GetNumberOfValues(); ++i)
  {
    anyIsolated = anyIsolated || original->GetValue(i) >= used;
  }
  CD_CHECK_MSG(original && !anyIsolated, "no isolated point in the output");
}

/**
 * A grid whose triangles inside a block are reversed (48 seam edges whose two triangles run
 * them the same way). The grid is decimated as if wound one way: no warning, the target
 * reached, and each output triangle keeps the winding of its input triangle (no output
 * triangle reversed against its own region: normal turned by more than 120 degrees from the
 * region's side; the flip guard bounds each collapse's turn by MaximumNormalAngle, 90 degrees,
 * so output triangles may stand steeply, see docs/RELIABILITY.md). With ConsistentOrientation
 * every output triangle faces the majority's side.
 */
CD_TEST_CASE(MixedOrientation)
{
  auto grid = colordecimation::meshes::Grid(30, 30, Pattern::SmoothGradient);
  const auto points = PointsOf(grid);
  Triangles triangles = GetTriangles(grid);
  std::vector<int> orientation(triangles.size(), 1);
  for (size_t c = 0; c < triangles.size(); ++c)
  {
    const auto& t = triangles[c];
    const double x = (points[t[0]][0] + points[t[1]][0] + points[t[2]][0]) / 3;
    const double y = (points[t[0]][1] + points[t[1]][1] + points[t[2]][1]) / 3;
    if (x > -0.4 && x < 0.4 && y > -0.4 && y < 0.4)
    {
      std::swap(triangles[c][1], triangles[c][2]);
      orientation[c] = -1;
    }
  }
  auto mesh = Make(points, triangles);
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SmoothGradient);
  AddCellValues(mesh, "Orientation", orientation);
  CD_CHECK_MSG(TriangleNormalZ(mesh, triangles[0]) > 0, "the grid faces +z");
  CD_CHECK_MSG(AnalyseTopology(triangles).MisorientedEdges == 48, "the seam has 48 edges");
  for (const bool consistent : { false, true })
  {
    RunResult run =
      Run(mesh, 0.9,
          [consistent](vtkColorHalfEdgeDecimation* f) { f->SetConsistentOrientation(consistent); });
    ExpectNoMessages(run);
    ExpectReached(run, 0.9);
    vtkIntArray* outOrientation =
      vtkIntArray::SafeDownCast(run.Output->GetCellData()->GetArray("Orientation"));
    const Triangles out = GetTriangles(run.Output);
    int reversed = 0, steep = 0;
    for (size_t c = 0; c < out.size() && outOrientation; ++c)
    {
      double a[3], b[3], d[3], u[3], v[3], n[3];
      run.Output->GetPoint(out[c][0], a);
      run.Output->GetPoint(out[c][1], b);
      run.Output->GetPoint(out[c][2], d);
      vtkMath::Subtract(b, a, u);
      vtkMath::Subtract(d, a, v);
      vtkMath::Cross(u, v, n);
      const int expected = consistent ? 1 : outOrientation->GetValue(static_cast<vtkIdType>(c));
      const double side = n[2] * expected;
      reversed += side < -0.5 * vtkMath::Norm(n) ? 1 : 0;
      steep += side <= 0 ? 1 : 0;
    }
    CD_CHECK_MSG(outOrientation && reversed == 0,
                 reversed << " output triangles are reversed against their region");
    CD_CHECK_MSG(consistent || AnalyseTopology(out).MisorientedEdges > 0,
                 "the output keeps the input's two windings");
    CD_CHECK_MSG(!consistent || AnalyseTopology(out).MisorientedEdges == 0,
                 "ConsistentOrientation: the output is wound one way");
    std::cout << "  " << (consistent ? "consistent" : "input winding") << ": " << steep
              << " output triangles stand at 90 degrees or more to their region\n";
  }
}

/**
 * A Moebius strip cannot be wound one way: the edges where the orientation must break are
 * locked (a warning counts them), the rest is decimated.
 */
CD_TEST_CASE(MoebiusStrip)
{
  std::vector<std::array<double, 3>> points;
  const int around = 60;
  for (int i = 0; i < around; ++i)
  {
    const double a = 2.0 * vtkMath::Pi() * i / around;
    for (const double w : { -0.3, 0.0, 0.3 })
    {
      const double r = 1.0 + w * std::cos(a / 2);
      points.push_back({ r * std::cos(a), r * std::sin(a), w * std::sin(a / 2) });
    }
  }
  Triangles triangles;
  for (int i = 0; i < around; ++i)
  {
    const int j = (i + 1) % around;
    for (int k = 0; k < 2; ++k)
    {
      // The last column joins the first one upside down: that is the twist.
      const vtkIdType a = 3 * i + k, b = 3 * i + k + 1;
      const vtkIdType c = j == 0 ? 3 * j + (2 - k) : 3 * j + k;
      const vtkIdType d = j == 0 ? 3 * j + (1 - k) : 3 * j + k + 1;
      triangles.push_back({ a, c, d });
      triangles.push_back({ a, d, b });
    }
  }
  auto mesh = Make(points, triangles);
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SmoothGradient);
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.HasWarning("non-orientable"),
               "a warning about the non-orientable edges");
  const Topology in = AnalyseTopology(triangles), out = AnalyseTopology(GetTriangles(run.Output));
  std::cout << "  Moebius strip: " << in.Faces << " -> " << out.Faces << " triangles, "
            << in.MisorientedEdges << " -> " << out.MisorientedEdges << " edges run one way\n";
  CD_CHECK_MSG(in.Euler() == 0 && in.MisorientedEdges == 2, "the input is a Moebius strip");
  CD_CHECK_MSG(run.ActualReduction > 0.5, "the strip is decimated");
  // Still a strip with its twist: Euler characteristic 0, no non-manifold edge, and (kept
  // with the input's winding) an edge its two triangles run the same way.
  CD_CHECK_MSG(out.Euler() == 0 && out.NonManifoldEdges == 0 && out.MisorientedEdges >= 1,
               "still a Moebius strip: " << out);
}

//------------------------------------------------------------------------------
// Geometry.

/**
 * Closed smooth surfaces (an icosphere and a torus) stay outward-facing: no output triangle
 * is folded over (its normal turned by more than 120 degrees from the surface's outward
 * normal), at 50 % and 90 % reduction, with both metrics and the default MaximumNormalAngle.
 * Triangles standing at about 90 degrees (slivers) are counted and printed, not failed.
 */
CD_TEST_CASE(NoFoldOver)
{
  struct Surface
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Mesh;
    bool Torus;
  };
  for (const Surface& s :
       { Surface{ "icosphere", colordecimation::meshes::Icosphere(5, Pattern::FineDetail), false },
         Surface{ "torus", colordecimation::meshes::Torus(200, 80, Pattern::SharpRegions), true } })
  {
    for (double target : { 0.5, 0.9 })
    {
      for (int metric :
           { vtkColorHalfEdgeDecimation::HalfEdgeColor, vtkColorHalfEdgeDecimation::Geometry })
      {
        RunResult run = Run(s.Mesh, target,
                            [metric](vtkColorHalfEdgeDecimation* f) { f->SetErrorMetric(metric); });
        ExpectNoMessages(run);
        int folded = 0, standing = 0;
        for (const auto& t : GetTriangles(run.Output))
        {
          double p[3][3], u[3], v[3], n[3], centre[3] = { 0, 0, 0 }, outward[3];
          for (int k = 0; k < 3; ++k)
          {
            run.Output->GetPoint(t[k], p[k]);
            vtkMath::Add(centre, p[k], centre);
          }
          vtkMath::MultiplyScalar(centre, 1.0 / 3.0);
          vtkMath::Subtract(p[1], p[0], u);
          vtkMath::Subtract(p[2], p[0], v);
          vtkMath::Cross(u, v, n);
          // Outward: from the centre (sphere) or from the core circle of radius 1 (torus).
          const double rho = std::hypot(centre[0], centre[1]);
          const double core[3] = { s.Torus && rho > 0 ? centre[0] / rho : 0.0,
                                   s.Torus && rho > 0 ? centre[1] / rho : 0.0, 0.0 };
          vtkMath::Subtract(centre, core, outward);
          const double cosine =
            vtkMath::Dot(n, outward) / (vtkMath::Norm(n) * vtkMath::Norm(outward));
          folded += cosine < -0.5 ? 1 : 0;
          standing += cosine <= 0 ? 1 : 0;
        }
        std::cout << "  " << standing << " triangles at 90 degrees or more to the outward normal, "
                  << folded << " beyond 120\n";
        CD_CHECK_MSG(folded == 0,
                     s.Name << ", reduction " << target << ", "
                            << run.Filter->GetErrorMetricAsString() << ": " << folded
                            << " output triangles are folded over (turned by more than 120 "
                               "degrees from the outward normal)");
      }
    }
  }
}

/// A flat grid: every quadric is singular (all Q = 0); colour alone orders the collapses.
CD_TEST_CASE(FlatGrid)
{
  for (Pattern pattern : { Pattern::SharpRegions, Pattern::Constant })
  {
    auto mesh = colordecimation::meshes::FlatGrid(50, 50, pattern);
    RunResult run = Run(mesh, 0.9);
    ExpectNoMessages(run);
    ExpectReached(run, 0.9);
    int flipped = 0;
    for (const auto& t : GetTriangles(run.Output))
    {
      flipped += TriangleNormalZ(run.Output, t) <= 0 ? 1 : 0;
    }
    CD_CHECK_MSG(flipped == 0, flipped << " output triangles flipped or degenerate");

    RunResult preserved =
      Run(mesh, 0.9, [](vtkColorHalfEdgeDecimation* f) { f->PreserveBoundaryOn(); });
    ExpectNoMessages(preserved);
    const Triangles input = GetTriangles(mesh);
    std::set<vtkIdType> boundary;
    for (const auto& e : EdgeUses(input))
    {
      if (e.second == 1)
      {
        boundary.insert(e.first.first);
        boundary.insert(e.first.second);
      }
    }
    std::set<vtkIdType> kept;
    for (const auto& t : OriginalTriangles(preserved.Output))
    {
      kept.insert(t.begin(), t.end());
    }
    size_t boundaryKept = 0;
    for (vtkIdType v : boundary)
    {
      boundaryKept += kept.count(v);
    }
    CD_CHECK_MSG(boundary.size() == 200 && boundaryKept == boundary.size(),
                 "PreserveBoundary keeps the " << boundary.size() << " boundary points ("
                                               << boundaryKept << ")");
    CD_CHECK_MSG(AnalyseTopology(GetTriangles(preserved.Output)).BoundaryEdges == 200,
                 "PreserveBoundary keeps every boundary edge");
  }
}

/// One triangle: nothing to collapse.
CD_TEST_CASE(SingleTriangle)
{
  auto mesh = Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 } });
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SharpRegions);
  for (double target : { 0.0, 0.9, 1.0 })
  {
    RunResult run = Run(mesh, target);
    ExpectNoMessages(run);
    CD_CHECK_MSG(run.Output->GetNumberOfPolys() == 1 && run.Output->GetNumberOfPoints() == 3,
                 "the triangle is kept");
    CD_CHECK_MSG(run.Collapses == 0 && run.ActualReduction == 0.0, "no collapse, reduction 0");
  }
}

/// Coordinates scaled by 1e7 and 1e-7 give the same triangles as at unit scale.
void Scale(double scale)
{
  for (auto mesh : { colordecimation::meshes::Icosphere(4, Pattern::FineDetail),
                     colordecimation::meshes::Grid(40, 40, Pattern::SharpRegions) })
  {
    RunResult unit = Run(mesh, 0.9);
    ExpectNoMessages(unit);
    const double origin[3] = { 0, 0, 0 };
    RunResult scaled = Run(Transformed(mesh, scale, origin), 0.9);
    ExpectNoMessages(scaled);
    CD_CHECK_MSG(OriginalTriangles(scaled.Output) == OriginalTriangles(unit.Output),
                 "scale " << scale << " gives the triangles of scale 1");
  }
}

CD_TEST_CASE(LargeScale)
{
  Scale(1e7);
}

CD_TEST_CASE(SmallScale)
{
  Scale(1e-7);
}

//------------------------------------------------------------------------------
// Colours.

/// The mesh of the colour-type tests, its colours as 0..255 values.
vtkSmartPointer<vtkPolyData> ColorMesh()
{
  return colordecimation::meshes::Icosphere(3, Pattern::SharpRegions);
}

/**
 * `mesh` with its colour replaced by an array of `type` with `components` components:
 * component k < 3 is the RGB value (halved for signed char and char, /255 for floating
 * types); component 3 is a pseudo-random alpha; one component is the red value.
 */
vtkSmartPointer<vtkPolyData> WithColorType(vtkPolyData* mesh, int type, int components)
{
  const auto rgb = RGBOf(mesh);
  auto copy = Copy(mesh);
  auto array = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(type));
  array->SetName("Color");
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(copy->GetNumberOfPoints());
  const bool floating = type == VTK_FLOAT || type == VTK_DOUBLE;
  const bool small = type == VTK_CHAR || type == VTK_SIGNED_CHAR;
  for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < components; ++k)
    {
      double value =
        k < 3 ? rgb[i][components == 1 ? 0 : k] : static_cast<double>((i * 7919) % 256); // alpha
      if (small)
      {
        value = std::floor(value / 2);
      }
      array->SetComponent(i, k, floating ? value / 255.0 : value);
    }
  }
  copy->GetPointData()->SetScalars(array);
  return copy;
}

const std::vector<std::pair<int, const char*>>& ColorTypes()
{
  static const std::vector<std::pair<int, const char*>> types = {
    { VTK_CHAR, "char" },
    { VTK_SIGNED_CHAR, "signed_char" },
    { VTK_UNSIGNED_CHAR, "unsigned_char" },
    { VTK_SHORT, "short" },
    { VTK_UNSIGNED_SHORT, "unsigned_short" },
    { VTK_INT, "int" },
    { VTK_UNSIGNED_INT, "unsigned_int" },
    { VTK_LONG, "long" },
    { VTK_UNSIGNED_LONG, "unsigned_long" },
    { VTK_LONG_LONG, "long_long" },
    { VTK_UNSIGNED_LONG_LONG, "unsigned_long_long" },
    { VTK_FLOAT, "float" },
    { VTK_DOUBLE, "double" },
  };
  return types;
}

/**
 * A colour array of `type` with 1, 3 and 4 components:
 * - is accepted without a message, decimates to the target, and is copied bit-exactly
 *   (checked by the invariants);
 * - 4 components (alpha not measured) give the triangles of 3;
 * - 1 component (grey) gives the triangles of 3 components holding that grey value thrice;
 * - the floating types holding value/255 give the triangles of unsigned char (used as they
 *   are in [0,1]); the other integer types all give the same triangles (scaled by the range).
 */
void ColorType(int type)
{
  auto mesh = ColorMesh();
  std::map<int, Triangles> byComponents;
  for (int components : { 1, 3, 4 })
  {
    RunResult run = Run(WithColorType(mesh, type, components), 0.9);
    ExpectNoMessages(run);
    ExpectReached(run, 0.9);
    vtkDataArray* out = run.Output->GetPointData()->GetArray("Color");
    CD_CHECK_MSG(out && out->GetDataType() == type && out->GetNumberOfComponents() == components,
                 "the colour array keeps its type and width");
    byComponents[components] = OriginalTriangles(run.Output);
  }
  CD_CHECK_MSG(byComponents[4] == byComponents[3], "RGBA gives the triangles of RGB");

  // Grey: one component equals three equal components.
  auto greyThrice = WithColorType(mesh, type, 3);
  vtkDataArray* grey = greyThrice->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < grey->GetNumberOfTuples(); ++i)
  {
    grey->SetComponent(i, 1, grey->GetComponent(i, 0));
    grey->SetComponent(i, 2, grey->GetComponent(i, 0));
  }
  CD_CHECK_MSG(byComponents[1] == OriginalTriangles(Run(greyThrice, 0.9).Output),
               "one grey component gives the triangles of three equal components");

  if (type == VTK_FLOAT || type == VTK_DOUBLE)
  {
    CD_CHECK_MSG(byComponents[3] ==
                   OriginalTriangles(Run(WithColorType(mesh, VTK_UNSIGNED_CHAR, 3), 0.9).Output),
                 "value/255 in a floating array gives the triangles of unsigned char");
  }
  else if (type != VTK_UNSIGNED_CHAR)
  {
    const int other = type == VTK_CHAR ? VTK_INT : VTK_CHAR;
    CD_CHECK_MSG(byComponents[3] ==
                   OriginalTriangles(Run(WithColorType(mesh, other, 3), 0.9).Output),
                 "every integer type other than unsigned char gives the triangles of char "
                 "(char those of int)");
  }
}

/**
 * `mesh`, whose colours hold `spoiled` NaN or infinite tuples, decimated: one warning counting
 * them, the target reached, every invariant of a decimated closed mesh (the NaN copied
 * bit-exactly with the other data).
 */
void CheckNaNColors(vtkPolyData* mesh, int spoiled, const std::string& label)
{
  Decorate(mesh);
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0, label << ": no error");
  CD_CHECK_MSG(run.Warnings == 1 && run.HasWarning(std::to_string(spoiled) + " colour tuples"),
               label << ": one warning counting the " << spoiled << " NaN or infinite tuples");
  CD_CHECK_MSG(std::abs(run.ActualReduction - 0.9) <= 0.01,
               label << ": reduction " << run.ActualReduction);
  CheckDecimatedMesh(mesh, run.Output, Expectation(), label);
  vtkDataArray* out = run.Output->GetPointData()->GetScalars();
  int nanKept = 0;
  for (vtkIdType i = 0; out && i < out->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      nanKept += std::isnan(out->GetComponent(i, k)) ? 1 : 0;
    }
  }
  std::cout << "  " << nanKept << " NaN colour values carried to the output\n";
}

/**
 * NaN and infinite colour values (float and double colours with NaN or inf in every 17th
 * tuple; smooth float colours with one NaN and one inf): a warning; measured as 0, carried
 * through unchanged. All colours NaN: a warning, and then the result of no colour at all.
 */
CD_TEST_CASE(NaNColors)
{
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    auto mesh = WithColorType(ColorMesh(), type, 3);
    vtkDataArray* colors = mesh->GetPointData()->GetScalars();
    int spoiled = 0;
    for (vtkIdType i = 0; i < colors->GetNumberOfTuples(); i += 17)
    {
      colors->SetComponent(i, i % 3,
                           (i % 2) ? std::numeric_limits<double>::quiet_NaN()
                                   : std::numeric_limits<double>::infinity());
      ++spoiled;
    }
    CheckNaNColors(mesh, spoiled, type == VTK_FLOAT ? "float" : "double");
  }
  auto smooth = colordecimation::meshes::Icosphere(4, Pattern::SmoothGradient);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(smooth->GetPointData()->GetScalars());
  vtkNew<vtkFloatArray> f;
  f->SetName("Colour");
  f->SetNumberOfComponents(3);
  f->SetNumberOfTuples(smooth->GetNumberOfPoints());
  for (vtkIdType i = 0; i < 3 * smooth->GetNumberOfPoints(); ++i)
  {
    f->SetValue(i, rgb->GetValue(i) / 255.0f);
  }
  f->SetValue(3 * 17 + 1, std::numeric_limits<float>::quiet_NaN());
  f->SetValue(3 * 100, std::numeric_limits<float>::infinity());
  smooth->GetPointData()->RemoveArray("RGB");
  smooth->GetPointData()->SetScalars(f);
  CheckNaNColors(smooth, 2, "smooth float");

  auto mesh = WithColorType(ColorMesh(), VTK_FLOAT, 3);
  mesh->GetPointData()->GetScalars()->Fill(std::numeric_limits<double>::quiet_NaN());
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.Warnings == 1, "all NaN: one warning");
  ExpectReached(run, 0.9);
}

/// Select the colour array `name` with the field association `association`.
Configure ColorFrom(int association, const char* name)
{
  return [association, name](vtkColorHalfEdgeDecimation* f)
  { f->SetInputArrayToProcess(0, 0, 0, association, name); };
}

/**
 * No colour array: legitimate input, decimated by geometry alone without a message (every
 * invariant of a decimated closed mesh); so with the Geometry metric.
 */
void CheckNoColor(vtkPolyData* mesh, const std::string& label)
{
  Decorate(mesh); // normals, texture coordinates and others, but no scalars
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.Warnings == 0,
               label << ": no message: " << run.WarningText());
  CD_CHECK_MSG(std::abs(run.ActualReduction - 0.9) <= 0.01,
               label << ": reduction " << run.ActualReduction);
  CheckDecimatedMesh(mesh, run.Output, Expectation{ true, 2, 0, nullptr, true }, label);
  RunResult geometry =
    Run(mesh, 0.9, [](vtkColorHalfEdgeDecimation* f) { f->SetErrorMetricToGeometry(); });
  ExpectNoMessages(geometry);
  CD_CHECK_MSG(std::abs(geometry.ActualReduction - 0.9) <= 0.01,
               label << ": Geometry metric, reduction " << geometry.ActualReduction);
}

/**
 * A colour array selected from a place a vtkPolyData does not have (a graph's vertices or edges,
 * a table's rows): a warning saying so and the triangles of a run without colour
 * (`byGeometry`), without VTK's own error from the look-up.
 */
void ExpectPlacesPolyDataLacks(vtkPolyData* mesh, const RunResult& byGeometry)
{
  for (const auto& place :
       { std::make_pair(vtkDataObject::FIELD_ASSOCIATION_VERTICES, "a graph's vertex data"),
         std::make_pair(vtkDataObject::FIELD_ASSOCIATION_EDGES, "a graph's edge data"),
         std::make_pair(vtkDataObject::FIELD_ASSOCIATION_ROWS, "a table's row data") })
  {
    const RunResult run = Run(mesh, 0.9, ColorFrom(place.first, "RGB"));
    CD_CHECK_MSG(run.Errors == 0 && run.Warnings == 1 &&
                   run.HasWarning(std::string("'RGB' is selected from ") + place.second +
                                  ", which a vtkPolyData does not have"),
                 "association " << place.first << ": one warning: " << run.WarningText());
    CD_CHECK_MSG(OriginalTriangles(run.Output) == OriginalTriangles(byGeometry.Output),
                 "association " << place.first << ": the triangles of a run without colour");
  }
  // Selected by attribute type there: the same warning, without a name.
  const RunResult byType =
    Run(mesh, 0.9,
        [](vtkColorHalfEdgeDecimation* f)
        {
          f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_ROWS,
                                    vtkDataSetAttributes::SCALARS);
        });
  CD_CHECK_MSG(byType.Errors == 0 && byType.Warnings == 1 &&
                 byType.HasWarning("The colour array is selected from a table's row data"),
               "rows by attribute type: " << byType.WarningText());
  CD_CHECK(OriginalTriangles(byType.Output) == OriginalTriangles(byGeometry.Output));
}

/**
 * Colour array of the wrong length (one tuple short as the scalars or selected by name, five
 * tuples long), or as cell data (selected as cell data, or as points then cells): errors,
 * empty output. No colour array (no scalars, or no point data at all): geometry alone,
 * quietly.
 */
CD_TEST_CASE(BadColorArrays)
{
  auto mesh = ColorMesh();
  auto shortColors = Copy(mesh);
  shortColors->GetPointData()->GetScalars()->SetNumberOfTuples(mesh->GetNumberOfPoints() - 1);
  ExpectEmptyWithError(Run(shortColors, 0.9), "tuples for");

  auto shortByName = Copy(mesh);
  vtkNew<vtkUnsignedCharArray> shortArray;
  shortArray->SetName("Short");
  shortArray->SetNumberOfComponents(3);
  shortArray->SetNumberOfTuples(mesh->GetNumberOfPoints() - 1);
  shortArray->FillValue(100);
  shortByName->GetPointData()->AddArray(shortArray);
  ExpectEmptyWithError(
    Run(shortByName, 0.9, ColorFrom(vtkDataObject::FIELD_ASSOCIATION_POINTS, "Short")),
    "tuples for");

  auto longColors = Copy(mesh);
  vtkNew<vtkFloatArray> longArray;
  longArray->SetNumberOfComponents(3);
  longArray->SetNumberOfTuples(mesh->GetNumberOfPoints() + 5);
  longArray->FillValue(0.5f);
  longColors->GetPointData()->RemoveArray("RGB");
  longColors->GetPointData()->SetScalars(longArray);
  ExpectEmptyWithError(Run(longColors, 0.9), "tuples for");

  auto cellColors = Copy(mesh);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("CellRGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(mesh->GetNumberOfCells());
  rgb->Fill(100);
  cellColors->GetCellData()->AddArray(rgb);
  // Colours per cell are not measured: a warning, and the decimation by geometry alone (the
  // triangles of a run without colour), as for a name the input does not have.
  auto uncoloured = Copy(mesh);
  uncoloured->GetPointData()->SetScalars(nullptr);
  const RunResult byGeometry = Run(uncoloured, 0.9);
  for (int association :
       { vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, vtkDataObject::FIELD_ASSOCIATION_CELLS,
         vtkDataObject::FIELD_ASSOCIATION_POINTS })
  {
    const RunResult run = Run(cellColors, 0.9, ColorFrom(association, "CellRGB"));
    CD_CHECK_MSG(run.Errors == 0 && run.Warnings == 1 &&
                   run.HasWarning("The colour array 'CellRGB' is cell data, not point data"),
                 "association " << association << ": one warning: " << run.WarningText());
    CD_CHECK_MSG(OriginalTriangles(run.Output) == OriginalTriangles(byGeometry.Output),
                 "association " << association << ": the triangles of a run without colour");
  }
  vtkNew<vtkUnsignedCharArray> fieldColors;
  fieldColors->DeepCopy(rgb);
  cellColors->GetFieldData()->AddArray(fieldColors); // "CellRGB" as field data too
  const RunResult fromField =
    Run(cellColors, 0.9, ColorFrom(vtkDataObject::FIELD_ASSOCIATION_NONE, "CellRGB"));
  CD_CHECK_MSG(fromField.Errors == 0 && fromField.Warnings == 1 &&
                 fromField.HasWarning("'CellRGB' is field data, not point data"),
               "a field-data array: " << fromField.WarningText());
  const RunResult fromCells =
    Run(cellColors, 0.9, ColorFrom(vtkDataObject::FIELD_ASSOCIATION_CELLS, "RGB"));
  CD_CHECK_MSG(fromCells.Errors == 0 && fromCells.Warnings == 1 &&
                 fromCells.HasWarning("'RGB' is selected from the cell data, not the point data"),
               "a point array selected from the cell data: " << fromCells.WarningText());

  ExpectPlacesPolyDataLacks(mesh, byGeometry);
  auto noScalars = Copy(mesh); // the colours stay, as an array that is not the scalars
  noScalars->GetPointData()->SetScalars(nullptr);
  CheckNoColor(noScalars, "no scalars");
  auto noPointData = colordecimation::meshes::Icosphere(5, Pattern::SharpRegions);
  noPointData->GetPointData()->Initialize();
  CheckNoColor(noPointData, "no point data");
}

/**
 * Point-data arrays shorter than the number of points and cell-data arrays shorter than the
 * number of cells, that the filter does not use as the colour (the Geometry metric does not
 * look at the colour): left out of the output, with one warning naming them; the rest is
 * decimated as usual. (Before 76cd09e they were copied past their end.)
 */
CD_TEST_CASE(ShortPointArray)
{
  auto mesh = ColorMesh();
  mesh->GetPointData()->GetScalars()->SetNumberOfTuples(mesh->GetNumberOfPoints() / 2);
  vtkNew<vtkIntArray> shortCells;
  shortCells->SetName("ShortCells");
  shortCells->SetNumberOfValues(mesh->GetNumberOfCells() - 1);
  shortCells->Fill(3);
  mesh->GetCellData()->AddArray(shortCells);
  vtkNew<vtkFloatArray> good;
  good->SetName("Good");
  good->SetNumberOfValues(mesh->GetNumberOfPoints());
  good->Fill(1.5);
  mesh->GetPointData()->AddArray(good);
  RunResult run =
    Run(mesh, 0.9, [](vtkColorHalfEdgeDecimation* f) { f->SetErrorMetricToGeometry(); });
  CD_CHECK_MSG(run.Errors == 0, "no error");
  CD_CHECK_MSG(run.Warnings == 1 && run.HasWarning("left out") && run.HasWarning("'RGB'") &&
                 run.HasWarning("'ShortCells'"),
               "one warning naming the two arrays left out");
  CD_CHECK_MSG(!run.Output->GetPointData()->GetArray("RGB") &&
                 !run.Output->GetCellData()->GetArray("ShortCells"),
               "the short arrays are not in the output");
  CD_CHECK_MSG(run.Output->GetPointData()->GetArray("Good") != nullptr, "the other arrays are");
  ExpectReached(run, 0.9);
}

//------------------------------------------------------------------------------
// Target reduction and input validation.

/// Two points, (0,0,0) and (1,0,0), without cells or colours.
vtkSmartPointer<vtkPolyData> TwoPoints()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  return cloud;
}

/**
 * Empty input, points without cells (with and without colours), only vertices and lines,
 * only triangles that repeat a point: empty output.
 */
CD_TEST_CASE(EmptyAndNoSurface)
{
  vtkNew<vtkPolyData> empty;
  RunResult run = Run(empty, 0.9);
  ExpectNoMessages(run);
  CD_CHECK_MSG(run.Output->GetNumberOfPoints() == 0 && run.Output->GetNumberOfCells() == 0,
               "empty input: empty output");
  CD_CHECK_MSG(run.ActualReduction == 0 && run.Collapses == 0, "empty input: no reduction");

  auto pointsOnly = ColorMesh();
  pointsOnly->SetPolys(vtkNew<vtkCellArray>());
  auto twoPoints = TwoPoints();
  for (vtkPolyData* points : { pointsOnly.Get(), twoPoints.Get() })
  {
    run = Run(points, 0.9);
    ExpectNoMessages(run);
    CD_CHECK_MSG(run.Output->GetNumberOfPoints() == 0 && run.Output->GetNumberOfCells() == 0,
                 "points without cells: empty output");
  }

  auto linesOnly = ColorMesh();
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[4] = { 0, 1, 2, 3 };
  lines->InsertNextCell(4, line);
  vtkNew<vtkCellArray> verts;
  verts->InsertNextCell(1, line);
  linesOnly->SetPolys(vtkNew<vtkCellArray>());
  linesOnly->SetLines(lines);
  linesOnly->SetVerts(verts);
  run = Run(linesOnly, 0.9);
  CD_CHECK_MSG(run.Errors == 0, "no error");
  CD_CHECK_MSG(run.HasWarning("Dropping 1 vertex and 1 line"), "a warning about the cells");
  CD_CHECK_MSG(run.Output->GetNumberOfPoints() == 0 && run.Output->GetNumberOfCells() == 0,
               "only vertices and lines: empty output");

  auto repeating = TwoPoints();
  vtkNew<vtkCellArray> polys;
  const vtkIdType repeated[3] = { 0, 1, 1 };
  polys->InsertNextCell(3, repeated);
  repeating->SetPolys(polys);
  run = Run(repeating, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.Warnings >= 1 &&
                 run.HasWarning("Dropped 1 triangles that repeat"),
               "only a triangle repeating a point: dropped with a warning");
  CD_CHECK_MSG(run.Output->GetNumberOfCells() == 0, "only a repeating triangle: empty output");

  // No data object in or out (a request made by hand, not by an executive): an error each.
  vtkNew<vtkColorHalfEdgeDecimation> decimation;
  vtkNew<vtkColorHalfEdgeLevelOfDetail> levels;
  for (vtkAlgorithm* filter :
       { static_cast<vtkAlgorithm*>(decimation), static_cast<vtkAlgorithm*>(levels) })
  {
    EventRecorder events;
    events.Watch(filter);
    vtkNew<vtkInformationVector> mesh, record, out;
    vtkInformationVector* in[2] = { mesh, record };
    vtkNew<vtkInformation> request;
    request->Set(vtkDemandDrivenPipeline::REQUEST_DATA());
    CD_CHECK_MSG(filter->ProcessRequest(request, in, out) == 0 && events.HasError("No input"),
                 filter->GetClassName() << ": no input data object: an error");
  }
}

/// Quads and strips: triangulated (quietly), then decimated.
CD_TEST_CASE(PolygonsAndStrips)
{
  auto grid = colordecimation::meshes::Grid(30, 30, Pattern::SharpRegions);
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkCellArray> strips;
  for (vtkIdType j = 0; j < 30; ++j)
  {
    if (j < 15)
    {
      for (vtkIdType i = 0; i < 30; ++i)
      {
        const vtkIdType a = j * 31 + i;
        const vtkIdType quad[4] = { a, a + 1, a + 32, a + 31 };
        quads->InsertNextCell(4, quad);
      }
    }
    else
    {
      std::vector<vtkIdType> strip;
      for (vtkIdType i = 0; i <= 30; ++i)
      {
        strip.push_back(j * 31 + i);
        strip.push_back((j + 1) * 31 + i);
      }
      strips->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(grid->GetPoints());
  mesh->GetPointData()->ShallowCopy(grid->GetPointData());
  mesh->SetPolys(quads);
  mesh->SetStrips(strips);
  RunResult run = Run(mesh, 0.9);
  // Legitimate input: triangulated without any message.
  CD_CHECK_MSG(run.Errors == 0 && run.Warnings == 0,
               "no message about the triangulation: " << run.WarningText());
  CD_CHECK_MSG(run.Output->GetNumberOfStrips() == 0 && run.Output->GetNumberOfPolys() > 0,
               "triangles out");
  ExpectReached(run, 0.9);
}

/// Non-finite coordinates (of a used point, or of an unused one) and point ids out of range:
/// errors.
CD_TEST_CASE(InvalidInput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : { nan, inf, -inf })
  {
    auto mesh = ColorMesh();
    vtkPoints* points = mesh->GetPoints();
    const vtkIdType unused = points->InsertNextPoint(bad, 0, 0);
    vtkDataArray* colors = mesh->GetPointData()->GetScalars();
    colors->InsertNextTuple3(0, 0, 0);
    CD_CHECK_MSG(unused > 0, "an extra point");
    ExpectEmptyWithError(Run(mesh, 0.9), "NaN or infinite point coordinates");
  }
  for (double bad : { nan, inf })
  {
    auto mesh = ColorMesh();
    mesh->GetPoints()->SetPoint(7, bad, 0, 0);
    ExpectEmptyWithError(Run(mesh, 0.9), "NaN or infinite point coordinates");
  }
  for (vtkIdType bad : { vtkIdType(-1), vtkIdType(642), vtkIdType(1) << 40 })
  {
    auto mesh = ColorMesh();
    const vtkIdType triangle[3] = { 0, 1, bad };
    mesh->GetPolys()->InsertNextCell(3, triangle);
    ExpectEmptyWithError(Run(mesh, 0.9), "point ids outside");
  }
  // A triangle that repeats a point: dropped with a warning.
  auto mesh = ColorMesh();
  const vtkIdType repeated[3] = { 0, 1, 1 };
  mesh->GetPolys()->InsertNextCell(3, repeated);
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.HasWarning("Dropped 1 triangles that repeat"),
               "a triangle repeating a point is dropped with a warning");
  ExpectReached(run, 0.9);
}

/// An input array already named vtkOriginalPointIds: replaced, with a warning.
CD_TEST_CASE(ExistingOriginalIds)
{
  auto mesh = ColorMesh();
  vtkNew<vtkIdTypeArray> stale;
  stale->SetName("vtkOriginalPointIds");
  stale->SetNumberOfValues(mesh->GetNumberOfPoints());
  stale->Fill(-5);
  mesh->GetPointData()->AddArray(stale);
  RunResult run = Run(mesh, 0.9);
  CD_CHECK_MSG(run.Errors == 0 && run.HasWarning("already has a point array"),
               "a warning about the replaced array");
  // The invariants check that the output array holds valid, distinct input ids.

  // The ids asked for under an empty name: written under the default one, with a warning.
  for (const char* name : { "", static_cast<const char*>(nullptr) })
  {
    run = Run(ColorMesh(), 0.9,
              [name](vtkColorHalfEdgeDecimation* filter)
              { filter->SetOriginalPointIdsArrayName(name); });
    auto* ids =
      vtkIdTypeArray::SafeDownCast(run.Output->GetPointData()->GetArray("vtkOriginalPointIds"));
    CD_CHECK_MSG(run.Errors == 0 && run.HasWarning("OriginalPointIdsArrayName is empty") && ids &&
                   ids->GetNumberOfTuples() == run.Output->GetNumberOfPoints(),
                 "an empty name: the ids under vtkOriginalPointIds, with a warning");
    // The invariants read the ids under the name the filter writes them (valid, distinct input
    // ids, the points and point data copied bit-exactly).
    CD_CHECK_MSG(run.Broken.empty(), "the ids are distinct input point ids");
  }
}

/**
 * A colour array of `type` with `components` components, decimated with `configure`: no
 * message, the target reached, the array keeps its type and width, and its values (moved ones
 * too) stay inside the domain of the array's mapping to [0,1]: [0,1] for floating values
 * already in it, otherwise the range of the colour components (alpha, copied, inside its own
 * range).
 */
void CheckColorKept(int type, int components, const std::string& label, const Configure& configure)
{
  auto mesh = WithColorType(ColorMesh(), type, components);
  RunResult run = Run(mesh, 0.9, configure);
  ExpectNoMessages(run);
  ExpectReached(run, 0.9);
  vtkDataArray* in = mesh->GetPointData()->GetScalars();
  vtkDataArray* out = run.Output->GetPointData()->GetArray("Color");
  CD_CHECK_MSG(out && out->GetDataType() == type && out->GetNumberOfComponents() == components,
               label << ": the colour array keeps its type and width");
  const int used = components >= 3 ? 3 : 1;
  double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
  for (int k = 0; k < used; ++k)
  {
    double r[2];
    in->GetRange(r, k);
    lo = std::min(lo, r[0]);
    hi = std::max(hi, r[1]);
  }
  if ((type == VTK_FLOAT || type == VTK_DOUBLE) && lo >= 0 && hi <= 1)
  {
    lo = 0;
    hi = 1;
  }
  for (int k = 0; out && k < components; ++k)
  {
    double domain[2] = { lo, hi }, outRange[2];
    if (k >= 3)
    {
      in->GetRange(domain, k);
    }
    out->GetRange(outRange, k);
    CD_CHECK_MSG(outRange[0] >= domain[0] && outRange[1] <= domain[1],
                 label << ": component " << k << " range [" << outRange[0] << ", " << outRange[1]
                       << "] inside [" << domain[0] << ", " << domain[1] << "]");
  }
}

/**
 * The comparison metrics on hostile input: ColorQuadric with half-edge collapses and with
 * OptimalPlacement (points and colours move), and the paper's metric in CIELab. Closed
 * surfaces keep their Euler characteristic at TargetReduction 1, flat grids stay unflipped,
 * every colour type keeps its type and width, and moved colours stay inside the domain of the
 * array's mapping to [0,1].
 */
CD_TEST_CASE(OtherMetrics)
{
  struct Setting
  {
    const char* Name;
    int Metric;
    bool Optimal;
    int Space;
  };
  const Setting settings[] = {
    { "ColorQuadric", vtkColorHalfEdgeDecimation::ColorQuadric, false,
      vtkColorHalfEdgeDecimation::RGB },
    { "ColorQuadric+OptimalPlacement", vtkColorHalfEdgeDecimation::ColorQuadric, true,
      vtkColorHalfEdgeDecimation::RGB },
    { "HalfEdgeColor+CIELab", vtkColorHalfEdgeDecimation::HalfEdgeColor, false,
      vtkColorHalfEdgeDecimation::CIELab },
  };
  for (const Setting& setting : settings)
  {
    std::cout << setting.Name << "\n";
    auto configure = [&setting](vtkColorHalfEdgeDecimation* f)
    {
      f->SetErrorMetric(setting.Metric);
      f->SetOptimalPlacement(setting.Optimal);
      f->SetColorSpace(setting.Space);
    };
    for (const auto& closed :
         { std::make_pair(colordecimation::meshes::Icosphere(3, Pattern::SharpRegions), 2LL),
           std::make_pair(colordecimation::meshes::Torus(40, 20, Pattern::FineDetail), 0LL) })
    {
      RunResult run = Run(closed.first, 1.0, configure);
      ExpectNoMessages(run);
      const Triangles out = GetTriangles(run.Output);
      const Topology topology = AnalyseTopology(out);
      CD_CHECK_MSG(
        !out.empty() && topology.Euler() == closed.second && topology.BoundaryEdges == 0 &&
          topology.NonManifoldEdges == 0 && IsOrientedSoup(out),
        setting.Name << ": a closed surface stays closed, oriented, Euler " << closed.second);
    }
    for (Pattern pattern : { Pattern::SharpRegions, Pattern::Constant })
    {
      RunResult run = Run(colordecimation::meshes::FlatGrid(40, 40, pattern), 0.9, configure);
      ExpectNoMessages(run);
      ExpectReached(run, 0.9);
      int flipped = 0;
      for (const auto& t : GetTriangles(run.Output))
      {
        flipped += TriangleNormalZ(run.Output, t) <= 0 ? 1 : 0;
      }
      CD_CHECK_MSG(flipped == 0, setting.Name << ": " << flipped << " flat-grid triangles flipped");
    }
    for (const auto& type : ColorTypes())
    {
      for (int components : { 1, 3, 4 })
      {
        CheckColorKept(type.first, components,
                       std::string(setting.Name) + ", " + type.second + " x " +
                         std::to_string(components),
                       configure);
      }
    }
    auto nan = WithColorType(ColorMesh(), VTK_FLOAT, 3);
    for (vtkIdType i = 0; i < nan->GetNumberOfPoints(); i += 13)
    {
      nan->GetPointData()->GetScalars()->SetComponent(i, 1,
                                                      std::numeric_limits<double>::quiet_NaN());
    }
    RunResult run = Run(nan, 0.9, configure);
    CD_CHECK_MSG(run.Errors == 0 && run.HasWarning("NaN"),
                 setting.Name << ": NaN colours give a warning");
    ExpectReached(run, 0.9);
  }
}

/// Out-of-range and extreme property values are clamped or survive without harm.
CD_TEST_CASE(ExtremeProperties)
{
  auto mesh = colordecimation::meshes::Icosphere(3, Pattern::FineDetail);
  const double inf = std::numeric_limits<double>::infinity();
  for (double weight : { 0.0, 1e-300, 1e300, std::numeric_limits<double>::max() })
  {
    RunResult run =
      Run(mesh, 0.9, [weight](vtkColorHalfEdgeDecimation* f) { f->SetGeometryWeight(weight); });
    ExpectNoMessages(run);
    ExpectReached(run, 0.9);
  }
  for (double angle : { 0.0, 1e-9, 180.0 })
  {
    RunResult run =
      Run(mesh, 0.9, [angle](vtkColorHalfEdgeDecimation* f) { f->SetMaximumNormalAngle(angle); });
    ExpectNoMessages(run);
    // On a sphere every collapse turns some normal: none within 1e-9 degrees.
    CD_CHECK_MSG((angle < 1 ? run.Collapses == 0 : run.Collapses > 0),
                 "MaximumNormalAngle " << angle << ": " << run.Collapses << " collapses");
  }
  vtkNew<vtkColorHalfEdgeDecimation> clamp;
  clamp->SetTargetReduction(-1);
  CD_CHECK_MSG(clamp->GetTargetReduction() == 0.0, "TargetReduction is clamped to 0");
  clamp->SetTargetReduction(2);
  CD_CHECK_MSG(clamp->GetTargetReduction() == 1.0, "TargetReduction is clamped to 1");
  clamp->SetTargetReduction(inf);
  CD_CHECK_MSG(clamp->GetTargetReduction() == 1.0, "TargetReduction inf is clamped to 1");
  clamp->SetErrorMetric(7);
  CD_CHECK_MSG(clamp->GetErrorMetric() == vtkColorHalfEdgeDecimation::AttributeQuadric,
               "ErrorMetric clamped");
  clamp->SetColorSpace(5);
  CD_CHECK_MSG(clamp->GetColorSpace() == vtkColorHalfEdgeDecimation::CIELab, "ColorSpace clamped");
  clamp->SetColorWeight(-1);
  CD_CHECK_MSG(clamp->GetColorWeight() == 0.0, "ColorWeight is clamped to 0");
  clamp->SetColorWeight(inf);
  CD_CHECK_MSG(clamp->GetColorWeight() == VTK_DOUBLE_MAX, "ColorWeight inf is clamped");
  clamp->SetBoundaryWeight(inf);
  CD_CHECK_MSG(clamp->GetBoundaryWeight() == VTK_DOUBLE_MAX, "BoundaryWeight inf is clamped");
  clamp->SetEdgeLengthWeight(-inf);
  CD_CHECK_MSG(clamp->GetEdgeLengthWeight() == 0.0, "EdgeLengthWeight -inf is clamped to 0");
  clamp->SetGeometryWeight(-3);
  CD_CHECK_MSG(clamp->GetGeometryWeight() == 0.0, "GeometryWeight is clamped to 0");
  clamp->SetGeometryWeight(std::numeric_limits<double>::infinity());
  CD_CHECK_MSG(clamp->GetGeometryWeight() == VTK_DOUBLE_MAX, "GeometryWeight inf is clamped");
  clamp->SetMaximumNormalAngle(-std::numeric_limits<double>::infinity());
  CD_CHECK_MSG(clamp->GetMaximumNormalAngle() == 0.0, "MaximumNormalAngle -inf is clamped to 0");
}

/**
 * NaN property values pass vtkSetClampMacro unchanged: the filter refuses them with an error
 * and an empty output. Also ColorWeight NaN with the ColorQuadric metric, and MaximumError
 * infinite either way (it has no clamp). (The setters clamp the other infinite values: see
 * ExtremeProperties.)
 */
CD_TEST_CASE(NaNProperties)
{
  auto mesh = colordecimation::meshes::Icosphere(3, Pattern::FineDetail);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<const char*, std::function<void(vtkColorHalfEdgeDecimation*)>>>
    settings = {
      { "TargetReduction", [nan](vtkColorHalfEdgeDecimation* f) { f->SetTargetReduction(nan); } },
      { "MaximumNormalAngle",
        [nan](vtkColorHalfEdgeDecimation* f) { f->SetMaximumNormalAngle(nan); } },
      { "GeometryWeight", [nan](vtkColorHalfEdgeDecimation* f) { f->SetGeometryWeight(nan); } },
      { "PieceWeight", [nan](vtkColorHalfEdgeDecimation* f) { f->SetPieceWeight(nan); } },
      { "KeptVertexErrorWeight",
        [nan](vtkColorHalfEdgeDecimation* f) { f->SetKeptVertexErrorWeight(nan); } },
      { "ColorWeight",
        [nan](vtkColorHalfEdgeDecimation* f)
        {
          f->SetErrorMetricToColorQuadric();
          f->SetColorWeight(nan);
        } },
      { "BoundaryWeight", [nan](vtkColorHalfEdgeDecimation* f) { f->SetBoundaryWeight(nan); } },
      { "EdgeLengthWeight", [nan](vtkColorHalfEdgeDecimation* f) { f->SetEdgeLengthWeight(nan); } },
      { "MaximumError", [nan](vtkColorHalfEdgeDecimation* f) { f->SetMaximumError(nan); } },
      { "MaximumError (infinite)",
        [](vtkColorHalfEdgeDecimation* f)
        { f->SetMaximumError(std::numeric_limits<double>::infinity()); } },
      { "MaximumError (-infinite)",
        [](vtkColorHalfEdgeDecimation* f)
        { f->SetMaximumError(-std::numeric_limits<double>::infinity()); } },
    };
  for (const auto& setting : settings)
  {
    std::cout << setting.first << "\n";
    ExpectEmptyWithError(Run(mesh, 0.9, setting.second), "NaN or infinite");
  }
}

/// A mesh that says it has 2^31 points, more than the core's 32-bit ids name (a real one would
/// need 24 GiB for its coordinates alone).
class HugePointCount : public vtkPolyData
{
public:
  static HugePointCount* New();
  vtkTypeMacro(HugePointCount, vtkPolyData);
  vtkIdType GetNumberOfPoints() override { return vtkIdType(1) << 31; }
};
vtkStandardNewMacro(HugePointCount);

/// Too many points: an error naming them, an empty output, the input untouched.
CD_TEST_CASE(TooManyPoints)
{
  auto mesh = colordecimation::meshes::Icosphere(2, Pattern::FineDetail);
  vtkNew<HugePointCount> huge;
  huge->ShallowCopy(mesh);
  vtkNew<vtkColorHalfEdgeDecimation> filter;
  EventRecorder messages;
  messages.Watch(filter);
  filter->SetInputData(huge);
  filter->SetTargetReduction(0.9);
  filter->Update();
  CD_CHECK_MSG(messages.Errors == 1 && messages.HasError("Too many points (2147483648)"),
               "one error naming the points: " << messages.ErrorText());
  vtkPolyData* output = filter->GetOutput();
  CD_CHECK_MSG(output->GetNumberOfPoints() == 0 && output->GetNumberOfCells() == 0, "empty output");
  CD_CHECK_MSG(huge->GetNumberOfPolys() == mesh->GetNumberOfPolys(), "the input keeps its cells");
}

CD_TEST_CASE(ColorType_char)
{
  ColorType(VTK_CHAR);
}

CD_TEST_CASE(ColorType_signed_char)
{
  ColorType(VTK_SIGNED_CHAR);
}

CD_TEST_CASE(ColorType_unsigned_char)
{
  ColorType(VTK_UNSIGNED_CHAR);
}

CD_TEST_CASE(ColorType_short)
{
  ColorType(VTK_SHORT);
}

CD_TEST_CASE(ColorType_unsigned_short)
{
  ColorType(VTK_UNSIGNED_SHORT);
}

CD_TEST_CASE(ColorType_int)
{
  ColorType(VTK_INT);
}

CD_TEST_CASE(ColorType_unsigned_int)
{
  ColorType(VTK_UNSIGNED_INT);
}

CD_TEST_CASE(ColorType_long)
{
  ColorType(VTK_LONG);
}

CD_TEST_CASE(ColorType_unsigned_long)
{
  ColorType(VTK_UNSIGNED_LONG);
}

CD_TEST_CASE(ColorType_long_long)
{
  ColorType(VTK_LONG_LONG);
}

CD_TEST_CASE(ColorType_unsigned_long_long)
{
  ColorType(VTK_UNSIGNED_LONG_LONG);
}

CD_TEST_CASE(ColorType_float)
{
  ColorType(VTK_FLOAT);
}

CD_TEST_CASE(ColorType_double)
{
  ColorType(VTK_DOUBLE);
}

//------------------------------------------------------------------------------
// Running out of memory.

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CD_SANITIZER_OWNS_MEMORY 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define CD_SANITIZER_OWNS_MEMORY 1
#endif
#endif

/// The address space this process maps now, in bytes (/proc/self/statm), 0 when unknown.
size_t MappedBytes()
{
  std::ifstream statm("/proc/self/statm");
  size_t pages = 0;
  statm >> pages;
  return pages * static_cast<size_t>(sysconf(_SC_PAGESIZE));
}

/// Limit the address space to what is mapped now plus `budget` bytes (0: lift the limit to
/// where it was, `old`).
void LimitAddressSpace(size_t budget, const rlimit& old)
{
  rlimit limited = old;
  if (budget > 0)
  {
    limited.rlim_cur = static_cast<rlim_t>(MappedBytes() + budget);
    if (old.rlim_cur != RLIM_INFINITY && limited.rlim_cur > old.rlim_cur)
    {
      limited.rlim_cur = old.rlim_cur;
    }
  }
  setrlimit(RLIMIT_AS, &limited);
}

/// The output after a run that failed for want of memory: empty, and said so.
bool IsEmptyWithError(vtkPolyData* output, const EventRecorder& events)
{
  return events.Errors > 0 && output->GetNumberOfPoints() == 0 && output->GetNumberOfCells() == 0;
}

/// Whether `output`'s "CellId" cell array (OutOfMemory's) has a value for each cell.
bool CarriesCellIds(vtkPolyData* output)
{
  vtkDataArray* ids = output->GetCellData()->GetArray("CellId");
  return ids && ids->GetNumberOfTuples() == output->GetNumberOfCells();
}

/// Outcomes of a run under a limit (OutOfMemory), as a child process's exit status.
enum MemoryOutcome
{
  DecimationFailed = 1, ///< the decimation ended with an error and an empty output
  LevelFailed = 2,      ///< the level's extraction did
  Wrong = 4,            ///< an output neither complete nor empty with an error
  Escaped = 8           ///< an exception came out of Update()
};

/// The decimation with the collapse record, then a level from it, with at most `budget`,
/// then `levelBudget`, bytes more address space than the process maps when each starts (0: no
/// limit): a MemoryOutcome mask.
int DecimateUnderLimit(vtkPolyData* mesh, size_t budget, size_t levelBudget)
{
  rlimit old{};
  getrlimit(RLIMIT_AS, &old);
  vtkNew<vtkColorHalfEdgeDecimation> filter;
  filter->SetInputData(mesh);
  filter->SetTargetReduction(0.9);
  filter->SetNumberOfThreads(2);
  filter->GenerateCollapseRecordOn();
  EventRecorder events;
  events.Watch(filter);
  LimitAddressSpace(budget, old);
  filter->Update();
  LimitAddressSpace(0, old);
  vtkPolyData* output = filter->GetOutput();
  if (IsEmptyWithError(output, events))
  {
    return DecimationFailed;
  }
  if (events.Errors > 0 || output->GetNumberOfPolys() != 2048 || !CarriesCellIds(output) ||
      !CheckInvariants(mesh, filter, output, false).empty())
  {
    std::cout << "  " << budget << " bytes: " << output->GetNumberOfPolys() << " triangles, "
              << events.ErrorText() << "\n";
    return Wrong;
  }
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  lod->SetInputData(mesh);
  lod->SetRecordData(filter->GetCollapseRecord());
  lod->SetTargetReduction(0.5);
  EventRecorder lodEvents;
  lodEvents.Watch(lod);
#ifdef __GLIBC__
  malloc_trim(0); // the decimation's freed memory unmapped: the level's must be mapped anew
#endif
  LimitAddressSpace(levelBudget, old);
  lod->Update();
  LimitAddressSpace(0, old);
  vtkPolyData* level = lod->GetOutput();
  if (IsEmptyWithError(level, lodEvents))
  {
    return lod->GetProgressText() ? Wrong : LevelFailed; // no "Reading..." left behind
  }
  return lodEvents.Errors == 0 && level->GetNumberOfPolys() == 10240 && CarriesCellIds(level)
    ? 0
    : Wrong;
}

CD_TEST_CASE(OutOfMemory)
{
  // The decimation (with the collapse record, on 2 threads), then a level's extraction, in a
  // child process (which has not decimated before: little freed memory to reuse), one or the
  // other under an address-space limit of 1 KiB to 256 MiB above what the process maps: each
  // ends as without the limit or with an error and an empty output, never with the process;
  // some of each, so that the limit is known to bite.
#ifdef CD_SANITIZER_OWNS_MEMORY
  colordecimation::testing::SkipTestCase("the sanitizer's runtime reserves the address space");
#else
  auto mesh = colordecimation::meshes::Icosphere(5, Pattern::FineDetail);
  vtkNew<vtkIdTypeArray> cellIds; // cell data to carry: the output's cell data path too
  cellIds->SetName("CellId");
  cellIds->SetNumberOfValues(mesh->GetNumberOfCells());
  std::iota(cellIds->GetPointer(0), cellIds->GetPointer(0) + mesh->GetNumberOfCells(), 0);
  mesh->GetCellData()->AddArray(cellIds);
  int counts[4] = {};
  // The decimation's budget from 64 KiB up, the level's unlimited; then the other way round,
  // from 1 KiB.
  for (const bool level : { false, true })
  {
    for (double kib = level ? 1 : 64; kib <= 256 * 1024; kib *= 1.5)
    {
      const auto budget = static_cast<size_t>(kib * 1024);
      std::cout.flush();
      const pid_t child = fork();
      if (child == 0)
      {
#ifdef __GLIBC__
        mallopt(M_ARENA_MAX, 1); // no arenas reserved ahead for the threads the filter starts
#endif
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // VTK's arrays' own errors
        int outcome = Escaped;
        try
        {
          outcome = DecimateUnderLimit(mesh, level ? 0 : budget, level ? budget : 0);
        }
        catch (...)
        {
        }
        std::cout.flush(); // _Exit flushes nothing: a wrong output's lines would be lost
        std::_Exit(outcome);
      }
      int status = 0;
      CD_CHECK(child > 0 && waitpid(child, &status, 0) == child);
      const bool exited = WIFEXITED(status);
      const int outcome = exited ? WEXITSTATUS(status) : Wrong;
      CD_CHECK_MSG(exited && !(outcome & (Wrong | Escaped)),
                   kib << " KiB" << (level ? " for the level" : "") << ": "
                       << (!exited               ? "the process ended on a signal"
                             : outcome & Escaped ? "an exception escaped"
                                                 : "wrong output"));
      counts[outcome & 3] += 1;
    }
  }
  std::cout << "  runs: decimation out of memory " << counts[DecimationFailed]
            << ", level out of memory " << counts[LevelFailed] << ", both complete " << counts[0]
            << "\n";
  CD_CHECK(counts[DecimationFailed] > 0 && counts[LevelFailed] > 0 && counts[0] > 0);
#endif
}

} // namespace

int main(int argc, char* argv[])
{
  return RunTestCases(argc, argv);
}
