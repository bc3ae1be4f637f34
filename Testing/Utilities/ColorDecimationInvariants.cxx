#include "ColorDecimationInvariants.h"

#include "ColorDecimationTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

namespace colordecimation
{
namespace testing
{
namespace
{

using Broken = std::vector<std::string>;

template <typename... T>
std::string Say(const T&... parts)
{
  std::ostringstream os;
  (void)std::initializer_list<int>{ ((os << parts), 0)... };
  return os.str();
}

/// The filter's own statistics, and an error leaving the output empty.
void CheckStatistics(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter, vtkPolyData* output,
                     bool filterReportedError, Broken& broken)
{
  const vtkIdType numInPoints = input->GetNumberOfPoints();
  const vtkIdType numOutPoints = output->GetNumberOfPoints();
  const vtkIdType numOutCells = output->GetNumberOfCells();
  if (filterReportedError && (numOutPoints != 0 || numOutCells != 0))
  {
    broken.push_back(Say("the filter reported an error but the output has ", numOutPoints,
                         " points and ", numOutCells, " cells"));
  }
  if (filter->GetNumberOfCollapses() < 0 || filter->GetNumberOfCollapses() > numInPoints)
  {
    broken.push_back(Say("NumberOfCollapses = ", filter->GetNumberOfCollapses(), " for ",
                         numInPoints, " input points"));
  }
  const double actual = filter->GetActualReduction();
  if (!(actual >= 0.0 && actual <= 1.0))
  {
    broken.push_back(Say("ActualReduction = ", actual));
  }
  const double error = filter->GetActualError(), bound = filter->GetMaximumError();
  if (!(error >= 0.0) || (bound > 0.0 && error > bound * (1.0 + 1e-9)))
  {
    broken.push_back(Say("ActualError = ", error, " with MaximumError ", bound));
  }
}

/// Every point the lock array locks is in the output (when the run went through); `original`:
/// each output point's input point (InputIds).
void CheckLocks(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter, vtkIdTypeArray* original,
                bool filterReportedError, Broken& broken)
{
  const char* name = filter->GetLockArrayName();
  vtkDataArray* locks = name ? input->GetPointData()->GetArray(name) : nullptr;
  // Ghost cells are left out by the filter (their points are kept anyway): not checked here.
  if (!locks || !original || filterReportedError || input->GetCellGhostArray() ||
      locks->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    return;
  }
  std::vector<char> kept(static_cast<size_t>(input->GetNumberOfPoints()), 0);
  for (vtkIdType i = 0; i < original->GetNumberOfTuples(); ++i)
  {
    const vtkIdType id = original->GetValue(i);
    if (id >= 0 && id < input->GetNumberOfPoints())
    {
      kept[id] = 1;
    }
  }
  // Only points some valid triangle uses can be kept (the others are not output at all).
  std::vector<char> used(kept.size(), 0);
  const auto numPoints = static_cast<vtkIdType>(used.size());
  for (const Tri& t : GetTriangles(input)) // {-1, -1, -1} for cells that are not triangles
  {
    bool valid = t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
    for (const vtkIdType v : t)
    {
      valid = valid && v >= 0 && v < numPoints;
    }
    for (const vtkIdType v : t)
    {
      if (valid)
      {
        used[v] = 1;
      }
    }
  }
  long long lost = 0;
  for (vtkIdType i = 0; i < locks->GetNumberOfTuples(); ++i)
  {
    bool locked = false;
    for (int k = 0; k < locks->GetNumberOfComponents(); ++k)
    {
      locked = locked || locks->GetComponent(i, k) != 0.0;
    }
    lost += locked && used[i] && !kept[i] ? 1 : 0;
  }
  if (lost > 0)
  {
    broken.push_back(Say(lost, " points locked by '", name, "' are not in the output"));
  }
}

/// Triangles only, with valid and distinct ids; finite points.
void CheckCellsAndPoints(vtkPolyData* output, Broken& broken)
{
  const vtkIdType numOutPoints = output->GetNumberOfPoints();
  if (output->GetNumberOfVerts() || output->GetNumberOfLines() || output->GetNumberOfStrips())
  {
    broken.push_back(Say("the output has ", output->GetNumberOfVerts(), " vertex, ",
                         output->GetNumberOfLines(), " line and ", output->GetNumberOfStrips(),
                         " strip cells"));
  }
  if (output->GetPolys())
  {
    auto it = vtk::TakeSmartPointer(output->GetPolys()->NewIterator());
    vtkIdType cell = 0;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      if (n != 3)
      {
        broken.push_back(Say("output cell ", cell, " has ", n, " points"));
        break;
      }
      bool inRange = true;
      for (vtkIdType k = 0; k < n; ++k)
      {
        inRange = inRange && ids[k] >= 0 && ids[k] < numOutPoints;
      }
      if (!inRange)
      {
        broken.push_back(Say("output cell ", cell, " has a point id outside [0, ", numOutPoints,
                             "): ", ids[0], " ", ids[1], " ", ids[2]));
        break;
      }
      if (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2])
      {
        broken.push_back(
          Say("output cell ", cell, " repeats a point: ", ids[0], " ", ids[1], " ", ids[2]));
        break;
      }
    }
  }
  for (vtkIdType i = 0; i < numOutPoints; ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      broken.push_back(Say("output point ", i, " is not finite: ", p[0], " ", p[1], " ", p[2]));
      break;
    }
  }
}

