// color-decimate-metro: two-sided surface distance between an original mesh and a simplified
// one by Metro's method (area-uniform sampling, closest-point distances both ways): mean, RMS
// and maximum, also as a percentage of the original's bounding-box diagonal; with --field, the
// difference of a one-component point array on the same samples. See ColorDecimationMetro.h.
#include "ColorDecimationMetro.h"

#include "CommandLine.h"
#include "MeshIO.h"
#include "SmpBackend.h"

#include <fstream>
#include <iostream>
#include <string>

namespace
{
using namespace colordecimation::tools;

const char* const Program = "color-decimate-metro";

struct Settings
{
  std::string Paths[2];
  std::string JsonPath;
  bool Quiet = false;
  colordecimation::metro::Options Metro;
};

void AddOptions(CLI::App& app, Settings& settings)
{
  for (int k = 0; k < 2; ++k)
  {
    app
      .add_option(k == 0 ? "ORIGINAL" : "SIMPLIFIED", settings.Paths[k],
                  k == 0 ? "the original mesh" : "the simplified mesh")
      ->required()
      ->type_name("");
  }
  AddValue(
    app, "--samples",
    [&settings](const std::string& text)
    {
      long long samples = 0;
      const bool ok = ParseWholeNumber(text, samples) && samples > 0;
      settings.Metro.Samples = ok ? samples : settings.Metro.Samples;
      return ok;
    },
    FixedComplaint("--samples wants a positive whole number"),
    "points sampled uniformly by area on each surface (default 200000)")
    ->type_name("N");
  app
    .add_option("--field", settings.Metro.Field,
                "also compare the one-component point array NAME of both meshes on the same "
                "samples (mean, RMS and max of the absolute difference, also as % of its range "
                "on the ORIGINAL)")
    ->type_name("NAME");
  app.add_option("--json", settings.JsonPath, "also write the JSON to FILE")->type_name("FILE");
  app.add_flag("--quiet", settings.Quiet, "print no JSON on standard output");
}

/// Reads both meshes, compares them, prints and writes the JSON; the exit status.
int Run(const Settings& settings)
{
  vtkSmartPointer<vtkPolyData> meshes[2];
  for (int k = 0; k < 2; ++k)
  {
    std::string description, error;
    meshes[k] = ReadMesh(settings.Paths[k], description, error);
    if (!meshes[k])
    {
      std::cerr << Program << ": " << error << "\n";
      return 1;
    }
  }
  const colordecimation::metro::Result result =
    colordecimation::metro::Compare(meshes[0], meshes[1], settings.Metro);
  const std::string json = colordecimation::metro::ToJson(result) + "\n";
  if (!settings.Quiet)
  {
    std::cout << json;
  }
  if (!settings.JsonPath.empty())
  {
    std::ofstream out(settings.JsonPath);
    out << json;
    if (!out)
    {
      std::cerr << Program << ": cannot write '" << settings.JsonPath << "'\n";
      return 1;
    }
  }
  if (!result.Ok)
  {
    std::cerr << Program << ": " << result.Error << "\n";
    return 1;
  }
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  UseAllCoresByDefault(); // vtkSMPTools on all cores unless asked otherwise
  CLI::App app(
    "Two-sided surface distance (Metro's method): N points sampled uniformly by area on each\n"
    "surface, the distance of each to the closest point of the other surface; mean, RMS and\n"
    "max per side and two-sided (the larger side), in the meshes' units and as % of the\n"
    "ORIGINAL's bounding-box diagonal. The maximum also looks at every vertex. With --field\n"
    "NAME, the point array NAME (one component, on both meshes) is interpolated in the\n"
    "triangles at each sample and at its closest point, and the absolute differences are\n"
    "summed the same way (\"field\" in the JSON). Prints JSON on standard output (and writes\n"
    "it to FILE with --json).\n"
    "Meshes: .ply .vtp .vtu .vtk .obj .stl, or demo: specifications (see color-decimate).",
    Program);
  SetUpCommandLine(
    app,
    "Usage: color-decimate-metro ORIGINAL SIMPLIFIED [--samples N] [--field NAME] [--json FILE]\n"
    "       [--quiet]");
  Settings settings;
  AddOptions(app, settings);
  const int status = ParseCommandLine(app, argc, argv);
  return status >= 0 ? status : Run(settings);
}
