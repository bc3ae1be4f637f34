#include "ColorDecimationFidelity.h"

#include "MeshIO.h"
#include "QuadricPeer.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkQuadricDecimation.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

namespace colordecimation
{
namespace fidelity
{

namespace
{

const View AxisViews[6] = { View::PlusX,  View::MinusX, View::PlusY,
                            View::MinusY, View::PlusZ,  View::MinusZ };

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// Where the colours are and how they map to RGB (chosen on the original).
struct RenderColors
{
  std::string Name; ///< empty: no colours
  bool OnCells = false;
  tools::ColorMapping Mapping;
};

bool IsColorLike(vtkDataArray* array)
{
  if (!array)
  {
    return false;
  }
  const int nc = array->GetNumberOfComponents();
  return nc == 1 || nc == 3 || nc == 4;
}

vtkDataArray* FindColorArray(vtkDataSetAttributes* data, const std::string& name)
{
  if (!name.empty())
  {
    return data->GetArray(name.c_str());
  }
  if (IsColorLike(data->GetScalars()))
  {
    return data->GetScalars();
  }
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = data->GetArray(i);
    if (array && (array->GetNumberOfComponents() == 3 || array->GetNumberOfComponents() == 4) &&
        array->GetName() && std::strcmp(array->GetName(), "Normals") != 0 &&
        array != data->GetNormals())
    {
      return array;
    }
  }
  return nullptr;
}

RenderColors ChooseColors(vtkPolyData* original, const std::string& requested)
{
  RenderColors colors;
  vtkDataArray* array = FindColorArray(original->GetPointData(), requested);
  bool onCells = false;
  if (!array)
  {
    array = FindColorArray(original->GetCellData(), requested);
    onCells = array != nullptr;
  }
  if (!array || !array->GetName())
  {
    return colors;
  }
  colors.Name = array->GetName();
  colors.OnCells = onCells;
  colors.Mapping = tools::ColorMapping::Of(array);
  return colors;
}

/// Only the triangles and an unsigned char RGB copy of the colours (no normals).
vtkSmartPointer<vtkPolyData> Renderable(vtkPolyData* mesh, const RenderColors& colors)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(mesh->GetPoints());
  out->SetPolys(mesh->GetPolys());
  out->SetStrips(mesh->GetStrips());
  if (colors.Name.empty())
  {
    return out;
  }
  vtkDataSetAttributes* data = colors.OnCells
    ? static_cast<vtkDataSetAttributes*>(mesh->GetCellData())
    : static_cast<vtkDataSetAttributes*>(mesh->GetPointData());
  vtkDataArray* array = data->GetArray(colors.Name.c_str());
  const vtkIdType expected = colors.OnCells ? mesh->GetNumberOfCells() : mesh->GetNumberOfPoints();
  if (!array || array->GetNumberOfTuples() != expected)
  {
    return out; // the simplified mesh lost its colours: it renders white
  }
  vtkSmartPointer<vtkUnsignedCharArray> rgb = tools::ToUnsignedChar(array, colors.Mapping, false);
  rgb->SetName("FidelityRGB");
  if (colors.OnCells)
  {
    out->GetCellData()->SetScalars(rgb);
  }
  else
  {
    out->GetPointData()->SetScalars(rgb);
  }
  return out;
}

enum class Mode
{
  Mask,
  Unlit,
  Lit
};

void ConfigureActor(vtkActor* actor, vtkPolyDataMapper* mapper, vtkPolyData* mesh, Mode mode)
{
  mapper->SetInputData(mesh);
  vtkProperty* property = actor->GetProperty();
  property->SetSpecular(0.0);
  const bool hasColors = mesh->GetPointData()->GetScalars() || mesh->GetCellData()->GetScalars();
  if (mode == Mode::Lit)
  {
    mapper->ScalarVisibilityOff();
    property->LightingOn();
    property->SetColor(0.85, 0.85, 0.85);
    property->SetAmbient(0.05);
    property->SetDiffuse(0.95);
    return;
  }
  property->LightingOff();
  property->SetAmbient(1.0);
  property->SetDiffuse(0.0);
  property->SetColor(1.0, 1.0, 1.0);
  if (mode == Mode::Unlit && hasColors)
  {
    mapper->ScalarVisibilityOn();
    mapper->SetColorModeToDirectScalars();
    mapper->InterpolateScalarsBeforeMappingOff();
    if (mesh->GetPointData()->GetScalars())
    {
      mapper->SetScalarModeToUsePointData();
    }
    else
    {
      mapper->SetScalarModeToUseCellData();
    }
  }
  else
  {
    mapper->ScalarVisibilityOff();
  }
}

/// An X server resets when its last client disconnects (Xvfb under xvfb-run does), and a
/// window opened while it resets fails with "bad X server connection" and aborts. Each
/// comparison or snapshot opens and closes its own window, so one initialised window is
/// kept for the life of the process: its connection keeps the server from resetting.
void HoldDisplay()
{
  static vtkSmartPointer<vtkRenderWindow> holder;
  if (!holder)
  {
    holder = vtkSmartPointer<vtkRenderWindow>::New();
    holder->SetOffScreenRendering(1);
    holder->SetSize(1, 1);
    holder->Render(); // opens the display connection and the context
  }
}

/// One offscreen window, renderer and actor reused for every render of a comparison.
class OffscreenRenderer
{
public:
  explicit OffscreenRenderer(int size)
    : Size(size)
  {
    HoldDisplay();
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Renderer->AddActor(this->Actor);
    this->Actor->SetMapper(this->Mapper);
    this->Grabber->SetInput(this->Window);
    this->Grabber->SetInputBufferTypeToRGB();
    this->Grabber->ReadFrontBufferOff();
  }

