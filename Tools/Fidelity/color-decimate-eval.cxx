// color-decimate-eval: render-based fidelity of a simplified coloured mesh against its
// original (RMS of the per-pixel RGB distance and PSNR over six axis views, unlit and lit),
// printed as JSON; optionally a side-by-side snapshot PNG. See docs/FIDELITY.md.
#include "ColorDecimationFidelity.h"
#include "CommandLine.h"
#include "JsonOutput.h"
#include "MeshIO.h"
#include "SmpBackend.h"

#include "vtkColorHalfEdgeDecimation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"

#include <cstdio>
#include <functional>
#include <iostream>
#include <string>

namespace fid = colordecimation::fidelity;
using namespace colordecimation::tools;

namespace
{
const char* const Program = "color-decimate-eval";

/// Bad options end the tool with status 1 (2 is a failed render).
const int UsageStatus = 1;

struct Settings
{
  std::string Original;
  std::string Simplified;
  std::string JsonPath;
  std::string SnapshotPath;
  std::string SavePath;
  std::string Method = "halfedge";
  int SnapshotSize = 600;
  double Reduction = -1.0; ///< --decimate; < 0: SIMPLIFIED is given
  fid::Options Render;
  fid::SnapshotOptions Snapshot;
};

/// A whole number from `lo` to `hi` into `value`.
std::function<bool(const std::string&)> WholeNumber(int& value, int lo, int hi)
{
  return [&value, lo, hi](const std::string& text)
  {
    long long number = 0;
    const bool ok = ParseWholeNumber(text, number) && number >= lo && number <= hi;
    value = ok ? static_cast<int>(number) : value;
    return ok;
  };
}

/// The meshes and the measure.
void AddMeasureOptions(CLI::App& app, Settings& settings)
{
  app.add_option("ORIGINAL", settings.Original, "the original mesh")->required()->type_name("");
  app.add_option("SIMPLIFIED", settings.Simplified, "the simplified mesh (none with --decimate)")
    ->type_name("");
  app.add_option("--json", settings.JsonPath, "also write the JSON to FILE")->type_name("FILE");
  AddValue(app, "--size", WholeNumber(settings.Render.Size, 8, 8192), BadValueComplaint("--size"),
           "pixels per view side (default 512)")
    ->type_name("N");
  app
    .add_option_function<std::string>(
      "--color-array",
      [&settings](const std::string& name)
      { settings.Render.ColorArray = settings.Snapshot.ColorArray = name; },
      "colour array (default: the active point scalars)")
    ->type_name("NAME");
  app.add_flag_callback(
    "--no-lit", [&settings] { settings.Render.Lit = false; }, "skip the lit (shape) pass");
  app.add_flag_callback(
    "--no-unlit", [&settings] { settings.Render.Unlit = false; }, "skip the unlit (colour) pass");
  app
    .add_option("--images", settings.Render.ImageDirectory,
                "write every view's renders and difference (x5) as PNG in DIR")
    ->type_name("DIR");
}

/// The snapshot picture.
void AddSnapshotOptions(CLI::App& app, Settings& settings)
{
  fid::SnapshotOptions& snapshot = settings.Snapshot;
  app
    .add_option("--snapshot", settings.SnapshotPath,
                "write a 2x2 picture: original | simplified, lit over unlit")
    ->type_name("FILE.png");
  AddValue(app, "--snapshot-size", WholeNumber(settings.SnapshotSize, 16, 4096),
           BadValueComplaint("--snapshot-size"), "pixels per snapshot panel (default 600)")
    ->type_name("N");
  AddValue(
    app, "--view",
    [&snapshot](const std::string& text) { return fid::ParseView(text, snapshot.ViewDirection); },
    BadValueComplaint("--view"), "snapshot view: +X -X +Y -Y +Z -Z iso (default iso)")
    ->type_name("V");
  AddValue(
    app, "--zoom",
    [&snapshot](const std::string& text)
    {
      double zoom = 0;
      const bool ok = ParseNumber(text, zoom) && zoom > 0.0;
      snapshot.Zoom = ok ? zoom : snapshot.Zoom;
      return ok;
    },
    BadValueComplaint("--zoom"), "snapshot close-up factor (default 1)")
    ->type_name("Z");
  AddValue(
    app, "--center",
    [&snapshot](const std::string& text)
    { return std::sscanf(text.c_str(), "%lf,%lf", &snapshot.Center[0], &snapshot.Center[1]) == 2; },
    BadValueComplaint("--center"), "close-up centre in the view's unit square (default 0.5,0.5)")
    ->type_name("X,Y");
  app
    .add_option("--label", snapshot.SimplifiedLabel,
                "label of the simplified column (default: simplified)")
    ->type_name("TEXT");
  app.add_flag_callback(
    "--no-labels", [&snapshot] { snapshot.Labels = false; }, "no text in the snapshot");
}

/// Simplifying ORIGINAL here instead of reading SIMPLIFIED.
void AddDecimateOptions(CLI::App& app, Settings& settings)
{
  AddValue(
    app, "--decimate",
    [&settings](const std::string& text)
    {
      double r = 0;
      const bool ok = ParseNumber(text, r) && r >= 0.0 && r < 1.0;
      settings.Reduction = ok ? r : settings.Reduction;
      return ok;
    },
    BadValueComplaint("--decimate"),
    "no SIMPLIFIED file: simplify ORIGINAL here, removing the fraction R\n"
    "of its triangles, with --method:")
    ->type_name("R");
  AddChoice<std::string>(app, "--method", settings.Method,
                         { { "halfedge", "halfedge" },
                           { "geometry", "geometry" },
                           { "quadric", "quadric" },
                           { "quadric-attr", "quadric-attr" } },
                         BadValueComplaint("--method"),
                         "halfedge (vtkColorHalfEdgeDecimation, default), geometry\n"
                         "(its geometry-only metric), quadric (vtkQuadricDecimation,\n"
                         "colours of the nearest original vertex), quadric-attr\n"
                         "(vtkQuadricDecimation with its attribute error metric)")
    ->type_name("M");
  app
    .add_option("--save-simplified", settings.SavePath,
                "write the simplified mesh (.vtp, .ply or .vtk)")
    ->type_name("F");
}

/// ORIGINAL simplified by --method to --decimate; `decimation` gets what was done.
vtkSmartPointer<vtkPolyData> Decimate(vtkPolyData* original, const Settings& settings,
                                      Json& decimation)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkSmartPointer<vtkPolyData> simplified;
  if (settings.Method == "halfedge" || settings.Method == "geometry")
  {
    vtkNew<vtkColorHalfEdgeDecimation> filter;
    filter->SetInputData(original);
    filter->SetTargetReduction(settings.Reduction);
    if (settings.Method == "geometry")
    {
      filter->SetErrorMetricToGeometry();
    }
    filter->Update();
    simplified = filter->GetOutput();
  }
  else
  {
    simplified = fid::SimplifyWithQuadric(
      original, settings.Reduction, settings.Method == "quadric-attr", settings.Render.ColorArray);
  }
  timer->StopTimer();
  const double in = static_cast<double>(original->GetNumberOfPolys());
  const double out = static_cast<double>(simplified->GetNumberOfPolys());
  decimation = { { "method", settings.Method },
                 { "target_reduction", settings.Reduction },
                 { "actual_reduction", in > 0 ? 1.0 - out / in : 0.0 },
                 { "seconds", timer->GetElapsedTime() } };
  return simplified;
}

