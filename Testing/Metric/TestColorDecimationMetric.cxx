// Tests of the comparison metric, Garland and Heckbert's colour quadric (Filters/Core/
// ColorQuadric), its optimal placement, and of the CIELab colour space (Filters/Core/
// ColorSpace): quadrics against hand-computed values, the 6x6 solve and its fallback,
// CIELab against published values, and decimations with the new options of
// vtkColorHalfEdgeDecimation (targets met, manifold kept, no flips, colour arrays written back).
#include "ColorDecimationTestUtilities.h"

#include "Decimator.h"
#include "mesh/HalfEdgeMesh.h"
#include "metric/AttributeQuadric.h"
#include "metric/ColorQuadric.h"
#include "metric/ColorSpace.h"
#include "metric/HalfEdgeColor.h"
#include "metric/Quadric.h"
#include "rules/CollapseRules.h"

#include "ColorDecimationMeshes.h"
#include "vtkColorHalfEdgeDecimation.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <random>
#include <set>
#include <sstream>

using namespace colordecimation;
using namespace colordecimation::testing;
using meshes::Pattern;

namespace
{
const double Sqrt2 = std::sqrt(2.0);
const double Sqrt3 = std::sqrt(3.0);

//------------------------------------------------------------------------------
// An independent reference: the squared distance from x to the affine plane of R^6 through
// a, b, c, by least squares (the 2x2 normal equations of x ~ a + s (b - a) + t (c - a)).
double PlaneDistance2(const double a[6], const double b[6], const double c[6], const double x[6])
{
  double u[6], v[6], w[6];
  for (int k = 0; k < 6; ++k)
  {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    w[k] = x[k] - a[k];
  }
  double uu = 0, uv = 0, vv = 0, uw = 0, vw = 0;
  for (int k = 0; k < 6; ++k)
  {
    uu += u[k] * u[k];
    uv += u[k] * v[k];
    vv += v[k] * v[k];
    uw += u[k] * w[k];
    vw += v[k] * w[k];
  }
  const double det = uu * vv - uv * uv;
  const double s = (uw * vv - vw * uv) / det;
  const double t = (vw * uu - uw * uv) / det;
  double d2 = 0;
  for (int k = 0; k < 6; ++k)
  {
    const double r = w[k] - s * u[k] - t * v[k];
    d2 += r * r;
  }
  return d2;
}

double TriangleArea3(const double a[6], const double b[6], const double c[6])
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                        u[0] * v[1] - u[1] * v[0] };
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

void Sub(const double a[6], const double b[6], double d[6])
{
  for (int k = 0; k < 6; ++k)
  {
    d[k] = a[k] - b[k];
  }
}

//------------------------------------------------------------------------------
CD_TEST_CASE(TriangleQuadric)
{
  // v1 = (1,2,3, .1,.2,.3); v2 = v1 + 2 e_x; v3 = v1 + (0,1,0, 0,.5,0). Then e1 = e_x and
  // e2 = (0,1,0,0,.5,0)/sqrt(1.25).
  const double v1[6] = { 1, 2, 3, 0.1, 0.2, 0.3 };
  const double v2[6] = { 3, 2, 3, 0.1, 0.2, 0.3 };
  const double v3[6] = { 1, 3, 3, 0.1, 0.7, 0.3 };
  double e1[6], e2[6];
  CD_CHECK(TriangleFrame(v1, v2, v3, e1, e2));
  const double s = std::sqrt(1.25);
  const double expected1[6] = { 1, 0, 0, 0, 0, 0 };
  const double expected2[6] = { 0, 1 / s, 0, 0, 0.5 / s, 0 };
  for (int k = 0; k < 6; ++k)
  {
    CD_CHECK_NEAR(e1[k], expected1[k], 1e-15);
    CD_CHECK_NEAR(e2[k], expected2[k], 1e-15);
  }

  ColorQuadricD q;
  CD_CHECK(TriangleColorQuadric(v1, v2, v3, q));
  // A = I - e1 e1^T - e2 e2^T: A(0,0) = 0, A(1,1) = 1 - 0.8 = 0.2, A(1,4) = -0.4, A(4,4) = 0.8.
  CD_CHECK_NEAR(q.GetA(0, 0), 0.0, 1e-15);
  CD_CHECK_NEAR(q.GetA(1, 1), 0.2, 1e-15);
  CD_CHECK_NEAR(q.GetA(1, 4), -0.4, 1e-15);
  CD_CHECK_NEAR(q.GetA(4, 1), -0.4, 1e-15);
  CD_CHECK_NEAR(q.GetA(4, 4), 0.8, 1e-15);
  CD_CHECK_NEAR(q.GetA(2, 2), 1.0, 1e-15);
  CD_CHECK_NEAR(q.GetA(3, 5), 0.0, 1e-15);

  // Zero on the triangle's own corners (and anywhere on its plane).
  const double onPlane[6] = { 7, -4, 3, 0.1, 0.2 - 3.0, 0.3 }; // v1 + 6 e_x - 6 (0,1,0,0,.5,0)
  for (const double* x : { v1, v2, v3, onPlane })
  {
    CD_CHECK_NEAR(q.Evaluate(x), 0.0, 1e-12);
  }
  // Offsets from v1, by hand: (.5,0,0,.2,0,.1) keeps .2^2 + .1^2 = 0.05 (its e_x part lies in
  // the plane); e_z gives 1; e_g gives 1 - (.5)^2/1.25 = 0.8.
  struct Case
  {
    double Offset[6];
    double Distance2;
  };
  const Case cases[] = { { { 0.5, 0, 0, 0.2, 0, 0.1 }, 0.05 },
                         { { 0, 0, 1, 0, 0, 0 }, 1.0 },
                         { { 0, 0, 0, 0, 1, 0 }, 0.8 },
                         { { 0, 0, -3, 0, 0, 0 }, 9.0 } };
  for (const Case& c : cases)
  {
    double x[6];
    for (int k = 0; k < 6; ++k)
    {
      x[k] = v2[k] + c.Offset[k]; // from another corner: the same distances
    }
    CD_CHECK_NEAR(q.Evaluate(x), c.Distance2, 1e-12);
    CD_CHECK_NEAR(PlaneDistance2(v1, v2, v3, x), c.Distance2, 1e-12);
  }

  // Degenerate triangles give no quadric.
  const double collinear[6] = { 5, 2, 3, 0.1, 0.2, 0.3 };
  ColorQuadricD untouched;
  CD_CHECK(!TriangleColorQuadric(v1, v2, collinear, untouched));
  CD_CHECK(!TriangleColorQuadric(v1, v1, v3, untouched));
  CD_CHECK(untouched.C == 0.0);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(CentredQuadric)
{
  // A triangle in general position; its quadric centred at corner v2 (only A: the plane
  // passes through the centre) equals the global one.
  const double v1[6] = { 0.3, -1.2, 2.0, 0.9, 0.1, 0.4 };
  const double v2[6] = { 1.1, -0.7, 2.4, 0.2, 0.6, 0.5 };
  const double v3[6] = { 0.2, 0.4, 1.5, 0.3, 0.3, 0.8 };
  ColorQuadricD global;
  CD_CHECK(TriangleColorQuadric(v1, v2, v3, global));
  double e1[6], e2[6];
  CD_CHECK(TriangleFrame(v1, v2, v3, e1, e2));
  ColorQuadricD centred;
  centred.AddPlaneThroughCentre(e1, e2, 2.5);

  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 20; ++trial)
  {
    double x[6], d[6];
    for (double& xk : x)
    {
      xk = u(random);
    }
    Sub(x, v2, d);
    const double reference = PlaneDistance2(v1, v2, v3, x);
    CD_CHECK_NEAR(global.Evaluate(x), reference, 1e-12);
    CD_CHECK_NEAR(centred.Evaluate(d), 2.5 * reference, 1e-12);

    // Recentre by s: Q is unchanged, only measured from elsewhere.
    double s[6], e[6];
    for (int k = 0; k < 6; ++k)
    {
      s[k] = u(random);
      e[k] = d[k] - s[k];
    }
    ColorQuadricD moved = centred;
    moved.Recentre(s);
    CD_CHECK_NEAR(moved.Evaluate(e), 2.5 * reference, 1e-11);

    // The float (per-vertex) storage keeps the value to float precision.
    ColorQuadric stored;
    stored.Assign(centred);
    CD_CHECK_NEAR(stored.Evaluate(d), 2.5 * reference, 1e-5);
  }
}

//------------------------------------------------------------------------------
CD_TEST_CASE(QuadricSums)
{
  // Two triangles' quadrics, one centred at a, one at b: sum centred at a by AddShifted;
  // and the 28 coefficients of a sum are the sums of the coefficients.
  const double a[6] = { 0, 0, 0, 0.2, 0.2, 0.2 };
  const double b1[6] = { 1, 0, 0, 0.4, 0.2, 0.2 };
  const double c1[6] = { 0, 1, 0, 0.2, 0.9, 0.2 };
  const double b[6] = { 0.5, 0.5, 1.0, 0.1, 0.5, 0.7 };
  const double b2[6] = { 1.5, 0.2, 1.3, 0.3, 0.5, 0.1 };
  const double c2[6] = { 0.7, 1.4, 0.4, 0.0, 0.9, 0.6 };
  double e1[6], e2[6], f1[6], f2[6];
  CD_CHECK(TriangleFrame(a, b1, c1, e1, e2));
  CD_CHECK(TriangleFrame(b, b2, c2, f1, f2));
  ColorQuadricD qa, qb;
  qa.AddPlaneThroughCentre(e1, e2, 0.7);
  qb.AddPlaneThroughCentre(f1, f2, 1.3);
  double ab[6];
  Sub(a, b, ab); // centre_this - centre_other
  ColorQuadricD sum = qa;
  sum.AddShifted(qb, ab);

  ColorQuadricD ga, gb, total;
  CD_CHECK(TriangleColorQuadric(a, b1, c1, ga));
  CD_CHECK(TriangleColorQuadric(b, b2, c2, gb));
  total.Add(ga, 0.7);
  total.Add(gb, 1.3);
  for (int k = 0; k < 21; ++k)
  {
    CD_CHECK_NEAR(total.A[k], 0.7 * ga.A[k] + 1.3 * gb.A[k], 1e-15);
  }

  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int trial = 0; trial < 20; ++trial)
  {
    double x[6], da[6];
    for (double& xk : x)
    {
      xk = u(random);
    }
    Sub(x, a, da);
    const double reference =
      0.7 * PlaneDistance2(a, b1, c1, x) + 1.3 * PlaneDistance2(b, b2, c2, x);
    CD_CHECK_NEAR(sum.Evaluate(da), reference, 1e-12);
    CD_CHECK_NEAR(total.Evaluate(x), reference, 1e-12);
  }
}

