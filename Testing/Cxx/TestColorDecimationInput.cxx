// Tests of vtkColorHalfEdgeDecimation's input handling: the colour array types and
// selection, that the metric really uses colour, and cells other than triangles (each must
// give a defined output, with the warning it announces). Bad input (empty, non-manifold,
// invalid coordinates and ids, bad colour arrays, NaN colours) is tested in Testing/Hostile.
#include "ColorDecimationTestUtilities.h"

#include "ColorDecimationMeshes.h"
#include "vtkColorHalfEdgeDecimation.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkSphereSource.h"
#include "vtkStringArray.h"
#include "vtkStripper.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>

using namespace colordecimation;
using namespace colordecimation::testing;
using meshes::Pattern;

namespace
{

std::set<Tri> Result(const RunResult& r)
{
  return CanonicalSet(GetOriginalTriangles(r.Output));
}

vtkUnsignedCharArray* RGB(vtkPolyData* mesh)
{
  return vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetArray("RGB"));
}

/// Replace the active scalars by `array`.
void SetColors(vtkPolyData* mesh, vtkDataArray* array)
{
  mesh->GetPointData()->RemoveArray("RGB");
  mesh->GetPointData()->SetScalars(array);
}

void SetGeometry(vtkColorHalfEdgeDecimation* f)
{
  f->SetErrorMetricToGeometry();
}

/// Fraction of the output's area on triangles whose corners do not all have one colour.
double MixedColorArea(vtkPolyData* output)
{
  vtkDataArray* colors = output->GetPointData()->GetArray("RGB");
  double mixed = 0, total = 0;
  for (const Tri& t : GetTriangles(output))
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      output->GetPoint(t[k], p[k]);
    }
    const double a[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double b[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    const double n[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                          a[0] * b[1] - a[1] * b[0] };
    const double area = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    total += area;
    bool same = true;
    for (int c = 0; c < 3; ++c)
    {
      same = same && colors->GetComponent(t[0], c) == colors->GetComponent(t[1], c) &&
        colors->GetComponent(t[0], c) == colors->GetComponent(t[2], c);
    }
    mixed += same ? 0 : area;
  }
  return total > 0 ? mixed / total : 0;
}

//------------------------------------------------------------------------------
// Colour arrays.

CD_TEST_CASE(ColorMetricKeepsBorders)
{
  // Sharp colour regions: the colour metric keeps the borders finely sampled, so far less
  // of the surface is covered by triangles that blend two colours than with geometry alone.
  struct Case
  {
    vtkSmartPointer<vtkPolyData> Mesh;
    const char* Name;
  };
  const Case cases[] = { { meshes::Icosphere(5, Pattern::SharpRegions), "Icosphere(5)" },
                         { meshes::Torus(120, 48, Pattern::SharpRegions), "Torus(120,48)" },
                         { meshes::Grid(80, 60, Pattern::SharpRegions), "Grid(80,60)" } };
  for (const Case& c : cases)
  {
    for (double reduction : { 0.9, 0.97 })
    {
      const RunResult color = Decimate(c.Mesh, reduction);
      const RunResult geometry = Decimate(c.Mesh, reduction, SetGeometry);
      const double mixedColor = MixedColorArea(color.Output);
      const double mixedGeometry = MixedColorArea(geometry.Output);
      std::cout << "  " << c.Name << " at " << reduction
                << ": area on two-colour triangles, colour metric " << mixedColor << ", geometry "
                << mixedGeometry << std::endl;
      CD_CHECK(std::abs(color.ActualReduction - geometry.ActualReduction) < 0.01);
      CD_CHECK_MSG(mixedColor < 0.6 * mixedGeometry,
                   c.Name << " at " << reduction << ": " << mixedColor << " vs " << mixedGeometry);
    }
  }
}

