/**
 * @file TestPlyReader.cxx
 * @brief PlyReader.h against vtkPLYReader: the same mesh (points, point arrays, polygons) for
 * every layout it reads (no colour, RGB, RGBA, normals, a property both skip, polygons up to
 * 255 corners, no faces, a file of several chunks), through ReadSimplePly and the CLI's
 * ReadMesh; the layouts it leaves to vtkPLYReader (face colours, texture coordinates,
 * big-endian, ASCII) are still read as vtkPLYReader reads them; a truncated file, or one whose
 * header announces more than it holds, is an error.
 *
 * Usage: TestPlyReader DIRECTORY (a scratch folder for the files)
 */
#include "MeshIO.h"
#include "PlyHeader.h"
#include "PlyReader.h"
#include "PlyTestMeshes.h"
#include "ToolsTest.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
using colordecimation::tools::IsSimplePly;
using colordecimation::tools::PlyHeader;
using colordecimation::tools::ReadMesh;
using colordecimation::tools::ReadPlyHeader;
using colordecimation::tools::ReadSimplePly;
using colordecimation::tools::test::Colors;
using colordecimation::tools::test::Expect;
using colordecimation::tools::test::FileBytes;
using colordecimation::tools::test::ReadWithVtk;
using colordecimation::tools::test::Sphere;

/// Write `mesh` with vtkPLYWriter (binary unless ascii; the named colour array, with alpha
/// when it has 4 components; texture coordinates when it has them).
std::string Write(vtkPolyData* mesh, const char* colors, const std::string& path,
                  bool bigEndian = false, bool ascii = false)
{
  vtkNew<vtkPLYWriter> writer;
  writer->SetFileName(path.c_str());
  ascii ? writer->SetFileTypeToASCII() : writer->SetFileTypeToBinary();
  bigEndian ? writer->SetDataByteOrderToBigEndian() : writer->SetDataByteOrderToLittleEndian();
  writer->SetInputData(mesh);
  if (colors)
  {
    writer->SetArrayName(colors);
    vtkDataArray* array = mesh->GetPointData()->GetArray(colors);
    array = array ? array : mesh->GetCellData()->GetArray(colors);
    writer->SetEnableAlpha(array && array->GetNumberOfComponents() == 4);
  }
  else
  {
    writer->SetColorModeToOff();
  }
  Expect(writer->Write() == 1, path + ": written by vtkPLYWriter");
  return path;
}

bool SameArray(vtkAbstractArray* a, vtkAbstractArray* b)
{
  if (!a || !b ||
      std::string(a->GetName() ? a->GetName() : "") != (b->GetName() ? b->GetName() : "") ||
      a->GetDataType() != b->GetDataType() ||
      a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
      a->GetNumberOfTuples() != b->GetNumberOfTuples())
  {
    return false;
  }
  const size_t bytes = size_t(a->GetNumberOfValues()) * size_t(a->GetDataTypeSize());
  return bytes == 0 || std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), bytes) == 0;
}

/// The same points (type and bits), point arrays (names, roles, values), cell arrays and
/// polygons, and no other cells.
bool SameMesh(vtkPolyData* a, vtkPolyData* b, std::string& why)
{
  if (!a || !b || !SameArray(a->GetPoints()->GetData(), b->GetPoints()->GetData()))
  {
    why = "points";
    return false;
  }
  vtkDataSetAttributes* pa = a->GetPointData();
  vtkDataSetAttributes* pb = b->GetPointData();
  if (pa->GetNumberOfArrays() != pb->GetNumberOfArrays() ||
      a->GetCellData()->GetNumberOfArrays() != b->GetCellData()->GetNumberOfArrays())
  {
    why = "the number of arrays";
    return false;
  }
  for (int i = 0; i < pa->GetNumberOfArrays(); ++i)
  {
    if (!SameArray(pa->GetAbstractArray(i), pb->GetAbstractArray(i)))
    {
      why = std::string("point array ") + (pa->GetArrayName(i) ? pa->GetArrayName(i) : "");
      return false;
    }
  }
  if ((pa->GetScalars() != nullptr) != (pb->GetScalars() != nullptr) ||
      (pa->GetNormals() != nullptr) != (pb->GetNormals() != nullptr))
  {
    why = "the scalars' or normals' role";
    return false;
  }
  if (a->GetNumberOfVerts() + a->GetNumberOfLines() + a->GetNumberOfStrips() !=
        b->GetNumberOfVerts() + b->GetNumberOfLines() + b->GetNumberOfStrips() ||
      a->GetNumberOfPolys() != b->GetNumberOfPolys())
  {
    why = "the number of cells";
    return false;
  }
  vtkNew<vtkIdList> ca, cb;
  for (vtkIdType c = 0; c < a->GetNumberOfPolys(); ++c)
  {
    a->GetPolys()->GetCellAtId(c, ca);
    b->GetPolys()->GetCellAtId(c, cb);
    if (ca->GetNumberOfIds() != cb->GetNumberOfIds() ||
        !std::equal(ca->begin(), ca->end(), cb->begin()))
    {
      why = "polygon " + std::to_string(c);
      return false;
    }
  }
  return true;
}

