// Tests of the Metro-style surface distance (ColorDecimationMetro) against closed forms.
#include "ColorDecimationMetro.h"

#include "ColorDecimationMeshes.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>

namespace
{
using colordecimation::metro::Compare;
using colordecimation::metro::Options;
using colordecimation::metro::Result;

int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "check failed: " << what << std::endl;
    ++Failures;
  }
}

void Near(double actual, double expected, double tolerance, const std::string& what)
{
  Check(std::abs(actual - expected) <= tolerance,
        what + " = " + std::to_string(actual) + ", expected " + std::to_string(expected));
}

/// The unit square at height z, in two triangles.
vtkSmartPointer<vtkPolyData> Square(double z)
{
  return colordecimation::meshes::FromTriangles({ 0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z },
                                                { 0, 1, 2, 0, 2, 3 });
}

void TestIdentical()
{
  auto sphere = colordecimation::meshes::Icosphere(3, colordecimation::meshes::Pattern::Constant);
  const Result r = Compare(sphere, sphere);
  Check(r.Ok, "ok");
  Near(r.Mean, 0, 1e-9, "mean");
  Near(r.Max, 0, 1e-9, "max");
  Near(r.Diagonal, 2 * std::sqrt(3.0), 1e-6, "diagonal");
}

void TestOffset()
{
  // Two parallel unit squares 0.1 apart: every distance is 0.1, both ways.
  const Result r = Compare(Square(0), Square(0.1));
  Check(r.Ok, "ok");
  for (double d : { r.Forward.Mean, r.Forward.Rms, r.Forward.Max, r.Backward.Mean, r.Backward.Rms,
                    r.Backward.Max, r.Mean, r.Rms, r.Max })
  {
    Near(d, 0.1, 1e-7, "offset distance");
  }
  Near(r.Forward.Area, 1.0, 1e-12, "area");
  Near(r.MeanPercent, 100 * 0.1 / std::sqrt(2.0), 1e-6, "mean %");
}

void TestHalfSquare()
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
  Check(r.Ok, "ok");
  Near(r.Forward.Mean, 0.5 * h / 3.0, 1e-3, "forward mean");
  Near(r.Forward.Rms, std::sqrt(0.5 * h * h / 6.0), 1e-3, "forward rms");
  Near(r.Forward.Max, h, 1e-12, "forward max (the vertex (0,1))");
  Near(r.Backward.Max, 0.0, 1e-12, "backward max");
  Near(r.Mean, r.Forward.Mean, 0, "two-sided mean");
  Near(r.Backward.Area, 0.5, 1e-12, "backward area");
  Check(r.OriginalTriangles == 2 && r.SimplifiedTriangles == 1, "triangle counts");
}

void TestSphere()
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
  Check(r.Ok, "ok");
  Near(r.Forward.Mean, 0.01, 2e-4, "forward mean");
  Near(r.Backward.Mean, 0.01, 2e-4, "backward mean");
  Near(r.Max, 0.0101, 2e-4, "max");
  Near(r.RmsPercent, 100 * 0.01 / (2 * std::sqrt(3.0)), 0.01, "rms %");
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "all";
  const struct
  {
    const char* Name;
    void (*Run)();
  } cases[] = { { "Identical", TestIdentical },
                { "Offset", TestOffset },
                { "HalfSquare", TestHalfSquare },
                { "Sphere", TestSphere } };
  bool found = false;
  for (const auto& c : cases)
  {
    if (name == "all" || name == c.Name)
    {
      found = true;
      const int before = Failures;
      c.Run();
      std::cout << (Failures == before ? "PASS " : "FAIL ") << c.Name << std::endl;
    }
  }
  if (!found)
  {
    std::cerr << "unknown case " << name << std::endl;
    return 2;
  }
  return Failures == 0 ? 0 : 1;
}
