#include "ColorDecimationInvariants.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <sstream>
#include <utility>

namespace colordecimation
{
namespace hostile
{
namespace
{

void OnEvent(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* self = static_cast<EventCounter*>(clientData);
  const std::string text = callData ? static_cast<const char*>(callData) : "";
  if (event == vtkCommand::ErrorEvent)
  {
    ++self->Errors;
    self->ErrorTexts.push_back(text);
  }
  else
  {
    ++self->Warnings;
    self->WarningTexts.push_back(text);
  }
}

template <typename... T>
std::string Say(const T&... parts)
{
  std::ostringstream os;
  (void)std::initializer_list<int>{ ((os << parts), 0)... };
  return os.str();
}

/// Bit-exact comparison of tuple `i` of `out` with tuple `j` of `in` (same type and width).
bool SameTuple(vtkDataArray* out, vtkIdType i, vtkDataArray* in, vtkIdType j)
{
  const int nc = out->GetNumberOfComponents();
  const int size = out->GetDataTypeSize();
  return std::memcmp(out->GetVoidPointer(i * nc), in->GetVoidPointer(j * nc),
                     static_cast<size_t>(nc) * size) == 0;
}

std::array<long long, 3> Canonical(std::array<long long, 3> t)
{
  // Rotate so that the smallest id comes first; the orientation is kept.
  while (t[0] > t[1] || t[0] > t[2])
  {
    t = { t[1], t[2], t[0] };
  }
  return t;
}

} // namespace

EventCounter::EventCounter()
  : Callback(vtkSmartPointer<vtkCallbackCommand>::New())
{
  this->Callback->SetCallback(OnEvent);
  this->Callback->SetClientData(this);
}

EventCounter::~EventCounter() = default;

void EventCounter::Observe(vtkObject* object)
{
  object->AddObserver(vtkCommand::WarningEvent, this->Callback);
  object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
}

bool EventCounter::HasWarning(const std::string& part) const
{
  return std::any_of(this->WarningTexts.begin(), this->WarningTexts.end(),
                     [&](const std::string& s) { return s.find(part) != std::string::npos; });
}

bool EventCounter::HasError(const std::string& part) const
{
  return std::any_of(this->ErrorTexts.begin(), this->ErrorTexts.end(),
                     [&](const std::string& s) { return s.find(part) != std::string::npos; });
}

void EventCounter::Clear()
{
  this->Warnings = this->Errors = 0;
  this->WarningTexts.clear();
  this->ErrorTexts.clear();
}

std::vector<std::array<long long, 3>> TrianglesOf(vtkPolyData* mesh)
{
  std::vector<std::array<long long, 3>> triangles;
  if (!mesh->GetPolys())
  {
    return triangles;
  }
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n == 3)
    {
      triangles.push_back({ ids[0], ids[1], ids[2] });
    }
  }
  return triangles;
}

bool IsOrientedSoup(const std::vector<std::array<long long, 3>>& triangles)
{
  std::set<std::pair<long long, long long>> directed;
  std::set<std::array<long long, 3>> vertexSets;
  for (const auto& t : triangles)
  {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!directed.insert({ t[k], t[(k + 1) % 3] }).second)
      {
        return false;
      }
    }
    std::array<long long, 3> sorted = t;
    std::sort(sorted.begin(), sorted.end());
    if (!vertexSets.insert(sorted).second)
    {
      return false;
    }
  }
  return true;
}

