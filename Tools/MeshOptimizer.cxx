#include "MeshOptimizer.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <meshoptimizer.h>

#include <cmath>
#include <string>

namespace colordecimation
{
namespace tools
{

std::vector<unsigned int> SimplifyWithMeshOptimizer(vtkPolyData* mesh, double reduction)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<float> positions(3 * static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      positions[3 * i + k] = static_cast<float>(p[k]);
    }
  }
  std::vector<unsigned int> indices;
  indices.reserve(3 * static_cast<size_t>(mesh->GetNumberOfPolys()));
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    if (npts == 3)
    {
      indices.insert(indices.end(),
                     { static_cast<unsigned int>(pts[0]), static_cast<unsigned int>(pts[1]),
                       static_cast<unsigned int>(pts[2]) });
    }
  }
  const size_t triangles = indices.size() / 3;
  const size_t target = 3 * static_cast<size_t>(std::llround(triangles * (1.0 - reduction)));
  std::vector<unsigned int> simplified(indices.size());
  float error = 0;
  // target_error 1 = 100 % of the mesh extent: no error bound, stop at the triangle target.
  const size_t count =
    meshopt_simplify(simplified.data(), indices.data(), indices.size(), positions.data(),
                     static_cast<size_t>(n), 3 * sizeof(float), target, 1.0f, 0, &error);
  simplified.resize(count);
  return simplified;
}

vtkSmartPointer<vtkPolyData> MakeMeshOptimizerOutput(vtkPolyData* mesh,
                                                     const std::vector<unsigned int>& triangles)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<vtkIdType> newId(n, -1);
  vtkNew<vtkIdList> source;
  vtkNew<vtkIdList> destination;
  for (const unsigned int v : triangles)
  {
    if (newId[v] < 0)
    {
      newId[v] = source->GetNumberOfIds();
      destination->InsertNextId(newId[v]);
      source->InsertNextId(v);
    }
  }
  auto output = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(source->GetNumberOfIds());
  mesh->GetPoints()->GetData()->GetTuples(source, points->GetData());
  output->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  for (size_t k = 0; k + 2 < triangles.size(); k += 3)
  {
    const vtkIdType tri[3] = { newId[triangles[k]], newId[triangles[k + 1]],
                               newId[triangles[k + 2]] };
    polys->InsertNextCell(3, tri);
  }
  output->SetPolys(polys);
  output->GetPointData()->CopyAllocate(mesh->GetPointData(), source->GetNumberOfIds());
  output->GetPointData()->CopyData(mesh->GetPointData(), source, destination);
  return output;
}

const char* MeshOptimizerVersion()
{
  static const std::string version = std::to_string(MESHOPTIMIZER_VERSION / 1000) + "." +
    std::to_string((MESHOPTIMIZER_VERSION % 1000) / 10);
  return version.c_str();
}

} // namespace tools
} // namespace colordecimation
