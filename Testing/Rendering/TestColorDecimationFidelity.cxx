// Colour fidelity of vtkColorHalfEdgeDecimation against vtkQuadricDecimation at 90 %, on
// generated coloured meshes, measured by ColorDecimation::Fidelity (RMS of the per-pixel
// RGB distance of unlit renders over six axis views, the measure of Kim, Choi and Lee's
// Table 3; PSNR; and the same on lit grey renders for the shape).
//
// Compared:
// - halfedge:      vtkColorHalfEdgeDecimation (the colour-aware half-edge metric);
// - geometry:      vtkColorHalfEdgeDecimation with its geometry-only metric;
// - quadric:       vtkQuadricDecimation, AttributeErrorMetric off (it drops colour), its
//                  output coloured by the nearest original vertex (vtkPointLocator);
// - quadric-attr:  vtkQuadricDecimation with AttributeErrorMetric on (colours optimised and
//                  interpolated by it).
// Asserts that, on every scene with colour features (sharp regions, fine detail), halfedge's
// unlit RMS is lower than quadric's (and that the comparison is not skewed: quadric
// removes no more triangles than halfedge).
//
// usage: TestColorDecimationFidelity [--size N] [--geometry-weight W] [--markdown FILE]
#include "ColorDecimationFidelity.h"
#include "ColorDecimationMeshes.h"

#include "vtkColorHalfEdgeDecimation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace fid = colordecimation::fidelity;
namespace meshes = colordecimation::meshes;

namespace
{

struct Case
{
  const char* Name;
  vtkSmartPointer<vtkPolyData> (*Make)();
  bool Asserted;
};

vtkSmartPointer<vtkPolyData> SharpIcosphere()
{
  return meshes::Icosphere(5, meshes::Pattern::SharpRegions);
}
vtkSmartPointer<vtkPolyData> SmoothTorus()
{
  return meshes::Torus(96, 40, meshes::Pattern::SmoothGradient);
}
vtkSmartPointer<vtkPolyData> FineDetailSphere()
{
  return meshes::UVSphere(160, meshes::Pattern::FineDetail);
}
vtkSmartPointer<vtkPolyData> SharpGrid()
{
  return meshes::Grid(128, 128, meshes::Pattern::SharpRegions);
}
vtkSmartPointer<vtkPolyData> FineDetailGrid()
{
  return meshes::Grid(128, 128, meshes::Pattern::FineDetail);
}

double GeometryWeight = 1.0;

vtkSmartPointer<vtkPolyData> Simplify(vtkPolyData* input, const std::string& method, double r)
{
  vtkSmartPointer<vtkPolyData> output;
  if (method == "halfedge" || method == "geometry")
  {
    vtkNew<vtkColorHalfEdgeDecimation> filter;
    filter->SetInputData(input);
    filter->SetTargetReduction(r);
    filter->SetGeometryWeight(GeometryWeight);
    if (method == "geometry")
    {
      filter->SetErrorMetricToGeometry();
    }
    filter->Update();
    output = filter->GetOutput();
    return output;
  }
  return fid::SimplifyWithQuadric(input, r, method == "quadric-attr");
}

const char* const Methods[] = { "halfedge", "geometry", "quadric", "quadric-attr" };

/// One scene measured with each method (a table row each); whether it passes: the half-edge
/// filter's unlit RMS below vtkQuadricDecimation's with nearest colours, at no fewer triangles
/// (or the scene is not asserted). False in `rendered` when a rendering failed.
bool MeasureCase(const Case& c, const fid::Options& options, double reduction,
                 std::ostringstream& table, bool& rendered)
{
  auto input = c.Make();
  double rms[4] = { 0, 0, 0, 0 };
  vtkIdType kept[4] = { 0, 0, 0, 0 };
  for (int m = 0; m < 4; ++m)
  {
    auto output = Simplify(input, Methods[m], reduction);
    const fid::Result r = fid::CompareRenders(input, output, options);
    if (!r.Ok)
    {
      std::cerr << "rendering failed: " << r.Error << "\n";
      rendered = false;
      return false;
    }
    rms[m] = r.Unlit.All.Rms;
    kept[m] = output->GetNumberOfPolys();
    table << "| " << c.Name << " (" << input->GetNumberOfPolys() << ") | " << Methods[m] << " | "
          << kept[m] << " | " << r.Unlit.All.Rms << " | " << r.Unlit.All.Psnr << " | "
          << r.Unlit.All.CommonRms << " | " << r.Lit.All.Rms << " | " << r.Lit.All.Psnr << " |\n";
  }
  const bool fair = kept[2] >= kept[0];
  const bool better = rms[0] < rms[2];
  std::cout << c.Name << ": halfedge unlit RMS " << rms[0] << " (" << kept[0]
            << " triangles) vs quadric + nearest colours " << rms[2] << " (" << kept[2]
            << " triangles): "
            << (!c.Asserted        ? "measured, not asserted"
                  : better && fair ? "ok"
                                   : "FAILED")
            << "\n";
  if (!fair)
  {
    std::cerr << "  vtkQuadricDecimation removed more triangles: the comparison is skewed\n";
  }
  return !c.Asserted || (better && fair);
}

} // namespace

int main(int argc, char* argv[])
{
  fid::Options options;
  options.Size = 256;
  std::string markdownPath;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc)
    {
      options.Size = std::atoi(argv[++i]);
    }
    else if (std::strcmp(argv[i], "--geometry-weight") == 0 && i + 1 < argc)
    {
      GeometryWeight = std::atof(argv[++i]);
    }
    else if (std::strcmp(argv[i], "--markdown") == 0 && i + 1 < argc)
    {
      markdownPath = argv[++i];
    }
  }
  std::string why;
  if (!fid::CanRender(&why))
  {
    std::cerr << "cannot render: " << why << "\n";
    return 1;
  }
  // The smooth-gradient torus is measured but not asserted: its colour varies slowly, so
  // the unlit error is mostly the silhouette of the tube, and a half-edge collapse (which
  // keeps the surviving vertex where it is) cannot place vertices as well as the quadric's
  // optimal placement; the geometry-only half-edge metric loses there too (see
  // docs/FIDELITY.md).
  const Case cases[] = { { "Icosphere, sharp regions", SharpIcosphere, true },
                         { "Torus, smooth gradient", SmoothTorus, false },
                         { "UV sphere, fine detail", FineDetailSphere, true },
                         { "Grid (open), sharp regions", SharpGrid, true },
                         { "Grid (open), fine detail", FineDetailGrid, true } };
  std::ostringstream table;
  table << std::fixed << std::setprecision(2);
  table << "| mesh (triangles) | method | triangles left | unlit RMS | unlit PSNR (dB) | unlit RMS"
           " where both cover | lit RMS | lit PSNR (dB) |\n";
  table << "|---|---|---:|---:|---:|---:|---:|---:|\n";
  int failures = 0;
  for (const Case& c : cases)
  {
    bool rendered = true;
    failures += MeasureCase(c, options, 0.9, table, rendered) ? 0 : 1;
    if (!rendered)
    {
      return 1;
    }
  }
  std::cout << "\n" << table.str();
  if (!markdownPath.empty())
  {
    std::ofstream(markdownPath) << table.str();
  }
  std::cout << (failures ? "FAILED: " : "all passed: ") << failures << " scene(s) failed\n";
  return failures ? 1 : 0;
}