std::vector<std::array<long long, 3>> OriginalTriangles(vtkPolyData* output)
{
  std::vector<std::array<long long, 3>> triangles = TrianglesOf(output);
  vtkIdTypeArray* original =
    vtkIdTypeArray::SafeDownCast(output->GetPointData()->GetArray("vtkOriginalPointIds"));
  for (auto& t : triangles)
  {
    for (auto& id : t)
    {
      id = original && id >= 0 && id < original->GetNumberOfValues() ? original->GetValue(id) : -1;
    }
    t = Canonical(t);
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

std::vector<std::string> CheckInvariants(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter,
                                         vtkPolyData* output, bool filterReportedError)
{
  std::vector<std::string> broken;
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

  // Cells: triangles only, valid and distinct ids.
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

  // Points.
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

  // Attribute tuple counts.
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

  // Original point ids, and bit-exact copies of the points and point data. With the
  // ColorQuadric metric's OptimalPlacement, points move and take a new colour: their
  // coordinates and the colour array are then not compared.
  const bool moves = filter->GetOptimalPlacement() &&
    filter->GetErrorMetric() == vtkColorHalfEdgeDecimation::ColorQuadric;
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
  const char* idsName = filter->GetOriginalPointIdsArrayName();
  if (filter->GetGenerateOriginalPointIds() && idsName && *idsName && numOutPoints > 0)
  {
    vtkIdTypeArray* original = vtkIdTypeArray::SafeDownCast(outPD->GetAbstractArray(idsName));
    if (!original)
    {
      broken.push_back(Say("no vtkIdTypeArray '", idsName, "' in the output"));
    }
    else if (original->GetNumberOfTuples() == numOutPoints &&
             original->GetNumberOfComponents() == 1)
    {
      std::vector<char> seen(static_cast<size_t>(numInPoints), 0);
      bool idsValid = true;
      for (vtkIdType i = 0; i < numOutPoints && idsValid; ++i)
      {
        const vtkIdType j = original->GetValue(i);
        if (j < 0 || j >= numInPoints || seen[j])
        {
          broken.push_back(
            Say("original point id ", j, " of output point ", i, " is out of range or repeated"));
          idsValid = false;
        }
        else
        {
          seen[j] = 1;
        }
      }
      vtkDataArray* inPoints = input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
      vtkDataArray* outPoints = output->GetPoints() ? output->GetPoints()->GetData() : nullptr;
      if (idsValid && inPoints && outPoints && !moves)
      {
        if (inPoints->GetDataType() != outPoints->GetDataType())
        {
          broken.push_back("the output points' data type differs from the input's");
        }
        else
        {
          for (vtkIdType i = 0; i < numOutPoints; ++i)
          {
            if (!SameTuple(outPoints, i, inPoints, original->GetValue(i)))
            {
              broken.push_back(
                Say("output point ", i, " is not input point ", original->GetValue(i)));
              break;
            }
          }
        }
      }
      vtkPointData* inPD = input->GetPointData();
      for (int a = 0; idsValid && a < outPD->GetNumberOfArrays(); ++a)
      {
        vtkDataArray* out = outPD->GetArray(a);
        if (!out || !out->GetName() || std::strcmp(out->GetName(), idsName) == 0 ||
            (moves && (out->GetName() == colorName || out == outPD->GetScalars())))
        {
          continue;
        }
        vtkDataArray* in = inPD->GetArray(out->GetName());
        if (!in)
        {
          continue;
        }
        if (in->GetDataType() != out->GetDataType() ||
            in->GetNumberOfComponents() != out->GetNumberOfComponents())
        {
          broken.push_back(
            Say("output point array '", out->GetName(), "' changed its type or width"));
          continue;
        }
        for (vtkIdType i = 0; i < std::min(numOutPoints, out->GetNumberOfTuples()); ++i)
        {
          const vtkIdType j = original->GetValue(i);
          if (j >= in->GetNumberOfTuples())
          {
            broken.push_back(Say("output point array '", out->GetName(), "' tuple ", i,
                                 " was copied from input tuple ", j, " but that array has only ",
                                 in->GetNumberOfTuples(), " tuples"));
            break;
          }
          if (!SameTuple(out, i, in, j))
          {
            broken.push_back(Say("output point array '", out->GetName(), "' tuple ", i,
                                 " is not input tuple ", j));
            break;
          }
        }
      }
    }
  }

  // Orientation: an oriented soup stays one.
  const auto inputTriangles = TrianglesOf(input);
  if (input->GetNumberOfStrips() == 0 &&
      static_cast<vtkIdType>(inputTriangles.size()) == input->GetNumberOfPolys() &&
      IsOrientedSoup(inputTriangles) && !IsOrientedSoup(TrianglesOf(output)))
  {
    broken.push_back("the input triangles use each directed edge at most once (and no two share "
                     "their three points) but the output triangles do not");
  }
  return broken;
}

} // namespace hostile
} // namespace colordecimation
