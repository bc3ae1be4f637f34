/**
 * @file TestPlyReader.cxx
 * @brief PlyReader.h against vtkPLYReader: the same mesh (points, point arrays, polygons) for
 * every layout it reads (no colour, RGB, RGBA, normals with colours and alpha, properties both
 * skip, before x and between the colours, unsigned corner ids, polygons of 0 to 255 corners,
 * no faces, a file of several chunks), through ReadSimplePly and the CLI's ReadMesh; the
 * layouts it leaves to vtkPLYReader (face colours, texture coordinates, normals or colours not
 * all there, a name twice, vertex_index, big-endian, ASCII, a blank before "ply") are still
 * read as vtkPLYReader reads them; ids out of range are kept as stored; a truncated file, or
 * one whose header announces more than it holds, is an error.
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
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cstring>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

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
using colordecimation::tools::test::WriteWithVtk;

/// Write `mesh` with vtkPLYWriter (binary unless ascii; the named colour array, with alpha
/// when it has 4 components; texture coordinates when it has them).
std::string Write(vtkPolyData* mesh, const char* colors, const std::string& path,
                  bool bigEndian = false, bool ascii = false)
{
  vtkDataArray* array = colors ? mesh->GetPointData()->GetArray(colors) : nullptr;
  array = array || !colors ? array : mesh->GetCellData()->GetArray(colors);
  Expect(WriteWithVtk(mesh, vtkUnsignedCharArray::SafeDownCast(array), path, bigEndian, ascii),
         path + ": written by vtkPLYWriter");
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
    Expect(SameMesh(ReadSimplePly(path, header, error), theirs, why),
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

/// A binary little-endian PLY file made by hand: `points` vertices with the given properties
/// (type and name; floats i / 4 + k, bytes from a pattern), and faces of the given corners,
/// each a list with a uchar count of `indexType` items named `indexName`.
struct HandMade
{
  std::vector<std::pair<std::string, std::string>> Properties;
  std::vector<std::vector<uint32_t>> Faces;
  int Points = 7;
  std::string IndexType = "int";
  std::string IndexName = "vertex_indices";

  std::string Write(const std::string& path) const
  {
    std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(this->Points) + "\n";
    for (const auto& p : this->Properties)
    {
      bytes += "property " + p.first + " " + p.second + "\n";
    }
    bytes += "element face " + std::to_string(this->Faces.size()) + "\nproperty list uchar " +
      this->IndexType + " " + this->IndexName + "\nend_header\n";
    for (int i = 0; i < this->Points; ++i)
    {
      for (size_t k = 0; k < this->Properties.size(); ++k)
      {
        if (this->Properties[k].first == "float")
        {
          const float value = 0.25f * float(i) + float(k);
          bytes.append(reinterpret_cast<const char*>(&value), sizeof(value));
        }
        else
        {
          bytes += static_cast<char>((i * 37 + int(k) * 11) % 256);
        }
      }
    }
    for (const auto& face : this->Faces)
    {
      bytes += static_cast<char>(face.size());
      bytes.append(reinterpret_cast<const char*>(face.data()), 4 * face.size());
    }
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
};

/// Layouts written by hand: normals with colours and alpha, properties vtkPLYReader skips
/// before x and between the colours, unsigned corner ids, faces of 0 to 2 corners; and the
/// ones left to vtkPLYReader (normals or colours not all there, a name twice, vertex_index).
void TestHandMade(const std::string& dir)
{
  using Props = std::vector<std::pair<std::string, std::string>>;
  const Props xyz = { { "float", "x" }, { "float", "y" }, { "float", "z" } };
  const std::vector<std::vector<uint32_t>> triangles = { { 0, 1, 2 }, { 2, 3, 4 }, { 4, 5, 6 } };
  HandMade full{ { { "float", "quality" },
                   { "float", "x" },
                   { "float", "y" },
                   { "float", "z" },
                   { "float", "nx" },
                   { "float", "ny" },
                   { "float", "nz" },
                   { "uchar", "red" },
                   { "uchar", "flags" },
                   { "uchar", "green" },
                   { "uint8", "blue" },
                   { "uchar", "alpha" } },
                 triangles };
  ExpectAsVtk(full.Write(dir + "/hand-full.ply"), true);
  HandMade unsignedIds{ xyz, { { 0, 1, 2, 3 }, { 6, 5, 4 } } };
  unsignedIds.IndexType = "uint";
  ExpectAsVtk(unsignedIds.Write(dir + "/hand-uint.ply"), true);
  HandMade shortFaces{ xyz, { { 0, 1, 2 }, {}, { 3 }, { 4, 5 }, { 6, 5, 4 } } };
  ExpectAsVtk(shortFaces.Write(dir + "/hand-short-faces.ply"), true);
  int file = 0;
  for (const auto& layout :
       { Props{ { "float", "x" },
                { "float", "y" },
                { "float", "z" },
                { "float", "nx" },
                { "float", "ny" } },
         Props{ { "float", "x" }, { "float", "y" }, { "float", "z" }, { "uchar", "alpha" } },
         Props{ { "float", "x" },
                { "float", "y" },
                { "float", "z" },
                { "uchar", "red" },
                { "uchar", "green" } },
         Props{ { "float", "x" }, { "float", "x" }, { "float", "y" }, { "float", "z" } } })
  {
    ExpectAsVtk(
      HandMade{ layout, triangles }.Write(dir + "/hand-vtk" + std::to_string(file++) + ".ply"),
      false);
  }
  HandMade singular{ xyz, triangles };
  singular.IndexName = "vertex_index";
  ExpectAsVtk(singular.Write(dir + "/hand-vertex-index.ply"), false);
  // Ids as stored, out of range too (vtkPLYReader would read points there: not compared); the
  // filter refuses them. A file that starts with a blank is left to vtkPLYReader's test.
  HandMade outside{ xyz, { { 0, 1, 7 }, { 2, 0xffffffffu, 3 } } };
  const std::string path = outside.Write(dir + "/hand-outside.ply");
  PlyHeader header;
  std::string error;
  ReadPlyHeader(path, header, error);
  auto mesh = ReadSimplePly(path, header, error);
  vtkNew<vtkIdList> ids;
  Expect(mesh && mesh->GetNumberOfPolys() == 2, "hand-outside.ply: read");
  if (mesh && mesh->GetNumberOfPolys() == 2)
  {
    mesh->GetPolys()->GetCellAtId(1, ids);
    Expect(ids->GetNumberOfIds() == 3 && ids->GetId(1) == -1, "hand-outside.ply: id -1 kept");
  }
  std::ofstream(dir + "/hand-blank.ply", std::ios::binary) << " " + FileBytes(path);
  Expect(ReadPlyHeader(dir + "/hand-blank.ply", header, error) && IsSimplePly(header) &&
           !ReadSimplePly(dir + "/hand-blank.ply", header, error) && error.empty(),
         "hand-blank.ply: not read in one pass");
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
    Expect(ReadSimplePly(path, header, error) == nullptr && error.empty(),
           path + ": ReadSimplePly reads nothing, and leaves the error to the checks");
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
  Expect(ReadSimplePly(path, big, error) == nullptr && error.empty(),
         "inflated.ply: ReadSimplePly reads nothing");
  std::string description;
  error.clear();
  Expect(!ReadMesh(path, description, error) && !error.empty(), "inflated.ply: " + error);
}
} // namespace

int main(int argc, char* argv[])
{
  return colordecimation::tools::test::Run(
    argc, argv, "TestPlyReader", { TestLayouts, TestHandMade, TestLeftToVtk, TestTruncated });
}