CD_TEST_CASE(ColorUnsignedCharRGBA)
{
  auto mesh = meshes::Icosphere(4, Pattern::SharpRegions);
  Decorate(mesh);
  const RunResult rgb = Decimate(mesh, 0.9);
  const RunResult geometry = Decimate(mesh, 0.9, SetGeometry);
  CD_CHECK(Result(rgb) != Result(geometry)); // colour matters on this mesh

  // RGBA with an alpha that varies wildly: alpha is carried but not measured.
  auto rgba = Copy(mesh);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RGBA");
  colors->SetNumberOfComponents(4);
  colors->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    unsigned char c[4];
    RGB(mesh)->GetTypedTuple(i, c);
    c[3] = static_cast<unsigned char>((i * 37) % 256);
    colors->SetTypedTuple(i, c);
  }
  SetColors(rgba, colors);
  const RunResult r = Decimate(rgba, 0.9);
  CD_CHECK(r.Errors == 0 && r.Warnings == 0);
  CD_CHECK(Result(r) == Result(rgb));
  // Alpha (with every other point array) is a bit-exact copy.
  CD_CHECK(CheckPointDataCopied(rgba, r.Output) == 0);
  CD_CHECK(vtkUnsignedCharArray::SafeDownCast(r.Output->GetPointData()->GetScalars()) &&
           r.Output->GetPointData()->GetScalars()->GetNumberOfComponents() == 4);
}

CD_TEST_CASE(ColorFloatAndDouble)
{
  auto mesh = meshes::Torus(80, 30, Pattern::SharpRegions);
  const RunResult reference = Decimate(mesh, 0.9);
  const RunResult geometry = Decimate(mesh, 0.9, SetGeometry);
  CD_CHECK(Result(reference) != Result(geometry));

  // The same colours as float and double RGB in [0,1]: the same decimation.
  auto asFloat = Copy(mesh);
  auto asDouble = Copy(mesh);
  vtkNew<vtkFloatArray> f;
  vtkNew<vtkDoubleArray> d;
  f->SetName("Colour");
  d->SetName("Colour");
  f->SetNumberOfComponents(3);
  d->SetNumberOfComponents(3);
  f->SetNumberOfTuples(mesh->GetNumberOfPoints());
  d->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const unsigned char c = RGB(mesh)->GetValue(3 * i + k);
      f->SetValue(3 * i + k, c / 255.0f);
      d->SetValue(3 * i + k, c / 255.0);
    }
  }
  SetColors(asFloat, f);
  SetColors(asDouble, d);
  const RunResult rf = Decimate(asFloat, 0.9);
  const RunResult rd = Decimate(asDouble, 0.9);
  CD_CHECK(rf.Errors == 0 && rf.Warnings == 0 && rd.Errors == 0 && rd.Warnings == 0);
  CD_CHECK(Result(rf) == Result(reference));
  CD_CHECK(Result(rd) == Result(reference));
  CD_CHECK(CheckPointDataCopied(asFloat, rf.Output) == 0);
  CD_CHECK(CheckPointDataCopied(asDouble, rd.Output) == 0);
}

// Bytes are /255 in any memory layout: a structure-of-arrays copy of the RGB array (whose
// values span 30..240 only, so a mapping by the range would stretch them) gives the same
// decimation as the array itself.
CD_TEST_CASE(ColorUnsignedCharLayouts)
{
  auto mesh = meshes::Torus(80, 30, Pattern::SharpRegions);
  const RunResult reference = Decimate(mesh, 0.9);
  CD_CHECK(RGB(mesh)->GetRange(0)[0] > 0 && RGB(mesh)->GetRange(0)[1] < 255);
  auto split = Copy(mesh);
  vtkNew<vtkSOADataArrayTemplate<unsigned char>> soa;
  soa->SetName("Colour");
  soa->SetNumberOfComponents(3);
  soa->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < 3 * mesh->GetNumberOfPoints(); ++i)
  {
    soa->SetValue(i, RGB(mesh)->GetValue(i));
  }
  SetColors(split, soa);
  const RunResult r = Decimate(split, 0.9);
  CD_CHECK(r.Errors == 0 && r.Warnings == 0);
  CD_CHECK(Result(r) == Result(reference));
  CD_CHECK(CheckPointDataCopied(split, r.Output) == 0);
}

