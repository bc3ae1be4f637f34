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
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using colordecimation::meshes::Pattern;
using colordecimation::testing::IsOrientedSoup;
using EventCounter = colordecimation::testing::EventRecorder;
using Triangles = std::vector<colordecimation::testing::Tri>;

Triangles TrianglesOf(vtkPolyData* mesh)
{
  return colordecimation::testing::GetTriangles(mesh);
}

Triangles OriginalTriangles(vtkPolyData* output)
{
  return colordecimation::testing::CanonicalSorted(
    colordecimation::testing::GetOriginalTriangles(output));
}

int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    ++Failures;
    std::cerr << "FAILED: " << what << "\n";
  }
}

template <typename... T>
std::string Say(const T&... parts)
{
  std::ostringstream os;
  (void)std::initializer_list<int>{ ((os << parts), 0)... };
  return os.str();
}

//------------------------------------------------------------------------------
// Running the filter.

struct Run
{
  vtkSmartPointer<vtkColorHalfEdgeDecimation> Filter;
  vtkSmartPointer<vtkPolyData> Output;
  std::unique_ptr<EventCounter> Events;
  vtkIdType InputTriangles = 0;
  vtkIdType OutputTriangles() const { return this->Output->GetNumberOfPolys(); }
};

/**
 * Decimate `input` (settings applied by `configure`), then assert the invariants and the
 * collapse bound, and that the input was left untouched.
 */
Run Decimate(vtkPolyData* input, double targetReduction,
             const std::function<void(vtkColorHalfEdgeDecimation*)>& configure = nullptr)
{
  Run run;
  run.Filter = vtkSmartPointer<vtkColorHalfEdgeDecimation>::New();
  run.Events.reset(new EventCounter);
  run.Events->Watch(run.Filter);
  run.Filter->SetInputData(input);
  run.Filter->SetTargetReduction(targetReduction);
  if (configure)
  {
    configure(run.Filter);
  }
  const vtkIdType inputPoints = input->GetNumberOfPoints();
  const vtkIdType inputCells = input->GetNumberOfCells();
  run.Filter->Update();
  run.Output = run.Filter->GetOutput();
  run.InputTriangles = static_cast<vtkIdType>(TrianglesOf(input).size());
  for (const std::string& broken : colordecimation::testing::CheckInvariants(
         input, run.Filter, run.Output, run.Events->Errors > 0))
  {
    Check(false, "invariant: " + broken);
  }
  Check(run.Filter->GetNumberOfCollapses() <= inputPoints,
        Say("NumberOfCollapses ", run.Filter->GetNumberOfCollapses(), " <= input points ",
            inputPoints));
  Check(input->GetNumberOfPoints() == inputPoints && input->GetNumberOfCells() == inputCells,
        "the input is left unchanged");
  for (const std::string& text : run.Events->WarningTexts)
  {
    std::cout << "  warning: " << text;
  }
  for (const std::string& text : run.Events->ErrorTexts)
  {
    std::cout << "  error: " << text;
  }
  std::cout << "  " << inputPoints << " points, " << run.InputTriangles << " triangles -> "
            << run.Output->GetNumberOfPoints() << " points, " << run.OutputTriangles()
            << " triangles; " << run.Filter->GetNumberOfCollapses() << " collapses, reduction "
            << run.Filter->GetActualReduction() << "\n";
  return run;
}

void ExpectNoMessages(const Run& run)
{
  Check(run.Events->Errors == 0, Say("no error (got ", run.Events->Errors, ")"));
  Check(run.Events->Warnings == 0, Say("no warning (got ", run.Events->Warnings, ")"));
}

void ExpectEmptyWithError(const Run& run, const std::string& text)
{
  Check(run.Events->Errors == 1, Say("one error (got ", run.Events->Errors, ")"));
  Check(run.Events->HasError(text), "the error says '" + text + "'");
  Check(run.Output->GetNumberOfPoints() == 0 && run.Output->GetNumberOfCells() == 0,
        "empty output");
}

void ExpectReached(const Run& run, double target, double slack = 0.02)
{
  Check(run.Filter->GetActualReduction() >= target - slack,
        Say("reduction ", run.Filter->GetActualReduction(), " reaches the target ", target,
            " (within ", slack, ")"));
}

//------------------------------------------------------------------------------
// Meshes.

vtkSmartPointer<vtkPolyData> Make(const std::vector<std::array<double, 3>>& points,
                                  const Triangles& triangles)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : points)
  {
    pts->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(pts);
  mesh->SetPolys(polys);
  return mesh;
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

/// A flat square grid (z = 0) in [-1,1]^2, coloured by `pattern`.
vtkSmartPointer<vtkPolyData> MakeFlatGrid(int n, Pattern pattern)
{
  auto mesh = colordecimation::meshes::Grid(n, n, pattern);
  vtkPoints* points = mesh->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[2] = 0;
    points->SetPoint(i, p);
  }
  colordecimation::meshes::ApplyPattern(mesh, pattern);
  return mesh;
}

/// Copy of `mesh` with every coordinate multiplied by `scale`.
vtkSmartPointer<vtkPolyData> Scaled(vtkPolyData* mesh, double scale)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  vtkPoints* points = copy->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (double& x : p)
    {
      x *= scale;
    }
    points->SetPoint(i, p);
  }
  return copy;
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

double TriangleNormalZ(vtkPolyData* mesh, const std::array<long long, 3>& t)
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
double LargestCornerSine(vtkPolyData* mesh, const std::array<long long, 3>& t)
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

struct EdgeCounts
{
  std::map<std::pair<long long, long long>, int> Undirected;
  long long Vertices = 0;
};

