/**
 * @file TestValgrindDecimation.cxx
 * @brief A representative decimation for memory checkers: a 20480-triangle coloured
 * icosphere through vtkColorHalfEdgeDecimation (90 % reduction: the defaults with the collapse
 * record, then the paper's metric and the geometric one), with the output invariants checked,
 * and a level extracted from the record by vtkColorHalfEdgeLevelOfDetail. Run under valgrind by
 * .ci/valgrind.sh and the ctest test ColorDecimation.Valgrind (label valgrind); it is an ordinary
 * test in every other build.
 */
#include "ColorDecimationMeshes.h"
#include "ColorDecimationTestUtilities.h"

#include "vtkColorHalfEdgeDecimation.h"
#include "vtkColorHalfEdgeLevelOfDetail.h"
#include "vtkNew.h"
#include "vtkTable.h"

#include <iostream>

int main()
{
  using namespace colordecimation::testing;
  auto mesh = colordecimation::meshes::Icosphere(5, colordecimation::meshes::Pattern::FineDetail);
  // The defaults (AttributeQuadric, Batched) with the record, then the other metrics.
  for (int metric : { -1, int(vtkColorHalfEdgeDecimation::HalfEdgeColor),
                      int(vtkColorHalfEdgeDecimation::Geometry) })
  {
    // The output invariants are checked by Decimate.
    const RunResult r = Decimate(mesh, 0.9,
                                 [metric](vtkColorHalfEdgeDecimation* filter)
                                 {
                                   if (metric < 0)
                                   {
                                     filter->GenerateCollapseRecordOn();
                                   }
                                   else
                                   {
                                     filter->SetErrorMetric(metric);
                                   }
                                 });
    if (metric < 0)
    {
      vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
      lod->SetInputData(mesh);
      lod->SetRecordData(r.Filter->GetCollapseRecord());
      lod->SetTargetReduction(0.5);
      lod->Update();
      std::cout << "level 0.5 from the record: " << lod->GetOutput()->GetNumberOfPolys()
                << " triangles\n";
      CD_CHECK(lod->GetOutput()->GetNumberOfPolys() == mesh->GetNumberOfPolys() / 2);
    }
    std::cout << r.Filter->GetErrorMetricAsString() << ": " << mesh->GetNumberOfPolys() << " -> "
              << r.Output->GetNumberOfPolys() << " triangles, " << r.Collapses << " collapses\n";
    CD_CHECK_MSG(r.Errors == 0 && r.Warnings == 0 && r.ActualReduction >= 0.88,
                 "unexpected: " << r.Errors << " errors, " << r.Warnings << " warnings, reduction "
                                << r.ActualReduction);
  }
  return GetNumberOfFailures() == 0 ? 0 : 1;
}