/// The file is read by ReadSimplePly (simple) or not, and ReadMesh gives vtkPLYReader's mesh.
void ExpectAsVtk(const std::string& path, bool simple)
{
  PlyHeader header;
  std::string error, why;
  Expect(ReadPlyHeader(path, header, error), path + ": a PLY header (" + error + ")");
  Expect(IsSimplePly(header) == simple, path + (simple ? ": read in one pass" : ": left to VTK"));
  auto theirs = ReadWithVtk(path);
  Expect(theirs->GetNumberOfPoints() > 0, path + ": vtkPLYReader read it");
  if (simple)
  {
    Expect(SameMesh(ReadSimplePly(path, header), theirs, why),
           path + ": ReadSimplePly gives vtkPLYReader's mesh (" + why + " differ)");
  }
  std::string description;
  auto ours = ReadMesh(path, description, error);
  Expect(ours && SameMesh(ours, theirs, why),
         path + ": ReadMesh gives vtkPLYReader's mesh (" + error + why + ")");
}

void TestLayouts(const std::string& dir)
{
  auto mesh = Sphere(24);
  const vtkIdType n = mesh->GetNumberOfPoints();
  // vtkPLYWriter 9.1 writes no normals (9.2's does): either way a simple layout.
  ExpectAsVtk(Write(mesh, nullptr, dir + "/normals.ply"), true);
  mesh->GetPointData()->SetNormals(nullptr);
  ExpectAsVtk(Write(mesh, nullptr, dir + "/plain.ply"), true);
  for (int components : { 3, 4 })
  {
    auto rgb = Colors(n, components, "RGB");
    mesh->GetPointData()->AddArray(rgb);
    ExpectAsVtk(Write(mesh, "RGB", dir + "/rgb" + std::to_string(components) + ".ply"), true);
    mesh->GetPointData()->RemoveArray("RGB");
  }
  // Polygons of several sizes, up to the 255 corners a byte counts; points without faces.
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 12; ++i)
  {
    points->InsertNextPoint(i, i * i, 1.0 / (1 + i));
  }
  vtkNew<vtkCellArray> polygons;
  polygons->InsertNextCell({ 0, 1, 2 });
  polygons->InsertNextCell({ 2, 3, 4, 5 });
  polygons->InsertNextCell({ 5, 6, 7, 8, 9, 10, 11 });
  polygons->InsertNextCell(255);
  for (int i = 0; i < 255; ++i)
  {
    polygons->InsertCellPoint(i % 12);
  }
  vtkNew<vtkPolyData> polygonal;
  polygonal->SetPoints(points);
  polygonal->SetPolys(polygons);
  ExpectAsVtk(Write(polygonal, nullptr, dir + "/polygons.ply"), true);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  ExpectAsVtk(Write(cloud, nullptr, dir + "/no-faces.ply"), true);
  // Several chunks of the reader (4 MiB): faces and vertices across their borders.
  auto large = Sphere(500);
  large->GetPointData()->AddArray(Colors(large->GetNumberOfPoints(), 3, "RGB"));
  const std::string path = Write(large, "RGB", dir + "/large.ply");
  Expect(FileBytes(path).size() > (size_t(8) << 20), "large.ply: over two chunks");
  ExpectAsVtk(path, true);
}