//------------------------------------------------------------------------------
/// A flat unit square (0,0,0) (1,0,0) (1,1,0) (0,1,0) in two triangles (0,1,2), (0,2,3).
struct Square
{
  std::vector<int32_t> Triangles = { 0, 1, 2, 0, 2, 3 };
  std::vector<float> Positions = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  HalfEdgeMesh Mesh;
  Square() { this->Mesh.Build(4, this->Triangles.data(), 2); }
};

CD_TEST_CASE(InitialQuadrics)
{
  Square square;
  const std::vector<float> grey(12, 0.5f);
  LargeVector<ColorQuadric> q;

  // Constant colour: the plane of R^6 is (x, y, 0, .5, .5, .5); vertex 0 has both triangles
  // (area 1/2 each), vertex 1 one of them.
  InitializeColorQuadrics(square.Mesh, square.Positions.data(), 3, 1.0, grey.data(), 3, 1.0, 0.0,
                          q);
  CD_CHECK(q.size() == 4);
  const double dz[6] = { 0.3, -0.2, 0.5, 0, 0, 0 }; // in-plane parts count for nothing
  const double dc[6] = { 0, 0, 0, 0.1, -0.2, 0.4 }; // colour offsets: 0.01 + 0.04 + 0.16
  CD_CHECK_NEAR(q[0].Evaluate(dz), 1.0 * 0.25, 1e-7);
  CD_CHECK_NEAR(q[1].Evaluate(dz), 0.5 * 0.25, 1e-7);
  CD_CHECK_NEAR(q[0].Evaluate(dc), 1.0 * 0.21, 1e-7);
  CD_CHECK_NEAR(q[3].Evaluate(dc), 0.5 * 0.21, 1e-7);
  for (const ColorQuadric& v : q)
  {
    CD_CHECK(v.C == 0.0f); // centred at the vertex, which lies on its planes
    for (float bk : v.B)
    {
      CD_CHECK(bk == 0.0f);
    }
  }

  // Scales: positions x2 (areas x4), colours x3.
  InitializeColorQuadrics(square.Mesh, square.Positions.data(), 3, 2.0, grey.data(), 3, 3.0, 0.0,
                          q);
  CD_CHECK_NEAR(q[0].Evaluate(dz), 4.0 * 0.25, 1e-6);
  CD_CHECK_NEAR(q[2].Evaluate(dc), 4.0 * 0.21, 1e-6); // vertex 2 has both triangles

  // Red = x: the plane (x, y, 0, x, 0, 0) is spanned by (1,0,0,1,0,0)/sqrt2 and e_y; an
  // offset e_x keeps half its length squared, e_r too, and e_x - e_r all of its 2.
  std::vector<float> ramp = { 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0 };
  InitializeColorQuadrics(square.Mesh, square.Positions.data(), 3, 1.0, ramp.data(), 3, 1.0, 0.0,
                          q);
  const double ex[6] = { 1, 0, 0, 0, 0, 0 };
  const double er[6] = { 0, 0, 0, 1, 0, 0 };
  const double exr[6] = { 1, 0, 0, -1, 0, 0 };
  const double exr2[6] = { 1, 0, 0, 1, 0, 0 };
  CD_CHECK_NEAR(q[0].Evaluate(ex), 0.5, 1e-7);
  CD_CHECK_NEAR(q[0].Evaluate(er), 0.5, 1e-7);
  CD_CHECK_NEAR(q[0].Evaluate(exr), 2.0, 1e-6);
  CD_CHECK_NEAR(q[0].Evaluate(exr2), 0.0, 1e-7);
  CD_CHECK_NEAR(q[1].Evaluate(exr), 1.0, 1e-6); // vertex 1 has one triangle

  // Boundary constraints (weight 10): vertex 1 is on the boundary edges 0-1 (along x, the
  // constraint plane is perpendicular to y) and 1-2 (along y: perpendicular to x), each of
  // squared length 1: an in-plane offset (dx, dy) costs 10 dx^2 + 10 dy^2. Vertex 0 is on
  // 3-0 and 0-1 the same way; the diagonal 0-2 is interior.
  InitializeColorQuadrics(square.Mesh, square.Positions.data(), 3, 1.0, grey.data(), 3, 1.0, 10.0,
                          q);
  const double inPlane[6] = { 0.3, -0.2, 0, 0, 0, 0 };
  CD_CHECK_NEAR(q[1].Evaluate(inPlane), 10 * 0.09 + 10 * 0.04, 1e-6);
  CD_CHECK_NEAR(q[0].Evaluate(inPlane), 10 * 0.09 + 10 * 0.04, 1e-6);
  CD_CHECK_NEAR(q[1].Evaluate(dc), 0.5 * 0.21, 1e-7); // colour: no constraint
  // Twice the scale: squared edge lengths x4.
  InitializeColorQuadrics(square.Mesh, square.Positions.data(), 3, 2.0, grey.data(), 3, 1.0, 10.0,
                          q);
  CD_CHECK_NEAR(q[1].Evaluate(inPlane), 40 * 0.09 + 40 * 0.04, 1e-5);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(OptimalPlacement)
{
  // Plane 1: through the origin along x and y. Plane 2: through (1,2,0,0,.4,.6) along z and r.
  // The sum of squared distances, z^2 + r^2 + g^2 + b^2 + (x-1)^2 + (y-2)^2 + (g-.4)^2 +
  // (b-.6)^2, is least at (1, 2, 0, 0, .2, .3), where it is 2 (.2^2 + .3^2) = 0.26.
  const double o[6] = { 0, 0, 0, 0, 0, 0 };
  const double x1[6] = { 1, 0, 0, 0, 0, 0 };
  const double y1[6] = { 0, 1, 0, 0, 0, 0 };
  const double p[6] = { 1, 2, 0, 0, 0.4, 0.6 };
  const double pz[6] = { 1, 2, 1, 0, 0.4, 0.6 };
  const double pr[6] = { 1, 2, 0, 1, 0.4, 0.6 };
  ColorQuadricD q1, q2, sum;
  CD_CHECK(TriangleColorQuadric(o, x1, y1, q1));
  CD_CHECK(TriangleColorQuadric(p, pz, pr, q2));
  sum.Add(q1);
  sum.Add(q2);
  double y[6];
  CD_CHECK(MinimizeColorQuadric(sum, y));
  const double expected[6] = { 1, 2, 0, 0, 0.2, 0.3 };
  for (int k = 0; k < 6; ++k)
  {
    CD_CHECK_NEAR(y[k], expected[k], 1e-12);
  }
  CD_CHECK_NEAR(sum.Evaluate(y), 0.26, 1e-12);

  // The same with the quadrics centred elsewhere (as the decimation stores them): centred at
  // c, the minimiser is expected - c.
  const double c[6] = { 0.5, 1.5, 0.2, 0.1, 0.3, 0.2 };
  ColorQuadricD centred = sum;
  centred.Recentre(c);
  CD_CHECK(MinimizeColorQuadric(centred, y));
  for (int k = 0; k < 6; ++k)
  {
    CD_CHECK_NEAR(y[k], expected[k] - c[k], 1e-12);
  }
  CD_CHECK_NEAR(centred.Evaluate(y), 0.26, 1e-12);

  // Area weights move the optimum: weight 3 on plane 2 gives g = 3 * .4 / 4 = .3, b = .45.
  ColorQuadricD weighted;
  weighted.Add(q1);
  weighted.Add(q2, 3.0);
  CD_CHECK(MinimizeColorQuadric(weighted, y));
  CD_CHECK_NEAR(y[4], 0.3, 1e-12);
  CD_CHECK_NEAR(y[5], 0.45, 1e-12);
  CD_CHECK_NEAR(y[0], 1.0, 1e-12);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(SingularSystem)
{
  double y[6] = { 42, 42, 42, 42, 42, 42 };
  // Nothing at all.
  CD_CHECK(!MinimizeColorQuadric(ColorQuadricD(), y));
  // One triangle: A = I - e1 e1^T - e2 e2^T has rank 4 (every point of its plane is optimal).
  const double a[6] = { 0, 0, 0, 0.1, 0.2, 0.3 };
  const double b[6] = { 1, 0, 0, 0.5, 0.2, 0.3 };
  const double c[6] = { 0, 1, 0, 0.1, 0.6, 0.3 };
  ColorQuadricD one;
  CD_CHECK(TriangleColorQuadric(a, b, c, one));
  CD_CHECK(!MinimizeColorQuadric(one, y));
  // Two triangles of the same plane of R^6 (a flat patch with a linear colour ramp): still
  // rank 4, in float storage too (where the rounding leaves tiny non-zero pivots).
  const double d[6] = { 1, 1, 0, 0.5, 0.6, 0.3 };
  ColorQuadricD two;
  CD_CHECK(TriangleColorQuadric(b, d, c, two));
  two.Add(one);
  CD_CHECK(!MinimizeColorQuadric(two, y));
  double e1[6], e2[6];
  CD_CHECK(TriangleFrame(a, b, c, e1, e2));
  ColorQuadric stored;
  stored.AddPlaneThroughCentre(e1, e2, 0.37);
  CD_CHECK(TriangleFrame(b, d, c, e1, e2));
  ColorQuadric other;
  other.AddPlaneThroughCentre(e1, e2, 0.52);
  const double shift[6] = { a[0] - b[0], a[1] - b[1], a[2] - b[2],
                            a[3] - b[3], a[4] - b[4], a[5] - b[5] };
  ColorQuadricD storedSum;
  storedSum.Assign(stored);
  storedSum.AddShifted(other, shift);
  CD_CHECK(!MinimizeColorQuadric(storedSum, y));
  for (double yk : y)
  {
    CD_CHECK(yk == 42.0); // untouched on failure
  }
  // Add a third, tilted plane: now a unique point.
  const double t1[6] = { 0, 0, 1, 0, 0, 0 };
  const double t2[6] = { 0, 0, 0, 0, 0, 1 };
  ColorQuadricD tilted;
  CD_CHECK(TriangleColorQuadric(a, t1, t2, tilted));
  two.Add(tilted);
  const double e3[6] = { 0, 0, 0, 1, 0, 0 };
  ColorQuadricD fourth;
  CD_CHECK(TriangleColorQuadric(a, e3, t2, fourth));
  two.Add(fourth);
  CD_CHECK(MinimizeColorQuadric(two, y));
}

//------------------------------------------------------------------------------
/**
 * The square pyramid of the core tests (PyramidPoints, PyramidTriangles). Bounding box
 * [-1,1]x[-1,1]x[0,1]: GH98's frame divides by its largest side, 2.
 */
const float PyramidColors[15] = { 0.1f, 0.1f, 0.1f, 0.6f, 0, 0, 0, 0, 0.9f, 0, 0.8f, 0, 1, 1, 1 };

/// The hand cost (Q0 + Q1)(x1) of a pyramid collapse in GH98's frame, colour weight w.
double PyramidQuadricCost(int v0, int v1, double w, const double* points = PyramidPoints)
{
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = hi[k] = points[k];
    for (int v = 1; v < 5; ++v)
    {
      lo[k] = std::min(lo[k], points[3 * v + k]);
      hi[k] = std::max(hi[k], points[3 * v + k]);
    }
  }
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  auto point = [&](int v, double x[6])
  {
    for (int k = 0; k < 3; ++k)
    {
      x[k] = (points[3 * v + k] - lo[k]) / extent;
      x[3 + k] = w * PyramidColors[3 * v + k];
    }
  };
  double x1[6];
  point(v1, x1);
  double cost = 0;
  for (int t = 0; t < 4; ++t)
  {
    const int32_t* tri = PyramidTriangles + 3 * t;
    double a[6], b[6], c[6];
    point(tri[0], a);
    point(tri[1], b);
    point(tri[2], c);
    const double area = TriangleArea3(a, b, c);
    for (int v : { v0, v1 })
    {
      if (tri[0] == v || tri[1] == v || tri[2] == v)
      {
        cost += area * PlaneDistance2(a, b, c, x1);
      }
    }
  }
  return cost;
}

DecimatorInput PyramidInput(const double* points)
{
  DecimatorInput input;
  input.NumberOfPoints = 5;
  input.Points = points;
  input.Colors = PyramidColors;
  input.NumberOfTriangles = 4;
  input.Triangles = PyramidTriangles;
  return input;
}

CD_TEST_CASE(CollapseCostColorQuadric)
{
  for (double w : { 1.0, 2.5, 0.0 })
  {
    DecimatorOptions options;
    options.Metric = ErrorMetric::ColorQuadric;
    options.ColorWeight = w;
    Decimator decimator(options);
    const DecimatorStatistics stats = decimator.Run(PyramidInput(PyramidPoints), 4);
    CD_CHECK(stats.Collapses == 0);
    CD_CHECK(stats.MetricBytesPerVertex == 112);
    CD_CHECK(decimator.GetMetrics().empty());
    CD_CHECK(decimator.GetColorQuadrics().size() == 5);
    for (auto edge : { std::make_pair(0, 1), std::make_pair(0, 3), std::make_pair(2, 1),
                       std::make_pair(1, 0), std::make_pair(4, 0) })
    {
      const double expected = PyramidQuadricCost(edge.first, edge.second, w);
      const double actual = decimator.CollapseCost(edge.first, edge.second);
      CD_CHECK_MSG(std::abs(actual - expected) <= 1e-6 * std::max(1.0, expected),
                   "w " << w << ", " << edge.first << " -> " << edge.second << ": " << actual
                        << ", expected " << expected);
      CD_CHECK_MSG(edge.second == 0 || expected > (w > 0 ? 1e-3 : 0.0),
                   "w " << w << ", " << edge.first << " -> " << edge.second << ": " << expected);
    }
    CD_CHECK(decimator.CollapseCost(1, 3) < 0); // not neighbours
  }

  // GH98's frame: the same costs whatever the input's unit and position.
  for (double scale : { 1e-3, 1e4 })
  {
    double points[15];
    for (int i = 0; i < 15; ++i)
    {
      points[i] = PyramidPoints[i] * scale + (i % 3 == 0 ? 17.0 : -3.0) * scale;
    }
    DecimatorOptions options;
    options.Metric = ErrorMetric::ColorQuadric;
    Decimator decimator(options);
    decimator.Run(PyramidInput(points), 4);
    CD_CHECK_NEAR(decimator.CollapseCost(0, 1), PyramidQuadricCost(0, 1, 1.0), 1e-6);
    CD_CHECK_NEAR(PyramidQuadricCost(0, 1, 1.0, points), PyramidQuadricCost(0, 1, 1.0), 1e-9);
  }
}

CD_TEST_CASE(PlacementCost)
{
  DecimatorOptions options;
  options.Metric = ErrorMetric::ColorQuadric;
  DecimatorOptions placing = options;
  placing.OptimalPlacement = true;
  Decimator halfEdge(options);
  Decimator full(placing);
  halfEdge.Run(PyramidInput(PyramidPoints), 4);
  full.Run(PyramidInput(PyramidPoints), 4);
  for (auto edge : { std::make_pair(0, 1), std::make_pair(0, 3), std::make_pair(2, 1) })
  {
    // Both endpoints are candidates of the full collapse: it costs at most either half-edge.
    const double forward = halfEdge.CollapseCost(edge.first, edge.second);
    const double backward = halfEdge.CollapseCost(edge.second, edge.first);
    const double placed = full.CollapseCost(edge.first, edge.second);
    CD_CHECK_MSG(placed <= std::min(forward, backward) * (1 + 1e-9) + 1e-12,
                 edge.first << "-" << edge.second << ": placed " << placed << ", half-edge "
                            << forward << " / " << backward);
    CD_CHECK(placed >= 0);
    // And the full collapse is symmetric (its optimum does not depend on which end stays).
    CD_CHECK_NEAR(full.CollapseCost(edge.second, edge.first), placed, 1e-6);
  }
  // On the apex-ring edge the optimum is strictly inside (the pyramid is curved there).
  CD_CHECK(full.CollapseCost(0, 1) < 0.9 * halfEdge.CollapseCost(0, 1));
}

//------------------------------------------------------------------------------
void CheckLab(double r, double g, double b, double l, double a, double bb, double tolerance)
{
  const double rgb[3] = { r, g, b };
  double lab[3];
  SRGBToLab(rgb, lab);
  CD_CHECK_MSG(std::abs(lab[0] - l) <= tolerance && std::abs(lab[1] - a) <= tolerance &&
                 std::abs(lab[2] - bb) <= tolerance,
               "sRGB (" << r << ", " << g << ", " << b << ") -> Lab (" << lab[0] << ", " << lab[1]
                        << ", " << lab[2] << "), expected (" << l << ", " << a << ", " << bb
                        << ")");
}

CD_TEST_CASE(CIELabValues)
{
  // Published sRGB (D65) -> CIELab values.
  CheckLab(1, 1, 1, 100, 0, 0, 1e-3);
  CheckLab(0, 0, 0, 0, 0, 0, 1e-12);
  CheckLab(1, 0, 0, 53.2408, 80.0925, 67.2032, 5e-3);
  CheckLab(0, 1, 0, 87.7347, -86.1827, 83.1793, 5e-3);
  CheckLab(0, 0, 1, 32.2970, 79.1875, -107.8602, 5e-3);
  CheckLab(0.5, 0.5, 0.5, 53.3890, 0, 0, 5e-3);
  // The linear segment of the sRGB curve (dark): 0.02 -> 0.02 / 12.92 -> L = 903.3 Y.
  CheckLab(0.02, 0.02, 0.02, 903.2963 * 0.02 / 12.92, 0, 0, 1e-3);
  // XYZ of white is the D65 white point.
  const double white[3] = { 1, 1, 1 };
  double xyz[3];
  SRGBToXYZ(white, xyz);
  CD_CHECK_NEAR(xyz[0], 0.95047, 1e-6);
  CD_CHECK_NEAR(xyz[1], 1.0, 1e-6);
  CD_CHECK_NEAR(xyz[2], 1.08883, 1e-6);
  // The metric's coordinates: Lab / 100.
  double m[3];
  const double red[3] = { 1, 0, 0 };
  RGBToMetricColor(ColorSpace::CIELab, red, m);
  CD_CHECK_NEAR(m[0], 0.532408, 5e-5);
  CD_CHECK_NEAR(m[1], 0.800925, 5e-5);
  CD_CHECK_NEAR(m[2], 0.672032, 5e-5);
  RGBToMetricColor(ColorSpace::RGB, red, m);
  CD_CHECK(m[0] == 1 && m[1] == 0 && m[2] == 0);
  CD_CHECK(std::string(ColorSpaceName(ColorSpace::CIELab)) == "CIELab");
  CD_CHECK(std::string(ColorSpaceName(ColorSpace::RGB)) == "RGB");
}

CD_TEST_CASE(CIELabRoundTrip)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 1000; ++trial)
  {
    const double rgb[3] = { u(random), u(random), u(random) };
    double lab[3], back[3], m[3], back2[3];
    SRGBToLab(rgb, lab);
    LabToSRGB(lab, back);
    RGBToMetricColor(ColorSpace::CIELab, rgb, m);
    MetricColorToRGB(ColorSpace::CIELab, m, back2);
    for (int k = 0; k < 3; ++k)
    {
      CD_CHECK_NEAR(back[k], rgb[k], 1e-9);
      CD_CHECK_NEAR(back2[k], rgb[k], 1e-9);
    }
    CD_CHECK(lab[0] >= -1e-9 && lab[0] <= 100 + 1e-3);
  }
}