  vtkCamera* Camera() { return this->Renderer->GetActiveCamera(); }

  /// Renders `mesh` and returns its RGB pixels (Size * Size * 3 bytes).
  std::vector<unsigned char> Render(vtkPolyData* mesh, Mode mode)
  {
    ConfigureActor(this->Actor, this->Mapper, mesh, mode);
    this->Window->Render();
    this->Grabber->Modified();
    this->Grabber->Update();
    vtkImageData* image = this->Grabber->GetOutput();
    auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
    std::vector<unsigned char> pixels(static_cast<size_t>(this->Size) * this->Size * 3, 0);
    if (scalars && scalars->GetNumberOfValues() >= static_cast<vtkIdType>(pixels.size()) &&
        scalars->GetNumberOfComponents() == 3)
    {
      std::copy(scalars->GetPointer(0), scalars->GetPointer(0) + pixels.size(), pixels.begin());
    }
    return pixels;
  }

private:
  int Size;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkWindowToImageFilter> Grabber;
};

void Finish(Measure& m)
{
  if (m.CoveredPixels > 0)
  {
    m.Rms = std::sqrt(m.SumSquared / static_cast<double>(m.CoveredPixels));
  }
  if (m.CommonPixels > 0)
  {
    m.CommonRms = std::sqrt(m.CommonSumSquared / static_cast<double>(m.CommonPixels));
  }
  const double mse = m.CoveredPixels > 0 ? m.SumSquared / (3.0 * m.CoveredPixels) : 0.0;
  m.Psnr =
    mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
}

Measure CompareImages(const std::vector<unsigned char>& maskA, const std::vector<unsigned char>& a,
                      const std::vector<unsigned char>& maskB, const std::vector<unsigned char>& b)
{
  Measure m;
  const size_t n = a.size() / 3;
  for (size_t i = 0; i < n; ++i)
  {
    const bool coveredA = maskA[3 * i] | maskA[3 * i + 1] | maskA[3 * i + 2];
    const bool coveredB = maskB[3 * i] | maskB[3 * i + 1] | maskB[3 * i + 2];
    if (!coveredA && !coveredB)
    {
      continue;
    }
    ++m.CoveredPixels;
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      // An uncovered pixel is the black background, whatever was drawn there.
      const double va = coveredA ? a[3 * i + c] : 0.0;
      const double vb = coveredB ? b[3 * i + c] : 0.0;
      d2 += (va - vb) * (va - vb);
    }
    m.SumSquared += d2;
    if (coveredA && coveredB)
    {
      ++m.CommonPixels;
      m.CommonSumSquared += d2;
    }
  }
  Finish(m);
  return m;
}

