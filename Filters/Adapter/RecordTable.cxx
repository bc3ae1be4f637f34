#include "Adapter/RecordTable.h"

#include "Adapter/InputMesh.h"
#include "Adapter/LargeArrays.h"
#include "Core/util/Parallel.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

namespace colordecimation
{
namespace adapter
{
namespace
{
const char* const RemovedColumn = "RemovedPointId";
const char* const SurvivorColumn = "SurvivingPointId";
const char* const CostColumn = "Cost";
const char* const ErrorColumn = "Error";
const char* const TrianglesColumn = "NumberOfTriangles";
const char* const PointsField = "InputNumberOfPoints";
const char* const TrianglesField = "InputNumberOfTriangles";
const char* const ChecksumField = "InputChecksum";
/// How the checksum is computed: 2 since the hash went by blocks (absent: 1, one chain).
const char* const ChecksumVersionField = "InputChecksumVersion";
constexpr vtkIdType ChecksumVersion = 2;
const char* const ScheduleField = "CollapseSchedule";

/// Every bit of a word spread over all 64 (splitmix64's finaliser).
uint64_t Mix(uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// Words in a block of HashWords: the blocks are hashed in parallel, then chained in order.
constexpr size_t HashBlockWords = size_t(1) << 16;
constexpr uint64_t HashOffset = 0x9e3779b97f4a7c15ULL;

/// The hash of one block of `words` words: four interleaved lanes (independent chains, whose
/// multiplications overlap), each word mixed fully before it is combined, so that no change
/// of the input (a sign flipped twice included) cancels out.
uint64_t HashBlock(const unsigned char* p, size_t words, uint64_t seed)
{
  uint64_t lane[4] = { Mix(seed), Mix(seed + 1), Mix(seed + 2), Mix(seed + 3) };
  for (size_t i = 0; i < words; ++i)
  {
    uint64_t word;
    std::memcpy(&word, p + 8 * i, 8);
    lane[i % 4] = Mix(lane[i % 4] ^ Mix(word + HashOffset));
  }
  return Mix(lane[0] ^ Mix(lane[1] ^ Mix(lane[2] ^ Mix(lane[3]))));
}

/// A 64-bit hash of `bytes` bytes: its blocks hashed on `threads` threads and chained in
/// order, then the bytes after the last whole word; the same for any number of threads.
uint64_t HashWords(const void* data, size_t bytes, uint64_t h, int threads)
{
  const auto* p = static_cast<const unsigned char*>(data);
  const size_t words = bytes / 8;
  const size_t blocks = (words + HashBlockWords - 1) / HashBlockWords;
  std::vector<uint64_t> hashes(blocks);
  uint64_t* hash = hashes.data();
  ParallelFor(blocks, ThreadsFor(blocks, threads, 4),
              [p, words, hash](size_t begin, size_t end, int)
              {
                for (size_t b = begin; b < end; ++b)
                {
                  const size_t first = b * HashBlockWords;
                  hash[b] = HashBlock(p + 8 * first, std::min(HashBlockWords, words - first), b);
                }
              });
  for (const uint64_t blockHash : hashes)
  {
    h = Mix(h ^ blockHash);
  }
  for (size_t i = 8 * words; i < bytes; ++i)
  {
    h = Mix(h ^ (p[i] + HashOffset));
  }
  return h;
}

template <typename Array, typename T>
void AddColumn(vtkTable* table, const char* name, const Buffer<T>& values)
{
  vtkNew<Array> column;
  column->SetName(name);
  AllocateValues(column.Get(), static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), column->GetPointer(0));
  table->AddColumn(column);
}

void AddField(vtkFieldData* field, const char* name, vtkIdType value)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  AllocateValues(array.Get(), 1); // not by VTK: ParaView's aborts when it cannot allocate
  array->SetValue(0, value);
  field->AddArray(array);
}

void AddField(vtkFieldData* field, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value); // std::bad_alloc when it cannot allocate
  field->AddArray(array);
}

/// A column of `rows` single values, or null.
vtkDataArray* Column(vtkTable* table, const char* name, vtkIdType rows)
{
  vtkDataArray* column = vtkDataArray::SafeDownCast(table->GetColumnByName(name));
  return column && column->GetNumberOfComponents() == 1 && column->GetNumberOfTuples() == rows
    ? column
    : nullptr;
}

/// The column's values as doubles: read in place for the types the filter writes
/// (vtkIdType, double), converted for any other (e.g. a table read from another format).
template <typename Function>
void ForEachValue(vtkDataArray* column, Function&& f)
{
  const vtkIdType n = column->GetNumberOfTuples();
  if (auto* ids = vtkIdTypeArray::FastDownCast(column))
  {
    const vtkIdType* p = ids->GetPointer(0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      f(i, static_cast<double>(p[i]));
    }
  }
  else if (auto* doubles = vtkDoubleArray::FastDownCast(column))
  {
    const double* p = doubles->GetPointer(0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      f(i, p[i]);
    }
  }
  else
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      f(i, column->GetComponent(i, 0));
    }
  }
}

