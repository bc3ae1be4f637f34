#include "ColorDecimationRenderingScenes.h"

#include "ColorDecimationFidelity.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

namespace colordecimation
{
namespace rendering
{

using meshes::Pattern;

const std::vector<Scene>& Scenes()
{
  // Sharp colour regions, smooth gradients, fine (text-like) detail, an open boundary;
  // 50, 90 and 97 % reductions; colour alone (unlit) and shape alone (lit).
  static const std::vector<Scene> scenes = {
    { "SharpIcosphere90Unlit", "Icosphere", { 5, 0 }, Pattern::SharpRegions, 0.90, false },
    { "SmoothTorus50Unlit", "Torus", { 96, 40 }, Pattern::SmoothGradient, 0.50, false },
    { "FineDetailSphere90Unlit", "UVSphere", { 160, 0 }, Pattern::FineDetail, 0.90, false },
    { "SharpGrid97Unlit", "Grid", { 128, 128 }, Pattern::SharpRegions, 0.97, false },
    { "FineDetailGrid50Unlit", "Grid", { 96, 96 }, Pattern::FineDetail, 0.50, false },
    { "SharpTorus90Lit", "Torus", { 96, 40 }, Pattern::SharpRegions, 0.90, true },
    { "SmoothIcosphere97Lit", "Icosphere", { 5, 0 }, Pattern::SmoothGradient, 0.97, true },
    { "FineDetailGrid90Lit", "Grid", { 96, 96 }, Pattern::FineDetail, 0.90, true },
  };
  return scenes;
}

const Scene* FindScene(const std::string& name)
{
  for (const Scene& scene : Scenes())
  {
    if (scene.Name == name)
    {
      return &scene;
    }
  }
  return nullptr;
}

vtkSmartPointer<vtkPolyData> MakeInput(const Scene& scene)
{
  if (scene.Shape == "Icosphere")
  {
    return meshes::Icosphere(scene.Resolution[0], scene.Pattern);
  }
  if (scene.Shape == "UVSphere")
  {
    return meshes::UVSphere(scene.Resolution[0], scene.Pattern);
  }
  if (scene.Shape == "Torus")
  {
    return meshes::Torus(scene.Resolution[0], scene.Resolution[1], scene.Pattern);
  }
  return meshes::Grid(scene.Resolution[0], scene.Resolution[1], scene.Pattern);
}

vtkSmartPointer<vtkPolyData> Decimate(vtkPolyData* input, double reduction)
{
  vtkNew<vtkColorHalfEdgeDecimation> decimation;
  decimation->SetInputData(input);
  decimation->SetTargetReduction(reduction);
  decimation->Update();
  vtkSmartPointer<vtkPolyData> output = decimation->GetOutput();
  return output;
}

vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkPolyData* input, vtkPolyData* mesh, bool lit,
                                            int panel)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(2 * panel, panel);
  double bounds[6];
  input->GetBounds(bounds);
  const fidelity::View views[2] = { fidelity::View::Iso, fidelity::View::MinusZ };
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(mesh);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetSpecular(0.0);
    if (lit)
    {
      mapper->ScalarVisibilityOff();
      property->SetColor(0.85, 0.85, 0.85);
      property->SetAmbient(0.05);
      property->SetDiffuse(0.95);
      // The triangulation is part of the shape under test: draw the edges.
      property->EdgeVisibilityOn();
      property->SetEdgeColor(0.2, 0.25, 0.45);
    }
    else
    {
      mapper->ScalarVisibilityOn();
      mapper->SetScalarModeToUsePointData();
      mapper->SetColorModeToDirectScalars();
      property->LightingOff();
      property->SetAmbient(1.0);
      property->SetDiffuse(0.0);
    }
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * i, 0.0, 0.5 * (i + 1), 1.0);
    renderer->SetBackground(0.1, 0.1, 0.15);
    renderer->AddActor(actor);
    fidelity::FitCamera(renderer->GetActiveCamera(), bounds, views[i]);
    window->AddRenderer(renderer);
  }
  return window;
}

} // namespace rendering
} // namespace colordecimation
