#include "Adapter/OutputMesh.h"

#include "Adapter/InputMesh.h"
#include "Adapter/LargeArrays.h"
#include "Core/Decimator.h"
#include "Core/util/Buffer.h"
#include "Core/util/Parallel.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSetGet.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace colordecimation
{
namespace adapter
{
namespace
{
/// The decimator's surviving faces, each wound as its input triangle or (consistent) as the
/// decimation wound its piece.
struct DecimatedFaces
{
  const Decimator& Result;
  bool Consistent;
  int32_t Count() const { return this->Result.GetMesh().GetNumberOfFaceSlots(); }
  bool Get(int32_t f, int32_t tri[3]) const
  {
    const HalfEdgeMesh& mesh = this->Result.GetMesh();
    if (!mesh.IsFaceAlive(f))
    {
      return false;
    }
    mesh.GetFace(f, tri);
    if (!this->Consistent && this->Result.IsFlipped(f))
    {
      std::swap(tri[1], tri[2]); // back to the input triangle's winding
    }
    return true;
  }
};

/// The faces of a level of detail: each input triangle on its points' survivors (Where), kept
/// if they are three different points (none -1: gone with a removed piece).
struct LevelFaces
{
  const int32_t* Triangles;
  int32_t NumberOfTriangles;
  const int32_t* Where;
  int32_t Count() const { return this->NumberOfTriangles; }
  bool Get(int32_t f, int32_t tri[3]) const
  {
    for (int k = 0; k < 3; ++k)
    {
      tri[k] = this->Where[this->Triangles[3 * size_t(f) + k]];
    }
    return tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0] && tri[0] >= 0 && tri[1] >= 0 &&
      tri[2] >= 0;
  }
};

/// Where each of the ranges of ParallelFor(count, threads) starts in the compacted output
/// (threads + 1 values: the last is the total), given each range's count.
std::vector<vtkIdType> RangeStarts(const std::vector<vtkIdType>& counts)
{
  std::vector<vtkIdType> starts(counts.size() + 1, 0);
  for (size_t t = 0; t < counts.size(); ++t)
  {
    starts[t + 1] = starts[t] + counts[t];
  }
  return starts;
}

/// The points the surviving triangles use: input id -> output id (-1 if unused), and back.
struct UsedPoints
{
  Buffer<vtkIdType> NewId;
  Buffer<vtkIdType> Source;               ///< output point i is input point Source[i]
  vtkIdType Points = 0;                   ///< the used points
  int FaceThreads = 1;                    ///< the ranges of faces, for WriteTriangles
  std::vector<vtkIdType> TrianglesBefore; ///< the surviving triangles before each range
  vtkIdType Triangles = 0;                ///< the surviving triangles
};

/// Each range of faces counts its surviving triangles and marks their points (a point marked
/// from several ranges gets the same value each time: relaxed atomic stores).
template <typename Faces>
std::unique_ptr<std::atomic<uint8_t>[]> MarkUsedPoints(const Faces& faces, vtkIdType numPoints,
                                                       int threads, UsedPoints& used)
{
  std::unique_ptr<std::atomic<uint8_t>[]> marks(new std::atomic<uint8_t>[numPoints]());
  std::atomic<uint8_t>* mark = marks.get();
  used.FaceThreads = ThreadsFor(static_cast<size_t>(faces.Count()), threads, 65536);
  std::vector<vtkIdType> counts(static_cast<size_t>(used.FaceThreads), 0);
  vtkIdType* count = counts.data();
  ParallelFor(static_cast<size_t>(faces.Count()), used.FaceThreads,
              [faces, mark, count](size_t begin, size_t end, int t)
              {
                vtkIdType alive = 0;
                for (size_t f = begin; f < end; ++f)
                {
                  int32_t tri[3];
                  if (faces.Get(static_cast<int32_t>(f), tri))
                  {
                    ++alive;
                    for (const int32_t v : tri)
                    {
                      mark[v].store(1, std::memory_order_relaxed);
                    }
                  }
                }
                count[t] = alive;
              });
  used.TrianglesBefore = RangeStarts(counts);
  used.Triangles = used.TrianglesBefore.back();
  return marks;
}

/// The marked points numbered in input order, on `threads` threads.
template <typename Faces>
void FindUsedPoints(const Faces& faces, vtkIdType numPoints, int threads, UsedPoints& used)
{
  const std::unique_ptr<std::atomic<uint8_t>[]> marks =
    MarkUsedPoints(faces, numPoints, threads, used);
  const std::atomic<uint8_t>* mark = marks.get();
  const int pointThreads = ThreadsFor(static_cast<size_t>(numPoints), threads, 65536);
  std::vector<vtkIdType> counts(static_cast<size_t>(pointThreads), 0);
  vtkIdType* count = counts.data();
  ParallelFor(static_cast<size_t>(numPoints), pointThreads,
              [mark, count](size_t begin, size_t end, int t)
              {
                vtkIdType marked = 0;
                for (size_t i = begin; i < end; ++i)
                {
                  marked += mark[i].load(std::memory_order_relaxed);
                }
                count[t] = marked;
              });
  const std::vector<vtkIdType> starts = RangeStarts(counts);
  used.Points = starts.back();
  used.NewId.resize(static_cast<size_t>(numPoints));
  used.Source.resize(static_cast<size_t>(used.Points));
  vtkIdType* newId = used.NewId.data();
  vtkIdType* source = used.Source.data();
  const vtkIdType* start = starts.data();
  ParallelFor(static_cast<size_t>(numPoints), pointThreads,
              [mark, start, newId, source](size_t begin, size_t end, int t)
              {
                vtkIdType next = start[t];
                for (size_t i = begin; i < end; ++i)
                {
                  newId[i] = -1;
                  if (mark[i].load(std::memory_order_relaxed))
                  {
                    newId[i] = next;
                    source[next] = static_cast<vtkIdType>(i);
                    ++next;
                  }
                }
              });
}

/// The ids as a vtkIdList.
vtkSmartPointer<vtkIdList> IdList(const vtkIdType* ids, vtkIdType count)
{
  auto list = vtkSmartPointer<vtkIdList>::New();
  list->SetNumberOfIds(count);
  RequireIds(list, count);
  std::copy(ids, ids + count, list->GetPointer(0));
  return list;
}

/// What describes `in` besides its values, given to `out`: name, component names, information
/// and lookup table.
void CopyDescription(vtkAbstractArray* in, vtkAbstractArray* out)
{
  out->SetName(in->GetName());
  out->CopyComponentNames(in);
  if (in->HasInformation())
  {
    out->CopyInformation(in->GetInformation(), 1);
  }
  vtkDataArray* data = vtkDataArray::SafeDownCast(in);
  vtkDataArray* outData = vtkDataArray::SafeDownCast(out);
  if (data && outData)
  {
    outData->SetLookupTable(data->GetLookupTable());
  }
}

/**
 * The tuples source[0], source[1], ... of `in`, bit for bit, in a new array of its class, with
 * its description (CopyDescription). Contiguous arrays are copied on `threads` threads (into
 * huge pages when large); the others by VTK, tuple by tuple when not data arrays.
 */
vtkSmartPointer<vtkAbstractArray> Gather(vtkAbstractArray* in, const vtkIdType* source,
                                         vtkIdType count, int threads)
{
  auto out = vtkSmartPointer<vtkAbstractArray>::Take(in->NewInstance());
  out->SetNumberOfComponents(in->GetNumberOfComponents());
  CopyDescription(in, out);
  vtkDataArray* data = vtkDataArray::SafeDownCast(in);
  const size_t valueBytes = static_cast<size_t>(in->GetDataTypeSize());
  const size_t tupleBytes = static_cast<size_t>(in->GetNumberOfComponents()) * valueBytes;
  // `out` is of the class of `in`: contiguous too when `in` is.
  void* memory = data && IsContiguous(in) && valueBytes > 0
    ? AdoptFreeable(out, count * in->GetNumberOfComponents(), valueBytes)
    : nullptr;
  if (!memory)
  {
    out->SetNumberOfTuples(count);
    RequireValues(out, count * in->GetNumberOfComponents());
    if (data)
    {
      in->GetTuples(IdList(source, count), out);
      return out;
    }
    // Strings, variants: tuple by tuple (vtkStringArray::GetTuples takes tuple ids for value
    // ids, which scrambles arrays of more than one component).
    for (vtkIdType i = 0; i < count; ++i)
    {
      out->SetTuple(i, source[i], in);
    }
    return out;
  }
  const char* from = static_cast<const char*>(data->GetVoidPointer(0));
  char* to = static_cast<char*>(memory);
  ParallelFor(static_cast<size_t>(count), ThreadsFor(static_cast<size_t>(count), threads, 65536),
              [from, to, source, tupleBytes](size_t begin, size_t end, int)
              {
                for (size_t i = begin; i < end; ++i)
                {
                  std::memcpy(to + i * tupleBytes,
                              from + static_cast<size_t>(source[i]) * tupleBytes, tupleBytes);
                }
              });
  return out;
}

/// Every array of `in` gathered at `source` (Gather), with its attribute roles but, unless
/// keepGlobalIds, the global ids' (then an ordinary array).
void GatherArrays(vtkDataSetAttributes* in, const vtkIdType* source, vtkIdType count, int threads,
                  bool keepGlobalIds, vtkDataSetAttributes* out)
{
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = in->GetAbstractArray(a);
    const int index = out->AddArray(Gather(array, source, count, threads));
    for (int role = 0; role < vtkDataSetAttributes::NUM_ATTRIBUTES; ++role)
    {
      if (in->GetAbstractAttribute(role) == array &&
          (keepGlobalIds || role != vtkDataSetAttributes::GLOBALIDS))
      {
        out->SetActiveAttribute(index, role);
      }
    }
  }
}

/// The used points, copied from the input (in its own type), moved ones (with a decimator) at
/// their new place.
void WritePoints(vtkPolyData* input, const Decimator* decimator, const UsedPoints& used,
                 int threads, vtkPolyData* output)
{
  vtkNew<vtkPoints> outPoints;
  vtkDataArray* in = input->GetPoints()->GetData();
  if (IsContiguous(in))
  {
    outPoints->SetData(
      vtkDataArray::SafeDownCast(Gather(in, used.Source.data(), used.Points, threads)));
  }
  else
  {
    // Another layout (mapped, SOA): into a plain array of its type, as vtkPoints makes one,
    // described as the input's.
    outPoints->SetDataType(in->GetDataType());
    vtkDataArray* out = outPoints->GetData();
    out->SetNumberOfComponents(3);
    if (!AdoptFreeable(out, 3 * used.Points, static_cast<size_t>(out->GetDataTypeSize())))
    {
      out->SetNumberOfTuples(0);
    }
    in->GetTuples(IdList(used.Source.data(), used.Points), out);
    CopyDescription(in, out);
  }
  if (decimator && decimator->HasMovedVertices())
  {
    // Full collapses (ColorQuadric with OptimalPlacement) moved some surviving vertices.
    for (vtkIdType i = 0; i < used.Points; ++i)
    {
      const auto source = static_cast<int32_t>(used.Source[static_cast<size_t>(i)]);
      if (decimator->IsMoved(source))
      {
        double p[3];
        decimator->GetOutputPosition(source, p);
        outPoints->SetPoint(i, p);
      }
    }
  }
  output->SetPoints(outPoints);
}

/// The surviving triangles, in input order, and the input cell of each (sourceCells, when not
/// null, sized to them): each range of faces of FindUsedPoints writes its own, where its
/// triangles start.
template <typename Faces>
void WriteTriangles(const Faces& faces, const TriangleSoup& soup, const UsedPoints& used,
                    vtkIdType* sourceCells, vtkPolyData* output)
{
  vtkNew<vtkIdTypeArray> connectivity;
  vtkNew<vtkIdTypeArray> offsets;
  AllocateValues(connectivity.Get(), 3 * used.Triangles);
  AllocateValues(offsets.Get(), used.Triangles + 1);
  vtkIdType* points = connectivity->GetPointer(0);
  vtkIdType* offset = offsets->GetPointer(0);
  vtkIdType* source = sourceCells;
  const vtkIdType* newId = used.NewId.data();
  const vtkIdType* before = used.TrianglesBefore.data();
  const vtkIdType* cell = soup.SourceCell.empty() ? nullptr : soup.SourceCell.data();
  const vtkIdType firstCell = soup.FirstCell;
  ParallelFor(
    static_cast<size_t>(faces.Count()), used.FaceThreads,
    [faces, points, offset, source, newId, before, cell, firstCell](size_t begin, size_t end, int t)
    {
      vtkIdType next = before[t];
      for (size_t f = begin; f < end; ++f)
      {
        int32_t tri[3];
        if (faces.Get(static_cast<int32_t>(f), tri))
        {
          offset[next] = 3 * next;
          for (int k = 0; k < 3; ++k)
          {
            points[3 * next + k] = newId[tri[k]];
          }
          if (source)
          {
            source[next] = cell ? cell[f] : firstCell + static_cast<vtkIdType>(f);
          }
          ++next;
        }
      }
    });
  offset[used.Triangles] = 3 * used.Triangles;
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);
}

