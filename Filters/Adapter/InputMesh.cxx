#include "Adapter/InputMesh.h"

#include "Core/util/Parallel.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSetGet.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleStrip.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace colordecimation
{
namespace adapter
{

void TriangleSoup::Add(const vtkIdType* ids, vtkIdType cell, vtkIdType numPoints)
{
  for (int k = 0; k < 3; ++k)
  {
    if (ids[k] < 0 || ids[k] >= numPoints)
    {
      this->IdsOutOfRange = true;
      return;
    }
  }
  if (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2])
  {
    ++this->Degenerate;
    return;
  }
  for (int k = 0; k < 3; ++k)
  {
    this->Triangles.push_back(static_cast<int32_t>(ids[k]));
  }
  this->SourceCell.push_back(cell);
}

DecimatorInput InputMesh::CoreInput()
{
  DecimatorInput in;
  in.NumberOfPoints = static_cast<int32_t>(this->Points.size() / 3);
  in.Points = this->Points.data();
  in.Colors = this->Colors.empty() ? nullptr : this->Colors.data();
  in.NumberOfTriangles = static_cast<int32_t>(this->Soup.Count());
  in.Triangles = this->Soup.Triangles.data();
  in.Fixed = this->Soup.HasFixed ? this->Soup.Fixed.data() : nullptr;
  in.ReleaseInput = [this]()
  {
    this->Points = Buffer<double>();
    this->Soup.Triangles = Buffer<int32_t>();
    this->Colors = Buffer<float>();
  };
  return in;
}

namespace
{
/// `ghosts` when it holds one value for each of `count` points or cells; otherwise null, and
/// the soup notes that it was ignored.
vtkUnsignedCharArray* CheckedGhosts(vtkUnsignedCharArray* ghosts, vtkIdType count,
                                    TriangleSoup& soup)
{
  if (ghosts && (ghosts->GetNumberOfComponents() != 1 || ghosts->GetNumberOfTuples() != count))
  {
    soup.IgnoredGhostArray = true;
    return nullptr;
  }
  return ghosts;
}

/// The input's cell ghost array, if it is usable (CheckedGhosts).
vtkUnsignedCharArray* CellGhosts(vtkPolyData* input, TriangleSoup& soup)
{
  return CheckedGhosts(input->GetCellGhostArray(), input->GetNumberOfCells(), soup);
}

/**
 * Ghost cells belong to a neighbouring piece (distributed data): they are left out, and the
 * points they share with this piece are fixed, as are ghost (duplicate) points, so that the
 * decimated pieces still meet without cracks.
 */
bool SkipGhostCell(vtkUnsignedCharArray* ghosts, vtkIdType cell, vtkIdType npts,
                   const vtkIdType* pts, vtkIdType numPoints, TriangleSoup& soup)
{
  if (!ghosts ||
      !(ghosts->GetValue(cell) &
        (vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL)))
  {
    return false;
  }
  ++soup.GhostCells;
  for (vtkIdType k = 0; k < npts; ++k)
  {
    if (pts[k] >= 0 && pts[k] < numPoints)
    {
      soup.Fixed[pts[k]] = 1;
      soup.HasFixed = true;
    }
  }
  return true;
}

/**
 * The common case in bulk: polygons that are all triangles, with ids in range and none
 * repeating a point, no strips and no ghost cells. Copies them on `threads` threads and returns
 * true; false (nothing added) for any other input, which takes the cell-by-cell way.
 */
template <typename Id>
bool CopyPlainTriangles(const Id* connectivity, vtkIdType numTriangles, vtkIdType numPoints,
                        vtkIdType firstCell, int threads, TriangleSoup& soup)
{
  const size_t nt = static_cast<size_t>(numTriangles);
  threads = ThreadsFor(nt, threads, 65536);
  const bool plain = ParallelAll(nt, threads,
                                 [connectivity, numPoints](size_t begin, size_t end)
                                 {
                                   bool ok = true;
                                   for (size_t f = begin; f < end; ++f)
                                   {
                                     const Id a = connectivity[3 * f], b = connectivity[3 * f + 1],
                                              c = connectivity[3 * f + 2];
                                     ok &= a >= 0 && a < numPoints && b >= 0 && b < numPoints &&
                                       c >= 0 && c < numPoints && a != b && b != c && a != c;
                                   }
                                   return ok;
                                 });
  if (!plain)
  {
    return false;
  }
  soup.Triangles.resize(3 * nt);
  soup.SourceCell = Buffer<vtkIdType>(); // triangle f is cell firstCell + f
  soup.FirstCell = firstCell;
  int32_t* triangles = soup.Triangles.data();
  ParallelFor(nt, threads,
              [connectivity, triangles](size_t begin, size_t end, int)
              {
                for (size_t i = 3 * begin; i < 3 * end; ++i)
                {
                  triangles[i] = static_cast<int32_t>(connectivity[i]);
                }
              });
  return true;
}

/// Ghost (duplicate) points are fixed.
void FixGhostPoints(vtkPolyData* input, TriangleSoup& soup)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkUnsignedCharArray* pointGhosts = CheckedGhosts(input->GetPointGhostArray(), numPoints, soup);
  if (!pointGhosts)
  {
    return;
  }
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    if (pointGhosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT)
    {
      soup.Fixed[i] = 1;
      soup.HasFixed = true;
      ++soup.GhostPoints;
    }
  }
}

