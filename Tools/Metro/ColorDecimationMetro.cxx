#include "ColorDecimationMetro.h"

#include "JsonOutput.h"
#include "MeshIO.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkGenericCell.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace colordecimation
{
namespace metro
{
namespace
{

/// The triangles of a mesh alone (polygons and strips triangulated; vertices and lines out),
/// with the point array `field` when it is given and present.
vtkSmartPointer<vtkPolyData> Triangles(vtkPolyData* mesh, const std::string& field = "")
{
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(mesh->GetPoints());
  surface->SetPolys(mesh->GetPolys());
  surface->SetStrips(mesh->GetStrips());
  if (vtkDataArray* array = field.empty() ? nullptr : mesh->GetPointData()->GetArray(field.c_str()))
  {
    surface->GetPointData()->AddArray(array);
  }
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(surface);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  return triangulate->GetOutput();
}

/// A surface ready to be sampled and searched.
struct Surface
{
  vtkSmartPointer<vtkPolyData> Mesh; ///< triangles only: cell i is triangle i
  std::vector<vtkIdType> Corners;    ///< 3 point ids per triangle
  std::vector<double> Cumulative;    ///< cumulative areas of the triangles
  std::vector<double> Field;         ///< the field at each point (empty: none)
};

/// The triangles of `mesh`, their areas and the one-component point array `field` if any.
Surface MakeSurface(vtkPolyData* mesh, const std::string& field)
{
  Surface surface;
  surface.Mesh = Triangles(mesh, field);
  const vtkIdType triangles = surface.Mesh->GetNumberOfPolys();
  surface.Cumulative.reserve(triangles);
  surface.Corners.reserve(3 * triangles);
  vtkPoints* points = surface.Mesh->GetPoints();
  double area = 0;
  auto it = vtk::TakeSmartPointer(surface.Mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    double a[3], b[3], c[3];
    points->GetPoint(pts[0], a);
    points->GetPoint(pts[1], b);
    points->GetPoint(pts[2], c);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                          u[0] * v[1] - u[1] * v[0] };
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    surface.Cumulative.push_back(area);
    surface.Corners.insert(surface.Corners.end(), { pts[0], pts[1], pts[2] });
  }
  vtkDataArray* values =
    field.empty() ? nullptr : surface.Mesh->GetPointData()->GetArray(field.c_str());
  if (values && values->GetNumberOfComponents() == 1)
  {
    surface.Field.resize(values->GetNumberOfTuples());
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      surface.Field[i] = values->GetComponent(i, 0);
    }
  }
  return surface;
}

/// Barycentric coordinates of `p` (on the triangle a b c, up to rounding) clamped to [0,1]
/// and summing to 1; for a degenerate triangle, those of its corner nearest to `p`.
void Barycentric(const double p[3], const double a[3], const double b[3], const double c[3],
                 double w[3])
{
  double u[3], v[3], d[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    d[k] = p[k] - a[k];
  }
  const double uu = vtkMath::Dot(u, u), uv = vtkMath::Dot(u, v), vv = vtkMath::Dot(v, v);
  const double du = vtkMath::Dot(d, u), dv = vtkMath::Dot(d, v);
  const double det = uu * vv - uv * uv;
  if (!(det > 1e-12 * uu * vv))
  {
    const double d2[3] = { vtkMath::Distance2BetweenPoints(p, a),
                           vtkMath::Distance2BetweenPoints(p, b),
                           vtkMath::Distance2BetweenPoints(p, c) };
    const int nearest = static_cast<int>(std::min_element(d2, d2 + 3) - d2);
    w[0] = w[1] = w[2] = 0;
    w[nearest] = 1;
    return;
  }
  w[1] = std::max(0.0, (vv * du - uv * dv) / det);
  w[2] = std::max(0.0, (uu * dv - uv * du) / det);
  w[0] = std::max(0.0, 1.0 - w[1] - w[2]);
  const double sum = w[0] + w[1] + w[2];
  for (int k = 0; k < 3; ++k)
  {
    w[k] /= sum;
  }
}

/// The field of `surface` interpolated linearly at `p` in its triangle `triangle`.
double FieldAt(const Surface& surface, vtkIdType triangle, const double p[3])
{
  const vtkIdType* ids = &surface.Corners[3 * triangle];
  double corners[3][3], w[3];
  for (int k = 0; k < 3; ++k)
  {
    surface.Mesh->GetPoints()->GetPoint(ids[k], corners[k]);
  }
  Barycentric(p, corners[0], corners[1], corners[2], w);
  return w[0] * surface.Field[ids[0]] + w[1] * surface.Field[ids[1]] + w[2] * surface.Field[ids[2]];
}

/// Points on a surface (3 coordinates each) and the field there (empty: none).
struct Samples
{
  std::vector<double> Points;
  std::vector<double> Field;
};

/// `n` points sampled uniformly by area on `surface` (of non-zero area).
Samples AreaSamples(const Surface& surface, long long n, uint64_t seed)
{
  Samples samples;
  samples.Points.resize(3 * static_cast<size_t>(n));
  samples.Field.resize(surface.Field.empty() ? 0 : static_cast<size_t>(n));
  const double area = surface.Cumulative.back();
  vtkPoints* points = surface.Mesh->GetPoints();
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (long long s = 0; s < n; ++s)
  {
    const double target = uniform(random) * area;
    const size_t t = std::min<size_t>(
      std::upper_bound(surface.Cumulative.begin(), surface.Cumulative.end(), target) -
        surface.Cumulative.begin(),
      surface.Cumulative.size() - 1);
    const vtkIdType* ids = &surface.Corners[3 * t];
    double a[3], b[3], c[3];
    points->GetPoint(ids[0], a);
    points->GetPoint(ids[1], b);
    points->GetPoint(ids[2], c);
    const double r1 = std::sqrt(uniform(random));
    const double r2 = uniform(random);
    const double wa = 1.0 - r1, wb = r1 * (1.0 - r2), wc = r1 * r2;
    for (int k = 0; k < 3; ++k)
    {
      samples.Points[3 * s + k] = wa * a[k] + wb * b[k] + wc * c[k];
    }
    if (!samples.Field.empty())
    {
      samples.Field[s] =
        wa * surface.Field[ids[0]] + wb * surface.Field[ids[1]] + wc * surface.Field[ids[2]];
    }
  }
  return samples;
}

/// The vertices used by a triangle of `surface`, at most `n` of them (evenly spread over the
/// ids beyond that).
Samples VertexSamples(const Surface& surface, long long n)
{
  std::vector<char> used(surface.Mesh->GetNumberOfPoints(), 0);
  for (vtkIdType id : surface.Corners)
  {
    used[id] = 1;
  }
  const long long count = std::count(used.begin(), used.end(), 1);
  const double stride = std::max(1.0, double(count) / double(n));
  Samples samples;
  double next = 0;
  long long k = 0;
  for (vtkIdType i = 0; i < surface.Mesh->GetNumberOfPoints(); ++i)
  {
    if (used[i] && k++ >= next)
    {
      next += stride;
      double p[3];
      surface.Mesh->GetPoints()->GetPoint(i, p);
      samples.Points.insert(samples.Points.end(), { p[0], p[1], p[2] });
      if (!surface.Field.empty())
      {
        samples.Field.push_back(surface.Field[i]);
      }
    }
  }
  return samples;
}

struct Sums
{
  double Sum = 0;
  double SumSquares = 0;
  double Max = 0;
  void Add(double value)
  {
    this->Sum += value;
    this->SumSquares += value * value;
    this->Max = std::max(this->Max, value);
  }
  void Add(const Sums& other)
  {
    this->Sum += other.Sum;
    this->SumSquares += other.SumSquares;
    this->Max = std::max(this->Max, other.Max);
  }
};

/// The sums of the distances and of the field's absolute differences.
struct Totals
{
  Sums Distance;
  Sums Field;
};

/// Distances from the samples to the surface `to` (searched by `locator`), and the absolute
/// differences of the field between the samples and the closest points, summed.
class DistanceFunctor
{
public:
  DistanceFunctor(const Samples& samples, vtkStaticCellLocator* locator, const Surface& to)
    : From(samples)
    , Locator(locator)
    , To(to)
  {
  }
  void Initialize() {}
  void operator()(vtkIdType begin, vtkIdType end)
  {
    Totals& totals = this->Local.Local();
    vtkGenericCell* cell = this->Cell.Local();
    for (vtkIdType i = begin; i < end; ++i)
    {
      const double* x = &this->From.Points[3 * i];
      double closest[3], dist2 = 0;
      vtkIdType cellId = -1;
      int subId = 0;
      this->Locator->FindClosestPoint(x, closest, cell, cellId, subId, dist2);
      totals.Distance.Add(cellId >= 0 ? std::sqrt(dist2) : 0.0);
      if (cellId >= 0 && !this->From.Field.empty())
      {
        totals.Field.Add(std::abs(this->From.Field[i] - FieldAt(this->To, cellId, closest)));
      }
    }
  }
  void Reduce()
  {
    for (const Totals& t : this->Local)
    {
      this->Total.Distance.Add(t.Distance);
      this->Total.Field.Add(t.Field);
    }
  }

  Totals Total;

private:
  const Samples& From;
  vtkStaticCellLocator* Locator;
  const Surface& To;
  vtkSMPThreadLocal<Totals> Local;
  vtkSMPThreadLocalObject<vtkGenericCell> Cell;
};

Totals Measure(const Samples& samples, vtkStaticCellLocator* locator, const Surface& to)
{
  DistanceFunctor functor(samples, locator, to);
  vtkSMPTools::For(0, static_cast<vtkIdType>(samples.Points.size() / 3), functor);
  return functor.Total;
}

tools::Json ToJson(const OneSided& side)
{
  tools::Json json;
  json["samples"] = side.Samples;
  json["area"] = side.Area;
  json["mean"] = side.Mean;
  json["rms"] = side.Rms;
  json["max"] = side.Max;
  return json;
}

tools::Json ToJson(const FieldDifference& difference)
{
  tools::Json json;
  json["mean"] = difference.Mean;
  json["rms"] = difference.Rms;
  json["max"] = difference.Max;
  return json;
}

tools::Json ToJson(const FieldComparison& field)
{
  tools::Json json;
  json["name"] = field.Name;
  json["range"] = { field.Range[0], field.Range[1] };
  json["forward"] = ToJson(field.Forward);
  json["backward"] = ToJson(field.Backward);
  json["mean"] = field.TwoSided.Mean;
  json["rms"] = field.TwoSided.Rms;
  json["max"] = field.TwoSided.Max;
  json["mean_percent"] = field.TwoSidedPercent.Mean;
  json["rms_percent"] = field.TwoSidedPercent.Rms;
  json["max_percent"] = field.TwoSidedPercent.Max;
  return json;
}

/// Why `field` cannot be compared on `mesh` (called `which`), or "" when it can.
std::string FieldError(vtkPolyData* mesh, const std::string& field, const char* which)
{
  vtkDataArray* array = mesh->GetPointData()->GetArray(field.c_str());
  if (!array)
  {
    return "the " + std::string(which) + " mesh has no point array '" + field +
      "' (point arrays: " + tools::PointArrayNames(mesh) + ")";
  }
  if (array->GetNumberOfComponents() != 1)
  {
    return "the point array '" + field + "' of the " + which + " mesh has " +
      std::to_string(array->GetNumberOfComponents()) +
      " components; only one-component fields are compared";
  }
  return "";
}

/// The two-sided field figures and their percentages of the range from both sides'.
void CombineField(FieldComparison& field)
{
  const FieldDifference& f = field.Forward;
  const FieldDifference& b = field.Backward;
  field.TwoSided = { std::max(f.Mean, b.Mean), std::max(f.Rms, b.Rms), std::max(f.Max, b.Max) };
  const double width = field.Range[1] - field.Range[0];
  const double scale = width > 0 ? 100.0 / width : 0.0;
  field.TwoSidedPercent = { field.TwoSided.Mean * scale, field.TwoSided.Rms * scale,
                            field.TwoSided.Max * scale };
}

} // namespace

