// Tests of the collapse record (vtkColorHalfEdgeDecimation::GenerateCollapseRecord) and of the
// levels of detail extracted from it (vtkColorHalfEdgeLevelOfDetail): a record computed by
// hand, Greedy levels equal to direct runs, Batched levels valid and nested, the vertex
// hierarchy, the round trip through a .vtt file, and every bad record.
#include "ColorDecimationTestUtilities.h"

#include "ColorDecimationMeshes.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkColorHalfEdgeLevelOfDetail.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLTableReader.h"
#include "vtkXMLTableWriter.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace colordecimation;
using namespace colordecimation::testing;
using meshes::Pattern;

namespace
{
/// A decimation with the record on (`configure` may set anything else); its record is a copy.
struct Recorded
{
  vtkSmartPointer<vtkPolyData> Output;
  vtkSmartPointer<vtkTable> Record;
};

Recorded RecordRun(vtkPolyData* input, double reduction, int schedule,
                   const Configure& configure = nullptr)
{
  const RunResult result = Decimate(input, reduction,
                                    [schedule, &configure](vtkColorHalfEdgeDecimation* f)
                                    {
                                      f->SetCollapseSchedule(schedule);
                                      f->GenerateCollapseRecordOn();
                                      if (configure)
                                      {
                                        configure(f);
                                      }
                                    });
  Recorded run;
  run.Output = result.Output;
  run.Record = vtkSmartPointer<vtkTable>::New();
  run.Record->DeepCopy(result.Filter->GetCollapseRecord());
  return run;
}

/// The level of `record` that `configure` asks for; its messages in `messages` if given.
vtkSmartPointer<vtkPolyData> Extract(
  vtkPolyData* input, vtkTable* record,
  const std::function<void(vtkColorHalfEdgeLevelOfDetail*)>& configure,
  Messages* messages = nullptr)
{
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  EventRecorder recorder;
  recorder.Watch(lod);
  lod->SetInputData(input);
  lod->SetRecordData(record);
  configure(lod);
  lod->Update();
  if (messages)
  {
    *messages = recorder;
  }
  else
  {
    CD_CHECK_MSG(recorder.Errors == 0 && recorder.Warnings == 0,
                 "no message: " << recorder.ErrorText() << recorder.WarningText());
  }
  auto level = vtkSmartPointer<vtkPolyData>::New();
  level->DeepCopy(lod->GetOutput());
  return level;
}

/// Every array of `a` and `b` (points, point data, cells, cell data) the same, byte for byte.
bool SameArrays(vtkDataSetAttributes* a, vtkDataSetAttributes* b, std::string& why)
{
  if (a->GetNumberOfArrays() != b->GetNumberOfArrays())
  {
    why = "different numbers of arrays";
    return false;
  }
  for (int i = 0; i < a->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* x = a->GetAbstractArray(i);
    vtkAbstractArray* y = x && x->GetName() ? b->GetAbstractArray(x->GetName()) : nullptr;
    if (!x || !y || x->GetDataType() != y->GetDataType() ||
        x->GetNumberOfTuples() != y->GetNumberOfTuples())
    {
      why = std::string("array ") + (x && x->GetName() ? x->GetName() : "?") + " differs";
      return false;
    }
    for (vtkIdType t = 0; t < x->GetNumberOfTuples(); ++t)
    {
      if (!SameTuple(x, t, y, t))
      {
        why = std::string("array ") + x->GetName() + " differs at tuple " + std::to_string(t);
        return false;
      }
    }
  }
  return true;
}

/// The same mesh: points, triangles in the same order, point and cell data, bit for bit.
bool SameMesh(vtkPolyData* a, vtkPolyData* b, std::string& why)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() || GetTriangles(a) != GetTriangles(b))
  {
    why = "points " + std::to_string(a->GetNumberOfPoints()) + " / " +
      std::to_string(b->GetNumberOfPoints()) + ", triangles " +
      std::to_string(a->GetNumberOfCells()) + " / " + std::to_string(b->GetNumberOfCells()) +
      (a->GetNumberOfPoints() == b->GetNumberOfPoints() ? " (other triangles)" : "");
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    if (!SameTupleBytes(a->GetPoints()->GetData(), i, b->GetPoints()->GetData(), i))
    {
      why = "point " + std::to_string(i) + " differs";
      return false;
    }
  }
  return SameArrays(a->GetPointData(), b->GetPointData(), why) &&
    SameArrays(a->GetCellData(), b->GetCellData(), why);
}

vtkSmartPointer<vtkPolyData> DecoratedSphere(int level)
{
  auto mesh = meshes::Icosphere(level, Pattern::SharpRegions);
  Decorate(mesh);
  return mesh;
}

/// The level filter on `input` and `record`: an error naming `part`, and an empty output.
void ExpectRecordError(vtkPolyData* input, vtkTable* record, const std::string& part)
{
  Messages messages;
  auto level = Extract(
    input, record, [](auto* f) { f->SetTargetReduction(0.5); }, &messages);
  CD_CHECK_MSG(messages.HasError(part),
               "expected an error with '" << part << "': " << messages.ErrorText());
  CD_CHECK(level->GetNumberOfPoints() == 0 && level->GetNumberOfCells() == 0);
}

/// A record's column as numbers.
std::vector<double> ColumnValues(vtkTable* record, const char* name)
{
  std::vector<double> values;
  vtkDataArray* column = vtkDataArray::SafeDownCast(record->GetColumnByName(name));
  for (vtkIdType i = 0; column && i < column->GetNumberOfTuples(); ++i)
  {
    values.push_back(column->GetComponent(i, 0));
  }
  return values;
}
} // namespace

