#include "IndexedMesh.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <cmath>

namespace colordecimation
{
namespace tools
{

IndexedMesh ToIndexedMesh(vtkPolyData* mesh)
{
  IndexedMesh indexed;
  const vtkIdType n = mesh->GetNumberOfPoints();
  indexed.Positions.resize(3 * static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      indexed.Positions[3 * i + k] = static_cast<float>(p[k]);
    }
  }
  indexed.Indices.reserve(3 * static_cast<size_t>(mesh->GetNumberOfPolys()));
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    if (npts == 3)
    {
      indexed.Indices.insert(indexed.Indices.end(),
                             { static_cast<unsigned int>(pts[0]), static_cast<unsigned int>(pts[1]),
                               static_cast<unsigned int>(pts[2]) });
    }
  }
  return indexed;
}

size_t TargetIndexCount(size_t triangles, double reduction)
{
  return 3 * static_cast<size_t>(std::llround(triangles * (1.0 - reduction)));
}

vtkSmartPointer<vtkPolyData> MeshOnKeptTriangles(vtkPolyData* mesh,
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

} // namespace tools
} // namespace colordecimation
