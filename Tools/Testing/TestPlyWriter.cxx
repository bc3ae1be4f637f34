/**
 * @file TestPlyWriter.cxx
 * @brief PlyWriter.h against vtkPLYWriter: the same bytes for every kind of mesh both write
 * (colours of points or faces, with and without alpha, normals, texture coordinates, double
 * points, polygons up to 255 corners, no faces, files of several blocks; point and face
 * colours together through the CLI's WriteMesh), and where vtkPLYWriter loses data (normals
 * and texture coordinates that are not floats), the values read back by vtkPLYReader. A
 * polygon of more than 255 corners and an unwritable path are errors that leave no file (and
 * remove nothing that was there).
 *
 * Usage: TestPlyWriter DIRECTORY (a scratch folder for the files)
 */
#include "MeshIO.h"
#include "PlyTestMeshes.h"
#include "PlyWriter.h"
#include "ToolsTest.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersionMacros.h"

#include <cmath>
#include <string>
#include <sys/stat.h>

namespace
{
using colordecimation::tools::WritePly;

using colordecimation::tools::test::Colors;
using colordecimation::tools::test::Expect;
using colordecimation::tools::test::FileBytes;
using colordecimation::tools::test::ReadWithVtk;
using colordecimation::tools::test::Sphere;
using colordecimation::tools::test::WriteWithVtk;

bool Exists(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0;
}

vtkSmartPointer<vtkDataArray> TCoords(vtkIdType tuples, bool doubles)
{
  vtkSmartPointer<vtkDataArray> tcoords = doubles
    ? vtkSmartPointer<vtkDataArray>::Take(vtkDoubleArray::New())
    : vtkSmartPointer<vtkDataArray>::Take(vtkFloatArray::New());
  tcoords->SetName("uv");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(tuples);
  for (vtkIdType i = 0; i < tuples; ++i)
  {
    tcoords->SetTuple2(i, 0.001 * double(i), 1.0 / (1.0 + double(i)));
  }
  return tcoords;
}

/// Write `mesh` with vtkPLYWriter (as the CLI set it: binary, the colour array by name, alpha
/// with 4 components) and with WritePly; the files must be byte for byte the same. VTK 9.1's
/// vtkPLYWriter writes no normals (9.2's does): there both files are of the mesh without them,
/// and TestDoublesKept reads normals back.
void ExpectSameAsVtk(vtkPolyData* input, vtkUnsignedCharArray* pointColors,
                     vtkUnsignedCharArray* faceColors, const std::string& dir,
                     const std::string& name)
{
  vtkNew<vtkPolyData> mesh;
  mesh->ShallowCopy(input);
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 2, 0)
  mesh->GetPointData()->SetNormals(nullptr);
#endif
  const std::string theirs = dir + "/" + name + ".vtk.ply";
  const std::string ours = dir + "/" + name + ".ours.ply";
  Expect(WriteWithVtk(mesh, pointColors ? pointColors : faceColors, theirs),
         name + ": vtkPLYWriter wrote its file");
  std::string error;
  Expect(WritePly(mesh, ours, pointColors, faceColors, error), name + ": written (" + error + ")");
  const std::string expected = FileBytes(theirs);
  Expect(expected.size() > 200, name + ": vtkPLYWriter's file is there");
  Expect(FileBytes(ours) == expected, name + ": the same bytes as vtkPLYWriter's file");
}

void TestSameBytes(const std::string& dir)
{
  auto mesh = Sphere(24);
  const vtkIdType points = mesh->GetNumberOfPoints();
  const vtkIdType faces = mesh->GetNumberOfCells();
  ExpectSameAsVtk(mesh, nullptr, nullptr, dir, "normals");
  mesh->GetPointData()->SetNormals(nullptr);
  ExpectSameAsVtk(mesh, nullptr, nullptr, dir, "plain");
  for (int components : { 3, 4 })
  {
    const std::string suffix = std::to_string(components);
    auto rgb = Colors(points, components, "RGB");
    mesh->GetPointData()->AddArray(rgb);
    ExpectSameAsVtk(mesh, rgb, nullptr, dir, "point-colors-" + suffix);
    mesh->GetPointData()->RemoveArray("RGB");
    auto faceRgb = Colors(faces, components, "FaceRGB");
    mesh->GetCellData()->AddArray(faceRgb);
    ExpectSameAsVtk(mesh, nullptr, faceRgb, dir, "face-colors-" + suffix);
    mesh->GetCellData()->RemoveArray("FaceRGB");
  }
  // Everything a vertex can hold: normals, colours with alpha, texture coordinates.
  auto full = Sphere(17);
  auto rgba = Colors(full->GetNumberOfPoints(), 4, "RGBA");
  full->GetPointData()->AddArray(rgba);
  full->GetPointData()->SetTCoords(TCoords(full->GetNumberOfPoints(), false));
  ExpectSameAsVtk(full, rgba, nullptr, dir, "full-vertex");
  // Double points (cast to float), polygons of several sizes, a mesh with no faces.
  vtkNew<vtkPoints> doubles;
  doubles->SetDataTypeToDouble();
  for (int i = 0; i < 12; ++i)
  {
    doubles->InsertNextPoint(std::cos(i * 0.5) + 1e-9 * i, std::sin(i * 0.5), 1.0 / 3.0 + i);
  }
  vtkNew<vtkCellArray> polygons;
  polygons->InsertNextCell({ 0, 1, 2 });
  polygons->InsertNextCell({ 2, 3, 4, 5 });
  polygons->InsertNextCell({ 5, 6, 7, 8, 9, 10, 11 });
  polygons->InsertNextCell(255); // the most corners a byte counts
  for (int i = 0; i < 255; ++i)
  {
    polygons->InsertCellPoint(i % 12);
  }
  vtkNew<vtkPolyData> polygonal;
  polygonal->SetPoints(doubles);
  polygonal->SetPolys(polygons);
  ExpectSameAsVtk(polygonal, nullptr, nullptr, dir, "double-polygons");
  // Files of several blocks (the writer gathers 1 MiB at a time).
  auto large = Sphere(400);
  auto largeRgb = Colors(large->GetNumberOfPoints(), 3, "RGB");
  large->GetPointData()->AddArray(largeRgb);
  ExpectSameAsVtk(large, largeRgb, nullptr, dir, "large");
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(doubles);
  ExpectSameAsVtk(cloud, nullptr, nullptr, dir, "no-faces");
}

