// The runner of ColorDecimationTestUtilities.h: the registered cases, failed checks, the
// recorder of warnings and errors, and running the filter.
#include "ColorDecimationTestUtilities.h"

#include "ColorDecimationInvariants.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>

namespace colordecimation
{
namespace testing
{
namespace
{
int Failures = 0;
int Skips = 0; ///< cases that skipped themselves (SkipTestCase)
constexpr int MaximumPrintedFailures = 40;

struct RegisteredCase
{
  std::string Name;
  void (*Function)();
};

/// The cases of this executable, in the order of their definitions.
std::vector<RegisteredCase>& Registry()
{
  static std::vector<RegisteredCase> cases;
  return cases;
}

/// Run one case; prints PASS, SKIP or FAIL with its name.
void RunCase(const RegisteredCase& c)
{
  const int before = Failures;
  const int skipsBefore = Skips;
  try
  {
    c.Function();
  }
  catch (const std::exception& e)
  {
    ReportFailure(__FILE__, __LINE__, c.Name.c_str(), std::string("exception: ") + e.what());
  }
  std::cout << (Failures != before ? "FAIL " : Skips != skipsBefore ? "SKIP " : "PASS ") << c.Name;
  if (Failures != before)
  {
    std::cout << " (" << Failures - before << " failed checks)";
  }
  std::cout << std::endl;
}

/// A hash of a data array's values (as doubles, bit for bit), its name and its shape.
void HashArray(vtkAbstractArray* abstract, uint64_t& hash)
{
  const auto mix = [&hash](uint64_t value)
  { hash ^= value + 0x9e3779b97f4a7c15ULL + (hash << 6) + (hash >> 2); };
  if (!abstract)
  {
    mix(0);
    return;
  }
  mix(std::hash<std::string>()(abstract->GetName() ? abstract->GetName() : ""));
  mix(static_cast<uint64_t>(abstract->GetNumberOfValues()));
  mix(static_cast<uint64_t>(abstract->GetDataType()));
  if (auto* array = vtkDataArray::SafeDownCast(abstract))
  {
    const int comps = array->GetNumberOfComponents();
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < comps; ++c)
      {
        const double value = array->GetComponent(t, c);
        uint64_t bits;
        std::memcpy(&bits, &value, sizeof(bits));
        mix(bits);
      }
    }
  }
}

/// A hash of everything in a mesh: points, the four cell arrays, point, cell and field data
/// (values bit for bit, names, attribute roles).
uint64_t Fingerprint(vtkPolyData* mesh)
{
  uint64_t hash = 0;
  HashArray(mesh->GetPoints() ? mesh->GetPoints()->GetData() : nullptr, hash);
  for (vtkCellArray* cells :
       { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    HashArray(cells ? cells->GetConnectivityArray() : nullptr, hash);
    HashArray(cells ? cells->GetOffsetsArray() : nullptr, hash);
  }
  for (vtkFieldData* data :
       { static_cast<vtkFieldData*>(mesh->GetPointData()),
         static_cast<vtkFieldData*>(mesh->GetCellData()), mesh->GetFieldData() })
  {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      HashArray(data->GetAbstractArray(a), hash);
    }
  }
  HashArray(mesh->GetPointData()->GetScalars(), hash);
  HashArray(mesh->GetCellData()->GetScalars(), hash);
  return hash;
}

bool Contains(const std::vector<std::string>& texts, const std::string& part)
{
  return std::any_of(texts.begin(), texts.end(),
                     [&](const std::string& s) { return s.find(part) != std::string::npos; });
}

std::string Joined(const std::vector<std::string>& texts)
{
  std::string all;
  for (const std::string& text : texts)
  {
    all += text;
  }
  return all;
}

void OnEvent(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* self = static_cast<Messages*>(clientData);
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
} // namespace

//------------------------------------------------------------------------------
void ReportFailure(const char* file, int line, const char* condition, const std::string& message)
{
  ++Failures;
  if (Failures <= MaximumPrintedFailures)
  {
    std::cerr << file << ":" << line << ": check failed: " << condition;
    if (!message.empty())
    {
      std::cerr << " -- " << message;
    }
    std::cerr << std::endl;
  }
  else if (Failures == MaximumPrintedFailures + 1)
  {
    std::cerr << "(further failures not printed)" << std::endl;
  }
}

int GetNumberOfFailures()
{
  return Failures;
}

bool RegisterTestCase(const char* name, void (*function)())
{
  for (const RegisteredCase& c : Registry())
  {
    if (c.Name == name)
    {
      std::cerr << "two test cases named '" << name << "'" << std::endl;
      std::abort();
    }
  }
  Registry().push_back({ name, function });
  return true;
}

int RunTestCases(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " CaseName | all | --list" << std::endl;
    return 2;
  }
  const std::string wanted = argv[1];
  if (wanted == "--list")
  {
    for (const RegisteredCase& c : Registry())
    {
      std::cout << c.Name << "\n";
    }
    return 0;
  }
  bool found = false;
  for (const RegisteredCase& c : Registry())
  {
    if (wanted == "all" || wanted == c.Name)
    {
      found = true;
      RunCase(c);
    }
  }
  if (!found)
  {
    std::cerr << "no test case named '" << wanted << "'" << std::endl;
    return 2;
  }
  if (Failures != 0)
  {
    return 1;
  }
  return wanted != "all" && Skips > 0 ? SkipExitCode : 0;
}

