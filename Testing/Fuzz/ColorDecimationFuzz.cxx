#include "ColorDecimationFuzz.h"

#include "ColorDecimationTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkColorHalfEdgeLevelOfDetail.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkType.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace colordecimation
{
namespace fuzz
{
namespace
{

/// Reads bytes from the front; past the end every read gives 0.
class ByteReader
{
public:
  ByteReader(const uint8_t* data, size_t size)
    : Data(data)
    , Size(size)
  {
  }

  uint8_t Byte() { return this->Position < this->Size ? this->Data[this->Position++] : 0; }
  size_t Remaining() const { return this->Size - this->Position; }
  void Raw(void* out, size_t n)
  {
    auto* bytes = static_cast<uint8_t*>(out);
    for (size_t k = 0; k < n; ++k)
    {
      bytes[k] = this->Byte();
    }
  }

private:
  const uint8_t* Data;
  size_t Size;
  size_t Position = 0;
};

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double Inf = std::numeric_limits<double>::infinity();

double TargetReduction(uint8_t b)
{
  static const double special[] = { -1.0, 2.0, NaN, 1e-9, 1.0 - 1e-9 };
  return b <= 250 ? b / 250.0 : special[b - 251];
}

double NormalAngle(uint8_t b)
{
  static const double special[] = { -10.0, 360.0, NaN, 1e-300, 180.0 };
  return b <= 250 ? 180.0 * b / 250.0 : special[b - 251];
}

double GeometryWeight(uint8_t b)
{
  static const double table[16] = { 1.0,    0.0,   0.5,     2.0, 10.0, 1e3,  1e6,    1e-6,
                                    1e-300, 1e300, DBL_MAX, Inf, NaN,  -1.0, 5e-324, 0.1 };
  return table[b % 16];
}

double Scale(uint8_t b)
{
  static const double table[8] = { 1.0, 1e-7, 1e7, 1e-30, 1e30, 3.7, 1e-3, 1e3 };
  return table[b % 8];
}

double Coordinate(ByteReader& in)
{
  const uint8_t b = in.Byte();
  if (b < 224)
  {
    return (static_cast<int>(b) - 112) / 16.0;
  }
  switch (b - 224)
  {
    case 0:
      return NaN;
    case 1:
      return Inf;
    case 2:
      return -Inf;
    case 3:
      return 1e38;
    case 4:
      return -1e38;
    case 5:
      return FLT_MAX;
    case 6:
      return -FLT_MAX;
    case 7:
      return 1e-38;
    case 8:
      return 1e-45;
    case 9:
      return DBL_MAX;
    case 10:
      return -DBL_MAX;
    case 11:
      return 1e300;
    case 12:
      return -1e300;
    case 13:
      return 1e-300;
    case 14:
      return 5e-324;
    case 15:
      return -0.0;
    case 16:
      return 1e7;
    case 17:
      return -1e7;
    case 18:
      return 1e-7;
    case 19:
      return -1e-7;
    case 20:
      return 1.0000001;
    case 21:
      return 1.0 / 3.0;
    case 22:
      return 1e15;
    case 23:
      return 1e-15;
    case 24:
      return 123456.789;
    case 25:
      return -3.0;
    case 26:
      return -NaN;
    case 27:
      return 0.5;
    case 28:
    case 29:
    {
      float f;
      in.Raw(&f, sizeof(f));
      return f;
    }
    default:
    {
      double d;
      in.Raw(&d, sizeof(d));
      return d;
    }
  }
}

vtkIdType PointId(ByteReader& in, vtkIdType numPoints)
{
  const uint8_t b = in.Byte();
  if (b < 250)
  {
    return b;
  }
  const vtkIdType special[6] = { -1,
                                 numPoints,
                                 numPoints + 1000,
                                 std::numeric_limits<int32_t>::max(),
                                 static_cast<vtkIdType>(1) << 40,
                                 -(static_cast<vtkIdType>(1) << 40) };
  return special[b - 250];
}

/// A cell section: a count byte, then per cell a size byte (% sizeModulo) and its ids.
void ReadCells(ByteReader& in, vtkIdType numPoints, int sizeModulo, vtkCellArray* cells)
{
  const int count = in.Byte();
  std::vector<vtkIdType> ids;
  for (int c = 0; c < count && in.Remaining() > 0; ++c)
  {
    const int n = in.Byte() % sizeModulo;
    ids.resize(n);
    for (int k = 0; k < n; ++k)
    {
      ids[k] = PointId(in, numPoints);
    }
    cells->InsertNextCell(n, ids.data());
  }
}

template <typename T>
void FillValues(ByteReader& in, bool raw, T* values, vtkIdType count)
{
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (raw)
    {
      in.Raw(values + i, sizeof(T));
    }
    else
    {
      const uint8_t b = in.Byte();
      values[i] =
        std::numeric_limits<T>::is_integer ? static_cast<T>(b) : static_cast<T>(b / 255.0);
    }
  }
}

bool ConsistentArrays()
{
  static const bool consistent = std::getenv("COLORDECIMATION_FUZZ_CONSISTENT_ARRAYS") != nullptr;
  return consistent;
}

vtkSmartPointer<vtkDataArray> ReadColors(ByteReader& in, vtkIdType numPoints, int& kind)
{
  static const int types[14] = {
    VTK_CHAR,           VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR,      VTK_SHORT,
    VTK_UNSIGNED_SHORT, VTK_INT,         VTK_UNSIGNED_INT,       VTK_LONG,
    VTK_UNSIGNED_LONG,  VTK_LONG_LONG,   VTK_UNSIGNED_LONG_LONG, VTK_FLOAT,
    VTK_DOUBLE,         VTK_ID_TYPE
  };
  kind = in.Byte() % 16; // 0-13 point data of that type, 14 none, 15 cell data
  const uint8_t width = in.Byte();
  const int components = 1 + (width & 0x7f) % 5;
  const bool raw = (width & 0x80) != 0;
  const uint8_t countCode = in.Byte() % 8;
  if (kind == 14)
  {
    return nullptr;
  }
  vtkIdType tuples = numPoints;
  if (ConsistentArrays())
  {
    // Exploration past the known short-array problem (see ColorDecimationFuzz.h).
  }
  else if (countCode == 5)
  {
    tuples = numPoints > 0 ? numPoints - 1 : 0;
  }
  else if (countCode == 6)
  {
    tuples = numPoints + 1;
  }
  else if (countCode == 7)
  {
    tuples = 0;
  }
  auto array = vtk::TakeSmartPointer(
    vtkDataArray::CreateDataArray(kind == 15 ? VTK_UNSIGNED_CHAR : types[kind]));
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  const vtkIdType count = tuples * components;
  switch (array->GetDataType())
  {
    vtkTemplateMacro(FillValues(in, raw, static_cast<VTK_TT*>(array->GetVoidPointer(0)), count));
  }
  return array;
}

struct Settings
{
  int Metric = 0;
  int ColorSpace = 0;
  bool OptimalPlacement = false;
  double ColorWeight = 1.0;
  bool PreserveBoundary = false;
  bool GenerateIds = true;
  bool ColorByName = false;
  double TargetReduction = 0.9;
  double NormalAngle = 90.0;
  double GeometryWeight = 1.0;
  int Schedule = 0;
  double MaximumError = 0.0;
  vtkIdType TargetTriangles = 0;
  const char* LockName = nullptr;
  bool Prune = false;
  bool ConsistentOrientation = false;
};

/// The trailing controls byte: MaximumError, TargetNumberOfTriangles, a lock array and
/// PruneComponents.
void ReadControls(ByteReader& in, vtkPolyData* mesh, Settings& settings)
{
  const uint8_t controls = in.Byte();
  static const double bounds[8] = { 0.0, 1e-9, 1e-3, 0.1, 10.0, std::nan(""), -1.0, HUGE_VAL };
  static const vtkIdType targets[4] = { 0, 1, 5, VTK_ID_MAX };
  settings.MaximumError = bounds[controls & 7];
  settings.TargetTriangles = targets[(controls >> 3) & 3];
  settings.Prune = (controls & 128) != 0;
  settings.ConsistentOrientation = (in.Byte() & 1) != 0;
  const int lock = (controls >> 5) & 3; // 0 none, 1 every third point, 2 missing, 3 short
  if (lock == 0)
  {
    return;
  }
  settings.LockName = lock == 2 ? "NoSuchLock" : "Lock";
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  vtkNew<vtkUnsignedCharArray> locks;
  locks->SetName("Lock");
  locks->SetNumberOfValues(lock == 3 ? numPoints / 2 : numPoints);
  for (vtkIdType i = 0; i < locks->GetNumberOfValues(); ++i)
  {
    locks->SetValue(i, i % 3 == 0 ? 1 : 0);
  }
  mesh->GetPointData()->AddArray(locks);
}

/// The settings from the first bytes (options and more: the two flag bytes, kept for what
/// follows); the coordinates' scale.
double ReadSettings(ByteReader& in, Settings& settings, uint8_t& options, uint8_t& more)
{
  options = in.Byte();
  more = in.Byte();
  settings.Metric = options & 3;
  settings.ColorSpace = (more & 8) ? vtkColorHalfEdgeDecimation::CIELab : 0;
  settings.OptimalPlacement = (more & 16) != 0;
  settings.Schedule = (more & 128) ? vtkColorHalfEdgeDecimation::Batched : 0;
  static const double colorWeights[4] = { 1.0, 0.0, 1e-3, 1e3 };
  settings.ColorWeight = colorWeights[(more >> 5) & 3];
  settings.PreserveBoundary = (options & 4) != 0;
  settings.GenerateIds = (options & 8) == 0;
  settings.ColorByName = (options & 32) != 0;
  settings.TargetReduction = TargetReduction(in.Byte());
  settings.NormalAngle = NormalAngle(in.Byte());
  settings.GeometryWeight = GeometryWeight(in.Byte());
  return Scale(in.Byte());
}

vtkSmartPointer<vtkPoints> ReadPoints(ByteReader& in, bool doubles, double scale)
{
  const vtkIdType numPoints = in.Byte() % 251;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(doubles ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(numPoints);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double p[3];
    for (double& x : p)
    {
      x = scale * Coordinate(in);
    }
    points->SetPoint(i, p);
  }
  return points;
}

/// Triangles (a 16-bit count, then their ids), more polygons, strips, vertices and lines.
void ReadAllCells(ByteReader& in, vtkPolyData* mesh)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  vtkNew<vtkCellArray> polys;
  int numTriangles = in.Byte();
  numTriangles |= in.Byte() << 8;
  for (int t = 0; t < numTriangles && in.Remaining() > 0; ++t)
  {
    vtkIdType ids[3];
    for (vtkIdType& id : ids)
    {
      id = PointId(in, numPoints);
    }
    polys->InsertNextCell(3, ids);
  }
  ReadCells(in, numPoints, 9, polys);
  vtkNew<vtkCellArray> strips, verts, lines;
  ReadCells(in, numPoints, 12, strips);
  ReadCells(in, numPoints, 4, verts);
  ReadCells(in, numPoints, 5, lines);
  mesh->SetPolys(polys);
  if (strips->GetNumberOfCells())
  {
    mesh->SetStrips(strips);
  }
  if (verts->GetNumberOfCells())
  {
    mesh->SetVerts(verts);
  }
  if (lines->GetNumberOfCells())
  {
    mesh->SetLines(lines);
  }
}

/// The colours as the point scalars (named "Color" unless `more` & 4), or, for kind 15, as a
/// cell array selected by name, which the filter must refuse.
void AddColors(ByteReader& in, vtkPolyData* mesh, uint8_t more, Settings& settings)
{
  int kind = 0;
  vtkSmartPointer<vtkDataArray> colors = ReadColors(in, mesh->GetNumberOfPoints(), kind);
  if (!colors)
  {
    return;
  }
  if (!(more & 4))
  {
    colors->SetName("Color");
  }
  if (kind != 15)
  {
    mesh->GetPointData()->SetScalars(colors);
    return;
  }
  colors->SetName("Color");
  colors->SetNumberOfTuples(mesh->GetNumberOfCells());
  if (colors->GetNumberOfValues() > 0)
  {
    std::memset(colors->GetVoidPointer(0), 128,
                static_cast<size_t>(colors->GetNumberOfValues()) * colors->GetDataTypeSize());
  }
  mesh->GetCellData()->AddArray(colors);
  settings.ColorByName = true;
}

/// Ghost flags from the bytes: of the cells when `more` & 1, of the points when `more` & 2.
void AddGhosts(ByteReader& in, vtkPolyData* mesh, uint8_t more)
{
  for (vtkDataSetAttributes* data : { static_cast<vtkDataSetAttributes*>(mesh->GetCellData()),
                                      static_cast<vtkDataSetAttributes*>(mesh->GetPointData()) })
  {
    const bool cells = data == mesh->GetCellData();
    if (!(more & (cells ? 1 : 2)))
    {
      continue;
    }
    const vtkIdType count = cells ? mesh->GetNumberOfCells() : mesh->GetNumberOfPoints();
    vtkNew<vtkUnsignedCharArray> ghosts;
    ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
    ghosts->SetNumberOfValues(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      ghosts->SetValue(i, in.Byte());
    }
    data->AddArray(ghosts);
  }
}

/// Arrays to carry (options & 64: a 2-component point array and cell ids) and a stale
/// original-ids array to replace (options & 128).
void AddExtraArrays(vtkPolyData* mesh, uint8_t options)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  const vtkIdType numCells = mesh->GetNumberOfCells();
  if (options & 64)
  {
    vtkNew<vtkFloatArray> extra;
    extra->SetName("Extra");
    extra->SetNumberOfComponents(2);
    extra->SetNumberOfTuples(numPoints);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      extra->SetTuple2(i, static_cast<double>(i), -static_cast<double>(i));
    }
    mesh->GetPointData()->AddArray(extra);
    vtkNew<vtkIdTypeArray> cellIds;
    cellIds->SetName("CellId");
    cellIds->SetNumberOfValues(numCells);
    for (vtkIdType c = 0; c < numCells; ++c)
    {
      cellIds->SetValue(c, c);
    }
    mesh->GetCellData()->AddArray(cellIds);
  }
  if (options & 128)
  {
    vtkNew<vtkIdTypeArray> stale;
    stale->SetName("vtkOriginalPointIds");
    stale->SetNumberOfValues(numPoints);
    stale->FillValue(-7);
    mesh->GetPointData()->AddArray(stale);
  }
}