/// The moved vertices' new colours, in the colour array's own type and range (the other arrays
/// keep the surviving input vertex's values).
void WriteMovedColors(const InputMesh& mesh, const Decimator& decimator, const UsedPoints& used,
                      vtkPointData* outPD)
{
  vtkDataArray* colorArray = mesh.ColorArray;
  vtkDataArray* outColors = colorArray->GetName() && *colorArray->GetName()
    ? outPD->GetArray(colorArray->GetName())
    : outPD->GetScalars();
  if (!outColors || outColors->GetNumberOfComponents() != colorArray->GetNumberOfComponents())
  {
    return;
  }
  for (vtkIdType i = 0; i < used.Points; ++i)
  {
    const auto source = static_cast<int32_t>(used.Source[static_cast<size_t>(i)]);
    if (decimator.IsMoved(source))
    {
      double c[3];
      decimator.GetOutputColor(source, c);
      WriteColor(outColors, i, c, mesh.ColorMapping);
    }
  }
}

bool IsIntegerType(int type)
{
  switch (type)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_ID_TYPE:
      return true;
    default:
      return false;
  }
}

/**
 * The input's ids to compose with, when its array `name` is one: one integer component per
 * point, every value in [0, 2^53] (e.g. vtkOriginalPointIds from vtkDataSetSurfaceFilter). Null
 * when there is no such array; a warning (and null) when there is one of another kind.
 */
