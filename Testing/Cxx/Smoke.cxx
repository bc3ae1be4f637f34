#include "vtkColorHalfEdgeDecimation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPointData.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkTimerLog.h"
#include <iostream>
int main(int argc, char** argv)
{
  vtkNew<vtkSphereSource> s;
  int res = argc > 1 ? atoi(argv[1]) : 100;
  s->SetThetaResolution(res);
  s->SetPhiResolution(res);
  s->Update();
  vtkPolyData* pd = s->GetOutput();
  vtkNew<vtkUnsignedCharArray> c;
  c->SetNumberOfComponents(3);
  c->SetName("RGB");
  c->SetNumberOfTuples(pd->GetNumberOfPoints());
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    c->SetTuple3(i, p[0] > 0 ? 255 : 0, 128 + 100 * p[1], p[2] > 0.2 ? 255 : 0);
  }
  pd->GetPointData()->SetScalars(c);
  vtkNew<vtkColorHalfEdgeDecimation> d;
  d->SetInputData(pd);
  d->SetTargetReduction(0.9);
  vtkNew<vtkTimerLog> t;
  t->StartTimer();
  d->Update();
  t->StopTimer();
  std::cout << pd->GetNumberOfPolys() << " -> " << d->GetOutput()->GetNumberOfPolys() << " actual "
            << d->GetActualReduction() << " in " << t->GetElapsedTime() << " s\n";
  return d->GetActualReduction() > 0.89 ? 0 : 1;
}