CD_TEST_CASE(CIELabClamp)
{
  // RGB: clamped to [0,1].
  double c[3] = { 1.2, -0.1, 0.5 };
  CD_CHECK(ClampMetricColor(ColorSpace::RGB, c));
  CD_CHECK(c[0] == 1.0 && c[1] == 0.0 && c[2] == 0.5);
  double inside[3] = { 0.2, 0.3, 0.4 };
  CD_CHECK(!ClampMetricColor(ColorSpace::RGB, inside));
  CD_CHECK(inside[0] == 0.2 && inside[1] == 0.3 && inside[2] == 0.4);

  // CIELab: (50, 120, 0) is outside the sRGB gamut; after clamping it is inside.
  double lab[3] = { 0.5, 1.2, 0.0 };
  double rgb[3];
  MetricColorToRGB(ColorSpace::CIELab, lab, rgb);
  CD_CHECK(rgb[0] > 1.0 || rgb[1] < 0.0 || rgb[2] > 1.0 || rgb[2] < 0.0);
  CD_CHECK(ClampMetricColor(ColorSpace::CIELab, lab));
  MetricColorToRGB(ColorSpace::CIELab, lab, rgb);
  for (double x : rgb)
  {
    CD_CHECK(x >= -1e-9 && x <= 1 + 1e-9);
  }
  // In gamut (a real sRGB colour): unchanged.
  const double orange[3] = { 1.0, 0.5, 0.0 };
  double m[3];
  RGBToMetricColor(ColorSpace::CIELab, orange, m);
  const double before[3] = { m[0], m[1], m[2] };
  CD_CHECK(!ClampMetricColor(ColorSpace::CIELab, m));
  CD_CHECK(m[0] == before[0] && m[1] == before[1] && m[2] == before[2]);
}

double LabDistance(const float* a, const float* b)
{
  const double ra[3] = { a[0], a[1], a[2] };
  const double rb[3] = { b[0], b[1], b[2] };
  double la[3], lb[3];
  SRGBToLab(ra, la);
  SRGBToLab(rb, lb);
  return std::sqrt((la[0] - lb[0]) * (la[0] - lb[0]) + (la[1] - lb[1]) * (la[1] - lb[1]) +
                   (la[2] - lb[2]) * (la[2] - lb[2])) /
    100.0;
}