/// The bulk path of CopyPlainTriangles, when the polygons are all triangles and there are no
/// strips nor (usable) ghost cells; false when it does not apply.
bool TryPlainTriangles(vtkPolyData* input, vtkIdType firstCell, int threads, TriangleSoup& soup)
{
  vtkCellArray* polyCells = input->GetPolys();
  if (CellGhosts(input, soup) || input->GetNumberOfStrips() != 0 ||
      polyCells->GetNumberOfCells() == 0 || polyCells->IsHomogeneous() != 3)
  {
    return false;
  }
  const vtkIdType nt = polyCells->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  // The ids in one 64- or 32-bit array; any other storage (newer VTK) goes cell by cell.
  auto* ids64 = polyCells->IsStorage64Bit() ? polyCells->GetConnectivityArray64() : nullptr;
  auto* ids32 = polyCells->IsStorage64Bit() ? nullptr : polyCells->GetConnectivityArray32();
  if (ids64)
  {
    return CopyPlainTriangles(ids64->GetPointer(0), nt, numPoints, firstCell, threads, soup);
  }
  return ids32 && CopyPlainTriangles(ids32->GetPointer(0), nt, numPoints, firstCell, threads, soup);
}

/// A polygon of more than 3 points, by ear cutting (a fan when ear cutting gives up).
void AddPolygon(vtkPolyData* input, vtkIdType cell, vtkIdType npts, const vtkIdType* pts,
                vtkPolygon* polygon, vtkIdList* local, TriangleSoup& soup)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  ++soup.Polygons;
  for (vtkIdType k = 0; k < npts; ++k)
  {
    if (pts[k] < 0 || pts[k] >= numPoints)
    {
      soup.IdsOutOfRange = true;
      return;
    }
  }
  polygon->Initialize(static_cast<int>(npts), pts, input->GetPoints());
  local->Reset();
  if (polygon->Triangulate(local) && local->GetNumberOfIds() == 3 * (npts - 2))
  {
    for (vtkIdType t = 0; t < local->GetNumberOfIds(); t += 3)
    {
      const vtkIdType ids[3] = { pts[local->GetId(t)], pts[local->GetId(t + 1)],
                                 pts[local->GetId(t + 2)] };
      soup.Add(ids, cell, numPoints);
    }
    return;
  }
  for (vtkIdType k = 1; k + 1 < npts; ++k)
  {
    const vtkIdType ids[3] = { pts[0], pts[k], pts[k + 1] };
    soup.Add(ids, cell, numPoints);
  }
}

/// The polygon cells one by one (cell ids from firstCell on).
void AddPolygons(vtkPolyData* input, vtkIdType firstCell, TriangleSoup& soup)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkUnsignedCharArray* cellGhosts = CellGhosts(input, soup);
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> local;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  vtkIdType cell = firstCell;
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cell)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    polys->GetCurrentCell(npts, pts);
    if (SkipGhostCell(cellGhosts, cell, npts, pts, numPoints, soup))
    {
      continue;
    }
    if (npts == 3)
    {
      soup.Add(pts, cell, numPoints);
    }
    else if (npts < 3)
    {
      ++soup.BadCells;
    }
    else
    {
      AddPolygon(input, cell, npts, pts, polygon, local, soup);
    }
  }
}