/// The mesh and the settings the bytes describe, read in this order.
vtkSmartPointer<vtkPolyData> Build(ByteReader& in, Settings& settings)
{
  uint8_t options = 0, more = 0;
  const double scale = ReadSettings(in, settings, options, more);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(ReadPoints(in, (options & 16) != 0, scale));
  ReadAllCells(in, mesh);
  AddColors(in, mesh, more, settings);
  AddGhosts(in, mesh, more);
  AddExtraArrays(mesh, options);
  ReadControls(in, mesh, settings);
  return mesh;
}

/// The filter with the settings, on `mesh` (with the collapse record when `record`); the
/// invariants are checked (RunFilter).
colordecimation::testing::RunResult Decimate(vtkPolyData* mesh, const Settings& settings,
                                             bool record = false)
{
  return colordecimation::testing::RunFilter(
    mesh, settings.TargetReduction,
    [&settings, record](vtkColorHalfEdgeDecimation* filter)
    {
      filter->SetGenerateCollapseRecord(record);
      filter->SetErrorMetric(settings.Metric);
      filter->SetColorSpace(settings.ColorSpace);
      filter->SetOptimalPlacement(settings.OptimalPlacement);
      filter->SetCollapseSchedule(settings.Schedule);
      filter->SetColorWeight(settings.ColorWeight);
      filter->SetPreserveBoundary(settings.PreserveBoundary);
      filter->SetGenerateOriginalPointIds(settings.GenerateIds);
      filter->SetMaximumNormalAngle(settings.NormalAngle);
      filter->SetGeometryWeight(settings.GeometryWeight);
      filter->SetMaximumError(settings.MaximumError);
      filter->SetTargetNumberOfTriangles(settings.TargetTriangles);
      filter->SetPruneComponents(settings.Prune);
      filter->SetConsistentOrientation(settings.ConsistentOrientation);
      if (settings.LockName)
      {
        filter->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                       settings.LockName);
      }
      if (settings.ColorByName)
      {
        filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS,
                                       "Color");
      }
    });
}