CD_TEST_CASE(CIELabMetric)
{
  // The paper's cost of the pyramid's apex -> 1 collapse with every colour distance taken
  // in CIELab / 100 (docs/ALGORITHM.md sections 4 and 8; the frame makes every spoke and the rims
  // 1-2, 1-4 of length 1, the rim 1-3 of length sqrt2; Q = 1/sqrt3).
  DecimatorOptions options;
  options.Space = ColorSpace::CIELab;
  Decimator decimator(options);
  decimator.Run(PyramidInput(PyramidPoints), 4);
  const float* c = PyramidColors;
  auto col = [c](int v) { return c + 3 * v; };
  double sum = 0, maximum = 0;
  for (int i = 1; i <= 4; ++i)
  {
    const double d = LabDistance(col(0), col(i));
    sum += d;
    maximum = std::max(maximum, d);
  }
  const double importance = sum / maximum;
  CD_CHECK_NEAR(decimator.GetMetrics()[0].Importance, importance, 1e-5);
  // C(0 -> 1) over the apex's ring i = 1..4 (lengths from apex 1; from 1: 0, 1, sqrt2, 1).
  const double fromOne[5] = { 0, 0, 1, Sqrt2, 1 };
  double colorError = 0;
  for (int i = 1; i <= 4; ++i)
  {
    const double before = LabDistance(col(0), col(i)) * 1.0;
    const double after = i == 1 ? 0.0 : LabDistance(col(1), col(i)) * fromOne[i];
    colorError += std::abs(before - after);
  }
  const double expected = (1.0 + 1.0 / Sqrt3) * (1.0 + importance) * (1.0 + colorError);
  CD_CHECK_NEAR(decimator.CollapseCost(0, 1), expected, 1e-5);

  // The RGB cost differs (the space matters).
  Decimator rgb{ DecimatorOptions() };
  rgb.Run(PyramidInput(PyramidPoints), 4);
  CD_CHECK(std::abs(rgb.CollapseCost(0, 1) - expected) > 1e-3);

  // The colour quadric measures colour in CIELab too: w = 1 with Lab / 100 coordinates.
  DecimatorOptions quadric;
  quadric.Metric = ErrorMetric::ColorQuadric;
  quadric.Space = ColorSpace::CIELab;
  Decimator lab(quadric);
  lab.Run(PyramidInput(PyramidPoints), 4);
  quadric.Space = ColorSpace::RGB;
  Decimator plain(quadric);
  plain.Run(PyramidInput(PyramidPoints), 4);
  CD_CHECK(std::abs(lab.CollapseCost(0, 1) - plain.CollapseCost(0, 1)) > 1e-4);
  CD_CHECK_NEAR(plain.CollapseCost(0, 1), PyramidQuadricCost(0, 1, 1.0), 1e-6);
}

//------------------------------------------------------------------------------
// Decimations.

vtkIdTypeArray* OriginalIdArray(vtkPolyData* output)
{
  return vtkIdTypeArray::SafeDownCast(output->GetPointData()->GetArray("vtkOriginalPointIds"));
}

/// Checks of a decimation whose surviving vertices may have moved (OptimalPlacement):
/// target met, CheckDecimatedMesh but for the moved points (2-manifold with the input's Euler
/// characteristic and orientation, no degenerate or flipped triangle, cell data copied), and
/// the point data of the points. Returns the number of moved points.
long long CheckPlacedDecimation(vtkPolyData* input, const RunResult& r, double reduction,
                                const Expectation& expected, const std::string& label)
{
  const vtkIdType in = input->GetNumberOfPolys();
  const vtkIdType out = r.Output->GetNumberOfPolys();
  CD_CHECK_MSG(r.Errors == 0 && r.Warnings == 0,
               label << ": unexpected messages: " << r.ErrorText() << r.WarningText());
  CD_CHECK_MSG(std::abs(r.ActualReduction - reduction) <= 0.01,
               label << ": actual reduction " << r.ActualReduction);
  CD_CHECK_NEAR(r.ActualReduction, 1.0 - double(out) / double(in), 1e-12);
  CD_CHECK_MSG(r.Collapses == input->GetNumberOfPoints() - r.Output->GetNumberOfPoints(),
               label << ": " << r.Collapses << " collapses");
  Expectation placed = expected;
  placed.PointsMove = true;
  CheckDecimatedMesh(input, r.Output, placed, label);

  // Points that did not move keep everything bit-exactly; moved points keep every point
  // array but the colours (copied from their surviving input vertex).
  vtkIdTypeArray* ids = OriginalIdArray(r.Output);
  CD_CHECK(ids != nullptr);
  if (!ids)
  {
    return 0;
  }
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = r.Output->GetPointData();
  vtkDataArray* colours = inPD->GetScalars();
  long long moved = 0;
  for (vtkIdType i = 0; i < r.Output->GetNumberOfPoints(); ++i)
  {
    const vtkIdType source = ids->GetValue(i);
    double p[3], q[3];
    r.Output->GetPoint(i, p);
    input->GetPoint(source, q);
    const bool same = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    moved += same ? 0 : 1;
    for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* ia = inPD->GetArray(a);
      if (!ia || (!same && ia == colours))
      {
        continue;
      }
      vtkDataArray* oa = outPD->GetArray(ia->GetName());
      CD_CHECK(oa != nullptr);
      if (!oa)
      {
        continue;
      }
      for (int k = 0; k < ia->GetNumberOfComponents(); ++k)
      {
        const double x = ia->GetComponent(source, k);
        const double y = oa->GetComponent(i, k);
        CD_CHECK_MSG((x == y) || (std::isnan(x) && std::isnan(y)),
                     label << ": point " << i << " array " << ia->GetName());
      }
    }
  }
  return moved;
}

/// The colour quadric as the paper compares against it (no boundary planes).
void ConfigureQuadric(vtkColorHalfEdgeDecimation* f, bool placement)
{
  f->SetPaperDefaults();
  f->SetErrorMetricToColorQuadric();
  f->SetOptimalPlacement(placement);
}

CD_TEST_CASE(InvariantsColorQuadric)
{
  auto configure = [](vtkColorHalfEdgeDecimation* f) { ConfigureQuadric(f, false); };
  CheckDecimations(meshes::Icosphere(5, Pattern::SharpRegions), ClosedSurface(2, SphereNormal),
                   "ColorQuadric Icosphere(5)", configure);
  CheckDecimations(meshes::Torus(120, 48, Pattern::FineDetail), ClosedSurface(0, TorusNormal),
                   "ColorQuadric Torus(120,48)", configure);
  CheckDecimations(meshes::Grid(80, 60, Pattern::SmoothGradient), OpenSheet(),
                   "ColorQuadric Grid(80,60)", configure);
}

/// One triangle (0,0,0), (1,0,0), (0,1,0) with the linear colour field R = x, G = y, B = 0.5.
struct RampTriangle
{
  std::vector<int32_t> Triangles = { 0, 1, 2 };
  std::vector<float> Positions = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  std::vector<float> Colors = { 0, 0, 0.5f, 1, 0, 0.5f, 0, 1, 0.5f };
  HalfEdgeMesh Mesh;
  RampTriangle() { this->Mesh.Build(3, this->Triangles.data(), 1); }
  /// The engine's vertex records of the corners (the quadrics' constants 0, as at the start).
  Buffer<HotVertex> Hot() const
  {
    Buffer<HotVertex> hot;
    hot.resize(3);
    for (int v = 0; v < 3; ++v)
    {
      for (int k = 0; k < 3; ++k)
      {
        hot[v].P[k] = this->Positions[3 * v + k];
        hot[v].C[k] = this->Colors[3 * v + k];
      }
      hot[v].QC = hot[v].Spare = 0;
    }
    return hot;
  }
};

CD_TEST_CASE(AttributeQuadricTriangle)
{
  // Centred at a corner, the quadric is area * (dz^2 + (dx - dR)^2 + (dy - dG)^2 + dB^2):
  // the squared distance to the plane z = 0 plus the squared difference from the field.
  RampTriangle t;
  Buffer<AttributeQuadric> q;
  InitializeAttributeQuadrics(t.Mesh, t.Positions.data(), 3, t.Colors.data(), 3, 1.0,
                              AttributeQuadricWeights(), q);
  CD_CHECK(q.size() == 3);
  const double onField[3] = { 1, 0, 0 }, field[3] = { 1, 0, 0 };
  const double up[3] = { 0, 0, 2 }, none[3] = { 0, 0, 0 };
  const double step[3] = { 0.3, 0.2, 0 }, blue[3] = { 0, 0, 0.5 };
  for (int v = 0; v < 3; ++v) // the field is linear: the same function at every corner
  {
    CD_CHECK_NEAR(q[v].Evaluate(onField, field), 0.0, 1e-12);
    CD_CHECK_NEAR(q[v].Evaluate(up, none), 0.5 * 4.0, 1e-6);
    CD_CHECK_NEAR(q[v].Evaluate(step, blue), 0.5 * (0.09 + 0.04 + 0.25), 1e-6);
    CD_CHECK_NEAR(q[v].W, 0.5, 1e-7);
  }
  // Colour scaled by 2: the colour differences count twice, on a field twice as steep.
  InitializeAttributeQuadrics(t.Mesh, t.Positions.data(), 3, t.Colors.data(), 3, 2.0,
                              AttributeQuadricWeights(), q);
  const double doubled[3] = { 0.6, 0.4, 0.0 }; // B is constant
  CD_CHECK_NEAR(q[0].Evaluate(step, doubled), 0.0, 1e-6);
  CD_CHECK_NEAR(q[0].Evaluate(step, blue), 0.5 * (0.36 + 0.16 + 0.25), 1e-6);
}

CD_TEST_CASE(AttributeQuadricWeights)
{
  // Vertex 0 lies on the boundary edges 0-1 (along x: its plane is y = 0) and 2-0 (x = 0),
  // each of squared length 1: an in-plane offset on the field costs bw (dx^2 + dy^2). The
  // edge-length term adds el * area * |d|^2; the geometry weight scales the plane term.
  RampTriangle t;
  Buffer<AttributeQuadric> q;
  AttributeQuadricWeights weights;
  weights.Boundary = 7.0;
  InitializeAttributeQuadrics(t.Mesh, t.Positions.data(), 3, t.Colors.data(), 3, 1.0, weights, q);
  const double step[3] = { 0.3, 0.2, 0 }, onField[3] = { 0.3, 0.2, 0 };
  CD_CHECK_NEAR(q[0].Evaluate(step, onField), 7.0 * (0.09 + 0.04), 1e-6);
  weights.Boundary = 0;
  weights.EdgeLength = 2.0;
  weights.Geometry = 3.0;
  InitializeAttributeQuadrics(t.Mesh, t.Positions.data(), 3, t.Colors.data(), 3, 1.0, weights, q);
  const double lifted[3] = { 0.3, 0.2, 0.5 };
  CD_CHECK_NEAR(q[0].Evaluate(lifted, onField), 0.5 * (3.0 * 0.25 + 2.0 * (0.09 + 0.04 + 0.25)),
                1e-6);
}