// Double colours whose range is wider than a double holds (-1e308 .. 1e308) cannot be mapped
// to [0, 1]: they are taken as one colour (0), never as NaN, so the decimation is that of an
// all-zero colour array, with every point array carried.
CD_TEST_CASE(ColorRangeOverflow)
{
  // Colours spanning -1e308..1e308 (a range wider than a double holds): (2 c - 1) 1e308 for
  // colours c quantised to eighths, black and white present, map back to c, as the same
  // colours in [0, 1] give: the same decimation (before: every colour 0, the geometry's).
  auto mesh = meshes::Icosphere(4, Pattern::SmoothGradient);
  const vtkIdType n = mesh->GetNumberOfPoints();
  auto unit = Copy(mesh);
  auto huge = Copy(mesh);
  vtkNew<vtkDoubleArray> u, d;
  u->SetName("Unit");
  d->SetName("Huge");
  for (vtkDoubleArray* a : { u.Get(), d.Get() })
  {
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(n);
  }
  for (vtkIdType i = 0; i < 3 * n; ++i)
  {
    int q = static_cast<int>(std::lround(RGB(mesh)->GetValue(i) / 255.0 * 8));
    q = i < 3 ? 0 : (i < 6 ? 8 : q);
    u->SetValue(i, q / 8.0);
    d->SetValue(i, (q / 4.0 - 1.0) * 1e308);
  }
  SetColors(unit, u);
  SetColors(huge, d);
  CD_CHECK(!std::isfinite(d->GetRange(0)[1] - d->GetRange(0)[0]));
  const RunResult r = Decimate(huge, 0.9);
  CD_CHECK(r.Errors == 0 && r.Warnings == 0);
  CD_CHECK(std::abs(r.ActualReduction - 0.9) < 0.01);
  const RunResult ru = Decimate(unit, 0.9);
  CD_CHECK(Result(ru) != Result(Decimate(mesh, 0.9, SetGeometry)));
  CD_CHECK(Result(r) == Result(ru));
  CheckDecimatedMesh(huge, r.Output, Expectation{ true, 2, 0, nullptr, false }, "huge range");
  CD_CHECK(CheckPointDataCopied(huge, r.Output) == 0);
  // Colours written back (the colour quadric's placement moves vertices) stay finite, in range,
  // up to the widest range a double array can hold (+-DBL_MAX: a subnormal scale).
  for (const double top : { 1e308, std::numeric_limits<double>::max() })
  {
    for (vtkIdType i = 0; i < 3 * n; ++i)
    {
      d->SetValue(i, (u->GetValue(i) * 2.0 - 1.0) * top);
    }
    d->Modified();
    const RunResult moved = Decimate(huge, 0.9,
                                     [](vtkColorHalfEdgeDecimation* filter)
                                     {
                                       filter->SetErrorMetricToColorQuadric();
                                       filter->OptimalPlacementOn();
                                     });
    vtkDataArray* out = moved.Output->GetPointData()->GetArray("Huge");
    CD_CHECK(moved.Errors == 0 && out && out->GetNumberOfTuples() > 0);
    CD_CHECK(std::abs(moved.ActualReduction - 0.9) < 0.01);
    int wrong = 0;
    for (vtkIdType i = 0; out && i < 3 * out->GetNumberOfTuples(); ++i)
    {
      const double v = out->GetComponent(i / 3, static_cast<int>(i % 3));
      wrong += std::isfinite(v) && v >= -top && v <= top ? 0 : 1;
    }
    CD_CHECK_MSG(wrong == 0, wrong << " values written out of [-" << top << ", " << top << "]");
  }
}

CD_TEST_CASE(ColorFloatRange)
{
  // Colours quantised to multiples of 1/8 (exact in float), with black and white present.
  // As float in [0,1] they are used as they are; multiplied by 1000 (range 0..1000) they
  // must be scaled back by the range to the same values: the same decimation.
  auto mesh = meshes::Icosphere(4, Pattern::SmoothGradient);
  const vtkIdType n = mesh->GetNumberOfPoints();
  auto unit = Copy(mesh);
  auto wide = Copy(mesh);
  vtkNew<vtkFloatArray> u;
  vtkNew<vtkFloatArray> w;
  u->SetNumberOfComponents(3);
  w->SetNumberOfComponents(3);
  u->SetNumberOfTuples(n);
  w->SetNumberOfTuples(n);
  u->SetName("Unit");
  w->SetName("Wide");
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      int q = static_cast<int>(std::lround(RGB(mesh)->GetValue(3 * i + k) / 255.0 * 8));
      q = i == 0 ? 0 : (i == 1 ? 8 : q);
      u->SetValue(3 * i + k, q / 8.0f);
      w->SetValue(3 * i + k, 125.0f * q);
    }
  }
  SetColors(unit, u);
  SetColors(wide, w);
  CD_CHECK(w->GetRange(0)[0] == 0 && w->GetRange(0)[1] == 1000);
  const RunResult ru = Decimate(unit, 0.9);
  const RunResult rw = Decimate(wide, 0.9);
  const RunResult geometry = Decimate(mesh, 0.9, SetGeometry);
  CD_CHECK(rw.Errors == 0 && rw.Warnings == 0);
  CD_CHECK(Result(ru) != Result(geometry));
  CD_CHECK(Result(rw) == Result(ru));
  CD_CHECK(CheckPointDataCopied(wide, rw.Output) == 0);

  // A range that does not start at 0: 200 + 100 q (q in 0..8) scales to q / 8 as well.
  auto shifted = Copy(unit);
  vtkNew<vtkDoubleArray> s;
  s->SetNumberOfComponents(3);
  s->SetNumberOfTuples(n);
  s->SetName("Shifted");
  for (vtkIdType i = 0; i < 3 * n; ++i)
  {
    s->SetValue(i, 200.0 + 800.0 * u->GetValue(i));
  }
  SetColors(shifted, s);
  const RunResult rs = Decimate(shifted, 0.9);
  CD_CHECK(Result(rs) == Result(ru));
}

