/**
 * @file TestLegacyVtk.cxx
 * @brief CheckLegacyVtk (LegacyVtk.h) on files vtkPolyDataWriter and
 * vtkUnstructuredGridWriter write, ASCII and binary, versions 4.2 and 5.1, with the sections a
 * mesh has (vertices, lines, polygons, strips, cells and cell types; colours, scalars with a
 * lookup table, normals, texture coordinates, vectors, tensors, global ids, field arrays of
 * several types with component names, one of them empty, bits): each whole file passes (and
 * VTK reads it), and each file cut inside any of those sections' values fails, naming that
 * section. Hand-written files: values on a keyword's line, an empty cell section, version "5",
 * pass; counts of -1 or beyond any file, an ASCII file cut short, fail (and return).
 *
 * Usage: TestLegacyVtk DIRECTORY (a scratch folder for the files)
 */
#include "LegacyVtk.h"
#include "ToolsTest.h"

#include "vtkBitArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataWriter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkIdTypeArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkShortArray.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridWriter.h"

#include <fstream>
#include <string>
#include <vector>

namespace
{
using colordecimation::tools::CheckLegacyVtk;

using colordecimation::tools::test::Expect;
using colordecimation::tools::test::FileBytes;

/// An array of `components` x `tuples` values i * 0.25 (as T's values).
template <typename Array>
vtkSmartPointer<Array> Values(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  for (vtkIdType i = 0; i < tuples * components; ++i)
  {
    array->SetVariantValue(i, vtkVariant(0.25 * double(i % 1000)));
  }
  return array;
}

/// A sphere with every kind of cell and of attribute the legacy format has a section for.
vtkSmartPointer<vtkPolyData> Everything()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(9);
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(sphere->GetOutput());
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkCellArray> verts, lines, strips;
  verts->InsertNextCell({ 0, 1 });
  lines->InsertNextCell({ 2, 3, 4 });
  strips->InsertNextCell({ 5, 6, 7, 8 });
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  mesh->SetStrips(strips);
  vtkPointData* pd = mesh->GetPointData();
  pd->SetScalars(Values<vtkUnsignedCharArray>("RGB", 3, n));
  pd->SetTCoords(Values<vtkFloatArray>("UV", 2, n));
  pd->SetVectors(Values<vtkDoubleArray>("Velocity", 3, n));
  pd->SetTensors(Values<vtkFloatArray>("Stress", 9, n));
  pd->SetGlobalIds(Values<vtkIdTypeArray>("Ids", 1, n));
  auto named = Values<vtkShortArray>("Pair", 2, n);
  named->SetComponentName(0, "first");
  named->SetComponentName(1, "second");
  pd->AddArray(named);
  pd->AddArray(Values<vtkBitArray>("Flags", 1, n));
  auto gap = Values<vtkFloatArray>("Gap", 3, n); // a component without a name: an empty line
  gap->SetComponentName(0, "x");
  gap->SetComponentName(2, "z");
  pd->AddArray(gap);
  const vtkIdType cells = mesh->GetNumberOfCells();
  auto scalars = Values<vtkFloatArray>("Pressure", 1, cells);
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(5);
  table->Build();
  scalars->SetLookupTable(table);
  mesh->GetCellData()->SetScalars(scalars);
  mesh->GetCellData()->AddArray(Values<vtkDoubleArray>("Area", 1, cells));
  return mesh;
}

/// Where each section's values start: after the line of each keyword (and, for SCALARS,
/// after its LOOKUP_TABLE line), with the section's name.
std::vector<std::pair<size_t, std::string>> ValueStarts(const std::string& file)
{
  std::vector<std::pair<size_t, std::string>> starts;
  for (const char* key : { "POINTS",
                           "OFFSETS",
                           "CONNECTIVITY",
                           "VERTICES",
                           "LINES",
                           "POLYGONS",
                           "TRIANGLE_STRIPS",
                           "COLOR_SCALARS",
                           "LOOKUP_TABLE",
                           "NORMALS",
                           "TEXTURE_COORDINATES",
                           "VECTORS",
                           "TENSORS",
                           "GLOBAL_IDS",
                           "Pair",
                           "Flags",
                           "Gap",
                           "Area",
                           "CELLS",
                           "CELL_TYPES" })
  {
    for (size_t at = file.find(std::string("\n") + key + " "); at != std::string::npos;
         at = file.find(std::string("\n") + key + " ", at + 1))
    {
      const size_t end = file.find('\n', at + 1);
      starts.emplace_back(end + 1, key);
    }
  }
  return starts;
}