/// The meshes: ORIGINAL and SIMPLIFIED read, or ORIGINAL read and simplified here.
bool Meshes(const Settings& settings, vtkSmartPointer<vtkPolyData> meshes[2], Json& decimation)
{
  std::string error;
  meshes[0] = fid::ReadMesh(settings.Original, &error);
  if (meshes[0] && settings.Reduction >= 0.0)
  {
    meshes[1] = Decimate(meshes[0], settings, decimation);
    if (!settings.SavePath.empty() && !WriteMesh(meshes[1], settings.SavePath, "", error))
    {
      meshes[1] = nullptr;
    }
  }
  else if (meshes[0])
  {
    meshes[1] = fid::ReadMesh(settings.Simplified, &error);
  }
  if (!meshes[0] || !meshes[1])
  {
    std::cerr << Program << ": " << error << "\n";
    return false;
  }
  return true;
}

/// The snapshot, labelled by the method when simplified here.
bool Snapshot(const Settings& settings, vtkPolyData* original, vtkPolyData* simplified)
{
  fid::SnapshotOptions snapshot = settings.Snapshot;
  if (snapshot.SimplifiedLabel.empty() && settings.Reduction >= 0.0)
  {
    snapshot.SimplifiedLabel = settings.Method + " " +
      std::to_string(static_cast<int>(settings.Reduction * 100.0 + 0.5)) + " %";
  }
  std::string error;
  if (!fid::WriteSnapshot(original, simplified, settings.SnapshotPath, settings.SnapshotSize,
                          snapshot, &error))
  {
    std::cerr << Program << ": " << error << "\n";
    return false;
  }
  return true;
}

