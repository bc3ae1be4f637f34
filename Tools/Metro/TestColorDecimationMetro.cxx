// Tests of the Metro-style surface distance (ColorDecimationMetro) against closed forms.
// Every case (CD_TEST_CASE(<Case>) below) is its own ctest entry ColorDecimation.Metro.<Case>.
#include "ColorDecimationMetro.h"

#include "ColorDecimationMeshes.h"
#include "ColorDecimationTestUtilities.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cmath>

namespace
{
using colordecimation::metro::Compare;
using colordecimation::metro::Options;
using colordecimation::metro::Result;

/// The unit square at height z, in two triangles.
vtkSmartPointer<vtkPolyData> Square(double z)
{
  return colordecimation::meshes::FromTriangles({ 0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z },
                                                { 0, 1, 2, 0, 2, 3 });
}

CD_TEST_CASE(Identical)
{
  auto sphere = colordecimation::meshes::Icosphere(3, colordecimation::meshes::Pattern::Constant);
  const Result r = Compare(sphere, sphere);
  CD_CHECK(r.Ok);
  CD_CHECK_NEAR(r.Mean, 0, 1e-9);
  CD_CHECK_NEAR(r.Max, 0, 1e-9);
  CD_CHECK_NEAR(r.Diagonal, 2 * std::sqrt(3.0), 1e-6);
}

CD_TEST_CASE(Offset)
{
  // Two parallel unit squares 0.1 apart: every distance is 0.1, both ways.
  const Result r = Compare(Square(0), Square(0.1));
  CD_CHECK(r.Ok);
  for (double d : { r.Forward.Mean, r.Forward.Rms, r.Forward.Max, r.Backward.Mean, r.Backward.Rms,
                    r.Backward.Max, r.Mean, r.Rms, r.Max })
  {
    CD_CHECK_NEAR(d, 0.1, 1e-7);
  }
  CD_CHECK_NEAR(r.Forward.Area, 1.0, 1e-12);
  CD_CHECK_NEAR(r.MeanPercent, 100 * 0.1 / std::sqrt(2.0), 1e-6);
}

CD_TEST_CASE(HalfSquare)
{
  // The simplified surface keeps the half (0,0)-(1,0)-(1,1) of the unit square. From the
  // missing half, the distance is the distance to the diagonal y = x: over that triangle
  // (height h = 1/sqrt2 above the diagonal) its mean is h/3 and its mean square h^2/6; over
  // the whole square, half of those. The maximum is h, at the corner (0,1). Backwards: 0.
  Options options;
  options.Samples = 400000;
  const Result r = Compare(
    Square(0), colordecimation::meshes::FromTriangles({ 0, 0, 0, 1, 0, 0, 1, 1, 0 }, { 0, 1, 2 }),
    options);
  const double h = 1.0 / std::sqrt(2.0);
  CD_CHECK(r.Ok);
  CD_CHECK_NEAR(r.Forward.Mean, 0.5 * h / 3.0, 1e-3);
  CD_CHECK_NEAR(r.Forward.Rms, std::sqrt(0.5 * h * h / 6.0), 1e-3);
  CD_CHECK_NEAR(r.Forward.Max, h, 1e-12);
  CD_CHECK_NEAR(r.Backward.Max, 0.0, 1e-12);
  CD_CHECK_NEAR(r.Mean, r.Forward.Mean, 0);
  CD_CHECK_NEAR(r.Backward.Area, 0.5, 1e-12);
  CD_CHECK(r.OriginalTriangles == 2 && r.SimplifiedTriangles == 1);
}

CD_TEST_CASE(Sphere)
{
  // An icosphere against itself scaled by 1.01 about its centre: the faces move out by
  // 1 % of their distance to the centre (0.9995 for level 4), so every distance is about
  // 0.01 both ways.
  auto sphere = colordecimation::meshes::Icosphere(4, colordecimation::meshes::Pattern::Constant);
  vtkNew<vtkTransform> scale;
  scale->Scale(1.01, 1.01, 1.01);
  vtkNew<vtkTransformPolyDataFilter> transform;
  transform->SetInputData(sphere);
  transform->SetTransform(scale);
  transform->Update();
  const Result r = Compare(sphere, transform->GetOutput());
  CD_CHECK(r.Ok);
  CD_CHECK_NEAR(r.Forward.Mean, 0.01, 2e-4);
  CD_CHECK_NEAR(r.Backward.Mean, 0.01, 2e-4);
  CD_CHECK_NEAR(r.Max, 0.0101, 2e-4);
  CD_CHECK_NEAR(r.RmsPercent, 100 * 0.01 / (2 * std::sqrt(3.0)), 0.01);
}
} // namespace

int main(int argc, char* argv[])
{
  return colordecimation::testing::RunTestCases(argc, argv);
}
