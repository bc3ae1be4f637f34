// Tests of the controls of vtkColorHalfEdgeDecimation for real-world meshes:
// TargetNumberOfTriangles, MaximumError with ActualError (on hand-built meshes whose error is
// computed by hand), the lock array (SetInputArrayToProcess(1, ...)) with its bad inputs,
// PruneComponents, input wound both ways (ConsistentOrientation), and attribute seams
// (PreserveSeams).
#include "ColorDecimationTestUtilities.h"

#include "ColorDecimationMeshes.h"
#include "vtkColorHalfEdgeDecimation.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <set>

using namespace colordecimation;
using namespace colordecimation::testing;
using meshes::Pattern;

namespace
{
constexpr int Schedules[] = { vtkColorHalfEdgeDecimation::Greedy,
                              vtkColorHalfEdgeDecimation::Batched };

/// Select `name` as the lock array (point data).
void SelectLocks(vtkColorHalfEdgeDecimation* f, const char* name)
{
  f->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
}

/**
 * A square pyramid of height h over the square (+-1, 0, 0), (0, +-1, 0): four triangles around
 * the apex (point 4), with `scale` and `shift` applied to every coordinate. With
 * PreserveBoundary on, the only possible collapse is the apex into a base point.
 */
vtkSmartPointer<vtkPolyData> Pyramid(double h, double scale = 1.0, double shift = 0.0)
{
  std::vector<double> xyz = { 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 0, 0, h };
  for (double& c : xyz)
  {
    c = c * scale + shift;
  }
  return meshes::FromTriangles(xyz, { 4, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0 });
}

/**
 * The error of collapsing the pyramid's apex into a base point, by hand: the apex holds its
 * four faces (area A each), the base point two of them, on which it lies. The face planes
 * are (+-x +-y + z/h = 1) / s with s = sqrt(2 + 1/h^2); from (1, 0, 0) the two far ones are at
 * distance 2/s. So Q = A (4 + 4) / s^2 over the area 6A: error sqrt(4/3) / s.
 */
double PyramidError(double h)
{
  return std::sqrt(4.0 / 3.0) / std::sqrt(2.0 + 1.0 / (h * h));
}

/// The points and triangles of a flat m x m grid of unit quads at z = 0, appended.
void AddGrid(int m, std::vector<double>& xyz, std::vector<vtkIdType>& triangles)
{
  for (int j = 0; j <= m; ++j)
  {
    for (int i = 0; i <= m; ++i)
    {
      xyz.insert(xyz.end(), { double(i), double(j), 0.0 });
    }
  }
  for (vtkIdType j = 0; j < m; ++j)
  {
    for (vtkIdType i = 0; i < m; ++i)
    {
      const vtkIdType a = (m + 1) * j + i, b = a + 1, c = a + m + 2, d = a + m + 1;
      triangles.insert(triangles.end(), { a, b, c, a, c, d });
    }
  }
}

/**
 * A flat grid of m x m quads over [0, m]^2 (m = 20: 441 points) and, beside it, ten separate
 * tetrahedra of edge 0.2 k (k = 1 .. 10), which no collapse can reduce: 2 m^2 + 40 triangles.
 */
vtkSmartPointer<vtkPolyData> GridAndTetrahedra(int m = 20)
{
  std::vector<double> xyz;
  std::vector<vtkIdType> triangles;
  AddGrid(m, xyz, triangles);
  for (int k = 1; k <= 10; ++k)
  {
    const auto first = static_cast<vtkIdType>(xyz.size() / 3);
    const double e = 0.2 * k, x = m + 10.0 + 3.0 * k;
    xyz.insert(xyz.end(), { x, 0, 0, x + e, 0, 0, x, e, 0, x, 0, e });
    for (const vtkIdType t : { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 })
    {
      triangles.push_back(first + t);
    }
  }
  return meshes::FromTriangles(xyz, triangles);
}

/// How many triangles use each point.
std::map<vtkIdType, int> TrianglesPerPoint(const std::vector<Tri>& triangles)
{
  std::map<vtkIdType, int> count;
  for (const Tri& t : triangles)
  {
    for (const vtkIdType v : t)
    {
      ++count[v];
    }
  }
  return count;
}

/**
 * A mesh with attribute seams (closed once welded), decimated at 0.9 and 0.97 with both
 * schedules: no open edge once welded, every point's data its input point's, the target
 * reached; with PreserveSeams off the seams open (so that the checks can fail).
 */
void CheckSeams(vtkPolyData* mesh, const std::string& name)
{
  CD_CHECK(WeldedOpenEdges(mesh) == 0);
  CD_CHECK(!BoundaryEdges(GetTriangles(mesh)).empty()); // unwelded, each side is open
  for (const int schedule : Schedules)
  {
    for (const double reduction : { 0.9, 0.97 })
    {
      auto configure = [schedule](bool seams)
      {
        return [schedule, seams](vtkColorHalfEdgeDecimation* f)
        {
          f->SetCollapseSchedule(schedule);
          f->SetPreserveSeams(seams);
        };
      };
      const RunResult run = Decimate(mesh, reduction, configure(true));
      const RunResult off = Decimate(mesh, reduction, configure(false));
      const long long open = WeldedOpenEdges(run.Output), cracks = WeldedOpenEdges(off.Output);
      std::cout << name << " " << (schedule == Schedules[0] ? "greedy" : "batched") << " "
                << reduction << ": reduction " << run.ActualReduction << ", " << open
                << " open edges welded (" << cracks << " without PreserveSeams)\n";
      CD_CHECK(run.Errors == 0 && run.Warnings == 0);
      CD_CHECK_MSG(open == 0, open << " open edges");
      CD_CHECK(CheckPointDataCopied(mesh, run.Output) == 0);
      CD_CHECK(run.ActualReduction >= reduction - 0.002);
      CD_CHECK(cracks > 0);
    }
  }
}
} // namespace