/**
 * The colours are converted on the filter's threads, by ranges of points: on a mesh large
 * enough for two ranges, one thread and two give the same decimation and the same NaN count,
 * for unsigned char, for a float and a one-component double range whose ends lie in the last
 * range only (a range taken from the first alone would map every colour differently), and
 * for a structure-of-arrays copy of the float one (converted on one thread: the same again).
 */
CD_TEST_CASE(ColorConversionThreads)
{
  auto mesh = meshes::Grid(420, 400, Pattern::SharpRegions);
  const vtkIdType n = mesh->GetNumberOfPoints();
  CD_CHECK(n >= 2 * 65536);
  vtkNew<vtkFloatArray> wide;
  wide->SetNumberOfComponents(3);
  wide->SetNumberOfTuples(n);
  wide->SetName("Wide");
  vtkNew<vtkDoubleArray> grey;
  grey->SetNumberOfTuples(n);
  grey->SetName("Grey");
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      wide->SetValue(3 * i + k, 100.0f + 10.0f * RGB(mesh)->GetValue(3 * i + k));
    }
    grey->SetValue(i, 20.0 + 2.0 * RGB(mesh)->GetValue(3 * i));
  }
  wide->SetValue(3 * (n - 1), -4000.0f); // the ends of the ranges, in the last points
  wide->SetValue(3 * (n - 2) + 1, 9000.0f);
  grey->SetValue(n - 1, -300.0);
  grey->SetValue(n - 2, 900.0);
  wide->SetValue(3 * (n / 3), std::numeric_limits<float>::quiet_NaN()); // one NaN a range
  wide->SetValue(3 * (n - 3) + 2, std::numeric_limits<float>::quiet_NaN());
  vtkNew<vtkSOADataArrayTemplate<float>> split;
  split->DeepCopy(wide);
  split->SetName("Split");
  CD_CHECK(!split->HasStandardMemoryLayout() && split->GetValue(3 * (n - 1)) == -4000.0f);
  vtkDataArray* arrays[] = { RGB(mesh), wide, grey, split };
  std::set<Tri> wideResult;
  for (vtkDataArray* array : arrays)
  {
    auto input = Copy(mesh);
    SetColors(input, array);
    const auto threads = [](int t)
    { return [t](vtkColorHalfEdgeDecimation* f) { f->SetNumberOfThreads(t); }; };
    const RunResult one = Decimate(input, 0.9, threads(1));
    const RunResult two = Decimate(input, 0.9, threads(2));
    std::cout << "  " << array->GetName() << ": " << two.Output->GetNumberOfPolys()
              << " triangles, " << two.Warnings << " warning(s)" << std::endl;
    CD_CHECK(one.Errors == 0 && two.Errors == 0);
    CD_CHECK(two.Filter->GetNumberOfThreadsUsed() == 2);
    CD_CHECK(Result(one) == Result(two));
    CD_CHECK(one.Warnings == two.Warnings);
    const bool nan = array == wide.Get() || array == split.Get();
    CD_CHECK(
      !nan ||
      (one.HasWarning("2 colour tuples hold NaN") && two.HasWarning("2 colour tuples hold NaN")));
    if (array == wide.Get())
    {
      wideResult = Result(two);
    }
    CD_CHECK(array != split.Get() || Result(two) == wideResult);
  }
}