/// The strips, decomposed into triangles (cell ids from firstCell on).
void AddStrips(vtkPolyData* input, vtkIdType firstCell, TriangleSoup& soup)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkUnsignedCharArray* cellGhosts = CellGhosts(input, soup);
  vtkNew<vtkCellArray> stripTriangles;
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  vtkIdType cell = firstCell;
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cell)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    strips->GetCurrentCell(npts, pts);
    if (SkipGhostCell(cellGhosts, cell, npts, pts, numPoints, soup))
    {
      continue;
    }
    ++soup.Strips;
    if (npts < 3)
    {
      ++soup.BadCells;
      continue;
    }
    stripTriangles->Reset();
    vtkTriangleStrip::DecomposeStrip(static_cast<int>(npts), pts, stripTriangles);
    auto tris = vtk::TakeSmartPointer(stripTriangles->NewIterator());
    for (tris->GoToFirstCell(); !tris->IsDoneWithTraversal(); tris->GoToNextCell())
    {
      vtkIdType n3;
      const vtkIdType* ids;
      tris->GetCurrentCell(n3, ids);
      // A repeated point is how strips swap or join (a b c c d): legitimate, left out quietly
      // (an id out of range in it is not: Add reports it).
      const bool join = (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2]) &&
        std::all_of(ids, ids + 3, [numPoints](vtkIdType id) { return id >= 0 && id < numPoints; });
      soup.StripJoins += join ? 1 : 0;
      if (!join)
      {
        soup.Add(ids, cell, numPoints);
      }
    }
  }
}
} // namespace

void ExtractTriangles(vtkPolyData* input, TriangleSoup& soup, int threads)
{
  soup.Fixed.assign(input->GetNumberOfPoints(), 0);
  FixGhostPoints(input, soup);
  const vtkIdType polyOffset = input->GetNumberOfVerts() + input->GetNumberOfLines();
  if (TryPlainTriangles(input, polyOffset, threads, soup))
  {
    return;
  }
  soup.Triangles.reserve(3 * static_cast<size_t>(input->GetNumberOfPolys()));
  soup.SourceCell.reserve(static_cast<size_t>(input->GetNumberOfPolys()));
  AddPolygons(input, polyOffset, soup);
  AddStrips(input, polyOffset + input->GetNumberOfPolys(), soup);
}

vtkIdType FixOpenBoundary(TriangleSoup& soup)
{
  std::vector<uint64_t> edges;
  edges.reserve(soup.Triangles.size());
  for (size_t t = 0; t + 2 < soup.Triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const auto a = static_cast<uint32_t>(soup.Triangles[t + k]);
      const auto b = static_cast<uint32_t>(soup.Triangles[t + (k + 1) % 3]);
      edges.push_back((uint64_t(std::min(a, b)) << 32) | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  vtkIdType fixed = 0;
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i])
    {
      ++j;
    }
    if (j - i == 1)
    {
      for (const uint32_t v : { uint32_t(edges[i] >> 32), uint32_t(edges[i] & 0xffffffffu) })
      {
        fixed += soup.Fixed[v] ? 0 : 1;
        soup.Fixed[v] = 1;
      }
      soup.HasFixed = true;
    }
    i = j;
  }
  return fixed;
}

bool GatherPoints(vtkPoints* points, Buffer<double>& xyz, int threads)
{
  const vtkIdType n = points->GetNumberOfPoints();
  const size_t values = 3 * static_cast<size_t>(n);
  xyz.resize(values);
  double* out = xyz.data();
  vtkDataArray* data = points->GetData();
  const void* source = nullptr;
  bool isFloat = false;
  if (auto* f = vtkFloatArray::FastDownCast(data))
  {
    source = f->GetPointer(0);
    isFloat = true;
  }
  else if (auto* d = vtkDoubleArray::FastDownCast(data))
  {
    source = d->GetPointer(0);
  }
  else
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      points->GetPoint(i, out + 3 * i);
    }
  }
  return ParallelAll(values, ThreadsFor(values, threads, 1 << 18),
                     [source, isFloat, out](size_t begin, size_t end)
                     {
                       if (source && isFloat)
                       {
                         std::copy(static_cast<const float*>(source) + begin,
                                   static_cast<const float*>(source) + end, out + begin);
                       }
                       else if (source)
                       {
                         std::copy(static_cast<const double*>(source) + begin,
                                   static_cast<const double*>(source) + end, out + begin);
                       }
                       return std::all_of(out + begin, out + end,
                                          [](double x) { return std::isfinite(x); });
                     });
}

vtkIdType LockPoints(vtkDataArray* locks, TriangleSoup& soup)
{
  vtkIdType locked = 0;
  const int components = locks->GetNumberOfComponents();
  const vtkIdType n = std::min<vtkIdType>(locks->GetNumberOfTuples(), soup.Fixed.size());
  for (vtkIdType i = 0; i < n; ++i)
  {
    bool lock = false;
    for (int k = 0; k < components && !lock; ++k)
    {
      lock = locks->GetComponent(i, k) != 0.0; // NaN != 0 too
    }
    if (lock && !soup.Fixed[i])
    {
      soup.Fixed[i] = 1;
      soup.HasFixed = true;
      ++locked;
    }
  }
  return locked;
}