void TestLeftToVtk(const std::string& dir)
{
  auto mesh = Sphere(20);
  mesh->GetPointData()->SetNormals(nullptr);
  mesh->GetCellData()->AddArray(Colors(mesh->GetNumberOfCells(), 3, "FaceRGB"));
  ExpectAsVtk(Write(mesh, "FaceRGB", dir + "/face-colors.ply"), false);
  mesh->GetCellData()->RemoveArray("FaceRGB");
  mesh->GetPointData()->AddArray(Colors(mesh->GetNumberOfPoints(), 3, "RGB"));
  ExpectAsVtk(Write(mesh, "RGB", dir + "/big-endian.ply", true), false);
  ExpectAsVtk(Write(mesh, "RGB", dir + "/ascii.ply", false, true), false);
  vtkNew<vtkFloatArray> uv;
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(mesh->GetNumberOfPoints());
  uv->Fill(0.25);
  mesh->GetPointData()->SetTCoords(uv);
  ExpectAsVtk(Write(mesh, "RGB", dir + "/tcoords.ply"), false);
  // A property vtkPLYReader leaves out (a scanner's confidence): skipped, as it does.
  const std::string plain = FileBytes(Write(Sphere(8), nullptr, dir + "/eight.ply"));
  PlyHeader header;
  std::string error;
  ReadPlyHeader(dir + "/eight.ply", header, error);
  std::string withConfidence = plain.substr(0, header.BodyOffset);
  const size_t at = withConfidence.find("property float z\n") + 17;
  withConfidence.insert(at, "property float confidence\n");
  const vtkIdType points = Sphere(8)->GetNumberOfPoints();
  const std::string vertices = plain.substr(header.BodyOffset, 12 * size_t(points));
  for (vtkIdType i = 0; i < points; ++i)
  {
    withConfidence += vertices.substr(12 * size_t(i), 12) + std::string(4, '\0');
  }
  withConfidence += plain.substr(header.BodyOffset + 12 * size_t(points));
  std::ofstream(dir + "/confidence.ply", std::ios::binary) << withConfidence;
  ExpectAsVtk(dir + "/confidence.ply", true);
}

/// A simple file cut short, in its vertices or its faces: ReadSimplePly gives nothing, and
/// ReadMesh the error of CheckPly, naming where the file ends.
void TestTruncated(const std::string& dir)
{
  auto mesh = Sphere(30);
  mesh->GetPointData()->SetNormals(nullptr);
  const std::string bytes = FileBytes(Write(mesh, nullptr, dir + "/whole.ply"));
  PlyHeader header;
  std::string error;
  ReadPlyHeader(dir + "/whole.ply", header, error);
  for (size_t keep : { size_t(header.BodyOffset + 100), bytes.size() - 5 })
  {
    const std::string path = dir + "/cut" + std::to_string(keep) + ".ply";
    std::ofstream(path, std::ios::binary) << bytes.substr(0, keep);
    Expect(ReadSimplePly(path, header) == nullptr, path + ": ReadSimplePly reads nothing");
    std::string description;
    error.clear();
    Expect(!ReadMesh(path, description, error), path + ": ReadMesh refuses it");
    Expect(error.find("cannot be read") != std::string::npos, path + ": " + error);
  }
  // A header that announces billions of faces in a small file: refused before any allocation.
  std::string inflated = bytes;
  const size_t at = inflated.find("element face ") + 13;
  inflated.replace(at, inflated.find('\n', at) - at, "4000000000");
  const std::string path = dir + "/inflated.ply";
  std::ofstream(path, std::ios::binary) << inflated;
  PlyHeader big;
  Expect(ReadPlyHeader(path, big, error) && big.Elements[1].Count == 4000000000u,
         "inflated.ply: the header counts 4e9 faces");
  Expect(ReadSimplePly(path, big) == nullptr, "inflated.ply: ReadSimplePly reads nothing");
  std::string description;
  error.clear();
  Expect(!ReadMesh(path, description, error) && !error.empty(), "inflated.ply: " + error);
}
} // namespace

int main(int argc, char* argv[])
{
  return colordecimation::tools::test::Run(argc, argv, "TestPlyReader",
                                           { TestLayouts, TestLeftToVtk, TestTruncated });
}
