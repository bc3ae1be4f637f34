// color-decimate-field-study: how well the simplifiers keep a one-component point field (a
// simulated temperature). The input is the flat square [-1,1]^2 of N x N quads, each cut in
// two triangles (ColorDecimation::Meshes' FlatGrid), with the float point array
// "Temperature" = cos(k x) cos(k y), k = 3 pi (three periods each way), as its only array and
// active scalars. It is decimated at the reduction R by
//  - vtkColorHalfEdgeDecimation at its defaults and with the paper's method, with Temperature
//    as the colour array (a grey value, stretched from its range);
//  - vtkColorHalfEdgeDecimation with the attribute quadric at colour weights 0.1 to 10;
//  - vtkColorHalfEdgeDecimation with the colour quadric and full collapses (OptimalPlacement,
//    which moves the survivor and gives it a new field value) at colour weights 1 and 0.1, on
//    both schedules;
//  - vtkQuadricDecimation with its attribute error metric on the scalars (QuadricPeer.h);
//  - vtkQuadricDecimation on geometry alone (each output point then takes the Temperature of
//    the nearest input point, as color-decimate-run does for colours);
// and each result is measured by Metro (ColorDecimationMetro.h) with the field: one row per
// run with its triangles, the two-sided field RMS as % of the field's range and the
// two-sided geometric RMS as % of the bounding-box diagonal.
#include "ColorDecimationMetro.h"

#include "ColorDecimationMeshes.h"
#include "CommandLine.h"
#include "JsonOutput.h"
#include "MeshColors.h"
#include "QuadricPeer.h"
#include "SmpBackend.h"

#include "vtkColorHalfEdgeDecimation.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkQuadricDecimation.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using namespace colordecimation::tools;

const char* const Program = "color-decimate-field-study";
const char* const FieldName = "Temperature";

struct Settings
{
  long long Size = 200;
  double Reduction = 0.9;
  colordecimation::metro::Options Metro;
  std::string JsonPath;
};

/// One simplification and its measures.
struct Run
{
  std::string Method;
  vtkSmartPointer<vtkPolyData> Output;
  colordecimation::metro::Result Measures;
};

/// The flat square of `size` x `size` quads with Temperature = cos(3 pi x) cos(3 pi y).
vtkSmartPointer<vtkPolyData> MakeInput(int size)
{
  auto mesh =
    colordecimation::meshes::FlatGrid(size, size, colordecimation::meshes::Pattern::Constant);
  mesh->GetPointData()->Initialize();
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName(FieldName);
  temperature->SetNumberOfTuples(mesh->GetNumberOfPoints());
  const double k = 3 * vtkMath::Pi();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    temperature->SetValue(i, static_cast<float>(std::cos(k * p[0]) * std::cos(k * p[1])));
  }
  mesh->GetPointData()->SetScalars(temperature);
  return mesh;
}

/// vtkColorHalfEdgeDecimation at `reduction` with Temperature as the colour array, after
/// `configure`.
template <typename Configure>
vtkSmartPointer<vtkPolyData> HalfEdge(vtkPolyData* input, double reduction, Configure configure)
{
  vtkNew<vtkColorHalfEdgeDecimation> filter;
  filter->SetInputData(input);
  filter->SetTargetReduction(reduction);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, FieldName);
  configure(filter.Get());
  filter->Update();
  return filter->GetOutput();
}

/// vtkQuadricDecimation at `reduction`, with its attribute metric on the scalars or without
/// (then Temperature comes from the nearest input point).
vtkSmartPointer<vtkPolyData> Quadric(vtkPolyData* input, double reduction, bool attributes)
{
  vtkNew<vtkQuadricDecimation> filter;
  filter->SetInputData(input);
  filter->SetTargetReduction(reduction);
  ConfigureQuadricPeer(filter, attributes);
  filter->Update();
  vtkSmartPointer<vtkPolyData> output = filter->GetOutput();
  if (!attributes)
  {
    TransferNearestColors(input, output, FieldName);
  }
  return output;
}

/// The attribute-quadric runs (on the defaults' other settings), one per colour weight.
void AddAttributeQuadricRuns(vtkPolyData* input, double reduction, std::vector<Run>& runs)
{
  for (double weight : { 0.1, 0.3, 1.0, 3.0, 10.0 })
  {
    auto configure = [weight](vtkColorHalfEdgeDecimation* filter)
    {
      filter->SetErrorMetricToAttributeQuadric();
      filter->SetColorWeight(weight);
    };
    char name[64];
    std::snprintf(name, sizeof(name), "attribute quadric, ColorWeight %g", weight);
    runs.push_back({ name, HalfEdge(input, reduction, configure), {} });
  }
}

/// The colour quadric with full collapses (OptimalPlacement: the survivor moves, and its field
/// value with it, as vtkQuadricDecimation's do), at two colour weights, on either schedule.
void AddPlacementRuns(vtkPolyData* input, double reduction, std::vector<Run>& runs)
{
  for (const double weight : { 1.0, 0.1 })
  {
    for (const bool greedy : { false, true })
    {
      auto configure = [weight, greedy](vtkColorHalfEdgeDecimation* filter)
      {
        filter->SetErrorMetricToColorQuadric();
        filter->OptimalPlacementOn();
        filter->SetColorWeight(weight);
        filter->SetCollapseSchedule(greedy ? vtkColorHalfEdgeDecimation::Greedy
                                           : vtkColorHalfEdgeDecimation::Batched);
      };
      char name[96];
      std::snprintf(name, sizeof(name), "colour quadric, OptimalPlacement, ColorWeight %g, %s",
                    weight, greedy ? "Greedy" : "Batched");
      runs.push_back({ name, HalfEdge(input, reduction, configure), {} });
    }
  }
}