void WritePixels(const std::vector<unsigned char>& pixels, int size, const std::string& path)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  std::copy(pixels.begin(), pixels.end(), out);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
}

void WriteViewImages(const std::string& directory, const char* pass, View view, int size,
                     const std::vector<unsigned char>& maskA, const std::vector<unsigned char>& a,
                     const std::vector<unsigned char>& maskB, const std::vector<unsigned char>& b)
{
  const std::string stem = directory + "/" + pass + "_" + ViewName(view) + "_";
  WritePixels(a, size, stem + "original.png");
  WritePixels(b, size, stem + "simplified.png");
  std::vector<unsigned char> difference(a.size(), 0);
  for (size_t i = 0; i < a.size(); ++i)
  {
    const size_t p = i - i % 3;
    const bool coveredA = maskA[p] | maskA[p + 1] | maskA[p + 2];
    const bool coveredB = maskB[p] | maskB[p + 1] | maskB[p + 2];
    const int va = coveredA ? a[i] : 0;
    const int vb = coveredB ? b[i] : 0;
    difference[i] = static_cast<unsigned char>(std::min(255, 5 * std::abs(va - vb)));
  }
  WritePixels(difference, size, stem + "difference.png");
}

tools::Json MeasureJson(const Measure& m)
{
  tools::Json json;
  json["view"] = m.View;
  json["covered_pixels"] = m.CoveredPixels;
  json["rms"] = m.Rms;
  json["psnr"] = m.Psnr; // +inf (identical renders) is written as null
  json["common_pixels"] = m.CommonPixels;
  json["common_rms"] = m.CommonRms;
  return json;
}

tools::Json PassJson(const PassResult& pass)
{
  if (!pass.Computed)
  {
    return nullptr;
  }
  tools::Json json;
  json["rms"] = pass.All.Rms;
  json["psnr"] = pass.All.Psnr;
  json["covered_pixels"] = pass.All.CoveredPixels;
  json["common_rms"] = pass.All.CommonRms;
  json["common_pixels"] = pass.All.CommonPixels;
  json["views"] = tools::Json::array();
  for (const Measure& view : pass.Views)
  {
    json["views"].push_back(MeasureJson(view));
  }
  return json;
}

void ProjectBounds(const double bounds[6], const double dir[3], const double up[3],
                   double halfExtent[2])
{
  // right = up x dir (dir points from the centre to the camera).
  const double right[3] = { up[1] * dir[2] - up[2] * dir[1], up[2] * dir[0] - up[0] * dir[2],
                            up[0] * dir[1] - up[1] * dir[0] };
  const double c[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                        0.5 * (bounds[4] + bounds[5]) };
  halfExtent[0] = halfExtent[1] = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[3] = { bounds[(corner & 1) ? 1 : 0] - c[0], bounds[(corner & 2) ? 3 : 2] - c[1],
                          bounds[(corner & 4) ? 5 : 4] - c[2] };
    halfExtent[0] =
      std::max(halfExtent[0], std::fabs(p[0] * right[0] + p[1] * right[1] + p[2] * right[2]));
    halfExtent[1] = std::max(halfExtent[1], std::fabs(p[0] * up[0] + p[1] * up[1] + p[2] * up[2]));
  }
}

} // namespace

const char* ViewName(View view)
{
  switch (view)
  {
    case View::PlusX:
      return "+X";
    case View::MinusX:
      return "-X";
    case View::PlusY:
      return "+Y";
    case View::MinusY:
      return "-Y";
    case View::PlusZ:
      return "+Z";
    case View::MinusZ:
      return "-Z";
    case View::Iso:
      return "iso";
  }
  return "?";
}

bool ParseView(const std::string& text, View& view)
{
  std::string t = Lower(text);
  if (t == "x" || t == "y" || t == "z")
  {
    t = "+" + t;
  }
  for (View v : { View::PlusX, View::MinusX, View::PlusY, View::MinusY, View::PlusZ, View::MinusZ,
                  View::Iso })
  {
    if (t == Lower(ViewName(v)))
    {
      view = v;
      return true;
    }
  }
  return false;
}