CD_TEST_CASE(ColorOneComponent)
{
  auto mesh = meshes::Icosphere(4, Pattern::SharpRegions);
  const vtkIdType n = mesh->GetNumberOfPoints();
  // A grey value g as one unsigned char component is measured as the RGB colour (g, g, g).
  auto grey = Copy(mesh);
  auto greyRGB = Copy(mesh);
  auto greyFloat = Copy(mesh);
  vtkNew<vtkUnsignedCharArray> g1;
  vtkNew<vtkUnsignedCharArray> g3;
  vtkNew<vtkFloatArray> gf;
  g1->SetName("Grey");
  g3->SetName("Grey3");
  gf->SetName("GreyFloat");
  g3->SetNumberOfComponents(3);
  g1->SetNumberOfTuples(n);
  g3->SetNumberOfTuples(n);
  gf->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    unsigned char c[3];
    RGB(mesh)->GetTypedTuple(i, c);
    const auto g = static_cast<unsigned char>((c[0] + c[1] + c[2]) / 3);
    g1->SetValue(i, g);
    const unsigned char ggg[3] = { g, g, g };
    g3->SetTypedTuple(i, ggg);
    gf->SetValue(i, g / 255.0f);
  }
  SetColors(grey, g1);
  SetColors(greyRGB, g3);
  SetColors(greyFloat, gf);
  const RunResult r1 = Decimate(grey, 0.9);
  const RunResult r3 = Decimate(greyRGB, 0.9);
  const RunResult rf = Decimate(greyFloat, 0.9);
  const RunResult geometry = Decimate(mesh, 0.9, SetGeometry);
  CD_CHECK(r1.Errors == 0 && r1.Warnings == 0);
  CD_CHECK(Result(r1) == Result(r3));
  CD_CHECK(Result(rf) == Result(r3));
  CD_CHECK(Result(r1) != Result(geometry));
  CD_CHECK(CheckPointDataCopied(grey, r1.Output) == 0);
}