//------------------------------------------------------------------------------
CD_TEST_CASE(TargetNumberOfTriangles)
{
  // A closed mesh loses exactly two triangles a collapse: 1280 -> 600 for a target of 601,
  // whatever TargetReduction says.
  auto sphere = meshes::Icosphere(3, Pattern::SharpRegions);
  CD_CHECK(sphere->GetNumberOfPolys() == 1280);
  for (const int schedule : Schedules)
  {
    const RunResult r = Decimate(sphere, 0.1,
                                 [schedule](vtkColorHalfEdgeDecimation* f)
                                 {
                                   f->SetCollapseSchedule(schedule);
                                   f->SetTargetNumberOfTriangles(601);
                                 });
    CD_CHECK(r.Errors == 0 && r.Warnings == 0);
    CD_CHECK(r.Output->GetNumberOfPolys() == 600);
    CD_CHECK(r.Collapses == 340);
    // A count at or above the input's leaves the mesh as it is.
    const RunResult all = Decimate(sphere, 0.9,
                                   [schedule](vtkColorHalfEdgeDecimation* f)
                                   {
                                     f->SetCollapseSchedule(schedule);
                                     f->SetTargetNumberOfTriangles(1280);
                                   });
    CD_CHECK(all.Collapses == 0 && all.Output->GetNumberOfPolys() == 1280);
  }
  // 0 is "use TargetReduction"; negative counts clamp to it.
  vtkNew<vtkColorHalfEdgeDecimation> f;
  f->SetTargetNumberOfTriangles(-5);
  CD_CHECK(f->GetTargetNumberOfTriangles() == 0);
  f->SetInputData(sphere);
  f->SetTargetReduction(0.5);
  f->Update();
  CD_CHECK(f->GetOutput()->GetNumberOfPolys() == 640);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(MaximumErrorByHand)
{
  // The pyramid (boundary preserved) has one possible collapse, the apex into a base point, whose
  // error PyramidError is known: a bound just below it stops the run before it, one just above lets
  // it through and ActualError reports it, in the input's units (scaled and shifted).
  for (const double scale : { 1.0, 1000.0 })
  {
    const double h = 0.1, error = scale * PyramidError(h);
    auto pyramid = Pyramid(h, scale, scale == 1.0 ? 0.0 : 5e4);
    for (const int schedule : Schedules)
    {
      for (const double factor : { 0.99, 1.01 })
      {
        const RunResult r = Decimate(pyramid, 1.0,
                                     [&](vtkColorHalfEdgeDecimation* f)
                                     {
                                       f->SetCollapseSchedule(schedule);
                                       f->SetPreserveBoundary(true);
                                       f->SetMaximumError(factor * error);
                                     });
        CD_CHECK(r.Errors == 0 && r.Warnings == 0);
        const double actual = r.Filter->GetActualError();
        std::cout << "scale " << scale << ", bound " << factor << " x " << error << ": "
                  << r.Collapses << " collapses, ActualError " << actual << "\n";
        if (factor < 1.0)
        {
          CD_CHECK(r.Collapses == 0 && r.Output->GetNumberOfPolys() == 4);
          CD_CHECK(actual == 0.0);
        }
        else
        {
          CD_CHECK(r.Collapses == 1 && r.Output->GetNumberOfPolys() == 2);
          CD_CHECK_NEAR(actual / error, 1.0, 1e-6);
        }
      }
    }
  }
  // Without a bound the collapse is made and ActualError stays 0 (not tracked).
  const RunResult free = Decimate(
    Pyramid(0.1), 1.0, [](vtkColorHalfEdgeDecimation* f) { f->SetPreserveBoundary(true); });
  CD_CHECK(free.Collapses == 1 && free.Filter->GetActualError() == 0.0);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(MaximumErrorFlatAndCurved)
{
  // On a flat sheet every collapse has error 0: the smallest bound changes nothing (the same
  // triangles as without one). On a sphere every collapse has an error: a tiny bound stops the
  // run before the first, and a bound of 1 % of the radius holds ActualError under it.
  auto sheet = meshes::FlatGrid(30, 30, Pattern::SmoothGradient);
  auto sphere = meshes::Icosphere(4, Pattern::SmoothGradient);
  for (const int schedule : Schedules)
  {
    auto run = [schedule](vtkPolyData* mesh, double bound)
    {
      return Decimate(mesh, 0.9,
                      [schedule, bound](vtkColorHalfEdgeDecimation* f)
                      {
                        f->SetCollapseSchedule(schedule);
                        f->SetMaximumError(bound);
                      });
    };
    const RunResult unbounded = run(sheet, 0.0), bounded = run(sheet, 1e-12);
    CD_CHECK(bounded.Collapses == unbounded.Collapses);
    CD_CHECK(GetOriginalTriangles(bounded.Output) == GetOriginalTriangles(unbounded.Output));
    CD_CHECK(bounded.Filter->GetActualError() == 0.0);

    const RunResult none = run(sphere, 1e-9);
    CD_CHECK(none.Collapses == 0 && none.ActualReduction == 0.0);
    const RunResult some = run(sphere, 0.01);
    std::cout << some.Filter->GetCollapseScheduleAsString() << ": bound 0.01, " << some.Collapses
              << " collapses, reduction " << some.ActualReduction << ", ActualError "
              << some.Filter->GetActualError() << "\n";
    CD_CHECK(some.Collapses > 100 && some.ActualReduction < 0.9);
    CD_CHECK(some.Filter->GetActualError() > 0.0 && some.Filter->GetActualError() <= 0.01);
  }
}

//------------------------------------------------------------------------------
CD_TEST_CASE(LockArray)
{
  // Every locked point survives, whatever the array's type and however many components it has
  // (any non-zero component locks); both schedules. Without the locks, most of them go.
  auto grid = meshes::Grid(40, 30, Pattern::SharpRegions);
  const vtkIdType n = grid->GetNumberOfPoints();
  std::set<vtkIdType> locked;
  vtkNew<vtkUnsignedCharArray> bytes;
  vtkNew<vtkFloatArray> floats;
  vtkNew<vtkIntArray> pairs;
  bytes->SetName("bytes");
  floats->SetName("floats");
  pairs->SetName("pairs");
  pairs->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool lock = i % 7 == 3 || (i >= 400 && i < 440);
    if (lock)
    {
      locked.insert(i);
    }
    bytes->InsertNextValue(lock ? 255 : 0);
    floats->InsertNextValue(lock ? 0.5f : 0.0f);
    pairs->InsertNextTuple2(0, lock ? -1 : 0);
  }
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(bytes), static_cast<vtkDataArray*>(floats),
                           static_cast<vtkDataArray*>(pairs) })
  {
    grid->GetPointData()->AddArray(a);
  }
  auto countLost = [&locked](vtkPolyData* output)
  {
    const std::set<vtkIdType> ids = OriginalIds(output);
    long long lost = 0;
    for (const vtkIdType v : locked)
    {
      lost += ids.count(v) ? 0 : 1;
    }
    return lost;
  };
  CD_CHECK(2 * countLost(Decimate(grid, 0.9).Output) > static_cast<long long>(locked.size()));
  const std::map<vtkIdType, int> before = TrianglesPerPoint(GetTriangles(grid));
  for (const int schedule : Schedules)
  {
    for (const char* name : { "bytes", "floats", "pairs" })
    {
      const RunResult r = Decimate(grid, 0.9,
                                   [&](vtkColorHalfEdgeDecimation* f)
                                   {
                                     f->SetCollapseSchedule(schedule);
                                     SelectLocks(f, name);
                                   });
      CD_CHECK(r.Errors == 0 && r.Warnings == 0);
      CD_CHECK(std::string(r.Filter->GetLockArrayName()) == name);
      const long long lost = countLost(r.Output);
      CD_CHECK_MSG(lost == 0,
                   name << ": " << lost << " of " << locked.size() << " locked points lost");
      // No triangle of a locked point is removed (corners of its neighbours may be renamed).
      const std::map<vtkIdType, int> after = TrianglesPerPoint(GetOriginalTriangles(r.Output));
      long long changed = 0;
      for (const vtkIdType v : locked)
      {
        const auto it = after.find(v);
        changed += (it == after.end() ? 0 : it->second) != before.at(v) ? 1 : 0;
      }
      CD_CHECK_MSG(changed == 0, name << ": " << changed << " locked points lost triangles");
      CD_CHECK(r.Collapses > 100);
    }
  }
}