// The pyramid with PreserveBoundary allows one collapse only, the apex (point 4) into a base
// point: the record has that one row, with the pyramid's hand-computed error (see
// TestColorDecimationControls' MaximumErrorByHand: sqrt(4/3) / sqrt(2 + 1/h^2)) and 2 triangles
// left of 4.
CD_TEST_CASE(RecordByHand)
{
  const double h = 0.1;
  auto pyramid = meshes::FromTriangles({ 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 0, 0, h },
                                       { 4, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0 });
  for (int schedule : { vtkColorHalfEdgeDecimation::Greedy, vtkColorHalfEdgeDecimation::Batched })
  {
    const Recorded run = RecordRun(pyramid, 1.0, schedule,
                                   [](vtkColorHalfEdgeDecimation* f) { f->PreserveBoundaryOn(); });
    CD_CHECK(run.Record->GetNumberOfRows() == 1);
    CD_CHECK(ColumnValues(run.Record, "RemovedPointId") == std::vector<double>{ 4 });
    const double survivor = ColumnValues(run.Record, "SurvivingPointId").at(0);
    CD_CHECK(survivor >= 0 && survivor <= 3);
    CD_CHECK(ColumnValues(run.Record, "NumberOfTriangles") == std::vector<double>{ 2 });
    CD_CHECK_NEAR(ColumnValues(run.Record, "Error").at(0),
                  std::sqrt(4.0 / 3.0) / std::sqrt(2.0 + 1.0 / (h * h)), 1e-6);
    vtkFieldData* field = run.Record->GetFieldData();
    CD_CHECK(field->GetArray("InputNumberOfPoints")->GetComponent(0, 0) == 5);
    CD_CHECK(field->GetArray("InputNumberOfTriangles")->GetComponent(0, 0) == 4);
    CD_CHECK(field->GetAbstractArray("InputChecksum") != nullptr);
  }
  // Off by default: an empty second output.
  vtkNew<vtkColorHalfEdgeDecimation> plain;
  plain->SetInputData(pyramid);
  plain->Update();
  CD_CHECK(plain->GetCollapseRecord()->GetNumberOfRows() == 0);
  CD_CHECK(plain->GetCollapseRecord()->GetNumberOfColumns() == 0);
}

// Greedy: the level of a record taken to the topological limit is, triangle for triangle and
// array for array, the output of a direct run to that target (reduction, triangle count,
// MaximumError), on a small mesh and on one large enough to be decimated in a spatial order.
CD_TEST_CASE(GreedyLevelsEqualDirectRuns)
{
  for (int level : { 3, 7 })
  {
    auto mesh = DecoratedSphere(level); // level 7: 163,842 points (renumbered)
    const Recorded all = RecordRun(mesh, 1.0, vtkColorHalfEdgeDecimation::Greedy);
    CD_CHECK(all.Record->GetNumberOfRows() > 0);
    struct Level
    {
      double Reduction;
      vtkIdType Triangles;
      double Error;
    };
    const double diagonal = mesh->GetLength();
    for (const Level& l : { Level{ 0.5, 0, 0 }, Level{ 0.9, 0, 0 }, Level{ 0.97, 0, 0 },
                            Level{ 0.0, 601, 0 }, Level{ 0.99, 0, 0.002 * diagonal } })
    {
      const auto configure = [&l](auto* f)
      {
        f->SetTargetReduction(l.Reduction);
        f->SetTargetNumberOfTriangles(l.Triangles);
        f->SetMaximumError(l.Error);
      };
      const RunResult direct = Decimate(mesh, l.Reduction,
                                        [&](vtkColorHalfEdgeDecimation* f)
                                        {
                                          f->SetCollapseScheduleToGreedy();
                                          configure(f);
                                        });
      auto extracted = Extract(mesh, all.Record, configure);
      std::string why;
      CD_CHECK_MSG(SameMesh(direct.Output, extracted, why),
                   "level " << level << " at " << l.Reduction << " / " << l.Triangles << " / "
                            << l.Error << ": " << why);
    }
  }
}

/// A sphere and twelve small tetrahedra around it (edges 0.01 k, k = 1..12): pieces that the
/// defaults remove whole during the run.
vtkSmartPointer<vtkPolyData> SphereWithFragments(int level)
{
  auto sphere = meshes::Icosphere(level, Pattern::SharpRegions);
  std::vector<double> xyz;
  std::vector<vtkIdType> triangles;
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double p[3];
    sphere->GetPoint(i, p);
    xyz.insert(xyz.end(), p, p + 3);
  }
  for (const Tri& t : GetTriangles(sphere))
  {
    triangles.insert(triangles.end(), t.begin(), t.end());
  }
  for (int k = 1; k <= 12; ++k)
  {
    const auto first = static_cast<vtkIdType>(xyz.size() / 3);
    const double e = 0.01 * k, a = 0.5 * k, x = 1.3 * std::cos(a), y = 1.3 * std::sin(a);
    xyz.insert(xyz.end(), { x, y, 0, x + e, y, 0, x, y + e, 0, x, y, e });
    for (const vtkIdType c : { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 })
    {
      triangles.push_back(first + c);
    }
  }
  auto mesh = meshes::FromTriangles(xyz, triangles);
  Decorate(mesh);
  return mesh;
}

// Greedy with pieces removed whole: each removed piece is in the record (one row a point, with
// SurvivingPointId -1, one step), and the levels are still the direct runs' outputs (their
// collapses the prefix's rows less the pieces'), also by MaximumError, under which the pieces
// beyond it are kept. Batched: its record run's output is its last level.
CD_TEST_CASE(GreedyLevelsWithPieces)
{
  auto mesh = SphereWithFragments(3);
  const Recorded all = RecordRun(mesh, 1.0, vtkColorHalfEdgeDecimation::Greedy);
  const std::vector<double> survivors = ColumnValues(all.Record, "SurvivingPointId");
  const auto pieceRows = std::count(survivors.begin(), survivors.end(), -1.0);
  std::cout << pieceRows << " rows of removed pieces in " << survivors.size() << "\n";
  CD_CHECK(pieceRows > 0 && pieceRows % 4 == 0);
  for (const double reduction : { 0.5, 0.9, 0.97 })
  {
    const RunResult direct =
      Decimate(mesh, reduction, [](auto* f) { f->SetCollapseScheduleToGreedy(); });
    auto extracted = Extract(mesh, all.Record, [&](auto* f) { f->SetTargetReduction(reduction); });
    std::string why;
    CD_CHECK_MSG(SameMesh(direct.Output, extracted, why), reduction << ": " << why);
    std::cout << reduction << ": " << direct.Filter->GetNumberOfPrunedComponents()
              << " pieces removed\n";
    if (reduction > 0.8)
    {
      CD_CHECK(direct.Filter->GetNumberOfPrunedComponents() > 0);
    }
    vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
    lod->SetInputData(mesh);
    lod->SetRecordData(all.Record);
    lod->SetTargetReduction(reduction);
    lod->Update();
    const auto rows = static_cast<size_t>(lod->GetNumberOfCollapses()); // the prefix's rows
    CD_CHECK(rows <= survivors.size());
    const auto collapses =
      std::count_if(survivors.begin(), survivors.begin() + rows, [](double s) { return s >= 0; });
    CD_CHECK_MSG(collapses == direct.Filter->GetNumberOfCollapses(),
                 collapses << " " << direct.Filter->GetNumberOfCollapses());
  }
  // Under MaximumError the pieces beyond it are kept and the run goes on; the level by error
  // skips their rows.
  const double bound = 0.01 * mesh->GetLength();
  const RunResult bounded = Decimate(mesh, 0.99,
                                     [bound](vtkColorHalfEdgeDecimation* f)
                                     {
                                       f->SetCollapseScheduleToGreedy();
                                       f->SetMaximumError(bound);
                                     });
  std::cout << "bound " << bound << ": " << bounded.Filter->GetNumberOfPrunedComponents()
            << " pieces removed, " << bounded.Output->GetNumberOfPolys() << " triangles\n";
  CD_CHECK(bounded.Filter->GetNumberOfPrunedComponents() > 0 &&
           bounded.Filter->GetNumberOfPrunedComponents() < 12);
  CD_CHECK(bounded.Output->GetNumberOfPolys() < mesh->GetNumberOfPolys() / 2);
  CD_CHECK(bounded.Filter->GetActualError() <= bound);
  auto byError = Extract(mesh, all.Record,
                         [bound](auto* f)
                         {
                           f->SetTargetReduction(0.99);
                           f->SetMaximumError(bound);
                         });
  std::string why;
  CD_CHECK_MSG(SameMesh(bounded.Output, byError, why), "by error: " << why);
  const Recorded batched = RecordRun(mesh, 1.0, vtkColorHalfEdgeDecimation::Batched);
  const std::vector<double> rows = ColumnValues(batched.Record, "SurvivingPointId");
  CD_CHECK(std::count(rows.begin(), rows.end(), -1.0) > 0);
  auto last = Extract(mesh, batched.Record, [](auto* f) { f->SetTargetReduction(1.0); });
  CD_CHECK_MSG(SameMesh(batched.Output, last, why), why);
}