/// Double normals and texture coordinates are written as floats, not dropped.
void TestDoublesKept(const std::string& dir)
{
  auto mesh = Sphere(20);
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> normals;
  normals->DeepCopy(mesh->GetPointData()->GetNormals());
  normals->SetName("N");
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetTCoords(TCoords(n, true));
  const std::string path = dir + "/doubles.ply";
  std::string error;
  Expect(WritePly(mesh, path, nullptr, nullptr, error), "doubles: written (" + error + ")");
  auto back = ReadWithVtk(path);
  vtkDataArray* readNormals = back->GetPointData()->GetNormals();
  vtkDataArray* readTCoords = back->GetPointData()->GetTCoords();
  Expect(back->GetNumberOfPoints() == n && readNormals && readTCoords,
         "doubles: the points, normals and texture coordinates read back");
  if (!readNormals || !readTCoords || back->GetNumberOfPoints() != n)
  {
    return;
  }
  bool same = true;
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      same = same && readNormals->GetComponent(i, k) == double(float(normals->GetComponent(i, k)));
    }
    for (int k = 0; k < 2; ++k)
    {
      same = same &&
        readTCoords->GetComponent(i, k) ==
          double(float(mesh->GetPointData()->GetTCoords()->GetComponent(i, k)));
    }
  }
  Expect(same, "doubles: every normal and texture coordinate read back as its float");
}

/// Through the CLI's WriteMesh: point and face colours of the same name (as vtkPLYReader names
/// both) are both written, as vtkPLYWriter, given that name, writes them.
void TestPointAndFaceColors(const std::string& dir)
{
  auto mesh = Sphere(24);
  mesh->GetPointData()->SetNormals(nullptr);
  auto points = Colors(mesh->GetNumberOfPoints(), 3, "RGB");
  auto faces = Colors(mesh->GetNumberOfCells(), 3, "RGB");
  mesh->GetPointData()->SetScalars(points);
  mesh->GetCellData()->SetScalars(faces);
  const std::string theirs = dir + "/both.vtk.ply";
  Expect(WriteWithVtk(mesh, points, theirs), "both colours: vtkPLYWriter wrote its file");
  std::string error;
  const std::string ours = dir + "/both.ours.ply";
  Expect(colordecimation::tools::WriteMesh(mesh, ours, "", error, nullptr),
         "both colours: written by WriteMesh (" + error + ")");
  Expect(FileBytes(theirs).find("element face") != std::string::npos &&
           FileBytes(ours) == FileBytes(theirs),
         "both colours: the same bytes as vtkPLYWriter's file");
}

/// What cannot be written is an error, and no file is left.
void TestErrors(const std::string& dir)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polygons;
  polygons->InsertNextCell(300);
  for (int i = 0; i < 300; ++i)
  {
    points->InsertNextPoint(std::cos(i * 0.02), std::sin(i * 0.02), 0.0);
    polygons->InsertCellPoint(i);
  }
  vtkNew<vtkPolyData> wide;
  wide->SetPoints(points);
  wide->SetPolys(polygons);
  const std::string path = dir + "/wide.ply";
  std::string error;
  Expect(!WritePly(wide, path, nullptr, nullptr, error) &&
           error.find("300 corners") != std::string::npos,
         "a polygon of 300 corners is an error naming it (" + error + ")");
  Expect(!Exists(path), "no file is left after an error");
  error.clear();
  Expect(!WritePly(Sphere(8), dir + "/no/such/folder/x.ply", nullptr, nullptr, error) &&
           error.find("cannot write") != std::string::npos,
         "an unwritable path is an error (" + error + ")");
  const std::string folder = dir + "/folder.ply";
  mkdir(folder.c_str(), 0755);
  error.clear();
  Expect(!WritePly(Sphere(8), folder, nullptr, nullptr, error) && Exists(folder),
         "a folder in the way is an error, and the folder stays (" + error + ")");
  auto mesh = Sphere(8);
  auto wrong = Colors(mesh->GetNumberOfPoints() - 1, 3, "RGB");
  error.clear();
  Expect(!WritePly(mesh, dir + "/short.ply", wrong, nullptr, error) &&
           error.find("colours") != std::string::npos && !Exists(dir + "/short.ply"),
         "colours of the wrong length are an error (" + error + ")");
}
} // namespace

int main(int argc, char* argv[])
{
  return colordecimation::tools::test::Run(
    argc, argv, "TestPlyWriter",
    { TestSameBytes, TestDoublesKept, TestPointAndFaceColors, TestErrors });
}
