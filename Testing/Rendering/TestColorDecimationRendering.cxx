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
#include "CommandLine.h"

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

/// The command line: the scene, the options, and vtkTesting's -V and -T.
struct Arguments
{
  std::string Scene;
  double Reduction = -1;   ///< -1: the scene's own
  double Threshold = 0.15; // vtkRegressionTestImage's own default
  bool Tamper = false;
  bool ExpectMismatch = false;
  std::string WriteBaseline;
  std::string Baseline;  ///< -V, read by vtkTesting too
  std::string Temporary; ///< -T, read by vtkTesting too
};

/// Parses the command line (CLI11); -1 to go on, otherwise the exit status.
int ParseArguments(int argc, char* argv[], Arguments& args)
{
  namespace tools = colordecimation::tools;
  CLI::App app("Renders a decimated scene and compares it with its baseline (vtkTesting).",
               "TestColorDecimationRendering");
  tools::SetUpCommandLine(app,
                          "Usage: TestColorDecimationRendering SCENE [options] -V "
                          "BASELINE.png -T TEMPDIR");
  app.add_option("SCENE", args.Scene, "the scene's name")->required();
  tools::AddNumber(app, "--reduction", args.Reduction, 0.0, 1.0,
                   tools::BadValueComplaint("--reduction"), "another reduction than the scene's");
  tools::AddNumber(app, "--threshold", args.Threshold, 0.0, 1e9,
                   tools::BadValueComplaint("--threshold"), "vtkTesting's image error threshold");
  app.add_flag("--tamper", args.Tamper, "paint a rectangle over the picture");
  app.add_flag("--expect-mismatch", args.ExpectMismatch, "pass only if the comparison fails");
  app.add_option("--write-baseline", args.WriteBaseline, "write the picture as this baseline");
  app.add_option("-V", args.Baseline, "the baseline picture");
  app.add_option("-T", args.Temporary, "the folder of the test's pictures");
  return tools::ParseCommandLine(app, argc, argv, EXIT_FAILURE);
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
  if (args.Baseline.empty() || !std::ifstream(args.Baseline).good())
  {
    // Without a baseline vtkTesting fails too: an expected mismatch must not pass so.
    std::cerr << "missing baseline (-V): '" << args.Baseline << "'\n";
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
  Arguments args;
  const int status = ParseArguments(argc, argv, args);
  if (status >= 0)
  {
    return status;
  }
  const cr::Scene* scene = cr::FindScene(args.Scene);
  if (!scene)
  {
    std::cerr << "unknown scene " << args.Scene << "\n";
    return EXIT_FAILURE;
  }
  if (args.Reduction < 0)
  {
    args.Reduction = scene->Reduction;
  }
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