// Batched: the record run's own output is its last level; every level is a valid decimation
// (CheckDecimatedMesh), on target, and the levels are nested with a consistent hierarchy.
CD_TEST_CASE(BatchedLevelsNestedAndValid)
{
  auto mesh = DecoratedSphere(5);
  const vtkIdType input = mesh->GetNumberOfCells();
  for (int schedule : { vtkColorHalfEdgeDecimation::Batched, vtkColorHalfEdgeDecimation::Greedy })
  {
    const Recorded run = RecordRun(mesh, 0.99, schedule);
    std::string why;
    auto last = Extract(mesh, run.Record, [](auto* f) { f->SetTargetReduction(0.99); });
    CD_CHECK_MSG(SameMesh(run.Output, last, why), "the run's output is its last level: " << why);
    const auto removed = ColumnValues(run.Record, "RemovedPointId");
    const auto parent = ColumnValues(run.Record, "SurvivingPointId");
    std::set<vtkIdType> finer;
    bool first = true;
    for (double reduction : { 0.5, 0.75, 0.9, 0.97, 0.99 })
    {
      vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
      lod->SetInputData(mesh);
      lod->SetRecordData(run.Record);
      lod->SetTargetReduction(reduction);
      lod->Update();
      vtkPolyData* level = lod->GetOutput();
      const auto target = static_cast<vtkIdType>(std::floor((1 - reduction) * input + 1e-6));
      CD_CHECK_MSG(level->GetNumberOfCells() <= target && level->GetNumberOfCells() >= target - 1,
                   reduction << ": " << level->GetNumberOfCells() << " triangles for " << target);
      CD_CHECK(CheckDecimatedMesh(mesh, level, ClosedSurface(2, SphereNormal),
                                  "level " + std::to_string(reduction)) == 0);
      // Nested: a coarser level's points are among the finer one's.
      const std::set<vtkIdType> kept = OriginalIds(level);
      for (vtkIdType id : kept)
      {
        CD_CHECK_MSG(first || finer.count(id),
                     "point " << id << " of " << reduction << " is not in the finer level");
      }
      // The hierarchy: each removed point's parents lead to a point of the level.
      std::map<vtkIdType, vtkIdType> parentOf;
      for (vtkIdType i = 0; i < lod->GetNumberOfCollapses(); ++i)
      {
        parentOf[vtkIdType(removed[i])] = vtkIdType(parent[i]);
      }
      for (const auto& entry : parentOf)
      {
        vtkIdType root = entry.second;
        while (parentOf.count(root))
        {
          root = parentOf[root];
        }
        CD_CHECK(kept.count(root) == 1 && kept.count(entry.first) == 0);
      }
      CD_CHECK(kept.size() + parentOf.size() == size_t(mesh->GetNumberOfPoints()));
      finer = kept;
      first = false;
    }
  }
}

