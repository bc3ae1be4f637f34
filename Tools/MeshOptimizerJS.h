/**
 * @file MeshOptimizerJS.h
 * @brief meshoptimizer's current attribute-aware simplifiers (the npm package, WebAssembly,
 * run with the machine's `node`) on a vtkPolyData, for color-decimate-run and the benchmark.
 *
 * The package is pinned in Tools/MeshOptimizerJS (package.json, package-lock.json; install
 * it with `npm ci --prefix Tools/MeshOptimizerJS`), where simplify.mjs runs one
 * simplification. The folder is the source tree's (configured by CMake), or the one named by
 * the environment variable COLORDECIMATION_MESHOPTIMIZER_JS; `node` is looked up on PATH.
 * The mesh goes to node and back through files in a fresh temporary folder.
 */
#ifndef MeshOptimizerJS_h
#define MeshOptimizerJS_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

namespace colordecimation
{
namespace tools
{

/// Which simplifier of the package runs.
enum class MeshOptimizerJSMode
{
  Attributes, ///< simplifyWithAttributes: the kept vertices stay as they are
  Update,     ///< simplifyWithUpdate: the kept vertices' positions and colours are moved
  Prune       ///< simplifyWithAttributes with the Prune flag: small pieces may go whole
};

struct MeshOptimizerJSSettings
{
  MeshOptimizerJSMode Mode = MeshOptimizerJSMode::Attributes;
  double Reduction = 0.9; ///< fraction of the triangles to remove
  /// Weights of red, green and blue (the attributes, in [0,1]).
  std::array<double, 3> Weights = { { 1.0, 1.0, 1.0 } };
};

struct MeshOptimizerJSResult
{
  std::string Error;                    ///< empty when it ran
  std::vector<unsigned int> Triangles;  ///< the kept triangles, 3 input point ids each
  std::vector<float> Positions, Colors; ///< Update: every input point's new xyz and RGB
  double Seconds = 0;                   ///< wall clock of the simplify call, measured inside node
  double CpuSeconds = 0;                ///< node's CPU time over the same span
  double RoundTripSeconds = 0;          ///< the whole call: arrays, files, node's start and run
  double ResultError = 0;               ///< the simplifier's result_error (relative to the extent)
  long long PeakBytes = -1; ///< node's peak resident memory above its level before the call
  double TargetError = 0;   ///< the target_error given
};

/// "" when node and the pinned package are there, otherwise one line saying why not (the
/// check, which starts node once, is made at the first call).
const std::string& MeshOptimizerJSUnavailable();

/// "meshoptimizer 1.3.0 (npm package, WebAssembly) on node v20.20.2", once available.
const std::string& MeshOptimizerJSDescription();

/// The package's function that `mode` calls, with its flag: "simplifyWithAttributes",
/// "simplifyWithUpdate", "simplifyWithAttributes + Prune".
const char* MeshOptimizerJSFunction(MeshOptimizerJSMode mode);

/**
 * Runs the simplifier of `settings.Mode` on `mesh`'s triangles: positions as float, the
 * colour array (the active scalars; mapped to RGB in [0,1] as MeshColors.h does; 0 when there
 * is none) as 3 attributes, target index count from the reduction (TargetIndexCount()),
 * target_error FLT_MAX (so that the triangle target governs), no locked vertex, LockBorder
 * off.
 */
MeshOptimizerJSResult SimplifyWithMeshOptimizerJS(vtkPolyData* mesh,
                                                  const MeshOptimizerJSSettings& settings);

/// The result as a vtkPolyData on the points it uses with every point-data array; in Update
/// mode with the moved positions and colours (the colour array keeps its type and name).
vtkSmartPointer<vtkPolyData> MakeMeshOptimizerJSOutput(vtkPolyData* mesh,
                                                       const MeshOptimizerJSResult& result);

} // namespace tools
} // namespace colordecimation

#endif
