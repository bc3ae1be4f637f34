/**
 * @file MeshOptimizer.h
 * @brief meshoptimizer's meshopt_simplify on a vtkPolyData, the reference peer of the tools.
 *
 * Built only when meshoptimizer (Debian: libmeshoptimizer-dev) is found: the target
 * ColorDecimationMeshOptimizer then exists and defines COLORDECIMATION_WITH_MESHOPTIMIZER=1
 * for its users.
 */
#ifndef ColorDecimationMeshOptimizer_h
#define ColorDecimationMeshOptimizer_h

#include "vtkPolyData.h"

#include <vector>

namespace colordecimation
{
namespace tools
{

/**
 * Copies the points to float and the triangle ids to 32 bits (what a VTK user has to do
 * first), then runs meshopt_simplify (geometry only, no error bound: target error 1, so it
 * stops at the triangle target). Returns the kept triangles as 3 ids each into mesh's points
 * (MeshOnKeptTriangles() of IndexedMesh.h makes the vtkPolyData).
 */
std::vector<unsigned int> SimplifyWithMeshOptimizer(vtkPolyData* mesh, double reduction);

/// meshoptimizer's version, as "0.18".
const char* MeshOptimizerVersion();

} // namespace tools
} // namespace colordecimation

#endif