namespace
{
/// The smallest and largest finite value of components [0, used) of `array`, by ranges of
/// tuples on `threads` threads (min and max do not depend on the order). Not VTK's
/// GetFiniteRange: that one caches in the array's information, stale when the array is
/// written in place without its own Modified(), and unlocked when filters share an input.
void FiniteRange(vtkDataArray* array, int used, int threads, double& lo, double& hi)
{
  const size_t n = static_cast<size_t>(array->GetNumberOfTuples());
  std::vector<double> los(size_t(threads), std::numeric_limits<double>::infinity());
  std::vector<double> his(size_t(threads), -std::numeric_limits<double>::infinity());
  double* loOut = los.data();
  double* hiOut = his.data();
  ParallelFor(n, threads,
              [array, used, loOut, hiOut](size_t begin, size_t end, int t)
              {
                double l = loOut[t], h = hiOut[t];
                for (size_t i = begin; i < end; ++i)
                {
                  for (int k = 0; k < used; ++k)
                  {
                    const double x = array->GetComponent(static_cast<vtkIdType>(i), k);
                    if (std::isfinite(x))
                    {
                      l = std::min(l, x);
                      h = std::max(h, x);
                    }
                  }
                }
                loOut[t] = l;
                hiOut[t] = h;
              });
  lo = *std::min_element(los.begin(), los.end());
  hi = *std::max_element(his.begin(), his.end());
}
} // namespace

vtkIdType ConvertColors(vtkDataArray* array, Buffer<float>& rgb, double mapping[2], int threads)
{
  const size_t n = static_cast<size_t>(array->GetNumberOfTuples());
  const int comps = array->GetNumberOfComponents();
  const int used = comps >= 3 ? 3 : 1; // RGB(A...) or a grey value
  rgb.resize(3 * n);                   // every value written below
  float* out = rgb.data();
  // Arrays of one contiguous buffer are read on all threads; others (implicit, or
  // structure-of-arrays) on one.
  threads = array->HasStandardMemoryLayout() ? ThreadsFor(n, threads, 1 << 16) : 1;

  mapping[0] = 0.0;
  mapping[1] = 1.0 / 255.0;
  if (auto* uc = vtkUnsignedCharArray::FastDownCast(array))
  {
    const unsigned char* src = uc->GetPointer(0);
    ParallelFor(n, threads,
                [src, comps, used, out](size_t begin, size_t end, int)
                {
                  for (size_t i = begin; i < end; ++i)
                  {
                    for (int k = 0; k < 3; ++k)
                    {
                      out[3 * i + k] = src[comps * i + (used == 3 ? k : 0)] / 255.0f;
                    }
                  }
                });
    return 0;
  }

  // Bytes in another layout (structure of arrays, implicit) are /255 too; other types are
  // taken as they are in [0, 1], otherwise mapped by their range.
  const bool bytes = array->GetDataType() == VTK_UNSIGNED_CHAR;
  double lo = 0.0, hi = 0.0;
  if (!bytes)
  {
    FiniteRange(array, used, threads, lo, hi);
  }
  const bool unit = !bytes && lo >= 0.0 && hi <= 1.0;
  // A range wider than a double holds (beyond 1.8e308) is mapped by halves: x/2 - lo/2 never
  // overflows, and 2 * scale = 1 / (hi/2 - lo/2) stays finite.
  const bool wide = !unit && !std::isfinite(hi - lo);
  const double offset = bytes || unit ? 0.0 : lo;
  const double scale = bytes ? 1.0 / 255.0
    : unit                   ? 1.0
    : wide                   ? 0.5 / (0.5 * hi - 0.5 * lo)
                             : (hi > lo ? 1.0 / (hi - lo) : 0.0);
  mapping[0] = offset;
  mapping[1] = scale;
  std::vector<vtkIdType> nonFinite(size_t(threads), 0);
  vtkIdType* counts = nonFinite.data();
  ParallelFor(
    n, threads,
    [array, used, bytes, wide, offset, scale, out, counts](size_t begin, size_t end, int t)
    {
      vtkIdType bad = 0;
      for (size_t i = begin; i < end; ++i)
      {
        bool finite = true;
        for (int k = 0; k < 3; ++k)
        {
          const double x = array->GetComponent(static_cast<vtkIdType>(i), used == 3 ? k : 0);
          finite = finite && std::isfinite(x);
          // Bytes as the contiguous ones above; NaN and infinite values map to 0.
          const double mapped =
            wide ? (0.5 * x - 0.5 * offset) * (2.0 * scale) : (x - offset) * scale;
          out[3 * i + k] = bytes    ? static_cast<float>(x) / 255.0f
            : std::isfinite(mapped) ? static_cast<float>(mapped)
                                    : 0.0f;
        }
        bad += finite ? 0 : 1;
      }
      counts[t] = bad;
    });
  return std::accumulate(nonFinite.begin(), nonFinite.end(), vtkIdType(0));
}