// A piece of several asked for through the record's port alone (a Level Of Detail filter as
// the decimation's only consumer) is decimated as one asked for on the mesh's port: its open
// boundary, where it would meet the other pieces, is kept.
CD_TEST_CASE(PieceBoundaries)
{
  auto sheet = meshes::Grid(30, 20, Pattern::SharpRegions);
  vtkNew<vtkColorHalfEdgeDecimation> direct;
  direct->SetInputData(sheet);
  direct->GenerateCollapseRecordOn();
  direct->SetTargetReduction(0.9);
  direct->UpdatePiece(0, 2, 0);
  const vtkIdType expected = direct->GetCollapseRecord()->GetNumberOfRows();
  vtkNew<vtkColorHalfEdgeDecimation> decimate;
  decimate->SetInputData(sheet);
  decimate->GenerateCollapseRecordOn();
  decimate->SetTargetReduction(0.9);
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  lod->SetInputData(sheet);
  lod->SetRecordConnection(decimate->GetOutputPort(1));
  lod->SetTargetReduction(0.9);
  lod->UpdatePiece(0, 2, 0);
  const vtkIdType recorded = decimate->GetCollapseRecord()->GetNumberOfRows();
  // Without the piece count the open boundary collapses too: more collapses are recorded.
  vtkNew<vtkColorHalfEdgeDecimation> whole;
  whole->SetInputData(sheet);
  whole->GenerateCollapseRecordOn();
  whole->SetTargetReduction(0.9);
  whole->Update();
  CD_CHECK(whole->GetCollapseRecord()->GetNumberOfRows() != expected);
  CD_CHECK_MSG(recorded == expected,
               recorded << " collapses recorded, " << expected
                        << " when the mesh's port asks for the piece");
  CD_CHECK(lod->GetOutput()->GetNumberOfCells() > 0);
  // A piece with ghost points but no ghost cell keeps its whole open boundary as well: the
  // ghost points mark only the shared points another piece owns.
  auto marked = Copy(sheet);
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfValues(marked->GetNumberOfPoints());
  ghosts->FillValue(0);
  ghosts->SetValue(0, vtkDataSetAttributes::DUPLICATEPOINT);
  marked->GetPointData()->AddArray(ghosts);
  vtkNew<vtkColorHalfEdgeDecimation> piece;
  piece->SetInputData(marked);
  piece->SetTargetReduction(0.9);
  piece->UpdatePiece(0, 2, 0);
  std::set<vtkIdType> kept;
  auto* ids = vtkIdTypeArray::SafeDownCast(
    piece->GetOutput()->GetPointData()->GetArray("vtkOriginalPointIds"));
  for (vtkIdType i = 0; ids && i < ids->GetNumberOfValues(); ++i)
  {
    kept.insert(ids->GetValue(i));
  }
  std::map<std::pair<vtkIdType, vtkIdType>, int> edgeUses;
  for (vtkIdType c = 0; c < marked->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    marked->GetPolys()->GetCellAtId(c, npts, pts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      const vtkIdType a = pts[k], b = pts[(k + 1) % npts];
      ++edgeUses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  long long lost = 0;
  for (const auto& edge : edgeUses)
  {
    lost += edge.second == 1 ? !kept.count(edge.first.first) + !kept.count(edge.first.second) : 0;
  }
  CD_CHECK_MSG(lost == 0, lost << " ends of open-boundary edges collapsed away");
}

// The level filter keeps the mesh and the record between updates, and reads them again when
// either changes: a record of another mesh given after a good one is refused, a good one again
// accepted, and a record changed in place is read again.
CD_TEST_CASE(LevelCacheFollowsInputs)
{
  auto mesh = DecoratedSphere(3);
  const Recorded run = RecordRun(mesh, 1.0, vtkColorHalfEdgeDecimation::Greedy);
  const Recorded other = RecordRun(DecoratedSphere(2), 1.0, vtkColorHalfEdgeDecimation::Greedy);
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  EventRecorder messages;
  messages.Watch(lod);
  lod->SetInputData(mesh);
  lod->SetRecordData(run.Record);
  lod->SetTargetReduction(0.5);
  lod->Update();
  const vtkIdType half = lod->GetOutput()->GetNumberOfCells();
  CD_CHECK(half > 0 && messages.Errors == 0);
  lod->SetRecordData(other.Record);
  lod->Update();
  CD_CHECK(messages.HasError("belongs to another mesh") &&
           lod->GetOutput()->GetNumberOfCells() == 0);
  messages.Clear();
  lod->SetRecordData(run.Record);
  lod->Update();
  CD_CHECK(messages.Errors == 0 && lod->GetOutput()->GetNumberOfCells() == half);
  // A column changed in place (a survivor out of range): read again, and refused.
  auto column = vtkDataArray::SafeDownCast(run.Record->GetColumnByName("SurvivingPointId"));
  column->SetComponent(0, 0, double(mesh->GetNumberOfPoints()));
  column->Modified(); // the level filter's MTime follows the record's columns
  lod->Update();
  CD_CHECK(messages.HasError("out of range"));
  // A column removed (which changes no MTime), the table then marked modified: read again.
  messages.Clear();
  auto copy = vtkSmartPointer<vtkTable>::New();
  copy->DeepCopy(run.Record);
  column->SetComponent(0, 0, ColumnValues(copy, "SurvivingPointId")[1]); // in range again
  lod->SetRecordData(copy);
  lod->Update();
  copy->RemoveColumnByName("Error");
  copy->Modified();
  lod->Update();
  CD_CHECK(messages.HasError("lacks one of the columns"));
  // An input with no points: an empty output.
  vtkNew<vtkPolyData> empty;
  lod->SetInputData(empty);
  lod->Update();
  CD_CHECK(lod->GetOutput()->GetNumberOfCells() == 0);
}

/// The leaves of a composite dataset by flat index.
std::map<unsigned int, vtkDataObject*> Leaves(vtkDataObject* data)
{
  std::map<unsigned int, vtkDataObject*> leaves;
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite ? composite->NewIterator() : nullptr);
  for (it ? it->InitTraversal() : void(); it && !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    leaves[it->GetCurrentFlatIndex()] = it->GetCurrentDataObject();
  }
  return leaves;
}

using LeafMap = std::map<unsigned int, vtkDataObject*>;

/// The composite level `lod` gives at `reduction`: each mesh's level is the one extracted alone
/// from its own record, and ActualReduction is over all the meshes.
void ExpectLevelOfEachMesh(vtkColorHalfEdgeLevelOfDetail* lod, const LeafMap& meshes,
                           const LeafMap& records, double reduction)
{
  lod->SetTargetReduction(reduction);
  lod->Update();
  CD_CHECK(vtkMultiBlockDataSet::SafeDownCast(lod->GetOutputDataObject(0)) != nullptr);
  const auto levels = Leaves(lod->GetOutputDataObject(0));
  CD_CHECK(levels.size() == meshes.size());
  vtkIdType in = 0, out = 0;
  for (const auto& [index, mesh] : meshes)
  {
    auto* table = vtkTable::SafeDownCast(records.at(index));
    auto* level = vtkPolyData::SafeDownCast(levels.count(index) ? levels.at(index) : nullptr);
    auto alone = Extract(vtkPolyData::SafeDownCast(mesh), table,
                         [reduction](auto* f) { f->SetTargetReduction(reduction); });
    std::string why;
    CD_CHECK_MSG(level && SameMesh(level, alone, why), "mesh " << index << ": " << why);
    in += vtkPolyData::SafeDownCast(mesh)->GetNumberOfCells();
    out += level ? level->GetNumberOfCells() : 0;
  }
  CD_CHECK(std::abs(lod->GetActualReduction() - (1.0 - double(out) / double(in))) < 1e-12);
}

/// `group` with a mesh added that has no record (an error for it, an empty level, the others
/// as before) and a block that is no mesh (a warning, an empty level).
void ExpectMixedBlocks(vtkColorHalfEdgeLevelOfDetail* lod, vtkMultiBlockDataSet* group,
                       const LeafMap& meshes, const Messages& messages)
{
  vtkNew<vtkMultiBlockDataSet> more;
  more->ShallowCopy(group);
  more->SetBlock(2, DecoratedSphere(1));
  more->SetBlock(3, vtkNew<vtkUnstructuredGrid>());
  lod->SetInputData(more);
  lod->Update();
  const auto levels = Leaves(lod->GetOutputDataObject(0));
  CD_CHECK(messages.HasError("No collapse record for the mesh at flat index"));
  CD_CHECK(messages.HasWarning("is a vtkUnstructuredGrid, not a vtkPolyData"));
  CD_CHECK(levels.size() == 4);
  vtkIdType kept = 0;
  for (const auto& [index, level] : levels)
  {
    kept += vtkPolyData::SafeDownCast(level)->GetNumberOfCells();
    CD_CHECK((meshes.count(index) > 0) ==
             (vtkPolyData::SafeDownCast(level)->GetNumberOfCells() > 0));
  }
  CD_CHECK(kept > 0);
}

/// The decimation of `group` with a block that is no mesh: a warning (no pipeline failure), that
/// block empty, the meshes decimated.
void ExpectImageBlockLeftEmpty(vtkMultiBlockDataSet* group)
{
  vtkNew<vtkMultiBlockDataSet> withImage;
  withImage->ShallowCopy(group);
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 4);
  withImage->SetBlock(2, image);
  vtkNew<vtkColorHalfEdgeDecimation> run;
  EventRecorder messages;
  messages.Watch(run);
  run->SetInputData(withImage);
  CD_CHECK(run->GetExecutive()->Update() == 1);
  CD_CHECK(messages.Errors == 0 && messages.Warnings == 1 &&
           messages.HasWarning("is a vtkImageData, not a vtkPolyData"));
  const auto blocks = Leaves(run->GetOutputDataObject(0));
  int decimated = 0, empty = 0;
  for (const auto& [index, block] : blocks)
  {
    auto* mesh = vtkPolyData::SafeDownCast(block);
    decimated += mesh && mesh->GetNumberOfPolys() > 0 ? 1 : 0;
    empty += !mesh || mesh->GetNumberOfCells() == 0 ? 1 : 0;
  }
  CD_CHECK_MSG(decimated == 2 && empty == static_cast<int>(blocks.size()) - 2,
               decimated << " meshes decimated of " << blocks.size() << " blocks");
  CD_CHECK(run->GetNumberOfCollapses() > 0); // the last mesh's, the image block after it

  // The figures are those of the update: an update again without a change keeps them; a
  // composite of the image alone leaves none of the earlier update's.
  const double reduction = run->GetActualReduction();
  run->Update();
  CD_CHECK(run->GetActualReduction() == reduction && reduction > 0);
  vtkNew<vtkMultiBlockDataSet> imageOnly;
  imageOnly->SetBlock(0, image);
  run->SetInputData(imageOnly);
  CD_CHECK(run->GetExecutive()->Update() == 1);
  CD_CHECK_MSG(run->GetActualReduction() == 0 && run->GetNumberOfCollapses() == 0 &&
                 run->GetNumberOfPhases() == 0,
               "an earlier update's figures: reduction " << run->GetActualReduction() << ", "
                                                         << run->GetNumberOfCollapses()
                                                         << " collapses");
}

