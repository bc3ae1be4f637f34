/**
 * @file ColorDecimateBench.cxx
 * @brief color-decimate-bench: time and peak memory of vtkColorHalfEdgeDecimation against
 * vtkQuadricDecimation (and meshoptimizer: the native library when built with it, and the
 * current version's attribute-aware simplifiers in WebAssembly when node and the npm package
 * are there) on the same meshes, plus a scale sweep of generated spheres.
 *
 * Run `color-decimate-bench --help` for the options. With --markdown FILE it writes the
 * whole report (docs/BENCHMARK.md) so that the figures can be regenerated in one command.
 */
#include "ColorDecimationMeshes.h"
#include "CommandLine.h"
#include "MeshIO.h"
#include "MeshOptimizerJS.h"
#include "ProcessMemory.h"
#include "QuadricPeer.h"
#include "SmpBackend.h"

#include "vtkColorHalfEdgeDecimation.h"
#include "vtkColorHalfEdgeLevelOfDetail.h"

#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkQuadricDecimation.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkVersion.h"

#ifndef COLORDECIMATION_WITH_MESHOPTIMIZER
#define COLORDECIMATION_WITH_MESHOPTIMIZER 0
#endif
#if COLORDECIMATION_WITH_MESHOPTIMIZER
#include "MeshOptimizer.h"
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <thread>
#include <unistd.h>
#include <vector>

#ifndef COLORDECIMATION_SOURCE_DIR
#define COLORDECIMATION_SOURCE_DIR "."
#endif
#ifndef COLORDECIMATION_BUILD_TYPE
#define COLORDECIMATION_BUILD_TYPE "unknown"
#endif

namespace
{
using namespace colordecimation::tools;
namespace meshes = colordecimation::meshes;

const char* const Program = "color-decimate-bench";
const char* const DefaultRealMesh = "shared/data/redkitchen_tsdf_7mm.ply";
const int DefaultSphereResolution = 700; // 2 * 700 * 698 = 977,200 triangles

enum Method
{
  OursDefaults = 0, // vtkColorHalfEdgeDecimation at its defaults
  OursPaper,        // the paper's method (SetPaperDefaults: HalfEdgeColor, Greedy)
  OursPaperBatched, // the paper's cost with the Batched schedule
  OursGeometry,     // the Geometry metric on the paper's other settings
  QuadricAttributes,
  QuadricGeometry,
  MeshOptimizer,
  MeshOptimizerJSAttributes, // meshoptimizer's WebAssembly build, run by node
  MeshOptimizerJSUpdate,
  MeshOptimizerJSPrune,
  NumberOfMethods
};

bool IsWebAssembly(int method)
{
  return method >= MeshOptimizerJSAttributes && method <= MeshOptimizerJSPrune;
}

MeshOptimizerJSMode ModeOf(int method)
{
  return method == MeshOptimizerJSUpdate ? MeshOptimizerJSMode::Update
    : method == MeshOptimizerJSPrune     ? MeshOptimizerJSMode::Prune
                                         : MeshOptimizerJSMode::Attributes;
}

/// "meshoptimizer 0.18 meshopt_simplify (geometry only)", with the version built in.
const char* NativeMeshOptimizerName()
{
#if COLORDECIMATION_WITH_MESHOPTIMIZER
  static const std::string name = std::string("meshoptimizer ") +
    colordecimation::tools::MeshOptimizerVersion() + " meshopt_simplify (geometry only)";
  return name.c_str();
#else
  return "meshoptimizer meshopt_simplify (geometry only)";
#endif
}

const char* MethodName(int method)
{
  switch (method)
  {
    case OursDefaults:
      return "vtkColorHalfEdgeDecimation, defaults (AttributeQuadric, Batched)";
    case OursPaper:
      return "vtkColorHalfEdgeDecimation, the paper's method (HalfEdgeColor, Greedy)";
    case OursPaperBatched:
      return "vtkColorHalfEdgeDecimation, HalfEdgeColor, Batched schedule";
    case OursGeometry:
      return "vtkColorHalfEdgeDecimation, Geometry, Greedy";
    case QuadricAttributes:
      return "vtkQuadricDecimation, AttributeErrorMetric on (colour as scalars)";
    case QuadricGeometry:
      return "vtkQuadricDecimation, AttributeErrorMetric off";
    case MeshOptimizer:
      return NativeMeshOptimizerName();
    case MeshOptimizerJSAttributes:
      return "meshoptimizer 1.3 simplifyWithAttributes (WebAssembly)";
    case MeshOptimizerJSUpdate:
      return "meshoptimizer 1.3 simplifyWithUpdate (WebAssembly)";
    case MeshOptimizerJSPrune:
      return "meshoptimizer 1.3 simplifyWithAttributes + Prune (WebAssembly)";
    default:
      return "?";
  }
}

const char* MethodShortName(int method)
{
  switch (method)
  {
    case OursDefaults:
      return "defaults";
    case OursPaper:
      return "paper";
    case OursPaperBatched:
      return "HalfEdgeColor batched";
    case OursGeometry:
      return "Geometry";
    case QuadricAttributes:
      return "vtkQD attr on";
    case QuadricGeometry:
      return "vtkQD attr off";
    case MeshOptimizer:
      return "meshopt";
    case MeshOptimizerJSAttributes:
      return "meshopt 1.3 attributes (wasm)";
    case MeshOptimizerJSUpdate:
      return "meshopt 1.3 update (wasm)";
    case MeshOptimizerJSPrune:
      return "meshopt 1.3 prune (wasm)";
    default:
      return "?";
  }
}

struct Options
{
  std::vector<std::string> Meshes;
  double Reduction = 0.9;
  std::vector<long long> Sizes = { 100000, 250000, 1000000, 4000000 };
  bool SizesGiven = false;
  bool NoSweep = false;
  bool NoDefaultMeshes = false;
  int Repeat = 1;
  long long QuadricMax = 1000000;
  bool NoQuadric = false;
  bool NoLod = false;
  long long LodMax = 1000000;
  std::string Markdown;
  std::string Array;
  std::string CommandLine;
};

struct RunResult
{
  bool Ran = false;
  std::string Skipped;   // why it did not run
  std::string Error;     // a VTK error reported by the filter (the run may be incomplete)
  std::string Note;      // how the input was prepared, when it was not run as given
  double Seconds = 0;    // median over the repeats
  double CpuSeconds = 0; // process CPU time of the same runs, median
  long long OutputTriangles = 0;
  long long PeakBytes = -1; // largest over the repeats, above the resident memory before
  long long StateBytes = -1;
  bool PeakReset = true;
  double RoundTripSeconds = 0; // WebAssembly: the whole call, node's start included; median
};

/// The reductions of the levels-of-detail section, finest first.
const double LodLevels[] = { 0.5, 0.75, 0.9, 0.97, 0.99 };
const int NumberOfLevels = 5;

/// The methods of the levels-of-detail section that run once per level.
const int LodSeparateMethods[] = { OursDefaults, QuadricAttributes, MeshOptimizer,
                                   MeshOptimizerJSAttributes };

/// The levels-of-detail section on one mesh (RunLevels).
struct LevelsResult
{
  bool Ran = false;
  std::string Skipped; // why it did not run on this mesh
  RunResult OneRun;    // the run to the coarsest level with the record; its peak spans the
                       // extractions too
  RunResult Extractions[NumberOfLevels]; // each level from the record
  std::string SeparateSkipped[NumberOfMethods];
  RunResult Separate[NumberOfMethods][NumberOfLevels]; // one run per level
  bool Reused[NumberOfMethods] = {}; // the level at --reduction is the Meshes table's run
  bool QuadricCleaned = false;       // vtkQuadricDecimation ran on the cleaned input
};

struct CaseResult
{
  std::string Name;
  std::string Description;
  long long Points = 0;
  long long Triangles = 0;
  RunResult Runs[NumberOfMethods];
  LevelsResult Levels;
};

/// What --help says before the options.
std::string Description()
{
  return "Times vtkColorHalfEdgeDecimation (at its defaults; the paper's method; the paper's\n"
         "cost with the Batched schedule; the Geometry metric) against\n"
         "vtkQuadricDecimation with AttributeErrorMetric on (the colour array as scalars) and\n"
         "off"
#if COLORDECIMATION_WITH_MESHOPTIMIZER
         ", and meshoptimizer's meshopt_simplify (geometry only, for reference)"
#endif
         ",\n"
         "in one process on the same input, and meshoptimizer 1.3's simplifyWithAttributes,\n"
         "simplifyWithUpdate and Prune mode (the npm package's WebAssembly build, run by node\n"
         "and timed inside node; left out when node or the package is missing: npm ci\n"
         "--prefix Tools/MeshOptimizerJS). For each run it prints the filter's own time\n"
         "(wall clock and CPU), the output triangles, vtkQuadricDecimation's time divided by\n"
         "the run's time, the run's time divided by simplifyWithAttributes's (WebAssembly, when\n"
         "it runs), and the peak resident memory of the run above the memory before it\n"
         "(VmHWM after resetting it through /proc/self/clear_refs).\n"
         "Then, on each mesh of up to --lod-max triangles, five levels of detail (reductions\n"
         "0.5, 0.75, 0.9, 0.97, 0.99) from one run with the collapse record and\n"
         "vtkColorHalfEdgeLevelOfDetail, against a run per level of this filter at its\n"
         "defaults, vtkQuadricDecimation (attribute metric on) and meshoptimizer (--no-lod\n"
         "skips them).";
}

/// --sizes LIST: comma-separated triangle counts of at least 8.
void ParseSizes(const std::string& list, Options& options)
{
  options.Sizes.clear();
  options.SizesGiven = true;
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ','))
  {
    long long n = 0;
    if (!ParseCount(item, n) || n < 8)
    {
      throw UsageError("--sizes wants triangle counts such as 100k,1M (got '" + item + "')");
    }
    options.Sizes.push_back(n);
  }
  if (options.Sizes.empty())
  {
    throw UsageError("--sizes needs at least one size (or use --no-sweep)");
  }
}