void FitCamera(vtkCamera* camera, const double bounds[6], View view)
{
  double dir[3] = { 0.0, 0.0, 0.0 };
  double up[3] = { 0.0, 0.0, 1.0 };
  switch (view)
  {
    case View::PlusX:
      dir[0] = 1.0;
      break;
    case View::MinusX:
      dir[0] = -1.0;
      break;
    case View::PlusY:
      dir[1] = 1.0;
      break;
    case View::MinusY:
      dir[1] = -1.0;
      break;
    case View::PlusZ:
      dir[2] = 1.0;
      up[2] = 0.0;
      up[1] = 1.0;
      break;
    case View::MinusZ:
      dir[2] = -1.0;
      up[2] = 0.0;
      up[1] = 1.0;
      break;
    case View::Iso:
    {
      const double s = 1.0 / std::sqrt(3.0);
      dir[0] = dir[1] = dir[2] = s;
      // Up: +Z made orthogonal to dir.
      const double k = 1.0 / std::sqrt(6.0);
      up[0] = -k;
      up[1] = -k;
      up[2] = 2.0 * k;
      break;
    }
  }
  const double c[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                        0.5 * (bounds[4] + bounds[5]) };
  const double dx = bounds[1] - bounds[0], dy = bounds[3] - bounds[2], dz = bounds[5] - bounds[4];
  double radius = 0.5 * std::sqrt(dx * dx + dy * dy + dz * dz);
  if (!(radius > 0.0))
  {
    radius = 1.0;
  }
  double half[2];
  ProjectBounds(bounds, dir, up, half);
  double scale = 1.04 * std::max(half[0], half[1]);
  if (!(scale > 0.0))
  {
    scale = radius;
  }
  const double distance = 4.0 * radius;
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(c);
  camera->SetPosition(c[0] + distance * dir[0], c[1] + distance * dir[1], c[2] + distance * dir[2]);
  camera->SetViewUp(up);
  camera->SetParallelScale(scale);
  camera->SetClippingRange(distance - 1.5 * radius, distance + 1.5 * radius);
}

Result CompareRenders(vtkPolyData* original, vtkPolyData* simplified, const Options& options)
{
  Result result;
  result.Size = options.Size;
  if (!original || !simplified)
  {
    result.Error = "null mesh";
    return result;
  }
  if (options.Size < 8 || options.Size > 8192)
  {
    result.Error = "size must lie in 8..8192";
    return result;
  }
  std::string why;
  if (!CanRender(&why))
  {
    result.Error = why;
    return result;
  }
  result.OriginalPoints = original->GetNumberOfPoints();
  result.OriginalTriangles = original->GetNumberOfPolys() + original->GetNumberOfStrips();
  result.SimplifiedPoints = simplified->GetNumberOfPoints();
  result.SimplifiedTriangles = simplified->GetNumberOfPolys() + simplified->GetNumberOfStrips();

  const RenderColors colors = ChooseColors(original, options.ColorArray);
  result.ColorArray = colors.Name;
  if (!options.ColorArray.empty() && colors.Name.empty())
  {
    result.Error = "no colour array named '" + options.ColorArray + "' in the original";
    return result;
  }
  auto a = Renderable(original, colors);
  auto b = Renderable(simplified, colors);
  double bounds[6];
  original->GetBounds(bounds);

  OffscreenRenderer renderer(options.Size);
  result.Unlit.Computed = options.Unlit;
  result.Lit.Computed = options.Lit;
  result.Unlit.All.View = result.Lit.All.View = "all";
  for (View view : AxisViews)
  {
    FitCamera(renderer.Camera(), bounds, view);
    const auto maskA = renderer.Render(a, Mode::Mask);
    const auto maskB = renderer.Render(b, Mode::Mask);
    for (int pass = 0; pass < 2; ++pass)
    {
      PassResult& target = pass == 0 ? result.Unlit : result.Lit;
      if (!target.Computed)
      {
        continue;
      }
      const Mode mode = pass == 0 ? Mode::Unlit : Mode::Lit;
      const auto imageA = renderer.Render(a, mode);
      const auto imageB = renderer.Render(b, mode);
      Measure m = CompareImages(maskA, imageA, maskB, imageB);
      if (!options.ImageDirectory.empty())
      {
        WriteViewImages(options.ImageDirectory, pass == 0 ? "unlit" : "lit", view, options.Size,
                        maskA, imageA, maskB, imageB);
      }
      m.View = ViewName(view);
      target.All.CoveredPixels += m.CoveredPixels;
      target.All.SumSquared += m.SumSquared;
      target.All.CommonPixels += m.CommonPixels;
      target.All.CommonSumSquared += m.CommonSumSquared;
      target.Views.push_back(m);
    }
  }
  Finish(result.Unlit.All);
  Finish(result.Lit.All);
  result.Ok = true;
  return result;
}

