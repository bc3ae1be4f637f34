/**
 * @file MeshCheck.cxx
 * @brief Test helper for the command-line tools: reads a mesh file written by
 * color-decimate and checks its counts and colours.
 *
 * Usage: ColorDecimationMeshCheck FILE [--triangles N | --triangles-between LO HI]
 *          [--points N] [--colors] [--colors-from INPUT] [--original-ids]
 *          [--boundary-of INPUT]
 *
 * --colors          the file has a 3- or 4-component unsigned char colour array (the active
 *                   scalars) with more than one colour in it;
 * --colors-from IN  every point of FILE is a point of IN (same coordinates) with the same
 *                   colour, bit for bit (decimation by half-edge collapses keeps both);
 * --original-ids    FILE has vtkOriginalPointIds, and each output point's coordinates and
 *                   colour are those of that input point of the file given by --colors-from;
 * --boundary-of IN  FILE's boundary edges (those of one polygon) are IN's, by coordinates
 *                   (what PreserveBoundary keeps).
 * Prints "points=P triangles=T colors=NAME/COMPONENTS" and exits non-zero on a failed check.
 */
#include "CommandLine.h"
#include "MeshIO.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkLogger.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

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
struct Checks
{
  std::string File;
  long long Triangles = -1;
  std::vector<long long> TrianglesBetween;
  long long Points = -1;
  bool Colors = false;
  std::string Reference;
  bool OriginalIds = false;
  std::string BoundaryReference;
};

void AddOptions(CLI::App& app, Checks& checks)
{
  app.add_option("FILE", checks.File, "the mesh file to check")->required()->type_name("");
  app.add_option("--triangles", checks.Triangles, "exactly N triangles")->type_name("N");
  app.add_option("--triangles-between", checks.TrianglesBetween, "LO to HI triangles")
    ->expected(2)
    ->type_name("LO HI");
  app.add_option("--points", checks.Points, "exactly N points")->type_name("N");
  app.add_flag("--colors", checks.Colors,
               "a 3- or 4-component unsigned char colour array (the active scalars) with\n"
               "more than one colour in it");
  app
    .add_option("--colors-from", checks.Reference,
                "every point is a point of INPUT (same coordinates) with the same colour,\n"
                "bit for bit")
    ->type_name("INPUT");
  app.add_flag("--original-ids", checks.OriginalIds,
               "vtkOriginalPointIds names, for each point, the point of --colors-from's\n"
               "file with its coordinates and colour");
  app
    .add_option("--boundary-of", checks.BoundaryReference,
                "the boundary edges (those of one polygon) are INPUT's, by coordinates")
    ->type_name("INPUT");
}

/// The boundary edges of `mesh` (those of one polygon), each as its two ends' coordinates in
/// increasing order.
std::set<std::array<Key, 2>> BoundaryEdges(vtkPolyData* mesh)
{
  std::map<std::array<Key, 2>, int> uses;
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType count;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    for (vtkIdType k = 0; k < count; ++k)
    {
      double a[3], b[3];
      mesh->GetPoint(ids[k], a);
      mesh->GetPoint(ids[(k + 1) % count], b);
      std::array<Key, 2> edge = { Key{ a[0], a[1], a[2] }, Key{ b[0], b[1], b[2] } };
      if (edge[1] < edge[0])
      {
        std::swap(edge[0], edge[1]);
      }
      ++uses[edge];
    }
  }
  std::set<std::array<Key, 2>> boundary;
  for (const auto& use : uses)
  {
    if (use.second == 1)
    {
      boundary.insert(use.first);
    }
  }
  return boundary;
}

/// The triangle and point counts; "" when right.
std::string CheckCounts(const Checks& checks, long long points, long long triangles)
{
  if (checks.Triangles >= 0 && triangles != checks.Triangles)
  {
    return "expected " + std::to_string(checks.Triangles) + " triangles, found " +
      std::to_string(triangles);
  }
  const std::vector<long long>& range = checks.TrianglesBetween;
  if (range.size() == 2 && (triangles < range[0] || triangles > range[1]))
  {
    return "expected " + std::to_string(range[0]) + " to " + std::to_string(range[1]) +
      " triangles, found " + std::to_string(triangles);
  }
  if (checks.Points >= 0 && points != checks.Points)
  {
    return "expected " + std::to_string(checks.Points) + " points, found " + std::to_string(points);
  }
  return "";
}

