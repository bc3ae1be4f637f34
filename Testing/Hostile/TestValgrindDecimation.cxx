/**
 * @file TestValgrindDecimation.cxx
 * @brief A representative decimation for memory checkers: a 20480-triangle coloured
 * icosphere through vtkColorHalfEdgeDecimation (90 % reduction, both metrics), with the output
 * invariants checked. Run under valgrind by .ci/valgrind.sh and the ctest test
 * ColorDecimation.Valgrind (label valgrind); it is an ordinary test in every other build.
 */
#include "ColorDecimationMeshes.h"
#include "ColorDecimationTestUtilities.h"

#include "vtkColorHalfEdgeDecimation.h"

#include <iostream>

int main()
{
  using namespace colordecimation::testing;
  auto mesh = colordecimation::meshes::Icosphere(5, colordecimation::meshes::Pattern::FineDetail);
  for (int metric :
       { vtkColorHalfEdgeDecimation::HalfEdgeColor, vtkColorHalfEdgeDecimation::Geometry })
  {
    // The output invariants are checked by Decimate.
    const RunResult r = Decimate(
      mesh, 0.9, [metric](vtkColorHalfEdgeDecimation* filter) { filter->SetErrorMetric(metric); });
    std::cout << r.Filter->GetErrorMetricAsString() << ": " << mesh->GetNumberOfPolys() << " -> "
              << r.Output->GetNumberOfPolys() << " triangles, " << r.Collapses << " collapses\n";
    CD_CHECK_MSG(r.Errors == 0 && r.Warnings == 0 && r.ActualReduction >= 0.88,
                 "unexpected: " << r.Errors << " errors, " << r.Warnings << " warnings, reduction "
                                << r.ActualReduction);
  }
  return GetNumberOfFailures() == 0 ? 0 : 1;
}