CD_TEST_CASE(AttributeQuadricShift)
{
  // AddShifted re-centres: (r + q shifted by d)(e) = r(e) + q(e + d), for any offsets.
  RampTriangle t;
  Buffer<AttributeQuadric> q;
  std::vector<float> colors = { 0.1f, 0.7f, 0.2f, 0.9f, 0.3f, 0.4f, 0.5f, 0.5f, 0.8f };
  std::vector<float> positions = { 0, 0, 0, 1, 0.2f, 0.1f, 0.3f, 1, -0.2f };
  InitializeAttributeQuadrics(t.Mesh, positions.data(), 3, colors.data(), 3, 1.0,
                              AttributeQuadricWeights(), q);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial)
  {
    double dx[3], ds[3], ex[3], es[3];
    for (int k = 0; k < 3; ++k)
    {
      dx[k] = offset(random);
      ds[k] = offset(random);
      ex[k] = offset(random);
      es[k] = offset(random);
    }
    AttributeQuadric sum = q[1];
    sum.AddShifted(q[0], dx, ds);
    const double shifted[3] = { ex[0] + dx[0], ex[1] + dx[1], ex[2] + dx[2] };
    const double shiftedColor[3] = { es[0] + ds[0], es[1] + ds[1], es[2] + ds[2] };
    CD_CHECK_NEAR(sum.Evaluate(ex, es),
                  q[1].Evaluate(ex, es) + q[0].Evaluate(shifted, shiftedColor), 1e-5);
  }
}

/**
 * The constant a merge adds, other(d), is 0 in exact arithmetic when d lies in the planes of
 * `other`, and rounds to either side of it: the kept vertex's constant never falls (the
 * premise of the re-costing, docs/ALGORITHM.md section 6), for the geometric quadric, the
 * colour quadric and the attribute quadric. Random planes through the centre, shifts within
 * them; the test also asserts that rounding did go below 0 in some of them.
 */
CD_TEST_CASE(MergedConstantNeverFalls)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int negative[3] = { 0, 0, 0 }, fell[3] = { 0, 0, 0 };
  for (int trial = 0; trial < 2000; ++trial)
  {
    double n[3] = { unit(random), unit(random), unit(random) };
    const double a[3] = { unit(random), unit(random), unit(random) };
    // d = a - (a.n / n.n) n: in the plane through the centre with normal n.
    const double an = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const double d[3] = { a[0] - an / nn * n[0], a[1] - an / nn * n[1], a[2] - an / nn * n[2] };
    const double length = std::sqrt(nn);
    for (double& c : n)
    {
      c /= length;
    }
    Quadric plane, kept;
    plane.AddPlaneThroughCentre(n, 1.7);
    negative[0] += plane.Evaluate(d) < 0;
    kept.AddShifted(plane, d);
    fell[0] += kept.C < 0;
    // The colour quadric of the plane spanned by two unit vectors of R^6: d within it.
    double e1[6] = { n[0], n[1], n[2], 0, 0, 0 }, e2[6] = { 0, 0, 0, 0, 0, 0 };
    e2[3 + trial % 3] = 1;
    ColorQuadric colour, colourKept;
    colour.AddPlaneThroughCentre(e1, e2, 0.9);
    double d6[6] = { 0.7 * n[0], 0.7 * n[1], 0.7 * n[2], 0, 0, 0 };
    d6[3 + trial % 3] = unit(random);
    negative[1] += colour.Evaluate(d6) < 0;
    colourKept.AddShifted(colour, d6);
    fell[1] += colourKept.C < 0;
    // The attribute quadric: the plane term alone, d within the plane, no colour offset.
    AttributeQuadric attribute, attributeKept;
    attribute.AddPlane(n, 1.3);
    const double noColour[3] = { 0, 0, 0 };
    negative[2] += attribute.Evaluate(d, noColour) < 0;
    attributeKept.AddShifted(attribute, d, noColour);
    fell[2] += attributeKept.C < 0;
  }
  for (int k = 0; k < 3; ++k)
  {
    std::cout << "  quadric " << k << ": " << negative[k] << " of 2000 rounded below 0, " << fell[k]
              << " merged constants below 0" << std::endl;
    CD_CHECK_MSG(negative[k] > 0, "quadric " << k << ": rounding never went below 0");
    CD_CHECK_MSG(fell[k] == 0, "quadric " << k << ": a merged constant fell below 0");
  }
}

CD_TEST_CASE(AttributeQuadricPieceCost)
{
  // The ramp triangle as a piece, with BoundaryWeight 7 and EdgeLengthWeight 2 (its colours
  // lie on their linear field: no colour term). Summed over the three corners, at corner a:
  // the boundary planes of the edges not through a, 7 * |edge|^2 * distance^2 each, and
  // 2 * area * (|a - b|^2 + |a - c|^2). Corner 0: the hypotenuse's plane x + y = 1 (squared
  // length 2, distance^2 1/2) twice, 14, plus 2 * 0.5 * 2 = 16; corners 1 and 2: the plane
  // of a leg twice, 14, plus 2 * 0.5 * 3 = 17 (the merged quadric of collapsing the other two
  // into corner 0 says 16 too). The area each corner holds (0.5) travels to a: 0.5 * 2 = 1 at
  // corner 0, 0.5 * 3 = 1.5 at the others. The least is 17, at corner 0; the mean squared
  // distance moved 1 / 1.5.
  RampTriangle t;
  Buffer<HotVertex> hot = t.Hot();
  DecimatorOptions options;
  options.BoundaryWeight = 7.0;
  options.EdgeLengthWeight = 2.0;
  AttributeQuadricMetric metric(options);
  metric.Initialize(t.Mesh, Frame(), hot, true, 1);
  const int32_t piece[3] = { 0, 1, 2 };
  int32_t best = -1;
  double spread = -1;
  CD_CHECK_NEAR(metric.PieceCost(piece, 3, best, spread), 17.0, 1e-5);
  CD_CHECK(best == 0);
  CD_CHECK_NEAR(spread, 1.0 / 1.5, 1e-6);
  const int32_t rotated[3] = { 2, 1, 0 };
  CD_CHECK_NEAR(metric.PieceCost(rotated, 3, best, spread), 17.0, 1e-5);
  CD_CHECK(best == 0);
  metric.Merge(1, 0, false, {});
  metric.Merge(2, 0, false, {});
  CD_CHECK_NEAR(metric.States[0].C, 16.0, 1e-5);
}

CD_TEST_CASE(AttributeQuadricKeptVertexError)
{
  // The ramp triangle with BoundaryWeight 7 and EdgeLengthWeight 2, as above. Corner 1's
  // quadric at corner 0: the hypotenuse's plane (squared length 2, distance^2 1/2), 7, plus
  // 2 * 0.5 * |x0 - x1|^2 = 1: 8; corner 2's the same by symmetry. After 1 -> 0, corner 0 holds
  // the error 8 (its constant), and the cost of 2 -> 0 is Q2(x0) + k * 8 for
  // KeptVertexErrorWeight k: 8 (the error the collapse adds), 12, 16 (the total error).
  RampTriangle t;
  Buffer<HotVertex> hot = t.Hot();
  for (const double k : { 0.0, 0.5, 1.0 })
  {
    DecimatorOptions options;
    options.BoundaryWeight = 7.0;
    options.EdgeLengthWeight = 2.0;
    options.KeptVertexErrorWeight = k;
    AttributeQuadricMetric metric(options);
    metric.Initialize(t.Mesh, Frame(), hot, true, 1);
    Ring ring;
    AttributeQuadricMetric::Scratch scratch;
    const auto costTowards0 = [&](int32_t v0)
    {
      const double p[3] = { hot[0].P[0], hot[0].P[1], hot[0].P[2] };
      const double c[3] = { hot[0].C[0], hot[0].C[1], hot[0].C[2] };
      ring.Clear();
      ring.Add(0, p, c, true, hot[0].QC);
      ring.Pad();
      double costs[4];
      metric.CostRing(v0, true, ring, costs, scratch);
      return costs[0];
    };
    CD_CHECK_NEAR(costTowards0(1), 8.0, 1e-5); // corner 0 holds nothing yet: any k
    metric.Merge(1, 0, false, {});
    CD_CHECK_NEAR(hot[0].QC, 8.0, 1e-5);
    CD_CHECK_NEAR(costTowards0(2), 8.0 + k * 8.0, 1e-5);
    hot[0].QC = 0; // as initialised, for the next weight
  }
}

CD_TEST_CASE(AttributeQuadricSceneRelativeWeights)
{
  // The scale s = max(D / 270, 1) of a frame whose bounding-box diagonal is D mean edge
  // lengths: a box of 324 x 432 (diagonal 540) at mean edge length 1 gives 2, at 2 (Scale 0.5)
  // 1, at 4 (D = 135) 1 as well; a box without extent gives 1.
  Frame frame;
  frame.Hi[0] = 324;
  frame.Hi[1] = 432;
  CD_CHECK(SceneWeightScale(frame) == 2.0);
  Frame halved = frame;
  halved.Scale = 0.5;
  CD_CHECK(SceneWeightScale(halved) == 1.0);
  halved.Scale = 0.25;
  CD_CHECK(SceneWeightScale(halved) == 1.0);
  CD_CHECK(SceneWeightScale(Frame()) == 1.0);

  // With scene-relative weights and s = 2, the ramp triangle's quadrics are those of ColorWeight
  // 2 c and BoundaryWeight 4 b given as they are, bit for bit; and the cost of 1 -> 0 is the
  // hypotenuse's plane (squared length 2, distance^2 1/2) times 7 * 4, plus the edge-length
  // term 2 * 0.5 * |x0 - x1|^2 = 1 (the colours lie on their field): 29.
  RampTriangle t;
  Buffer<HotVertex> hot = t.Hot();
  DecimatorOptions relative;
  relative.ColorWeight = 3.0;
  relative.BoundaryWeight = 7.0;
  relative.EdgeLengthWeight = 2.0;
  relative.SceneRelativeWeights = true;
  DecimatorOptions given = relative;
  given.SceneRelativeWeights = false;
  given.ColorWeight = 6.0;
  given.BoundaryWeight = 28.0;
  // Whether two settings give the same quadrics, bit for bit, in a frame.
  const auto sameQuadrics =
    [&](const DecimatorOptions& a, const DecimatorOptions& b, const Frame& f)
  {
    AttributeQuadricMetric first(a), second(b);
    first.Initialize(t.Mesh, f, hot, true, 1);
    second.Initialize(t.Mesh, f, hot, true, 1);
    return std::memcmp(first.States.data(), second.States.data(), 3 * sizeof(AttributeQuadric)) ==
      0;
  };
  CD_CHECK(sameQuadrics(relative, given, frame));
  AttributeQuadricMetric scaled(relative);
  scaled.Initialize(t.Mesh, frame, hot, true, 1);
  const double p[3] = { hot[0].P[0], hot[0].P[1], hot[0].P[2] };
  const double c[3] = { hot[0].C[0], hot[0].C[1], hot[0].C[2] };
  Ring ring;
  ring.Add(0, p, c, true, hot[0].QC);
  ring.Pad();
  AttributeQuadricMetric::Scratch scratch;
  double costs[4];
  scaled.CostRing(1, true, ring, costs, scratch);
  CD_CHECK_NEAR(costs[0], 29.0, 1e-5);
  // Off, the weights apply as given: 7 + 1.
  relative.SceneRelativeWeights = false;
  AttributeQuadricMetric unscaled(relative);
  unscaled.Initialize(t.Mesh, frame, hot, true, 1);
  unscaled.CostRing(1, true, ring, costs, scratch);
  CD_CHECK_NEAR(costs[0], 8.0, 1e-5);

  // On a mesh at most 270 mean edge lengths across (here 135: Scale 1/4) the weights apply as
  // given: the quadrics of ColorWeight 3 and BoundaryWeight 7.
  Frame coarse = frame;
  coarse.Scale = 0.25;
  relative.SceneRelativeWeights = true;
  given.ColorWeight = 3.0;
  given.BoundaryWeight = 7.0;
  CD_CHECK(sameQuadrics(relative, given, coarse));
  CD_CHECK(!sameQuadrics(relative, given, frame)); // and the comparison can fail
}

