/**
 * @file ColorDecimationRenderingScenes.h
 * @brief The scenes of the image regression tests and the fidelity tests: a generated
 * coloured mesh, a reduction and a lighting mode, decimated by vtkColorHalfEdgeDecimation
 * and rendered offscreen into a window of two panels.
 */
#ifndef ColorDecimationRenderingScenes_h
#define ColorDecimationRenderingScenes_h

#include "ColorDecimationMeshes.h"

#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace colordecimation
{
namespace rendering
{

struct Scene
{
  std::string Name;
  std::string Shape; ///< Icosphere, UVSphere, Torus or Grid
  int Resolution[2];
  meshes::Pattern Pattern;
  double Reduction; ///< TargetReduction of the decimation
  bool Lit;         ///< false: colour alone (unlit); true: shape alone (lit grey, edges)
};

/// Every scene of the image tests.
const std::vector<Scene>& Scenes();

/// The scene of that name, or null.
const Scene* FindScene(const std::string& name);

/// The scene's generated input mesh.
vtkSmartPointer<vtkPolyData> MakeInput(const Scene& scene);

/// The scene's input decimated to `reduction` (the scene's when negative).
vtkSmartPointer<vtkPolyData> Decimate(vtkPolyData* input, double reduction);

/**
 * An offscreen window of 2 * `panel` x `panel` pixels showing `mesh` (left: iso view,
 * right: the -Z view) with cameras fitted to `input`'s bounding box; unlit colours or
 * lit grey shape with its edges drawn, as `lit` says.
 */
vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkPolyData* input, vtkPolyData* mesh, bool lit,
                                            int panel = 200);

} // namespace rendering
} // namespace colordecimation

#endif