/// MESH, --demo, and what is measured on them.
void AddMeshOptions(CLI::App& app, Options& options)
{
  app
    .add_option("MESH", options.Meshes,
                "mesh files (.ply, .vtp, .vtu, .vtk, .obj, .stl) or demo: specifications\n"
                "(see color-decimate --help). Without MESH: ../shared/data/\n"
                "redkitchen_tsdf_7mm.ply beside the source tree or the working directory\n"
                "(when present) and the 977,200-triangle coloured UV sphere\n"
                "(UVSphere(700), SharpRegions), then the scale sweep")
    ->type_name("");
  app.add_flag_callback(
    "--demo", [&options] { options.Meshes.push_back("--demo"); },
    "the built-in demo mesh (demo:) as one more MESH");
  AddNumber(app, "--reduction", options.Reduction, 0, 1,
            RuleComplaint("--reduction must be a number from 0 to 1"),
            "fraction of triangles to remove (default 0.9)")
    ->type_name("R");
  app.add_option("--array", options.Array, "colour point array (default: the active scalars)")
    ->type_name("NAME");
  app.add_flag("--no-default-meshes", options.NoDefaultMeshes,
               "without MESH, skip the real mesh and the 977k sphere");
}

/// The sweep, the repeats, the peers and the report.
void AddRunOptions(CLI::App& app, Options& options)
{
  app
    .add_option_function<std::string>(
      "--sizes", [&options](const std::string& list) { ParseSizes(list, options); },
      "triangle counts of the scale sweep of generated UV spheres, e.g.\n"
      "100k,250k,1M,4M (the default); the sweep runs by default only when no\n"
      "MESH is given")
    ->type_name("LIST");
  app.add_flag("--no-sweep", options.NoSweep, "no scale sweep");
  AddValue(
    app, "--repeat",
    [&options](const std::string& text)
    {
      long long n = 0;
      const bool ok = ParseCount(text, n) && n >= 1 && n <= 1000;
      options.Repeat = ok ? static_cast<int>(n) : options.Repeat;
      return ok;
    },
    RuleComplaint("--repeat must be a whole number from 1 to 1000"),
    "runs per method and mesh, in rounds (each method once per round); the\n"
    "median time is reported (default 1)")
    ->type_name("N");
  AddValue(
    app, "--quadric-max",
    [&options](const std::string& text) { return ParseCount(text, options.QuadricMax); },
    RuleComplaint("--quadric-max must be a triangle count such as 1M"),
    "in the sweep, run vtkQuadricDecimation only up to N input triangles\n"
    "(default 1M; 0 = no limit). Given meshes always run it.")
    ->type_name("N");
  app.add_flag("--no-quadric", options.NoQuadric, "skip vtkQuadricDecimation everywhere");
  app.add_flag("--no-lod", options.NoLod,
               "skip the levels-of-detail section (levels 0.5, 0.75, 0.9, 0.97, 0.99 from\n"
               "one run with the collapse record, against a run per level)");
  AddValue(
    app, "--lod-max",
    [&options](const std::string& text) { return ParseCount(text, options.LodMax); },
    RuleComplaint("--lod-max must be a triangle count such as 1M"),
    "run the levels-of-detail section only on meshes of up to N triangles\n"
    "(default 1M: the 977k sphere, not the 1.5M kitchen; 0 = no limit)")
    ->type_name("N");
  app
    .add_option("--markdown", options.Markdown,
                "also write the report as Markdown (e.g. docs/BENCHMARK.md)")
    ->type_name("FILE");
}