/// The area of the output's triangles whose corners' red channel differs (on both sides of a
/// colour step), as a fraction of the output's area.
double StraddlingArea(vtkPolyData* mesh)
{
  vtkDataArray* colors = mesh->GetPointData()->GetScalars();
  double straddling = 0, total = 0;
  for (const Tri& t : GetTriangles(mesh))
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(t[k], p[k]);
    }
    const double area = TriangleArea3(p[0], p[1], p[2]);
    const double r0 = colors->GetComponent(t[0], 0);
    const bool mixed = colors->GetComponent(t[1], 0) != r0 || colors->GetComponent(t[2], 0) != r0;
    straddling += mixed ? area : 0;
    total += area;
  }
  return total > 0 ? straddling / total : 0;
}

CD_TEST_CASE(AttributeQuadricSeesColor)
{
  // A flat sheet whose colour jumps along a line: the geometric quadric cannot see the jump,
  // the attribute quadric keeps triangles from straddling it.
  auto sheet = meshes::FlatGrid(60, 60, Pattern::SharpRegions);
  auto run = [&sheet](int metric)
  {
    vtkNew<vtkColorHalfEdgeDecimation> f;
    f->SetInputData(sheet);
    f->SetErrorMetric(metric);
    f->SetBoundaryWeight(10);
    f->SetEdgeLengthWeight(0.001);
    f->SetTargetReduction(0.9);
    f->Update();
    vtkSmartPointer<vtkPolyData> out = f->GetOutput();
    return out;
  };
  const double geometry = StraddlingArea(run(vtkColorHalfEdgeDecimation::Geometry));
  const double attribute = StraddlingArea(run(vtkColorHalfEdgeDecimation::AttributeQuadric));
  std::cout << "straddling area: Geometry " << geometry << ", AttributeQuadric " << attribute
            << "\n";
  CD_CHECK_MSG(attribute < 0.5 * geometry, "the attribute quadric keeps the colour steps");
}

CD_TEST_CASE(InvariantsAttributeQuadric)
{
  auto configure = [](vtkColorHalfEdgeDecimation* f) { f->SetErrorMetricToAttributeQuadric(); };
  CheckDecimations(meshes::Icosphere(5, Pattern::SharpRegions), ClosedSurface(2, SphereNormal),
                   "AttributeQuadric Icosphere(5)", configure);
  CheckDecimations(meshes::Torus(120, 48, Pattern::FineDetail), ClosedSurface(0, TorusNormal),
                   "AttributeQuadric Torus(120,48)", configure);
  CheckDecimations(meshes::Grid(80, 60, Pattern::SmoothGradient), OpenSheet(),
                   "AttributeQuadric Grid(80,60)", configure);
}

CD_TEST_CASE(InvariantsColorQuadricPlacement)
{
  struct Case
  {
    vtkSmartPointer<vtkPolyData> Mesh;
    Expectation Expected;
    std::string Name;
    bool Sphere;
  };
  std::vector<Case> cases;
  cases.push_back({ meshes::Icosphere(5, Pattern::SharpRegions), ClosedSurface(2, SphereNormal),
                    "Icosphere(5) sharp", true });
  cases.push_back({ meshes::UVSphere(100, Pattern::SmoothGradient), ClosedSurface(2, SphereNormal),
                    "UVSphere(100) smooth", true });
  cases.push_back({ meshes::Torus(120, 48, Pattern::FineDetail), ClosedSurface(0, TorusNormal),
                    "Torus(120,48) fine", false });
  cases.push_back(
    { meshes::Grid(80, 60, Pattern::SharpRegions), OpenSheet(), "Grid(80,60)", false });
  for (Case& c : cases)
  {
    Decorate(c.Mesh);
    for (double reduction : { 0.5, 0.9, 0.97 })
    {
      std::ostringstream label;
      label << "placement " << c.Name << " at " << reduction;
      const RunResult r = Decimate(
        c.Mesh, reduction, [](vtkColorHalfEdgeDecimation* f) { ConfigureQuadric(f, true); });
      const long long moved = CheckPlacedDecimation(c.Mesh, r, reduction, c.Expected, label.str());
      std::cout << "  " << label.str() << ": " << r.Output->GetNumberOfPolys() << " triangles, "
                << moved << " of " << r.Output->GetNumberOfPoints() << " points moved" << std::endl;
      CD_CHECK_MSG(moved > r.Output->GetNumberOfPoints() / 20, label.str() << ": few moved");
      if (c.Sphere)
      {
        // Optimal points stay near the sphere (they lie on or just outside it: the planes
        // of a convex surface meet outside it).
        for (vtkIdType i = 0; i < r.Output->GetNumberOfPoints(); ++i)
        {
          double p[3];
          r.Output->GetPoint(i, p);
          const double radius = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
          CD_CHECK_MSG(radius > 0.97 && radius < 1.05, label.str() << ": radius " << radius);
        }
      }
    }
  }
}

/**
 * A flat n x n grid of unit squares in z = 0, coloured by `colour(i / n, j / n)` at its point
 * (i, j): meshes::FlatGrid scaled from [-1,1]^2 to [0,n]^2, with float points (at integers).
 */
vtkSmartPointer<vtkPolyData> UnitSquareGrid(int n, void (*colour)(double, double, unsigned char*))
{
  const double half = 0.5 * n, shift[3] = { half, half, 0 };
  auto grid = WithFloatPoints(Transformed(meshes::FlatGrid(n, n, Pattern::Constant), half, shift));
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType v = 0; v < grid->GetNumberOfPoints(); ++v)
  {
    const int i = static_cast<int>(v % (n + 1)), j = static_cast<int>(v / (n + 1));
    double p[3];
    grid->GetPoint(v, p);
    CD_CHECK(p[0] == i && p[1] == j && p[2] == 0);
    unsigned char c[3];
    colour(double(i) / n, double(j) / n, c);
    rgb->SetTypedTuple(v, c);
  }
  grid->GetPointData()->SetScalars(rgb);
  return grid;
}

void ConstantColour(double, double, unsigned char* c)
{
  c[0] = 40;
  c[1] = 120;
  c[2] = 200;
}

void RampColour(double x, double, unsigned char* c)
{
  c[0] = static_cast<unsigned char>(255 * x); // a multiple of 1/255 per column (n = 51)
  c[1] = 0;
  c[2] = 90;
}

CD_TEST_CASE(PlacementFallback)
{
  // On a flat patch with a constant colour or a linear ramp every vertex's quadric has the
  // same plane of R^6: every 6x6 system is singular, so every collapse falls back to an
  // endpoint: every output point is an input point (the surviving one on the constant
  // patch, where both endpoints cost the same).
  for (auto colour : { ConstantColour, RampColour })
  {
    auto grid = UnitSquareGrid(51, colour);
    Decorate(grid);
    const RunResult r =
      Decimate(grid, 0.9, [](vtkColorHalfEdgeDecimation* f) { ConfigureQuadric(f, true); });
    Expectation e = OpenSheet();
    const long long moved = CheckPlacedDecimation(grid, r, 0.9, e, "flat grid");
    if (colour == ConstantColour)
    {
      CD_CHECK_MSG(moved == 0, moved << " points moved on a flat constant patch");
    }
    for (vtkIdType i = 0; i < r.Output->GetNumberOfPoints(); ++i)
    {
      double p[3];
      r.Output->GetPoint(i, p);
      // Grid points are integers; the frame's float rounding is far below 1e-4 here.
      CD_CHECK_MSG(std::abs(p[2]) < 1e-4 && std::abs(p[0] - std::round(p[0])) < 1e-4 &&
                     std::abs(p[1] - std::round(p[1])) < 1e-4 && p[0] > -0.5 && p[0] < 51.5 &&
                     p[1] > -0.5 && p[1] < 51.5,
                   "not an input point: " << p[0] << ", " << p[1] << ", " << p[2]);
    }
  }
}

/// The icosphere with its colours as a `T` array mapped by value = offset + scale * rgb/255.
template <typename ArrayT>
vtkSmartPointer<vtkPolyData> WithColourArray(vtkPolyData* mesh, double offset, double scale,
                                             int components)
{
  auto copy = Copy(mesh);
  auto* uc = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetScalars());
  vtkNew<ArrayT> colours;
  colours->SetName("Colours");
  colours->SetNumberOfComponents(components);
  colours->SetNumberOfTuples(uc->GetNumberOfTuples());
  for (vtkIdType i = 0; i < uc->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      colours->SetComponent(i, k, offset + scale * uc->GetComponent(i, k) / 255.0);
    }
    if (components == 4)
    {
      colours->SetComponent(i, 3, 77);
    }
  }
  copy->GetPointData()->SetScalars(colours);
  return copy;
}

