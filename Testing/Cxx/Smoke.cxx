#include "ColorDecimationMeshes.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkNew.h"
#include "vtkTimerLog.h"
#include <iostream>
using namespace colordecimation::meshes;
int main(int argc, char** argv)
{
  int res = argc > 1 ? atoi(argv[1]) : 100;
  auto pd = UVSphere(res, Pattern::SharpRegions);
  for (auto mesh : { pd, Icosphere(4, Pattern::FineDetail), Torus(100, 40, Pattern::SmoothGradient),
         Grid(80, 60, Pattern::SharpRegions) })
  {
    vtkNew<vtkColorHalfEdgeDecimation> d;
    d->SetInputData(mesh);
    d->SetTargetReduction(0.9);
    vtkNew<vtkTimerLog> t;
    t->StartTimer();
    d->Update();
    t->StopTimer();
    std::cout << mesh->GetNumberOfPolys() << " -> " << d->GetOutput()->GetNumberOfPolys()
              << " actual " << d->GetActualReduction() << " in " << t->GetElapsedTime() << " s\n";
    if (d->GetActualReduction() < 0.89)
      return 1;
  }
  return 0;
}