/// The level filter's progress on a composite input of several meshes, read anew: each mesh in
/// its share, from 0 to 1 without going back.
void ExpectCompositeProgress(vtkMultiBlockDataSet* group, vtkDataObject* records)
{
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod; // no cache: every mesh and record is read
  std::vector<double> reported;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&reported);
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* reported, void* amount)
    { static_cast<std::vector<double>*>(reported)->push_back(*static_cast<double*>(amount)); });
  lod->AddObserver(vtkCommand::ProgressEvent, progress);
  lod->SetInputData(group);
  lod->SetRecordData(records);
  lod->Update();
  std::ostringstream values;
  for (const double value : reported)
  {
    values << " " << value;
  }
  CD_CHECK_MSG(reported.size() >= 5 && std::is_sorted(reported.begin(), reported.end()) &&
                 reported.back() == 1.0,
               "progress:" << values.str());
}

/// A single record serves a composite of one mesh (whatever other blocks it has), not one of
/// several; the other way round, a single mesh takes a composite record of one mesh, as its
/// table, and a composite record of several is refused, naming what it is.
void ExpectSingleRecords(vtkColorHalfEdgeLevelOfDetail* lod, vtkMultiBlockDataSet* group,
                         const LeafMap& meshes, const LeafMap& records, vtkDataObject* recorded,
                         EventRecorder& messages)
{
  vtkNew<vtkMultiBlockDataSet> one;
  one->SetBlock(0, meshes.begin()->second);
  one->SetBlock(1, vtkNew<vtkUnstructuredGrid>());
  messages.Clear();
  lod->SetInputData(one);
  lod->SetRecordData(records.begin()->second);
  lod->Update();
  CD_CHECK(messages.Errors == 0 && Leaves(lod->GetOutputDataObject(0)).size() == 2);
  CD_CHECK(vtkPolyData::SafeDownCast(Leaves(lod->GetOutputDataObject(0)).begin()->second)
             ->GetNumberOfCells() > 0);
  lod->SetInputData(group);
  lod->Update();
  CD_CHECK(messages.HasError("No collapse record"));

  auto* first = vtkPolyData::SafeDownCast(meshes.begin()->second);
  vtkNew<vtkMultiBlockDataSet> oneRecord;
  oneRecord->SetBlock(0, records.begin()->second);
  messages.Clear();
  lod->SetInputData(first);
  lod->SetRecordData(oneRecord);
  lod->SetTargetReduction(0.9);
  lod->Update();
  auto alone = Extract(first, vtkTable::SafeDownCast(records.begin()->second),
                       [](auto* f) { f->SetTargetReduction(0.9); });
  std::string why;
  CD_CHECK_MSG(messages.Errors == 0 && SameMesh(lod->GetOutput(), alone, why), why);
  lod->SetRecordData(recorded);
  lod->Update();
  CD_CHECK(messages.HasError("vtkMultiBlockDataSet of 2 records") &&
           lod->GetOutput()->GetNumberOfCells() == 0);
}