EdgeCounts CountEdges(const Triangles& triangles)
{
  EdgeCounts counts;
  std::set<long long> vertices;
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const long long a = t[k], b = t[(k + 1) % 3];
      ++counts.Undirected[{ std::min(a, b), std::max(a, b) }];
      vertices.insert(a);
    }
  }
  counts.Vertices = static_cast<long long>(vertices.size());
  return counts;
}

/// V - E + F of a triangle set, and whether every edge has exactly `perEdge` triangles.
long long Euler(const Triangles& triangles)
{
  const EdgeCounts counts = CountEdges(triangles);
  return counts.Vertices - static_cast<long long>(counts.Undirected.size()) +
    static_cast<long long>(triangles.size());
}

int CountBoundaryEdges(const Triangles& triangles)
{
  int boundary = 0;
  for (const auto& e : CountEdges(triangles).Undirected)
  {
    boundary += e.second == 1 ? 1 : 0;
  }
  return boundary;
}

bool EveryEdgeHas(const Triangles& triangles, int count)
{
  for (const auto& e : CountEdges(triangles).Undirected)
  {
    if (e.second != count)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Topology.

/// An edge shared by three triangles (a fin on a grid's interior edge).
void NonManifoldEdge()
{
  // The small grid, and one large enough to be decimated renumbered (Decimator.h).
  for (int size : { 30, 300 })
  {
    auto grid = colordecimation::meshes::Grid(size, size, Pattern::SharpRegions);
    // Interior edge (a, b) of the grid: a diagonal of the cell in the middle.
    const long long a = (size / 2) * (size + 1) + size / 2, b = a + size + 1 + 1;
    auto points = PointsOf(grid);
    Triangles triangles = TrianglesOf(grid);
    int onEdge = 0;
    for (const auto& t : triangles)
    {
      int hits = 0;
      for (long long id : t)
      {
        hits += (id == a || id == b) ? 1 : 0;
      }
      onEdge += hits == 2 ? 1 : 0;
    }
    Check(onEdge == 2, "the chosen edge is an interior grid edge");
    points.push_back({ 0.0, 0.0, 1.0 });
    triangles.push_back({ a, b, static_cast<long long>(points.size() - 1) });
    auto mesh = Make(points, triangles);
    // The fin's apex needs a colour too.
    vtkNew<vtkUnsignedCharArray> rgb;
    rgb->DeepCopy(grid->GetPointData()->GetScalars());
    rgb->InsertNextTuple3(10, 20, 30);
    mesh->GetPointData()->SetScalars(rgb);

    Run run = Decimate(mesh, 0.9);
    Check(run.Events->Errors == 0, "no error");
    Check(run.Events->HasWarning("non-manifold"), "a warning about the non-manifold edge");
    int kept = 0;
    for (const auto& t : OriginalTriangles(run.Output))
    {
      int hits = 0;
      for (long long id : t)
      {
        hits += (id == a || id == b) ? 1 : 0;
      }
      kept += hits == 2 ? 1 : 0;
    }
    Check(
      kept == 3,
      Say("grid ", size, ": the three triangles on the non-manifold edge are kept (", kept, ")"));
    Check(run.Filter->GetActualReduction() > 0.5, "the rest of the grid is decimated");
  }
}

/// Two grids that share one corner point: a bow-tie vertex.
void NonManifoldVertex()
{
  auto first = colordecimation::meshes::Grid(20, 20, Pattern::SmoothGradient);
  auto points = PointsOf(first);
  Triangles triangles = TrianglesOf(first);
  const long long n = static_cast<long long>(points.size());
  const long long corner = n - 1; // (1, 1, z)
  std::vector<int> part(triangles.size(), 0);
  // The second grid: the first turned by 180 degrees about the vertical through `corner`,
  // so that its own corner n - 1 falls on `corner` and the two touch at that point only.
  const auto c = points[corner];
  const auto firstPoints = PointsOf(first);
  std::vector<long long> remap(static_cast<size_t>(n));
  for (long long i = 0; i < n; ++i)
  {
    if (i == corner)
    {
      remap[i] = corner;
      continue;
    }
    const auto& p = firstPoints[i];
    points.push_back({ 2 * c[0] - p[0], 2 * c[1] - p[1], p[2] });
    remap[i] = static_cast<long long>(points.size() - 1);
  }
  for (const auto& t : TrianglesOf(first))
  {
    triangles.push_back({ remap[t[0]], remap[t[1]], remap[t[2]] });
    part.push_back(1);
  }
  auto mesh = Make(points, triangles);
  AddCellValues(mesh, "Part", part);
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SmoothGradient);

  Run run = Decimate(mesh, 0.9);
  Check(run.Events->Errors == 0, "no error");
  Check(run.Events->HasWarning("non-manifold vertices"), "a warning about the bow-tie");
  // The bow-tie vertex survives with triangles of both grids.
  std::set<int> partsAtCorner;
  vtkIntArray* outPart = vtkIntArray::SafeDownCast(run.Output->GetCellData()->GetArray("Part"));
  const Triangles out = TrianglesOf(run.Output);
  vtkIdTypeArray* original =
    vtkIdTypeArray::SafeDownCast(run.Output->GetPointData()->GetArray("vtkOriginalPointIds"));
  for (size_t c = 0; c < out.size() && outPart && original; ++c)
  {
    for (long long id : out[c])
    {
      if (original->GetValue(id) == corner)
      {
        partsAtCorner.insert(outPart->GetValue(static_cast<vtkIdType>(c)));
      }
    }
  }
  Check(partsAtCorner.size() == 2, "the bow-tie vertex keeps triangles of both grids");
  Check(run.Filter->GetActualReduction() > 0.8, "both grids are decimated");
}

/// The same triangle twice (same orientation, and once reversed) inside a grid.
void DuplicateTriangles()
{
  auto grid = colordecimation::meshes::Grid(20, 20, Pattern::FineDetail);
  Triangles triangles = TrianglesOf(grid);
  const std::array<long long, 3> same = triangles[200];
  const std::array<long long, 3> reversed = { triangles[500][0], triangles[500][2],
                                              triangles[500][1] };
  triangles.push_back(same);
  triangles.push_back(reversed);
  auto mesh = Make(PointsOf(grid), triangles);
  mesh->GetPointData()->SetScalars(grid->GetPointData()->GetScalars());

  Run run = Decimate(mesh, 0.9);
  Check(run.Events->Errors == 0, "no error");
  Check(run.Events->HasWarning("non-manifold"), "a warning about the duplicated edges");
  auto sorted = [](std::array<long long, 3> t)
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
  Check(copiesOfSame == 2,
        Say("both copies of the duplicated triangle are kept (", copiesOfSame, ")"));
  Check(copiesOfReversed == 2,
        Say("the triangle and its reversed copy are kept (", copiesOfReversed, ")"));
  Check(run.Filter->GetActualReduction() > 0.7, "the rest of the grid is decimated");
}

/// A triangle and its reversed copy alone: a closed two-faced "pillow".
void DoubleSidedTriangle()
{
  auto mesh = Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 2, 1 } });
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SmoothGradient);
  for (double target : { 0.5, 1.0 })
  {
    Run run = Decimate(mesh, target);
    ExpectNoMessages(run);
    Check(run.OutputTriangles() == 2 && run.Filter->GetNumberOfCollapses() == 0,
          "both faces are kept");
  }
}

