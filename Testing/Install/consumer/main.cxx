// Uses the installed ColorDecimation package: decimates a coloured sphere and checks the
// counts and that the surviving points keep their colours.
#include <vtkColorHalfEdgeDecimation.h>

#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

int main()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(60);
  sphere->SetPhiResolution(60);
  sphere->Update();
  vtkPolyData* mesh = sphere->GetOutput();

  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    const unsigned char red[3] = { 230, 20, 20 };
    const unsigned char blue[3] = { 20, 40, 220 };
    rgb->SetTypedTuple(i, p[2] > 0.1 ? red : blue);
  }
  mesh->GetPointData()->SetScalars(rgb);

  vtkNew<vtkColorHalfEdgeDecimation> decimation;
  decimation->SetInputData(mesh);
  decimation->SetTargetReduction(0.75);
  decimation->Update();
  vtkPolyData* out = decimation->GetOutput();

  const vtkIdType nIn = mesh->GetNumberOfPolys();
  // The filter's target, floor((1 - TargetReduction) * triangles); a collapse on a closed
  // surface removes two triangles, so the output has the target or one less.
  const vtkIdType target = static_cast<vtkIdType>(std::floor((1.0 - 0.75) * nIn + 1e-6));
  std::cout << nIn << " -> " << out->GetNumberOfPolys() << " triangles (target " << target << ")\n";
  if (out->GetNumberOfPolys() > target || out->GetNumberOfPolys() < target - 1)
  {
    std::cerr << "FAILED: the target was not reached\n";
    return EXIT_FAILURE;
  }
  auto* outRgb = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("RGB"));
  auto* ids = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("vtkOriginalPointIds"));
  if (!outRgb || !ids)
  {
    std::cerr << "FAILED: RGB or vtkOriginalPointIds missing\n";
    return EXIT_FAILURE;
  }
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (outRgb->GetTypedComponent(i, k) != rgb->GetTypedComponent(ids->GetValue(i), k))
      {
        std::cerr << "FAILED: point " << i << " changed colour\n";
        return EXIT_FAILURE;
      }
    }
  }
  std::cout << "OK\n";
  return EXIT_SUCCESS;
}