// A composite input (multiblock, nested; partitioned collection): the decimation makes a record
// for each mesh in a composite of the same structure, and the level filter gives a composite
// output of that type whose each mesh is the level extracted from that mesh's own record; the
// statistics are over all meshes; a mesh without a record, a block that is no mesh, are said.
CD_TEST_CASE(CompositeInput)
{
  vtkNew<vtkMultiBlockDataSet> nested;
  nested->SetBlock(0, DecoratedSphere(2));
  vtkNew<vtkMultiBlockDataSet> group;
  group->SetBlock(0, DecoratedSphere(3));
  group->SetBlock(1, nested);
  vtkNew<vtkColorHalfEdgeDecimation> run;
  run->SetInputData(group);
  run->SetCollapseScheduleToGreedy();
  run->GenerateCollapseRecordOn();
  run->SetTargetReduction(0.99);
  run->Update();
  const auto meshes = Leaves(group);
  vtkSmartPointer<vtkDataObject> recorded;
  recorded.TakeReference(run->GetOutputDataObject(1)->NewInstance());
  recorded->DeepCopy(run->GetOutputDataObject(1)); // the run is made again below
  const auto records = Leaves(recorded);
  CD_CHECK(meshes.size() == 2 && records.size() == 2);

  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  EventRecorder messages;
  messages.Watch(lod);
  lod->SetInputData(group);
  lod->SetRecordConnection(run->GetOutputPort(1));
  for (const double reduction : { 0.5, 0.9 }) // the second reuses each mesh's cache
  {
    ExpectLevelOfEachMesh(lod, meshes, records, reduction);
    CD_CHECK(messages.Errors == 0 && messages.Warnings == 0);
  }

  // The same meshes as a partitioned dataset collection: that type out.
  vtkNew<vtkPartitionedDataSetCollection> collection;
  vtkNew<vtkPartitionedDataSet> partitions;
  partitions->SetPartition(0, DecoratedSphere(2));
  partitions->SetPartition(1, DecoratedSphere(1));
  collection->SetPartitionedDataSet(0, partitions);
  run->SetInputData(collection);
  lod->SetInputData(collection);
  lod->Update();
  CD_CHECK(vtkPartitionedDataSetCollection::SafeDownCast(lod->GetOutputDataObject(0)));
  CD_CHECK(Leaves(lod->GetOutputDataObject(0)).size() == 2 && messages.Errors == 0);

  run->SetInputData(group);
  ExpectMixedBlocks(lod, group, meshes, messages);
  ExpectImageBlockLeftEmpty(group);
  ExpectCompositeProgress(group, recorded);

  // A composite record given as data and edited in place (a column removed, the table marked
  // modified): read again, and refused.
  vtkNew<vtkMultiBlockDataSet> nestedCopy;
  nestedCopy->DeepCopy(recorded);
  messages.Clear();
  lod->SetInputData(group);
  lod->SetRecordData(nestedCopy);
  lod->Update();
  CD_CHECK(messages.Errors == 0);
  auto* firstTable = vtkTable::SafeDownCast(Leaves(nestedCopy).begin()->second);
  firstTable->RemoveColumnByName("Error");
  firstTable->Modified();
  lod->Update();
  CD_CHECK(messages.HasError("lacks one of the columns"));

  ExpectSingleRecords(lod, group, meshes, records, recorded, messages);
}

// The mesh is read again only when its points or cells change: not when the input is a new
// shallow copy of the same data (as ParaView hands it at each update), nor when only a point
// array changes (the level then carries the new values); the progress text says when.
CD_TEST_CASE(LevelCacheKeepsShallowCopies)
{
  auto mesh = DecoratedSphere(3);
  const Recorded run = RecordRun(mesh, 1.0, vtkColorHalfEdgeDecimation::Greedy);
  vtkNew<vtkPolyData> input;
  input->ShallowCopy(mesh);
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  int reads = 0;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&reads);
  progress->SetCallback(
    [](vtkObject* caller, unsigned long, void* reads, void*)
    {
      const char* text = static_cast<vtkAlgorithm*>(caller)->GetProgressText();
      *static_cast<int*>(reads) += text && std::string(text).find("Reading the mesh") == 0;
    });
  lod->AddObserver(vtkCommand::ProgressEvent, progress);
  lod->SetInputData(input);
  lod->SetRecordData(run.Record);
  lod->SetTargetReduction(0.5);
  lod->Update();
  CD_CHECK(reads == 1 && lod->GetOutput()->GetNumberOfCells() > 0);
  const vtkMTimeType before = input->GetMTime();
  input->ShallowCopy(mesh);
  CD_CHECK(input->GetMTime() > before);
  lod->SetTargetReduction(0.8);
  lod->Update();
  CD_CHECK(reads == 1);
  std::string why;
  CD_CHECK_MSG(
    SameMesh(lod->GetOutput(),
             Extract(mesh, run.Record,
                     [](vtkColorHalfEdgeLevelOfDetail* l) { l->SetTargetReduction(0.8); }),
             why),
    why);
  // A point array changed in place: kept, and the level carries the new value.
  vtkDataArray* colors = input->GetPointData()->GetScalars();
  const vtkIdType kept =
    vtkIdTypeArray::SafeDownCast(lod->GetOutput()->GetPointData()->GetArray("vtkOriginalPointIds"))
      ->GetValue(0);
  colors->SetComponent(kept, 0, 255 - colors->GetComponent(kept, 0));
  colors->Modified();
  lod->Update();
  CD_CHECK(reads == 1 &&
           lod->GetOutput()->GetPointData()->GetScalars()->GetComponent(0, 0) ==
             colors->GetComponent(kept, 0));
  // A point moved in place: read again, and the record no longer belongs to the mesh.
  EventRecorder messages;
  messages.Watch(lod);
  double p[3], original[3];
  input->GetPoints()->GetPoint(0, p);
  std::copy(p, p + 3, original);
  p[0] += 0.5;
  input->GetPoints()->SetPoint(0, p);
  input->GetPoints()->Modified();
  lod->Update();
  CD_CHECK(reads == 2 && messages.HasError("belongs to another mesh"));
  input->GetPoints()->SetPoint(0, original); // mesh shares them
  input->GetPoints()->Modified();
  lod->Update();
  CD_CHECK(reads == 3 && lod->GetOutput()->GetNumberOfCells() > 0);
  // A triangle's corners turned in place, the cell array marked modified (its connectivity
  // array's MTime does not move): read again, and the record is another mesh's.
  messages.Clear();
  vtkCellArray* polys = input->GetPolys();
  vtkIdType npts;
  const vtkIdType* pts;
  polys->GetCellAtId(0, npts, pts);
  const vtkIdType corners[3] = { pts[0], pts[1], pts[2] };
  const vtkIdType turned[3] = { corners[1], corners[2], corners[0] };
  polys->ReplaceCellAtId(0, 3, turned);
  polys->Modified();
  lod->Update();
  CD_CHECK(reads == 4 && messages.HasError("belongs to another mesh"));
  polys->ReplaceCellAtId(0, 3, corners); // mesh shares them
  polys->Modified();
  colors->SetComponent(kept, 0, 255 - colors->GetComponent(kept, 0)); // mesh shares it
  colors->Modified();
}