/// One tuple per point in every point array, one per cell in every cell array.
void CheckTupleCounts(vtkPolyData* output, Broken& broken)
{
  const vtkIdType numOutPoints = output->GetNumberOfPoints();
  const vtkIdType numOutCells = output->GetNumberOfCells();
  vtkPointData* outPD = output->GetPointData();
  for (int a = 0; a < outPD->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = outPD->GetAbstractArray(a);
    if (array->GetNumberOfTuples() != numOutPoints)
    {
      broken.push_back(Say("output point array '", array->GetName() ? array->GetName() : "",
                           "' has ", array->GetNumberOfTuples(), " tuples for ", numOutPoints,
                           " points"));
    }
  }
  vtkCellData* outCD = output->GetCellData();
  for (int a = 0; a < outCD->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = outCD->GetAbstractArray(a);
    if (array->GetNumberOfTuples() != numOutCells)
    {
      broken.push_back(Say("output cell array '", array->GetName() ? array->GetName() : "",
                           "' has ", array->GetNumberOfTuples(), " tuples for ", numOutCells,
                           " cells"));
    }
  }
}

/// The name of the colour array the filter used (the input's scalars unless asked by name).
std::string ColorArrayName(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter)
{
  std::string colorName;
  if (input->GetPointData()->GetScalars() && input->GetPointData()->GetScalars()->GetName())
  {
    colorName = input->GetPointData()->GetScalars()->GetName();
  }
  if (vtkInformation* info = filter->GetInputArrayInformation(0))
  {
    if (info->Has(vtkDataObject::FIELD_NAME()))
    {
      colorName = info->Get(vtkDataObject::FIELD_NAME());
    }
  }
  return colorName;
}

/// Original ids distinct and in range; returns false if they are not.
bool CheckOriginalIdValues(vtkIdTypeArray* original, vtkIdType numInPoints, Broken& broken)
{
  std::vector<char> seen(static_cast<size_t>(numInPoints), 0);
  for (vtkIdType i = 0; i < original->GetNumberOfTuples(); ++i)
  {
    const vtkIdType j = original->GetValue(i);
    if (j < 0 || j >= numInPoints || seen[j])
    {
      broken.push_back(
        Say("original point id ", j, " of output point ", i, " is out of range or repeated"));
      return false;
    }
    seen[j] = 1;
  }
  return true;
}