/// Every triangle with its own three points (a triangle soup): nothing can collapse.
void TriangleSoup()
{
  auto grid = colordecimation::meshes::Grid(10, 10, Pattern::SharpRegions);
  const auto gridPoints = PointsOf(grid);
  std::vector<std::array<double, 3>> points;
  Triangles triangles;
  for (const auto& t : TrianglesOf(grid))
  {
    const long long base = static_cast<long long>(points.size());
    for (long long id : t)
    {
      points.push_back(gridPoints[id]);
    }
    triangles.push_back({ base, base + 1, base + 2 });
  }
  auto mesh = Make(points, triangles);
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SharpRegions);
  Run run = Decimate(mesh, 0.9);
  ExpectNoMessages(run);
  Check(run.Filter->GetNumberOfCollapses() == 0, "no collapse");
  Check(OriginalTriangles(run.Output) == OriginalTriangles(Decimate(mesh, 0.0).Output),
        "the output is the input");
}

/// Coincident duplicates of every point, unused: dropped, and the result does not change.
void DuplicatePoints()
{
  auto grid = colordecimation::meshes::Grid(30, 30, Pattern::SharpRegions);
  auto points = PointsOf(grid);
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i)
  {
    points.push_back(points[i]);
  }
  auto mesh = Make(points, TrianglesOf(grid));
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SharpRegions);
  Run run = Decimate(mesh, 0.9);
  ExpectNoMessages(run);
  Run reference = Decimate(grid, 0.9);
  Check(OriginalTriangles(run.Output) == OriginalTriangles(reference.Output),
        "the same triangles as without the duplicates");
  Check(run.Output->GetNumberOfPoints() == reference.Output->GetNumberOfPoints(),
        "the unused duplicates are dropped");
}

/// A flat grid whose second row of points lies on the first (zero-length edges, zero-area
/// triangles) and whose row 10 lies on row 9's line (collinear triangles).
void ZeroAreaTriangles()
{
  auto grid = MakeFlatGrid(20, Pattern::SharpRegions);
  auto points = PointsOf(grid);
  for (int i = 0; i <= 20; ++i)
  {
    points[21 + i] = points[i]; // row 1 onto row 0
    // Row 10 onto row 9's line, shifted by half a cell: collinear triangles between them.
    points[10 * 21 + i] = points[9 * 21 + i];
    points[10 * 21 + i][0] += 0.05;
  }
  const Triangles triangles = TrianglesOf(grid);
  auto mesh = Make(points, triangles);
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SharpRegions);
  int zeroArea = 0;
  for (const auto& t : triangles)
  {
    zeroArea += LargestCornerSine(mesh, t) < 1e-6 ? 1 : 0;
  }
  Check(zeroArea == 80, Say("the input has 80 zero-area triangles (", zeroArea, ")"));

  Run run = Decimate(mesh, 0.9);
  Check(run.Events->Errors == 0, "no error");
  Check(run.Filter->GetActualReduction() > 0.5, "the grid is decimated");
  // No collapse creates a zero-area triangle: those of the output are input triangles.
  std::set<std::array<long long, 3>> input;
  for (const auto& t : triangles)
  {
    std::array<long long, 3> s = t;
    while (s[0] > s[1] || s[0] > s[2])
    {
      s = { s[1], s[2], s[0] };
    }
    input.insert(s);
  }
  for (const auto& t : OriginalTriangles(run.Output))
  {
    if (LargestCornerSine(mesh, t) < 1e-6)
    {
      Check(input.count(t) == 1,
            Say("zero-area output triangle ", t[0], " ", t[1], " ", t[2], " is an input one"));
    }
  }
}