CD_TEST_CASE(ColorArrayByName)
{
  // The active scalars are one flat colour; the sharp colours are in "Paint", a point array
  // that is not the scalars, selected by name.
  auto mesh = meshes::Icosphere(4, Pattern::Constant);
  auto painted = meshes::Icosphere(4, Pattern::SharpRegions);
  vtkNew<vtkUnsignedCharArray> paint;
  paint->DeepCopy(RGB(painted));
  paint->SetName("Paint");
  mesh->GetPointData()->AddArray(paint);
  CD_CHECK(mesh->GetPointData()->GetScalars() == RGB(mesh));

  const RunResult byName =
    Decimate(mesh, 0.9,
             [](vtkColorHalfEdgeDecimation* f) {
               f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Paint");
             });
  const RunResult byScalars = Decimate(mesh, 0.9);
  const RunResult reference = Decimate(painted, 0.9);
  CD_CHECK(byName.Errors == 0 && byName.Warnings == 0);
  CD_CHECK(Result(byName) == Result(reference));
  CD_CHECK(Result(byScalars) != Result(reference));
  // Both arrays are carried through, and the active scalars stay the input's.
  CD_CHECK(CheckPointDataCopied(mesh, byName.Output) == 0);

  // A name that does not exist: no colour (a warning, since one was asked for), geometry alone.
  const RunResult missing =
    Decimate(mesh, 0.9,
             [](vtkColorHalfEdgeDecimation* f) {
               f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Nope");
             });
  CD_CHECK(missing.Warnings == 1 && missing.Errors == 0);
  CD_CHECK(missing.WarningText().find("No colour array named 'Nope'") != std::string::npos);
  CD_CHECK(std::abs(missing.ActualReduction - 0.9) <= 0.01);
  // A name that holds text, not numbers: a warning that says so, geometry alone.
  auto labelled = Copy(mesh);
  vtkNew<vtkStringArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfValues(labelled->GetNumberOfPoints());
  labelled->GetPointData()->AddArray(labels);
  const RunResult textual = Decimate(
    labelled, 0.9,
    [](vtkColorHalfEdgeDecimation* f)
    { f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Labels"); });
  CD_CHECK(textual.Warnings == 1 && textual.Errors == 0);
  CD_CHECK(textual.HasWarning("The colour array 'Labels' is not numeric"));
  CD_CHECK(Result(textual) == Result(missing));

  // An empty name (ParaView's Colors when the input has no point scalars) selects none:
  // geometry alone, quietly on a mesh without point scalars, with a warning on one that has
  // them (a ParaView state saved before the input had colours).
  const auto unnamed = [](vtkColorHalfEdgeDecimation* f)
  { f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, ""); };
  auto plain = Copy(mesh);
  plain->GetPointData()->SetScalars(nullptr);
  const RunResult quiet = Decimate(plain, 0.9, unnamed);
  CD_CHECK(quiet.Warnings == 0 && quiet.Errors == 0);
  CD_CHECK(Result(quiet) == Result(missing));
  const RunResult coloured = Decimate(mesh, 0.9, unnamed);
  CD_CHECK(coloured.Warnings == 1 && coloured.Errors == 0);
  CD_CHECK(coloured.HasWarning("No colour array selected (an empty name), though the input "
                               "has point scalars 'RGB'"));
  CD_CHECK(Result(coloured) == Result(missing));
}

//------------------------------------------------------------------------------
// Cells other than triangles.

CD_TEST_CASE(Quads)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(60, 40);
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  plane->Update();
  auto quads = Copy(plane->GetOutput());
  meshes::ApplyPattern(quads, Pattern::SharpRegions);
  Decorate(quads);
  CD_CHECK(quads->GetNumberOfPolys() == 2400);

  // Quads and strips are legitimate input: triangulated without a message.
  RunResult r = Decimate(quads, 0.0);
  CD_CHECK(r.Warnings == 0 && r.Errors == 0);
  CD_CHECK(r.Output->GetNumberOfPolys() == 4800);
  CheckDecimatedMesh(quads, r.Output, Expectation{ false, 1, 1, UpNormal, true }, "quads, 0");
  // Each quad gives two triangles that carry its cell data.
  auto* source = vtkIdTypeArray::SafeDownCast(r.Output->GetCellData()->GetArray("SourceId"));
  std::vector<int> uses(2400, 0);
  for (vtkIdType t = 0; source && t < source->GetNumberOfValues(); ++t)
  {
    uses[source->GetValue(t)]++;
  }
  CD_CHECK(std::all_of(uses.begin(), uses.end(), [](int u) { return u == 2; }));

  r = Decimate(quads, 0.9);
  CD_CHECK(r.Warnings == 0 && r.Errors == 0);
  std::cout << "  quads: " << r.Output->GetNumberOfPolys() << " triangles, actual "
            << r.ActualReduction << std::endl;
  CD_CHECK_NEAR(r.ActualReduction, 1.0 - r.Output->GetNumberOfPolys() / 4800.0, 1e-12);
  CD_CHECK(std::abs(r.ActualReduction - 0.9) <= 0.01);
  CheckDecimatedMesh(quads, r.Output, Expectation{ false, 1, 1, UpNormal, true }, "quads, 0.9");
}

// Ghost arrays that do not hold one value a cell or a point (here one short, one too long)
// are ignored with a warning, never read past their end: every cell is decimated.
CD_TEST_CASE(GhostArraysOfTheWrongSize)
{
  auto mesh = meshes::Icosphere(3, Pattern::SharpRegions);
  vtkNew<vtkUnsignedCharArray> cellGhosts;
  cellGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
  cellGhosts->SetNumberOfValues(mesh->GetNumberOfCells() / 2);
  cellGhosts->FillValue(vtkDataSetAttributes::DUPLICATECELL);
  mesh->GetCellData()->AddArray(cellGhosts);
  vtkNew<vtkUnsignedCharArray> pointGhosts;
  pointGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
  pointGhosts->SetNumberOfValues(mesh->GetNumberOfPoints() + 5);
  pointGhosts->FillValue(vtkDataSetAttributes::DUPLICATEPOINT);
  mesh->GetPointData()->AddArray(pointGhosts);
  for (double reduction : { 0.0, 0.5 })
  {
    const RunResult r = Decimate(mesh, reduction);
    CD_CHECK(r.Errors == 0 && r.Warnings >= 1);
    CD_CHECK_MSG(r.WarningText().find("ghost array") != std::string::npos, r.WarningText());
    // No cell taken for a ghost, no point fixed: the whole mesh, then half of it.
    const double expected =
      reduction == 0.0 ? mesh->GetNumberOfCells() : std::floor(0.5 * mesh->GetNumberOfCells());
    CD_CHECK_MSG(std::abs(r.Output->GetNumberOfPolys() - expected) <= 0.01 * expected,
                 r.Output->GetNumberOfPolys() << " triangles, expected " << expected);
  }
}