/// Whether the column holds single-precision floats (exact integers only up to 2^24).
bool IsSinglePrecision(vtkDataArray* column)
{
  return column->GetDataType() == VTK_FLOAT;
}

/// Integer ids from a column; false if one is not an integer that fits.
bool ReadIds(vtkDataArray* column, Buffer<int32_t>& ids)
{
  ids.resize(static_cast<size_t>(column->GetNumberOfTuples()));
  bool valid = true;
  ForEachValue(column,
               [&ids, &valid](vtkIdType i, double v)
               {
                 valid = valid && v >= -1.0 && v <= 2147483647.0 && v == std::floor(v);
                 ids[i] = valid ? static_cast<int32_t>(v) : -1;
               });
  return valid;
}

/// Values from a column, each of which must pass `valid` (checked before any conversion);
/// false if one does not.
template <typename T, typename Valid>
bool ReadValues(vtkDataArray* column, Buffer<T>& values, Valid&& valid)
{
  values.resize(static_cast<size_t>(column->GetNumberOfTuples()));
  bool all = true;
  ForEachValue(column,
               [&values, &valid, &all](vtkIdType i, double v)
               {
                 all = all && valid(v);
                 values[i] = all ? static_cast<T>(v) : T(0);
               });
  return all;
}

/// A count: finite, whole, from 0 to 2^53 (exact as a double).
bool IsCount(double v)
{
  return v >= 0.0 && v <= 9007199254740992.0 && v == std::floor(v);
}

/// The identity kept in the table's field data; false if it is not there.
bool ReadIdentity(vtkTable* table, MeshIdentity& identity)
{
  vtkFieldData* field = table->GetFieldData();
  auto* points = vtkDataArray::SafeDownCast(field->GetAbstractArray(PointsField));
  auto* triangles = vtkDataArray::SafeDownCast(field->GetAbstractArray(TrianglesField));
  auto* checksum = vtkStringArray::SafeDownCast(field->GetAbstractArray(ChecksumField));
  if (!points || !triangles || !checksum || points->GetNumberOfTuples() != 1 ||
      triangles->GetNumberOfTuples() != 1 || checksum->GetNumberOfValues() != 1)
  {
    return false;
  }
  const double numPoints = points->GetComponent(0, 0), numTriangles = triangles->GetComponent(0, 0);
  if (!IsCount(numPoints) || !IsCount(numTriangles))
  {
    return false;
  }
  identity.Points = static_cast<vtkIdType>(numPoints);
  identity.Triangles = static_cast<vtkIdType>(numTriangles);
  identity.Checksum = checksum->GetValue(0);
  auto* version = vtkDataArray::SafeDownCast(field->GetAbstractArray(ChecksumVersionField));
  const double number = version && version->GetNumberOfTuples() == 1
    ? version->GetComponent(0, 0)
    : 1.0; // absent: the first version
  identity.ChecksumVersion = IsCount(number) ? static_cast<vtkIdType>(number) : -1;
  return true;
}