tools::Json ResultJson(const Result& result)
{
  tools::Json json;
  json["ok"] = result.Ok;
  if (!result.Ok)
  {
    json["error"] = result.Error;
    return json;
  }
  json["size"] = result.Size;
  json["views"] = 6;
  json["color_array"] = result.ColorArray.empty() ? tools::Json() : tools::Json(result.ColorArray);
  json["original"] = { { "points", result.OriginalPoints },
                       { "triangles", result.OriginalTriangles } };
  json["simplified"] = { { "points", result.SimplifiedPoints },
                         { "triangles", result.SimplifiedTriangles } };
  json["unlit"] = PassJson(result.Unlit);
  json["lit"] = PassJson(result.Lit);
  return json;
}

std::string ToJson(const Result& result, int indent)
{
  return tools::JsonText(ResultJson(result), indent);
}

namespace
{
/// Moves the focal point (and the camera) to the snapshot's centre, then zooms.
void CloseUp(vtkCamera* camera, const SnapshotOptions& options)
{
  const double scale = camera->GetParallelScale();
  double up[3], dir[3], right[3], fp[3], pos[3];
  camera->GetViewUp(up);
  camera->GetDirectionOfProjection(dir); // from the camera to the focal point
  right[0] = dir[1] * up[2] - dir[2] * up[1];
  right[1] = dir[2] * up[0] - dir[0] * up[2];
  right[2] = dir[0] * up[1] - dir[1] * up[0];
  camera->GetFocalPoint(fp);
  camera->GetPosition(pos);
  const double sx = (options.Center[0] - 0.5) * 2.0 * scale;
  const double sy = (options.Center[1] - 0.5) * 2.0 * scale;
  for (int k = 0; k < 3; ++k)
  {
    const double shift = sx * right[k] + sy * up[k];
    fp[k] += shift;
    pos[k] += shift;
  }
  camera->SetFocalPoint(fp);
  camera->SetPosition(pos);
  camera->SetParallelScale(scale / options.Zoom);
}

/// "NAME: N triangles" and the pass, in the panel's top left corner.
vtkSmartPointer<vtkTextActor> PanelLabel(const std::string& name, vtkPolyData* mesh, bool lit,
                                         int size)
{
  std::ostringstream label;
  label << name << ": " << mesh->GetNumberOfPolys() << " triangles\n"
        << (lit ? "shape (lit, grey)" : "colour (unlit)");
  auto text = vtkSmartPointer<vtkTextActor>::New();
  text->SetInput(label.str().c_str());
  text->GetTextProperty()->SetFontSize(std::max(10, size / 28));
  text->GetTextProperty()->SetColor(1.0, 1.0, 0.6);
  text->GetTextProperty()->SetVerticalJustificationToTop();
  text->GetTextProperty()->ShadowOn();
  text->SetPosition(size / 64.0, size - size / 64.0);
  return text;
}

/// One of the four panels of `size` pixels (row 0: lit, top; column 0: original, left),
/// `gap` pixels apart, all seen by `camera`.
vtkSmartPointer<vtkRenderer> Panel(vtkPolyData* renderable, vtkCamera* camera, int row, int column,
                                   int size, int gap)
{
  const double w = 2.0 * size + gap;
  const double x0 = column == 0 ? 0.0 : (size + gap) / w;
  const double y0 = row == 0 ? (size + gap) / w : 0.0;
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(x0, y0, x0 + size / w, y0 + size / w);
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->SetActiveCamera(camera);
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  ConfigureActor(actor, mapper, renderable, row == 0 ? Mode::Lit : Mode::Unlit);
  renderer->AddActor(actor);
  return renderer;
}

} // namespace

