/**
 * @file TestValgrindDecimation.cxx
 * @brief A representative decimation for memory checkers: a 20480-triangle coloured
 * icosphere through vtkColorHalfEdgeDecimation (90 % reduction, both metrics), with the output
 * invariants checked. Run under valgrind by .ci/valgrind.sh and the ctest test
 * ColorDecimation.Valgrind (label valgrind); it is an ordinary test in every other build.
 */
#include "ColorDecimationInvariants.h"
#include "ColorDecimationMeshes.h"

#include "vtkColorHalfEdgeDecimation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <iostream>

int main()
{
  using colordecimation::meshes::Pattern;
  auto mesh = colordecimation::meshes::Icosphere(5, Pattern::FineDetail);
  int failures = 0;
  for (int metric :
       { vtkColorHalfEdgeDecimation::HalfEdgeColor, vtkColorHalfEdgeDecimation::Geometry })
  {
    vtkNew<vtkColorHalfEdgeDecimation> filter;
    colordecimation::hostile::EventCounter events;
    events.Observe(filter);
    filter->SetInputData(mesh);
    filter->SetErrorMetric(metric);
    filter->SetTargetReduction(0.9);
    filter->Update();
    vtkPolyData* output = filter->GetOutput();
    std::cout << filter->GetErrorMetricAsString() << ": " << mesh->GetNumberOfPolys() << " -> "
              << output->GetNumberOfPolys() << " triangles, " << filter->GetNumberOfCollapses()
              << " collapses\n";
    for (const std::string& broken :
         colordecimation::hostile::CheckInvariants(mesh, filter, output, events.Errors > 0))
    {
      std::cout << "broken invariant: " << broken << "\n";
      ++failures;
    }
    if (events.Errors || events.Warnings || filter->GetActualReduction() < 0.88)
    {
      std::cout << "unexpected: " << events.Errors << " errors, " << events.Warnings
                << " warnings, reduction " << filter->GetActualReduction() << "\n";
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
