// Checks the render-based fidelity measures of ColorDecimation::Fidelity on cases whose
// answer is known: identical meshes, a uniform colour shift, a moved copy, float colours,
// colours lost and restored by TransferNearestColors, the snapshot PNG and the JSON.
//
// usage: TestFidelityMeasures TEMPDIR
#include "ColorDecimationFidelity.h"
#include "ColorDecimationMeshes.h"
#include "ColorDecimationTestUtilities.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

namespace fid = colordecimation::fidelity;
namespace meshes = colordecimation::meshes;
using colordecimation::testing::Copy;

namespace
{

void SetConstantColor(vtkPolyData* mesh, int r, int g, int b)
{
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetScalars());
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    rgb->SetTypedComponent(i, 0, static_cast<unsigned char>(r));
    rgb->SetTypedComponent(i, 1, static_cast<unsigned char>(g));
    rgb->SetTypedComponent(i, 2, static_cast<unsigned char>(b));
  }
}

void ToFloatColors(vtkPolyData* mesh)
{
  vtkDataArray* rgb = mesh->GetPointData()->GetScalars();
  vtkNew<vtkFloatArray> colors;
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(rgb->GetNumberOfTuples());
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      colors->SetComponent(i, c, rgb->GetComponent(i, c) / 255.0);
    }
  }
  mesh->GetPointData()->RemoveArray("RGB");
  mesh->GetPointData()->SetScalars(colors);
}

/// |a - b| <= tolerance (absolute).
bool Near(double a, double b, double tolerance)
{
  return std::fabs(a - b) <= tolerance;
}

/// 1. Identical meshes: nothing differs; PSNR is infinite.
fid::Result CheckIdentical(vtkPolyData* sphere, const fid::Options& options)
{
  const fid::Result same = fid::CompareRenders(sphere, sphere, options);
  CD_CHECK_MSG(same.Ok, "identical meshes render");
  CD_CHECK_MSG(same.Unlit.All.CoveredPixels > 6 * 200 * 200 / 4, "the sphere covers its views");
  CD_CHECK_MSG(same.Unlit.Views.size() == 6 && same.Lit.Views.size() == 6, "six views per pass");
  CD_CHECK_MSG(same.Unlit.All.Rms == 0.0 && same.Lit.All.Rms == 0.0, "identical meshes: RMS 0");
  CD_CHECK_MSG(std::isinf(same.Unlit.All.Psnr), "identical meshes: PSNR +inf");
  const std::string json = fid::ToJson(same);
  CD_CHECK_MSG(json.find("\"psnr\": null") != std::string::npos &&
                 json.find("\"color_array\": \"RGB\"") != std::string::npos,
               "JSON writes an infinite PSNR as null and names the colour array");
  return same;
}

/// 2. A uniform colour shift of (10, -20, 5) on a constant mesh: every covered pixel is off
/// by sqrt(525); the shape is unchanged.
fid::Result CheckShift(vtkPolyData* constant, vtkPolyData* shifted, const fid::Options& options)
{
  const fid::Result shift = fid::CompareRenders(constant, shifted, options);
  const double expectedRms = std::sqrt(525.0);
  const double expectedPsnr = 10.0 * std::log10(255.0 * 255.0 / (525.0 / 3.0));
  std::cout << "        shift: unlit RMS " << shift.Unlit.All.Rms << " (expected " << expectedRms
            << "), PSNR " << shift.Unlit.All.Psnr << " (expected " << expectedPsnr << ")\n";
  CD_CHECK_MSG(Near(shift.Unlit.All.Rms, expectedRms, 0.05),
               "colour shift: RMS = sqrt(10^2+20^2+5^2)");
  CD_CHECK_MSG(Near(shift.Unlit.All.Psnr, expectedPsnr, 0.02), "colour shift: PSNR = 25.70 dB");
  CD_CHECK_MSG(shift.Lit.All.Rms == 0.0, "colour shift: the lit (shape) pass sees no change");
  return shift;
}

/// `mesh` moved by 0.2 along x (a fifth of the unit sphere's radius).
vtkSmartPointer<vtkPolyData> Moved(vtkPolyData* mesh)
{
  auto moved = Copy(mesh);
  for (vtkIdType i = 0; i < moved->GetNumberOfPoints(); ++i)
  {
    double p[3];
    moved->GetPoint(i, p);
    p[0] += 0.2;
    moved->GetPoints()->SetPoint(i, p);
  }
  return moved;
}

/// 3. A copy moved by a fifth of the radius: shape and colour both differ, and the pixels
/// covered by either mesh outnumber those of one mesh.
void CheckMoved(vtkPolyData* sphere, vtkPolyData* moved, const fid::Result& same,
                const fid::Options& options)
{
  fid::Result move = fid::CompareRenders(sphere, moved, options);
  std::cout << "        moved: unlit RMS " << move.Unlit.All.Rms << ", lit RMS " << move.Lit.All.Rms
            << "\n";
  CD_CHECK_MSG(move.Unlit.All.Rms > 10.0 && move.Lit.All.Rms > 10.0,
               "moved copy: both passes differ");
  CD_CHECK_MSG(move.Unlit.All.CoveredPixels > same.Unlit.All.CoveredPixels,
               "moved copy: the union of the silhouettes is counted");
}