vtkDataArray* UpstreamIds(vtkObject* self, vtkPolyData* input, const char* name)
{
  vtkAbstractArray* given = input->GetPointData()->GetAbstractArray(name);
  if (!given)
  {
    return nullptr;
  }
  vtkDataArray* ids = vtkDataArray::SafeDownCast(given);
  bool valid = ids && IsIntegerType(ids->GetDataType()) && ids->GetNumberOfComponents() == 1 &&
    ids->GetNumberOfTuples() == input->GetNumberOfPoints();
  for (vtkIdType i = 0; valid && i < ids->GetNumberOfTuples(); ++i)
  {
    const double id = ids->GetComponent(i, 0);
    valid = id >= 0 && id <= 9007199254740992.0; // 2^53: exact as a double, and a vtkIdType
  }
  if (!valid)
  {
    vtkWarningWithObjectMacro(self, << "The input already has a point array named '" << name
                                    << "' that does not hold one id >= 0 per point: it is "
                                       "replaced by this filter's.");
    return nullptr;
  }
  vtkDebugWithObjectMacro(self, << "The input's '" << name
                                << "' ids are composed with this "
                                   "filter's.");
  return ids;
}

/// Each output point's id in the input, as a vtkIdTypeArray named `name`, composed with the
/// input's ids of that name when it has them (see UpstreamIds).
void WriteOriginalIds(vtkObject* self, vtkPolyData* input, const char* name, const UsedPoints& used,
                      int threads, vtkPointData* outPD)
{
  vtkDataArray* upstream = UpstreamIds(self, input, name);
  vtkIdTypeArray* upstreamIds = vtkIdTypeArray::SafeDownCast(upstream);
  outPD->RemoveArray(name);
  const vtkIdType numOutPoints = used.Points;
  vtkNew<vtkIdTypeArray> original;
  original->SetName(name);
  AllocateValues(original.Get(), numOutPoints);
  vtkIdType* out = original->GetPointer(0);
  const vtkIdType* source = used.Source.data();
  if (upstream && !upstreamIds)
  {
    for (vtkIdType i = 0; i < numOutPoints; ++i) // any array type: one thread
    {
      out[i] = static_cast<vtkIdType>(upstream->GetComponent(source[i], 0));
    }
  }
  else
  {
    const vtkIdType* ids = upstreamIds ? upstreamIds->GetPointer(0) : nullptr;
    ParallelFor(static_cast<size_t>(numOutPoints),
                ThreadsFor(static_cast<size_t>(numOutPoints), threads, 65536),
                [out, source, ids](size_t begin, size_t end, int)
                {
                  for (size_t i = begin; i < end; ++i)
                  {
                    out[i] = ids ? ids[source[i]] : source[i];
                  }
                });
  }
  outPD->AddArray(original);
}