CD_TEST_CASE(TriangleStrips)
{
  auto mesh = meshes::Icosphere(4, Pattern::SharpRegions);
  vtkNew<vtkStripper> stripper;
  stripper->SetInputData(mesh);
  stripper->Update();
  auto strips = Copy(stripper->GetOutput());
  CD_CHECK(strips->GetNumberOfStrips() > 0);
  CD_CHECK(strips->GetNumberOfPoints() == mesh->GetNumberOfPoints());

  // At 0 the strips come back as the very triangles they were made of, with their
  // orientation.
  RunResult r = Decimate(strips, 0.0);
  CD_CHECK(r.Warnings == 0 && r.Errors == 0);
  CD_CHECK(Result(r) == CanonicalSet(GetTriangles(mesh)));

  r = Decimate(strips, 0.9);
  CD_CHECK(r.Warnings == 0 && r.Errors == 0);
  CD_CHECK(std::abs(r.ActualReduction - 0.9) <= 0.01);
  CD_CHECK(r.Output->GetNumberOfStrips() == 0);
  CheckDecimatedMesh(strips, r.Output, Expectation{ true, 2, 0, nullptr, false }, "strips");

  // Two ribbons of two triangles joined into one strip by repeated points (0 1 2 3 3 4 4 5 6
  // 7), as strip writers do: the four zero-area joining triangles are no input error.
  vtkNew<vtkPoints> points;
  for (const double x : { 0.0, 1.0, 3.0, 4.0 })
  {
    points->InsertNextPoint(x, 0, 0);
    points->InsertNextPoint(x, 1, 0);
  }
  vtkNew<vtkCellArray> joined;
  const vtkIdType ids[10] = { 0, 1, 2, 3, 3, 4, 4, 5, 6, 7 };
  joined->InsertNextCell(10, ids);
  vtkNew<vtkPolyData> ribbons;
  ribbons->SetPoints(points);
  ribbons->SetStrips(joined);
  r = Decimate(ribbons, 0.0);
  CD_CHECK(r.Warnings == 0 && r.Errors == 0);
  CD_CHECK(r.Output->GetNumberOfPolys() == 4);

  // A joining triangle with an id out of range (0 1 2 3 3 8, eight points) is an input error.
  vtkNew<vtkCellArray> broken;
  const vtkIdType bad[6] = { 0, 1, 2, 3, 3, 8 };
  broken->InsertNextCell(6, bad);
  ribbons->SetStrips(broken);
  r = RunFilter(ribbons, 0.0);
  CD_CHECK_MSG(r.HasError("point ids outside [0, 8)") && r.Output->GetNumberOfPoints() == 0,
               r.ErrorText());
}

CD_TEST_CASE(VerticesAndLines)
{
  auto mesh = meshes::Icosphere(4, Pattern::SharpRegions);
  vtkNew<vtkCellArray> verts;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); i += 10)
  {
    verts->InsertNextCell(1, &i);
  }
  vtkNew<vtkCellArray> lines;
  std::vector<vtkIdType> polyline;
  for (vtkIdType i = 0; i < 20; ++i)
  {
    polyline.push_back(3 * i);
  }
  lines->InsertNextCell(static_cast<vtkIdType>(polyline.size()), polyline.data());
  const vtkIdType segment[2] = { 5, 6 };
  lines->InsertNextCell(2, segment);
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  Decorate(mesh); // cell data over vertices, lines and triangles, in VTK's cell order
  const RunResult r = Decimate(mesh, 0.9);
  CD_CHECK_MSG(r.Warnings == 1 && r.Errors == 0, r.WarningText() << r.ErrorText());
  CD_CHECK(r.Output->GetNumberOfVerts() == 0 && r.Output->GetNumberOfLines() == 0);
  CD_CHECK(std::abs(r.ActualReduction - 0.9) <= 0.01);
  // The cell data of each triangle is its source triangle's (cell ids after the vertices
  // and lines).
  CheckDecimatedMesh(mesh, r.Output, Expectation{ true, 2, 0, nullptr, true }, "verts+lines");
}

// The generated meshes that the tests, the benchmarks and the CLI's demo read.

