// color-decimate-metro: two-sided surface distance between an original mesh and a simplified
// one by Metro's method (area-uniform sampling, closest-point distances both ways): mean, RMS
// and maximum, also as a percentage of the original's bounding-box diagonal. See
// ColorDecimationMetro.h.
#include "ColorDecimationMetro.h"

#include "MeshIO.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
const char* Usage =
  "usage: color-decimate-metro ORIGINAL SIMPLIFIED [--samples N] [--json FILE] [--quiet]\n"
  "\n"
  "Two-sided surface distance (Metro's method): N points sampled uniformly by area on each\n"
  "surface (default 200000), the distance of each to the closest point of the other\n"
  "surface; mean, RMS and max per side and two-sided (the larger side), in the meshes'\n"
  "units and as % of the ORIGINAL's bounding-box diagonal. The maximum also looks at every\n"
  "vertex. Prints JSON on standard output (and writes it to FILE with --json).\n"
  "Meshes: .ply .vtp .vtu .vtk .obj .stl, or demo: specifications (see color-decimate).\n";

bool ParseCount(const char* text, long long& value)
{
  char* end = nullptr;
  value = std::strtoll(text, &end, 10);
  return end && !*end && end != text && value > 0;
}
} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::string> positional;
  std::string jsonPath;
  bool quiet = false;
  colordecimation::metro::Options options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help")
    {
      std::cout << Usage;
      return 0;
    }
    else if (arg == "--samples" && i + 1 < argc)
    {
      if (!ParseCount(argv[++i], options.Samples))
      {
        std::cerr << "color-decimate-metro: --samples wants a positive whole number\n";
        return 2;
      }
    }
    else if (arg == "--json" && i + 1 < argc)
    {
      jsonPath = argv[++i];
    }
    else if (arg == "--quiet")
    {
      quiet = true;
    }
    else if (!arg.empty() && arg[0] == '-' && arg.compare(0, 5, "demo:") != 0)
    {
      std::cerr << "color-decimate-metro: unknown option '" << arg << "'\n" << Usage;
      return 2;
    }
    else
    {
      positional.push_back(arg);
    }
  }
  if (positional.size() != 2)
  {
    std::cerr << Usage;
    return 2;
  }
  vtkSmartPointer<vtkPolyData> meshes[2];
  for (int k = 0; k < 2; ++k)
  {
    std::string description, error;
    meshes[k] = colordecimation::tools::ReadMesh(positional[k], description, error);
    if (!meshes[k])
    {
      std::cerr << "color-decimate-metro: " << error << "\n";
      return 1;
    }
  }
  const colordecimation::metro::Result result =
    colordecimation::metro::Compare(meshes[0], meshes[1], options);
  const std::string json = colordecimation::metro::ToJson(result);
  if (!quiet)
  {
    std::cout << json;
  }
  if (!jsonPath.empty())
  {
    std::ofstream out(jsonPath);
    out << json;
    if (!out)
    {
      std::cerr << "color-decimate-metro: cannot write '" << jsonPath << "'\n";
      return 1;
    }
  }
  if (!result.Ok)
  {
    std::cerr << "color-decimate-metro: " << result.Error << "\n";
    return 1;
  }
  return 0;
}