OneSided SampleDistance(vtkPolyData* fromMesh, vtkPolyData* toMesh, const Options& options)
{
  OneSided result;
  Surface from = MakeSurface(fromMesh, options.Field);
  Surface to = MakeSurface(toMesh, options.Field);
  if (from.Cumulative.empty() || to.Cumulative.empty())
  {
    return result;
  }
  result.Area = from.Cumulative.back();
  if (!(result.Area > 0))
  {
    return result;
  }
  if (from.Field.empty() || to.Field.empty())
  {
    // The field is compared only when both surfaces have it.
    from.Field.clear();
    to.Field.clear();
  }

  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to.Mesh);
  locator->SetNumberOfCellsPerNode(8);
  locator->BuildLocator();

  const long long n = std::max<long long>(options.Samples, 1);
  const Totals sums = Measure(AreaSamples(from, n, options.Seed), locator, to);
  result.Samples = n;
  result.Mean = sums.Distance.Sum / n;
  result.Rms = std::sqrt(sums.Distance.SumSquares / n);
  result.Max = sums.Distance.Max;
  result.Field = { sums.Field.Sum / n, std::sqrt(sums.Field.SumSquares / n), sums.Field.Max };
  if (options.SampleVertices)
  {
    const Totals vertices = Measure(VertexSamples(from, n), locator, to);
    result.Max = std::max(result.Max, vertices.Distance.Max);
    result.Field.Max = std::max(result.Field.Max, vertices.Field.Max);
  }
  return result;
}

