// color-decimate-run: one simplification of a mesh by one method, for the fidelity benchmark
// (Tools/fidelity-benchmark.py): vtkColorHalfEdgeDecimation with any of its metrics and
// options, vtkQuadricDecimation (attribute error metric on or off), meshoptimizer's
// meshopt_simplify (the native library) or its current attribute-aware simplifiers (the npm
// package's WebAssembly build, run with node: MeshOptimizerJS.h); writes the result and, as
// JSON, the time, the peak memory and the metric's bytes per vertex.
#include "CommandLine.h"
#include "IndexedMesh.h"
#include "JsonOutput.h"
#include "MeshColors.h"
#include "MeshIO.h"
#include "MeshOptimizerJS.h"
#include "ProcessMemory.h"
#include "QuadricPeer.h"

#include "vtkCleanPolyData.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkQuadricDecimation.h"

#ifndef COLORDECIMATION_WITH_MESHOPTIMIZER
#define COLORDECIMATION_WITH_MESHOPTIMIZER 0
#endif
#if COLORDECIMATION_WITH_MESHOPTIMIZER
#include "MeshOptimizer.h"
#include "SmpBackend.h"
#endif

#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace colordecimation::tools;

namespace
{
const char* const Program = "color-decimate-run";

const char* const Methods =
  "Methods:\n"
  "  defaults          vtkColorHalfEdgeDecimation at its defaults (the default)\n"
  "  paper             vtkColorHalfEdgeDecimation with SetPaperDefaults(): the paper's method\n"
  "  half-edge-color, geometry, color-quadric, attribute-quadric\n"
  "                    vtkColorHalfEdgeDecimation with that metric on the paper's other\n"
  "                    settings (the weights and the schedule given apply on top)\n"
  "  vtk-quadric       vtkQuadricDecimation (--attributes: its attribute error metric on,\n"
  "                    with the colours as scalars; without, the output has no colour and\n"
  "                    gets the colour of the nearest input vertex, after the timing)\n"
  "  meshopt           meshoptimizer's meshopt_simplify, the native library (geometry only;\n"
  "                    the output keeps input vertices, with all their point data)\n"
  "  meshopt-attr      meshoptimizer 1.3's simplifyWithAttributes, the colour (RGB in [0,1])\n"
  "                    as 3 attributes (--attribute-weights); the output keeps input vertices\n"
  "  meshopt-update    meshoptimizer 1.3's simplifyWithUpdate: the same, and the kept\n"
  "                    vertices' positions and colours are moved\n"
  "  meshopt-prune     meshopt-attr with the Prune flag (small disconnected pieces may be\n"
  "                    removed whole)\n"
  "meshopt-attr, -update and -prune run the npm package meshoptimizer (WebAssembly) with\n"
  "node; their \"seconds\" is the time of the simplify call measured inside node. They need\n"
  "node on PATH and the package (npm ci --prefix Tools/MeshOptimizerJS); without, the tool\n"
  "says why and exits with status 4.";

/// Exit status when node or the npm package of meshopt-attr, -update and -prune is missing.
const int MissingPeer = 4;

struct Settings
{
  std::string Input;
  std::string Output;
  std::string Method = "defaults";
  std::string JsonPath;
  double Reduction = 0.9;
  // vtkColorHalfEdgeDecimation's settings: NaN or empty when not given (then the method's own).
  double GeometryWeight = std::numeric_limits<double>::quiet_NaN();
  double ColorWeight = std::numeric_limits<double>::quiet_NaN();
  double BoundaryWeight = std::numeric_limits<double>::quiet_NaN();
  double EdgeLengthWeight = std::numeric_limits<double>::quiet_NaN();
  double KeptVertexErrorWeight = std::numeric_limits<double>::quiet_NaN();
  std::string Schedule;
  bool Placement = false;
  bool CieLab = false;
  bool Attributes = false;
  bool PreserveBoundary = false;
  bool AbsoluteWeights = false;
  bool Clean = false;
  std::array<double, 3> AttributeWeights = { { 1.0, 1.0, 1.0 } };
};

struct Figures
{
  std::string Method;
  double Seconds = 0;
  long long PeakBytes = -1;
  bool PeakReset = false;
  long long StateBytes = -1;
  double MetricBytesPerVertex = 0;
  std::string MetricBytesNote;
  long long InputPoints = 0, InputTriangles = 0, OutputPoints = 0, OutputTriangles = 0;
  Json Extra = Json::object(); // the method's own figures
};

/// vtkColorHalfEdgeDecimation's methods: at its defaults, at the paper's settings, or one
/// metric (on the paper's other settings), with their ErrorMetric.
const std::pair<const char*, int> OurMethods[] = {
  { "defaults", -1 },
  { "paper", vtkColorHalfEdgeDecimation::HalfEdgeColor },
  { "half-edge-color", vtkColorHalfEdgeDecimation::HalfEdgeColor },
  { "geometry", vtkColorHalfEdgeDecimation::Geometry },
  { "color-quadric", vtkColorHalfEdgeDecimation::ColorQuadric },
  { "attribute-quadric", vtkColorHalfEdgeDecimation::AttributeQuadric },
};

bool IsOurs(const std::string& method)
{
  for (const auto& m : OurMethods)
  {
    if (method == m.first)
    {
      return true;
    }
  }
  return false;
}

/// The methods of meshoptimizer's WebAssembly build and their modes.
const std::pair<const char*, MeshOptimizerJSMode> JSMethods[] = {
  { "meshopt-attr", MeshOptimizerJSMode::Attributes },
  { "meshopt-update", MeshOptimizerJSMode::Update },
  { "meshopt-prune", MeshOptimizerJSMode::Prune },
};

bool IsMeshOptimizerJS(const std::string& method, MeshOptimizerJSMode* mode = nullptr)
{
  for (const auto& m : JSMethods)
  {
    if (method == m.first)
    {
      if (mode)
      {
        *mode = m.second;
      }
      return true;
    }
  }
  return false;
}

/// --attribute-weights W or W,W,W (red, green, blue): finite numbers >= 0.
bool ParseWeights(const std::string& text, std::array<double, 3>& weights)
{
  std::vector<double> values;
  std::istringstream items(text);
  std::string item;
  double w = 0;
  while (std::getline(items, item, ','))
  {
    if (!ParseNumber(item, w) || w < 0)
    {
      return false;
    }
    values.push_back(w);
  }
  if (values.size() != 1 && values.size() != 3)
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    weights[k] = values[values.size() == 3 ? k : 0];
  }
  return true;
}