void SkipTestCase(const std::string& why)
{
  std::cout << "  skipped: " << why << std::endl;
  ++Skips;
}

//------------------------------------------------------------------------------
bool Messages::HasError(const std::string& part) const
{
  return Contains(this->ErrorTexts, part);
}

bool Messages::HasWarning(const std::string& part) const
{
  return Contains(this->WarningTexts, part);
}

std::string Messages::ErrorText() const
{
  return Joined(this->ErrorTexts);
}

std::string Messages::WarningText() const
{
  return Joined(this->WarningTexts);
}

void Messages::Clear()
{
  this->Errors = this->Warnings = 0;
  this->ErrorTexts.clear();
  this->WarningTexts.clear();
}

EventRecorder::EventRecorder()
  : Callback(vtkSmartPointer<vtkCallbackCommand>::New())
{
  this->Callback->SetCallback(OnEvent);
  this->Callback->SetClientData(static_cast<Messages*>(this));
}

EventRecorder::~EventRecorder() = default;

void EventRecorder::Watch(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
  object->AddObserver(vtkCommand::WarningEvent, this->Callback);
}

void EventRecorder::Unwatch(vtkObject* object)
{
  object->RemoveObserver(this->Callback);
}

//------------------------------------------------------------------------------
RunResult RunFilter(vtkPolyData* input, double reduction, const Configure& configure)
{
  RunResult result;
  result.Filter = vtkSmartPointer<vtkColorHalfEdgeDecimation>::New();
  EventRecorder recorder;
  recorder.Watch(result.Filter);
  result.Filter->SetInputData(input);
  result.Filter->SetTargetReduction(reduction);
  if (configure)
  {
    configure(result.Filter);
  }
  const uint64_t inputBefore = Fingerprint(input);
  result.Filter->Update();
  recorder.Unwatch(result.Filter);
  static_cast<Messages&>(result) = recorder;
  result.Output = vtkSmartPointer<vtkPolyData>::New();
  result.Output->ShallowCopy(result.Filter->GetOutput());
  result.ActualReduction = result.Filter->GetActualReduction();
  result.Collapses = result.Filter->GetNumberOfCollapses();
  result.Broken = CheckInvariants(input, result.Filter, result.Output, result.Errors > 0);
  if (Fingerprint(input) != inputBefore)
  {
    result.Broken.push_back("the input was changed (points, cells, or an array's values)");
  }
  return result;
}

RunResult Decimate(vtkPolyData* input, double reduction, const Configure& configure)
{
  RunResult result = RunFilter(input, reduction, configure);
  for (const std::string& broken : result.Broken)
  {
    ReportFailure(__FILE__, __LINE__, "output invariant", broken);
  }
  return result;
}

} // namespace testing
} // namespace colordecimation