/// Points used by no triangle: dropped from the output.
void IsolatedPoints()
{
  auto grid = colordecimation::meshes::Torus(40, 20, Pattern::SmoothGradient);
  auto points = PointsOf(grid);
  const long long used = static_cast<long long>(points.size());
  for (int k = 0; k < 50; ++k)
  {
    points.push_back({ 0.01 * k, -0.02 * k, 0.03 * k }); // inside the bounding box
  }
  auto mesh = Make(points, TrianglesOf(grid));
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SmoothGradient);
  Run run = Decimate(mesh, 0.9);
  ExpectNoMessages(run);
  ExpectReached(run, 0.9);
  vtkIdTypeArray* original =
    vtkIdTypeArray::SafeDownCast(run.Output->GetPointData()->GetArray("vtkOriginalPointIds"));
  bool anyIsolated = false;
  for (vtkIdType i = 0; original && i < original->GetNumberOfValues(); ++i)
  {
    anyIsolated = anyIsolated || original->GetValue(i) >= used;
  }
  Check(original && !anyIsolated, "no isolated point in the output");
}

/**
 * A grid whose triangles inside a block are reversed. The seam edges (two triangles of
 * disagreeing orientation) lock their vertices, so each of them keeps its two triangles; both
 * regions are decimated; no output triangle is reversed against its own region (normal turned
 * by more than 120 degrees from the region's side; the flip guard bounds each collapse's turn
 * by MaximumNormalAngle, 90 degrees, so output triangles may stand steeply, see
 * docs/RELIABILITY.md).
 */
void MixedOrientation()
{
  auto grid = colordecimation::meshes::Grid(30, 30, Pattern::SmoothGradient);
  const auto points = PointsOf(grid);
  Triangles triangles = TrianglesOf(grid);
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
  Check(TriangleNormalZ(mesh, triangles[0]) > 0, "the grid faces +z");
  // The seam: edges whose two triangles use them in the same direction.
  std::map<std::pair<long long, long long>, int> directed;
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  std::set<std::pair<long long, long long>> seam;
  for (const auto& e : directed)
  {
    if (e.second == 2)
    {
      seam.insert(
        { std::min(e.first.first, e.first.second), std::max(e.first.first, e.first.second) });
    }
  }
  Check(seam.size() == 48, Say("the seam has 48 edges (", seam.size(), ")"));

  Run run = Decimate(mesh, 0.9);
  Check(run.Events->Errors == 0, "no error");
  Check(run.Events->HasWarning("48 non-manifold or inconsistently oriented edges"),
        "a warning about the 48 seam edges");
  Check(run.Filter->GetActualReduction() > 0.6, "both regions are decimated");
  const Triangles original = OriginalTriangles(run.Output);
  size_t seamKept = 0;
  for (const auto& e : CountEdges(original).Undirected)
  {
    seamKept += (seam.count(e.first) && e.second == 2) ? 1 : 0;
  }
  Check(seamKept == seam.size(),
        Say("every seam edge keeps its two triangles (", seamKept, " of ", seam.size(), ")"));
  vtkIntArray* outOrientation =
    vtkIntArray::SafeDownCast(run.Output->GetCellData()->GetArray("Orientation"));
  const Triangles out = TrianglesOf(run.Output);
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
    const double side = n[2] * outOrientation->GetValue(static_cast<vtkIdType>(c));
    reversed += side < -0.5 * vtkMath::Norm(n) ? 1 : 0;
    steep += side <= 0 ? 1 : 0;
  }
  Check(outOrientation && reversed == 0,
        Say(reversed, " output triangles are reversed against their region"));
  std::cout << "  " << steep << " output triangles stand at 90 degrees or more to their region\n";
}

//------------------------------------------------------------------------------
// Geometry.

/**
 * Closed smooth surfaces (an icosphere and a torus) stay outward-facing: no output triangle
 * is folded over (its normal turned by more than 120 degrees from the surface's outward
 * normal), at 50 % and 90 % reduction, with both metrics and the default MaximumNormalAngle.
 * Triangles standing at about 90 degrees (slivers) are counted and printed, not failed.
 */
void NoFoldOver()
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
        Run run = Decimate(s.Mesh, target,
                           [metric](vtkColorHalfEdgeDecimation* f) { f->SetErrorMetric(metric); });
        ExpectNoMessages(run);
        int folded = 0, standing = 0;
        for (const auto& t : TrianglesOf(run.Output))
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
        Check(folded == 0,
              Say(s.Name, ", reduction ", target, ", ", run.Filter->GetErrorMetricAsString(), ": ",
                  folded,
                  " output triangles are folded over (turned by more than 120 "
                  "degrees from the outward normal)"));
      }
    }
  }
}

/// A flat grid: every quadric is singular (all Q = 0); colour alone orders the collapses.
void FlatGrid()
{
  for (Pattern pattern : { Pattern::SharpRegions, Pattern::Constant })
  {
    auto mesh = MakeFlatGrid(50, pattern);
    Run run = Decimate(mesh, 0.9);
    ExpectNoMessages(run);
    ExpectReached(run, 0.9);
    int flipped = 0;
    for (const auto& t : TrianglesOf(run.Output))
    {
      flipped += TriangleNormalZ(run.Output, t) <= 0 ? 1 : 0;
    }
    Check(flipped == 0, Say(flipped, " output triangles flipped or degenerate"));

    Run preserved =
      Decimate(mesh, 0.9, [](vtkColorHalfEdgeDecimation* f) { f->PreserveBoundaryOn(); });
    ExpectNoMessages(preserved);
    const Triangles input = TrianglesOf(mesh);
    std::set<long long> boundary;
    for (const auto& e : CountEdges(input).Undirected)
    {
      if (e.second == 1)
      {
        boundary.insert(e.first.first);
        boundary.insert(e.first.second);
      }
    }
    std::set<long long> kept;
    for (const auto& t : OriginalTriangles(preserved.Output))
    {
      kept.insert(t.begin(), t.end());
    }
    size_t boundaryKept = 0;
    for (long long v : boundary)
    {
      boundaryKept += kept.count(v);
    }
    Check(
      boundary.size() == 200 && boundaryKept == boundary.size(),
      Say("PreserveBoundary keeps the ", boundary.size(), " boundary points (", boundaryKept, ")"));
    Check(CountBoundaryEdges(TrianglesOf(preserved.Output)) == 200,
          "PreserveBoundary keeps every boundary edge");
  }
}