// Saved with vtkXMLTableWriter and read back, the record gives the same level.
CD_TEST_CASE(RecordRoundTrip)
{
  auto mesh = DecoratedSphere(4);
  const Recorded run = RecordRun(mesh, 1.0, vtkColorHalfEdgeDecimation::Batched);
  const std::string file = "ColorDecimationRecordRoundTrip.vtt";
  vtkNew<vtkXMLTableWriter> writer;
  writer->SetInputData(run.Record);
  writer->SetFileName(file.c_str());
  CD_CHECK(writer->Write() == 1);
  vtkNew<vtkXMLTableReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  CD_CHECK(reader->GetOutput()->GetNumberOfRows() == run.Record->GetNumberOfRows());
  for (double reduction : { 0.6, 0.95 })
  {
    const auto configure = [reduction](auto* f) { f->SetTargetReduction(reduction); };
    auto fromMemory = Extract(mesh, run.Record, configure);
    auto fromFile = Extract(mesh, reader->GetOutput(), configure);
    std::string why;
    CD_CHECK_MSG(SameMesh(fromMemory, fromFile, why), reduction << ": " << why);
    CD_CHECK(CheckPointDataCopied(mesh, fromFile) == 0);
  }
}

// Bad records: each gives an error naming what is wrong and an empty output.
CD_TEST_CASE(BadRecords)
{
  auto mesh = DecoratedSphere(3);
  const Recorded run = RecordRun(mesh, 1.0, vtkColorHalfEdgeDecimation::Greedy);
  const auto expectError = [&mesh](vtkTable* record, vtkPolyData* input, const std::string& part)
  { ExpectRecordError(input ? input : mesh.GetPointer(), record, part); };
  // Another mesh: one point moved (same counts), then another mesh altogether.
  auto moved = Copy(mesh);
  double p[3];
  moved->GetPoint(7, p);
  p[0] += 1e-9;
  moved->GetPoints()->SetPoint(7, p);
  expectError(run.Record, moved, "belongs to another mesh");
  expectError(run.Record, DecoratedSphere(2), "belongs to another mesh");
  // Not a record: the empty table of a run without GenerateCollapseRecord.
  vtkNew<vtkTable> empty;
  expectError(empty, nullptr, "not a collapse record");
  // A column missing.
  vtkNew<vtkTable> noColumn;
  noColumn->DeepCopy(run.Record);
  noColumn->RemoveColumnByName("SurvivingPointId");
  expectError(noColumn, nullptr, "lacks one of the columns");
  // Ids out of range, a point removed twice, triangle counts that do not decrease.
  const auto tampered = [&run](const char* column, vtkIdType row, double value)
  {
    auto table = vtkSmartPointer<vtkTable>::New();
    table->DeepCopy(run.Record);
    vtkDataArray::SafeDownCast(table->GetColumnByName(column))->SetComponent(row, 0, value);
    return table;
  };
  expectError(tampered("SurvivingPointId", 3, mesh->GetNumberOfPoints()), nullptr, "out of range");
  expectError(tampered("RemovedPointId", 0, -1), nullptr, "out of range");
  expectError(tampered("SurvivingPointId", 3, -5), nullptr, "whole numbers from -1 to 2^31 - 1");
  expectError(tampered("RemovedPointId", 5, ColumnValues(run.Record, "RemovedPointId")[2]), nullptr,
              "an earlier one removed");
  expectError(tampered("NumberOfTriangles", 4, mesh->GetNumberOfCells()), nullptr,
              "do not decrease");
  // Values no record holds: NaN and huge counts, NaN and negative errors.
  expectError(tampered("NumberOfTriangles", 2, 1e300), nullptr, "not all finite");
  expectError(tampered("Error", 1, std::nan("")), nullptr, "not all finite");
  expectError(tampered("Error", 1, -1.0), nullptr, "not all finite");
  // Single-precision ids (exact only up to 2^24).
  auto floatIds = vtkSmartPointer<vtkTable>::New();
  floatIds->DeepCopy(run.Record);
  vtkNew<vtkFloatArray> survivors;
  survivors->DeepCopy(floatIds->GetColumnByName("SurvivingPointId"));
  survivors->SetName("SurvivingPointId");
  floatIds->RemoveColumnByName("SurvivingPointId");
  floatIds->AddColumn(survivors);
  expectError(floatIds, nullptr, "single-precision");
  // Costs are not read: an infinite one is accepted (the schedule may record one).
  EventRecorder quiet;
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  quiet.Watch(lod);
  lod->SetInputData(mesh);
  lod->SetRecordData(tampered("Cost", 1, HUGE_VAL));
  lod->Update();
  CD_CHECK(quiet.Errors == 0 && lod->GetOutput()->GetNumberOfCells() > 0);
  // A NaN reduction: an error, not the coarsest level.
  lod->SetTargetReduction(std::nan(""));
  lod->Update();
  CD_CHECK(quiet.HasError("TargetReduction is NaN") && lod->GetOutput()->GetNumberOfCells() == 0);
  // The mesh mirrored (every x negated: the sign bits flipped in pairs) is another mesh.
  auto mirrored = Copy(mesh);
  for (vtkIdType i = 0; i < mirrored->GetNumberOfPoints(); ++i)
  {
    double q[3];
    mirrored->GetPoint(i, q);
    q[0] = -q[0];
    mirrored->GetPoints()->SetPoint(i, q);
  }
  expectError(run.Record, mirrored, "belongs to another mesh");
}