/**
 * The arrays of `data` that have `tuples` tuples, in `consistent` (a shallow copy that keeps
 * the attribute roles); the names of the others, which cannot be carried, in `dropped`.
 */
void KeepConsistentArrays(vtkDataSetAttributes* data, vtkIdType tuples,
                          vtkDataSetAttributes* consistent, std::string& dropped)
{
  consistent->ShallowCopy(data);
  for (int a = consistent->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    vtkAbstractArray* array = consistent->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() != tuples)
    {
      dropped += std::string(dropped.empty() ? "" : ", ") + "'" +
        (array->GetName() ? array->GetName() : "(unnamed)") + "' (" +
        std::to_string(array->GetNumberOfTuples()) + " tuples)";
      consistent->RemoveArray(a);
    }
  }
}

/// The input's point and cell data that can be carried (arrays whose tuple count does not
/// match their points or cells cannot: a warning names them).
void KeepCarriedArrays(vtkObject* self, vtkPolyData* input, vtkPointData* inPD, vtkCellData* inCD)
{
  std::string droppedPointArrays, droppedCellArrays;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  KeepConsistentArrays(input->GetPointData(), numPoints, inPD, droppedPointArrays);
  KeepConsistentArrays(input->GetCellData(), input->GetNumberOfCells(), inCD, droppedCellArrays);
  if (!droppedPointArrays.empty() || !droppedCellArrays.empty())
  {
    vtkWarningWithObjectMacro(
      self, << "Arrays whose size does not match the mesh are left out of the output: "
            << (droppedPointArrays.empty() ? "" : "point data ") << droppedPointArrays
            << (droppedCellArrays.empty() ? "" : " cell data ") << droppedCellArrays << " ("
            << numPoints << " points, " << input->GetNumberOfCells() << " cells).");
  }
}