/// Output points bit-exact copies of the input points they come from.
void CheckPointsCopied(vtkPolyData* input, vtkPolyData* output, vtkIdTypeArray* original,
                       Broken& broken)
{
  vtkDataArray* inPoints = input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
  vtkDataArray* outPoints = output->GetPoints() ? output->GetPoints()->GetData() : nullptr;
  if (!inPoints || !outPoints)
  {
    return;
  }
  if (inPoints->GetDataType() != outPoints->GetDataType())
  {
    broken.push_back("the output points' data type differs from the input's");
    return;
  }
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    if (!SameTupleBytes(outPoints, i, inPoints, original->GetValue(i)))
    {
      broken.push_back(Say("output point ", i, " is not input point ", original->GetValue(i)));
      return;
    }
  }
}

/// One output point array a bit-exact copy of the input array of its name.
void CheckPointArrayCopied(vtkDataArray* in, vtkDataArray* out, vtkIdTypeArray* original,
                           vtkIdType numOutPoints, Broken& broken)
{
  if (in->GetDataType() != out->GetDataType() ||
      in->GetNumberOfComponents() != out->GetNumberOfComponents())
  {
    broken.push_back(Say("output point array '", out->GetName(), "' changed its type or width"));
    return;
  }
  for (vtkIdType i = 0; i < std::min(numOutPoints, out->GetNumberOfTuples()); ++i)
  {
    const vtkIdType j = original->GetValue(i);
    if (j >= in->GetNumberOfTuples())
    {
      broken.push_back(Say("output point array '", out->GetName(), "' tuple ", i,
                           " was copied from input tuple ", j, " but that array has only ",
                           in->GetNumberOfTuples(), " tuples"));
      return;
    }
    if (!SameTupleBytes(out, i, in, j))
    {
      broken.push_back(
        Say("output point array '", out->GetName(), "' tuple ", i, " is not input tuple ", j));
      return;
    }
  }
}

/**
 * Original point ids, and bit-exact copies of the points and point data. With the
 * ColorQuadric metric's OptimalPlacement, points move and take a new colour: their
 * coordinates and the colour array are then not compared.
 */
/// The name the filter writes its original ids under: null when it writes none, its
/// OriginalPointIdsArrayName, or vtkOriginalPointIds when that is empty.
const char* WrittenIdsName(vtkColorHalfEdgeDecimation* filter)
{
  const char* name = filter->GetOriginalPointIdsArrayName();
  if (!filter->GetGenerateOriginalPointIds())
  {
    return nullptr;
  }
  return name && *name ? name : "vtkOriginalPointIds";
}

/**
 * The input's own ids of the filter's id array name, when the filter composes with them (one
 * integer id in [0, 2^53] per point), else null.
 */
vtkDataArray* UpstreamIds(vtkPolyData* input, const char* idsName)
{
  vtkDataArray* ids = input->GetPointData()->GetArray(idsName);
  if (!ids || ids->GetNumberOfComponents() != 1 ||
      ids->GetNumberOfTuples() != input->GetNumberOfPoints() || ids->GetDataType() == VTK_FLOAT ||
      ids->GetDataType() == VTK_DOUBLE || ids->GetDataType() == VTK_BIT)
  {
    return nullptr;
  }
  for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
  {
    const double id = ids->GetComponent(i, 0);
    if (!(id >= 0 && id <= 9007199254740992.0)) // as the filter: [0, 2^53]
    {
      return nullptr;
    }
  }
  return ids;
}

/**
 * The output's original ids as input point ids: the array itself, or (composed with upstream
 * ids) mapped back through them, each output id checked to be an upstream id. Null when the
 * filter writes none, or when upstream ids repeat (then only their membership is checked).
 */
