/**
 * @file PlyTestMeshes.h
 * @brief The meshes and arrays the PLY tests (TestPlyWriter, TestPlyReader) write, and the
 * writing and reading of a file by vtkPLYWriter and vtkPLYReader, which both compare with.
 */
#ifndef colordecimation_tools_PlyTestMeshes_h
#define colordecimation_tools_PlyTestMeshes_h

#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <string>

namespace colordecimation
{
namespace tools
{
namespace test
{
/// A sphere (float points, float normals) of `resolution`, with none of its arrays but those.
inline vtkSmartPointer<vtkPolyData> Sphere(int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(sphere->GetOutput());
  return mesh;
}

/// Bytes of tuple i: a pattern that differs between tuples and components.
inline vtkSmartPointer<vtkUnsignedCharArray> Colors(vtkIdType tuples, int components,
                                                    const char* name)
{
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName(name);
  colors->SetNumberOfComponents(components);
  colors->SetNumberOfTuples(tuples);
  for (vtkIdType i = 0; i < tuples * components; ++i)
  {
    colors->SetValue(i, static_cast<unsigned char>((i * 37 + i / 7) % 256));
  }
  return colors;
}

/// Write `mesh` to `path` with vtkPLYWriter as the CLI would: binary (little-endian unless
/// bigEndian) or ascii, the colour array `colors` by name with alpha when it has 4 components,
/// no colour without it; whether it wrote the file.
inline bool WriteWithVtk(vtkPolyData* mesh, vtkUnsignedCharArray* colors, const std::string& path,
                         bool bigEndian = false, bool ascii = false)
{
  vtkNew<vtkPLYWriter> writer;
  writer->SetFileName(path.c_str());
  ascii ? writer->SetFileTypeToASCII() : writer->SetFileTypeToBinary();
  bigEndian ? writer->SetDataByteOrderToBigEndian() : writer->SetDataByteOrderToLittleEndian();
  writer->SetInputData(mesh);
  if (colors)
  {
    writer->SetArrayName(colors->GetName());
    writer->SetEnableAlpha(colors->GetNumberOfComponents() == 4);
  }
  else
  {
    writer->SetColorModeToOff();
  }
  return writer->Write() == 1;
}

/// The mesh vtkPLYReader reads from `path`.
inline vtkSmartPointer<vtkPolyData> ReadWithVtk(const std::string& path)
{
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  return mesh;
}
} // namespace test
} // namespace tools
} // namespace colordecimation

#endif