/// INPUT, OUTPUT, the method and the JSON.
void AddRunOptions(CLI::App& app, Settings& settings)
{
  app.add_option("INPUT", settings.Input, "the mesh to simplify (a mesh file or demo:)")
    ->required()
    ->type_name("");
  app.add_option("OUTPUT", settings.Output, "the result: .vtp (keeps every array), .ply or .vtk")
    ->required()
    ->type_name("");
  AddValue(
    app, "--method",
    [&settings](const std::string& method)
    {
      settings.Method = method;
      return IsOurs(method) || method == "vtk-quadric" || method == "meshopt" ||
        IsMeshOptimizerJS(method);
    },
    [](const std::string& method) { return "unknown method '" + method + "'"; },
    "the simplifier (default defaults; see Methods below)")
    ->type_name("M");
  AddNumber(app, "--reduction", settings.Reduction, 0.0, 1.0, BadValueComplaint("--reduction"),
            "fraction of triangles to remove (default 0.9)")
    ->type_name("R");
  app.add_option("--json", settings.JsonPath, "write the figures as JSON")->type_name("FILE");
}

/// The settings of the methods.
void AddMethodOptions(CLI::App& app, Settings& settings)
{
  const double any = 1e300; // any finite weight >= 0
  app.add_flag("--placement", settings.Placement,
               "color-quadric: optimal placement (full collapses)");
  app.add_flag("--cielab", settings.CieLab,
               "measure colour in CIELab (the vtkColorHalfEdgeDecimation metrics)");
  AddNumber(app, "--geometry-weight", settings.GeometryWeight, 0.0, any,
            BadValueComplaint("--geometry-weight"), "GeometryWeight (vtkColorHalfEdgeDecimation)")
    ->type_name("W");
  AddNumber(app, "--color-weight", settings.ColorWeight, 0.0, any,
            BadValueComplaint("--color-weight"), "ColorWeight (vtkColorHalfEdgeDecimation)")
    ->type_name("W");
  AddNumber(app, "--boundary-weight", settings.BoundaryWeight, 0.0, any,
            BadValueComplaint("--boundary-weight"), "BoundaryWeight (vtkColorHalfEdgeDecimation)")
    ->type_name("W");
  AddNumber(app, "--edge-length-weight", settings.EdgeLengthWeight, 0.0, any,
            BadValueComplaint("--edge-length-weight"),
            "EdgeLengthWeight (vtkColorHalfEdgeDecimation)")
    ->type_name("W");
  AddNumber(app, "--kept-vertex-error-weight", settings.KeptVertexErrorWeight, 0.0, 1.0,
            BadValueComplaint("--kept-vertex-error-weight"),
            "KeptVertexErrorWeight (vtkColorHalfEdgeDecimation)")
    ->type_name("W");
  AddValue(
    app, "--schedule",
    [&settings](const std::string& schedule)
    {
      settings.Schedule = schedule;
      return schedule == "greedy" || schedule == "batched";
    },
    BadValueComplaint("--schedule"), "greedy or batched (vtkColorHalfEdgeDecimation)")
    ->type_name("S");
  app.add_flag("--preserve-boundary", settings.PreserveBoundary,
               "PreserveBoundary (vtkColorHalfEdgeDecimation)");
  app.add_flag("--no-scene-relative-weights", settings.AbsoluteWeights,
               "SceneRelativeWeights off (vtkColorHalfEdgeDecimation)");
  app.add_flag("--attributes", settings.Attributes, "vtk-quadric: AttributeErrorMetric on");
  AddValue(
    app, "--attribute-weights",
    [&settings](const std::string& text) { return ParseWeights(text, settings.AttributeWeights); },
    BadValueComplaint("--attribute-weights"),
    "meshopt-attr, -update, -prune: weight of each colour attribute,\n"
    "one for all or R,G,B (default 1)")
    ->type_name("W[,W,W]");
  app.add_flag("--clean", settings.Clean,
               "vtk-quadric: merge coincident points and drop the triangles that\n"
               "become degenerate first (vtkCleanPolyData, not timed)");
}