/// One triangle: nothing to collapse.
void SingleTriangle()
{
  auto mesh = Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 } });
  colordecimation::meshes::ApplyPattern(mesh, Pattern::SharpRegions);
  for (double target : { 0.0, 0.9, 1.0 })
  {
    Run run = Decimate(mesh, target);
    ExpectNoMessages(run);
    Check(run.OutputTriangles() == 1 && run.Output->GetNumberOfPoints() == 3,
          "the triangle is kept");
    Check(run.Filter->GetNumberOfCollapses() == 0 && run.Filter->GetActualReduction() == 0.0,
          "no collapse, reduction 0");
  }
}

/// Coordinates scaled by 1e7 and 1e-7 give the same triangles as at unit scale.
void Scale(double scale)
{
  for (auto mesh : { colordecimation::meshes::Icosphere(4, Pattern::FineDetail),
                     colordecimation::meshes::Grid(40, 40, Pattern::SharpRegions) })
  {
    Run unit = Decimate(mesh, 0.9);
    ExpectNoMessages(unit);
    Run scaled = Decimate(Scaled(mesh, scale), 0.9);
    ExpectNoMessages(scaled);
    Check(OriginalTriangles(scaled.Output) == OriginalTriangles(unit.Output),
          Say("scale ", scale, " gives the triangles of scale 1"));
  }
}

void LargeScale()
{
  Scale(1e7);
}

void SmallScale()
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
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
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
    Run run = Decimate(WithColorType(mesh, type, components), 0.9);
    ExpectNoMessages(run);
    ExpectReached(run, 0.9);
    vtkDataArray* out = run.Output->GetPointData()->GetArray("Color");
    Check(out && out->GetDataType() == type && out->GetNumberOfComponents() == components,
          "the colour array keeps its type and width");
    byComponents[components] = OriginalTriangles(run.Output);
  }
  Check(byComponents[4] == byComponents[3], "RGBA gives the triangles of RGB");

  // Grey: one component equals three equal components.
  auto greyThrice = WithColorType(mesh, type, 3);
  vtkDataArray* grey = greyThrice->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < grey->GetNumberOfTuples(); ++i)
  {
    grey->SetComponent(i, 1, grey->GetComponent(i, 0));
    grey->SetComponent(i, 2, grey->GetComponent(i, 0));
  }
  Check(byComponents[1] == OriginalTriangles(Decimate(greyThrice, 0.9).Output),
        "one grey component gives the triangles of three equal components");

  if (type == VTK_FLOAT || type == VTK_DOUBLE)
  {
    Check(byComponents[3] ==
            OriginalTriangles(Decimate(WithColorType(mesh, VTK_UNSIGNED_CHAR, 3), 0.9).Output),
          "value/255 in a floating array gives the triangles of unsigned char");
  }
  else if (type != VTK_UNSIGNED_CHAR)
  {
    Check(byComponents[3] ==
            OriginalTriangles(Decimate(WithColorType(mesh, VTK_CHAR, 3), 0.9).Output),
          "every integer type other than unsigned char gives the triangles of char");
  }
}

/// NaN and infinite colour values: a warning; measured as 0, carried through unchanged.
void NaNColors()
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
    Run run = Decimate(mesh, 0.9);
    Check(run.Events->Errors == 0, "no error");
    Check(run.Events->Warnings == 1 && run.Events->HasWarning(Say(spoiled, " colour tuples")),
          Say("one warning counting the ", spoiled, " NaN or infinite tuples"));
    ExpectReached(run, 0.9);
    // Bit-exact copies (NaN included) are checked by the invariants; count the NaN kept.
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
  // All colours NaN: a warning, and then the result of no colour at all.
  auto mesh = WithColorType(ColorMesh(), VTK_FLOAT, 3);
  mesh->GetPointData()->GetScalars()->Fill(std::numeric_limits<double>::quiet_NaN());
  Run run = Decimate(mesh, 0.9);
  Check(run.Events->Errors == 0 && run.Events->Warnings == 1, "all NaN: one warning");
  ExpectReached(run, 0.9);
}