/// A grid of two triangles and a tetrahedron, for CELLS and CELL_TYPES.
vtkSmartPointer<vtkUnstructuredGrid> Grid()
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 5; ++i)
  {
    points->InsertNextPoint(i % 2, i / 2, i == 4 ? 1.0 : 0.0);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  const vtkIdType first[] = { 0, 1, 2 }, second[] = { 1, 3, 2 }, tetra[] = { 0, 1, 2, 4 };
  grid->InsertNextCell(VTK_TRIANGLE, 3, first);
  grid->InsertNextCell(VTK_TRIANGLE, 3, second);
  grid->InsertNextCell(VTK_TETRA, 4, tetra);
  grid->GetPointData()->SetScalars(Values<vtkUnsignedCharArray>("RGB", 3, 5));
  return grid;
}

/// `data` written by `writer` in each format: the whole file passes (and VTK reads it), and
/// the file cut 2 bytes into the values of each section fails naming the section.
void TestFile(vtkDataSet* data, vtkDataWriter* writer, bool binary, int version,
              const std::string& dir, size_t sections)
{
  const std::string name = std::string(data->GetClassName()) + "-" + (binary ? "binary" : "ascii") +
    "-" + std::to_string(version);
  const std::string path = dir + "/" + name + ".vtk";
  writer->SetFileName(path.c_str());
  writer->SetFileVersion(version);
  binary ? writer->SetFileTypeToBinary() : writer->SetFileTypeToASCII();
  writer->SetInputDataObject(data);
  Expect(writer->Write() == 1, name + ": written");
  std::string error;
  Expect(CheckLegacyVtk(path, error), name + ": the whole file passes (" + error + ")");
  vtkNew<vtkGenericDataObjectReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto* read = vtkDataSet::SafeDownCast(reader->GetOutput());
  Expect(read && read->GetNumberOfCells() == data->GetNumberOfCells(), name + ": VTK reads it");
  const std::string file = FileBytes(path);
  const auto starts = ValueStarts(file);
  Expect(starts.size() >= sections,
         name + ": its sections found (" + std::to_string(starts.size()) + ")");
  for (const auto& [start, key] : starts)
  {
    const std::string cut = dir + "/" + name + "-cut.vtk";
    std::ofstream(cut, std::ios::binary).write(file.data(), std::streamsize(start + 2));
    error.clear();
    const bool passed = CheckLegacyVtk(cut, error);
    Expect(!passed && error.find("ends inside its") != std::string::npos,
           name + ": cut 2 bytes into the values after " + key + " at " + std::to_string(start) +
             ": " + (passed ? "passed" : error));
  }
}
/// Files written by hand: what VTK reads must pass, what ends early (or announces more values
/// than a file can hold) must fail, and nothing may hang.
void TestHandWritten(const std::string& dir)
{
  const std::string header = "# vtk DataFile Version ";
  const std::string triangle = "\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n";
  const struct
  {
    const char* Name;
    std::string Text;
    bool Passes;
  } files[] = {
    { "values on the keyword lines",
      header +
        "4.2\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 "
        "float 0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4 3 0 1 2\n",
      true },
    { "an empty cell section with no offsets (5.1)",
      header + "5.1\nx\nASCII" + triangle +
        "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n"
        "VERTICES 0 0\n",
      true },
    { "version 5 without a minor number (cells as in 4.2)",
      header + "5\nx\nASCII" + triangle + "POLYGONS 1 4\n3 0 1 2\n", true },
    { "a lookup table's values on its line",
      header + "4.2\nx\nASCII" + triangle +
        "POINT_DATA 3\nSCALARS s float\nLOOKUP_TABLE "
        "default 1 2 3\n",
      true },
    { "a count of -1",
      header + "5.1\nx\nBINARY\nDATASET POLYDATA\nPOINTS -1 double\n" + std::string(24, '\x01'),
      false },
    { "a count beyond any file",
      header + "5.1\nx\nBINARY\nDATASET POLYDATA\nPOINTS 4611686018427387904 float\n" +
        std::string(12, '\x01'),
      false },
    { "an ASCII triangle cut short",
      header + "4.2\nx\nASCII" + triangle + "POLYGONS 2 8\n3 0 1 2\n3 1", false },
  };
  for (const auto& file : files)
  {
    const std::string path = dir + "/hand.vtk";
    std::ofstream(path, std::ios::binary) << file.Text;
    std::string error;
    Expect(CheckLegacyVtk(path, error) == file.Passes,
           std::string(file.Name) + ": " + (file.Passes ? "passes" : "fails") + " (" + error + ")");
  }
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string dir = colordecimation::tools::test::Start(argc, argv, "TestLegacyVtk");
  if (dir.empty())
  {
    return 2;
  }
  auto mesh = Everything();
  auto grid = Grid();
  for (bool binary : { true, false })
  {
    for (int version : { 42, 51 })
    {
      TestFile(mesh, vtkNew<vtkPolyDataWriter>(), binary, version, dir, 17);
      TestFile(grid, vtkNew<vtkUnstructuredGridWriter>(), binary, version, dir, 4);
    }
  }
  TestHandWritten(dir);
  std::string error;
  Expect(CheckLegacyVtk(dir + "/none.vtk", error),
         "a file that is not there is left to the reader");
  return colordecimation::tools::test::Finish();
}