/// Measures, prints and writes the JSON, then the snapshot; the exit status.
int Run(const Settings& settings)
{
  vtkSmartPointer<vtkPolyData> meshes[2];
  Json decimation;
  if (!Meshes(settings, meshes, decimation))
  {
    return 1;
  }
  const fid::Result result = fid::CompareRenders(meshes[0], meshes[1], settings.Render);
  Json json;
  if (!decimation.is_null())
  {
    json["decimation"] = decimation; // first, before the measures
  }
  json.update(fid::ResultJson(result));
  std::cout << JsonText(json) << std::endl;
  std::string error;
  if (!settings.JsonPath.empty() && !WriteJsonFile(json, settings.JsonPath, error))
  {
    std::cerr << Program << ": " << error << "\n";
    return 1;
  }
  if (!result.Ok)
  {
    std::cerr << Program << ": " << result.Error << "\n";
    return 2;
  }
  return settings.SnapshotPath.empty() || Snapshot(settings, meshes[0], meshes[1]) ? 0 : 2;
}
} // namespace

int main(int argc, char* argv[])
{
  UseAllCoresByDefault(); // vtkSMPTools on all cores unless asked otherwise
  CLI::App app(
    "Renders both meshes offscreen from the six axis views with the same orthographic\n"
    "camera (fitted to ORIGINAL), unlit (colour alone) and lit (grey shape), and prints as\n"
    "JSON the RMS of the per-pixel RGB distance over covered pixels (0-255) and the PSNR\n"
    "(dB). Meshes: .ply .vtp .vtu .vtk .obj .stl or demo: specifications. Needs an X\n"
    "display: use `xvfb-run -a` headless.",
    Program);
  SetUpCommandLine(app,
                   "Usage: color-decimate-eval ORIGINAL SIMPLIFIED [options]\n"
                   "       color-decimate-eval ORIGINAL --decimate R [--method M] [options]");
  Settings settings;
  AddMeasureOptions(app, settings);
  AddSnapshotOptions(app, settings);
  AddDecimateOptions(app, settings);
  const int status = ParseCommandLine(app, argc, argv, UsageStatus);
  if (status >= 0)
  {
    return status;
  }
  if (settings.Reduction >= 0.0 && !settings.Simplified.empty())
  {
    return ReportUsageError(app, "SIMPLIFIED and --decimate exclude each other", UsageStatus);
  }
  if (settings.Reduction < 0.0 && settings.Simplified.empty())
  {
    return ReportUsageError(app, "missing SIMPLIFIED (or --decimate R)", UsageStatus);
  }
  return Run(settings);
}
