/**
 * @file MeshCheck.cxx
 * @brief Test helper for the command-line tools: reads a mesh file written by
 * color-decimate and checks its counts and colours.
 *
 * Usage: ColorDecimationMeshCheck FILE [--triangles N | --triangles-between LO HI]
 *          [--points N] [--colors] [--colors-from INPUT] [--original-ids]
 *
 * --colors          the file has a 3- or 4-component unsigned char colour array (the active
 *                   scalars) with more than one colour in it;
 * --colors-from IN  every point of FILE is a point of IN (same coordinates) with the same
 *                   colour, bit for bit (decimation by half-edge collapses keeps both);
 * --original-ids    FILE has vtkOriginalPointIds, and each output point's coordinates and
 *                   colour are those of that input point of the file given by --colors-from.
 * Prints "points=P triangles=T colors=NAME/COMPONENTS" and exits non-zero on a failed check.
 */
#include "MeshIO.h"

#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkLogger.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <string>

namespace
{
using namespace colordecimation::tools;

int Failure(const std::string& message)
{
  std::cerr << "MeshCheck: FAILED: " << message << std::endl;
  return 1;
}

vtkSmartPointer<vtkPolyData> Load(const std::string& path)
{
  std::string description, error;
  auto mesh = ReadMesh(path, description, error);
  if (!mesh)
  {
    std::cerr << "MeshCheck: " << error << std::endl;
  }
  return mesh;
}

using Key = std::array<double, 3>;
using Colour = std::array<int, 4>;

Colour ColourOf(vtkDataArray* colors, vtkIdType i)
{
  Colour c = { 0, 0, 0, 255 };
  for (int k = 0; k < colors->GetNumberOfComponents() && k < 4; ++k)
  {
    c[k] = static_cast<int>(colors->GetComponent(i, k));
  }
  return c;
}
} // namespace

int main(int argc, char* argv[])
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  if (argc < 2)
  {
    std::cerr << "usage: ColorDecimationMeshCheck FILE [checks]" << std::endl;
    return 2;
  }
  const std::string file = argv[1];
  long long wantTriangles = -1, lo = -1, hi = -1, wantPoints = -1;
  bool wantColors = false, wantIds = false;
  std::string reference;
  for (int i = 2; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--triangles" && i + 1 < argc)
    {
      wantTriangles = std::atoll(argv[++i]);
    }
    else if (arg == "--triangles-between" && i + 2 < argc)
    {
      lo = std::atoll(argv[++i]);
      hi = std::atoll(argv[++i]);
    }
    else if (arg == "--points" && i + 1 < argc)
    {
      wantPoints = std::atoll(argv[++i]);
    }
    else if (arg == "--colors")
    {
      wantColors = true;
    }
    else if (arg == "--colors-from" && i + 1 < argc)
    {
      reference = argv[++i];
    }
    else if (arg == "--original-ids")
    {
      wantIds = true;
    }
    else
    {
      std::cerr << "MeshCheck: bad argument '" << arg << "'" << std::endl;
      return 2;
    }
  }

  auto mesh = Load(file);
  if (!mesh)
  {
    return 1;
  }
  const long long points = mesh->GetNumberOfPoints();
  const long long triangles = CountTriangles(mesh);
  vtkDataArray* colors = mesh->GetPointData()->GetScalars();
  std::cout << "points=" << points << " triangles=" << triangles
            << " colors=" << (colors && colors->GetName() ? colors->GetName() : "none") << "/"
            << (colors ? colors->GetNumberOfComponents() : 0) << std::endl;

  if (wantTriangles >= 0 && triangles != wantTriangles)
  {
    return Failure("expected " + std::to_string(wantTriangles) + " triangles, found " +
                   std::to_string(triangles));
  }
  if (lo >= 0 && (triangles < lo || triangles > hi))
  {
    return Failure("expected " + std::to_string(lo) + " to " + std::to_string(hi) +
                   " triangles, found " + std::to_string(triangles));
  }
  if (wantPoints >= 0 && points != wantPoints)
  {
    return Failure("expected " + std::to_string(wantPoints) + " points, found " +
                   std::to_string(points));
  }
  if (wantColors || !reference.empty())
  {
    if (!colors || !vtkUnsignedCharArray::SafeDownCast(colors) ||
        (colors->GetNumberOfComponents() != 3 && colors->GetNumberOfComponents() != 4))
    {
      return Failure("no unsigned char RGB(A) colour array as active scalars");
    }
    if (colors->GetNumberOfTuples() != points)
    {
      return Failure("the colour array does not have one colour per point");
    }
    std::set<Colour> distinct;
    for (vtkIdType i = 0; i < points && distinct.size() < 2; ++i)
    {
      distinct.insert(ColourOf(colors, i));
    }
    if (distinct.size() < 2)
    {
      return Failure("every point has the same colour: the colours were lost");
    }
  }
  if (!reference.empty())
  {
    auto input = Load(reference);
    if (!input)
    {
      return 1;
    }
    vtkDataArray* inputColors = input->GetPointData()->GetScalars();
    if (!inputColors)
    {
      return Failure("the reference mesh has no colours");
    }
    std::map<Key, vtkIdType> where;
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double p[3];
      input->GetPoint(i, p);
      where.emplace(Key{ p[0], p[1], p[2] }, i);
    }
    vtkIdTypeArray* ids =
      vtkIdTypeArray::SafeDownCast(mesh->GetPointData()->GetArray("vtkOriginalPointIds"));
    if (wantIds && !ids)
    {
      return Failure("no vtkOriginalPointIds array");
    }
    for (vtkIdType i = 0; i < points; ++i)
    {
      double p[3];
      mesh->GetPoint(i, p);
      auto it = where.find(Key{ p[0], p[1], p[2] });
      if (it == where.end())
      {
        return Failure("output point " + std::to_string(i) + " is not an input point");
      }
      if (ColourOf(colors, i) != ColourOf(inputColors, it->second))
      {
        return Failure("output point " + std::to_string(i) +
                       " has another colour than input point " + std::to_string(it->second));
      }
      if (ids)
      {
        const vtkIdType original = ids->GetValue(i);
        double q[3];
        if (original < 0 || original >= input->GetNumberOfPoints())
        {
          return Failure("vtkOriginalPointIds out of range at point " + std::to_string(i));
        }
        input->GetPoint(original, q);
        if (q[0] != p[0] || q[1] != p[1] || q[2] != p[2] ||
            ColourOf(inputColors, original) != ColourOf(colors, i))
        {
          return Failure("vtkOriginalPointIds of point " + std::to_string(i) +
                         " names an input point with other coordinates or colour");
        }
      }
    }
    std::cout << "all " << points << " points and colours found in " << reference << std::endl;
  }
  return 0;
}