vtkSmartPointer<vtkIdTypeArray> InputIds(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter,
                                         vtkPolyData* output, Broken& broken)
{
  const char* idsName = WrittenIdsName(filter);
  if (!idsName || output->GetNumberOfPoints() == 0)
  {
    return nullptr;
  }
  vtkIdTypeArray* original =
    vtkIdTypeArray::SafeDownCast(output->GetPointData()->GetAbstractArray(idsName));
  if (!original)
  {
    broken.push_back(Say("no vtkIdTypeArray '", idsName, "' in the output"));
    return nullptr;
  }
  vtkDataArray* upstream = UpstreamIds(input, idsName);
  if (!upstream)
  {
    return original;
  }
  std::map<vtkIdType, vtkIdType> back; // upstream id -> input point
  bool distinct = true;
  for (vtkIdType i = 0; i < upstream->GetNumberOfTuples(); ++i)
  {
    distinct =
      back.emplace(static_cast<vtkIdType>(upstream->GetComponent(i, 0)), i).second && distinct;
  }
  vtkNew<vtkIdTypeArray> local;
  local->SetNumberOfValues(original->GetNumberOfValues());
  for (vtkIdType i = 0; i < original->GetNumberOfValues(); ++i)
  {
    const auto it = back.find(original->GetValue(i));
    if (it == back.end())
    {
      broken.push_back(Say("output point ", i, " has the id ", original->GetValue(i),
                           ", which is none of the input's '", idsName, "' ids"));
      return nullptr;
    }
    local->SetValue(i, it->second);
  }
  return distinct ? vtkSmartPointer<vtkIdTypeArray>(local) : nullptr;
}

/// Ids valid and distinct, and the surviving points' data copied bit-exactly; `original`:
/// each output point's input point (InputIds).
void CheckOriginalIds(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter, vtkPolyData* output,
                      vtkIdTypeArray* original, Broken& broken)
{
  const vtkIdType numOutPoints = output->GetNumberOfPoints();
  const char* idsName = WrittenIdsName(filter);
  vtkPointData* outPD = output->GetPointData();
  if (!original || original->GetNumberOfTuples() != numOutPoints ||
      original->GetNumberOfComponents() != 1 ||
      !CheckOriginalIdValues(original, input->GetNumberOfPoints(), broken))
  {
    return;
  }
  const bool moves = filter->GetOptimalPlacement() &&
    filter->GetErrorMetric() == vtkColorHalfEdgeDecimation::ColorQuadric;
  if (!moves)
  {
    CheckPointsCopied(input, output, original, broken);
  }
  const std::string colorName = ColorArrayName(input, filter);
  for (int a = 0; a < outPD->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* out = outPD->GetArray(a);
    if (!out || !out->GetName() || std::strcmp(out->GetName(), idsName) == 0 ||
        (moves && (out->GetName() == colorName || out == outPD->GetScalars())))
    {
      continue;
    }
    if (vtkDataArray* in = input->GetPointData()->GetArray(out->GetName()))
    {
      CheckPointArrayCopied(in, out, original, numOutPoints, broken);
    }
  }
}

} // namespace

std::vector<std::string> CheckInvariants(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter,
                                         vtkPolyData* output, bool filterReportedError)
{
  Broken broken;
  CheckStatistics(input, filter, output, filterReportedError, broken);
  CheckCellsAndPoints(output, broken);
  CheckTupleCounts(output, broken);
  const vtkSmartPointer<vtkIdTypeArray> ids = InputIds(input, filter, output, broken);
  CheckOriginalIds(input, filter, output, ids, broken);
  CheckLocks(input, filter, ids, filterReportedError, broken);

  // Orientation: an oriented soup stays one.
  const std::vector<Tri> inputTriangles = GetTriangles(input);
  if (input->GetNumberOfStrips() == 0 &&
      static_cast<vtkIdType>(inputTriangles.size()) == input->GetNumberOfPolys() &&
      IsOrientedSoup(inputTriangles) && !IsOrientedSoup(GetTriangles(output)))
  {
    broken.push_back("the input triangles use each directed edge at most once (and no two share "
                     "their three points) but the output triangles do not");
  }
  return broken;
}

} // namespace testing
} // namespace colordecimation