// A one-component field (a temperature) that is linear on a flat sheet, T = 2x + 3y + 5: the
// colour quadric of every triangle holds that linear relation exactly, so full collapses place
// each moved survivor where T is still that function of its new position, for either schedule.
CD_TEST_CASE(PlacementLinearField)
{
  auto sheet = meshes::FlatGrid(40, 40, Pattern::Constant);
  sheet->GetPointData()->Initialize();
  vtkNew<vtkFloatArray> field;
  field->SetName("Temperature");
  field->SetNumberOfTuples(sheet->GetNumberOfPoints());
  const auto linear = [](const double p[3]) { return 2.0 * p[0] + 3.0 * p[1] + 5.0; };
  for (vtkIdType i = 0; i < sheet->GetNumberOfPoints(); ++i)
  {
    double p[3];
    sheet->GetPoint(i, p);
    field->SetValue(i, static_cast<float>(linear(p)));
  }
  sheet->GetPointData()->SetScalars(field);
  double range[2];
  field->GetRange(range);
  for (const int schedule :
       { vtkColorHalfEdgeDecimation::Greedy, vtkColorHalfEdgeDecimation::Batched })
  {
    const RunResult r = Decimate(sheet, 0.9,
                                 [schedule](vtkColorHalfEdgeDecimation* f)
                                 {
                                   f->SetErrorMetricToColorQuadric();
                                   f->OptimalPlacementOn();
                                   f->SetCollapseSchedule(schedule);
                                 });
    Expectation sheetKept = OpenSheet();
    sheetKept.Decorated = false;
    const long long moved = CheckPlacedDecimation(sheet, r, 0.9, sheetKept, "linear field");
    vtkDataArray* out = r.Output->GetPointData()->GetArray("Temperature");
    CD_CHECK(out && out->GetNumberOfComponents() == 1);
    if (!out)
    {
      return;
    }
    double worst = 0.0;
    for (vtkIdType i = 0; i < r.Output->GetNumberOfPoints(); ++i)
    {
      double p[3];
      r.Output->GetPoint(i, p);
      worst = std::max(worst, std::abs(out->GetComponent(i, 0) - linear(p)));
    }
    std::cout << "  schedule " << schedule << ": " << moved << " of "
              << r.Output->GetNumberOfPoints() << " points moved, largest |T - (2x + 3y + 5)| "
              << worst << " (range " << range[1] - range[0] << ")" << std::endl;
    CD_CHECK(moved > 0);
    CD_CHECK(worst <= 1e-4 * (range[1] - range[0]));
  }
}

CD_TEST_CASE(PlacementColorArrays)
{
  // Sharp regions with pure 0 and 255 channels: the float array spans [0,1] exactly, the
  // double array [0, 1000] (mapped by its range, written back through the inverse), so both
  // decimate alike and the written colours agree up to the scale.
  auto sphere = meshes::Icosphere(4, Pattern::SharpRegions);
  auto* uc = vtkUnsignedCharArray::SafeDownCast(sphere->GetPointData()->GetScalars());
  const unsigned char black[3] = { 0, 0, 0 };
  const unsigned char white[3] = { 255, 255, 255 };
  uc->SetTypedTuple(0, black);
  uc->SetTypedTuple(1, white);
  double range[2] = { 255, 0 };
  for (int k = 0; k < 3; ++k)
  {
    double r[2];
    uc->GetRange(r, k);
    range[0] = std::min(range[0], r[0]);
    range[1] = std::max(range[1], r[1]);
  }
  CD_CHECK(range[0] == 0 && range[1] == 255);
  auto floats = WithColourArray<vtkFloatArray>(sphere, 0.0, 1.0, 3);
  auto doubles = WithColourArray<vtkDoubleArray>(sphere, 0.0, 1000.0, 3);
  auto rgba = WithColourArray<vtkUnsignedCharArray>(sphere, 0.0, 255.0, 4);
  auto place = [](vtkColorHalfEdgeDecimation* f) { ConfigureQuadric(f, true); };
  const RunResult rf = Decimate(floats, 0.9, place);
  const RunResult rd = Decimate(doubles, 0.9, place);
  const RunResult ru = Decimate(sphere, 0.9, place);
  const RunResult ra = Decimate(rgba, 0.9, place);
  CD_CHECK(rf.Errors == 0 && rd.Errors == 0 && ru.Errors == 0 && ra.Errors == 0);
  CD_CHECK(rf.Output->GetNumberOfPoints() == rd.Output->GetNumberOfPoints());
  CD_CHECK(rf.Output->GetNumberOfPoints() == ru.Output->GetNumberOfPoints());
  vtkDataArray* of = rf.Output->GetPointData()->GetArray("Colours");
  vtkDataArray* od = rd.Output->GetPointData()->GetArray("Colours");
  vtkDataArray* ou = ru.Output->GetPointData()->GetArray("RGB");
  vtkDataArray* oa = ra.Output->GetPointData()->GetArray("Colours");
  CD_CHECK(of && od && ou && oa);
  if (!of || !od || !ou || !oa)
  {
    return;
  }
  CD_CHECK(of->GetDataType() == VTK_FLOAT && od->GetDataType() == VTK_DOUBLE);
  vtkIdTypeArray* ids = OriginalIdArray(rf.Output);
  long long blended = 0;
  const vtkIdType n = std::min(rf.Output->GetNumberOfPoints(), rd.Output->GetNumberOfPoints());
  for (vtkIdType i = 0; i < n; ++i)
  {
    bool differs = false;
    for (int k = 0; k < 3; ++k)
    {
      const double f = of->GetComponent(i, k);
      CD_CHECK(f >= 0.0 && f <= 1.0);
      CD_CHECK_NEAR(od->GetComponent(i, k), 1000.0 * f, 1e-3);
      // uchar: the same colour times 255, rounded.
      if (i < ru.Output->GetNumberOfPoints())
      {
        CD_CHECK(std::abs(ou->GetComponent(i, k) - 255.0 * f) <= 0.5 + 1e-4);
      }
      const double original = uc->GetComponent(ids->GetValue(i), k) / 255.0;
      differs = differs || std::abs(f - original) > 1e-6;
    }
    blended += differs ? 1 : 0;
  }
  std::cout << "  " << blended << " of " << n << " output colours are new" << std::endl;
  CD_CHECK(blended > 0);
  // RGBA: the alpha is carried, never blended.
  for (vtkIdType i = 0; i < ra.Output->GetNumberOfPoints(); ++i)
  {
    CD_CHECK(oa->GetComponent(i, 3) == 77);
  }
}

CD_TEST_CASE(PlacementPreserveBoundary)
{
  // With PreserveBoundary, boundary points are neither removed nor moved.
  auto grid = meshes::Grid(60, 50, Pattern::SharpRegions);
  const std::set<std::pair<vtkIdType, vtkIdType>> boundary = BoundaryEdges(GetTriangles(grid));
  std::set<vtkIdType> boundaryPoints;
  for (const auto& e : boundary)
  {
    boundaryPoints.insert(e.first);
    boundaryPoints.insert(e.second);
  }
  const RunResult r = Decimate(grid, 0.9,
                               [](vtkColorHalfEdgeDecimation* f)
                               {
                                 ConfigureQuadric(f, true);
                                 f->PreserveBoundaryOn();
                               });
  vtkIdTypeArray* ids = OriginalIdArray(r.Output);
  CD_CHECK(ids != nullptr);
  if (!ids)
  {
    return;
  }
  std::set<vtkIdType> kept;
  for (vtkIdType i = 0; i < r.Output->GetNumberOfPoints(); ++i)
  {
    const vtkIdType source = ids->GetValue(i);
    if (boundaryPoints.count(source))
    {
      kept.insert(source);
      double p[3], q[3];
      r.Output->GetPoint(i, p);
      grid->GetPoint(source, q);
      CD_CHECK_MSG(p[0] == q[0] && p[1] == q[1] && p[2] == q[2],
                   "boundary point " << source << " moved");
    }
  }
  CD_CHECK(kept.size() == boundaryPoints.size());
  CD_CHECK(r.ActualReduction > 0.85);
}

CD_TEST_CASE(InvariantsCIELab)
{
  auto lab = [](vtkColorHalfEdgeDecimation* f) { f->SetColorSpaceToCIELab(); };
  CheckDecimations(meshes::Icosphere(5, Pattern::SharpRegions), ClosedSurface(2, SphereNormal),
                   "CIELab Icosphere(5)", lab);
  CheckDecimations(meshes::Grid(80, 60, Pattern::FineDetail), OpenSheet(), "CIELab Grid(80,60)",
                   lab);
  auto labQuadric = [](vtkColorHalfEdgeDecimation* f)
  {
    f->SetColorSpaceToCIELab();
    f->SetErrorMetricToColorQuadric();
  };
  CheckDecimations(meshes::Torus(120, 48, Pattern::FineDetail), ClosedSurface(0, TorusNormal),
                   "CIELab ColorQuadric Torus(120,48)", labQuadric);
  // With placement, the colours written back come from CIELab: in range, and new ones.
  auto torus = meshes::Torus(120, 48, Pattern::FineDetail);
  Decorate(torus);
  const RunResult placed = Decimate(torus, 0.9,
                                    [](vtkColorHalfEdgeDecimation* f)
                                    {
                                      ConfigureQuadric(f, true);
                                      f->SetColorSpaceToCIELab();
                                    });
  CD_CHECK(CheckPlacedDecimation(torus, placed, 0.9, ClosedSurface(0, TorusNormal),
                                 "CIELab placement torus") > 0);

  // CIELab is not RGB: the kept vertices differ on a colourful mesh.
  auto fine = meshes::Torus(120, 48, Pattern::FineDetail);
  const RunResult a = Decimate(fine, 0.9);
  const RunResult b = Decimate(fine, 0.9, lab);
  CD_CHECK(OriginalIds(a.Output) != OriginalIds(b.Output));
}