/// Colour array of the wrong length, or as cell data: errors, empty output.
void BadColorArrays()
{
  auto mesh = ColorMesh();
  auto shortColors = vtkSmartPointer<vtkPolyData>::New();
  shortColors->DeepCopy(mesh);
  shortColors->GetPointData()->GetScalars()->SetNumberOfTuples(mesh->GetNumberOfPoints() - 1);
  ExpectEmptyWithError(Decimate(shortColors, 0.9), "tuples for");

  auto cellColors = vtkSmartPointer<vtkPolyData>::New();
  cellColors->DeepCopy(mesh);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("CellRGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(mesh->GetNumberOfCells());
  rgb->Fill(100);
  cellColors->GetCellData()->AddArray(rgb);
  ExpectEmptyWithError(Decimate(cellColors, 0.9,
                                [](vtkColorHalfEdgeDecimation* f)
                                {
                                  f->SetInputArrayToProcess(
                                    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS,
                                    "CellRGB");
                                }),
                       "not a point-data array");

  auto noColors = vtkSmartPointer<vtkPolyData>::New();
  noColors->DeepCopy(mesh);
  noColors->GetPointData()->SetScalars(nullptr);
  Run run = Decimate(noColors, 0.9);
  Check(run.Events->Errors == 0 && run.Events->HasWarning("No colour array"),
        "no colour array: a warning");
  ExpectReached(run, 0.9);
}

/**
 * Point-data arrays shorter than the number of points and cell-data arrays shorter than the
 * number of cells, that the filter does not use as the colour (the Geometry metric does not
 * look at the colour): left out of the output, with one warning naming them; the rest is
 * decimated as usual. (Before 76cd09e they were copied past their end.)
 */
void ShortPointArray()
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
  Run run =
    Decimate(mesh, 0.9, [](vtkColorHalfEdgeDecimation* f) { f->SetErrorMetricToGeometry(); });
  Check(run.Events->Errors == 0, "no error");
  Check(run.Events->Warnings == 1 && run.Events->HasWarning("left out") &&
          run.Events->HasWarning("'RGB'") && run.Events->HasWarning("'ShortCells'"),
        "one warning naming the two arrays left out");
  Check(!run.Output->GetPointData()->GetArray("RGB") &&
          !run.Output->GetCellData()->GetArray("ShortCells"),
        "the short arrays are not in the output");
  Check(run.Output->GetPointData()->GetArray("Good") != nullptr, "the other arrays are");
  ExpectReached(run, 0.9);
}

//------------------------------------------------------------------------------
// Target reduction and input validation.

/// TargetReduction 0: the output is the input (its triangles, on the points they use).
void TargetReductionZero()
{
  auto mesh = colordecimation::meshes::Torus(40, 20, Pattern::FineDetail);
  Run run = Decimate(mesh, 0.0);
  ExpectNoMessages(run);
  Check(run.Filter->GetNumberOfCollapses() == 0, "no collapse");
  Check(run.OutputTriangles() == run.InputTriangles && run.Filter->GetActualReduction() == 0.0,
        "every triangle is kept");
  Triangles input = TrianglesOf(mesh);
  for (auto& t : input)
  {
    while (t[0] > t[1] || t[0] > t[2])
    {
      t = { t[1], t[2], t[0] };
    }
  }
  std::sort(input.begin(), input.end());
  Check(OriginalTriangles(run.Output) == input, "the same triangles");
}

/// TargetReduction 1: as far as the rules allow; closed surfaces stay closed, of the same
/// Euler characteristic; an open grid keeps one boundary loop.
void TargetReductionOne()
{
  struct Case
  {
    vtkSmartPointer<vtkPolyData> Mesh;
    long long Euler;
    bool Closed;
  };
  for (const Case& c :
       { Case{ colordecimation::meshes::Icosphere(3, Pattern::SharpRegions), 2, true },
         Case{ colordecimation::meshes::Torus(40, 20, Pattern::SmoothGradient), 0, true },
         Case{ colordecimation::meshes::Grid(30, 30, Pattern::FineDetail), 1, false } })
  {
    Run run = Decimate(c.Mesh, 1.0);
    ExpectNoMessages(run);
    const Triangles out = TrianglesOf(run.Output);
    Check(!out.empty(), "the output is not empty");
    Check(run.Filter->GetActualReduction() > 0.9, "most triangles are removed");
    Check(Euler(out) == c.Euler, Say("Euler characteristic ", Euler(out), " == ", c.Euler));
    Check(IsOrientedSoup(out), "the output is consistently oriented");
    if (c.Closed)
    {
      Check(EveryEdgeHas(out, 2), "the output is closed");
    }
    else
    {
      Check(CountBoundaryEdges(out) >= 3, "the grid keeps a boundary");
    }
  }
}

/// Empty input, points without cells, only vertices and lines: empty output.
void EmptyAndNoSurface()
{
  vtkNew<vtkPolyData> empty;
  Run run = Decimate(empty, 0.9);
  ExpectNoMessages(run);
  Check(run.Output->GetNumberOfPoints() == 0, "empty input: empty output");

  auto pointsOnly = ColorMesh();
  pointsOnly->SetPolys(vtkNew<vtkCellArray>());
  run = Decimate(pointsOnly, 0.9);
  ExpectNoMessages(run);
  Check(run.Output->GetNumberOfPoints() == 0, "points without cells: empty output");

  auto linesOnly = ColorMesh();
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[4] = { 0, 1, 2, 3 };
  lines->InsertNextCell(4, line);
  vtkNew<vtkCellArray> verts;
  verts->InsertNextCell(1, line);
  linesOnly->SetPolys(vtkNew<vtkCellArray>());
  linesOnly->SetLines(lines);
  linesOnly->SetVerts(verts);
  run = Decimate(linesOnly, 0.9);
  Check(run.Events->Errors == 0, "no error");
  Check(run.Events->HasWarning("Dropping 1 vertex and 1 line"), "a warning about the cells");
  Check(run.Output->GetNumberOfPoints() == 0 && run.Output->GetNumberOfCells() == 0,
        "only vertices and lines: empty output");
}

/// Quads and strips: triangulated (with a warning), then decimated.
void PolygonsAndStrips()
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
  Run run = Decimate(mesh, 0.9);
  Check(run.Events->Errors == 0, "no error");
  Check(run.Events->HasWarning("Triangulated 450 polygons and 15 triangle strips"),
        "a warning about the triangulation");
  Check(run.Output->GetNumberOfStrips() == 0 && run.OutputTriangles() > 0, "triangles out");
  ExpectReached(run, 0.9);
}