void WriteColor(vtkDataArray* array, vtkIdType i, const double rgb[3], const double mapping[2])
{
  if (!(mapping[1] > 0.0))
  {
    return;
  }
  const int comps = array->GetNumberOfComponents();
  const bool integral = array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE;
  const double lo = array->GetDataTypeMin();
  const double hi = array->GetDataTypeMax();
  // A range wider than a double holds (ConvertColors) is walked by halves; its scale may be
  // subnormal (the range +-DBL_MAX), whose inverse overflows: the half range is capped.
  const double half = std::min(0.5 / mapping[1], std::numeric_limits<double>::max());
  const bool wide = !std::isfinite(1.0 / mapping[1]);
  auto value = [&](double c)
  {
    const double x = wide ? (mapping[0] + c * half) + c * half : mapping[0] + c / mapping[1];
    return std::min(std::max(integral ? std::round(x) : x, lo), hi);
  };
  if (comps >= 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      array->SetComponent(i, k, value(rgb[k]));
    }
  }
  else if (comps >= 1)
  {
    array->SetComponent(i, 0, value((rgb[0] + rgb[1] + rgb[2]) / 3.0));
  }
}

/// The points and the triangles; false (with an error) where they cannot be decimated.
bool ReadGeometry(vtkObject* self, vtkPolyData* input, int threads, InputMesh& mesh)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (!GatherPoints(input->GetPoints(), mesh.Points, threads))
  {
    vtkErrorWithObjectMacro(
      self, << "The input has NaN or infinite point coordinates; output is empty.");
    return false;
  }
  TriangleSoup& soup = mesh.Soup;
  ExtractTriangles(input, soup, threads);
  if (soup.IdsOutOfRange)
  {
    vtkErrorWithObjectMacro(self, << "The input has cells with point ids outside [0, " << numPoints
                                  << "); output is empty.");
    return false;
  }
  if (soup.Polygons > 0 || soup.Strips > 0)
  {
    // Legitimate input: the output is triangles whatever the input's cells.
    vtkDebugWithObjectMacro(self, << "Triangulated " << soup.Polygons << " polygons and "
                                  << soup.Strips << " triangle strips.");
  }
  if (soup.IgnoredGhostArray)
  {
    vtkWarningWithObjectMacro(self, << "The input's ghost array ("
                                    << vtkDataSetAttributes::GhostArrayName()
                                    << ") does not hold one value for each point or cell; it is "
                                       "ignored: no point or cell is taken for a ghost.");
  }
  if (soup.StripJoins > 0)
  {
    vtkDebugWithObjectMacro(self, << "Left out the " << soup.StripJoins
                                  << " zero-area triangles of the strips' swaps and joins.");
  }
  if (soup.Degenerate > 0 || soup.BadCells > 0)
  {
    vtkWarningWithObjectMacro(self, << "Dropped " << soup.Degenerate
                                    << " triangles that repeat a point and " << soup.BadCells
                                    << " polygons with fewer than 3 points.");
  }
  const vtkIdType numTriangles = soup.Count();
  if (numTriangles > std::numeric_limits<int32_t>::max() / 3)
  {
    vtkErrorWithObjectMacro(self, << "Too many triangles (" << numTriangles << ").");
    return false;
  }
  if (numTriangles == 0)
  {
    vtkWarningWithObjectMacro(self, << "The input has no triangles: empty output.");
    return false;
  }
  return true;
}

/// (The small allowance keeps a product that is an integer on paper, 1 - 0.8 being
/// 0.19999999999999996 in double, from losing one.)
int64_t TargetTriangles(vtkIdType targetNumber, double reduction, vtkIdType numTriangles)
{
  if (targetNumber > 0)
  {
    return static_cast<int64_t>(targetNumber);
  }
  return static_cast<int64_t>(
    std::floor((1.0 - reduction) * static_cast<double>(numTriangles) + 1e-6));
}

void RequestGhostCells(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  // Any output port (the decimation's record may be the one asked for).
  for (int port = 0; inInfo && port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) &&
        outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) > 1)
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 1);
      return;
    }
  }
}

} // namespace adapter
} // namespace colordecimation