/// --colors: unsigned char RGB(A), one per point, not all the same (`varied`; --colors-from
/// alone compares them with its reference's, which may have one colour); "" when so.
std::string CheckColors(vtkDataArray* colors, long long points, bool varied)
{
  if (!colors || !vtkUnsignedCharArray::SafeDownCast(colors) ||
      (colors->GetNumberOfComponents() != 3 && colors->GetNumberOfComponents() != 4))
  {
    return "no unsigned char RGB(A) colour array as active scalars";
  }
  if (colors->GetNumberOfTuples() != points)
  {
    return "the colour array does not have one colour per point";
  }
  if (!varied)
  {
    return "";
  }
  std::set<Colour> distinct;
  for (vtkIdType i = 0; i < points && distinct.size() < 2; ++i)
  {
    distinct.insert(ColourOf(colors, i));
  }
  return distinct.size() < 2 ? "every point has the same colour: the colours were lost" : "";
}

/// --original-ids: point i of `mesh` is input point ids[i], with its coordinates and colour.
std::string CheckOriginalId(vtkPolyData* mesh, vtkPolyData* input, vtkIdTypeArray* ids, vtkIdType i)
{
  const vtkIdType original = ids->GetValue(i);
  if (original < 0 || original >= input->GetNumberOfPoints())
  {
    return "vtkOriginalPointIds out of range at point " + std::to_string(i);
  }
  double p[3], q[3];
  mesh->GetPoint(i, p);
  input->GetPoint(original, q);
  if (q[0] != p[0] || q[1] != p[1] || q[2] != p[2] ||
      ColourOf(input->GetPointData()->GetScalars(), original) !=
        ColourOf(mesh->GetPointData()->GetScalars(), i))
  {
    return "vtkOriginalPointIds of point " + std::to_string(i) +
      " names an input point with other coordinates or colour";
  }
  return "";
}

/// --colors-from (and --original-ids): every point and colour is the reference's; "" if so.
std::string CheckAgainst(vtkPolyData* mesh, vtkPolyData* input, bool wantIds)
{
  vtkDataArray* colors = mesh->GetPointData()->GetScalars();
  vtkDataArray* inputColors = input->GetPointData()->GetScalars();
  if (!inputColors)
  {
    return "the reference mesh has no colours";
  }
  std::map<Key, vtkIdType> where;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    where.emplace(Key{ p[0], p[1], p[2] }, i);
  }
  auto* ids = vtkIdTypeArray::SafeDownCast(mesh->GetPointData()->GetArray("vtkOriginalPointIds"));
  if (wantIds && !ids)
  {
    return "no vtkOriginalPointIds array";
  }
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    auto it = where.find(Key{ p[0], p[1], p[2] });
    if (it == where.end())
    {
      return "output point " + std::to_string(i) + " is not an input point";
    }
    if (ColourOf(colors, i) != ColourOf(inputColors, it->second))
    {
      return "output point " + std::to_string(i) + " has another colour than input point " +
        std::to_string(it->second);
    }
    const std::string wrong = ids ? CheckOriginalId(mesh, input, ids, i) : std::string();
    if (!wrong.empty())
    {
      return wrong;
    }
  }
  return "";
}

/// Every check asked for, in order; the exit status.
int Check(const Checks& checks)
{
  auto mesh = Load(checks.File);
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
  std::string wrong = CheckCounts(checks, points, triangles);
  if (wrong.empty() && (checks.Colors || !checks.Reference.empty()))
  {
    wrong = CheckColors(colors, points, checks.Colors);
  }
  if (!wrong.empty())
  {
    return Failure(wrong);
  }
  if (!checks.Reference.empty())
  {
    auto input = Load(checks.Reference);
    wrong = input ? CheckAgainst(mesh, input, checks.OriginalIds) : "cannot read the reference";
    if (!wrong.empty())
    {
      return Failure(wrong);
    }
    std::cout << "all " << points << " points and colours found in " << checks.Reference << "\n";
  }
  if (!checks.BoundaryReference.empty())
  {
    auto input = Load(checks.BoundaryReference);
    if (!input)
    {
      return 1;
    }
    const auto boundary = BoundaryEdges(mesh);
    if (boundary != BoundaryEdges(input))
    {
      return Failure("the boundary edges differ from those of " + checks.BoundaryReference);
    }
    std::cout << "the " << boundary.size() << " boundary edges of " << checks.BoundaryReference
              << "\n";
  }
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app("Reads a mesh file written by color-decimate and checks its counts and colours;\n"
               "prints \"points=P triangles=T colors=NAME/COMPONENTS\" and exits non-zero on a\n"
               "failed check.",
               "ColorDecimationMeshCheck");
  SetUpCommandLine(app, "Usage: ColorDecimationMeshCheck FILE [checks]");
  Checks checks;
  AddOptions(app, checks);
  const int status = ParseCommandLine(app, argc, argv);
  return status >= 0 ? status : Check(checks);
}
