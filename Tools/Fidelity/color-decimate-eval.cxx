// color-decimate-eval: render-based fidelity of a simplified coloured mesh against its
// original (RMS of the per-pixel RGB distance and PSNR over six axis views, unlit and lit),
// printed as JSON; optionally a side-by-side snapshot PNG. See docs/FIDELITY.md.
#include "ColorDecimationFidelity.h"
#include "MeshIO.h"

#include "vtkColorHalfEdgeDecimation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fid = colordecimation::fidelity;

namespace
{

const char* Usage =
  "usage: color-decimate-eval ORIGINAL SIMPLIFIED [options]\n"
  "       color-decimate-eval ORIGINAL --decimate R [--method M] [options]\n"
  "\n"
  "Renders both meshes offscreen from the six axis views with the same orthographic\n"
  "camera (fitted to ORIGINAL), unlit (colour alone) and lit (grey shape), and prints as\n"
  "JSON the RMS of the per-pixel RGB distance over covered pixels (0-255) and the PSNR (dB).\n"
  "Meshes: .ply .vtp .vtu .vtk .obj .stl. Needs an X display: use `xvfb-run -a` headless.\n"
  "\n"
  "options:\n"
  "  --json FILE          also write the JSON to FILE\n"
  "  --size N             pixels per view side (default 512)\n"
  "  --color-array NAME   colour array (default: the active point scalars)\n"
  "  --no-lit             skip the lit (shape) pass\n"
  "  --no-unlit           skip the unlit (colour) pass\n"
  "  --images DIR         write every view's renders and difference (x5) as PNG in DIR\n"
  "  --snapshot FILE.png  write a 2x2 picture: original | simplified, lit over unlit\n"
  "  --snapshot-size N    pixels per snapshot panel (default 600)\n"
  "  --view V             snapshot view: +X -X +Y -Y +Z -Z iso (default iso)\n"
  "  --zoom Z             snapshot close-up factor (default 1)\n"
  "  --center X,Y         close-up centre in the view's unit square (default 0.5,0.5)\n"
  "  --label TEXT         label of the simplified column (default: simplified)\n"
  "  --no-labels          no text in the snapshot\n"
  "  --decimate R         no SIMPLIFIED file: simplify ORIGINAL here, removing the\n"
  "                       fraction R of its triangles, with --method:\n"
  "  --method M           halfedge (vtkColorHalfEdgeDecimation, default), geometry\n"
  "                       (its geometry-only metric), quadric (vtkQuadricDecimation,\n"
  "                       colours of the nearest original vertex), quadric-attr\n"
  "                       (vtkQuadricDecimation with its attribute error metric)\n"
  "  --save-simplified F  write the simplified mesh (.vtp or .ply)\n"
  "  -h, --help           this text\n";

bool ParseInt(const char* text, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (!end || *end || end == text)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

bool ParseDouble(const char* text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end && !*end && end != text;
}

} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::string> positional;
  std::string jsonPath, snapshotPath, method = "halfedge", savePath;
  fid::Options options;
  fid::SnapshotOptions snapshot;
  int snapshotSize = 600;
  double reduction = -1.0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&](const char* what) -> const char*
    {
      if (i + 1 >= argc)
      {
        std::cerr << "color-decimate-eval: " << arg << " needs " << what << "\n";
        std::exit(1);
      }
      return argv[++i];
    };
    auto bad = [&](const char* value)
    {
      std::cerr << "color-decimate-eval: bad value '" << value << "' for " << arg << "\n";
      std::exit(1);
    };
    if (arg == "-h" || arg == "--help")
    {
      std::cout << Usage;
      return 0;
    }
    else if (arg == "--json")
    {
      jsonPath = next("a file");
    }
    else if (arg == "--size")
    {
      const char* v = next("a number");
      if (!ParseInt(v, options.Size) || options.Size < 8 || options.Size > 8192)
      {
        bad(v);
      }
    }
    else if (arg == "--color-array")
    {
      options.ColorArray = snapshot.ColorArray = next("a name");
    }
    else if (arg == "--images")
    {
      options.ImageDirectory = next("a folder");
    }
    else if (arg == "--no-lit")
    {
      options.Lit = false;
    }
    else if (arg == "--no-unlit")
    {
      options.Unlit = false;
    }
    else if (arg == "--snapshot")
    {
      snapshotPath = next("a file");
    }
    else if (arg == "--snapshot-size")
    {
      const char* v = next("a number");
      if (!ParseInt(v, snapshotSize) || snapshotSize < 16 || snapshotSize > 4096)
      {
        bad(v);
      }
    }
    else if (arg == "--view")
    {
      const char* v = next("a view");
      if (!fid::ParseView(v, snapshot.ViewDirection))
      {
        bad(v);
      }
    }
    else if (arg == "--zoom")
    {
      const char* v = next("a number");
      if (!ParseDouble(v, snapshot.Zoom) || !(snapshot.Zoom > 0.0))
      {
        bad(v);
      }
    }
    else if (arg == "--center")
    {
      const char* v = next("X,Y");
      if (std::sscanf(v, "%lf,%lf", &snapshot.Center[0], &snapshot.Center[1]) != 2)
      {
        bad(v);
      }
    }
    else if (arg == "--label")
    {
      snapshot.SimplifiedLabel = next("a text");
    }
    else if (arg == "--no-labels")
    {
      snapshot.Labels = false;
    }
    else if (arg == "--decimate")
    {
      const char* v = next("a fraction");
      if (!ParseDouble(v, reduction) || reduction < 0.0 || reduction >= 1.0)
      {
        bad(v);
      }
    }
    else if (arg == "--method")
    {
      method = next("a method");
      if (method != "halfedge" && method != "geometry" && method != "quadric" &&
          method != "quadric-attr")
      {
        bad(method.c_str());
      }
    }
    else if (arg == "--save-simplified")
    {
      savePath = next("a file");
    }
    else if (!arg.empty() && arg[0] == '-' && arg != "-")
    {
      std::cerr << "color-decimate-eval: unknown option " << arg << "\n" << Usage;
      return 1;
    }
    else
    {
      positional.push_back(arg);
    }
  }
  const bool decimateHere = reduction >= 0.0;
  if (positional.size() != (decimateHere ? 1u : 2u))
  {
    std::cerr << Usage;
    return 1;
  }

  std::string error;
  vtkSmartPointer<vtkPolyData> original = fid::ReadMesh(positional[0], &error);
  if (!original)
  {
    std::cerr << "color-decimate-eval: " << error << "\n";
    return 1;
  }
  vtkSmartPointer<vtkPolyData> simplified;
  std::ostringstream decimation;
  if (decimateHere)
  {
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    if (method == "halfedge" || method == "geometry")
    {
      vtkNew<vtkColorHalfEdgeDecimation> filter;
      filter->SetInputData(original);
      filter->SetTargetReduction(reduction);
      if (method == "geometry")
      {
        filter->SetErrorMetricToGeometry();
      }
      filter->Update();
      simplified = filter->GetOutput();
    }
    else
    {
      simplified =
        fid::SimplifyWithQuadric(original, reduction, method == "quadric-attr", options.ColorArray);
    }
    timer->StopTimer();
    const double in = static_cast<double>(original->GetNumberOfPolys());
    const double out = static_cast<double>(simplified->GetNumberOfPolys());
    decimation << "  \"decimation\": {\"method\": \"" << method
               << "\", \"target_reduction\": " << reduction
               << ", \"actual_reduction\": " << (in > 0 ? 1.0 - out / in : 0.0)
               << ", \"seconds\": " << timer->GetElapsedTime() << "},\n";
    if (!savePath.empty() && !colordecimation::tools::WriteMesh(simplified, savePath, "", error))
    {
      std::cerr << "color-decimate-eval: " << error << "\n";
      return 1;
    }
  }
  else
  {
    simplified = fid::ReadMesh(positional[1], &error);
    if (!simplified)
    {
      std::cerr << "color-decimate-eval: " << error << "\n";
      return 1;
    }
  }

  const fid::Result result = fid::CompareRenders(original, simplified, options);
  std::string json = fid::ToJson(result);
  if (!decimation.str().empty())
  {
    json.insert(2, decimation.str()); // after "{\n"
  }
  std::cout << json << std::endl;
  if (!jsonPath.empty())
  {
    std::ofstream file(jsonPath);
    file << json << "\n";
    if (!file)
    {
      std::cerr << "color-decimate-eval: could not write " << jsonPath << "\n";
      return 1;
    }
  }
  if (!result.Ok)
  {
    std::cerr << "color-decimate-eval: " << result.Error << "\n";
    return 2;
  }
  if (!snapshotPath.empty())
  {
    if (snapshot.SimplifiedLabel.empty() && decimateHere)
    {
      std::ostringstream label;
      label << method << " " << static_cast<int>(reduction * 100.0 + 0.5) << " %";
      snapshot.SimplifiedLabel = label.str();
    }
    if (!fid::WriteSnapshot(original, simplified, snapshotPath, snapshotSize, snapshot, &error))
    {
      std::cerr << "color-decimate-eval: " << error << "\n";
      return 2;
    }
  }
  return 0;
}