// The checksum of a mesh too large for one block of the hash (163,842 points): the same on one
// thread and on two, and changed by one point moved in a late block or two points swapped.
CD_TEST_CASE(ChecksumInBlocks)
{
  auto mesh = DecoratedSphere(7);
  const auto checksum = [](vtkTable* record)
  {
    return record->GetFieldData()->GetAbstractArray("InputChecksum")->GetVariantValue(0).ToString();
  };
  std::string checksums[2];
  for (int threads : { 1, 2 })
  {
    const Recorded run =
      RecordRun(mesh, 0.5, vtkColorHalfEdgeDecimation::Batched,
                [threads](vtkColorHalfEdgeDecimation* f) { f->SetNumberOfThreads(threads); });
    checksums[threads - 1] = checksum(run.Record);
    CD_CHECK(checksums[threads - 1].size() == 16);
  }
  CD_CHECK_MSG(checksums[0] == checksums[1], checksums[0] << " != " << checksums[1]);
  const Recorded run = RecordRun(mesh, 0.5, vtkColorHalfEdgeDecimation::Batched);
  auto moved = Copy(mesh);
  double p[3], q[3];
  moved->GetPoint(150000, p);
  p[2] += 1e-9;
  moved->GetPoints()->SetPoint(150000, p);
  ExpectRecordError(moved, run.Record, "belongs to another mesh");
  auto swapped = Copy(mesh);
  swapped->GetPoint(100000, p);
  swapped->GetPoint(100001, q);
  swapped->GetPoints()->SetPoint(100000, q);
  swapped->GetPoints()->SetPoint(100001, p);
  ExpectRecordError(swapped, run.Record, "belongs to another mesh");
  // A record of the same mesh saved before the checksum went by blocks (no version field).
  auto older = vtkSmartPointer<vtkTable>::New();
  older->DeepCopy(run.Record);
  older->GetFieldData()->RemoveArray("InputChecksumVersion");
  ExpectRecordError(mesh, older, "saved by another version");
}

// A record file cut short, and no record at all: an error each, and an empty output.
CD_TEST_CASE(BadRecordFiles)
{
  auto mesh = DecoratedSphere(3);
  const Recorded run = RecordRun(mesh, 1.0, vtkColorHalfEdgeDecimation::Greedy);
  // A file cut short: the reader fails, and so does the extraction.
  const std::string file = "ColorDecimationRecordTruncated.vtt";
  {
    vtkNew<vtkXMLTableWriter> writer;
    writer->SetInputData(run.Record);
    writer->SetDataModeToAscii();
    writer->SetFileName(file.c_str());
    writer->Write();
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
  }
  vtkNew<vtkXMLTableReader> reader;
  EventRecorder readerMessages;
  readerMessages.Watch(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  CD_CHECK(readerMessages.Errors > 0);
  ExpectRecordError(mesh, reader->GetOutput(), "collapse record");
  // No record connected at all.
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  EventRecorder lodMessages;
  lodMessages.Watch(lod);
  lod->SetInputData(mesh);
  lod->Update();
  CD_CHECK(lodMessages.Errors > 0);
  CD_CHECK(lod->GetOutput()->GetNumberOfCells() == 0);
}

// OptimalPlacement moves points: no record, with a warning; the decimation itself is unchanged.
CD_TEST_CASE(RecordNotWithOptimalPlacement)
{
  auto mesh = DecoratedSphere(3);
  const RunResult run = RunFilter(mesh, 0.9,
                                  [](vtkColorHalfEdgeDecimation* f)
                                  {
                                    f->SetErrorMetricToColorQuadric();
                                    f->OptimalPlacementOn();
                                    f->GenerateCollapseRecordOn();
                                  });
  CD_CHECK(run.HasWarning("No collapse record with OptimalPlacement"));
  CD_CHECK(run.Filter->GetCollapseRecord()->GetNumberOfRows() == 0);
  CD_CHECK(run.Output->GetNumberOfCells() > 0);
  // The other metrics ignore OptimalPlacement: their record is made, quietly.
  const RunResult other = RunFilter(mesh, 0.9,
                                    [](vtkColorHalfEdgeDecimation* f)
                                    {
                                      f->OptimalPlacementOn();
                                      f->GenerateCollapseRecordOn();
                                    });
  CD_CHECK(other.Warnings == 0 && other.Filter->GetCollapseRecord()->GetNumberOfRows() > 0);
}

// Attribute seams: a pair of collapses is one step of the record. Greedy levels of a seam
// sphere equal direct runs, and no level of either schedule opens the seam (welded, closed).
CD_TEST_CASE(SeamLevels)
{
  auto sphere = meshes::SeamSphere(40);
  CD_CHECK(WeldedOpenEdges(sphere) == 0);
  for (int schedule : { vtkColorHalfEdgeDecimation::Greedy, vtkColorHalfEdgeDecimation::Batched })
  {
    const Recorded run = RecordRun(sphere, 0.98, schedule);
    const auto triangles = ColumnValues(run.Record, "NumberOfTriangles");
    size_t pairs = 0;
    for (size_t i = 1; i < triangles.size(); ++i)
    {
      pairs += triangles[i] == triangles[i - 1] ? 1 : 0;
    }
    CD_CHECK_MSG(pairs > 10, pairs << " seam pairs recorded");
    // A target one triangle below the count before a pair: a level that ended inside the pair
    // would open the seam there.
    std::vector<vtkIdType> targets;
    for (size_t i = 1; i < triangles.size() && targets.size() < 8; ++i)
    {
      if (triangles[i] == triangles[i - 1])
      {
        const double before = i >= 2 ? triangles[i - 2] : double(sphere->GetNumberOfCells());
        targets.push_back(vtkIdType(before) - 1);
      }
    }
    for (vtkIdType target : targets)
    {
      auto level =
        Extract(sphere, run.Record, [target](auto* f) { f->SetTargetNumberOfTriangles(target); });
      CD_CHECK_MSG(WeldedOpenEdges(level) == 0, "the level at " << target << " opens the seam");
      CD_CHECK(level->GetNumberOfCells() < target);
    }
    for (double reduction : { 0.5, 0.8, 0.9, 0.95, 0.98 })
    {
      const auto configure = [reduction](auto* f) { f->SetTargetReduction(reduction); };
      auto level = Extract(sphere, run.Record, configure);
      CD_CHECK_MSG(WeldedOpenEdges(level) == 0, "level " << reduction << " opens the seam");
      CD_CHECK(CheckPointDataCopied(sphere, level) == 0);
      if (schedule == vtkColorHalfEdgeDecimation::Greedy)
      {
        const RunResult direct =
          Decimate(sphere, reduction,
                   [](vtkColorHalfEdgeDecimation* f) { f->SetCollapseScheduleToGreedy(); });
        std::string why;
        CD_CHECK_MSG(SameMesh(direct.Output, level, why), "level " << reduction << ": " << why);
      }
    }
  }
}

int main(int argc, char* argv[])
{
  return RunTestCases(argc, argv);
}