/// INPUT, triangulated (and cleaned for vtk-quadric with --clean); null when unreadable.
vtkSmartPointer<vtkPolyData> ReadInput(const Settings& settings)
{
  std::string description, error;
  vtkSmartPointer<vtkPolyData> read = ReadMesh(settings.Input, description, error);
  if (!read)
  {
    std::cerr << Program << ": " << error << "\n";
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> input = Triangulated(read);
  if (settings.Clean && settings.Method == "vtk-quadric")
  {
    // vtkQuadricDecimation's attribute quadrics cannot be built on zero-area triangles.
    vtkNew<vtkCleanPolyData> cleaner;
    cleaner->SetInputData(input);
    cleaner->PointMergingOn();
    cleaner->SetTolerance(0.0);
    cleaner->ConvertPolysToLinesOff();
    cleaner->ConvertLinesToPointsOff();
    cleaner->Update();
    input = Triangulated(cleaner->GetOutput());
  }
  return input;
}

/// The settings given on the command line, over the method's own.
void ApplyGivenSettings(vtkColorHalfEdgeDecimation* filter, const Settings& settings)
{
  const std::pair<double, void (vtkColorHalfEdgeDecimation::*)(double)> weights[] = {
    { settings.GeometryWeight, &vtkColorHalfEdgeDecimation::SetGeometryWeight },
    { settings.ColorWeight, &vtkColorHalfEdgeDecimation::SetColorWeight },
    { settings.BoundaryWeight, &vtkColorHalfEdgeDecimation::SetBoundaryWeight },
    { settings.EdgeLengthWeight, &vtkColorHalfEdgeDecimation::SetEdgeLengthWeight },
    { settings.KeptVertexErrorWeight, &vtkColorHalfEdgeDecimation::SetKeptVertexErrorWeight },
  };
  for (const auto& weight : weights)
  {
    if (!std::isnan(weight.first))
    {
      (filter->*weight.second)(weight.first);
    }
  }
  if (!settings.Schedule.empty())
  {
    filter->SetCollapseSchedule(settings.Schedule == "batched"
                                  ? vtkColorHalfEdgeDecimation::Batched
                                  : vtkColorHalfEdgeDecimation::Greedy);
  }
  if (settings.Placement)
  {
    filter->OptimalPlacementOn();
  }
  if (settings.CieLab)
  {
    filter->SetColorSpaceToCIELab();
  }
  if (settings.PreserveBoundary)
  {
    filter->PreserveBoundaryOn();
  }
  if (settings.AbsoluteWeights)
  {
    filter->SceneRelativeWeightsOff();
  }
}

vtkSmartPointer<vtkPolyData> SimplifyOurs(vtkPolyData* input, const Settings& settings,
                                          Figures& figures)
{
  vtkNew<vtkColorHalfEdgeDecimation> filter;
  filter->SetInputData(input);
  filter->SetTargetReduction(settings.Reduction);
  for (const auto& method : OurMethods)
  {
    if (settings.Method == method.first && method.second >= 0)
    {
      filter->SetPaperDefaults(); // a named metric on the paper's other settings
      filter->SetErrorMetric(method.second);
    }
  }
  ApplyGivenSettings(filter, settings);
  filter->Update();
  figures.StateBytes = filter->GetStateMemory();
  switch (filter->GetErrorMetric())
  {
    case vtkColorHalfEdgeDecimation::ColorQuadric:
      figures.MetricBytesPerVertex = 112;
      figures.MetricBytesNote = "28 floats (6-D quadric)";
      break;
    case vtkColorHalfEdgeDecimation::AttributeQuadric:
      figures.MetricBytesPerVertex = 92;
      figures.MetricBytesNote = "23 floats (attribute quadric)";
      break;
    default:
      figures.MetricBytesPerVertex = 48;
      figures.MetricBytesNote = "12 floats (quadric 10, importance, max colour distance)";
  }
  return filter->GetOutput();
}

vtkSmartPointer<vtkPolyData> SimplifyWithQuadric(vtkPolyData* input, const Settings& settings,
                                                 Figures& figures)
{
  vtkNew<vtkQuadricDecimation> filter;
  filter->SetInputData(input);
  filter->SetTargetReduction(settings.Reduction);
  ConfigureQuadricPeer(filter, settings.Attributes);
  filter->Update();
  // vtkQuadricDecimation keeps per vertex a sparse quadric of 11 + 4 m doubles (m the
  // attribute components: 3 for RGB).
  vtkDataArray* colors = input->GetPointData()->GetScalars();
  const int m = settings.Attributes && colors ? colors->GetNumberOfComponents() : 0;
  figures.MetricBytesPerVertex = 8.0 * (11 + 4 * m);
  figures.MetricBytesNote = std::to_string(11 + 4 * m) + " doubles (sparse quadric)";
  return filter->GetOutput();
}

/// meshopt-attr, -update or -prune: its figures are node's (the simplify call timed inside node,
/// node's peak memory); null and the message printed when it failed.
vtkSmartPointer<vtkPolyData> SimplifyWithJS(vtkPolyData* input, const Settings& settings,
                                            Figures& figures)
{
  MeshOptimizerJSSettings js;
  IsMeshOptimizerJS(settings.Method, &js.Mode);
  js.Reduction = settings.Reduction;
  js.Weights = settings.AttributeWeights;
  const MeshOptimizerJSResult result = SimplifyWithMeshOptimizerJS(input, js);
  if (!result.Error.empty())
  {
    std::cerr << Program << ": " << settings.Method << ": " << result.Error << "\n";
    return nullptr;
  }
  figures.Seconds = result.Seconds;
  figures.PeakBytes = result.PeakBytes;
  // meshoptimizer's simplifier keeps per vertex a position quadric and an attribute quadric
  // of 11 floats each and a gradient of 4 floats per attribute.
  figures.MetricBytesPerVertex = 4 * (11 + 11 + 4 * 3);
  figures.MetricBytesNote = "34 floats (position and attribute quadrics, 3 gradients)";
  Json& extra = figures.Extra;
  extra["peer"] = MeshOptimizerJSDescription();
  extra["function"] = MeshOptimizerJSFunction(js.Mode);
  extra["seconds_measured"] =
    "inside node around the simplify call (WebAssembly, compiled before it)";
  extra["cpu_seconds"] = result.CpuSeconds;
  extra["round_trip_seconds"] = result.RoundTripSeconds;
  extra["peak_measured"] = "node's peak RSS above its RSS before the call";
  extra["attribute_weights"] = settings.AttributeWeights;
  extra["target_error"] = result.TargetError;
  extra["result_error"] = result.ResultError;
  return MakeMeshOptimizerJSOutput(input, result);
}

/// The method's run, timed, with its peak memory.
vtkSmartPointer<vtkPolyData> Simplify(vtkPolyData* input, const Settings& settings,
                                      Figures& figures)
{
  if (IsMeshOptimizerJS(settings.Method))
  {
    return SimplifyWithJS(input, settings, figures);
  }
  vtkSmartPointer<vtkPolyData> output;
  PeakMemoryProbe probe;
  const auto start = std::chrono::steady_clock::now();
  if (IsOurs(settings.Method))
  {
    output = SimplifyOurs(input, settings, figures);
  }
  else if (settings.Method == "vtk-quadric")
  {
    output = SimplifyWithQuadric(input, settings, figures);
  }
#if COLORDECIMATION_WITH_MESHOPTIMIZER
  else
  {
    output = MeshOnKeptTriangles(input, SimplifyWithMeshOptimizer(input, settings.Reduction));
    // meshopt_simplify keeps a quadric of 11 floats per vertex (and other per-vertex
    // tables: remap, kind, adjacency).
    figures.MetricBytesPerVertex = 44;
    figures.MetricBytesNote = "11 floats (quadric)";
  }
#endif
  figures.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  figures.PeakBytes = probe.PeakAboveBaseline();
  figures.PeakReset = probe.PeakWasReset();
  return output;
}

Json ToJson(const Figures& f)
{
  Json json;
  json["method"] = f.Method;
  json["seconds"] = f.Seconds;
  json["peak_bytes"] = f.PeakBytes;
  json["peak_reset"] = f.PeakReset;
  json["state_bytes"] = f.StateBytes;
  json["metric_bytes_per_vertex"] = f.MetricBytesPerVertex;
  json["metric_bytes_note"] = f.MetricBytesNote;
  json["input_points"] = f.InputPoints;
  json["input_triangles"] = f.InputTriangles;
  json["output_points"] = f.OutputPoints;
  json["output_triangles"] = f.OutputTriangles;
  json.update(f.Extra);
  return json;
}

/// Reads, simplifies, writes OUTPUT and the figures; the exit status.
int Run(const Settings& settings)
{
  vtkSmartPointer<vtkPolyData> input = ReadInput(settings);
  if (!input)
  {
    return 1;
  }
  Figures figures;
  figures.Method = settings.Method;
  figures.InputPoints = input->GetNumberOfPoints();
  figures.InputTriangles = input->GetNumberOfPolys();
  vtkSmartPointer<vtkPolyData> output = Simplify(input, settings, figures);
  if (!output)
  {
    return 1;
  }
  if (settings.Method == "vtk-quadric" && !settings.Attributes)
  {
    TransferNearestColors(input, output);
  }
  figures.OutputPoints = output->GetNumberOfPoints();
  figures.OutputTriangles = output->GetNumberOfPolys();
  std::string error;
  if (!WriteMesh(output, settings.Output, "", error))
  {
    std::cerr << Program << ": " << error << "\n";
    return 1;
  }
  const Json json = ToJson(figures);
  std::cout << JsonText(json) << "\n";
  if (!settings.JsonPath.empty() && !WriteJsonFile(json, settings.JsonPath, error))
  {
    std::cerr << Program << ": " << error << "\n";
    return 1;
  }
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  UseAllCoresByDefault(); // vtkSMPTools on all cores unless asked otherwise
  CLI::App app("Simplifies INPUT with one method and writes OUTPUT (.vtp keeps every array; "
               ".ply, .vtk),\nand prints its time, peak memory and metric bytes per vertex as "
               "JSON.",
               Program);
  SetUpCommandLine(app, "Usage: color-decimate-run INPUT OUTPUT --method M [options]");
  Settings settings;
  AddRunOptions(app, settings);
  AddMethodOptions(app, settings);
  app.footer(Methods);
  const int status = ParseCommandLine(app, argc, argv);
  if (status >= 0)
  {
    return status;
  }
  if (!COLORDECIMATION_WITH_MESHOPTIMIZER && settings.Method == "meshopt")
  {
    std::cerr << Program << ": built without meshoptimizer\n";
    return 3;
  }
  if (IsMeshOptimizerJS(settings.Method) && !MeshOptimizerJSUnavailable().empty())
  {
    std::cerr << Program << ": " << settings.Method << " not run: " << MeshOptimizerJSUnavailable()
              << "\n";
    return MissingPeer;
  }
  return Run(settings);
}