//------------------------------------------------------------------------------
CD_TEST_CASE(RulesNewPosition)
{
  // CheckGeometry with a new position for the merged vertex. At p1 it is the half-edge check;
  // at p0 v0's triangles do not move, and v1's triangles move onto p0: exactly the check of
  // the reverse half-edge collapse v1 -> v0. On a noisy sphere both verdicts occur.
  auto sphere = meshes::Icosphere(2, Pattern::Constant);
  const std::vector<int32_t> triangles = ToPlain(sphere).Triangles;
  const int32_t n = static_cast<int32_t>(sphere->GetNumberOfPoints());
  std::vector<float> positions(3 * n);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> noise(0.75, 1.25);
  for (int32_t v = 0; v < n; ++v)
  {
    double p[3];
    sphere->GetPoint(v, p);
    const double r = noise(random);
    for (int k = 0; k < 3; ++k)
    {
      positions[3 * v + k] = static_cast<float>(r * p[k]);
    }
  }
  HalfEdgeMesh mesh;
  mesh.Build(n, triangles.data(), static_cast<int32_t>(triangles.size() / 3));
  CollapseRuleOptions options;
  options.MinimumNormalCosine = std::cos(30.0 * 3.14159265358979 / 180.0);
  CollapseRules rules(options);
  int legal = 0, refused = 0;
  for (size_t t = 0; t < triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int32_t v0 = triangles[t + k], v1 = triangles[t + (k + 1) % 3];
      const float* f0 = &positions[3 * v0];
      const float* f1 = &positions[3 * v1];
      const double p0[3] = { f0[0], f0[1], f0[2] };
      const double p1[3] = { f1[0], f1[1], f1[2] };
      const CollapseVerdict forward = rules.CheckGeometry(mesh, positions.data(), v0, v1);
      const CollapseVerdict backward = rules.CheckGeometry(mesh, positions.data(), v1, v0);
      CD_CHECK(rules.CheckGeometry(mesh, positions.data(), v0, v1, 3, p1) == forward);
      CD_CHECK(rules.CheckGeometry(mesh, positions.data(), v0, v1, 3, p0) == backward);
      CD_CHECK(rules.Check(mesh, positions.data(), v0, v1, 3, p1) ==
               rules.Check(mesh, positions.data(), v0, v1));
      (forward == CollapseVerdict::Legal ? legal : refused) += 1;
      // A point three edge lengths beyond v1 turns some triangle of v1 too far.
      double far[3];
      for (int c = 0; c < 3; ++c)
      {
        far[c] = p1[c] + 3.0 * (p1[c] - p0[c]);
      }
      CD_CHECK(rules.CheckGeometry(mesh, positions.data(), v0, v1, 3, far) !=
               CollapseVerdict::Legal);
    }
  }
  std::cout << "  " << legal << " legal, " << refused << " refused half-edge collapses"
            << std::endl;
  CD_CHECK(legal > 10 && refused > 10);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(BoundaryQuadric)
{
  // The paper's 10-float quadric with boundary planes (BoundaryWeight): on the flat square,
  // vertex 1 lies on the boundary edges 0-1 (along x: its plane is perpendicular to y) and
  // 1-2 (along y: perpendicular to x), each of squared length 1, so an in-plane offset
  // (dx, dy) costs w (dx^2 + dy^2); without the weight it costs nothing (the triangles' own
  // plane is z = 0). A normal offset dz costs the area of its triangles, 1/2.
  Square square;
  std::vector<VertexMetric> metrics;
  const double inPlane[3] = { 0.3, -0.2, 0 };
  const double normal[3] = { 0, 0, 0.5 };
  InitializeVertexMetrics(square.Mesh, square.Positions.data(), nullptr, metrics);
  CD_CHECK_NEAR(metrics[1].Q.Evaluate(inPlane), 0.0, 1e-12);
  CD_CHECK_NEAR(metrics[1].Q.Evaluate(normal), 0.5 * 0.25, 1e-7);
  InitializeVertexMetrics(square.Mesh, square.Positions.data(), nullptr, metrics, 3, 3, 7.0);
  CD_CHECK_NEAR(metrics[1].Q.Evaluate(inPlane), 7.0 * (0.09 + 0.04), 1e-6);
  CD_CHECK_NEAR(metrics[1].Q.Evaluate(normal), 0.5 * 0.25, 1e-7);
  // Vertex 2: edges 1-2 (along y) and 2-3 (along x) too; the diagonal 0-2 is interior.
  CD_CHECK_NEAR(metrics[2].Q.Evaluate(inPlane), 7.0 * (0.09 + 0.04), 1e-6);
  // Along one boundary edge only: vertex 1 moving along x stays on edge 0-1's line but
  // leaves edge 1-2's plane.
  const double alongX[3] = { 0.4, 0, 0 };
  CD_CHECK_NEAR(metrics[1].Q.Evaluate(alongX), 7.0 * 0.16, 1e-6);
}

/// The output points' bounding box in x and y against the input's.
double BoxShrink(vtkPolyData* input, vtkPolyData* output)
{
  double a[6], b[6];
  input->GetBounds(a);
  output->GetBounds(b);
  return std::max({ b[0] - a[0], a[1] - b[1], b[2] - a[2], a[3] - b[3] });
}

CD_TEST_CASE(BoundaryWeight)
{
  // The open grid's square outline: with boundary planes its corners cannot be cut (that
  // would move the outline by a whole edge against a weight of 100), for every metric.
  auto grid = meshes::Grid(60, 50, Pattern::SharpRegions);
  Decorate(grid);
  for (int metric :
       { vtkColorHalfEdgeDecimation::HalfEdgeColor, vtkColorHalfEdgeDecimation::Geometry,
         vtkColorHalfEdgeDecimation::ColorQuadric })
  {
    for (bool placement : { false, true })
    {
      if (placement && metric != vtkColorHalfEdgeDecimation::ColorQuadric)
      {
        continue;
      }
      std::ostringstream label;
      label << "metric " << metric << (placement ? " placement" : "") << " BoundaryWeight 100";
      const RunResult r = Decimate(grid, 0.9,
                                   [&](vtkColorHalfEdgeDecimation* f)
                                   {
                                     f->SetErrorMetric(metric);
                                     f->SetOptimalPlacement(placement);
                                     f->SetBoundaryWeight(100);
                                   });
      CD_CHECK_MSG(std::abs(r.ActualReduction - 0.9) <= 0.01, label.str());
      const double shrink = BoxShrink(grid, r.Output);
      std::cout << "  " << label.str() << ": outline moved in by " << shrink << std::endl;
      // Full collapses place the corners at the optimum of all their planes: within 1e-4
      // (the grid's edges are 0.03 long), not exactly.
      CD_CHECK_MSG(shrink < (placement ? 1e-4 : 1e-9),
                   label.str() << ": outline moved in by " << shrink);
      if (!placement)
      {
        CheckDecimatedMesh(grid, r.Output, OpenSheet(), label.str());
      }
    }
  }
  // The weight changes the result (and BoundaryWeight 0 is the paper's metric).
  const auto paper = [](vtkColorHalfEdgeDecimation* f) { f->SetPaperDefaults(); };
  const RunResult plain = Decimate(grid, 0.9, paper);
  const RunResult placedPlain =
    Decimate(grid, 0.9, [](vtkColorHalfEdgeDecimation* f) { ConfigureQuadric(f, true); });
  std::cout << "  without BoundaryWeight: outline moved in by " << BoxShrink(grid, plain.Output)
            << " (HalfEdgeColor), " << BoxShrink(grid, placedPlain.Output)
            << " (ColorQuadric, placement)" << std::endl;
  CD_CHECK(BoxShrink(grid, placedPlain.Output) > 1e-3);
  const RunResult weighted = Decimate(grid, 0.9,
                                      [](vtkColorHalfEdgeDecimation* f)
                                      {
                                        f->SetPaperDefaults();
                                        f->SetBoundaryWeight(100);
                                      });
  CD_CHECK(OriginalIds(plain.Output) != OriginalIds(weighted.Output));
  // The defaults keep the outline too (boundary planes on).
  const RunResult defaults = Decimate(grid, 0.9);
  CD_CHECK_MSG(BoxShrink(grid, defaults.Output) < 1e-9,
               "the defaults moved the outline in by " << BoxShrink(grid, defaults.Output));
}

//------------------------------------------------------------------------------
CD_TEST_CASE(Properties)
{
  vtkNew<vtkColorHalfEdgeDecimation> f;
  CD_CHECK(f->GetErrorMetric() == vtkColorHalfEdgeDecimation::AttributeQuadric);
  CD_CHECK(f->GetColorSpace() == vtkColorHalfEdgeDecimation::RGB);
  CD_CHECK(!f->GetOptimalPlacement());
  CD_CHECK(f->GetColorWeight() == defaults::ColorWeight);
  CD_CHECK(f->GetBoundaryWeight() == defaults::BoundaryWeight);
  CD_CHECK(f->GetEdgeLengthWeight() == defaults::EdgeLengthWeight);
  f->SetEdgeLengthWeight(-1);
  CD_CHECK(f->GetEdgeLengthWeight() == 0.0);
  CD_CHECK(f->GetKeptVertexErrorWeight() == defaults::KeptVertexErrorWeight);
  f->SetKeptVertexErrorWeight(-1);
  CD_CHECK(f->GetKeptVertexErrorWeight() == 0.0);
  f->SetKeptVertexErrorWeight(3);
  CD_CHECK(f->GetKeptVertexErrorWeight() == 1.0);
  f->SetBoundaryWeight(-1);
  CD_CHECK(f->GetBoundaryWeight() == 0.0);
  f->SetBoundaryWeight(250);
  f->SetErrorMetricToColorQuadric();
  CD_CHECK(f->GetErrorMetric() == 2);
  CD_CHECK(std::string(f->GetErrorMetricAsString()) == "ColorQuadric");
  f->SetErrorMetric(7);
  CD_CHECK(f->GetErrorMetric() == vtkColorHalfEdgeDecimation::AttributeQuadric);
  f->SetErrorMetricToAttributeQuadric();
  CD_CHECK(std::string(f->GetErrorMetricAsString()) == "AttributeQuadric");
  f->SetErrorMetricToGeometry();
  CD_CHECK(std::string(f->GetErrorMetricAsString()) == "Geometry");
  f->SetColorSpaceToCIELab();
  CD_CHECK(f->GetColorSpace() == 1);
  CD_CHECK(std::string(f->GetColorSpaceAsString()) == "CIELab");
  f->SetColorSpace(9);
  CD_CHECK(f->GetColorSpace() == vtkColorHalfEdgeDecimation::CIELab);
  f->SetColorSpaceToRGB();
  CD_CHECK(std::string(f->GetColorSpaceAsString()) == "RGB");
  f->OptimalPlacementOn();
  CD_CHECK(f->GetOptimalPlacement());
  f->SetColorWeight(-3);
  CD_CHECK(f->GetColorWeight() == 0.0);
  f->SetColorWeight(2.5);
  f->SetErrorMetricToColorQuadric();
  f->SetColorSpaceToCIELab();
  std::ostringstream os;
  f->Print(os);
  const std::string text = os.str();
  CD_CHECK(text.find("ErrorMetric: ColorQuadric") != std::string::npos);
  CD_CHECK(text.find("ColorSpace: CIELab") != std::string::npos);
  CD_CHECK(text.find("OptimalPlacement: On") != std::string::npos);
  CD_CHECK(text.find("ColorWeight: 2.5") != std::string::npos);
  CD_CHECK(text.find("BoundaryWeight: 250") != std::string::npos);
}

CD_TEST_CASE(StateMemory)
{
  // The colour quadric holds 28 floats per vertex instead of the paper's 12 (64 bytes more),
  // plus one byte of moved flag with placement.
  auto sphere = meshes::Icosphere(4, Pattern::SharpRegions);
  const vtkIdType n = sphere->GetNumberOfPoints();
  auto memory = [&](int metric, bool placement)
  {
    vtkNew<vtkColorHalfEdgeDecimation> f;
    f->SetInputData(sphere);
    f->SetErrorMetric(metric);
    f->SetOptimalPlacement(placement);
    f->Update();
    return static_cast<long long>(f->GetStateMemory());
  };
  const long long paper = memory(vtkColorHalfEdgeDecimation::HalfEdgeColor, false);
  const long long quadric = memory(vtkColorHalfEdgeDecimation::ColorQuadric, false);
  const long long placed = memory(vtkColorHalfEdgeDecimation::ColorQuadric, true);
  CD_CHECK_MSG(quadric - paper == 64 * n, quadric << " - " << paper << " for " << n << " points");
  CD_CHECK(placed - quadric == n);
}

} // namespace

int main(int argc, char* argv[])
{
  return RunTestCases(argc, argv);
}