/// Every run on `input`.
std::vector<Run> Simplify(vtkPolyData* input, double reduction)
{
  std::vector<Run> runs;
  runs.push_back({ "vtkColorHalfEdgeDecimation, defaults",
                   HalfEdge(input, reduction, [](vtkColorHalfEdgeDecimation*) {}),
                   {} });
  runs.push_back(
    { "the paper's method (half-edge-color)",
      HalfEdge(input, reduction, [](vtkColorHalfEdgeDecimation* f) { f->SetPaperDefaults(); }),
      {} });
  AddAttributeQuadricRuns(input, reduction, runs);
  AddPlacementRuns(input, reduction, runs);
  runs.push_back({ "vtkQuadricDecimation, attributes on", Quadric(input, reduction, true), {} });
  runs.push_back({ "vtkQuadricDecimation, attributes off", Quadric(input, reduction, false), {} });
  return runs;
}

/// The table (Markdown) of the runs.
void PrintTable(const std::vector<Run>& runs)
{
  std::printf("| method | triangles | field RMS, %% of range | geometric RMS, %% of diagonal |\n");
  std::printf("|---|---:|---:|---:|\n");
  for (const Run& run : runs)
  {
    std::printf("| %s | %lld | %.4f | %.5f |\n", run.Method.c_str(),
                run.Measures.SimplifiedTriangles, run.Measures.Field.TwoSidedPercent.Rms,
                run.Measures.RmsPercent);
  }
}

/// Every run's method and Metro JSON.
Json ToJson(const Settings& settings, const std::vector<Run>& runs)
{
  Json json;
  json["size"] = settings.Size;
  json["reduction"] = settings.Reduction;
  json["runs"] = Json::array();
  for (const Run& run : runs)
  {
    Json row;
    row["method"] = run.Method;
    row["metro"] = Json::parse(colordecimation::metro::ToJson(run.Measures));
    json["runs"].push_back(row);
  }
  return json;
}

int RunStudy(const Settings& settings)
{
  vtkSmartPointer<vtkPolyData> input = MakeInput(static_cast<int>(settings.Size));
  std::vector<Run> runs = Simplify(input, settings.Reduction);
  for (Run& run : runs)
  {
    run.Measures = colordecimation::metro::Compare(input, run.Output, settings.Metro);
    if (!run.Measures.Ok)
    {
      std::cerr << Program << ": " << run.Method << ": " << run.Measures.Error << "\n";
      return 1;
    }
  }
  PrintTable(runs);
  std::string error;
  if (!settings.JsonPath.empty() &&
      !WriteJsonFile(ToJson(settings, runs), settings.JsonPath, error))
  {
    std::cerr << Program << ": " << error << "\n";
    return 1;
  }
  return 0;
}

void AddOptions(CLI::App& app, Settings& settings)
{
  const auto whole = [](long long& value, long long lo, long long hi)
  {
    return [&value, lo, hi](const std::string& text)
    {
      long long parsed = 0;
      const bool ok = ParseWholeNumber(text, parsed) && parsed >= lo && parsed <= hi;
      value = ok ? parsed : value;
      return ok;
    };
  };
  AddValue(app, "--size", whole(settings.Size, 2, 4000),
           FixedComplaint("--size wants a whole number from 2 to 4000"),
           "quads along each side of the square (default 200: 80,000 triangles)")
    ->type_name("N");
  AddNumber(app, "--reduction", settings.Reduction, 0.0, 1.0, BadValueComplaint("--reduction"),
            "TargetReduction of every run (default 0.9)")
    ->type_name("R");
  AddValue(app, "--samples", whole(settings.Metro.Samples, 1, 100000000),
           FixedComplaint("--samples wants a positive whole number"),
           "Metro's samples per side (default 200000)")
    ->type_name("N");
  app.add_option("--json", settings.JsonPath, "also write every run's Metro JSON to FILE")
    ->type_name("FILE");
}
} // namespace

int main(int argc, char* argv[])
{
  UseAllCoresByDefault(); // vtkSMPTools on all cores unless asked otherwise
  CLI::App app("Decimates a flat square carrying the point field Temperature = cos(3 pi x) "
               "cos(3 pi y)\nwith vtkColorHalfEdgeDecimation and vtkQuadricDecimation, and "
               "prints, for each run, its\ntriangles, the field's two-sided RMS difference "
               "(% of its range) and the geometric\ntwo-sided RMS distance (% of the diagonal) "
               "by Metro's method (color-decimate-metro --field).",
               Program);
  SetUpCommandLine(app,
                   "Usage: color-decimate-field-study [--size N] [--reduction R] "
                   "[--samples N] [--json FILE]");
  Settings settings;
  settings.Metro.Field = FieldName;
  AddOptions(app, settings);
  const int status = ParseCommandLine(app, argc, argv);
  return status >= 0 ? status : RunStudy(settings);
}
