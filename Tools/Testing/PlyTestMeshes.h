/**
 * @file PlyTestMeshes.h
 * @brief The meshes and arrays the PLY tests (TestPlyWriter, TestPlyReader) write, and the
 * reading of a file by vtkPLYReader, which both compare with.
 */
#ifndef colordecimation_tools_PlyTestMeshes_h
#define colordecimation_tools_PlyTestMeshes_h

#include "vtkNew.h"
#include "vtkPLYReader.h"
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
