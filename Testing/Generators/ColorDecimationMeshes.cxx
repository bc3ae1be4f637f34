#include "ColorDecimationMeshes.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace colordecimation
{
namespace meshes
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// vtkSMPTools::For, but on one thread under ThreadSanitizer: VTK's TBB backend is not
/// instrumented, and its work stealing inlined here reads as data races.
template <typename Function>
void ForRanges(vtkIdType begin, vtkIdType end, Function&& function)
{
#if defined(__SANITIZE_THREAD__)
  function(begin, end);
#else
  vtkSMPTools::For(begin, end, function);
#endif
}

unsigned char ToByte(double x)
{
  x = x < 0 ? 0 : (x > 1 ? 1 : x);
  return static_cast<unsigned char>(std::lround(255.0 * x));
}

/// The square sheet in [-1,1]^2 of Grid (waved) or FlatGrid (z = 0).
vtkSmartPointer<vtkPolyData> MakeGrid(int nx, int ny, bool waved, Pattern pattern)
{
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<size_t>(nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      const double x = -1.0 + 2.0 * i / nx, y = -1.0 + 2.0 * j / ny;
      xyz.push_back(x);
      xyz.push_back(y);
      xyz.push_back(waved ? 0.15 * std::sin(2.0 * x) * std::cos(1.5 * y) : 0.0);
    }
  }
  std::vector<vtkIdType> tris;
  tris.reserve(6 * static_cast<size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const vtkIdType a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
      const vtkIdType quad[6] = { a, b, c, a, c, d };
      tris.insert(tris.end(), quad, quad + 6);
    }
  }
  auto mesh = FromTriangles(xyz, tris);
  ApplyPattern(mesh, pattern);
  return mesh;
}
} // namespace