/// Every data array of `output` marked modified once its values are final: the range caches
/// its information may hold from the input (CopyInformation keeps the finite magnitude range)
/// are then dropped, so that ranges are the output's own.
void MarkArraysModified(vtkPolyData* output)
{
  if (output->GetPoints())
  {
    output->GetPoints()->GetData()->Modified();
  }
  for (vtkDataSetAttributes* data : { static_cast<vtkDataSetAttributes*>(output->GetPointData()),
                                      static_cast<vtkDataSetAttributes*>(output->GetCellData()) })
  {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      data->GetAbstractArray(a)->Modified();
    }
  }
}

/**
 * The output of `faces` (DecimatedFaces or LevelFaces): points, triangles, point data (moved
 * points with their new colour, with a decimator), the original ids, cell data.
 */
template <typename Faces>
vtkIdType Write(vtkObject* self, vtkPolyData* input, const InputMesh& mesh, const Faces& faces,
                const Decimator* decimator, const char* originalIdsName, int threads,
                vtkPolyData* output)
{
  vtkNew<vtkPointData> inPD;
  vtkNew<vtkCellData> inCD;
  KeepCarriedArrays(self, input, inPD, inCD);
  UsedPoints used;
  FindUsedPoints(faces, input->GetNumberOfPoints(), threads, used);
  WritePoints(input, decimator, used, threads, output);
  // Each output triangle's input cell, when there is cell data to copy.
  const bool cellData = inCD->GetNumberOfArrays() > 0;
  Buffer<vtkIdType> sourceCells(cellData ? static_cast<size_t>(used.Triangles) : 0); // unwritten
  WriteTriangles(faces, mesh.Soup, used, cellData ? sourceCells.data() : nullptr, output);
  vtkPointData* outPD = output->GetPointData();
  GatherArrays(inPD, used.Source.data(), used.Points, threads, true, outPD);
  if (decimator && decimator->HasMovedVertices() && mesh.ColorArray)
  {
    WriteMovedColors(mesh, *decimator, used, outPD);
  }
  if (originalIdsName && *originalIdsName)
  {
    WriteOriginalIds(self, input, originalIdsName, used, threads, outPD);
  }
  if (cellData)
  {
    // Global cell ids stay global ids when each output triangle is one input cell (they stay
    // unique), not when a polygon's or a strip's triangles share theirs.
    GatherArrays(inCD, sourceCells.data(), used.Triangles, threads,
                 mesh.Soup.Polygons == 0 && mesh.Soup.Strips == 0, output->GetCellData());
  }
  MarkArraysModified(output);
  return used.Triangles;
}

} // namespace

