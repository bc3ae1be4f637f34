/*=========================================================================

  Program:   ColorDecimation (a VTK module)
  Module:    vtkColorHalfEdgeDecimation.cxx

  Distributed under the OSI-approved BSD 3-Clause License; see LICENSE.

=========================================================================*/
#include "vtkColorHalfEdgeDecimation.h"

#include "Core/Decimator.h"
#include "Core/util/Parallel.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleStrip.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkColorHalfEdgeDecimation);

namespace
{

/// Triangles of the input with, for each, the id of the input cell it came from.
struct TriangleSoup
{
  colordecimation::Buffer<int32_t> Triangles;
  colordecimation::Buffer<vtkIdType> SourceCell;
  vtkIdType Polygons = 0;    ///< cells with more than 3 points that were triangulated
  vtkIdType Strips = 0;      ///< strips decomposed
  vtkIdType Degenerate = 0;  ///< triangles with a repeated point, dropped
  vtkIdType BadCells = 0;    ///< cells with fewer than 3 points, dropped
  vtkIdType GhostCells = 0;  ///< ghost cells (another piece's), left out
  vtkIdType GhostPoints = 0; ///< ghost (duplicate) points, fixed
  bool IdsOutOfRange = false;
  /// Per point: non-zero if it must not collapse (used by a ghost cell, or a ghost point).
  std::vector<uint8_t> Fixed;
  bool HasFixed = false;

  void Add(const vtkIdType* ids, vtkIdType cell, vtkIdType numPoints)
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
};

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
  threads = colordecimation::ThreadsFor(nt, threads, 65536);
  const bool plain =
    colordecimation::ParallelAll(nt, threads,
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
  soup.SourceCell.resize(nt);
  int32_t* triangles = soup.Triangles.data();
  vtkIdType* sources = soup.SourceCell.data();
  colordecimation::ParallelFor(
    nt, threads,
    [connectivity, triangles, sources, firstCell](size_t begin, size_t end, int)
    {
      for (size_t i = 3 * begin; i < 3 * end; ++i)
      {
        triangles[i] = static_cast<int32_t>(connectivity[i]);
      }
      for (size_t f = begin; f < end; ++f)
      {
        sources[f] = firstCell + static_cast<vtkIdType>(f);
      }
    });
  return true;
}

void ExtractTriangles(vtkPolyData* input, TriangleSoup& soup, int threads)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  soup.Fixed.assign(numPoints, 0);
  vtkUnsignedCharArray* cellGhosts = input->GetCellGhostArray();
  if (vtkUnsignedCharArray* pointGhosts = input->GetPointGhostArray())
  {
    for (vtkIdType i = 0; i < numPoints && i < pointGhosts->GetNumberOfValues(); ++i)
    {
      if (pointGhosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT)
      {
        soup.Fixed[i] = 1;
        soup.HasFixed = true;
        ++soup.GhostPoints;
      }
    }
  }
  const vtkIdType polyOffset = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkCellArray* polyCells = input->GetPolys();
  if (!cellGhosts && input->GetNumberOfStrips() == 0 && polyCells->GetNumberOfCells() > 0 &&
      polyCells->IsHomogeneous() == 3)
  {
    const vtkIdType nt = polyCells->GetNumberOfCells();
    if (polyCells->IsStorage64Bit()
          ? CopyPlainTriangles(polyCells->GetConnectivityArray64()->GetPointer(0), nt, numPoints,
                               polyOffset, threads, soup)
          : CopyPlainTriangles(polyCells->GetConnectivityArray32()->GetPointer(0), nt, numPoints,
                               polyOffset, threads, soup))
    {
      return;
    }
  }
  soup.Triangles.reserve(3 * static_cast<size_t>(input->GetNumberOfPolys()));
  soup.SourceCell.reserve(static_cast<size_t>(input->GetNumberOfPolys()));

  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> local;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  vtkIdType cell = polyOffset;
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
      continue;
    }
    if (npts < 3)
    {
      ++soup.BadCells;
      continue;
    }
    ++soup.Polygons;
    bool inRange = true;
    for (vtkIdType k = 0; k < npts; ++k)
    {
      inRange = inRange && pts[k] >= 0 && pts[k] < numPoints;
    }
    if (!inRange)
    {
      soup.IdsOutOfRange = true;
      continue;
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
    }
    else
    {
      for (vtkIdType k = 1; k + 1 < npts; ++k) // fan, when ear cutting gives up
      {
        const vtkIdType ids[3] = { pts[0], pts[k], pts[k + 1] };
        soup.Add(ids, cell, numPoints);
      }
    }
  }

  vtkNew<vtkCellArray> stripTriangles;
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  cell = polyOffset + input->GetNumberOfPolys();
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
      soup.Add(ids, cell, numPoints);
    }
  }
}