/// Non-finite coordinates (even of an unused point) and point ids out of range: errors.
void InvalidInput()
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
    Check(unused > 0, "an extra point");
    ExpectEmptyWithError(Decimate(mesh, 0.9), "NaN or infinite point coordinates");
  }
  for (vtkIdType bad : { vtkIdType(-1), vtkIdType(642), vtkIdType(1) << 40 })
  {
    auto mesh = ColorMesh();
    const vtkIdType triangle[3] = { 0, 1, bad };
    mesh->GetPolys()->InsertNextCell(3, triangle);
    ExpectEmptyWithError(Decimate(mesh, 0.9), "point ids outside");
  }
  // A triangle that repeats a point: dropped with a warning.
  auto mesh = ColorMesh();
  const vtkIdType repeated[3] = { 0, 1, 1 };
  mesh->GetPolys()->InsertNextCell(3, repeated);
  Run run = Decimate(mesh, 0.9);
  Check(run.Events->Errors == 0 && run.Events->HasWarning("Dropped 1 triangles that repeat"),
        "a triangle repeating a point is dropped with a warning");
  ExpectReached(run, 0.9);
}

/// An input array already named vtkOriginalPointIds: replaced, with a warning.
void ExistingOriginalIds()
{
  auto mesh = ColorMesh();
  vtkNew<vtkIdTypeArray> stale;
  stale->SetName("vtkOriginalPointIds");
  stale->SetNumberOfValues(mesh->GetNumberOfPoints());
  stale->Fill(-5);
  mesh->GetPointData()->AddArray(stale);
  Run run = Decimate(mesh, 0.9);
  Check(run.Events->Errors == 0 && run.Events->HasWarning("already has a point array"),
        "a warning about the replaced array");
  // The invariants check that the output array holds valid, distinct input ids.
}

/**
 * The comparison metrics on hostile input: ColorQuadric with half-edge collapses and with
 * OptimalPlacement (points and colours move), and the paper's metric in CIELab. Closed
 * surfaces keep their Euler characteristic at TargetReduction 1, flat grids stay unflipped,
 * every colour type keeps its type and width, and moved colours stay inside the domain of the
 * array's mapping to [0,1].
 */
void OtherMetrics()
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
      Run run = Decimate(closed.first, 1.0, configure);
      ExpectNoMessages(run);
      const Triangles out = TrianglesOf(run.Output);
      Check(!out.empty() && Euler(out) == closed.second && EveryEdgeHas(out, 2) &&
              IsOrientedSoup(out),
            Say(setting.Name, ": a closed surface stays closed, oriented, Euler ", closed.second));
    }
    for (Pattern pattern : { Pattern::SharpRegions, Pattern::Constant })
    {
      Run run = Decimate(MakeFlatGrid(40, pattern), 0.9, configure);
      ExpectNoMessages(run);
      ExpectReached(run, 0.9);
      int flipped = 0;
      for (const auto& t : TrianglesOf(run.Output))
      {
        flipped += TriangleNormalZ(run.Output, t) <= 0 ? 1 : 0;
      }
      Check(flipped == 0, Say(setting.Name, ": ", flipped, " flat-grid triangles flipped"));
    }
    for (const auto& type : ColorTypes())
    {
      for (int components : { 1, 3, 4 })
      {
        auto mesh = WithColorType(ColorMesh(), type.first, components);
        Run run = Decimate(mesh, 0.9, configure);
        ExpectNoMessages(run);
        ExpectReached(run, 0.9);
        vtkDataArray* in = mesh->GetPointData()->GetScalars();
        vtkDataArray* out = run.Output->GetPointData()->GetArray("Color");
        Check(out && out->GetDataType() == type.first && out->GetNumberOfComponents() == components,
              Say(setting.Name, ", ", type.second, " x ", components,
                  ": the colour array keeps its type and width"));
        // Moved colours stay inside the domain of the array's mapping to [0,1]: [0,1] for
        // floating values already in it, otherwise the range of the colour components
        // (alpha, copied, inside its own range).
        const int used = components >= 3 ? 3 : 1;
        double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
        for (int k = 0; k < used; ++k)
        {
          double r[2];
          in->GetRange(r, k);
          lo = std::min(lo, r[0]);
          hi = std::max(hi, r[1]);
        }
        if ((type.first == VTK_FLOAT || type.first == VTK_DOUBLE) && lo >= 0 && hi <= 1)
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
          Check(outRange[0] >= domain[0] && outRange[1] <= domain[1],
                Say(setting.Name, ", ", type.second, " x ", components, ": component ", k,
                    " range [", outRange[0], ", ", outRange[1], "] inside [", domain[0], ", ",
                    domain[1], "]"));
        }
      }
    }
    auto nan = WithColorType(ColorMesh(), VTK_FLOAT, 3);
    for (vtkIdType i = 0; i < nan->GetNumberOfPoints(); i += 13)
    {
      nan->GetPointData()->GetScalars()->SetComponent(i, 1,
                                                      std::numeric_limits<double>::quiet_NaN());
    }
    Run run = Decimate(nan, 0.9, configure);
    Check(run.Events->Errors == 0 && run.Events->HasWarning("NaN"),
          Say(setting.Name, ": NaN colours give a warning"));
    ExpectReached(run, 0.9);
  }
}