vtkSmartPointer<vtkPolyData> FromTriangles(const std::vector<double>& xyz,
                                           const std::vector<vtkIdType>& triangles)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(xyz.size() / 3));
  std::copy(xyz.begin(), xyz.begin() + 3 * points->GetNumberOfPoints(),
            vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0));
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(triangles.size()));
  std::copy(triangles.begin(), triangles.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> polys;
  polys->SetData(3, connectivity);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

void PatternColor(Pattern pattern, const double p[3], unsigned char rgb[3])
{
  const double x = p[0], y = p[1], z = p[2];
  switch (pattern)
  {
    case Pattern::SharpRegions:
    {
      // Four flat regions split by a wavy border and a plane.
      static const unsigned char palette[4][3] = {
        { 200, 30, 30 }, { 30, 160, 60 }, { 40, 70, 200 }, { 240, 220, 40 }
      };
      const int a = (y + 0.25 * std::sin(4.0 * x) > 0) ? 1 : 0;
      const int b = (z > 0.1) ? 2 : 0;
      for (int k = 0; k < 3; ++k)
      {
        rgb[k] = palette[a + b][k];
      }
      return;
    }
    case Pattern::SmoothGradient:
      rgb[0] = ToByte(0.5 + 0.5 * std::sin(1.5 * x + 0.3));
      rgb[1] = ToByte(0.5 + 0.5 * std::sin(1.7 * y + 2.0));
      rgb[2] = ToByte(0.5 + 0.5 * std::cos(1.3 * z + 0.7 * x));
      return;
    case Pattern::FineDetail:
    {
      // Thin dark strokes on a light ground: stripes along x and a grid of short bars.
      const double stripe = std::abs(std::sin(12.0 * Pi * x));
      const double bars = std::abs(std::sin(9.0 * Pi * y)) * std::abs(std::sin(9.0 * Pi * z));
      const bool ink = stripe < 0.18 || bars > 0.85;
      rgb[0] = ink ? 20 : 235;
      rgb[1] = ink ? 20 : 230;
      rgb[2] = ink ? 60 : 210;
      return;
    }
    case Pattern::Constant:
    default:
      rgb[0] = 180;
      rgb[1] = 140;
      rgb[2] = 100;
      return;
  }
}

void ApplyPattern(vtkPolyData* mesh, Pattern pattern)
{
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(mesh->GetNumberOfPoints());
  vtkDataArray* points = mesh->GetPoints() ? mesh->GetPoints()->GetData() : nullptr;
  unsigned char* rgb = colors->GetPointer(0);
  // Each point's colour depends on its position only: on all cores (demo:sphere80M has 40M).
  ForRanges(0, mesh->GetNumberOfPoints(),
            [points, pattern, rgb](vtkIdType begin, vtkIdType end)
            {
              for (vtkIdType i = begin; i < end; ++i)
              {
                double p[3];
                points->GetTuple(i, p);
                PatternColor(pattern, p, rgb + 3 * i);
              }
            });
  mesh->GetPointData()->SetScalars(colors);
}

vtkSmartPointer<vtkPolyData> Icosphere(int level, Pattern pattern)
{
  level = std::max(level, 0);
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<double> xyz = { -1, t,  0,  1, t, 0,  -1, -t, 0,  1, -t, 0, 0,  -1, t,  0,  1, t,
                              0,  -1, -t, 0, 1, -t, t,  0,  -1, t, 0,  1, -t, 0,  -1, -t, 0, 1 };
  std::vector<vtkIdType> tris = { 0, 11, 5, 0, 5,  1,  0,  1,  7,  0,  7, 10, 0, 10, 11,
                                  1, 5,  9, 5, 11, 4,  11, 10, 2,  10, 7, 6,  7, 1,  8,
                                  3, 9,  4, 3, 4,  2,  3,  2,  6,  3,  6, 8,  3, 8,  9,
                                  4, 9,  5, 2, 4,  11, 6,  2,  10, 8,  6, 7,  9, 8,  1 };
  auto normalize = [&xyz](vtkIdType i)
  {
    double* p = &xyz[3 * i];
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    p[0] /= r;
    p[1] /= r;
    p[2] /= r;
  };
  for (vtkIdType i = 0; i < 12; ++i)
  {
    normalize(i);
  }
  const size_t finalPoints = 10 * (size_t(1) << (2 * level)) + 2;
  xyz.reserve(3 * finalPoints);
  for (int l = 0; l < level; ++l)
  {
    // Each edge's midpoint is kept at the edge's lower vertex (valence at most 6), so the
    // points are numbered in the order the triangles first reach the edges.
    const size_t n = xyz.size() / 3;
    std::vector<vtkIdType> other(6 * n, -1), middle(6 * n);
    auto midpoint = [&](vtkIdType a, vtkIdType b)
    {
      const vtkIdType lo = std::min(a, b), hi = std::max(a, b);
      vtkIdType* slot = &other[6 * lo];
      int k = 0;
      while (k < 5 && slot[k] >= 0 && slot[k] != hi)
      {
        ++k;
      }
      if (slot[k] == hi)
      {
        return middle[6 * lo + k];
      }
      const vtkIdType m = static_cast<vtkIdType>(xyz.size() / 3);
      for (int c = 0; c < 3; ++c)
      {
        xyz.push_back(0.5 * (xyz[3 * a + c] + xyz[3 * b + c]));
      }
      normalize(m);
      slot[k] = hi;
      middle[6 * lo + k] = m;
      return m;
    };
    std::vector<vtkIdType> next;
    next.reserve(4 * tris.size());
    for (size_t f = 0; f < tris.size(); f += 3)
    {
      const vtkIdType a = tris[f], b = tris[f + 1], c = tris[f + 2];
      const vtkIdType ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      const vtkIdType sub[12] = { a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca };
      next.insert(next.end(), sub, sub + 12);
    }
    tris.swap(next);
  }
  auto mesh = FromTriangles(xyz, tris);
  ApplyPattern(mesh, pattern);
  return mesh;
}

namespace
{
/// The points of UVSphere: the poles, then each meridian from north to south, with the same
/// floating-point steps as vtkSphereSource (so the same doubles bit for bit).
vtkSmartPointer<vtkPoints> UVSpherePoints(int r, int meridians)
{
  const int perMeridian = r - 2;
  const double startTheta = 0.0 * (Pi / 180.0);
  const double endTheta = (360.0 / r * r) * (Pi / 180.0);
  const double deltaTheta = (endTheta - startTheta) / r;
  const double deltaPhi = (180.0 * (Pi / 180.0) - 0.0 * (Pi / 180.0)) / (r - 1);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(2 + static_cast<vtkIdType>(meridians) * perMeridian);
  double* xyz = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  const double poles[6] = { 0, 0, 1, 0, 0, -1 };
  std::copy(poles, poles + 6, xyz);
  ForRanges(0, meridians,
            [=](vtkIdType begin, vtkIdType end)
            {
              for (vtkIdType i = begin; i < end; ++i)
              {
                const double theta = 0.0 * Pi / 180.0 + i * deltaTheta;
                double* p = xyz + 3 * (2 + i * perMeridian);
                for (int j = 1; j <= perMeridian; ++j, p += 3)
                {
                  const double phi = 0.0 + j * deltaPhi;
                  const double radius = 1.0 * std::sin(phi);
                  p[0] = radius * std::cos(theta);
                  p[1] = radius * std::sin(theta);
                  p[2] = 1.0 * std::cos(phi);
                }
              }
            });
  return points;
}

/// The triangles of UVSphere in vtkSphereSource's order: the fans around the north and the
/// south pole, then two triangles per quad of the bands, meridian by meridian. Stored with
/// 32-bit ids where they fit (the same ids as vtkSphereSource's 64-bit ones, in half the memory
/// for the benchmark's largest spheres; the tests read that storage too).
template <typename Id, typename IdArray>
vtkSmartPointer<vtkCellArray> UVSphereTriangles(int r, int meridians, int columns)
{
  const vtkIdType m = r - 2, base = m * meridians, bands = columns * (m - 1);
  const vtkIdType triangles = 2 * columns + 2 * bands;
  vtkNew<IdArray> connectivity, offsets;
  connectivity->SetNumberOfValues(3 * triangles);
  offsets->SetNumberOfValues(triangles + 1);
  Id* c = connectivity->GetPointer(0);
  Id* o = offsets->GetPointer(0);
  for (vtkIdType i = 0; i < columns; ++i)
  {
    Id* north = c + 3 * i;
    Id* south = c + 3 * (columns + i);
    north[0] = static_cast<Id>(m * i + 2);
    north[1] = static_cast<Id>((m * (i + 1)) % base + 2);
    north[2] = 0;
    south[0] = static_cast<Id>(m * i + m + 1);
    south[1] = 1;
    south[2] = static_cast<Id>((m * (i + 1)) % base + m + 1);
  }
  Id* band = c + 6 * columns;
  ForRanges(0, columns,
            [=](vtkIdType begin, vtkIdType end)
            {
              for (vtkIdType i = begin; i < end; ++i)
              {
                Id* t = band + 6 * (m - 1) * i;
                for (vtkIdType j = 0; j < m - 1; ++j, t += 6)
                {
                  const auto a = static_cast<Id>(m * i + j + 2);
                  const auto d = static_cast<Id>((m * (i + 1) + j) % base + 3);
                  const Id quad[6] = { a, a + 1, d, a, d, d - 1 };
                  std::copy(quad, quad + 6, t);
                }
              }
            });
  ForRanges(0, triangles + 1,
            [o](vtkIdType begin, vtkIdType end)
            {
              for (vtkIdType t = begin; t < end; ++t)
              {
                o[t] = static_cast<Id>(3 * t);
              }
            });
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  return polys;
}
} // namespace

vtkSmartPointer<vtkPolyData> UVSphere(int resolution, Pattern pattern, bool compactIds)
{
  const int r = std::max(resolution, 3);
  // vtkSphereSource repeats the first meridian at the end when r steps of 360 / r fall short
  // of 360 (the last band then joins the copy, not the first meridian: an open seam of
  // near-coincident points, as in vtkSphereSource's own output).
  const int meridians = (std::fabs(0.0 - 360.0 / r * r) < 360.0) ? r + 1 : r;
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(UVSpherePoints(r, meridians));
  const bool small = compactIds && 6.0 * r * (r - 2) <= std::numeric_limits<int32_t>::max();
  mesh->SetPolys(small ? UVSphereTriangles<int32_t, vtkTypeInt32Array>(r, meridians, r)
                       : UVSphereTriangles<vtkIdType, vtkIdTypeArray>(r, meridians, r));
  ApplyPattern(mesh, pattern);
  return mesh;
}

vtkSmartPointer<vtkPolyData> UVSphereWithTriangles(long long triangles, Pattern pattern)
{
  // 2 r (r - 2) = triangles
  const int r = static_cast<int>(std::lround(1.0 + std::sqrt(1.0 + triangles / 2.0)));
  return UVSphere(r < 4 ? 4 : r, pattern);
}

vtkSmartPointer<vtkPolyData> Torus(int nu, int nv, Pattern pattern)
{
  const double R = 1.0, r = 0.35;
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<size_t>(nu) * nv);
  for (int i = 0; i < nu; ++i)
  {
    const double u = 2.0 * Pi * i / nu;
    for (int j = 0; j < nv; ++j)
    {
      const double v = 2.0 * Pi * j / nv;
      xyz.push_back((R + r * std::cos(v)) * std::cos(u));
      xyz.push_back((R + r * std::cos(v)) * std::sin(u));
      xyz.push_back(r * std::sin(v));
    }
  }
  std::vector<vtkIdType> tris;
  tris.reserve(6 * static_cast<size_t>(nu) * nv);
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const vtkIdType a = i * nv + j, b = ((i + 1) % nu) * nv + j;
      const vtkIdType c = ((i + 1) % nu) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
      const vtkIdType quad[6] = { a, b, c, a, c, d };
      tris.insert(tris.end(), quad, quad + 6);
    }
  }
  auto mesh = FromTriangles(xyz, tris);
  ApplyPattern(mesh, pattern);
  return mesh;
}