/// The columns into `record`; false (and why) if one is missing or malformed.
bool ReadColumns(vtkTable* table, CollapseRecord& record, std::string& why)
{
  const vtkIdType rows = table->GetNumberOfRows();
  vtkDataArray* removed = Column(table, RemovedColumn, rows);
  vtkDataArray* survivor = Column(table, SurvivorColumn, rows);
  vtkDataArray* cost = Column(table, CostColumn, rows);
  vtkDataArray* error = Column(table, ErrorColumn, rows);
  vtkDataArray* triangles = Column(table, TrianglesColumn, rows);
  if (!removed || !survivor || !cost || !error || !triangles)
  {
    why = std::string("it lacks one of the columns ") + RemovedColumn + ", " + SurvivorColumn +
      ", " + CostColumn + ", " + ErrorColumn + ", " + TrianglesColumn +
      " (numeric, one component, one value per row)";
    return false;
  }
  if (IsSinglePrecision(removed) || IsSinglePrecision(survivor) || IsSinglePrecision(triangles))
  {
    why = "its point ids or triangle counts are single-precision floats, which cannot hold every "
          "id above 2^24 (integers or doubles are needed)";
    return false;
  }
  if (!ReadIds(removed, record.Removed) || !ReadIds(survivor, record.Survivor))
  {
    why = "its point ids are not all whole numbers from -1 to 2^31 - 1";
    return false;
  }
  // The costs are the schedule's, kept for the user (the levels do not read them): any value.
  if (!ReadValues(cost, record.Cost, [](double) { return true; }) ||
      !ReadValues(error, record.Error, [](double v) { return v >= 0.0 && std::isfinite(v); }) ||
      !ReadValues(triangles, record.Triangles, IsCount))
  {
    why = "its errors or triangle counts are not all finite (errors >= 0, counts whole and >= 0)";
    return false;
  }
  return true;
}
} // namespace

MeshIdentity Identify(const InputMesh& mesh, int threads)
{
  MeshIdentity identity;
  identity.Points = static_cast<vtkIdType>(mesh.Points.size() / 3);
  identity.Triangles = mesh.Soup.Count();
  uint64_t h = 0xcbf29ce484222325ULL;
  h = HashWords(mesh.Points.data(), mesh.Points.size() * sizeof(double), h, threads);
  h =
    HashWords(mesh.Soup.Triangles.data(), mesh.Soup.Triangles.size() * sizeof(int32_t), h, threads);
  h = Mix(h ^ static_cast<uint64_t>(identity.Points));
  std::ostringstream hex;
  hex << std::hex;
  hex.width(16);
  hex.fill('0');
  hex << h;
  identity.Checksum = hex.str();
  return identity;
}

void WriteRecordTable(const CollapseRecord& record, const MeshIdentity& mesh, const char* schedule,
                      vtkTable* table)
{
  table->Initialize();
  AddColumn<vtkIdTypeArray>(table, RemovedColumn, record.Removed);
  AddColumn<vtkIdTypeArray>(table, SurvivorColumn, record.Survivor);
  AddColumn<vtkDoubleArray>(table, CostColumn, record.Cost);
  AddColumn<vtkDoubleArray>(table, ErrorColumn, record.Error);
  AddColumn<vtkIdTypeArray>(table, TrianglesColumn, record.Triangles);
  vtkFieldData* field = table->GetFieldData();
  AddField(field, PointsField, mesh.Points);
  AddField(field, TrianglesField, mesh.Triangles);
  AddField(field, ChecksumField, mesh.Checksum);
  AddField(field, ChecksumVersionField, ChecksumVersion);
  AddField(field, ScheduleField, std::string(schedule));
}

bool ReadRecordTable(vtkTable* table, const MeshIdentity& mesh, CollapseRecord& record,
                     std::string& why)
{
  record.Clear();
  MeshIdentity recorded;
  if (!table || !ReadIdentity(table, recorded))
  {
    why = std::string("it is not a collapse record (no ") + PointsField + ", " + TrianglesField +
      " and " + ChecksumField +
      " in its field data: make it with the decimation's GenerateCollapseRecord on, "
      "color-decimate's --save-record)";
    return false;
  }
  if (recorded.Points == mesh.Points && recorded.Triangles == mesh.Triangles &&
      recorded.ChecksumVersion != ChecksumVersion)
  {
    why = "it was saved by another version of this module, whose checksum of the mesh is "
          "computed otherwise (" +
      std::string(ChecksumVersionField) + " " + std::to_string(recorded.ChecksumVersion) +
      ", now " + std::to_string(ChecksumVersion) + "): make the record again";
    return false;
  }
  if (recorded.Points != mesh.Points || recorded.Triangles != mesh.Triangles ||
      recorded.Checksum != mesh.Checksum)
  {
    why = "it belongs to another mesh (" + std::to_string(recorded.Points) + " points, " +
      std::to_string(recorded.Triangles) + " triangles, checksum " + recorded.Checksum +
      "; this input: " + std::to_string(mesh.Points) + ", " + std::to_string(mesh.Triangles) +
      ", " + mesh.Checksum + ")";
    return false;
  }
  if (!ReadColumns(table, record, why))
  {
    return false;
  }
  record.InputPoints = static_cast<int32_t>(mesh.Points);
  record.InputTriangles = mesh.Triangles;
  return IsConsistent(record, why);
}

} // namespace adapter
} // namespace colordecimation