bool SavePng(vtkRenderWindow* window, const std::string& path)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grabber;
  grabber->SetInput(window);
  grabber->SetInputBufferTypeToRGB();
  grabber->ReadFrontBufferOff();
  grabber->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grabber->GetOutputPort());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

bool WriteSnapshot(vtkPolyData* original, vtkPolyData* simplified, const std::string& path,
                   int size, const SnapshotOptions& options, std::string* error)
{
  auto fail = [error](const std::string& why)
  {
    if (error)
    {
      *error = why;
    }
    return false;
  };
  if (!original || !simplified)
  {
    return fail("null mesh");
  }
  if (size < 16 || size > 4096)
  {
    return fail("snapshot size must lie in 16..4096");
  }
  std::string why;
  if (!CanRender(&why))
  {
    return fail(why);
  }
  const RenderColors colors = ChooseColors(original, options.ColorArray);
  vtkPolyData* given[2] = { original, simplified };
  vtkSmartPointer<vtkPolyData> meshes[2] = { Renderable(original, colors),
                                             Renderable(simplified, colors) };
  double bounds[6];
  original->GetBounds(bounds);
  vtkNew<vtkCamera> camera;
  FitCamera(camera, bounds, options.ViewDirection);
  if (options.Zoom > 0.0 && options.Zoom != 1.0)
  {
    CloseUp(camera, options);
  }

  HoldDisplay();
  const int gap = std::max(2, size / 128);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(2 * size + gap, 2 * size + gap);
  vtkNew<vtkRenderer> frame; // the white gaps between the panels
  frame->SetBackground(1.0, 1.0, 1.0);
  window->AddRenderer(frame);
  const std::string columnNames[2] = { "original",
                                       options.SimplifiedLabel.empty() ? "simplified"
                                                                       : options.SimplifiedLabel };
  for (int row = 0; row < 2; ++row) // 0: lit (top), 1: unlit (bottom)
  {
    for (int column = 0; column < 2; ++column)
    {
      auto renderer = Panel(meshes[column], camera, row, column, size, gap);
      if (options.Labels)
      {
        renderer->AddActor2D(PanelLabel(columnNames[column], given[column], row == 0, size));
      }
      window->AddRenderer(renderer);
    }
  }
  return SavePng(window, path) || fail("could not write " + path);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> SimplifyWithQuadric(vtkPolyData* input, double reduction,
                                                 bool attributes, const std::string& colorArray)
{
  vtkNew<vtkQuadricDecimation> filter;
  filter->SetInputData(input);
  filter->SetTargetReduction(reduction);
  tools::ConfigureQuadricPeer(filter, attributes);
  filter->Update();
  vtkSmartPointer<vtkPolyData> output = filter->GetOutput();
  if (!attributes)
  {
    TransferNearestColors(input, output, colorArray);
  }
  return output;
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string* error)
{
  std::string description, why;
  vtkSmartPointer<vtkPolyData> mesh = tools::ReadMesh(path, description, why);
  if (mesh && tools::CountTriangles(mesh) == 0)
  {
    why = "no triangles in " + path;
    mesh = nullptr;
  }
  if (!mesh && error)
  {
    *error = why;
  }
  return mesh ? tools::Triangulated(mesh) : nullptr;
}

bool CanRender(std::string* why)
{
  vtkNew<vtkRenderWindow> probe;
  const char* name = probe->GetClassName();
  if (name && std::strstr(name, "XOpenGL") != nullptr)
  {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
    {
      if (why)
      {
        *why = "no X display (DISPLAY is unset): run under `xvfb-run -a` on a headless machine";
      }
      return false;
    }
  }
  return true;
}

} // namespace fidelity
} // namespace colordecimation