/**
 * The whole record of a run is the run's own output: its last level, extracted from the record,
 * has the same triangles on the same points (not when pieces were pruned, which the record
 * does not hold, nor with ConsistentOrientation, whose winding the levels do not take).
 */
void CheckLastLevel(vtkPolyData* mesh, const Settings& settings,
                    const colordecimation::testing::RunResult& run,
                    std::vector<std::string>& broken)
{
  if (settings.OptimalPlacement || settings.Prune || settings.ConsistentOrientation ||
      run.Errors > 0 || run.Output->GetNumberOfCells() == 0)
  {
    return;
  }
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  lod->SetInputData(mesh);
  lod->SetRecordData(run.Filter->GetCollapseRecord());
  lod->SetTargetReduction(1.0);
  lod->SetGenerateOriginalPointIds(settings.GenerateIds);
  colordecimation::testing::EventRecorder messages;
  messages.Watch(lod);
  lod->Update();
  if (messages.Errors > 0)
  {
    broken.push_back("the level of the run's record failed: " + messages.ErrorText());
  }
  else if (colordecimation::testing::GetTriangles(lod->GetOutput()) !=
             colordecimation::testing::GetTriangles(run.Output) ||
           lod->GetOutput()->GetNumberOfPoints() != run.Output->GetNumberOfPoints())
  {
    broken.push_back("the last level of the record is not the run's output");
  }
}

} // namespace

void Initialize()
{
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

std::vector<std::string> RunOne(const uint8_t* data, size_t size)
{
  ByteReader in(data, size);
  Settings settings;
  vtkSmartPointer<vtkPolyData> mesh = Build(in, settings);

  const auto first = Decimate(mesh, settings);
  std::vector<std::string> broken = first.Broken;

  // The same input and settings must give the same output, with the collapse record on too.
  const auto second = Decimate(mesh, settings, !settings.OptimalPlacement);
  const auto a = colordecimation::testing::GetTriangles(first.Output);
  const auto b = colordecimation::testing::GetTriangles(second.Output);
  if (a != b || first.Collapses != second.Collapses || first.Errors != second.Errors ||
      first.Output->GetNumberOfPoints() != second.Output->GetNumberOfPoints())
  {
    broken.push_back("two runs on the same input differ");
  }
  // The second run's own broken invariants (its record's path), those the first did not have.
  for (const std::string& why : second.Broken)
  {
    if (std::find(first.Broken.begin(), first.Broken.end(), why) == first.Broken.end())
    {
      broken.push_back("second run: " + why);
    }
  }
  CheckLastLevel(mesh, settings, second, broken);
  return broken;
}

} // namespace fuzz
} // namespace colordecimation
