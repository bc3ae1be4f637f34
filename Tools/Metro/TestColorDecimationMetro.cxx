// Tests of the Metro-style surface distance (ColorDecimationMetro) against closed forms.
// Every case (CD_TEST_CASE(<Case>) below) is its own ctest entry ColorDecimation.Metro.<Case>.
#include "ColorDecimationMetro.h"

#include "ColorDecimationMeshes.h"
#include "ColorDecimationTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cmath>
#include <functional>
#include <string>

namespace
{
using colordecimation::meshes::FlatGrid;
using colordecimation::meshes::Pattern;
using colordecimation::metro::Compare;
using colordecimation::metro::FieldDifference;
using colordecimation::metro::Options;
using colordecimation::metro::Result;
using colordecimation::metro::ToJson;

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

/// A copy of `mesh` with the point array "T" (double) = field(point), beside its colours.
vtkSmartPointer<vtkPolyData> WithField(vtkPolyData* mesh,
                                       const std::function<double(const double p[3])>& field)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  vtkNew<vtkDoubleArray> values;
  values->SetName("T");
  values->SetNumberOfTuples(copy->GetNumberOfPoints());
  for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
  {
    double p[3];
    copy->GetPoint(i, p);
    values->SetValue(i, field(p));
  }
  copy->GetPointData()->AddArray(values);
  return copy;
}

/// Options that compare the field "T".
Options FieldT()
{
  Options options;
  options.Field = "T";
  return options;
}

/// The field's figures of a side or of both (mean, RMS, max) near `expected`.
void CheckField(const FieldDifference& actual, const FieldDifference& expected, double tolerance)
{
  CD_CHECK_NEAR(actual.Mean, expected.Mean, tolerance);
  CD_CHECK_NEAR(actual.Rms, expected.Rms, tolerance);
  CD_CHECK_NEAR(actual.Max, expected.Max, tolerance);
}

CD_TEST_CASE(FieldIdentical)
{
  // A nonlinear field on a sphere against itself: no difference anywhere. Without --field,
  // no "field" in the JSON.
  auto sphere = WithField(colordecimation::meshes::Icosphere(3, Pattern::Constant),
                          [](const double p[3]) { return p[0] * p[1] + p[2]; });
  const Result r = Compare(sphere, sphere, FieldT());
  CD_CHECK(r.Ok);
  CD_CHECK(r.Field.Name == "T");
  for (const FieldDifference& f : { r.Field.Forward, r.Field.Backward, r.Field.TwoSided })
  {
    CheckField(f, { 0, 0, 0 }, 1e-12);
  }
  CD_CHECK(ToJson(r).find("\"field\": {") != std::string::npos);
  CD_CHECK(ToJson(r).find("\"name\": \"T\"") != std::string::npos);
  CD_CHECK(ToJson(Compare(sphere, sphere)).find("\"field\"") == std::string::npos);
}

CD_TEST_CASE(FieldLinear)
{
  // A linear field is interpolated exactly by any triangulation: a 40x40 plane against a 3x3
  // one of the same square, both with T = 3x - 2y + 1, differ only by rounding. Over
  // [-1,1]^2 its range is [-4, 6].
  const auto linear = [](const double p[3]) { return 3 * p[0] - 2 * p[1] + 1; };
  const Result r = Compare(WithField(FlatGrid(40, 40, Pattern::Constant), linear),
                           WithField(FlatGrid(3, 3, Pattern::Constant), linear), FieldT());
  CD_CHECK(r.Ok);
  CD_CHECK_NEAR(r.Field.Range[0], -4, 1e-12);
  CD_CHECK_NEAR(r.Field.Range[1], 6, 1e-12);
  CheckField(r.Field.Forward, { 0, 0, 0 }, 1e-9);
  CheckField(r.Field.Backward, { 0, 0, 0 }, 1e-9);
  CD_CHECK_NEAR(r.Max, 0, 1e-12);
}

CD_TEST_CASE(FieldOffset)
{
  // T = xy, and T + 0.25 on the other copy: every difference is 0.25, at the area samples and
  // at the vertices, both ways. The range of xy on [-1,1]^2 is [-1, 1]: 12.5 % of it.
  const Result r = Compare(
    WithField(FlatGrid(10, 10, Pattern::Constant), [](const double p[3]) { return p[0] * p[1]; }),
    WithField(FlatGrid(10, 10, Pattern::Constant),
              [](const double p[3]) { return p[0] * p[1] + 0.25; }),
    FieldT());
  CD_CHECK(r.Ok);
  CD_CHECK_NEAR(r.Field.Range[0], -1, 1e-12);
  CD_CHECK_NEAR(r.Field.Range[1], 1, 1e-12);
  for (const FieldDifference& f : { r.Field.Forward, r.Field.Backward, r.Field.TwoSided })
  {
    CheckField(f, { 0.25, 0.25, 0.25 }, 1e-12);
  }
  CheckField(r.Field.TwoSidedPercent, { 12.5, 12.5, 12.5 }, 1e-12);
}

CD_TEST_CASE(FieldDiagonals)
{
  // The unit square with T = 1 at (1,1) and 0 at the other corners, cut along either
  // diagonal. Cut along (0,0)-(1,1), T = min(x, y); along (1,0)-(0,1), T = max(0, x + y - 1).
  // Their difference is min(x, y, 1 - x, 1 - y), the distance to the square's border: a
  // pyramid of height 1/2, so its mean is 1/6; the area where it exceeds t is (1 - 2t)^2, so
  // its mean square is the integral of 2t (1 - 2t)^2 over [0, 1/2], 1/24. Its maximum, 1/2,
  // is at the centre (approached by the samples; 0 at the vertices). Same both ways.
  const std::vector<double> square = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  const auto corner = [](const double p[3]) { return p[0] * p[1]; };
  const Result r =
    Compare(WithField(colordecimation::meshes::FromTriangles(square, { 0, 1, 2, 0, 2, 3 }), corner),
            WithField(colordecimation::meshes::FromTriangles(square, { 0, 1, 3, 1, 2, 3 }), corner),
            FieldT());
  CD_CHECK(r.Ok);
  const FieldDifference expected = { 1.0 / 6, std::sqrt(1.0 / 24), 0.5 };
  CheckField(r.Field.Forward, expected, 3e-3);
  CheckField(r.Field.Backward, expected, 3e-3);
  CD_CHECK_NEAR(r.Field.TwoSidedPercent.Rms, 100 * std::sqrt(1.0 / 24), 3e-3);
  CD_CHECK_NEAR(r.Max, 0, 1e-12);
}

CD_TEST_CASE(FieldErrors)
{
  // The field must be a point array of both meshes, of one component.
  auto plain = FlatGrid(4, 4, Pattern::Constant);
  auto withT = WithField(plain, [](const double p[3]) { return p[0]; });
  Result r = Compare(withT, plain, FieldT());
  CD_CHECK(!r.Ok);
  CD_CHECK_MSG(r.Error.find("simplified mesh has no point array 'T'") != std::string::npos,
               r.Error);
  Options rgb;
  rgb.Field = "RGB";
  r = Compare(plain, plain, rgb);
  CD_CHECK(!r.Ok);
  CD_CHECK_MSG(r.Error.find("has 3 components") != std::string::npos, r.Error);
}
} // namespace

int main(int argc, char* argv[])
{
  return colordecimation::testing::RunTestCases(argc, argv);
}