/**
 * Fixes the points on the open boundary of the triangles (edges used by one triangle): for a
 * piece of distributed data that came without ghost cells, the points it shares with other
 * pieces are among these. Returns the number of points fixed.
 */
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

/// Points as doubles (copied on `threads` threads); false if a coordinate is NaN or infinite.
bool GatherPoints(vtkPoints* points, colordecimation::Buffer<double>& xyz, int threads)
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
  return colordecimation::ParallelAll(
    values, colordecimation::ThreadsFor(values, threads, 1 << 18),
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
      return std::all_of(out + begin, out + end, [](double x) { return std::isfinite(x); });
    });
}

/**
 * RGB in [0,1], 3 floats per point (SPEC.md, Frame). Returns the number of tuples holding a
 * NaN or infinite value (measured as 0, carried through unchanged). The mapping used is
 * (x - offset) * scale; it is returned in `mapping` (offset, scale) when given.
 */
vtkIdType ConvertColors(vtkDataArray* array, std::vector<float>& rgb, double* mapping = nullptr)
{
  const vtkIdType n = array->GetNumberOfTuples();
  const int comps = array->GetNumberOfComponents();
  const int used = comps >= 3 ? 3 : 1; // RGB(A...) or a grey value
  rgb.assign(3 * static_cast<size_t>(n), 0.0f);
  vtkIdType nonFinite = 0;

  if (mapping)
  {
    mapping[0] = 0.0;
    mapping[1] = 1.0 / 255.0;
  }
  if (auto* uc = vtkUnsignedCharArray::FastDownCast(array))
  {
    const unsigned char* src = uc->GetPointer(0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        rgb[3 * i + k] = src[comps * i + (used == 3 ? k : 0)] / 255.0f;
      }
    }
    return 0;
  }

  // Range of the components used, finite values only.
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < used; ++k)
    {
      const double x = array->GetComponent(i, k);
      if (std::isfinite(x))
      {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
    }
  }
  const bool unit = lo >= 0.0 && hi <= 1.0;
  const double offset = unit ? 0.0 : lo;
  const double scale = unit ? 1.0 : (hi > lo ? 1.0 / (hi - lo) : 0.0);
  if (mapping)
  {
    mapping[0] = offset;
    mapping[1] = scale;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    bool finite = true;
    for (int k = 0; k < 3; ++k)
    {
      const double x = array->GetComponent(i, used == 3 ? k : 0);
      finite = finite && std::isfinite(x);
      rgb[3 * i + k] = std::isfinite(x) ? static_cast<float>((x - offset) * scale) : 0.0f;
    }
    nonFinite += finite ? 0 : 1;
  }
  return nonFinite;
}

