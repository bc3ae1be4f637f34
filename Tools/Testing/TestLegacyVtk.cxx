/**
 * @file TestLegacyVtk.cxx
 * @brief CheckLegacyVtk (LegacyVtk.h) on files vtkPolyDataWriter writes, ASCII and binary,
 * versions 4.2 and 5.1, with every kind of section (vertices, lines, polygons, strips;
 * colours, scalars with a lookup table, normals, texture coordinates, vectors, tensors,
 * global ids, field arrays of several types with component names, bits): each whole file
 * passes (and VTK reads it), and each file cut inside any of its sections' values fails,
 * naming that section.
 *
 * Usage: TestLegacyVtk DIRECTORY (a scratch folder for the files)
 */
#include "LegacyVtk.h"
#include "ToolsTest.h"

#include "vtkBitArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkShortArray.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
using colordecimation::tools::CheckLegacyVtk;

using colordecimation::tools::test::Expect;

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

std::string Bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Where each section's values start: after the line of each keyword (and, for SCALARS,
/// after its LOOKUP_TABLE line), with the section's name.
std::vector<std::pair<size_t, std::string>> ValueStarts(const std::string& file)
{
  std::vector<std::pair<size_t, std::string>> starts;
  for (const char* key :
       { "POINTS", "OFFSETS", "CONNECTIVITY", "VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS",
         "COLOR_SCALARS", "LOOKUP_TABLE", "NORMALS", "TEXTURE_COORDINATES", "VECTORS", "TENSORS",
         "GLOBAL_IDS", "Pair", "Flags", "Area" })
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

void TestFile(vtkPolyData* mesh, bool binary, int version, const std::string& dir)
{
  const std::string name = std::string(binary ? "binary" : "ascii") + "-" + std::to_string(version);
  const std::string path = dir + "/" + name + ".vtk";
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetFileVersion(version);
  binary ? writer->SetFileTypeToBinary() : writer->SetFileTypeToASCII();
  writer->SetInputData(mesh);
  Expect(writer->Write() == 1, name + ": written");
  std::string error;
  Expect(CheckLegacyVtk(path, error), name + ": the whole file passes (" + error + ")");
  vtkNew<vtkPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  Expect(reader->GetOutput()->GetNumberOfCells() == mesh->GetNumberOfCells(),
         name + ": and VTK reads it");
  const std::string file = Bytes(path);
  const auto starts = ValueStarts(file);
  Expect(starts.size() >= 14,
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
} // namespace

int main(int argc, char* argv[])
{
  colordecimation::tools::test::Name = "TestLegacyVtk";
  if (argc != 2)
  {
    std::cerr << "Usage: TestLegacyVtk DIRECTORY" << std::endl;
    return 2;
  }
  auto mesh = Everything();
  for (bool binary : { true, false })
  {
    for (int version : { 42, 51 })
    {
      TestFile(mesh, binary, version, argv[1]);
    }
  }
  std::string error;
  Expect(CheckLegacyVtk(std::string(argv[1]) + "/none.vtk", error),
         "a file that is not there is left to the reader");
  return colordecimation::tools::test::Finish();
}