namespace
{
// Points (as doubles, whatever their type) and triangles of two meshes, bit for bit; not their
// arrays (vtkSphereSource gives normals, the generated spheres colours).
bool SamePointsAndTriangles(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
      a->GetNumberOfPolys() != b->GetNumberOfPolys())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (std::memcmp(p, q, sizeof(p)) != 0)
    {
      return false;
    }
  }
  vtkNew<vtkIdList> ca, cb;
  for (vtkIdType c = 0; c < a->GetNumberOfPolys(); ++c)
  {
    a->GetCellPoints(c, ca);
    b->GetCellPoints(c, cb);
    if (ca->GetNumberOfIds() != 3 || cb->GetNumberOfIds() != 3 ||
        !std::equal(ca->begin(), ca->end(), cb->begin()))
    {
      return false;
    }
  }
  return true;
}
} // namespace

// The demo's and the benchmark's UV spheres are made on all cores, as vtkSphereSource makes
// them: the same points bit for bit, the same triangles in the same order, also where it repeats
// the first meridian (39, 78: 360 / r * r < 360), with 32-bit and with 64-bit cell ids.
CD_TEST_CASE(GeneratedUVSphere)
{
  for (int r : { 4, 5, 8, 39, 78, 100, 161, 700 })
  {
    vtkNew<vtkSphereSource> source;
    source->SetThetaResolution(r);
    source->SetPhiResolution(r);
    source->SetRadius(1.0);
    source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    source->Update();
    auto generated = meshes::UVSphere(r, Pattern::SharpRegions);
    CD_CHECK(SamePointsAndTriangles(generated, source->GetOutput()));
    CD_CHECK(!generated->GetPolys()->IsStorage64Bit());
    auto wide = meshes::UVSphere(r, Pattern::SharpRegions, false); // the ids of huge spheres
    CD_CHECK(SamePointsAndTriangles(wide, source->GetOutput()) &&
             wide->GetPolys()->IsStorage64Bit());
    CD_CHECK(generated->GetNumberOfPolys() == 2 * r * (r - 2));
    auto* rgb = RGB(generated);
    CD_CHECK(rgb && rgb->GetNumberOfTuples() == generated->GetNumberOfPoints());
    for (vtkIdType i = 0; rgb && i < generated->GetNumberOfPoints(); i += 97)
    {
      double p[3];
      generated->GetPoint(i, p);
      unsigned char expected[3];
      meshes::PatternColor(Pattern::SharpRegions, p, expected);
      CD_CHECK(std::equal(expected, expected + 3, rgb->GetPointer(3 * i)));
    }
  }
}

// The icosphere numbers each new point where the triangles, in order, first reach its edge:
// the same mesh as subdividing with a map of the edges (written out here as the reference).
CD_TEST_CASE(GeneratedIcosphere)
{
  auto coarse = meshes::Icosphere(0, Pattern::Constant);
  CD_CHECK(coarse->GetNumberOfPoints() == 12 && coarse->GetNumberOfPolys() == 20);
  std::vector<double> xyz(3 * 12);
  std::vector<vtkIdType> tris;
  for (vtkIdType i = 0; i < 12; ++i)
  {
    coarse->GetPoint(i, &xyz[3 * i]);
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < 20; ++c)
  {
    coarse->GetCellPoints(c, ids);
    tris.insert(tris.end(), ids->begin(), ids->end());
  }
  for (int level = 1; level <= 5; ++level)
  {
    std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> midpoints;
    auto midpoint = [&](vtkIdType a, vtkIdType b)
    {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      const vtkIdType m = static_cast<vtkIdType>(xyz.size() / 3);
      double p[3];
      for (int k = 0; k < 3; ++k)
      {
        p[k] = 0.5 * (xyz[3 * a + k] + xyz[3 * b + k]);
      }
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      xyz.insert(xyz.end(), { p[0] / r, p[1] / r, p[2] / r });
      return midpoints[key] = m;
    };
    std::vector<vtkIdType> next;
    for (size_t f = 0; f < tris.size(); f += 3)
    {
      const vtkIdType a = tris[f], b = tris[f + 1], c = tris[f + 2];
      const vtkIdType ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), { a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca });
    }
    tris.swap(next);
    auto reference = meshes::FromTriangles(xyz, tris);
    auto generated = meshes::Icosphere(level, Pattern::Constant);
    CD_CHECK(SamePointsAndTriangles(generated, reference));
    CD_CHECK(generated->GetNumberOfPolys() == 20 * (1 << (2 * level)));
  }
}

} // namespace

int main(int argc, char* argv[])
{
  return RunTestCases(argc, argv);
}