Result Compare(vtkPolyData* original, vtkPolyData* simplified, const Options& options)
{
  Result result;
  if (!original || !simplified || original->GetNumberOfPoints() == 0 ||
      simplified->GetNumberOfPoints() == 0)
  {
    result.Error = "empty mesh";
    return result;
  }
  if (!options.Field.empty())
  {
    result.Error = FieldError(original, options.Field, "original");
    result.Error =
      result.Error.empty() ? FieldError(simplified, options.Field, "simplified") : result.Error;
    if (!result.Error.empty())
    {
      return result;
    }
    result.Field.Name = options.Field;
    original->GetPointData()->GetArray(options.Field.c_str())->GetRange(result.Field.Range, 0);
  }
  double bounds[6];
  original->GetBounds(bounds);
  result.Diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
                              (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
                              (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  result.Forward = SampleDistance(original, simplified, options);
  Options other = options;
  other.Seed = options.Seed ^ 0x9e3779b97f4a7c15ULL;
  result.Backward = SampleDistance(simplified, original, other);
  if (result.Forward.Samples == 0 || result.Backward.Samples == 0)
  {
    result.Error = "a mesh has no triangle of non-zero area";
    return result;
  }
  result.OriginalTriangles = Triangles(original)->GetNumberOfPolys();
  result.SimplifiedTriangles = Triangles(simplified)->GetNumberOfPolys();
  result.Mean = std::max(result.Forward.Mean, result.Backward.Mean);
  result.Rms = std::max(result.Forward.Rms, result.Backward.Rms);
  result.Max = std::max(result.Forward.Max, result.Backward.Max);
  const double scale = result.Diagonal > 0 ? 100.0 / result.Diagonal : 0.0;
  result.MeanPercent = result.Mean * scale;
  result.RmsPercent = result.Rms * scale;
  result.MaxPercent = result.Max * scale;
  result.Field.Forward = result.Forward.Field;
  result.Field.Backward = result.Backward.Field;
  CombineField(result.Field);
  result.Ok = true;
  return result;
}

std::string ToJson(const Result& result)
{
  tools::Json json;
  json["ok"] = result.Ok;
  if (!result.Ok)
  {
    json["error"] = result.Error;
    return tools::JsonText(json);
  }
  json["diagonal"] = result.Diagonal;
  json["original_triangles"] = result.OriginalTriangles;
  json["simplified_triangles"] = result.SimplifiedTriangles;
  json["forward"] = ToJson(result.Forward);
  json["backward"] = ToJson(result.Backward);
  json["mean"] = result.Mean;
  json["rms"] = result.Rms;
  json["max"] = result.Max;
  json["mean_percent"] = result.MeanPercent;
  json["rms_percent"] = result.RmsPercent;
  json["max_percent"] = result.MaxPercent;
  if (!result.Field.Name.empty())
  {
    json["field"] = ToJson(result.Field);
  }
  return tools::JsonText(json);
}

} // namespace metro
} // namespace colordecimation
