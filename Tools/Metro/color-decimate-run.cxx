// color-decimate-run: one simplification of a mesh by one method, for the fidelity benchmark
// (Tools/fidelity-benchmark.py): vtkColorHalfEdgeDecimation with any of its metrics and
// options, vtkQuadricDecimation (attribute error metric on or off) or meshoptimizer's
// meshopt_simplify; writes the result and, as JSON, the time, the peak memory and the
// metric's bytes per vertex.
#include "MeshColors.h"
#include "MeshIO.h"
#include "ProcessMemory.h"
#include "QuadricPeer.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkQuadricDecimation.h"
#include "vtkUnsignedCharArray.h"

#ifndef COLORDECIMATION_WITH_MESHOPTIMIZER
#define COLORDECIMATION_WITH_MESHOPTIMIZER 0
#endif
#if COLORDECIMATION_WITH_MESHOPTIMIZER
#include "MeshOptimizer.h"
#endif

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace colordecimation::tools;

namespace
{
const char* Usage =
  "usage: color-decimate-run INPUT OUTPUT --method M [options]\n"
  "\n"
  "Simplifies INPUT with one method and writes OUTPUT (.vtp keeps every array; .ply, .vtk).\n"
  "Methods:\n"
  "  half-edge-color   vtkColorHalfEdgeDecimation, the paper's metric (default)\n"
  "  geometry          vtkColorHalfEdgeDecimation, quadric error only\n"
  "  color-quadric     vtkColorHalfEdgeDecimation, Garland-Heckbert's colour quadric\n"
  "  vtk-quadric       vtkQuadricDecimation (--attributes: its attribute error metric on,\n"
  "                    with the colours as scalars; without, the output has no colour and\n"
  "                    gets the colour of the nearest input vertex, after the timing)\n"
  "  meshopt           meshoptimizer's meshopt_simplify (geometry only; the output keeps\n"
  "                    input vertices, with all their point data)\n"
  "Options:\n"
  "  --reduction R         fraction of triangles to remove (default 0.9)\n"
  "  --placement           color-quadric: optimal placement (full collapses)\n"
  "  --cielab              measure colour in CIELab (the vtkColorHalfEdgeDecimation metrics)\n"
  "  --geometry-weight W   GeometryWeight (half-edge-color)\n"
  "  --color-weight W      ColorWeight (color-quadric)\n"
  "  --boundary-weight W   BoundaryWeight (vtkColorHalfEdgeDecimation)\n"
  "  --preserve-boundary   PreserveBoundary (vtkColorHalfEdgeDecimation)\n"
  "  --attributes          vtk-quadric: AttributeErrorMetric on\n"
  "  --clean               vtk-quadric: merge coincident points and drop the triangles\n"
  "                        that become degenerate first (vtkCleanPolyData, not timed)\n"
  "  --json FILE           write the figures as JSON\n";

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
};

std::string Json(const Figures& f)
{
  std::ostringstream os;
  os.precision(9);
  os << "{\n  \"method\": \"" << f.Method << "\",\n  \"seconds\": " << f.Seconds
     << ",\n  \"peak_bytes\": " << f.PeakBytes
     << ",\n  \"peak_reset\": " << (f.PeakReset ? "true" : "false")
     << ",\n  \"state_bytes\": " << f.StateBytes
     << ",\n  \"metric_bytes_per_vertex\": " << f.MetricBytesPerVertex
     << ",\n  \"metric_bytes_note\": \"" << f.MetricBytesNote << "\""
     << ",\n  \"input_points\": " << f.InputPoints
     << ",\n  \"input_triangles\": " << f.InputTriangles
     << ",\n  \"output_points\": " << f.OutputPoints
     << ",\n  \"output_triangles\": " << f.OutputTriangles << "\n}\n";
  return os.str();
}

bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end && !*end && end != text.c_str() && std::isfinite(value);
}
} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::string> positional;
  std::string method = "half-edge-color", jsonPath;
  double reduction = 0.9, geometryWeight = 1.0, colorWeight = 1.0, boundaryWeight = 0.0;
  bool placement = false, cielab = false, attributes = false, preserveBoundary = false;
  bool clean = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string
    {
      if (i + 1 >= argc)
      {
        std::cerr << "color-decimate-run: " << arg << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    auto number = [&](double& out, double lo, double hi)
    {
      const std::string text = value();
      if (!ParseNumber(text, out) || out < lo || out > hi)
      {
        std::cerr << "color-decimate-run: bad value '" << text << "' for " << arg << "\n";
        std::exit(2);
      }
    };
    if (arg == "-h" || arg == "--help")
    {
      std::cout << Usage;
      return 0;
    }
    else if (arg == "--method")
    {
      method = value();
    }
    else if (arg == "--reduction")
    {
      number(reduction, 0.0, 1.0);
    }
    else if (arg == "--geometry-weight")
    {
      number(geometryWeight, 0.0, 1e300);
    }
    else if (arg == "--color-weight")
    {
      number(colorWeight, 0.0, 1e300);
    }
    else if (arg == "--boundary-weight")
    {
      number(boundaryWeight, 0.0, 1e300);
    }
    else if (arg == "--placement")
    {
      placement = true;
    }
    else if (arg == "--cielab")
    {
      cielab = true;
    }
    else if (arg == "--attributes")
    {
      attributes = true;
    }
    else if (arg == "--clean")
    {
      clean = true;
    }
    else if (arg == "--preserve-boundary")
    {
      preserveBoundary = true;
    }
    else if (arg == "--json")
    {
      jsonPath = value();
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      std::cerr << "color-decimate-run: unknown option '" << arg << "'\n" << Usage;
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
  const bool ours =
    method == "half-edge-color" || method == "geometry" || method == "color-quadric";
  if (!ours && method != "vtk-quadric" && method != "meshopt")
  {
    std::cerr << "color-decimate-run: unknown method '" << method << "'\n";
    return 2;
  }
#if !COLORDECIMATION_WITH_MESHOPTIMIZER
  if (method == "meshopt")
  {
    std::cerr << "color-decimate-run: built without meshoptimizer\n";
    return 3;
  }
#endif

  std::string description, error;
  vtkSmartPointer<vtkPolyData> read = ReadMesh(positional[0], description, error);
  if (!read)
  {
    std::cerr << "color-decimate-run: " << error << "\n";
    return 1;
  }
  vtkSmartPointer<vtkPolyData> input = Triangulated(read);
  read = nullptr;
  if (clean && method == "vtk-quadric")
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
  Figures figures;
  figures.Method = method;
  figures.InputPoints = input->GetNumberOfPoints();
  figures.InputTriangles = input->GetNumberOfPolys();

  vtkSmartPointer<vtkPolyData> output;
  {
    PeakMemoryProbe probe;
    const auto start = std::chrono::steady_clock::now();
    if (ours)
    {
      vtkNew<vtkColorHalfEdgeDecimation> filter;
      filter->SetInputData(input);
      filter->SetTargetReduction(reduction);
      filter->SetErrorMetric(method == "geometry" ? vtkColorHalfEdgeDecimation::Geometry
                               : method == "color-quadric"
                               ? vtkColorHalfEdgeDecimation::ColorQuadric
                               : vtkColorHalfEdgeDecimation::HalfEdgeColor);
      filter->SetOptimalPlacement(placement);
      filter->SetColorSpace(cielab ? vtkColorHalfEdgeDecimation::CIELab
                                   : vtkColorHalfEdgeDecimation::RGB);
      filter->SetGeometryWeight(geometryWeight);
      filter->SetColorWeight(colorWeight);
      filter->SetBoundaryWeight(boundaryWeight);
      filter->SetPreserveBoundary(preserveBoundary);
      filter->Update();
      output = filter->GetOutput();
      figures.StateBytes = filter->GetStateMemory();
      figures.MetricBytesPerVertex = method == "color-quadric" ? 112 : 48;
      figures.MetricBytesNote = method == "color-quadric"
        ? "28 floats (6-D quadric)"
        : "12 floats (quadric 10, importance, max colour distance)";
    }
    else if (method == "vtk-quadric")
    {
      vtkNew<vtkQuadricDecimation> filter;
      filter->SetInputData(input);
      filter->SetTargetReduction(reduction);
      colordecimation::tools::ConfigureQuadricPeer(filter, attributes);
      filter->Update();
      output = filter->GetOutput();
      // vtkQuadricDecimation keeps per vertex a sparse quadric of 11 + 4 m doubles (m the
      // attribute components: 3 for RGB).
      const int m = attributes && input->GetPointData()->GetScalars()
        ? input->GetPointData()->GetScalars()->GetNumberOfComponents()
        : 0;
      figures.MetricBytesPerVertex = 8.0 * (11 + 4 * m);
      figures.MetricBytesNote = std::to_string(11 + 4 * m) + " doubles (sparse quadric)";
    }
#if COLORDECIMATION_WITH_MESHOPTIMIZER
    else
    {
      output = colordecimation::tools::MakeMeshOptimizerOutput(
        input, colordecimation::tools::SimplifyWithMeshOptimizer(input, reduction));
      // meshopt_simplify keeps a quadric of 11 floats per vertex (and other per-vertex
      // tables: remap, kind, adjacency).
      figures.MetricBytesPerVertex = 44;
      figures.MetricBytesNote = "11 floats (quadric)";
    }
#endif
    figures.Seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    figures.PeakBytes = probe.PeakAboveBaseline();
    figures.PeakReset = probe.PeakWasReset();
  }
  if (method == "vtk-quadric" && !attributes)
  {
    TransferNearestColors(input, output);
  }
  figures.OutputPoints = output->GetNumberOfPoints();
  figures.OutputTriangles = output->GetNumberOfPolys();

  if (!WriteMesh(output, positional[1], "", error))
  {
    std::cerr << "color-decimate-run: " << error << "\n";
    return 1;
  }
  const std::string json = Json(figures);
  std::cout << json;
  if (!jsonPath.empty())
  {
    std::ofstream out(jsonPath);
    out << json;
  }
  return 0;
}
