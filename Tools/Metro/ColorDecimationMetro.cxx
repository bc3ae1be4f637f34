#include "ColorDecimationMetro.h"

#include "JsonOutput.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
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

/// The triangles of a mesh alone (polygons and strips triangulated; vertices and lines out).
vtkSmartPointer<vtkPolyData> Triangles(vtkPolyData* mesh)
{
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(mesh->GetPoints());
  surface->SetPolys(mesh->GetPolys());
  surface->SetStrips(mesh->GetStrips());
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(surface);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  return triangulate->GetOutput();
}

struct Sums
{
  double Sum = 0;
  double SumSquares = 0;
  double Max = 0;
};

/// Distances from `points` (3 per point) to the surface of `locator`, summed.
class DistanceFunctor
{
public:
  DistanceFunctor(const std::vector<double>& points, vtkStaticCellLocator* locator)
    : Points(points)
    , Locator(locator)
  {
  }
  void Initialize() {}
  void operator()(vtkIdType begin, vtkIdType end)
  {
    Sums& sums = this->Local.Local();
    vtkGenericCell* cell = this->Cell.Local();
    for (vtkIdType i = begin; i < end; ++i)
    {
      double closest[3], dist2 = 0;
      vtkIdType cellId = -1;
      int subId = 0;
      this->Locator->FindClosestPoint(&this->Points[3 * i], closest, cell, cellId, subId, dist2);
      const double d = cellId >= 0 ? std::sqrt(dist2) : 0.0;
      sums.Sum += d;
      sums.SumSquares += d * d;
      sums.Max = std::max(sums.Max, d);
    }
  }
  void Reduce()
  {
    for (const Sums& s : this->Local)
    {
      this->Total.Sum += s.Sum;
      this->Total.SumSquares += s.SumSquares;
      this->Total.Max = std::max(this->Total.Max, s.Max);
    }
  }

  Sums Total;

private:
  const std::vector<double>& Points;
  vtkStaticCellLocator* Locator;
  vtkSMPThreadLocal<Sums> Local;
  vtkSMPThreadLocalObject<vtkGenericCell> Cell;
};

Sums Measure(const std::vector<double>& points, vtkStaticCellLocator* locator)
{
  DistanceFunctor functor(points, locator);
  vtkSMPTools::For(0, static_cast<vtkIdType>(points.size() / 3), functor);
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

} // namespace

OneSided SampleDistance(vtkPolyData* fromMesh, vtkPolyData* toMesh, const Options& options)
{
  OneSided result;
  vtkSmartPointer<vtkPolyData> from = Triangles(fromMesh);
  vtkSmartPointer<vtkPolyData> to = Triangles(toMesh);
  if (from->GetNumberOfPolys() == 0 || to->GetNumberOfPolys() == 0)
  {
    return result;
  }

  // The cumulative areas of the triangles of `from`.
  std::vector<double> cumulative;
  std::vector<vtkIdType> corners;
  cumulative.reserve(from->GetNumberOfPolys());
  corners.reserve(3 * from->GetNumberOfPolys());
  vtkPoints* points = from->GetPoints();
  double area = 0;
  auto it = vtk::TakeSmartPointer(from->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    if (npts != 3)
    {
      continue;
    }
    double a[3], b[3], c[3];
    points->GetPoint(pts[0], a);
    points->GetPoint(pts[1], b);
    points->GetPoint(pts[2], c);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                          u[0] * v[1] - u[1] * v[0] };
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    cumulative.push_back(area);
    corners.insert(corners.end(), { pts[0], pts[1], pts[2] });
  }
  result.Area = area;
  if (!(area > 0))
  {
    return result;
  }

  // Area-uniform samples.
  const long long n = std::max<long long>(options.Samples, 1);
  std::vector<double> samples(3 * static_cast<size_t>(n));
  std::mt19937_64 random(options.Seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (long long s = 0; s < n; ++s)
  {
    const double target = uniform(random) * area;
    const size_t t = std::min<size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin(),
      cumulative.size() - 1);
    double a[3], b[3], c[3];
    points->GetPoint(corners[3 * t], a);
    points->GetPoint(corners[3 * t + 1], b);
    points->GetPoint(corners[3 * t + 2], c);
    const double r1 = std::sqrt(uniform(random));
    const double r2 = uniform(random);
    const double wa = 1.0 - r1, wb = r1 * (1.0 - r2), wc = r1 * r2;
    for (int k = 0; k < 3; ++k)
    {
      samples[3 * s + k] = wa * a[k] + wb * b[k] + wc * c[k];
    }
  }

  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to);
  locator->SetNumberOfCellsPerNode(8);
  locator->BuildLocator();

  const Sums sums = Measure(samples, locator);
  result.Samples = n;
  result.Mean = sums.Sum / n;
  result.Rms = std::sqrt(sums.SumSquares / n);
  result.Max = sums.Max;

  if (options.SampleVertices)
  {
    // Every vertex used by a triangle, for the maximum.
    std::vector<char> used(from->GetNumberOfPoints(), 0);
    for (vtkIdType id : corners)
    {
      used[id] = 1;
    }
    long long count = 0;
    for (char u : used)
    {
      count += u;
    }
    // At most as many vertices as area samples (evenly spread over the ids beyond that).
    const double stride = std::max(1.0, double(count) / double(n));
    std::vector<double> vertices;
    double next = 0;
    long long k = 0;
    for (vtkIdType i = 0; i < from->GetNumberOfPoints(); ++i)
    {
      if (used[i] && k++ >= next)
      {
        next += stride;
        double p[3];
        points->GetPoint(i, p);
        vertices.insert(vertices.end(), { p[0], p[1], p[2] });
      }
    }
    result.Max = std::max(result.Max, Measure(vertices, locator).Max);
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
  return tools::JsonText(json);
}

} // namespace metro
} // namespace colordecimation