/// 4. Float colours in [0,1] are scaled to 0..255: same figures as unsigned char.
void CheckFloatColors(vtkPolyData* constant, vtkPolyData* shifted, const fid::Result& shift,
                      const fid::Options& options)
{
  auto floatA = Copy(constant);
  auto floatB = Copy(shifted);
  ToFloatColors(floatA);
  ToFloatColors(floatB);
  fid::Result floats = fid::CompareRenders(floatA, floatB, options);
  CD_CHECK_MSG(Near(floats.Unlit.All.Rms, shift.Unlit.All.Rms, 0.05), "float colours in [0,1]");
}

/// 5. Colours lost (the mesh renders white), then restored from the nearest points.
void CheckLostColors(vtkPolyData* sphere, const fid::Options& options)
{
  auto bare = Copy(sphere);
  bare->GetPointData()->RemoveArray("RGB");
  fid::Result lost = fid::CompareRenders(sphere, bare, options);
  CD_CHECK_MSG(lost.Unlit.All.Rms > 50.0, "a mesh without colours is far from the original");
  CD_CHECK_MSG(fid::TransferNearestColors(sphere, bare), "TransferNearestColors succeeds");
  fid::Result restored = fid::CompareRenders(sphere, bare, options);
  CD_CHECK_MSG(restored.Unlit.All.Rms == 0.0, "nearest-point colours of the same points: RMS 0");
}

/// 6. The per-view images and the snapshot.
void CheckImages(vtkPolyData* sphere, vtkPolyData* moved, fid::Options options,
                 const std::string& temporary)
{
  options.ImageDirectory = temporary;
  std::string why;
  const std::string views[] = { temporary + "/unlit_-Z_difference.png",
                                temporary + "/lit_+X_original.png" };
  for (const std::string& view : views)
  {
    std::remove(view.c_str()); // an earlier run's must not pass
  }
  const fid::Result result = fid::CompareRenders(sphere, moved, options);
  CD_CHECK_MSG(result.Ok, "CompareRenders with images: " << result.Error);
  CD_CHECK_MSG(std::ifstream(views[0]).good() && std::ifstream(views[1]).good(),
               "per-view images are written");
  const std::string snapshot = temporary + "/fidelity_snapshot.png";
  std::remove(snapshot.c_str());
  CD_CHECK_MSG(fid::WriteSnapshot(sphere, moved, snapshot, 100, {}, &why),
               "WriteSnapshot succeeds");
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(snapshot.c_str());
  reader->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  CD_CHECK_MSG(dims[0] == 2 * 100 + 2 && dims[1] == 2 * 100 + 2,
               "snapshot: 2 x 2 panels of 100 px");
  // Each panel shows the mesh: its centre pixel is not the black background.
  bool panelsDrawn = true;
  for (int px : { 50, 152 })
  {
    for (int py : { 50, 152 })
    {
      double sum = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        sum += reader->GetOutput()->GetScalarComponentAsDouble(px, py, 0, c);
      }
      panelsDrawn = panelsDrawn && sum > 30.0;
    }
  }
  CD_CHECK_MSG(panelsDrawn, "snapshot: the mesh is drawn in all four panels");
}

/// 7. Errors are reported, not crashed on.
void CheckErrors(vtkPolyData* sphere, const fid::Options& options, const std::string& temporary)
{
  fid::Options badArray = options;
  badArray.ColorArray = "NoSuchArray";
  fid::Result bad = fid::CompareRenders(sphere, sphere, badArray);
  CD_CHECK_MSG(!bad.Ok && !bad.Error.empty(), "an unknown colour array is an error");
  CD_CHECK_MSG(!fid::ReadMesh(temporary + "/missing.ply"), "ReadMesh of a missing file is null");
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string temporary = argc > 1 ? argv[1] : ".";
  std::string why;
  if (!fid::CanRender(&why))
  {
    std::cerr << "cannot render: " << why << "\n";
    return 1;
  }
  fid::Options options;
  options.Size = 200;
  auto sphere = meshes::Icosphere(4, meshes::Pattern::SmoothGradient);
  const fid::Result same = CheckIdentical(sphere, options);
  auto constant = meshes::Icosphere(4, meshes::Pattern::Constant);
  auto shifted = Copy(constant);
  SetConstantColor(constant, 180, 140, 100);
  SetConstantColor(shifted, 190, 120, 105);
  const fid::Result shift = CheckShift(constant, shifted, options);
  auto moved = Moved(sphere);
  CheckMoved(sphere, moved, same, options);
  CheckFloatColors(constant, shifted, shift, options);
  CheckLostColors(sphere, options);
  CheckImages(sphere, moved, options, temporary);
  CheckErrors(sphere, options, temporary);

  const int failures = colordecimation::testing::GetNumberOfFailures();
  std::cout << (failures ? "FAILED: " : "all passed: ") << failures << " failure(s)\n";
  return failures ? 1 : 0;
}