vtkSmartPointer<vtkPolyData> Grid(int nx, int ny, Pattern pattern)
{
  return MakeGrid(nx, ny, true, pattern);
}

vtkSmartPointer<vtkPolyData> FlatGrid(int nx, int ny, Pattern pattern)
{
  return MakeGrid(nx, ny, false, pattern);
}

namespace
{
/// Set RGB (3 bytes per point, active scalars) and TCoords (2 floats per point).
void SetSeamArrays(vtkPolyData* mesh, const std::vector<unsigned char>& rgb,
                   const std::vector<float>& uv)
{
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(rgb.size() / 3));
  std::copy(rgb.begin(), rgb.end(), colors->GetPointer(0));
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(static_cast<vtkIdType>(uv.size() / 2));
  std::copy(uv.begin(), uv.end(), tcoords->GetPointer(0));
  mesh->GetPointData()->SetScalars(colors);
  mesh->GetPointData()->SetTCoords(tcoords);
}
} // namespace

vtkSmartPointer<vtkPolyData> SeamSphere(int r)
{
  std::vector<double> xyz = { 0, 0, 1 };
  std::vector<unsigned char> rgb = { 255, 255, 255 };
  std::vector<float> uv = { 0.5f, 1.0f };
  for (int i = 1; i < r; ++i)
  {
    const double theta = Pi * i / r;
    for (int j = 0; j <= r; ++j)
    {
      const double phi = 2.0 * Pi * (j % r) / r; // the last column: the first's positions
      xyz.insert(
        xyz.end(),
        { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) });
      const double u = double(j) / r, v = 1.0 - double(i) / r;
      rgb.insert(rgb.end(),
                 { static_cast<unsigned char>(255 * u), static_cast<unsigned char>(255 * v),
                   static_cast<unsigned char>((j / 4) % 2 ? 255 * (1 - u) : 40) });
      uv.insert(uv.end(), { static_cast<float>(u), static_cast<float>(v) });
    }
  }
  xyz.insert(xyz.end(), { 0, 0, -1 });
  rgb.insert(rgb.end(), { 0, 0, 0 });
  uv.insert(uv.end(), { 0.5f, 0.0f });
  const vtkIdType south = static_cast<vtkIdType>(xyz.size() / 3) - 1;
  const auto at = [r](int i, int j) { return vtkIdType(1 + (i - 1) * (r + 1) + j); };
  std::vector<vtkIdType> tris;
  for (int j = 0; j < r; ++j)
  {
    tris.insert(tris.end(), { 0, at(1, j), at(1, j + 1), south, at(r - 1, j + 1), at(r - 1, j) });
    for (int i = 1; i < r - 1; ++i)
    {
      tris.insert(
        tris.end(),
        { at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  }
  auto mesh = FromTriangles(xyz, tris);
  SetSeamArrays(mesh, rgb, uv);
  return mesh;
}

vtkSmartPointer<vtkPolyData> ColorCube(int n)
{
  static const unsigned char palette[6][3] = {
    { 230, 40, 40 },  { 40, 200, 40 },  { 40, 40, 230 },
    { 230, 230, 40 }, { 40, 230, 230 }, { 230, 40, 230 }
  };
  std::vector<double> xyz;
  std::vector<unsigned char> rgb;
  std::vector<float> uv;
  std::vector<vtkIdType> tris;
  for (int face = 0; face < 6; ++face)
  {
    // Face (axis, sign), spanned by t1 x t2 = the outward normal.
    const int axis = face / 2, sign = face % 2 ? -1 : 1;
    const int t1 = (axis + (sign > 0 ? 1 : 2)) % 3, t2 = (axis + (sign > 0 ? 2 : 1)) % 3;
    const auto base = static_cast<vtkIdType>(xyz.size() / 3);
    for (int i = 0; i <= n; ++i)
    {
      for (int j = 0; j <= n; ++j)
      {
        double p[3];
        p[axis] = sign;
        p[t1] = -1.0 + 2.0 * i / n; // the same expression on every face: bit-identical edges
        p[t2] = -1.0 + 2.0 * j / n;
        xyz.insert(xyz.end(), p, p + 3);
        rgb.insert(rgb.end(), palette[face], palette[face] + 3);
        uv.insert(uv.end(), { float(i) / n, float(j) / n });
      }
    }
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; j < n; ++j)
      {
        const vtkIdType a = base + i * (n + 1) + j, b = a + n + 1;
        tris.insert(tris.end(), { a, b, b + 1, a, b + 1, a + 1 });
      }
    }
  }
  auto mesh = FromTriangles(xyz, tris);
  SetSeamArrays(mesh, rgb, uv);
  return mesh;
}

} // namespace meshes
} // namespace colordecimation
