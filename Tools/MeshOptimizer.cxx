#include "MeshOptimizer.h"

#include "IndexedMesh.h"

#include <meshoptimizer.h>

#include <string>

namespace colordecimation
{
namespace tools
{

std::vector<unsigned int> SimplifyWithMeshOptimizer(vtkPolyData* mesh, double reduction)
{
  const IndexedMesh indexed = ToIndexedMesh(mesh);
  const size_t target = TargetIndexCount(indexed.Indices.size() / 3, reduction);
  std::vector<unsigned int> simplified(indexed.Indices.size());
  float error = 0;
  // target_error 1 = 100 % of the mesh extent: no error bound, stop at the triangle target.
  const size_t count = meshopt_simplify(
    simplified.data(), indexed.Indices.data(), indexed.Indices.size(), indexed.Positions.data(),
    indexed.Positions.size() / 3, 3 * sizeof(float), target, 1.0f, 0, &error);
  simplified.resize(count);
  return simplified;
}

const char* MeshOptimizerVersion()
{
  static const std::string version = std::to_string(MESHOPTIMIZER_VERSION / 1000) + "." +
    std::to_string((MESHOPTIMIZER_VERSION % 1000) / 10);
  return version.c_str();
}

} // namespace tools
} // namespace colordecimation