/// Out-of-range and extreme property values are clamped or survive without harm.
void ExtremeProperties()
{
  auto mesh = colordecimation::meshes::Icosphere(3, Pattern::FineDetail);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double weight : { 0.0, 1e-300, 1e300, std::numeric_limits<double>::max() })
  {
    Run run = Decimate(mesh, 0.9,
                       [weight](vtkColorHalfEdgeDecimation* f) { f->SetGeometryWeight(weight); });
    ExpectNoMessages(run);
    ExpectReached(run, 0.9);
  }
  for (double angle : { 0.0, 1e-9, 180.0 })
  {
    Run run = Decimate(mesh, 0.9,
                       [angle](vtkColorHalfEdgeDecimation* f) { f->SetMaximumNormalAngle(angle); });
    ExpectNoMessages(run);
  }
  vtkNew<vtkColorHalfEdgeDecimation> clamp;
  clamp->SetTargetReduction(-1);
  Check(clamp->GetTargetReduction() == 0.0, "TargetReduction is clamped to 0");
  clamp->SetTargetReduction(2);
  Check(clamp->GetTargetReduction() == 1.0, "TargetReduction is clamped to 1");
  clamp->SetErrorMetric(7);
  Check(clamp->GetErrorMetric() == vtkColorHalfEdgeDecimation::ColorQuadric, "ErrorMetric clamped");
  clamp->SetColorSpace(5);
  Check(clamp->GetColorSpace() == vtkColorHalfEdgeDecimation::CIELab, "ColorSpace clamped");
  clamp->SetColorWeight(-1);
  Check(clamp->GetColorWeight() == 0.0, "ColorWeight is clamped to 0");
  clamp->SetGeometryWeight(-3);
  Check(clamp->GetGeometryWeight() == 0.0, "GeometryWeight is clamped to 0");
  clamp->SetGeometryWeight(std::numeric_limits<double>::infinity());
  Check(clamp->GetGeometryWeight() == VTK_DOUBLE_MAX, "GeometryWeight inf is clamped");
  clamp->SetMaximumNormalAngle(-std::numeric_limits<double>::infinity());
  Check(clamp->GetMaximumNormalAngle() == 0.0, "MaximumNormalAngle -inf is clamped to 0");
}

/**
 * NaN property values pass vtkSetClampMacro unchanged: the filter refuses them with an error
 * and an empty output. Also ColorWeight NaN with the ColorQuadric metric. (Infinite values
 * are clamped by the setters: see ExtremeProperties.)
 */
void NaNProperties()
{
  auto mesh = colordecimation::meshes::Icosphere(3, Pattern::FineDetail);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<const char*, std::function<void(vtkColorHalfEdgeDecimation*)>>>
    settings = {
      { "TargetReduction", [nan](vtkColorHalfEdgeDecimation* f) { f->SetTargetReduction(nan); } },
      { "MaximumNormalAngle",
        [nan](vtkColorHalfEdgeDecimation* f) { f->SetMaximumNormalAngle(nan); } },
      { "GeometryWeight", [nan](vtkColorHalfEdgeDecimation* f) { f->SetGeometryWeight(nan); } },
      { "ColorWeight",
        [nan](vtkColorHalfEdgeDecimation* f)
        {
          f->SetErrorMetricToColorQuadric();
          f->SetColorWeight(nan);
        } },
    };
  for (const auto& setting : settings)
  {
    std::cout << setting.first << "\n";
    ExpectEmptyWithError(Decimate(mesh, 0.9, setting.second), "NaN or infinite");
  }
}

} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::pair<std::string, std::function<void()>>> cases = {
    { "NonManifoldEdge", NonManifoldEdge },
    { "NonManifoldVertex", NonManifoldVertex },
    { "DuplicateTriangles", DuplicateTriangles },
    { "DoubleSidedTriangle", DoubleSidedTriangle },
    { "TriangleSoup", TriangleSoup },
    { "DuplicatePoints", DuplicatePoints },
    { "ZeroAreaTriangles", ZeroAreaTriangles },
    { "IsolatedPoints", IsolatedPoints },
    { "MixedOrientation", MixedOrientation },
    { "FlatGrid", FlatGrid },
    { "NoFoldOver", NoFoldOver },
    { "SingleTriangle", SingleTriangle },
    { "LargeScale", LargeScale },
    { "SmallScale", SmallScale },
    { "NaNColors", NaNColors },
    { "BadColorArrays", BadColorArrays },
    { "ShortPointArray", ShortPointArray },
    { "TargetReductionZero", TargetReductionZero },
    { "TargetReductionOne", TargetReductionOne },
    { "EmptyAndNoSurface", EmptyAndNoSurface },
    { "PolygonsAndStrips", PolygonsAndStrips },
    { "InvalidInput", InvalidInput },
    { "ExistingOriginalIds", ExistingOriginalIds },
    { "ExtremeProperties", ExtremeProperties },
    { "NaNProperties", NaNProperties },
    { "OtherMetrics", OtherMetrics },
  };
  for (const auto& type : ColorTypes())
  {
    const int id = type.first;
    cases.emplace_back(std::string("ColorType_") + type.second, [id]() { ColorType(id); });
  }
  if (argc != 2)
  {
    std::cerr << "usage: " << argv[0] << " CASE|all|--list\n";
    return 2;
  }
  const std::string wanted = argv[1];
  bool found = false;
  for (const auto& c : cases)
  {
    if (wanted == "--list")
    {
      std::cout << c.first << "\n";
      found = true;
    }
    else if (wanted == "all" || wanted == c.first)
    {
      std::cout << c.first << "\n";
      c.second();
      found = true;
    }
  }
  if (!found)
  {
    std::cerr << "no case named " << wanted << "\n";
    return 2;
  }
  std::cout << (Failures ? "FAILED" : "passed") << " (" << Failures << " failed checks)\n";
  return Failures ? 1 : 0;
}
