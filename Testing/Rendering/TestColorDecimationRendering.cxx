// Image regression test of vtkColorHalfEdgeDecimation: decimates a generated coloured
// mesh (a scene of ColorDecimationRenderingScenes), renders the result offscreen and
// compares the picture with a committed baseline through VTK's regression machinery
// (vtkRegressionTestImageThreshold, which reads -V BASELINE.png and -T TEMPDIR from the
// command line, and accepts alternates BASELINE_1.png, BASELINE_2.png, ...).
//
// usage: TestColorDecimationRendering SCENE [--reduction R] [--threshold T] [--tamper]
//          [--expect-mismatch] [--write-baseline FILE.png] -V BASELINE.png -T TEMPDIR
//   --reduction R        decimate to R instead of the scene's own reduction
//   --tamper             paint a magenta rectangle over the picture before comparing
//   --expect-mismatch    succeed only when the comparison FAILS (tests that the image
//                        test can fail: a tampered picture, or another reduction)
//   --write-baseline F   write the picture to F and compare nothing (refresh baselines)
#include "ColorDecimationFidelity.h"
#include "ColorDecimationRenderingScenes.h"

#include "vtkActor2D.h"
#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper2D.h"
#include "vtkProperty2D.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

namespace
{

void PaintRectangle(vtkRenderWindow* window)
{
  // A magenta rectangle over a fifth of the left panel, on top of the mesh.
  const int* size = window->GetSize();
  const double x0 = 0.15 * size[0], x1 = 0.30 * size[0];
  const double y0 = 0.30 * size[1], y1 = 0.65 * size[1];
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(x0, y0, 0.0);
  points->InsertNextPoint(x1, y0, 0.0);
  points->InsertNextPoint(x1, y1, 0.0);
  points->InsertNextPoint(x0, y1, 0.0);
  vtkNew<vtkCellArray> quad;
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  quad->InsertNextCell(4, ids);
  vtkNew<vtkPolyData> rectangle;
  rectangle->SetPoints(points);
  rectangle->SetPolys(quad);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(rectangle);
  vtkNew<vtkActor2D> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1.0, 0.0, 1.0);
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  renderer->AddActor2D(actor);
}

std::string ArgumentAfter(int argc, char* argv[], const char* flag)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], flag) == 0)
    {
      return argv[i + 1];
    }
  }
  return std::string();
}

/// The command line after the scene.
struct Arguments
{
  double Reduction = 0.0;
  double Threshold = 0.15; // vtkRegressionTestImage's own default
  bool Tamper = false;
  bool ExpectMismatch = false;
  std::string WriteBaseline;
};

Arguments ParseArguments(int argc, char* argv[], double reduction)
{
  Arguments args;
  args.Reduction = reduction;
  for (int i = 2; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--reduction" && i + 1 < argc)
    {
      args.Reduction = std::atof(argv[++i]);
    }
    else if (arg == "--threshold" && i + 1 < argc)
    {
      args.Threshold = std::atof(argv[++i]);
    }
    else if (arg == "--tamper")
    {
      args.Tamper = true;
    }
    else if (arg == "--expect-mismatch")
    {
      args.ExpectMismatch = true;
    }
    else if (arg == "--write-baseline" && i + 1 < argc)
    {
      args.WriteBaseline = argv[++i];
    }
  }
  return args;
}

/// The window's picture written as the baseline `path`.
int WriteBaseline(vtkRenderWindow* window, const std::string& path)
{
  const bool written = colordecimation::fidelity::SavePng(window, path);
  std::cout << "wrote baseline " << path << "\n";
  return written ? EXIT_SUCCESS : EXIT_FAILURE;
}

/// The window's picture against the baseline (-V); with --expect-mismatch, passing means the
/// comparison failed.
int CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window, const Arguments& args)
{
  const std::string baseline = ArgumentAfter(argc, argv, "-V");
  if (baseline.empty() || !std::ifstream(baseline).good())
  {
    // Without a baseline vtkTesting fails too: an expected mismatch must not pass so.
    std::cerr << "missing baseline (-V): '" << baseline << "'\n";
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImageThreshold(window, args.Threshold);
  if (args.ExpectMismatch)
  {
    if (result == vtkTesting::FAILED)
    {
      std::cout << "the changed picture was rejected, as expected\n";
      return EXIT_SUCCESS;
    }
    std::cerr << "the changed picture was ACCEPTED: the image test cannot fail\n";
    return EXIT_FAILURE;
  }
  return result == vtkTesting::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}

} // namespace

int main(int argc, char* argv[])
{
  namespace cr = colordecimation::rendering;
  if (argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " SCENE [options] -V BASELINE.png -T TEMPDIR\n";
    return EXIT_FAILURE;
  }
  const cr::Scene* scene = cr::FindScene(argv[1]);
  if (!scene)
  {
    std::cerr << "unknown scene " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  const Arguments args = ParseArguments(argc, argv, scene->Reduction);
  auto input = cr::MakeInput(*scene);
  auto output = cr::Decimate(input, args.Reduction);
  const double actual =
    1.0 - static_cast<double>(output->GetNumberOfPolys()) / input->GetNumberOfPolys();
  std::cout << scene->Name << ": " << input->GetNumberOfPolys() << " -> "
            << output->GetNumberOfPolys() << " triangles (reduction " << actual << ", target "
            << args.Reduction << "), " << (scene->Lit ? "lit" : "unlit") << "\n";
  if (output->GetNumberOfPolys() == 0 || actual < args.Reduction - 0.02)
  {
    std::cerr << "the decimation did not reach its target\n";
    return EXIT_FAILURE;
  }
  auto window = cr::MakeWindow(input, output, scene->Lit);
  if (args.Tamper)
  {
    PaintRectangle(window);
  }
  window->Render();
  return args.WriteBaseline.empty() ? CompareWithBaseline(argc, argv, window, args)
                                    : WriteBaseline(window, args.WriteBaseline);
}