vtkIdType WriteOutput(vtkObject* self, vtkPolyData* input, const InputMesh& mesh,
                      const Decimator& decimator, const OutputOptions& options, vtkPolyData* output)
{
  const DecimatedFaces faces{ decimator, options.ConsistentOrientation };
  return Write(self, input, mesh, faces, &decimator, options.OriginalIdsName, options.Threads,
               output);
}

void EmptyOutput(vtkDataObject* input, vtkDataObject* output) noexcept
{
  output->Initialize();
  try
  {
    output->GetFieldData()->PassData(input->GetFieldData());
  }
  catch (const std::exception&)
  {
    // Still short of memory: the field data are left out too.
  }
}

const char* OriginalIdsName(vtkObject* self, bool generate, const char* name)
{
  if (!generate)
  {
    return nullptr;
  }
  if (!name || !*name)
  {
    vtkWarningWithObjectMacro(self, << "GenerateOriginalPointIds is on but "
                                       "OriginalPointIdsArrayName is empty: the ids are written "
                                       "as 'vtkOriginalPointIds'.");
    return "vtkOriginalPointIds";
  }
  return name;
}

vtkIdType WriteLevel(vtkObject* self, vtkPolyData* input, const InputMesh& mesh,
                     const std::vector<int32_t>& where, const char* originalIdsName, int threads,
                     vtkPolyData* output)
{
  const LevelFaces faces{ mesh.Soup.Triangles.data(), static_cast<int32_t>(mesh.Soup.Count()),
                          where.data() };
  return Write(self, input, mesh, faces, nullptr, originalIdsName, threads, output);
}

} // namespace adapter
} // namespace colordecimation