/**
 * Writes an RGB colour in [0,1] into tuple `i` of a colour array, in the array's own type and
 * range: the inverse of the mapping (x - offset) * scale of ConvertColors (unsigned char:
 * times 255, rounded); a one-component array gets the grey mean; further components (alpha)
 * are left as they are. Nothing is written when the mapping is not invertible (scale 0).
 */
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
  auto value = [&](double c)
  {
    double x = mapping[0] + c / mapping[1];
    if (integral)
    {
      x = std::min(std::max(std::round(x), lo), hi);
    }
    return x;
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

void CopyPassedData(vtkPolyData* input, vtkPolyData* output)
{
  output->GetFieldData()->PassData(input->GetFieldData());
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

} // namespace

//------------------------------------------------------------------------------
vtkColorHalfEdgeDecimation::vtkColorHalfEdgeDecimation()
  : ErrorMetric(HalfEdgeColor)
  , CollapseSchedule(Greedy)
  , NumberOfThreads(0)
  , ColorSpace(RGB)
  , OptimalPlacement(false)
  , ColorWeight(1.0)
  , BoundaryWeight(0.0)
  , TargetReduction(0.9)
  , PreserveBoundary(false)
  , MaximumNormalAngle(90.0)
  , GeometryWeight(1.0)
  , GenerateOriginalPointIds(true)
  , OriginalPointIdsArrayName(nullptr)
  , ActualReduction(0.0)
  , NumberOfCollapses(0)
  , StateMemory(0)
  , NumberOfThreadsUsed(0)
{
  this->SetOriginalPointIdsArrayName("vtkOriginalPointIds");
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                               vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkColorHalfEdgeDecimation::~vtkColorHalfEdgeDecimation()
{
  this->SetOriginalPointIdsArrayName(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkColorHalfEdgeDecimation::GetErrorMetricAsString()
{
  switch (this->ErrorMetric)
  {
    case Geometry:
      return "Geometry";
    case ColorQuadric:
      return "ColorQuadric";
    default:
      return "HalfEdgeColor";
  }
}

//------------------------------------------------------------------------------
const char* vtkColorHalfEdgeDecimation::GetCollapseScheduleAsString()
{
  return this->CollapseSchedule == Batched ? "Batched" : "Greedy";
}

//------------------------------------------------------------------------------
const char* vtkColorHalfEdgeDecimation::GetColorSpaceAsString()
{
  return this->ColorSpace == CIELab ? "CIELab" : "RGB";
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeDecimation::RequestData(vtkInformation* vtkNotUsed(request),
                                            vtkInformationVector** inputVector,
                                            vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->ActualReduction = 0.0;
  this->NumberOfCollapses = 0;
  this->StateMemory = 0;
  this->NumberOfThreadsUsed = 0;
  if (!input || !output)
  {
    return 0;
  }
  CopyPassedData(input, output);

  for (const double value : { this->TargetReduction, this->MaximumNormalAngle, this->GeometryWeight,
                              this->ColorWeight, this->BoundaryWeight })
  {
    if (!std::isfinite(value))
    {
      vtkErrorMacro(<< "A property is NaN or infinite (TargetReduction " << this->TargetReduction
                    << ", MaximumNormalAngle " << this->MaximumNormalAngle << ", GeometryWeight "
                    << this->GeometryWeight << ", ColorWeight " << this->ColorWeight
                    << ", BoundaryWeight " << this->BoundaryWeight << "); output is empty.");
      return 1;
    }
  }

  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (numPoints == 0 || input->GetNumberOfCells() == 0)
  {
    vtkDebugMacro(<< "Empty input: empty output.");
    return 1;
  }
  if (input->GetNumberOfVerts() > 0 || input->GetNumberOfLines() > 0)
  {
    vtkWarningMacro(<< "Dropping " << input->GetNumberOfVerts() << " vertex and "
                    << input->GetNumberOfLines() << " line cells: only surfaces are decimated.");
  }
  if (numPoints > std::numeric_limits<int32_t>::max())
  {
    vtkErrorMacro(<< "Too many points (" << numPoints << "); at most 2^31 - 1 are supported.");
    return 1;
  }

  // Threads: as many as asked, or as vtkSMPTools runs (VTK_SMP_MAX_THREADS, ParaView's settings).
  const int threads = this->NumberOfThreads > 0
    ? this->NumberOfThreads
    : std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  colordecimation::Buffer<double> xyz;
  if (!GatherPoints(input->GetPoints(), xyz, threads))
  {
    vtkErrorMacro(<< "The input has NaN or infinite point coordinates; output is empty.");
    return 1;
  }

  TriangleSoup soup;
  ExtractTriangles(input, soup, threads);
  if (soup.IdsOutOfRange)
  {
    vtkErrorMacro(<< "The input has cells with point ids outside [0, " << numPoints
                  << "); output is empty.");
    return 1;
  }
  if (soup.Polygons > 0 || soup.Strips > 0)
  {
    vtkWarningMacro(<< "Triangulated " << soup.Polygons << " polygons and " << soup.Strips
                    << " triangle strips.");
  }
  if (soup.Degenerate > 0 || soup.BadCells > 0)
  {
    vtkWarningMacro(<< "Dropped " << soup.Degenerate << " triangles that repeat a point and "
                    << soup.BadCells << " polygons with fewer than 3 points.");
  }
  const vtkIdType numTriangles = static_cast<vtkIdType>(soup.SourceCell.size());
  if (numTriangles > std::numeric_limits<int32_t>::max() / 3)
  {
    vtkErrorMacro(<< "Too many triangles (" << numTriangles << ").");
    return 1;
  }
  if (numTriangles == 0)
  {
    vtkWarningMacro(<< "The input has no triangles: empty output.");
    return 1;
  }

  // The colour array.
  std::vector<float> rgb;
  const float* colors = nullptr;
  vtkDataArray* colorArray = nullptr;
  double colorMapping[2] = { 0.0, 0.0 };
  if (this->ErrorMetric != Geometry)
  {
    int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    colorArray = this->GetInputArrayToProcess(0, inputVector, association);
    if (!colorArray)
    {
      vtkWarningMacro(<< "No colour array (point scalars or the array selected with "
                         "SetInputArrayToProcess): decimating by geometry alone.");
    }
    else if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
    {
      vtkErrorMacro(<< "The colour array '" << (colorArray->GetName() ? colorArray->GetName() : "")
                    << "' is not a point-data array; output is empty.");
      return 1;
    }
    else if (colorArray->GetNumberOfTuples() != numPoints)
    {
      vtkErrorMacro(<< "The colour array '" << (colorArray->GetName() ? colorArray->GetName() : "")
                    << "' has " << colorArray->GetNumberOfTuples() << " tuples for " << numPoints
                    << " points; output is empty.");
      return 1;
    }
    else if (colorArray->GetNumberOfComponents() < 1)
    {
      vtkErrorMacro(<< "The colour array has no components; output is empty.");
      return 1;
    }
    else
    {
      const vtkIdType nonFinite = ConvertColors(colorArray, rgb, colorMapping);
      if (nonFinite > 0)
      {
        vtkWarningMacro(<< nonFinite
                        << " colour tuples hold NaN or infinite values: they are measured as 0 "
                           "and carried through unchanged.");
      }
      colors = rgb.data();
    }
  }

  // Decimate.
  colordecimation::DecimatorOptions options;
  options.Metric = this->ErrorMetric == Geometry ? colordecimation::ErrorMetric::Geometry
    : this->ErrorMetric == ColorQuadric          ? colordecimation::ErrorMetric::ColorQuadric
                                                 : colordecimation::ErrorMetric::HalfEdgeColor;
  options.Space = this->ColorSpace == CIELab ? colordecimation::ColorSpace::CIELab
                                             : colordecimation::ColorSpace::RGB;
  options.OptimalPlacement = this->OptimalPlacement != 0;
  options.Schedule = this->CollapseSchedule == Batched ? colordecimation::CollapseSchedule::Batched
                                                       : colordecimation::CollapseSchedule::Greedy;
  options.NumberOfThreads = threads;
  options.KeepVertexState = false; // the output needs the mesh and the moved vertices only
  options.ColorWeight = this->ColorWeight;
  options.BoundaryWeight = this->BoundaryWeight;
  options.PreserveBoundary = this->PreserveBoundary != 0;
  options.MaximumNormalAngle = this->MaximumNormalAngle;
  options.GeometryWeight = this->GeometryWeight;

  colordecimation::DecimatorInput in;
  in.NumberOfPoints = static_cast<int32_t>(numPoints);
  in.Points = xyz.data();
  in.Colors = colors;
  in.NumberOfTriangles = static_cast<int32_t>(numTriangles);
  in.Triangles = soup.Triangles.data();
  in.Fixed = soup.HasFixed ? soup.Fixed.data() : nullptr;
  if (soup.GhostCells > 0)
  {
    vtkDebugMacro(<< "Left out " << soup.GhostCells << " ghost cells; their points are fixed.");
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int numPieces = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  if (numPieces > 1 && soup.GhostCells == 0 && soup.GhostPoints == 0)
  {
    // One piece of several, without ghosts: keep its open boundary, where it meets the others.
    const vtkIdType fixed = FixOpenBoundary(soup);
    in.Fixed = soup.HasFixed ? soup.Fixed.data() : nullptr;
    vtkDebugMacro(<< "Piece of " << numPieces << " without ghost cells: " << fixed
                  << " points of its open boundary are fixed.");
  }

  // At most (1 - TargetReduction) of the triangles remain. The small allowance keeps a product
  // that is an integer on paper (1 - 0.8 is 0.19999999999999996 in double) from losing one.
  const auto target = static_cast<int64_t>(
    std::floor((1.0 - this->TargetReduction) * static_cast<double>(numTriangles) + 1e-6));
  this->UpdateProgress(0.05);
  colordecimation::Decimator decimator(options);
  const colordecimation::DecimatorStatistics stats =
    decimator.Run(in, target,
                  [this](double fraction)
                  {
                    this->UpdateProgress(0.05 + 0.85 * fraction);
                    return !this->GetAbortExecute();
                  });
  const colordecimation::MeshBuildReport& build = stats.Build;
  if (build.NonManifoldEdges > 0 || build.NonManifoldVertices > 0)
  {
    vtkWarningMacro(<< "The input has " << build.NonManifoldEdges
                    << " non-manifold or inconsistently oriented edges and "
                    << build.NonManifoldVertices << " non-manifold vertices; their "
                    << build.LockedVertices << " vertices are kept as they are.");
  }
  this->NumberOfCollapses = stats.Collapses;
  this->StateMemory = static_cast<vtkIdType>(stats.StateBytes);
  this->NumberOfThreadsUsed =
    std::max({ stats.Threads, stats.CollapseThreads, stats.WideCollapseThreads });

  // Output: the surviving triangles on the points they use, in input order.
  const colordecimation::HalfEdgeMesh& mesh = decimator.GetMesh();
  std::vector<vtkIdType> newId(numPoints, -1);
  vtkIdType numOutTriangles = 0;
  for (int32_t f = 0; f < mesh.GetNumberOfFaceSlots(); ++f)
  {
    if (mesh.IsFaceAlive(f))
    {
      ++numOutTriangles;
      int32_t tri[3];
      mesh.GetFace(f, tri);
      newId[tri[0]] = newId[tri[1]] = newId[tri[2]] = 0;
    }
  }
  vtkNew<vtkIdList> sourcePoints;
  vtkNew<vtkIdList> targetPoints;
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    if (newId[i] == 0)
    {
      newId[i] = sourcePoints->GetNumberOfIds();
      targetPoints->InsertNextId(newId[i]);
      sourcePoints->InsertNextId(i);
    }
  }
  const vtkIdType numOutPoints = sourcePoints->GetNumberOfIds();

  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(input->GetPoints()->GetDataType());
  outPoints->SetNumberOfPoints(numOutPoints);
  input->GetPoints()->GetData()->GetTuples(sourcePoints, outPoints->GetData());
  if (decimator.HasMovedVertices())
  {
    // Full collapses (ColorQuadric with OptimalPlacement) moved some surviving vertices.
    for (vtkIdType i = 0; i < numOutPoints; ++i)
    {
      const auto source = static_cast<int32_t>(sourcePoints->GetId(i));
      if (decimator.IsMoved(source))
      {
        double p[3];
        decimator.GetOutputPosition(source, p);
        outPoints->SetPoint(i, p);
      }
    }
  }
  output->SetPoints(outPoints);

  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * numOutTriangles);
  vtkNew<vtkIdList> sourceCells;
  vtkNew<vtkIdList> targetCells;
  sourceCells->SetNumberOfIds(numOutTriangles);
  targetCells->SetNumberOfIds(numOutTriangles);
  vtkIdType t = 0;
  for (int32_t f = 0; f < mesh.GetNumberOfFaceSlots(); ++f)
  {
    if (mesh.IsFaceAlive(f))
    {
      int32_t tri[3];
      mesh.GetFace(f, tri);
      for (int k = 0; k < 3; ++k)
      {
        connectivity->SetValue(3 * t + k, newId[tri[k]]);
      }
      sourceCells->SetId(t, soup.SourceCell[f]);
      targetCells->SetId(t, t);
      ++t;
    }
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(3, connectivity);
  output->SetPolys(polys);

  // Arrays whose tuple count does not match their points or cells cannot be carried.
  vtkNew<vtkPointData> inPD;
  vtkNew<vtkCellData> inCD;
  std::string droppedPointArrays, droppedCellArrays;
  KeepConsistentArrays(input->GetPointData(), numPoints, inPD, droppedPointArrays);
  KeepConsistentArrays(input->GetCellData(), input->GetNumberOfCells(), inCD, droppedCellArrays);
  if (!droppedPointArrays.empty() || !droppedCellArrays.empty())
  {
    vtkWarningMacro(<< "Arrays whose size does not match the mesh are left out of the output: "
                    << (droppedPointArrays.empty() ? "" : "point data ") << droppedPointArrays
                    << (droppedCellArrays.empty() ? "" : " cell data ") << droppedCellArrays << " ("
                    << numPoints << " points, " << input->GetNumberOfCells() << " cells).");
  }

  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(inPD, numOutPoints);
  outPD->CopyData(inPD, sourcePoints, targetPoints);
  if (decimator.HasMovedVertices() && colors)
  {
    // The moved vertices' new colours, in the colour array's own type and range (the other
    // arrays keep the surviving input vertex's values).
    vtkDataArray* outColors = colorArray->GetName() && *colorArray->GetName()
      ? outPD->GetArray(colorArray->GetName())
      : outPD->GetScalars();
    if (outColors && outColors->GetNumberOfComponents() == colorArray->GetNumberOfComponents())
    {
      for (vtkIdType i = 0; i < numOutPoints; ++i)
      {
        const auto source = static_cast<int32_t>(sourcePoints->GetId(i));
        if (decimator.IsMoved(source))
        {
          double c[3];
          decimator.GetOutputColor(source, c);
          WriteColor(outColors, i, c, colorMapping);
        }
      }
    }
  }
  if (this->GenerateOriginalPointIds && this->OriginalPointIdsArrayName &&
      *this->OriginalPointIdsArrayName)
  {
    if (input->GetPointData()->HasArray(this->OriginalPointIdsArrayName))
    {
      vtkWarningMacro(<< "The input already has a point array named '"
                      << this->OriginalPointIdsArrayName << "': it is replaced by this filter's.");
      outPD->RemoveArray(this->OriginalPointIdsArrayName);
    }
    vtkNew<vtkIdTypeArray> original;
    original->SetName(this->OriginalPointIdsArrayName);
    original->SetNumberOfValues(numOutPoints);
    for (vtkIdType i = 0; i < numOutPoints; ++i)
    {
      original->SetValue(i, sourcePoints->GetId(i));
    }
    outPD->AddArray(original);
  }
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, numOutTriangles);
  outCD->CopyData(inCD, sourceCells, targetCells);

  this->ActualReduction = 1.0 - static_cast<double>(numOutTriangles) / numTriangles;
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeDecimation::RequestUpdateExtent(vtkInformation* request,
                                                    vtkInformationVector** inputVector,
                                                    vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  // Distributed data: one level of ghost cells tells which points are shared with other pieces.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (inInfo && outInfo &&
      outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) > 1)
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeDecimation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorMetric: " << this->GetErrorMetricAsString() << "\n";
  os << indent << "CollapseSchedule: " << this->GetCollapseScheduleAsString() << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "ColorSpace: " << this->GetColorSpaceAsString() << "\n";
  os << indent << "OptimalPlacement: " << (this->OptimalPlacement ? "On" : "Off") << "\n";
  os << indent << "ColorWeight: " << this->ColorWeight << "\n";
  os << indent << "BoundaryWeight: " << this->BoundaryWeight << "\n";
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "PreserveBoundary: " << (this->PreserveBoundary ? "On" : "Off") << "\n";
  os << indent << "MaximumNormalAngle: " << this->MaximumNormalAngle << "\n";
  os << indent << "GeometryWeight: " << this->GeometryWeight << "\n";
  os << indent << "GenerateOriginalPointIds: " << (this->GenerateOriginalPointIds ? "On" : "Off")
     << "\n";
  os << indent << "OriginalPointIdsArrayName: "
     << (this->OriginalPointIdsArrayName ? this->OriginalPointIdsArrayName : "(none)") << "\n";
  os << indent << "ActualReduction: " << this->ActualReduction << "\n";
  os << indent << "NumberOfCollapses: " << this->NumberOfCollapses << "\n";
  os << indent << "StateMemory: " << this->StateMemory << "\n";
  os << indent << "NumberOfThreadsUsed: " << this->NumberOfThreadsUsed << "\n";
}