bool FileExists(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

std::string Format(const char* format, double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::string MiB(long long bytes)
{
  return bytes < 0 ? std::string("?") : Format("%.1f", bytes / (1024.0 * 1024.0));
}

std::string SizeLabel(long long n)
{
  if (n >= 1000000 && n % 100000 == 0)
  {
    return Format(n % 1000000 == 0 ? "%.0fM" : "%.1fM", n / 1e6);
  }
  if (n >= 1000 && n % 1000 == 0)
  {
    return Format("%.0fk", n / 1e3);
  }
  return WithThousands(n);
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

//------------------------------------------------------------------------------
// One run of each method. Each returns the filter's own time; the probe around it measures
// the peak memory; everything the run allocated is freed before it returns.

struct Single
{
  double Seconds = 0;
  double CpuSeconds = 0;
  long long OutputTriangles = 0;
  long long StateBytes = -1;
  long long PeakBytes = -1; // measured by the run itself (node's), instead of the probe's
  double RoundTripSeconds = 0;
  bool Ok = true;
  std::string Error;
};

/// The settings of this filter's rows.
void ConfigureOurs(int method, vtkColorHalfEdgeDecimation* filter)
{
  if (method == OursDefaults)
  {
    return;
  }
  filter->SetPaperDefaults();
  if (method == OursPaperBatched)
  {
    filter->SetCollapseScheduleToBatched();
  }
  if (method == OursGeometry)
  {
    filter->SetErrorMetricToGeometry();
  }
}

Single RunOurs(vtkPolyData* mesh, int method, double reduction)
{
  Single result;
  MessageCatcher::Scope quiet; // the filter's warnings (e.g. no colours) are not timing data
  vtkNew<vtkColorHalfEdgeDecimation> filter;
  filter->SetInputData(mesh);
  filter->SetTargetReduction(reduction);
  ConfigureOurs(method, filter);
  const double cpu = ProcessCpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  result.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.CpuSeconds = ProcessCpuSeconds() - cpu;
  result.OutputTriangles = CountTriangles(filter->GetOutput());
  result.StateBytes = filter->GetStateMemory();
  if (!quiet.Get()->Errors.empty())
  {
    result.Ok = false;
    result.Error = quiet.Get()->FirstError();
  }
  return result;
}

Single RunQuadric(vtkPolyData* mesh, bool attributes, double reduction)
{
  Single result;
  MessageCatcher::Scope quiet;
  vtkNew<vtkQuadricDecimation> filter;
  filter->SetInputData(mesh);
  filter->SetTargetReduction(reduction);
  ConfigureQuadricPeer(filter, attributes);
  const double cpu = ProcessCpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  result.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.CpuSeconds = ProcessCpuSeconds() - cpu;
  result.OutputTriangles = CountTriangles(filter->GetOutput());
  if (!quiet.Get()->Errors.empty())
  {
    result.Ok = false;
    result.Error = quiet.Get()->FirstError();
  }
  return result;
}

#if COLORDECIMATION_WITH_MESHOPTIMIZER
/// The timed part: copying the points to float and the ids to 32 bits (what a VTK user has
/// to do first) and meshopt_simplify; no vtkPolyData is built from the result.
Single RunMeshOptimizer(vtkPolyData* mesh, double reduction)
{
  Single result;
  const double cpu = ProcessCpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  const std::vector<unsigned int> kept =
    colordecimation::tools::SimplifyWithMeshOptimizer(mesh, reduction);
  result.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.CpuSeconds = ProcessCpuSeconds() - cpu;
  result.OutputTriangles = static_cast<long long>(kept.size() / 3);
  return result;
}
#endif

/// meshoptimizer's WebAssembly build: its times are node's, around the simplify call.
Single RunMeshOptimizerJS(vtkPolyData* mesh, int method, double reduction)
{
  MeshOptimizerJSSettings settings;
  settings.Mode = ModeOf(method);
  settings.Reduction = reduction;
  const MeshOptimizerJSResult run = SimplifyWithMeshOptimizerJS(mesh, settings);
  Single result;
  result.Seconds = run.Seconds;
  result.CpuSeconds = run.CpuSeconds;
  result.OutputTriangles = static_cast<long long>(run.Triangles.size() / 3);
  result.PeakBytes = run.PeakBytes;
  result.RoundTripSeconds = run.RoundTripSeconds;
  result.Ok = run.Error.empty();
  result.Error = run.Error;
  return result;
}

bool MethodAvailable(int method)
{
  if (IsWebAssembly(method))
  {
    return MeshOptimizerJSUnavailable().empty();
  }
#if COLORDECIMATION_WITH_MESHOPTIMIZER
  return method >= 0 && method < NumberOfMethods;
#else
  return method >= 0 && method < MeshOptimizer;
#endif
}

/// One run of `method` on `mesh`.
Single RunMethod(int method, vtkPolyData* mesh, double reduction)
{
  switch (method)
  {
    case OursDefaults:
    case OursPaper:
    case OursPaperBatched:
    case OursGeometry:
      return RunOurs(mesh, method, reduction);
    case QuadricAttributes:
      return RunQuadric(mesh, true, reduction);
    case QuadricGeometry:
      return RunQuadric(mesh, false, reduction);
#if COLORDECIMATION_WITH_MESHOPTIMIZER
    case MeshOptimizer:
      return RunMeshOptimizer(mesh, reduction);
#endif
    default:
      return RunMeshOptimizerJS(mesh, method, reduction);
  }
}

/// One method's runs on one mesh, gathered over the rounds of RunCase.
struct Measurement
{
  RunResult Result;
  std::vector<double> Times, CpuTimes, RoundTrips;
  vtkSmartPointer<vtkPolyData> Mesh; // the mesh as given, or its cleaned copy (see below)
};

/// " (run r+1/n)" on the progress line when there are several repeats.
std::string RunLabel(int r, const Options& options)
{
  return options.Repeat > 1
    ? " (run " + std::to_string(r + 1) + "/" + std::to_string(options.Repeat) + ")"
    : std::string();
}

/// One run's figures added to `m` (times, whose medians are kept, and the largest peak).
void AddRun(const Single& single, long long peak, bool reset, Measurement& m)
{
  RunResult& result = m.Result;
  if (!single.Ok)
  {
    result.Error = single.Error;
  }
  m.Times.push_back(single.Seconds);
  m.CpuTimes.push_back(single.CpuSeconds);
  m.RoundTrips.push_back(single.RoundTripSeconds);
  result.OutputTriangles = single.OutputTriangles;
  result.StateBytes = single.StateBytes;
  result.PeakBytes = std::max(result.PeakBytes, peak);
  result.PeakReset = result.PeakReset && reset;
  result.Ran = true;
  result.Seconds = Median(m.Times);
  result.CpuSeconds = Median(m.CpuTimes);
  result.RoundTripSeconds = Median(m.RoundTrips);
}

/// Run `r` (0-based) of `method` to `reduction`, added to `m`.
void MeasureOnce(int method, vtkPolyData* given, const Options& options, const std::string& name,
                 int r, double reduction, Measurement& m)
{
  RunResult& result = m.Result;
  if (!m.Mesh)
  {
    m.Mesh = given;
  }
  for (;;)
  {
    std::fprintf(stderr, "[bench] %s: %s%s ...", name.c_str(), MethodName(method),
                 RunLabel(r, options).c_str());
    std::fflush(stderr);
    Single single;
    long long peak = -1;
    bool reset = true;
    {
      PeakMemoryProbe probe;
      single = RunMethod(method, m.Mesh, reduction);
      peak = single.PeakBytes >= 0 ? single.PeakBytes : probe.PeakAboveBaseline();
      reset = single.PeakBytes >= 0 || probe.PeakWasReset();
    }
    std::fprintf(stderr, " %.3f s (CPU %.3f s)\n", single.Seconds, single.CpuSeconds);
    if (!single.Ok && method == QuadricAttributes && m.Mesh == given)
    {
      // vtkQuadricDecimation's attribute metric gives up on some raw scans ("Unable to factor
      // attribute matrix!"); it runs once duplicate points are merged. Clean (untimed) and run
      // again, so that the ratio compares with a finished decimation.
      std::fprintf(stderr, "[bench] %s: %s reported an error: %s; again after vtkCleanPolyData\n",
                   name.c_str(), MethodName(method), single.Error.c_str());
      result.Note = "run on the output of vtkCleanPolyData (untimed): on the mesh as given it "
                    "reported \"" +
        single.Error + "\" after " + Format("%.3f", single.Seconds) + " s, with " +
        WithThousands(single.OutputTriangles) + " triangles left";
      vtkNew<vtkCleanPolyData> clean;
      clean->SetInputData(given);
      clean->Update();
      m.Mesh = clean->GetOutput();
      continue;
    }
    if (!single.Ok)
    {
      std::fprintf(stderr, "[bench] %s: %s reported an error: %s (%lld output triangles)\n",
                   name.c_str(), MethodName(method), single.Error.c_str(), single.OutputTriangles);
    }
    AddRun(single, peak, reset, m);
    return;
  }
}

/// Every available method on `mesh`; `quadricInput` gets the cleaned copy that
/// vtkQuadricDecimation's attribute metric needed, if it did.
CaseResult RunCase(const std::string& name, const std::string& description, vtkPolyData* mesh,
                   const Options& options, bool runQuadric,
                   vtkSmartPointer<vtkPolyData>* quadricInput = nullptr)
{
  CaseResult result;
  result.Name = name;
  result.Description = description;
  result.Points = mesh->GetNumberOfPoints();
  result.Triangles = CountTriangles(mesh);
  std::vector<int> methods;
  for (int method = 0; method < NumberOfMethods; ++method)
  {
    if (!MethodAvailable(method))
    {
      result.Runs[method].Skipped = IsWebAssembly(method)
        ? "not run (" + MeshOptimizerJSUnavailable() + ")"
        : "not built (meshoptimizer not found)";
    }
    else if ((method == QuadricAttributes || method == QuadricGeometry) && !runQuadric)
    {
      result.Runs[method].Skipped =
        options.NoQuadric ? "not run (--no-quadric)" : "not run (above --quadric-max)";
    }
    else
    {
      methods.push_back(method);
    }
  }
  // In rounds, each method once per round: a slow spell of a shared machine falls on every
  // method rather than on the repeats of one, and the ratios of the medians stay fair.
  Measurement measured[NumberOfMethods];
  for (int r = 0; r < options.Repeat; ++r)
  {
    for (const int method : methods)
    {
      MeasureOnce(method, mesh, options, name, r, options.Reduction, measured[method]);
    }
  }
  for (const int method : methods)
  {
    result.Runs[method] = measured[method].Result;
  }
  if (quadricInput && measured[QuadricAttributes].Mesh != mesh)
  {
    *quadricInput = measured[QuadricAttributes].Mesh;
  }
  return result;
}

//------------------------------------------------------------------------------
// Levels of detail: five levels from one run with the collapse record, against a run per
// level of this filter and of the peers.

/// Wall clock and process CPU time from construction to Stop().
struct Stopwatch
{
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
  double Cpu = ProcessCpuSeconds();
  void Stop(Single& result) const
  {
    result.Seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
    result.CpuSeconds = ProcessCpuSeconds() - this->Cpu;
  }
};

/// One round of the one-run row: the run, then each level.
struct LevelsOnce
{
  Single Run;
  Single Levels[NumberOfLevels];
};

/// vtkColorHalfEdgeDecimation at its defaults with the collapse record, to the coarsest
/// level, then each level extracted by one vtkColorHalfEdgeLevelOfDetail (which keeps the
/// mesh and the record between levels, as a viewer's slider would).
LevelsOnce RunOneRunLevels(vtkPolyData* mesh)
{
  LevelsOnce result;
  MessageCatcher::Scope quiet;
  vtkNew<vtkColorHalfEdgeDecimation> filter;
  filter->SetInputData(mesh);
  filter->SetTargetReduction(LodLevels[NumberOfLevels - 1]);
  filter->GenerateCollapseRecordOn();
  const Stopwatch run;
  filter->Update();
  run.Stop(result.Run);
  result.Run.OutputTriangles = CountTriangles(filter->GetOutput());
  result.Run.StateBytes = filter->GetStateMemory();
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  lod->SetInputData(mesh);
  lod->SetRecordData(filter->GetCollapseRecord());
  for (int i = 0; i < NumberOfLevels; ++i)
  {
    lod->SetTargetReduction(LodLevels[i]);
    const Stopwatch extraction;
    lod->Update();
    extraction.Stop(result.Levels[i]);
    result.Levels[i].OutputTriangles = CountTriangles(lod->GetOutput());
  }
  if (!quiet.Get()->Errors.empty())
  {
    result.Run.Ok = false;
    result.Run.Error = quiet.Get()->FirstError();
  }
  return result;
}

/// Round `r` of the one-run row, added to `run` and `levels`; the peak spans the whole round.
void MeasureOneRunLevels(vtkPolyData* mesh, const Options& options, const std::string& name, int r,
                         Measurement& run, Measurement* levels)
{
  std::fprintf(stderr,
               "[bench] %s: levels of detail, one run with the record + %d extractions%s ...",
               name.c_str(), NumberOfLevels, RunLabel(r, options).c_str());
  std::fflush(stderr);
  LevelsOnce once;
  long long peak = -1;
  bool reset = true;
  {
    PeakMemoryProbe probe;
    once = RunOneRunLevels(mesh);
    peak = probe.PeakAboveBaseline();
    reset = probe.PeakWasReset();
  }
  double extraction = 0;
  for (int i = 0; i < NumberOfLevels; ++i)
  {
    extraction += once.Levels[i].Seconds;
    AddRun(once.Levels[i], -1, true, levels[i]);
  }
  std::fprintf(stderr, " %.3f s + %.3f s\n", once.Run.Seconds, extraction);
  if (!once.Run.Ok)
  {
    std::fprintf(stderr, "[bench] %s: levels of detail reported an error: %s\n", name.c_str(),
                 once.Run.Error.c_str());
  }
  AddRun(once.Run, peak, reset, run);
}

/// Why the section does not run on a mesh of `triangles`, or "".
std::string LevelsSkipReason(const Options& options, long long triangles)
{
  if (options.NoLod)
  {
    return "not run (--no-lod)";
  }
  if (options.LodMax > 0 && triangles > options.LodMax)
  {
    return "not run (above --lod-max " + SizeLabel(options.LodMax) + "; `--lod-max 0` runs it)";
  }
  return "";
}

/// The methods run once per level, with the reason for those that are not.
std::vector<int> SeparateMethods(const Options& options, LevelsResult& result)
{
  std::vector<int> methods;
  for (const int method : LodSeparateMethods)
  {
    if (!MethodAvailable(method))
    {
      result.SeparateSkipped[method] = IsWebAssembly(method)
        ? "not run (" + MeshOptimizerJSUnavailable() + ")"
        : "not built (meshoptimizer not found)";
    }
    else if (method == QuadricAttributes && options.NoQuadric)
    {
      result.SeparateSkipped[method] = "not run (--no-quadric)";
    }
    else
    {
      methods.push_back(method);
    }
  }
  return methods;
}

/// Whether level `i` of `method`'s runs per level is the Meshes table's run (the same run).
bool LevelIsCaseRun(const CaseResult& c, int method, int i, const Options& options)
{
  return std::abs(LodLevels[i] - options.Reduction) < 1e-9 && c.Runs[method].Ran;
}

/// The levels-of-detail section on `mesh`, in rounds as RunCase; the level at --reduction of
/// the runs per level is the Meshes table's run (`c`), not run again. `quadricInput`: the
/// cleaned copy that vtkQuadricDecimation needed there, or null.
LevelsResult RunLevels(const CaseResult& c, vtkPolyData* mesh, vtkPolyData* quadricInput,
                       const Options& options)
{
  LevelsResult result;
  result.Skipped = LevelsSkipReason(options, c.Triangles);
  if (!result.Skipped.empty())
  {
    return result;
  }
  const std::vector<int> methods = SeparateMethods(options, result);
  Measurement oneRun, extractions[NumberOfLevels];
  std::vector<Measurement> separate(NumberOfMethods * NumberOfLevels);
  for (const int method : methods)
  {
    for (int i = 0; i < NumberOfLevels; ++i)
    {
      separate[method * NumberOfLevels + i].Mesh =
        method == QuadricAttributes && quadricInput ? quadricInput : mesh;
    }
  }
  result.QuadricCleaned = quadricInput != nullptr;
  for (int r = 0; r < options.Repeat; ++r)
  {
    MeasureOneRunLevels(mesh, options, c.Name, r, oneRun, extractions);
    for (const int method : methods)
    {
      for (int i = 0; i < NumberOfLevels; ++i)
      {
        result.Reused[method] = result.Reused[method] || LevelIsCaseRun(c, method, i, options);
        if (!LevelIsCaseRun(c, method, i, options))
        {
          MeasureOnce(method, mesh, options, c.Name + ", level " + Format("%g", LodLevels[i]), r,
                      LodLevels[i], separate[method * NumberOfLevels + i]);
        }
      }
    }
  }
  result.Ran = true;
  result.OneRun = oneRun.Result;
  for (int i = 0; i < NumberOfLevels; ++i)
  {
    result.Extractions[i] = extractions[i].Result;
    for (const int method : methods)
    {
      result.Separate[method][i] = LevelIsCaseRun(c, method, i, options)
        ? c.Runs[method]
        : separate[method * NumberOfLevels + i].Result;
    }
  }
  return result;
}

//------------------------------------------------------------------------------
// Report.

/// a's time divided by b's, printed with `format`, or "—" when either has no valid time.
std::string TimeRatio(const RunResult& a, const RunResult& b, const char* format)
{
  if (!a.Ran || !b.Ran || b.Seconds <= 0 || !a.Error.empty() || !b.Error.empty())
  {
    return "—";
  }
  return Format(format, a.Seconds / b.Seconds);
}

/// The WebAssembly rows' whole calls, node's start included, or "".
std::string RoundTripNote(const CaseResult& c)
{
  std::string times;
  for (int m = MeshOptimizerJSAttributes; m <= MeshOptimizerJSPrune; ++m)
  {
    const RunResult& r = c.Runs[m];
    if (r.Ran && r.Error.empty())
    {
      times += std::string(times.empty() ? "" : ", ") + Format("%.3f", r.RoundTripSeconds) +
        " s (" + MeshOptimizerJSFunction(ModeOf(m)) + ")";
    }
  }
  if (times.empty())
  {
    return "";
  }
  return "\n- meshoptimizer 1.3 (WebAssembly): *seconds* and *CPU seconds* measured inside "
         "node around the simplify call, the module compiled before it; peak memory: node's "
         "peak resident memory above its level before the call. The whole calls (the arrays "
         "and files, node's start, loading the module, reading the result back) took " +
    times + ".\n";
}

std::string CaseTable(const CaseResult& c, double reduction)
{
  std::ostringstream os;
  os << "### " << c.Name << "\n\n"
     << c.Description << ": " << WithThousands(c.Points) << " points, "
     << WithThousands(c.Triangles) << " triangles; target reduction " << Format("%g", reduction)
     << ".\n\n";
  // Each row's time over meshoptimizer's attribute mode's, the peer to beat on speed, when
  // that can run.
  const bool againstMeshopt = MethodAvailable(MeshOptimizerJSAttributes);
  os << "| method | seconds | CPU seconds | output triangles | reduction | vtkQD attr on ÷ this | "
        "vtkQD attr off ÷ this | "
     << (againstMeshopt ? "this ÷ meshopt attr | " : "")
     << "peak memory (MiB) | decimation state (MiB) |\n"
     << "|---|--:|--:|--:|--:|--:|--:|" << (againstMeshopt ? "--:|" : "") << "--:|--:|\n";
  for (int m = 0; m < NumberOfMethods; ++m)
  {
    const RunResult& r = c.Runs[m];
    if ((m == MeshOptimizer || IsWebAssembly(m)) && !MethodAvailable(m))
    {
      continue;
    }
    os << "| " << MethodName(m) << (r.Error.empty() ? "" : " (error, see below)")
       << (r.Note.empty() ? "" : " (cleaned input, see below)") << " | ";
    if (!r.Ran)
    {
      os << r.Skipped << " | | | | | | | |" << (againstMeshopt ? " |" : "") << "\n";
      continue;
    }
    os << Format("%.3f", r.Seconds) << " | " << Format("%.3f", r.CpuSeconds) << " | "
       << WithThousands(r.OutputTriangles) << " | "
       << Format("%.4f", c.Triangles ? 1.0 - double(r.OutputTriangles) / c.Triangles : 0.0) << " | "
       << TimeRatio(c.Runs[QuadricAttributes], r, "%.1f") << " | "
       << TimeRatio(c.Runs[QuadricGeometry], r, "%.1f") << " | "
       << (againstMeshopt ? TimeRatio(r, c.Runs[MeshOptimizerJSAttributes], "%.2f") + " | "
                          : std::string())
       << MiB(r.PeakBytes) << (r.PeakReset ? "" : " (process peak)") << " | "
       << (r.StateBytes >= 0 ? MiB(r.StateBytes) : std::string("—")) << " |\n";
  }
  for (int m = 0; m < NumberOfMethods; ++m)
  {
    const RunResult& r = c.Runs[m];
    if (r.Ran && !r.Note.empty())
    {
      os << "\n- " << MethodName(m) << ": " << r.Note << ".\n";
    }
    if (r.Ran && !r.Error.empty())
    {
      os << "\n- " << MethodName(m) << ": " << (IsWebAssembly(m) ? "node" : "VTK")
         << " reported the error \"" << r.Error << "\"; it returned "
         << WithThousands(r.OutputTriangles) << " triangles after " << Format("%.3f", r.Seconds)
         << " s. Its time is not a valid reference, so no ratio to it is given.\n";
    }
  }
  os << RoundTripNote(c);
  return os.str();
}

/// The figures of one row of the levels-of-detail table.
struct LevelsRow
{
  std::string Name;
  std::string Skipped;
  double Seconds = 0, CpuSeconds = 0, RoundTripSeconds = 0;
  double ExtractionSeconds = -1; // the one-run row only
  long long PeakBytes = -1;
  bool PeakReset = true;
  std::string Error;
  long long Triangles[NumberOfLevels] = {};
};

/// The one-run row: the run's time plus the extractions' (medians), the round's peak.
LevelsRow OneRunRow(const LevelsResult& l)
{
  LevelsRow row;
  row.Name = "vtkColorHalfEdgeDecimation, defaults, one run to " +
    Format("%g", LodLevels[NumberOfLevels - 1]) + " with GenerateCollapseRecord, then " +
    std::to_string(NumberOfLevels) + " vtkColorHalfEdgeLevelOfDetail extractions";
  row.Seconds = l.OneRun.Seconds;
  row.CpuSeconds = l.OneRun.CpuSeconds;
  row.ExtractionSeconds = 0;
  for (int i = 0; i < NumberOfLevels; ++i)
  {
    row.Seconds += l.Extractions[i].Seconds;
    row.CpuSeconds += l.Extractions[i].CpuSeconds;
    row.ExtractionSeconds += l.Extractions[i].Seconds;
    row.Triangles[i] = l.Extractions[i].OutputTriangles;
  }
  row.PeakBytes = l.OneRun.PeakBytes;
  row.PeakReset = l.OneRun.PeakReset;
  row.Error = l.OneRun.Error;
  return row;
}

/// A row of runs per level: the sums of their median times, their largest peak.
LevelsRow SeparateRow(const LevelsResult& l, int method)
{
  LevelsRow row;
  row.Name = std::string(MethodName(method)) + ", a run per level";
  row.Skipped = l.SeparateSkipped[method];
  for (int i = 0; i < NumberOfLevels; ++i)
  {
    const RunResult& r = l.Separate[method][i];
    row.Seconds += r.Seconds;
    row.CpuSeconds += r.CpuSeconds;
    row.RoundTripSeconds += r.RoundTripSeconds;
    row.PeakBytes = std::max(row.PeakBytes, r.PeakBytes);
    row.PeakReset = row.PeakReset && r.PeakReset;
    row.Error = row.Error.empty() ? r.Error : row.Error;
    row.Triangles[i] = r.OutputTriangles;
  }
  return row;
}

std::string LevelsRowText(const LevelsRow& row, double oneRunSeconds)
{
  std::ostringstream os;
  os << "| " << row.Name << (row.Error.empty() ? "" : " (error, see below)") << " | ";
  if (!row.Skipped.empty())
  {
    os << row.Skipped << " |";
    for (int k = 0; k < 4 + NumberOfLevels; ++k)
    {
      os << " |";
    }
    return os.str() + "\n";
  }
  os << Format("%.3f", row.Seconds) << " | " << Format("%.3f", row.CpuSeconds) << " | "
     << (row.ExtractionSeconds >= 0 ? Format("%.3f", row.ExtractionSeconds) : std::string("—"))
     << " | "
     << (oneRunSeconds > 0 && row.Error.empty() ? Format("%.1f", row.Seconds / oneRunSeconds)
                                                : std::string("—"))
     << " | " << MiB(row.PeakBytes) << (row.PeakReset ? "" : " (process peak)") << " |";
  for (const long long n : row.Triangles)
  {
    os << " " << WithThousands(n) << " |";
  }
  return os.str() + "\n";
}

/// What the table's rows are, under it.
std::string LevelsNotes(const LevelsResult& l, const std::vector<LevelsRow>& rows,
                        const Options& options)
{
  std::ostringstream os;
  std::string reused;
  for (const int method : LodSeparateMethods)
  {
    reused += l.Reused[method] ? std::string(reused.empty() ? "" : "; ") + MethodName(method) : "";
  }
  if (!reused.empty())
  {
    os << "\n- The level at " << Format("%g", options.Reduction)
       << " of these runs per level is the Meshes table's run (the same run): " << reused << ".\n";
  }
  if (l.QuadricCleaned)
  {
    os << "\n- vtkQuadricDecimation ran on the output of vtkCleanPolyData, as in the Meshes "
          "table.\n";
  }
  for (const LevelsRow& row : rows)
  {
    if (!row.Error.empty())
    {
      os << "\n- " << row.Name << ": the error \"" << row.Error << "\" was reported.\n";
    }
    if (row.Skipped.empty() && row.RoundTripSeconds > 0)
    {
      os << "\n- " << row.Name << ": the whole calls (node's start included) took "
         << Format("%.3f", row.RoundTripSeconds) << " s.\n";
    }
  }
  return os.str();
}

std::string LevelsTable(const CaseResult& c, const Options& options)
{
  const LevelsResult& l = c.Levels;
  std::ostringstream os;
  os << "### Levels of detail: " << c.Name << "\n\n";
  if (!l.Ran)
  {
    return os.str() + l.Skipped + ".\n";
  }
  os << c.Description << ": " << WithThousands(c.Points) << " points, "
     << WithThousands(c.Triangles) << " triangles.\n\n"
     << "| method | seconds | CPU seconds | extraction seconds | this ÷ one run | peak memory "
        "(MiB) |";
  std::string target = "| target triangles | | | | | |", rule = "|---|--:|--:|--:|--:|--:|";
  for (const double reduction : LodLevels)
  {
    os << " triangles at " << Format("%g", reduction) << " |";
    target += " " +
      WithThousands(static_cast<long long>(std::floor((1.0 - reduction) * c.Triangles + 1e-6))) +
      " |";
    rule += "--:|";
  }
  os << "\n" << rule << "\n" << target << "\n";
  std::vector<LevelsRow> rows = { OneRunRow(l) };
  for (const int method : LodSeparateMethods)
  {
    if ((method == MeshOptimizer || IsWebAssembly(method)) && !MethodAvailable(method))
    {
      continue;
    }
    rows.push_back(SeparateRow(l, method));
  }
  for (const LevelsRow& row : rows)
  {
    os << LevelsRowText(row, rows.front().Seconds);
  }
  return os.str() + LevelsNotes(l, rows, options);
}

std::string SweepTable(const std::vector<CaseResult>& sweep)
{
  // One block of rows per method, sizes in order, so that each method's ns/triangle can be
  // read down the column: flat means linear time.
  std::ostringstream os;
  os << "| method | input triangles | seconds | CPU seconds | ns/triangle | CPU ns/triangle | "
        "output triangles | peak memory (MiB) | peak bytes/triangle |\n"
     << "|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (int m = 0; m < NumberOfMethods; ++m)
  {
    if (!MethodAvailable(m))
    {
      continue;
    }
    for (const CaseResult& c : sweep)
    {
      const RunResult& r = c.Runs[m];
      const double n = static_cast<double>(std::max<long long>(1, c.Triangles));
      os << "| " << MethodShortName(m) << " | " << WithThousands(c.Triangles) << " | ";
      if (!r.Ran)
      {
        os << r.Skipped << " | | | | | | |\n";
        continue;
      }
      os << Format("%.3f", r.Seconds) << (r.Error.empty() ? "" : " (VTK error)") << " | "
         << Format("%.3f", r.CpuSeconds) << " | " << Format("%.0f", 1e9 * r.Seconds / n) << " | "
         << Format("%.0f", 1e9 * r.CpuSeconds / n) << " | " << WithThousands(r.OutputTriangles)
         << " | " << MiB(r.PeakBytes) << " | "
         << (r.PeakBytes >= 0 ? Format("%.0f", r.PeakBytes / n) : std::string("?")) << " |\n";
    }
  }
  return os.str();
}

std::string ReadFirstLine(const char* command)
{
  std::string line;
  if (std::FILE* pipe = popen(command, "r"))
  {
    char buffer[256];
    if (std::fgets(buffer, sizeof(buffer), pipe))
    {
      line = buffer;
    }
    pclose(pipe);
  }
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
  {
    line.pop_back();
  }
  return line;
}

std::string MachineDescription()
{
  std::string cpu = "unknown CPU";
  long long memKb = 0;
  {
    std::ifstream info("/proc/cpuinfo");
    std::string line;
    while (std::getline(info, line))
    {
      if (line.compare(0, 10, "model name") == 0 && line.find(':') != std::string::npos)
      {
        cpu = line.substr(line.find(':') + 2);
        break;
      }
    }
  }
  {
    std::ifstream info("/proc/meminfo");
    std::string key;
    while (info >> key)
    {
      if (key == "MemTotal:")
      {
        info >> memKb;
        break;
      }
      std::string rest;
      std::getline(info, rest);
    }
  }
  std::ostringstream os;
  os << cpu << ", " << std::thread::hardware_concurrency() << " logical cores";
  if (memKb > 0)
  {
    os << ", " << Format("%.0f", memKb / (1024.0 * 1024.0)) << " GiB RAM";
  }
  struct utsname name;
  if (uname(&name) == 0)
  {
    os << ", " << name.sysname << " " << name.release << " " << name.machine;
  }
  return os.str();
}

/// " (in DIR)" for the current working directory, or "".
std::string WorkingDirectory()
{
  char buffer[4096];
  if (getcwd(buffer, sizeof(buffer)))
  {
    return std::string(" (in `") + buffer + "`)";
  }
  return "";
}

/// The 1-, 5- and 15-minute load averages ("0.12 0.30 0.25"), or "?".
std::string LoadAverage()
{
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  if (file >> one >> five >> fifteen)
  {
    return one + " " + five + " " + fifteen;
  }
  return "?";
}

/// The report's title and the lines on the run, the machine and the software.
std::string ReportHeader(const Options& options, const std::string& date, double totalSeconds,
                         const std::string& loadBefore, const std::string& loadAfter)
{
  std::ostringstream os;
  os << "# Benchmark: vtkColorHalfEdgeDecimation against vtkQuadricDecimation\n\n"
     << "This file is written by `color-decimate-bench --markdown FILE` "
        "(Tools/ColorDecimateBench.cxx); rerun the command below to regenerate it.\n\n"
     << "- Command: `" << options.CommandLine << "`" << WorkingDirectory() << "\n"
     << "- Date: " << date << "; whole run " << Format("%.0f", totalSeconds) << " s\n"
     << "- Machine: " << MachineDescription() << "\n"
     << "- Load average (1, 5, 15 min): " << loadBefore << " before, " << loadAfter
     << " after (other work on the machine slows the runs down)\n"
     << "- VTK " << vtkVersion::GetVTKVersion() << "; build type " << COLORDECIMATION_BUILD_TYPE
#ifdef NDEBUG
     << " (NDEBUG)"
#else
     << " (assertions on: timings are not representative)"
#endif
#if defined(__clang__)
     << "; clang " << __clang_major__ << "." << __clang_minor__
#elif defined(__GNUC__)
     << "; GCC " << __GNUC__ << "." << __GNUC_MINOR__
#endif
#if COLORDECIMATION_WITH_MESHOPTIMIZER
     << "; meshoptimizer " << colordecimation::tools::MeshOptimizerVersion()
#else
     << "; meshoptimizer not built in"
#endif
     << "\n"
     << "- "
     << (MeshOptimizerJSUnavailable().empty()
           ? MeshOptimizerJSDescription()
           : "meshoptimizer 1.3 (WebAssembly) not run: " + MeshOptimizerJSUnavailable())
     << "\n";
  const std::string commit =
    ReadFirstLine("git -C \"" COLORDECIMATION_SOURCE_DIR
                  "\" log -1 --format='%h of %cd' --date=short 2>/dev/null");
  if (!commit.empty())
  {
    const std::string dirty = ReadFirstLine("git -C \"" COLORDECIMATION_SOURCE_DIR
                                            "\" status --porcelain --untracked-files=no "
                                            "-- Filters 2>/dev/null");
    os << "- Source: commit `" << commit << "`"
       << (dirty.empty() ? "" : " with uncommitted changes in Filters/") << "\n";
  }
  os << "- Repeats: " << options.Repeat << " run(s) per method and mesh"
     << (options.Repeat > 1 ? ", taken in rounds (each method once per round, so that a slow "
                              "spell of the machine falls on all of them), median time, largest "
                              "peak"
                            : "")
     << "\n\n";

  return os.str();
}

/// The levels-of-detail section of the report: what it measures, then a table per mesh.
std::string LevelsSection(const Options& options, const std::vector<CaseResult>& cases)
{
  std::ostringstream os;
  os << "## Levels of detail: five levels from one run against a run per level\n\n"
        "Levels at reductions 0.5, 0.75, 0.9, 0.97 and 0.99 of each mesh above";
  if (options.LodMax > 0)
  {
    os << " that has at most " << WithThousands(options.LodMax)
       << " triangles (--lod-max; `--lod-max 0` takes every mesh)";
  }
  os << ".\n\n"
        "- The first row: one run of vtkColorHalfEdgeDecimation at its defaults with "
        "GenerateCollapseRecord on, to 0.99, then the five levels from its record by one "
        "vtkColorHalfEdgeLevelOfDetail (TargetReduction set five times; it keeps the mesh "
        "and the record between levels). *seconds*: the run plus the five extractions; "
        "*extraction seconds*: the five extractions alone; *peak memory*: over the run and "
        "the extractions together (record, cached mesh and level included).\n"
        "- The other rows: one run per level, each measured as in the Meshes tables; "
        "*seconds* and *CPU seconds* add up the five runs' medians, *peak memory* is the "
        "largest of the five (each run's output is freed before the next).\n"
        "- *this ÷ one run*: the row's seconds divided by the first row's.\n"
        "- *triangles at R*: the triangles of the level; the *target triangles* row gives "
        "(1 - R) × the input's triangles, rounded down (the filter's rule); a closed mesh "
        "loses two triangles a collapse, so it may stop one below.\n\n";
  for (const CaseResult& c : cases)
  {
    os << LevelsTable(c, options) << "\n";
  }
  return os.str();
}

/// The report's "What is measured" section: what each column and row means.
std::string MeasuredSection()
{
  return "## What is measured\n\n"
         "- Every method runs in this one process on the very same vtkPolyData (triangles; "
         "polygons and strips would be triangulated once beforehand), one after the other.\n"
         "- *seconds*: the filter's own wall-clock time, `Update()` only (reading and generating "
         "the mesh are not counted). *CPU seconds*: the process's CPU time over the same span "
         "(user + system, all threads); on a busy machine it is the steadier figure. For "
         "meshoptimizer: copying the points to float and the ids to 32 "
         "bits, then `meshopt_simplify` (target error 1, i.e. unbounded, so that it stops at "
         "the triangle target; no vtkPolyData is built from its result).\n"
         "- meshoptimizer 1.3 (WebAssembly): the npm package `meshoptimizer` (pinned in "
         "Tools/MeshOptimizerJS), same algorithm as the native library, run by node (V8) with "
         "the module compiled by the optimising compiler before the call, which "
         "Tools/MeshOptimizerJS/simplify.mjs times inside node (`performance.now()`, "
         "`process.cpuUsage()`); the colour as 3 attributes in [0,1] of weight 1, target error "
         "FLT_MAX (the triangle target governs), LockBorder off; its peak memory is node's "
         "(maxRSS above the RSS before the call). The whole call, node's start included, is "
         "below each table.\n"
         "- *vtkQD attr on ÷ this*, *vtkQD attr off ÷ this*: vtkQuadricDecimation's time "
         "(AttributeErrorMetric on with the colour array as the only attribute, resp. off) "
         "divided by the row's time: how many times faster the row is.\n"
         "- *this ÷ meshopt attr* (when node and the package are there): the row's time divided "
         "by that of meshoptimizer 1.3's `simplifyWithAttributes` (WebAssembly) in the same "
         "run; below 1 the row is faster. The WebAssembly build is slower than native "
         "meshoptimizer's `simplifyWithAttributes` (not built into this benchmark), so against "
         "that the ratio is larger (docs/BENCHMARK.md, *One thread and two against native "
         "meshoptimizer in the same rounds*).\n"
         "- *peak memory*: before each run the heap is trimmed (`malloc_trim`), the resident "
         "size is read (VmRSS) and the high-water mark is reset (writing `5` to "
         "`/proc/self/clear_refs`); after the run, VmHWM minus that baseline. It counts what "
         "the run allocated at its peak, output included, input excluded.\n"
         "- *decimation state*: vtkColorHalfEdgeDecimation::GetStateMemory(), the bytes of "
         "its own arrays (connectivity, metric, heap or the Batched schedule's keys).\n"
         "- This filter's rows: its defaults (AttributeQuadric with boundary planes and the "
         "Batched schedule, NumberOfThreads 0: every core, so its CPU seconds add up the "
         "threads); the paper's method (SetPaperDefaults: HalfEdgeColor, Greedy); the paper's "
         "cost with the Batched schedule; the Geometry metric with the Greedy schedule "
         "(docs/SCHEDULES.md, docs/RESULTS.md).\n"
         "- *ns/triangle* in the sweep: seconds (CPU seconds for the CPU column) divided by the "
         "input triangles; flat means linear time (n log n shows as a slow rise, cache misses "
         "as a step once the working set outgrows the caches).\n"
         "- The spheres are vtkSphereSource latitude-longitude spheres (ColorDecimation::Meshes "
         "UVSphere): two poles of valence equal to the resolution (700 for the 977,200-triangle "
         "sphere), all other vertices of valence 6.\n\n";
}

std::string Report(const Options& options, const std::vector<CaseResult>& cases,
                   const std::vector<CaseResult>& sweep, const std::string& date,
                   double totalSeconds, const std::string& loadBefore, const std::string& loadAfter)
{
  std::ostringstream os;
  os << ReportHeader(options, date, totalSeconds, loadBefore, loadAfter);
  os << MeasuredSection();

  if (!cases.empty())
  {
    os << "## Meshes\n\n";
    for (const CaseResult& c : cases)
    {
      os << CaseTable(c, options.Reduction) << "\n";
    }
  }
  if (!cases.empty() && !options.NoLod)
  {
    os << LevelsSection(options, cases);
  }
  if (!sweep.empty())
  {
    os << "## Scale sweep (coloured UV spheres, SharpRegions)\n\n"
       << "Target reduction " << Format("%g", options.Reduction) << "; vtkQuadricDecimation ";
    if (options.NoQuadric)
    {
      os << "not run.\n\n";
    }
    else if (options.QuadricMax > 0)
    {
      os << "only up to " << WithThousands(options.QuadricMax) << " input triangles.\n\n";
    }
    else
    {
      os << "at every size.\n\n";
    }
    os << SweepTable(sweep) << "\n";
  }
  return os.str();
}

std::string Now()
{
  const std::time_t t = std::time(nullptr);
  char buffer[64];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%d %H:%M %Z", std::localtime(&t));
  return buffer;
}

/// A mesh to measure.
struct Input
{
  std::string Name;   // shown in the table title
  std::string Source; // path or demo spec, or "" for the default sphere
};

/// The given meshes, or the defaults (the real mesh when it is there, the 977k sphere).
std::vector<Input> Inputs(const Options& options)
{
  std::vector<Input> inputs;
  for (const std::string& m : options.Meshes)
  {
    inputs.push_back({ m, m });
  }
  if (!options.Meshes.empty() || options.NoDefaultMeshes)
  {
    return inputs;
  }
  const std::string candidates[] = { std::string(COLORDECIMATION_SOURCE_DIR) + "/../" +
                                       DefaultRealMesh,
                                     std::string("../") + DefaultRealMesh };
  for (const std::string& path : candidates)
  {
    if (FileExists(path))
    {
      inputs.push_back({ "redkitchen_tsdf_7mm.ply", path });
      break;
    }
  }
  if (inputs.empty())
  {
    std::fprintf(stderr, "[bench] ../%s not found: skipped\n", DefaultRealMesh);
  }
  inputs.push_back({ "Coloured UV sphere", "" });
  return inputs;
}

/// The mesh of `input`, triangulated, with the colour array made the active scalars; null
/// (and the message printed) when it cannot be used.
vtkSmartPointer<vtkPolyData> LoadInput(const Input& input, const Options& options,
                                       std::string& description)
{
  if (input.Source.empty())
  {
    description = "UVSphere(700), SharpRegions colours";
    return meshes::UVSphere(DefaultSphereResolution, meshes::Pattern::SharpRegions);
  }
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(input.Source, description, error);
  if (!mesh)
  {
    std::cerr << Program << ": " << error << std::endl;
    return nullptr;
  }
  // "icosphere level 4, SharpRegions colours (2,562 points, ...)": the counts are in the
  // table's title line already.
  description = IsDemoSpec(input.Source) ? description.substr(0, description.rfind(" ("))
                                         : "`" + input.Source + "`";
  if (!options.Array.empty() && !mesh->GetPointData()->GetArray(options.Array.c_str()))
  {
    std::cerr << Program << ": " << NoNumericPointArray(mesh, input.Source, options.Array)
              << std::endl;
    return nullptr;
  }
  if (!options.Array.empty())
  {
    mesh->GetPointData()->SetActiveScalars(options.Array.c_str());
  }
  // The same triangles for every method: polygons and strips are triangulated once here.
  mesh = Triangulated(mesh);
  if (CountTriangles(mesh) == 0)
  {
    std::cerr << Program << ": '" << input.Source << "' has no triangles" << std::endl;
    return nullptr;
  }
  return mesh;
}

/// Every method on every input, each table printed as it is done; false on a bad input.
bool RunCases(const Options& options, std::vector<CaseResult>& cases)
{
  for (const Input& input : Inputs(options))
  {
    std::string description;
    vtkSmartPointer<vtkPolyData> mesh = LoadInput(input, options, description);
    if (!mesh)
    {
      return false;
    }
    if (!mesh->GetPointData()->GetScalars())
    {
      std::fprintf(
        stderr,
        "[bench] %s has no colour (active scalars): the colour-aware runs use geometry only\n",
        input.Name.c_str());
    }
    vtkSmartPointer<vtkPolyData> quadricInput;
    cases.push_back(
      RunCase(input.Name, description, mesh, options, !options.NoQuadric, &quadricInput));
    std::cout << "\n" << CaseTable(cases.back(), options.Reduction) << std::endl;
    cases.back().Levels = RunLevels(cases.back(), mesh, quadricInput, options);
    if (!options.NoLod)
    {
      std::cout << "\n" << LevelsTable(cases.back(), options) << std::endl;
    }
  }
  return true;
}

/// The scale sweep of generated spheres (when it is on).
std::vector<CaseResult> RunSweep(const Options& options)
{
  std::vector<CaseResult> sweep;
  if (options.NoSweep || (!options.Meshes.empty() && !options.SizesGiven))
  {
    return sweep;
  }
  for (long long size : options.Sizes)
  {
    vtkSmartPointer<vtkPolyData> mesh =
      meshes::UVSphereWithTriangles(size, meshes::Pattern::SharpRegions);
    const bool quadric =
      !options.NoQuadric && (options.QuadricMax <= 0 || CountTriangles(mesh) <= options.QuadricMax);
    sweep.push_back(RunCase("sphere " + SizeLabel(size), "UV sphere", mesh, options, quadric));
  }
  std::cout << "\n## Scale sweep (coloured UV spheres, SharpRegions)\n\n"
            << SweepTable(sweep) << std::endl;
  return sweep;
}

/// The whole benchmark, then --markdown; the exit status.
int RunBenchmark(const Options& options)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string date = Now();
  const std::string loadBefore = LoadAverage();
  if (!MeshOptimizerJSUnavailable().empty())
  {
    std::fprintf(stderr, "[bench] meshoptimizer 1.3 (WebAssembly) rows left out: %s\n",
                 MeshOptimizerJSUnavailable().c_str());
  }
  std::vector<CaseResult> cases;
  if (!RunCases(options, cases))
  {
    return 1;
  }
  const std::vector<CaseResult> sweep = RunSweep(options);
  const double total =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "[bench] done in %.0f s\n", total);
  if (options.Markdown.empty())
  {
    return 0;
  }
  std::ofstream out(options.Markdown);
  out << Report(options, cases, sweep, date, total, loadBefore, LoadAverage());
  out.close();
  if (!out)
  {
    std::cerr << Program << ": cannot write '" << options.Markdown << "'" << std::endl;
    return 1;
  }
  std::fprintf(stderr, "[bench] wrote %s\n", options.Markdown.c_str());
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  UseAllCoresByDefault(); // vtkSMPTools on all cores unless asked otherwise
  // VTK's messages are caught and reported in one line (MessageCatcher); its logger would
  // print them to stderr a second time, with timestamps.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app(Description(), Program);
  SetUpCommandLine(app, "Usage: color-decimate-bench [MESH ...] [options]");
  Options options;
  AddMeshOptions(app, options);
  AddRunOptions(app, options);
  for (int i = 0; i < argc; ++i)
  {
    options.CommandLine += (i ? " " : "") + std::string(argv[i]);
  }
  const int status = ParseCommandLine(app, argc, argv);
  if (status >= 0)
  {
    return status;
  }
  if (!options.Markdown.empty() && !std::ofstream(options.Markdown, std::ios::app))
  {
    std::cerr << Program << ": cannot write '" << options.Markdown << "'" << std::endl;
    return 1;
  }
  return RunBenchmark(options);
}