//------------------------------------------------------------------------------
CD_TEST_CASE(LockArrayBadInput)
{
  auto grid = meshes::Grid(20, 20, Pattern::SmoothGradient);
  const RunResult plain = Decimate(grid, 0.9);
  // Not there: a warning naming it, nothing locked (the same output as without).
  const RunResult missing =
    Decimate(grid, 0.9, [](vtkColorHalfEdgeDecimation* f) { SelectLocks(f, "nothere"); });
  CD_CHECK(missing.Errors == 0 && missing.Warnings == 1 && missing.HasWarning("'nothere'"));
  CD_CHECK(GetOriginalTriangles(missing.Output) == GetOriginalTriangles(plain.Output));
  // A string array of that name, or a selection by attribute type rather than by name: a
  // warning saying so, nothing locked.
  auto withText = Copy(grid);
  vtkNew<vtkStringArray> text;
  text->SetName("labels");
  text->SetNumberOfValues(withText->GetNumberOfPoints());
  withText->GetPointData()->AddArray(text);
  const RunResult textual =
    Decimate(withText, 0.9, [](vtkColorHalfEdgeDecimation* f) { SelectLocks(f, "labels"); });
  CD_CHECK(textual.Errors == 0 && textual.Warnings == 1 && textual.HasWarning("not numeric"));
  CD_CHECK(GetOriginalTriangles(textual.Output) == GetOriginalTriangles(plain.Output));
  const RunResult byType =
    Decimate(grid, 0.9,
             [](vtkColorHalfEdgeDecimation* f)
             {
               f->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                         vtkDataSetAttributes::SCALARS);
             });
  CD_CHECK(byType.Errors == 0 && byType.Warnings == 1 && byType.HasWarning("attribute type"));
  CD_CHECK(GetOriginalTriangles(byType.Output) == GetOriginalTriangles(plain.Output));
  // No selection ("" or ParaView's "None"): quiet, nothing locked.
  for (const char* none : { "", "None" })
  {
    const RunResult r =
      Decimate(grid, 0.9, [none](vtkColorHalfEdgeDecimation* f) { SelectLocks(f, none); });
    CD_CHECK(r.Errors == 0 && r.Warnings == 0 && r.Filter->GetLockArrayName() == nullptr);
    CD_CHECK(GetOriginalTriangles(r.Output) == GetOriginalTriangles(plain.Output));
  }
  // A cell-data array: a warning, and nothing locked (as for a name the input does not have);
  // a point array of the wrong length: an error and an empty output.
  auto withCellLock = Copy(grid);
  vtkNew<vtkDoubleArray> cellLock;
  cellLock->SetName("celllock");
  cellLock->SetNumberOfTuples(withCellLock->GetNumberOfCells());
  cellLock->Fill(1.0);
  withCellLock->GetCellData()->AddArray(cellLock);
  const RunResult cells = Decimate(
    withCellLock, 0.9,
    [](vtkColorHalfEdgeDecimation* f)
    { f->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "celllock"); });
  CD_CHECK(cells.Errors == 0 && cells.Warnings == 1 &&
           cells.HasWarning("The lock array 'celllock' is cell data, not point data"));
  CD_CHECK(GetOriginalTriangles(cells.Output) == GetOriginalTriangles(plain.Output));
  // Selected from a place a vtkPolyData does not have: a warning saying so (no error from VTK's
  // look-up), nothing locked.
  const RunResult rows =
    Decimate(grid, 0.9,
             [](vtkColorHalfEdgeDecimation* f) {
               f->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_ROWS, "rowlock");
             });
  CD_CHECK(rows.Errors == 0 && rows.Warnings == 1 &&
           rows.HasWarning("The lock array 'rowlock' is selected from a table's row data"));
  CD_CHECK(GetOriginalTriangles(rows.Output) == GetOriginalTriangles(plain.Output));
  auto withShortLock = Copy(grid);
  vtkNew<vtkUnsignedCharArray> shortLock;
  shortLock->SetName("short");
  shortLock->SetNumberOfTuples(7);
  shortLock->Fill(1);
  withShortLock->GetPointData()->AddArray(shortLock);
  const RunResult shortRun =
    Decimate(withShortLock, 0.9, [](vtkColorHalfEdgeDecimation* f) { SelectLocks(f, "short"); });
  CD_CHECK(shortRun.Errors == 1 && shortRun.HasError("7 tuples"));
  CD_CHECK(shortRun.Output->GetNumberOfPoints() == 0);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(PruneComponents)
{
  // Collapses take the grid to G triangles and leave the ten tetrahedra (40 triangles): at
  // 0.99 (target 8) the run stops short. With PruneComponents the smallest tetrahedra go,
  // one after the other, until G + 4 (10 - k) <= 8; the largest ones stay. A locked point
  // keeps its tetrahedron (the next smallest goes instead).
  auto mesh = GridAndTetrahedra();
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkUnsignedCharArray> lock;
  lock->SetName("lock");
  lock->SetNumberOfValues(n);
  lock->Fill(0);
  lock->SetValue(441, 1); // the first point of the smallest tetrahedron (after the grid's 441)
  mesh->GetPointData()->AddArray(lock);
  const vtkIdType target = 8; // floor(0.01 * 840)
  for (const int schedule : Schedules)
  {
    auto run = [&](bool prune, bool locked)
    {
      return Decimate(mesh, 0.99,
                      [&](vtkColorHalfEdgeDecimation* f)
                      {
                        f->SetCollapseSchedule(schedule);
                        f->SetPieceWeight(0); // pruning after the run alone
                        f->SetPruneComponents(prune);
                        SelectLocks(f, locked ? "lock" : "");
                      });
    };
    const RunResult plain = run(false, false);
    const vtkIdType grid = plain.Output->GetNumberOfPolys() - 40;
    CD_CHECK(grid >= 1 && grid <= target && plain.Filter->GetNumberOfPrunedComponents() == 0);
    vtkIdType removed = 0;
    while (grid + 4 * (10 - removed) > target)
    {
      ++removed;
    }
    const RunResult pruned = run(true, false);
    std::cout << pruned.Filter->GetCollapseScheduleAsString() << ": grid " << grid
              << " triangles; pruned " << pruned.Filter->GetNumberOfPrunedComponents()
              << " pieces, " << pruned.Output->GetNumberOfPolys() << " triangles left\n";
    CD_CHECK(pruned.Errors == 0 && pruned.Warnings == 0);
    CD_CHECK(pruned.Filter->GetNumberOfPrunedComponents() == removed);
    CD_CHECK(pruned.Output->GetNumberOfPolys() == grid + 4 * (10 - removed));
    // The tetrahedra left are the largest: their points are the last of the input.
    const std::set<vtkIdType> ids = OriginalIds(pruned.Output);
    CD_CHECK(ids.count(441 + 4 * removed) == 1 && ids.count(441 + 4 * removed - 1) == 0);
    const RunResult locked = run(true, true);
    const std::set<vtkIdType> lockedIds = OriginalIds(locked.Output);
    CD_CHECK(locked.Filter->GetNumberOfPrunedComponents() == removed);
    CD_CHECK(lockedIds.count(441) == 1 && lockedIds.count(441 + 4 * removed) == 0);
  }
  // Nothing to prune when collapses reach the target; and never the last piece.
  CD_CHECK(Decimate(mesh, 0.5, [](vtkColorHalfEdgeDecimation* f) { f->PruneComponentsOn(); })
             .Filter->GetNumberOfPrunedComponents() == 0);
  auto single = meshes::Icosphere(2, Pattern::SharpRegions);
  const RunResult all =
    Decimate(single, 1.0, [](vtkColorHalfEdgeDecimation* f) { f->PruneComponentsOn(); });
  CD_CHECK(all.Filter->GetNumberOfPrunedComponents() == 0 && all.Output->GetNumberOfPolys() > 0);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(PieceWeight)
{
  // The grid and ten tetrahedra of edge 0.2 k (k = 1..10), away from it, to 99 %: at the
  // defaults the tetrahedra go during the run as the collapses' cost reaches theirs, smallest
  // first, never the grid (the largest piece); PieceWeight 0 removes none (the grid and the
  // ten tetrahedra's 40 triangles are left); a larger weight removes no more than a smaller
  // one; a locked point keeps its tetrahedron, not the others.
  auto mesh = GridAndTetrahedra();
  vtkNew<vtkUnsignedCharArray> lock;
  lock->SetName("lock");
  lock->SetNumberOfValues(mesh->GetNumberOfPoints());
  lock->Fill(0);
  lock->SetValue(441 + 4, 1); // the second smallest tetrahedron
  mesh->GetPointData()->AddArray(lock);
  for (const int schedule : Schedules)
  {
    auto run = [&](double weight, bool locked)
    {
      return Decimate(mesh, 0.99,
                      [&](vtkColorHalfEdgeDecimation* f)
                      {
                        f->SetCollapseSchedule(schedule);
                        f->SetPieceWeight(weight);
                        SelectLocks(f, locked ? "lock" : "");
                      });
    };
    const RunResult defaults = run(10, false);
    const vtkIdType removed = defaults.Filter->GetNumberOfPrunedComponents();
    const std::set<vtkIdType> ids = OriginalIds(defaults.Output);
    std::cout << defaults.Filter->GetCollapseScheduleAsString() << ": " << removed
              << " tetrahedra removed, " << defaults.Output->GetNumberOfPolys() << " triangles\n";
    CD_CHECK(defaults.Errors == 0 && defaults.Warnings == 0);
    CD_CHECK(removed > 0 && removed < 10);
    for (vtkIdType k = 0; k < 10; ++k)
    {
      CD_CHECK_MSG(ids.count(441 + 4 * k) == (k < removed ? 0u : 1u), "tetrahedron " << k);
    }
    CD_CHECK(defaults.Output->GetNumberOfPolys() - 4 * (10 - removed) >= 1); // the grid
    const RunResult none = run(0, false);
    CD_CHECK(none.Filter->GetNumberOfPrunedComponents() == 0);
    CD_CHECK(OriginalIds(none.Output).count(441) == 1);
    const vtkIdType light = run(1, false).Filter->GetNumberOfPrunedComponents();
    const vtkIdType heavy = run(1e6, false).Filter->GetNumberOfPrunedComponents();
    CD_CHECK_MSG(light >= removed && removed >= heavy, light << " " << removed << " " << heavy);
    const RunResult locked = run(10, true);
    const std::set<vtkIdType> lockedIds = OriginalIds(locked.Output);
    CD_CHECK(lockedIds.count(445) == 1 && lockedIds.count(441) == 0);
    CD_CHECK(locked.Filter->GetNumberOfPrunedComponents() >= removed - 1);
  }
}

CD_TEST_CASE(PieceWeightKeeps)
{
  // Pieces that hold something together or that the user keeps are never removed whole: the
  // six faces of a colour cube (its own points a face, joined by seams: twinned points along
  // the edges for n > 1, only the locked corners for n = 1), even at a weight that makes
  // removing them all but free; and, with PreserveBoundary, open pieces (a grid and ten single
  // triangles away from it, which the defaults remove).
  for (const int n : { 1, 8 })
  {
    // A weight so light that any piece not kept would go at once.
    const RunResult cube = Decimate(meshes::ColorCube(n), 0.99,
                                    [](vtkColorHalfEdgeDecimation* f) { f->SetPieceWeight(1e-9); });
    CD_CHECK_MSG(cube.Filter->GetNumberOfPrunedComponents() == 0, "ColorCube(" << n << ")");
  }
  std::vector<double> xyz;
  std::vector<vtkIdType> triangles;
  const int m = 20;
  AddGrid(m, xyz, triangles);
  for (int k = 1; k <= 10; ++k)
  {
    const auto first = static_cast<vtkIdType>(xyz.size() / 3);
    const double e = 0.2 * k, x = m + 10.0 + 3.0 * k;
    xyz.insert(xyz.end(), { x, 0, 0, x + e, 0, 0, x, e, 0 });
    triangles.insert(triangles.end(), { first, first + 1, first + 2 });
  }
  auto mesh = meshes::FromTriangles(xyz, triangles);
  const RunResult open = Decimate(mesh, 0.99);
  const RunResult kept =
    Decimate(mesh, 0.99, [](vtkColorHalfEdgeDecimation* f) { f->PreserveBoundaryOn(); });
  std::cout << "open triangles: " << open.Filter->GetNumberOfPrunedComponents()
            << " removed; with PreserveBoundary " << kept.Filter->GetNumberOfPrunedComponents()
            << "\n";
  CD_CHECK(open.Filter->GetNumberOfPrunedComponents() > 0);
  CD_CHECK(kept.Filter->GetNumberOfPrunedComponents() == 0);
}

CD_TEST_CASE(PieceWeightWithOtherControls)
{
  // The grid and ten tetrahedra again. PruneComponents after PieceWeight (a heavy one, which
  // removes fewer): the count is the sum of both, every piece removed a tetrahedron. MaximumError:
  // a bound below the smallest tetrahedron's error keeps every piece and the run goes on as
  // without PieceWeight, ActualError within it; an unreachable bound removes what the defaults
  // remove, and ActualError counts the pieces' errors. A mesh large enough to be renumbered: the
  // same rule, smallest first.
  auto mesh = GridAndTetrahedra();
  const vtkIdType target = 2;
  const auto toTarget = [target](bool prune)
  {
    return [target, prune](vtkColorHalfEdgeDecimation* f)
    {
      f->SetTargetNumberOfTriangles(target);
      f->SetPieceWeight(1e5); // only the smallest go during the run
      f->SetPruneComponents(prune);
    };
  };
  const vtkIdType removed =
    Decimate(mesh, 0.99, toTarget(false)).Filter->GetNumberOfPrunedComponents();
  const RunResult both = Decimate(mesh, 0.99, toTarget(true));
  const vtkIdType all = both.Filter->GetNumberOfPrunedComponents();
  const std::set<vtkIdType> left = OriginalIds(both.Output);
  vtkIdType missing = 0;
  for (vtkIdType k = 0; k < 10; ++k)
  {
    missing += left.count(441 + 4 * k) == 0 ? 1 : 0;
  }
  std::cout << "PieceWeight " << removed << ", with PruneComponents " << all << ", "
            << both.Output->GetNumberOfPolys() << " triangles (target " << target << ")\n";
  CD_CHECK(all > removed && all == missing && both.Output->GetNumberOfPolys() <= target);
  const RunResult plain = Decimate(mesh, 0.99);
  const vtkIdType removedAt99 = plain.Filter->GetNumberOfPrunedComponents();
  CD_CHECK(removed > 0);
  const auto withBound = [](double weight)
  {
    return [weight](vtkColorHalfEdgeDecimation* f)
    {
      f->SetMaximumError(1e-3);
      f->SetPieceWeight(weight);
    };
  };
  const RunResult bounded = Decimate(mesh, 0.99, withBound(10));
  const RunResult keepAll = Decimate(mesh, 0.99, withBound(0));
  CD_CHECK(bounded.Filter->GetNumberOfPrunedComponents() == 0);
  CD_CHECK(bounded.Filter->GetActualError() <= 1e-3);
  CD_CHECK(bounded.Output->GetNumberOfPolys() == keepAll.Output->GetNumberOfPolys() &&
           OriginalIds(bounded.Output) == OriginalIds(keepAll.Output));
  const RunResult unbounded =
    Decimate(mesh, 0.99, [](vtkColorHalfEdgeDecimation* f) { f->SetMaximumError(1e9); });
  CD_CHECK(unbounded.Filter->GetNumberOfPrunedComponents() == removedAt99);
  CD_CHECK_MSG(unbounded.Filter->GetActualError() > 0.05, unbounded.Filter->GetActualError());
  auto large = GridAndTetrahedra(260);
  const RunResult big = Decimate(large, 0.99);
  const vtkIdType gone = big.Filter->GetNumberOfPrunedComponents();
  const std::set<vtkIdType> ids = OriginalIds(big.Output);
  const vtkIdType first = large->GetNumberOfPoints() - 40;
  std::cout << "renumbered: " << gone << " tetrahedra removed\n";
  CD_CHECK(gone > 0 && gone <= 10);
  for (vtkIdType k = 0; k < 10; ++k)
  {
    CD_CHECK_MSG(ids.count(first + 4 * k) == (k < gone ? 0u : 1u), "tetrahedron " << k);
  }
}

//------------------------------------------------------------------------------
CD_TEST_CASE(FlippedSphere)
{
  // A sphere with 30 % of its triangles wound the other way is decimated as the sphere it is:
  // cell for cell the output of the consistent sphere, each triangle wound as its input
  // triangle (or, with ConsistentOrientation, as the consistent sphere's).
  auto sphere = meshes::Icosphere(4, Pattern::SharpRegions);
  Decorate(sphere);
  auto flipped = Copy(sphere);
  std::vector<Tri> triangles = GetTriangles(sphere);
  std::mt19937 random(7);
  std::vector<char> reversed(triangles.size(), 0);
  vtkNew<vtkCellArray> polys;
  for (size_t c = 0; c < triangles.size(); ++c)
  {
    reversed[c] = random() % 10 < 3 ? 1 : 0;
    const Tri& t = triangles[c];
    const vtkIdType ids[3] = { t[0], reversed[c] ? t[2] : t[1], reversed[c] ? t[1] : t[2] };
    polys->InsertNextCell(3, ids);
  }
  flipped->SetPolys(polys);
  for (const auto& [schedule, reduction] : { std::pair<int, double>{ Schedules[0], 0.9 },
                                             { Schedules[0], 0.97 },
                                             { Schedules[1], 0.9 },
                                             { Schedules[1], 0.97 } })
  {
    auto configure = [schedule = schedule](bool consistent)
    {
      return [schedule, consistent](vtkColorHalfEdgeDecimation* f)
      {
        f->SetCollapseSchedule(schedule);
        f->SetConsistentOrientation(consistent);
      };
    };
    const RunResult plain = Decimate(sphere, reduction, configure(false));
    const RunResult mixed = Decimate(flipped, reduction, configure(false));
    const RunResult consistent = Decimate(flipped, reduction, configure(true));
    CD_CHECK(mixed.Errors == 0 && mixed.Warnings == 0);
    CD_CHECK(mixed.ActualReduction == plain.ActualReduction &&
             plain.ActualReduction >= reduction - 1e-3);
    const std::vector<Tri> expected = GetOriginalTriangles(plain.Output);
    const std::vector<Tri> kept = GetOriginalTriangles(mixed.Output);
    CD_CHECK(GetOriginalTriangles(consistent.Output) == expected);
    // The input cell of each output triangle (Decorate's cell ids) tells its winding.
    vtkDataArray* cells = mixed.Output->GetCellData()->GetArray("SourceId");
    long long wrong = kept.size() == expected.size() && cells ? 0 : 1;
    for (size_t c = 0; wrong == 0 && c < kept.size(); ++c)
    {
      const Tri& t = expected[c];
      const bool back = reversed[static_cast<size_t>(cells->GetTuple1(vtkIdType(c)))] != 0;
      wrong += kept[c] == (back ? Tri{ t[0], t[2], t[1] } : t) ? 0 : 1;
    }
    CD_CHECK_MSG(wrong == 0, "output triangles keep their input winding");
  }
}

//------------------------------------------------------------------------------
CD_TEST_CASE(LargeMeshControls)
{
  // From 65,536 points on, the mesh is decimated under a spatial order and mapped back: the
  // reversed triangles' flags and the pruned pieces must come back to the input's ids. A large
  // flipped sphere gives the consistent one's output, cell for cell; a 260 x 260 grid with the
  // ten tetrahedra prunes the smallest ones.
  auto sphere = meshes::Icosphere(7, Pattern::SharpRegions);
  CD_CHECK(sphere->GetNumberOfPoints() >= 65536);
  auto flipped = Copy(sphere);
  vtkNew<vtkCellArray> polys;
  long long reversed = 0;
  for (const Tri& t : GetTriangles(sphere))
  {
    const bool back = (t[0] + t[1] + t[2]) % 3 == 0;
    const vtkIdType ids[3] = { t[0], back ? t[2] : t[1], back ? t[1] : t[2] };
    polys->InsertNextCell(3, ids);
    reversed += back ? 1 : 0;
  }
  flipped->SetPolys(polys);
  const RunResult plain = Decimate(sphere, 0.9);
  const RunResult consistent =
    Decimate(flipped, 0.9, [](vtkColorHalfEdgeDecimation* f) { f->ConsistentOrientationOn(); });
  std::cout << reversed << " of " << sphere->GetNumberOfPolys() << " triangles reversed\n";
  CD_CHECK(consistent.Errors == 0 && consistent.Warnings == 0);
  CD_CHECK(GetOriginalTriangles(consistent.Output) == GetOriginalTriangles(plain.Output));

  auto mesh = GridAndTetrahedra(260);
  CD_CHECK(mesh->GetNumberOfPoints() >= 65536);
  const vtkIdType target = 10;
  auto run = [target](bool prune)
  {
    return [target, prune](vtkColorHalfEdgeDecimation* f)
    {
      f->SetTargetNumberOfTriangles(target);
      f->SetPieceWeight(0); // pruning after the run alone
      f->SetPruneComponents(prune);
    };
  };
  const RunResult unpruned = Decimate(mesh, 0.9, run(false));
  const vtkIdType grid = unpruned.Output->GetNumberOfPolys() - 40;
  vtkIdType removed = 0;
  while (grid + 4 * (10 - removed) > target && removed < 10)
  {
    ++removed;
  }
  const RunResult pruned = Decimate(mesh, 0.9, run(true));
  std::cout << "grid " << grid << " triangles, target " << target << ": pruned "
            << pruned.Filter->GetNumberOfPrunedComponents() << "\n";
  CD_CHECK(grid >= 1 && removed > 0);
  CD_CHECK(pruned.Filter->GetNumberOfPrunedComponents() == removed);
  CD_CHECK(pruned.Output->GetNumberOfPolys() == grid + 4 * (10 - removed));
  // The largest tetrahedra are left: the points of the last of them are in the output.
  const std::set<vtkIdType> ids = OriginalIds(pruned.Output);
  CD_CHECK(ids.count(mesh->GetNumberOfPoints() - 1) == 1);
}

CD_TEST_CASE(SeamSphere)
{
  // A UV sphere whose points along one meridian are duplicated with other texture coordinates
  // and colours (48 x 48: 4,512 triangles, 47 twinned pairs, the poles shared).
  auto sphere = meshes::SeamSphere(48);
  CheckSeams(sphere, "seam sphere");
  // Under MaximumError a pair is made only when both of its collapses keep within it.
  for (const int schedule : Schedules)
  {
    const RunResult bounded = Decimate(sphere, 0.97,
                                       [schedule](vtkColorHalfEdgeDecimation* f)
                                       {
                                         f->SetCollapseSchedule(schedule);
                                         f->SetMaximumError(0.01);
                                       });
    std::cout << "seam sphere, MaximumError 0.01: reduction " << bounded.ActualReduction
              << ", ActualError " << bounded.Filter->GetActualError() << "\n";
    CD_CHECK(WeldedOpenEdges(bounded.Output) == 0);
    CD_CHECK(bounded.Filter->GetActualError() <= 0.01);
    CD_CHECK(bounded.ActualReduction > 0.5 && bounded.ActualReduction < 0.97);
  }
}

CD_TEST_CASE(SeamCube)
{
  // A cube whose six faces each have their own points and colour (20 x 20 quads a face, 4,800
  // triangles; 12 x 19 twinned pairs, the 8 corners of three faces kept).
  auto cube = meshes::ColorCube(20);
  CheckSeams(cube, "colour cube");
  // The corners are kept: each of the 24 corner points is in the output.
  const RunResult run = Decimate(cube, 0.97);
  long long corners = 0;
  for (vtkIdType i = 0; i < run.Output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    run.Output->GetPoint(i, p);
    corners += std::abs(p[0]) == 1 && std::abs(p[1]) == 1 && std::abs(p[2]) == 1 ? 1 : 0;
  }
  CD_CHECK_MSG(corners == 24, corners << " corner points");
}

CD_TEST_CASE(SeamByHand)
{
  // An octahedron cut along its equator: the top pyramid (apex 0, equator 1-4) and the bottom
  // one (apex 5, equator 6-9 at the same positions), red and blue. Each side can only shrink to
  // one triangle (a triangle with two boundary edges cannot collapse): with the seam, both
  // apexes go, then one pair of equator points (a collapse on each side along the seam): 2
  // triangles on the same three positions, closed once welded, 6 points, 3 of each side.
  std::vector<double> xyz = { 0, 0, 1, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 0, 0, -1 };
  xyz.insert(xyz.end(), xyz.begin() + 3, xyz.begin() + 15);
  auto mesh = meshes::FromTriangles(xyz, { 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1, //
                                           5, 7, 6, 5, 8, 7, 5, 9, 8, 5, 6, 9 });
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  colors->SetName("RGB");
  for (vtkIdType i = 0; i < 10; ++i)
  {
    const bool top = i < 5;
    colors->InsertNextTuple3(top ? 255 : 0, 0, top ? 0 : 255);
  }
  mesh->GetPointData()->SetScalars(colors);
  CD_CHECK(WeldedOpenEdges(mesh) == 0 && BoundaryEdges(GetTriangles(mesh)).size() == 8);
  for (const int schedule : Schedules)
  {
    const RunResult run = Decimate(
      mesh, 1.0, [schedule](vtkColorHalfEdgeDecimation* f) { f->SetCollapseSchedule(schedule); });
    const std::set<vtkIdType> ids = OriginalIds(run.Output);
    std::set<std::array<double, 3>> top, bottom;
    for (vtkIdType i = 0; i < run.Output->GetNumberOfPoints(); ++i)
    {
      double p[3];
      run.Output->GetPoint(i, p);
      const bool first = run.Output->GetPointData()->GetScalars()->GetComponent(i, 0) == 255;
      (first ? top : bottom).insert({ p[0], p[1], p[2] });
    }
    CD_CHECK(run.Output->GetNumberOfPolys() == 2 && run.ActualReduction == 0.75);
    CD_CHECK(ids.size() == 6 && ids.count(0) == 0 && ids.count(5) == 0);
    CD_CHECK(top.size() == 3 && top == bottom);
    CD_CHECK(WeldedOpenEdges(run.Output) == 0);
    CD_CHECK(CheckPointDataCopied(mesh, run.Output) == 0);
  }
}

CD_TEST_CASE(LargeSeams)
{
  // From 65,536 points on, the seams are found under the spatial order (a 260 x 260 seam
  // sphere: 67,341 points).
  auto sphere = meshes::SeamSphere(260);
  CD_CHECK(sphere->GetNumberOfPoints() >= 65536);
  for (const int schedule : Schedules)
  {
    const RunResult run =
      Decimate(sphere, 0.97,
               [schedule](vtkColorHalfEdgeDecimation* f) { f->SetCollapseSchedule(schedule); });
    CD_CHECK(WeldedOpenEdges(run.Output) == 0);
    CD_CHECK(CheckPointDataCopied(sphere, run.Output) == 0);
    CD_CHECK(run.ActualReduction >= 0.97 - 0.002);
  }
}

int main(int argc, char* argv[])
{
  return RunTestCases(argc, argv);
}
