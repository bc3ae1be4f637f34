// Unit tests of the algorithm core (Filters/Core): cost terms against hand-computed values,
// the vertex heap against a reference, the corner table and the collapse rules.
#include "ColorDecimationTestUtilities.h"

#include "Decimator.h"
#include "engine/Engine.h"
#include "lod/CollapseRecord.h"
#include "mesh/Components.h"
#include "mesh/HalfEdgeMesh.h"
#include "mesh/Seams.h"
#include "mesh/SpatialOrder.h"
#include "metric/HalfEdgeColor.h"
#include "metric/Quadric.h"
#include "rules/CollapseRules.h"
#include "schedule/Selection.h"
#include "schedule/VertexHeap.h"
#include "util/Parallel.h"

#include "ColorDecimationMeshes.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

using namespace colordecimation;
using namespace colordecimation::testing;

namespace
{
const double Sqrt2 = std::sqrt(2.0);
const double Sqrt3 = std::sqrt(3.0);

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/**
 * The square pyramid (PyramidPoints, PyramidTriangles) for hand computations. Every one of
 * its 8 edges has length sqrt(2), so the normalised frame is: subtract the bounding-box centre
 * (0,0,1/2), divide by sqrt(2). Each face is equilateral with side 1 there (area sqrt(3)/4)
 * and its unit normal is (+-1,+-1,1)/sqrt(3).
 * Colours: apex black, ring (0.6,0,0), black, (0,0.8,0), black.
 */
const float PyramidColors[15] = { 0, 0, 0, 0.6f, 0, 0, 0, 0, 0, 0, 0.8f, 0, 0, 0, 0 };

//------------------------------------------------------------------------------
/// One plane through the centre, axis-aligned and oblique: Q(d) = w (n.d)^2 by hand.
void CheckQuadricOnePlane()
{
  Quadric q;
  const double nz[3] = { 0, 0, 1 };
  q.AddPlaneThroughCentre(nz, 2.0);
  const double d1[3] = { 1, 2, 3 };
  CD_CHECK_NEAR(q.Evaluate(d1), 18.0, 1e-12); // 2 * 3^2
  const double zero[3] = { 0, 0, 0 };
  CD_CHECK_NEAR(q.Evaluate(zero), 0.0, 1e-12);

  // An oblique plane exercises the off-diagonal terms: n = (0.6, 0.8, 0), w = 0.5.
  Quadric oblique;
  const double n2[3] = { 0.6, 0.8, 0 };
  oblique.AddPlaneThroughCentre(n2, 0.5);
  const double d2[3] = { 1, -2, 7 };
  // n.d = 0.6 - 1.6 = -1, so 0.5 * 1 = 0.5.
  CD_CHECK_NEAR(oblique.Evaluate(d2), 0.5, 1e-6);
  const double d3[3] = { 3, 4, -1 };
  // n.d = 1.8 + 3.2 = 5, so 0.5 * 25 = 12.5.
  CD_CHECK_NEAR(oblique.Evaluate(d3), 12.5, 1e-6);
}

/// A sum of random planes against the direct sum of weighted squared plane distances.
void CheckQuadricSumOfPlanes(std::mt19937& rng, std::uniform_real_distribution<double>& u)
{
  // Sum of planes vs the direct sum of weighted squared plane distances, random points.
  Quadric sum;
  std::vector<std::array<double, 4>> planes;
  for (int i = 0; i < 5; ++i)
  {
    double n[3] = { u(rng), u(rng), u(rng) };
    const double l = std::sqrt(Dot(n, n));
    for (double& x : n)
    {
      x /= l;
    }
    const double w = 0.5 + 0.5 * (u(rng) + 1);
    sum.AddPlaneThroughCentre(n, w);
    planes.push_back({ n[0], n[1], n[2], w });
  }
  for (int trial = 0; trial < 20; ++trial)
  {
    const double d[3] = { 3 * u(rng), 3 * u(rng), 3 * u(rng) };
    double direct = 0;
    for (const auto& p : planes)
    {
      const double dist = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
      direct += p[3] * dist * dist;
    }
    CD_CHECK_NEAR(sum.Evaluate(d), direct, 1e-6);
  }
}

/// AddShifted of two one-plane quadrics against the merged quadric computed by hand.
void CheckQuadricAddShiftedByHand()
{
  // AddShifted: v0 at p0 with the plane z = p0.z (w 2); v1 at p1 = p0 + (1,2,3) with the
  // plane x = p1.x (w 3). The merged quadric, centred at p1, at offset y from p1 is
  // 2 (3 + y_z)^2 + 3 y_x^2.
  const double nz[3] = { 0, 0, 1 };
  const double zero[3] = { 0, 0, 0 };
  Quadric q0, q1;
  q0.AddPlaneThroughCentre(nz, 2.0);
  const double nx[3] = { 1, 0, 0 };
  q1.AddPlaneThroughCentre(nx, 3.0);
  const double shift[3] = { 1, 2, 3 }; // p1 - p0
  q1.AddShifted(q0, shift);
  CD_CHECK_NEAR(q1.Evaluate(zero), 18.0, 1e-6);
  const double y1[3] = { 1, 1, 1 };
  CD_CHECK_NEAR(q1.Evaluate(y1), 35.0, 1e-6); // 2 * 16 + 3
  const double y2[3] = { -2, 5, -3 };
  CD_CHECK_NEAR(q1.Evaluate(y2), 12.0, 1e-6); // 2 * 0 + 3 * 4
}

/// AddShifted of random quadrics against evaluating both at the same absolute point.
void CheckQuadricAddShiftedRandom(std::mt19937& rng, std::uniform_real_distribution<double>& u)
{
  // AddShifted of random quadrics (with their own b and c) against evaluating both at the
  // same absolute point.
  for (int trial = 0; trial < 10; ++trial)
  {
    Quadric a, b;
    double na[3] = { u(rng), u(rng), u(rng) }, nb[3] = { u(rng), u(rng), u(rng) };
    a.AddPlaneThroughCentre(na, 1.3);
    b.AddPlaneThroughCentre(nb, 0.7);
    const double s1[3] = { u(rng), u(rng), u(rng) };
    b.AddShifted(a, s1); // b now has a linear and a constant part
    Quadric c;
    double nc[3] = { u(rng), u(rng), u(rng) };
    c.AddPlaneThroughCentre(nc, 2.1);
    const double s2[3] = { u(rng), u(rng), u(rng) }; // p_c - p_b
    Quadric merged = c;
    merged.AddShifted(b, s2);
    const double y[3] = { u(rng), u(rng), u(rng) }; // offset from p_c
    const double yb[3] = { y[0] + s2[0], y[1] + s2[1], y[2] + s2[2] };
    CD_CHECK_NEAR(merged.Evaluate(y), c.Evaluate(y) + b.Evaluate(yb), 1e-5);
  }
}

CD_TEST_CASE(Quadric)
{
  CheckQuadricOnePlane();
  // The random phases draw from one generator, in this order.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  CheckQuadricSumOfPlanes(rng, u);
  CheckQuadricAddShiftedByHand();
  CheckQuadricAddShiftedRandom(rng, u);
}

//------------------------------------------------------------------------------
CD_TEST_CASE(VisualImportance)
{
  CD_CHECK_NEAR(VisualImportance(0.0, 0.0), 0.0, 0.0);
  CD_CHECK_NEAR(VisualImportance(3.0, 1.5), 2.0, 1e-15);

  // On the pyramid. Apex black; its neighbours at colour distances 0.6, 0, 0.8, 0:
  // I = (0.6 + 0 + 0.8 + 0) / 0.8 = 1.75, max 0.8.
  HalfEdgeMesh mesh;
  mesh.Build(5, PyramidTriangles, 4);
  std::vector<float> positions(PyramidPoints, PyramidPoints + 15);
  std::vector<VertexMetric> metrics;
  InitializeVertexMetrics(mesh, positions.data(), PyramidColors, metrics);
  CD_CHECK(metrics.size() == 5);
  CD_CHECK_NEAR(metrics[0].Importance, 1.75, 1e-6);
  CD_CHECK_NEAR(metrics[0].MaxColorDistance, 0.8, 1e-6);
  // Ring vertex 1 (0.6,0,0): neighbours apex (0.6), 2 (0.6), 4 (0.6): I = 3.
  CD_CHECK_NEAR(metrics[1].Importance, 3.0, 1e-6);
  // Ring vertex 2 (black): neighbours apex (0), 1 (0.6), 3 (0.8): I = 1.4 / 0.8 = 1.75.
  CD_CHECK_NEAR(metrics[2].Importance, 1.75, 1e-6);
  // Ring vertex 3 (0,0.8,0): neighbours apex, 2, 4, all at 0.8: I = 3.
  CD_CHECK_NEAR(metrics[3].Importance, 3.0, 1e-6);

  // The 0 case: one colour everywhere gives I = 0, not NaN.
  const float grey[15] = { 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f,
                           0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f };
  InitializeVertexMetrics(mesh, positions.data(), grey, metrics);
  for (const VertexMetric& m : metrics)
  {
    CD_CHECK(m.Importance == 0.0f);
    CD_CHECK(m.MaxColorDistance == 0.0f);
  }
  // No colours at all: importance 0.
  InitializeVertexMetrics(mesh, positions.data(), nullptr, metrics);
  CD_CHECK(metrics[0].Importance == 0.0f);

  // The area-weighted quadric (eq. 8) of the apex in the input's units: each face has area
  // sqrt(3)/2 and normal (+-1,+-1,1)/sqrt(3). At d = (0,0,1): each face gives
  // sqrt(3)/2 * 1/3, the four sqrt(3) * 2/3 = 1.1547.
  InitializeVertexMetrics(mesh, positions.data(), PyramidColors, metrics);
  const double up[3] = { 0, 0, 1 };
  CD_CHECK_NEAR(metrics[0].Q.Evaluate(up), 2.0 * Sqrt3 / 3.0, 1e-6);
  // Ring vertex 1 has faces (0,1,2) and (0,4,1), normals (1,1,1)/sqrt3 and (1,-1,1)/sqrt3;
  // at d = (0,0,1) each gives sqrt(3)/2 * 1/3: total 1/sqrt(3).
  CD_CHECK_NEAR(metrics[1].Q.Evaluate(up), 1.0 / Sqrt3, 1e-6);

  // On three threads (vertex ranges {0}, {1, 2}, {3, 4}: most faces span two of them), with
  // boundary planes: the very same bits.
  std::vector<VertexMetric> threaded;
  InitializeVertexMetrics(mesh, positions.data(), PyramidColors, metrics, 3, 3, 2.0, 1);
  InitializeVertexMetrics(mesh, positions.data(), PyramidColors, threaded, 3, 3, 2.0, 3);
  CD_CHECK(threaded.size() == metrics.size() &&
           std::memcmp(threaded.data(), metrics.data(), sizeof(VertexMetric) * 5) == 0);
}

//------------------------------------------------------------------------------
/// The colour error by hand on a three-member ring (reference and batch) and a one-colour ring.
void CheckColorErrorByHand()
{
  // v0 at the origin, black. Ring: i0 at (2,0,0) red, i1 at (0,1,0) black, i2 at (-1,0,0) green.
  const double p0[3] = { 0, 0, 0 }, c0[3] = { 0, 0, 0 };
  Ring ring;
  const double pa[3] = { 2, 0, 0 }, ca[3] = { 1, 0, 0 };
  const double pb[3] = { 0, 1, 0 }, cb[3] = { 0, 0, 0 };
  const double pc[3] = { -1, 0, 0 }, cc[3] = { 0, 1, 0 };
  ring.Add(10, pa, ca, true);
  ring.Add(11, pb, cb, true);
  ring.Add(12, pc, cc, true);

  // Collapse onto i0: sum_i | |c0-ci||p0-pi| - |c1-ci||p1-pi| |
  //   i0: |1*2 - 0|                 = 2
  //   i1: |0*1 - 1*sqrt5|           = sqrt5
  //   i2: |1*1 - sqrt2*3|           = 3 sqrt2 - 1
  // total 1 + sqrt5 + 3 sqrt2 = 7.4787. The paper's misprint (|c1-ci|^2 for the second
  // product) would give 2 + 1 + 1 = 4.
  const double expected0 = 1.0 + std::sqrt(5.0) + 3.0 * Sqrt2;
  const double misprint0 = 4.0;
  CD_CHECK_NEAR(CollapseColorError(p0, c0, ring, 0), expected0, 1e-12);
  CD_CHECK(std::abs(expected0 - misprint0) > 1.0);
  // Onto i2: i0: |2 - sqrt2*3| = 3 sqrt2 - 2; i1: |0 - 1*sqrt2| = sqrt2; i2: |1 - 0| = 1:
  // total 4 sqrt2 - 1 = 4.6569 (misprint: |2 - 2| + |0 - 1| + 1 = 2).
  CD_CHECK_NEAR(CollapseColorError(p0, c0, ring, 2), 4.0 * Sqrt2 - 1.0, 1e-12);
  // Onto i1 (black, at (0,1,0)): i0: |2 - 1*sqrt5| = sqrt5 - 2; i1: 0; i2: |1 - 1*sqrt2|:
  // total sqrt5 + sqrt2 - 3.
  CD_CHECK_NEAR(CollapseColorError(p0, c0, ring, 1), std::sqrt(5.0) + Sqrt2 - 3.0, 1e-12);

  // The batch version agrees with the reference for every member of the ring. It works on
  // whole blocks of 4 (the ring padded with Pad()), so it writes PaddedSize() entries.
  ring.Pad();
  double errors[4] = { -1, -1, -1, -1 };
  CD_CHECK(ring.PaddedSize() == 4);
  CollapseColorErrors(p0, c0, ring, errors);
  for (int j = 0; j < 3; ++j)
  {
    CD_CHECK_NEAR(errors[j], CollapseColorError(p0, c0, ring, j), 1e-12);
  }

  // A ring of one colour around a vertex of the same colour: no colour error.
  Ring flat;
  flat.Add(0, pa, c0, true);
  flat.Add(1, pb, c0, true);
  CD_CHECK(CollapseColorError(p0, c0, flat, 0) == 0.0);
}

/// The batch colour error against the reference on random rings: the very same bits.
void CheckColorErrorRandomRings()
{
  // Random rings of 1 to 19 members (whole vector blocks and remainders, the valences of
  // real meshes and the large rings of poles), some with repeated positions or colours: the
  // batch version sums the same terms in the same order as the reference, so it gives the
  // very same bits (the schedules' results rest on it). Compilers allowed to fuse a multiply
  // and an add (FMA) may round the two versions differently; there, nearly the same.
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double batch[32];
  for (int trial = 0; trial < 400; ++trial)
  {
    const int size = 1 + trial % 19;
    Ring random;
    for (int k = 0; k < size; ++k)
    {
      double p[3] = { unit(rng), unit(rng), unit(rng) };
      double c[3] = { unit(rng), unit(rng), unit(rng) };
      if (k > 0 && trial % 5 == 0)
      {
        random.GetPosition(k - 1, p); // the same point as the one before, another colour
      }
      if (k > 0 && trial % 7 == 0)
      {
        random.GetColor(k - 1, c); // the same colour, another point
      }
      random.Add(k, p, c, true);
    }
    random.Pad();
    const double centre[3] = { unit(rng), unit(rng), unit(rng) };
    const double colour[3] = { unit(rng), unit(rng), unit(rng) };
    CollapseColorErrors(centre, colour, random, batch);
    for (int j = 0; j < size; ++j)
    {
      const double reference = CollapseColorError(centre, colour, random, j);
#ifdef __FMA__
      CD_CHECK_NEAR(batch[j], reference, 1e-12 * (1.0 + reference));
#else
      CD_CHECK(batch[j] == reference);
#endif
    }
  }
}

//------------------------------------------------------------------------------
CD_TEST_CASE(CollapseColorError)
{
  CheckColorErrorByHand();
  CheckColorErrorRandomRings();
}

//------------------------------------------------------------------------------
CD_TEST_CASE(TotalCost)
{
  // eq. 17: (1 + Q)(1 + I)(1 + C).
  CD_CHECK_NEAR(TotalCost(0.5, 2.0, 3.0), 18.0, 1e-15);
  CD_CHECK_NEAR(TotalCost(0.0, 0.0, 0.0), 1.0, 1e-15);
  CD_CHECK_NEAR(TotalCost(1.0 / Sqrt3, 1.75, 1.0 + Sqrt2),
                (1.0 + 1.0 / Sqrt3) * 2.75 * (2.0 + Sqrt2), 1e-14);
  // Not a sum: (1+1)(1+1)(1+1) = 8, the sum of the terms + 1 would be 4.
  CD_CHECK_NEAR(TotalCost(1.0, 1.0, 1.0), 8.0, 1e-15);
}

//------------------------------------------------------------------------------
/// The hand-computed cost of the apex -> ring vertex 1 collapse of the pyramid.
void CheckPyramidCosts(double scale, const double translation[3])
{
  std::vector<double> points(PyramidPoints, PyramidPoints + 15);
  for (int i = 0; i < 15; ++i)
  {
    points[i] = points[i] * scale + translation[i % 3];
  }
  DecimatorInput input;
  input.NumberOfPoints = 5;
  input.Points = points.data();
  input.Colors = PyramidColors;
  input.NumberOfTriangles = 4;
  input.Triangles = PyramidTriangles;

  DecimatorOptions options;
  Decimator decimator(options);
  const DecimatorStatistics stats = decimator.Run(input, 4); // target met: no collapse
  CD_CHECK(stats.Collapses == 0);
  CD_CHECK_NEAR(stats.MeanEdgeLength, Sqrt2 * scale, 1e-12);
  // The frame: apex at (0,0,1/2)/sqrt2, ring vertex 1 at (1,0,-1/2)/sqrt2.
  const std::vector<float>& p = decimator.GetNormalizedPositions();
  CD_CHECK_NEAR(p[2], 0.5 / Sqrt2, 1e-6);
  CD_CHECK_NEAR(p[3], 1.0 / Sqrt2, 1e-6);
  CD_CHECK_NEAR(p[5], -0.5 / Sqrt2, 1e-6);

  // Q(apex -> 1): d = p1 - p0 = (1,0,-1)/sqrt2, faces of area sqrt3/4 with n.d = 0, -2/sqrt6,
  // -2/sqrt6, 0: Q = 2 * sqrt3/4 * 4/6 = 1/sqrt3 (Q(v1) is 0 at p1).
  const double q = 1.0 / Sqrt3;
  // I(apex) = 1.75 (see the VisualImportance case).
  const double importance = 1.75;
  // C(apex -> 1): all spokes have length 1, rim 1-2 and 1-4 length 1, 1-3 length sqrt2.
  //   i=1: |0.6*1 - 0| = 0.6; i=2: |0 - 0.6*1| = 0.6; i=3: |0.8*1 - 1.0*sqrt2| = sqrt2 - 0.8;
  //   i=4: |0 - 0.6*1| = 0.6: C = 1 + sqrt2.
  const double c = 1.0 + Sqrt2;
  // The misprint would give 0.6 + 0.36 + |0.8 - 1| + 0.36 = 1.52.
  const double expected = (1.0 + q) * (1.0 + importance) * (1.0 + c); // 14.8097
  const double misprinted = (1.0 + q) * (1.0 + importance) * (1.0 + 1.52);
  CD_CHECK(std::abs(expected - misprinted) > 1.0);
  CD_CHECK_NEAR(decimator.CollapseCost(0, 1), expected, 1e-5);
  CD_CHECK_NEAR(decimator.GetMetrics()[0].Importance, importance, 1e-6);
  const double d[3] = { 1 / Sqrt2, 0, -1 / Sqrt2 };
  CD_CHECK_NEAR(decimator.GetMetrics()[0].Q.Evaluate(d), q, 1e-5);

  // Apex -> 3 (the mirror image: same Q; colour: i=3: |0.8 - 0| = 0.8; i=1: |0.6*1 - 1.0*sqrt2|;
  // i=2: |0 - 0.8| ; i=4: |0 - 0.8|): C = 2.4 + sqrt2 - 0.6 = 1.8 + sqrt2.
  CD_CHECK_NEAR(decimator.CollapseCost(0, 3), (1.0 + q) * 2.75 * (2.8 + Sqrt2), 1e-5);
  // Not neighbours (1 and 3): negative.
  CD_CHECK(decimator.CollapseCost(1, 3) < 0);

  // GeometryWeight scales Q: w = 3 gives (1 + sqrt3) (1 + I) (1 + C).
  DecimatorOptions weighted;
  weighted.GeometryWeight = 3.0;
  Decimator heavy(weighted);
  heavy.Run(input, 4);
  CD_CHECK_NEAR(heavy.CollapseCost(0, 1), (1.0 + Sqrt3) * 2.75 * (2.0 + Sqrt2), 1e-5);

  // The Geometry metric is Q alone.
  DecimatorOptions geometric;
  geometric.Metric = ErrorMetric::Geometry;
  Decimator geometry(geometric);
  geometry.Run(input, 4);
  CD_CHECK_NEAR(geometry.CollapseCost(0, 1), q, 1e-5);
  // Ring vertex 2 -> 1 is a boundary collapse along the rim: the faces of 2 are (0,1,2) and
  // (0,2,3); (0,1,2) disappears. Q(2) at p1 - p2 = (1,-1,0)/sqrt2: face (0,1,2) normal
  // (1,1,1)/sqrt3 gives 0, face (0,2,3) normal (-1,1,1)/sqrt3 gives sqrt3/4 * (2/sqrt6)^2
  // = sqrt3/6. Q(1) at p1 is 0.
  CD_CHECK_NEAR(geometry.CollapseCost(2, 1), Sqrt3 / 6.0, 1e-5);
}

CD_TEST_CASE(CollapseCost)
{
  const double none[3] = { 0, 0, 0 };
  CheckPyramidCosts(1.0, none);
}

CD_TEST_CASE(CollapseCostFrame)
{
  // The same costs whatever the input's unit and position (normalised frame).
  const double shift1[3] = { 0.02, -0.01, 0.005 };
  CheckPyramidCosts(1e-3, shift1);
  const double shift2[3] = { 1e5, -5e4, 3e4 };
  CheckPyramidCosts(1e4, shift2);
  const double shift3[3] = { 10, -20, 5 };
  CheckPyramidCosts(1.0, shift3);
}

//------------------------------------------------------------------------------
/// The RGB point scalars of a generated mesh as floats in [0, 1], three per point.
std::vector<float> UnitColors(vtkPolyData* mesh)
{
  const int32_t n = static_cast<int32_t>(mesh->GetNumberOfPoints());
  std::vector<float> colors(3 * static_cast<size_t>(n));
  vtkDataArray* rgb = mesh->GetPointData()->GetScalars();
  for (int32_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      colors[3 * i + k] = static_cast<float>(rgb->GetComponent(i, k) / 255.0);
    }
  }
  return colors;
}

/// Keying high-valence vertices by a lower bound (Decimator::LargeRing) must not change the
/// result: a UV sphere's poles have valence 120 here.
CD_TEST_CASE(HighValenceBound)
{
  auto mesh = meshes::UVSphere(120, meshes::Pattern::SharpRegions);
  const int32_t n = static_cast<int32_t>(mesh->GetNumberOfPoints());
  std::vector<double> points(3 * static_cast<size_t>(n));
  for (int32_t i = 0; i < n; ++i)
  {
    mesh->GetPoint(i, &points[3 * i]);
  }
  const std::vector<float> colors = UnitColors(mesh);
  std::vector<int32_t> triangles;
  for (const Tri& t : GetTriangles(mesh))
  {
    triangles.insert(triangles.end(), { int32_t(t[0]), int32_t(t[1]), int32_t(t[2]) });
  }
  DecimatorInput input;
  input.NumberOfPoints = n;
  input.Points = points.data();
  input.Colors = colors.data();
  input.NumberOfTriangles = static_cast<int32_t>(triangles.size() / 3);
  input.Triangles = triangles.data();

  std::vector<std::vector<int32_t>> faces;
  for (bool bound : { true, false })
  {
    DecimatorOptions options;
    options.BoundHighValence = bound;
    Decimator decimator(options);
    const DecimatorStatistics stats = decimator.Run(input, input.NumberOfTriangles / 10);
    CD_CHECK(stats.OutputTriangles <= input.NumberOfTriangles / 10);
    std::vector<int32_t> live;
    const HalfEdgeMesh& m = decimator.GetMesh();
    for (int32_t f = 0; f < m.GetNumberOfFaceSlots(); ++f)
    {
      if (m.IsFaceAlive(f))
      {
        live.insert(live.end(), { f, m.Origin(3 * f), m.Origin(3 * f + 1), m.Origin(3 * f + 2) });
      }
    }
    faces.push_back(live);
  }
  CD_CHECK_MSG(faces[0] == faces[1], "the bounded and the exact keys give different meshes");
}

/// The random source of BatchSelection: one generator and its distributions, drawn in turn.
struct SelectionDraws
{
  std::mt19937 Rng{ 2026 };
  std::uniform_int_distribution<int> Kind{ 0, 9 };
  std::uniform_real_distribution<double> Wide{ -3.0, 40.0 };
  std::uniform_int_distribution<int> Coarse{ 0, 6 };
};

/// The keys and candidacy of n vertices for one pattern of BatchSelection (see there).
void MakeSelectionKeys(int pattern, int32_t n, SelectionDraws& draws, std::vector<double>& keys,
                       std::vector<char>& eligible)
{
  std::mt19937& rng = draws.Rng;
  std::uniform_int_distribution<int>& kind = draws.Kind;
  std::uniform_real_distribution<double>& wide = draws.Wide;
  std::uniform_int_distribution<int>& coarse = draws.Coarse;
  keys.assign(n, 0.0);
  eligible.assign(n, 0);
  for (int32_t v = 0; v < n; ++v)
  {
    const int k = kind(rng);
    keys[v] = k == 0 ? std::nan("")
      : k == 1       ? -0.0
      : k == 2       ? 0.5 * coarse(rng)
      : k == 3       ? 1.0 + 1e-9 * coarse(rng)
      : k < 6        ? 1.0 + 1e-5 * coarse(rng)
                     : std::exp(wide(rng)) * (k == 6 ? -1.0 : 1.0);
    eligible[v] = kind(rng) != 0;
    if (pattern == 1)
    {
      keys[v] = v % 16 == 0 ? -1.0 - v : 1.0 + v % 7;
    }
    else if (pattern == 2)
    {
      eligible[v] = eligible[v] && v % 16 != 0;
    }
    else if (pattern == 3)
    {
      keys[v] = v % 16 == 0 ? 100.0 + v : 1.0 + v % 7;
    }
    else if (pattern == 4)
    {
      eligible[v] = 1;
      keys[v] = v % 4 == 1 ? 1.0 + 1e-3 * (v % 5) : 50.0 + v % 3;
    }
  }
}

/// SelectCheapest of a share of the candidates against a full sort, on 1, 2 and 3 threads.
void CheckSelectCheapestShare(int pattern, const std::vector<double>& keys,
                              const std::vector<char>& eligible, const std::vector<Candidate>& all,
                              double share)
{
  const int32_t n = static_cast<int32_t>(keys.size());
  const size_t wanted = static_cast<size_t>(share * static_cast<double>(all.size()));
  std::vector<Candidate> expected(all.begin(), all.begin() + wanted);
  std::sort(expected.begin(), expected.end(),
            [](const Candidate& a, const Candidate& b) { return a.Vertex < b.Vertex; });
  for (const int threads : { 1, 2, 3 })
  {
    std::vector<Candidate> out = { { -1.0, -1 } }; // appended to, not replaced
    size_t seen = 0;
    const size_t total = SelectCheapest(
      static_cast<size_t>(n), nullptr,
      [&keys, &eligible](int32_t v, double& key)
      {
        key = OrderableKey(keys[v]);
        return eligible[v] != 0;
      },
      [wanted, &seen](size_t count)
      {
        seen = count;
        return wanted;
      },
      threads, out);
    CD_CHECK(total == all.size() && seen == (n > 0 ? all.size() : seen));
    CD_CHECK_MSG(out.size() == expected.size() + 1,
                 "pattern " << pattern << " n " << n << " share " << share << " threads " << threads
                            << ": " << out.size() - 1 << " selected, " << expected.size()
                            << " expected");
    bool same = out.size() == expected.size() + 1 && out[0].Vertex == -1;
    for (size_t i = 0; same && i < expected.size(); ++i)
    {
      const Candidate& a = out[i + 1];
      const Candidate& b = expected[i];
      same = a.Vertex == b.Vertex && std::memcmp(&a.Key, &b.Key, sizeof(double)) == 0;
    }
    CD_CHECK_MSG(
      same, "pattern " << pattern << " n " << n << " share " << share << " threads " << threads);
  }
}

/// SelectCheapest against a full sort for every pattern, size and share (see BatchSelection).
void CheckSelectionPatterns(SelectionDraws& draws)
{
  // Pattern 0: random keys (many ties, near ties 1e-9 and 1e-5 apart around 1). Pattern 1: the
  // vertices a sample of every 16th would see are the cheapest (the estimate misleads). Pattern
  // 2: those vertices are no candidates (an empty sample). Pattern 3: they are the dearest
  // (both thresholds too high: too many below the lower one). Pattern 4: two well apart groups
  // of keys, the cheap one a quarter of the candidates (the cut may fall between thresholds).
  for (const int pattern : { 0, 1, 2, 3, 4 })
  {
    for (const int32_t n : { 0, 1, 7, 1000, 20000, 100000 })
    {
      std::vector<double> keys;
      std::vector<char> eligible;
      MakeSelectionKeys(pattern, n, draws, keys, eligible);
      std::vector<Candidate> all;
      for (int32_t v = 0; v < n; ++v)
      {
        if (eligible[v])
        {
          all.push_back({ OrderableKey(keys[v]), v });
        }
      }
      std::sort(all.begin(), all.end());
      for (const double share : { 0.0, 0.001, 0.25, 0.5, 1.0 })
      {
        CheckSelectCheapestShare(pattern, keys, eligible, all, share);
      }
    }
  }
}

/// SelectCheapest over a list of vertices: only the listed ones count, on 1, 2 and 3 threads.
void CheckSelectionFromList(SelectionDraws& draws)
{
  std::mt19937& rng = draws.Rng;
  std::uniform_int_distribution<int>& kind = draws.Kind;
  std::uniform_int_distribution<int>& coarse = draws.Coarse;
  // A list of vertices (as the Batched schedule passes its live ones): only the listed ones
  // count, and the result is the same as over an identity list of those.
  const int32_t n = 50000;
  std::vector<double> keys(n);
  std::vector<int32_t> listed;
  for (int32_t v = 0; v < n; ++v)
  {
    keys[v] = 0.25 * coarse(rng) + (v % 3 == 0 ? -10.0 : 0.0); // the unlisted are the cheapest
    if (v % 3 != 0 && kind(rng) != 0)
    {
      listed.push_back(v);
    }
  }
  std::vector<Candidate> expected;
  for (const int32_t v : listed)
  {
    if (v % 7 != 0)
    {
      expected.push_back({ keys[v], v });
    }
  }
  std::sort(expected.begin(), expected.end());
  const size_t candidates = expected.size();
  const size_t wanted = candidates / 4;
  expected.resize(wanted);
  std::sort(expected.begin(), expected.end(),
            [](const Candidate& a, const Candidate& b) { return a.Vertex < b.Vertex; });
  for (const int threads : { 1, 2, 3 })
  {
    std::vector<Candidate> out;
    size_t seen = 0;
    const size_t total = SelectCheapest(
      listed.size(), listed.data(),
      [&keys](int32_t v, double& key)
      {
        key = keys[v];
        return v % 7 != 0;
      },
      [&seen](size_t count)
      {
        seen = count;
        return count / 4;
      },
      threads, out);
    CD_CHECK(total == candidates && seen == candidates);
    bool same = out.size() == expected.size();
    for (size_t i = 0; same && i < expected.size(); ++i)
    {
      same = out[i].Vertex == expected[i].Vertex && out[i].Key == expected[i].Key;
    }
    CD_CHECK_MSG(same, "a list of vertices, threads " << threads);
  }
}

CD_TEST_CASE(BatchSelection)
{
  // SelectCheapest against a full sort: the same set (the smallest by key, ties by vertex) for
  // any number of threads, in vertex order; with ties across the cut, NaN (last, as +inf), -0
  // (equal to +0), negative keys, non-candidates, near ties, and samples that mislead.
  SelectionDraws draws; // the phases draw from it in this order
  CheckSelectionPatterns(draws);
  CD_CHECK(OrderableKey(std::nan("")) == std::numeric_limits<double>::infinity());
  CheckSelectionFromList(draws);
}

CD_TEST_CASE(SortByKey)
{
  // SortByKey against std::sort on candidates in vertex order: the same order, bit for bit, for
  // sizes on both sides of where it turns to the radix sort; keys with many ties, -0 and +0
  // (equal, so in vertex order), negatives, infinities, keys sharing their high bytes, and
  // keys that differ in their last bit only.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> kind(0, 7);
  std::uniform_real_distribution<double> wide(-30.0, 30.0);
  std::uniform_int_distribution<int> coarse(0, 5);
  Buffer<Candidate> room;
  for (const int size : { 0, 1, 2, 255, 256, 257, 1000, 5000, 40000 })
  {
    for (const int pattern : { 0, 1, 2 })
    {
      std::vector<Candidate> candidates(size);
      for (int i = 0; i < size; ++i)
      {
        double key;
        const int k = kind(rng);
        if (pattern == 0)
        {
          key = k == 0 ? -0.0
            : k == 1   ? 0.0
            : k == 2   ? 0.25 * coarse(rng)
            : k == 3   ? std::numeric_limits<double>::infinity()
            : k == 4   ? -std::exp(wide(rng))
                       : std::exp(wide(rng));
        }
        else if (pattern == 1)
        {
          key = 1.0 + std::ldexp(double(coarse(rng)), -52); // the last bits only
        }
        else
        {
          key = 3.0 + 1e-3 * coarse(rng) + 1e-9 * k; // the high bytes shared
        }
        candidates[i] = { key, 3 * i + coarse(rng) % 3 }; // increasing vertices
      }
      std::vector<Candidate> expected = candidates;
      std::sort(expected.begin(), expected.end());
      SortByKey(candidates.data(), candidates.data() + candidates.size(), room);
      bool same = true;
      for (int i = 0; same && i < size; ++i)
      {
        same = candidates[i].Vertex == expected[i].Vertex &&
          std::memcmp(&candidates[i].Key, &expected[i].Key, sizeof(double)) == 0;
      }
      CD_CHECK_MSG(same, "size " << size << " pattern " << pattern);
    }
  }
}

CD_TEST_CASE(ParallelForException)
{
  // An exception in any range (the calling thread's or a started one's) reaches the caller
  // after every range has run to its end or its throw: the lowest throwing range's, its type
  // kept; without one, each range is run once.
  for (const int threads : { 1, 2, 3 })
  {
    for (int thrower = -1; thrower < threads; ++thrower)
    {
      std::vector<int> ran(static_cast<size_t>(threads), 0);
      int* r = ran.data();
      int caught = -1; // the range named by the exception caught, -1: none
      try
      {
        ParallelFor(size_t(30), threads,
                    [r, thrower, threads](size_t, size_t, int t)
                    {
                      r[t] = 1;
                      if (t == thrower || (thrower >= 0 && t == threads - 1))
                      {
                        throw std::out_of_range(std::to_string(t));
                      }
                    });
      }
      catch (const std::out_of_range& e)
      {
        caught = std::stoi(e.what());
      }
      CD_CHECK_MSG(std::count(ran.begin(), ran.end(), 1) == threads,
                   "threads " << threads << " thrower " << thrower);
      CD_CHECK_MSG(caught == thrower,
                   "threads " << threads << " thrower " << thrower << " caught " << caught);
    }
  }
  // ParallelAll runs on ParallelFor: a std::bad_alloc in a range comes out as one.
  bool badAlloc = false;
  try
  {
    ParallelAll(size_t(10), 2,
                [](size_t begin, size_t) -> bool
                {
                  if (begin > 0)
                  {
                    throw std::bad_alloc();
                  }
                  return true;
                });
  }
  catch (const std::bad_alloc&)
  {
    badAlloc = true;
  }
  CD_CHECK(badAlloc);
}

//------------------------------------------------------------------------------
/// ParallelForChunks: every item in exactly one chunk, chunks of at most `chunk` items inside
/// one thread's range (ParallelFor's) on 2 to 4 threads, one call for all on one, for counts
/// and chunks around each other (the largest chunk too).
void CheckChunksCoverItemsOnce()
{
  for (const size_t count :
       { size_t(0), size_t(1), size_t(5), size_t(2047), size_t(2049), size_t(10000) })
  {
    for (const int threads : { 1, 2, 3, 4 })
    {
      for (const size_t chunk :
           { size_t(0), size_t(1), size_t(7), size_t(2048), std::numeric_limits<size_t>::max() })
      {
        std::vector<std::atomic<int>> seen(count);
        std::atomic<int> bad(0);
        std::atomic<int>* s = seen.data();
        std::atomic<int>* b = &bad;
        ParallelForChunks(count, threads, chunk,
                          [s, b, count, threads, chunk](size_t begin, size_t end, int t)
                          {
                            const auto range = [count, threads](size_t i)
                            {
                              int u = 0; // ParallelFor's u-th range holds i
                              while (count * size_t(u + 1) / size_t(threads) <= i)
                              {
                                ++u;
                              }
                              return u;
                            };
                            const bool inside = threads == 1 ? begin == 0 && end == count && t == 0
                                                             : begin < end && end <= count &&
                                end - begin <= std::max<size_t>(chunk, 1) && t >= 0 &&
                                t < threads && range(begin) == range(end - 1);
                            b->fetch_add(inside ? 0 : 1);
                            for (size_t i = begin; i < end && end <= count; ++i)
                            {
                              s[i].fetch_add(1);
                            }
                          });
        CD_CHECK_MSG(bad.load() == 0 &&
                       std::all_of(seen.begin(), seen.end(),
                                   [](const std::atomic<int>& n) { return n.load() == 1; }),
                     "count " << count << " threads " << threads << " chunk " << chunk);
      }
    }
  }
}

/// ParallelForChunks: the thread that runs item 0 waits there until another thread has run an
/// item of the first range (for 20 s at most), which the other does once its own is done.
void CheckChunksTakenFromHeldUpThread()
{
  std::vector<int> ranBy(64, -1);
  std::atomic<int> zeroRunner(-1);
  std::atomic<bool> taken(false);
  int* r = ranBy.data();
  std::atomic<int>* z = &zeroRunner;
  std::atomic<bool>* k = &taken;
  ParallelForChunks(size_t(64), 2, size_t(1),
                    [r, z, k](size_t begin, size_t, int t)
                    {
                      r[begin] = t;
                      if (begin == 0)
                      {
                        z->store(t);
                        const auto start = std::chrono::steady_clock::now();
                        while (!k->load() &&
                               std::chrono::steady_clock::now() - start < std::chrono::seconds(20))
                        {
                          std::this_thread::sleep_for(std::chrono::milliseconds(1));
                        }
                      }
                      else if (begin < 32 && t != z->load())
                      {
                        k->store(true);
                      }
                    });
  CD_CHECK_MSG(taken.load(), "no other thread took a chunk of the held-up thread's range");
  CD_CHECK(std::count(ranBy.begin(), ranBy.end(), -1) == 0);
}

/// ParallelForChunks: a body's exception reaches the caller; the other chunks still run, each
/// once.
void CheckChunksAfterException()
{
  std::vector<std::atomic<int>> seen(1000);
  std::atomic<int>* s = seen.data();
  bool caught = false;
  try
  {
    ParallelForChunks(seen.size(), 2, size_t(10),
                      [s](size_t begin, size_t end, int)
                      {
                        for (size_t i = begin; i < end; ++i)
                        {
                          s[i].fetch_add(1);
                        }
                        if (begin == 500)
                        {
                          throw std::out_of_range("500");
                        }
                      });
  }
  catch (const std::out_of_range&)
  {
    caught = true;
  }
  CD_CHECK(
    caught &&
    std::all_of(seen.begin(), seen.end(), [](const std::atomic<int>& n) { return n.load() == 1; }));
}

CD_TEST_CASE(ParallelForChunks)
{
  CheckChunksCoverItemsOnce();
  CheckChunksTakenFromHeldUpThread();
  CheckChunksAfterException();
}

CD_TEST_CASE(CollectInOrder)
{
  // CollectInOrder against a plain loop, on 1 to 3 threads, for sizes around its chunks of
  // 256 and room made for none, some or all of a range at first: both lists in index order,
  // items in both or neither, and the count of the items marked with bit 4.
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> bits(0, 7);
  for (const size_t count :
       { size_t(0), size_t(1), size_t(255), size_t(256), size_t(257), size_t(1000), size_t(20000) })
  {
    std::vector<int> marks(count);
    for (int& m : marks)
    {
      m = bits(rng);
    }
    std::vector<int32_t> expectedFirst = { -7 }, expectedSecond;
    size_t expectedMarked = 0;
    for (size_t i = 0; i < count; ++i)
    {
      if (marks[i] & 1)
      {
        expectedFirst.push_back(static_cast<int32_t>(3 * i));
      }
      if (marks[i] & 2)
      {
        expectedSecond.push_back(static_cast<int32_t>(3 * i));
      }
      expectedMarked += (marks[i] & 4) ? 1 : 0;
    }
    for (const int threads : { 1, 2, 3 })
    {
      for (const double share : { 0.0, 0.3, 1.0 })
      {
        std::vector<int32_t> first = { -7 }, second; // appended to, not replaced
        const int* m = marks.data();
        const size_t marked = CollectInOrder(
          count, threads,
          [m](size_t i, int32_t& item)
          {
            item = static_cast<int32_t>(3 * i);
            return m[i];
          },
          first, second, share);
        CD_CHECK_MSG(first == expectedFirst && second == expectedSecond && marked == expectedMarked,
                     "count " << count << " threads " << threads << " share " << share);
      }
    }
  }
}

CD_TEST_CASE(CountingSort)
{
  // CountingSort against std::stable_sort, on 1 to 3 threads: every item placed once, in key
  // order, equal keys in item order, and the buckets' offsets. Keys with empty buckets and
  // with many repeats; counts smaller than the number of threads; buckets enough for the
  // offsets to be summed on several threads.
  std::mt19937 rng(2024);
  for (const size_t count : { size_t(0), size_t(2), size_t(1000), size_t(50000) })
  {
    for (const size_t buckets : { size_t(1), size_t(7), size_t(5000), size_t(40000) })
    {
      std::uniform_int_distribution<int32_t> pick(0, static_cast<int32_t>(buckets) - 1);
      std::vector<int32_t> keys(count);
      for (int32_t& k : keys)
      {
        k = pick(rng) / 2; // the upper half of the buckets stays empty
      }
      std::vector<int32_t> expected(count);
      std::iota(expected.begin(), expected.end(), 0);
      std::stable_sort(expected.begin(), expected.end(),
                       [&keys](int32_t a, int32_t b) { return keys[a] < keys[b]; });
      for (int threads = 1; threads <= 3; ++threads)
      {
        std::vector<int32_t> sorted(count, -1);
        std::vector<int32_t> offsets;
        int32_t* into = sorted.data();
        const int32_t* key = keys.data();
        CountingSort(
          count, buckets, threads, [key](size_t i) { return key[i]; },
          [into](size_t i, int32_t slot) { into[slot] = static_cast<int32_t>(i); }, offsets);
        CD_CHECK_MSG(sorted == expected,
                     "order, count " << count << " buckets " << buckets << " threads " << threads);
        bool rows = offsets.size() == buckets + 1 && offsets.front() == 0 &&
          offsets.back() == static_cast<int32_t>(count);
        for (size_t b = 0; rows && b < buckets; ++b)
        {
          const auto first =
            std::lower_bound(expected.begin(), expected.end(), int32_t(b),
                             [&keys](int32_t i, int32_t k) { return keys[i] < k; });
          rows = offsets[b] == static_cast<int32_t>(first - expected.begin());
        }
        CD_CHECK_MSG(
          rows, "offsets, count " << count << " buckets " << buckets << " threads " << threads);
      }
    }
  }
}

/// Every vertex is in the heap exactly when in the reference, with the reference's key.
void CheckVertexHeapMatches(const VertexHeap& heap, std::map<int32_t, double>& reference, int32_t n)
{
  for (int32_t v = 0; v < n; ++v)
  {
    CD_CHECK(heap.Contains(v) == (reference.count(v) > 0));
    if (reference.count(v))
    {
      CD_CHECK(heap.GetKey(v) == reference[v]);
    }
  }
}

/**
 * Random sets, removals and pops against a reference map: pops give the smallest key, sizes
 * and tops agree. Returns false if it stopped early (more than 20 failures).
 */
bool CheckVertexHeapRandomOperations(VertexHeap& heap, std::map<int32_t, double>& reference,
                                     int32_t n)
{
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int32_t> vertex(0, n - 1);
  std::uniform_int_distribution<int> op(0, 9);
  std::uniform_int_distribution<int> coarse(0, 20); // many equal keys
  std::uniform_real_distribution<double> fine(-1e3, 1e3);
  auto smallest = [&]()
  {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& e : reference)
    {
      best = std::min(best, e.second);
    }
    return best;
  };
  long long pops = 0;
  for (int step = 0; step < 30000; ++step)
  {
    const int o = op(rng);
    if (o < 5)
    {
      const int32_t v = vertex(rng);
      const double key = (step % 2) ? fine(rng) : 0.25 * coarse(rng);
      heap.Set(v, key);
      reference[v] = key;
    }
    else if (o < 8)
    {
      const int32_t v = vertex(rng);
      heap.Remove(v);
      reference.erase(v);
    }
    else if (!reference.empty())
    {
      const double best = smallest();
      const int32_t v = heap.Pop();
      ++pops;
      CD_CHECK_MSG(reference.count(v) && reference[v] == best,
                   "popped " << v << " with key " << (reference.count(v) ? reference[v] : -1e300)
                             << ", smallest is " << best);
      reference.erase(v);
      CD_CHECK(!heap.Contains(v));
    }
    CD_CHECK(heap.Size() == reference.size());
    CD_CHECK(heap.Empty() == reference.empty());
    if (!reference.empty())
    {
      CD_CHECK(heap.GetKey(heap.Top()) == smallest());
    }
    if (step % 997 == 0)
    {
      CheckVertexHeapMatches(heap, reference, n);
    }
    if (GetNumberOfFailures() > 20)
    {
      return false;
    }
  }
  CD_CHECK(pops > 1000);
  return true;
}

/// Draining the heap gives the keys sorted, as the sorted reference.
void CheckVertexHeapDrain(VertexHeap& heap, const std::map<int32_t, double>& reference)
{
  std::vector<double> expected;
  for (const auto& e : reference)
  {
    expected.push_back(e.second);
  }
  std::sort(expected.begin(), expected.end());
  std::vector<double> drained;
  while (!heap.Empty())
  {
    const int32_t v = heap.Top();
    drained.push_back(heap.GetKey(v));
    CD_CHECK(heap.Pop() == v);
  }
  CD_CHECK(drained == expected);
}

CD_TEST_CASE(VertexHeap)
{
  const int32_t n = 400;
  VertexHeap heap(n);
  std::map<int32_t, double> reference; // vertex -> key
  if (!CheckVertexHeapRandomOperations(heap, reference, n))
  {
    return;
  }
  CheckVertexHeapDrain(heap, reference);
  // Reset empties it.
  heap.Set(3, 1.0);
  heap.Reset(10);
  CD_CHECK(heap.Empty() && !heap.Contains(3));
}

//------------------------------------------------------------------------------
/// The violations CheckMeshConsistency counts; the first five are reported as failed checks.
struct ConsistencyFailures
{
  long long Count = 0;
  void operator()(const std::string& what)
  {
    if (++this->Count <= 5)
    {
      ReportFailure(__FILE__, __LINE__, "half-edge mesh consistent", what);
    }
  }
};

/// The live faces of a corner table: distinct live vertices and consistent twins (counts corners).
void CheckFaceConsistency(const HalfEdgeMesh& mesh, bool closed, std::vector<int>& corners,
                          ConsistencyFailures& fail)
{
  const int32_t faces = mesh.GetNumberOfFaceSlots();
  long long live = 0;
  for (int32_t f = 0; f < faces; ++f)
  {
    if (!mesh.IsFaceAlive(f))
    {
      continue;
    }
    ++live;
    const int32_t tri[3] = { mesh.Origin(3 * f), mesh.Origin(3 * f + 1), mesh.Origin(3 * f + 2) };
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
    {
      fail("face " + std::to_string(f) + " repeats a vertex");
    }
    for (int k = 0; k < 3; ++k)
    {
      const int32_t h = 3 * f + k;
      if (tri[k] < 0 || mesh.IsRemoved(tri[k]))
      {
        fail("face " + std::to_string(f) + " uses a removed vertex");
        continue;
      }
      ++corners[tri[k]];
      const int32_t t = mesh.Twin(h);
      if (t < 0)
      {
        if (closed)
        {
          fail("half-edge " + std::to_string(h) + " has no twin on a closed mesh");
        }
        continue;
      }
      if (!mesh.IsFaceAlive(t / 3) || mesh.Twin(t) != h || mesh.Origin(t) != mesh.Target(h) ||
          mesh.Target(t) != mesh.Origin(h))
      {
        fail("twin of half-edge " + std::to_string(h) + " is inconsistent");
      }
    }
  }
  if (live != mesh.GetNumberOfLiveFaces())
  {
    fail("live face count");
  }
}

/// The vertices of a corner table: removed ones unused, circulation visits every corner.
void CheckVertexConsistency(const HalfEdgeMesh& mesh, const std::vector<int>& corners,
                            ConsistencyFailures& fail)
{
  const int32_t n = mesh.GetNumberOfVertices();
  for (int32_t v = 0; v < n; ++v)
  {
    if (mesh.IsRemoved(v))
    {
      if (mesh.Outgoing(v) != -1 || corners[v] != 0)
      {
        fail("removed vertex " + std::to_string(v) + " still used");
      }
      continue;
    }
    if (corners[v] == 0)
    {
      continue;
    }
    const int32_t out = mesh.Outgoing(v);
    if (out < 0 || !mesh.IsFaceAlive(out / 3) || mesh.Origin(out) != v)
    {
      fail("outgoing half-edge of vertex " + std::to_string(v));
      continue;
    }
    if (mesh.IsLocked(v))
    {
      continue;
    }
    int visited = 0;
    bool hasBoundary = false;
    mesh.ForEachOutgoing(v,
                         [&](int32_t h)
                         {
                           ++visited;
                           hasBoundary = hasBoundary || mesh.Twin(h) < 0;
                           if (mesh.Origin(h) != v)
                           {
                             fail("circulation left vertex " + std::to_string(v));
                           }
                         });
    if (visited != corners[v])
    {
      fail("circulating vertex " + std::to_string(v) + " visits " + std::to_string(visited) +
           " of its " + std::to_string(corners[v]) + " corners");
    }
    if (hasBoundary && mesh.Twin(out) >= 0)
    {
      fail("boundary vertex " + std::to_string(v) + " does not start at its boundary");
    }
  }
}

/// Every structural invariant of a corner table; returns the number of violations.
long long CheckMeshConsistency(const HalfEdgeMesh& mesh, bool closed)
{
  ConsistencyFailures fail;
  std::vector<int> corners(mesh.GetNumberOfVertices(), 0);
  CheckFaceConsistency(mesh, closed, corners, fail);
  CheckVertexConsistency(mesh, corners, fail);
  return fail.Count;
}

/// The live faces of a corner table.
std::vector<Tri> LiveTriangles(const HalfEdgeMesh& mesh)
{
  std::vector<Tri> tris;
  for (int32_t f = 0; f < mesh.GetNumberOfFaceSlots(); ++f)
  {
    if (mesh.IsFaceAlive(f))
    {
      const int32_t t[3] = { mesh.Origin(3 * f), mesh.Origin(3 * f + 1), mesh.Origin(3 * f + 2) };
      tris.push_back({ t[0], t[1], t[2] });
    }
  }
  return tris;
}

/// Build on one thread and on three: the same report, twins, outgoing half-edges and locks.
void CheckBuildThreads(int32_t numVertices, const int32_t* triangles, int32_t numTriangles)
{
  HalfEdgeMesh one, three;
  const MeshBuildReport a = one.Build(numVertices, triangles, numTriangles, 1);
  const MeshBuildReport b = three.Build(numVertices, triangles, numTriangles, 3);
  CD_CHECK(a.BoundaryEdges == b.BoundaryEdges && a.NonManifoldEdges == b.NonManifoldEdges &&
           a.NonManifoldVertices == b.NonManifoldVertices &&
           a.IsolatedVertices == b.IsolatedVertices && a.LockedVertices == b.LockedVertices);
  int differences = 0;
  for (int32_t h = 0; h < 3 * numTriangles; ++h)
  {
    differences += one.Twin(h) != three.Twin(h) ? 1 : 0;
  }
  for (int32_t v = 0; v < numVertices; ++v)
  {
    differences += one.Outgoing(v) != three.Outgoing(v) ? 1 : 0;
    differences += one.IsLocked(v) != three.IsLocked(v) ? 1 : 0;
  }
  CD_CHECK(differences == 0);
}

CD_TEST_CASE(HalfEdgeBuildClosed)
{
  for (auto poly : { meshes::Icosphere(3, meshes::Pattern::Constant),
                     meshes::Torus(24, 10, meshes::Pattern::Constant) })
  {
    const PlainMesh m = ToPlain(poly);
    HalfEdgeMesh mesh;
    const MeshBuildReport report =
      mesh.Build(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
    CD_CHECK(report.BoundaryEdges == 0);
    CD_CHECK(report.NonManifoldEdges == 0);
    CD_CHECK(report.NonManifoldVertices == 0);
    CD_CHECK(report.LockedVertices == 0);
    CD_CHECK(report.IsolatedVertices == 0);
    CD_CHECK(mesh.GetNumberOfLiveFaces() == m.NumberOfTriangles());
    CD_CHECK(CheckMeshConsistency(mesh, true) == 0);
    // Sum of valences = twice the number of edges = 3 F.
    long long valences = 0;
    for (int32_t v = 0; v < m.NumberOfPoints(); ++v)
    {
      CD_CHECK(!mesh.IsBoundaryVertex(v) && mesh.IsCollapsible(v));
      valences += mesh.Valence(v);
      // FindHalfEdge agrees with the face list.
      mesh.ForEachNeighbor(v,
                           [&](int32_t u)
                           {
                             const int32_t h = mesh.FindHalfEdge(v, u);
                             CD_CHECK(h >= 0 && mesh.Origin(h) == v && mesh.Target(h) == u);
                           });
    }
    CD_CHECK(valences == 3LL * m.NumberOfTriangles());
    CheckBuildThreads(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
  }
}

CD_TEST_CASE(HalfEdgeBuildOpen)
{
  const int nx = 12, ny = 7;
  const PlainMesh m = ToPlain(meshes::Grid(nx, ny, meshes::Pattern::Constant));
  HalfEdgeMesh mesh;
  const MeshBuildReport report =
    mesh.Build(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
  CD_CHECK(report.BoundaryEdges == 2 * (nx + ny));
  CD_CHECK(report.LockedVertices == 0);
  CD_CHECK(CheckMeshConsistency(mesh, false) == 0);
  int boundaryVertices = 0;
  long long valences = 0;
  for (int32_t v = 0; v < m.NumberOfPoints(); ++v)
  {
    const int i = v % (nx + 1), j = v / (nx + 1);
    const bool onBorder = i == 0 || j == 0 || i == nx || j == ny;
    CD_CHECK(mesh.IsBoundaryVertex(v) == onBorder);
    boundaryVertices += mesh.IsBoundaryVertex(v) ? 1 : 0;
    valences += mesh.Valence(v);
  }
  CD_CHECK(boundaryVertices == 2 * (nx + ny));
  // 2E = sum of valences; E = (3F + boundary edges) / 2.
  CD_CHECK(valences == 3LL * m.NumberOfTriangles() + 2 * (nx + ny));
  // The interior vertex (1,1) has valence 6; the corner (0,0) valence 3; (nx,0) valence 2.
  CD_CHECK(mesh.Valence((nx + 1) + 1) == 6);
  CD_CHECK(mesh.Valence(0) == 3);
  CD_CHECK(mesh.Valence(nx) == 2);
  // The early-stopping test agrees with the count, at and around each vertex's valence.
  long long disagreements = 0;
  for (int32_t v = 0; v < m.NumberOfPoints(); ++v)
  {
    const int valence = mesh.Valence(v);
    for (int most = valence - 2; most <= valence + 1; ++most)
    {
      disagreements += mesh.IsValenceAtMost(v, most) != (valence <= most) ? 1 : 0;
    }
  }
  CD_CHECK(disagreements == 0);
  // A single triangle: three boundary edges.
  const int32_t one[3] = { 0, 1, 2 };
  HalfEdgeMesh single;
  CD_CHECK(single.Build(3, one, 1).BoundaryEdges == 3);
  CD_CHECK(single.IsBoundaryVertex(0) && single.Valence(0) == 2);
}

CD_TEST_CASE(HalfEdgeNonManifold)
{
  // Three triangles on the edge 0-1 (a fin), plus an unrelated triangle.
  const int32_t fin[12] = { 0, 1, 2, 1, 0, 3, 0, 1, 4, 5, 6, 7 };
  HalfEdgeMesh mesh;
  MeshBuildReport report = mesh.Build(8, fin, 4);
  CheckBuildThreads(8, fin, 4);
  CD_CHECK(report.NonManifoldEdges == 1);
  CD_CHECK(mesh.IsLocked(0) && mesh.IsLocked(1));
  CD_CHECK(!mesh.IsLocked(2) && !mesh.IsLocked(3) && !mesh.IsLocked(4) && !mesh.IsLocked(5));
  CD_CHECK(!mesh.IsCollapsible(0) && mesh.IsCollapsible(5));

  // Two triangles on an edge with the same orientation (inconsistent): locked.
  const int32_t twisted[6] = { 0, 1, 2, 0, 1, 3 };
  report = mesh.Build(4, twisted, 2);
  CheckBuildThreads(4, twisted, 2);
  CD_CHECK(report.NonManifoldEdges == 1 && report.MisorientedEdges == 1);
  CD_CHECK(mesh.IsLocked(0) && mesh.IsLocked(1) && !mesh.IsLocked(2));

  // A bow-tie: two fans (0,1,2),(0,2,3) and (0,4,5),(0,5,6) meet only at vertex 0.
  const int32_t bowtie[12] = { 0, 1, 2, 0, 2, 3, 0, 4, 5, 0, 5, 6 };
  report = mesh.Build(7, bowtie, 4);
  CheckBuildThreads(7, bowtie, 4);
  CD_CHECK(report.NonManifoldEdges == 0);
  CD_CHECK(report.NonManifoldVertices == 1);
  CD_CHECK(report.LockedVertices == 1);
  CD_CHECK(mesh.IsLocked(0));
  for (int32_t v = 1; v < 7; ++v)
  {
    CD_CHECK(!mesh.IsLocked(v));
  }
  // A bow-tie of two closed-around fans (vertex 0 interior to both): two tetrahedra
  // sharing a vertex.
  const int32_t tetras[24] = { 0, 2, 1, 0, 3, 2, 0, 1, 3, 1, 2, 3,
                               0, 5, 4, 0, 6, 5, 0, 4, 6, 4, 5, 6 };
  report = mesh.Build(7, tetras, 8);
  CheckBuildThreads(7, tetras, 8);
  CD_CHECK(report.NonManifoldVertices == 1);
  CD_CHECK(mesh.IsLocked(0) && !mesh.IsLocked(1) && !mesh.IsLocked(4));
  // An isolated vertex is reported and not collapsible.
  const int32_t tri[3] = { 0, 1, 2 };
  report = mesh.Build(4, tri, 1);
  CheckBuildThreads(4, tri, 1);
  CD_CHECK(report.IsolatedVertices == 1);
  CD_CHECK(!mesh.IsCollapsible(3));
}

CD_TEST_CASE(HalfEdgeCollapse)
{
  struct Case
  {
    vtkSmartPointer<vtkPolyData> Poly;
    bool Closed;
  };
  const Case cases[] = { { meshes::Icosphere(3, meshes::Pattern::Constant), true },
                         { meshes::Torus(30, 12, meshes::Pattern::Constant), true },
                         { meshes::Grid(20, 14, meshes::Pattern::Constant), false } };
  for (const Case& c : cases)
  {
    const PlainMesh m = ToPlain(c.Poly);
    HalfEdgeMesh mesh;
    mesh.Build(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
    const long long euler = AnalyseTopology(LiveTriangles(mesh)).Euler();
    CollapseRuleOptions options;
    options.MinimumNormalCosine = -1.0; // topology only: many different collapses
    CollapseRules rules(options);
    std::mt19937 rng(99);
    std::uniform_int_distribution<int32_t> pick(0, m.NumberOfPoints() - 1);
    int collapses = 0, refused = 0, boundaryCollapses = 0;
    for (int attempt = 0; attempt < 20000 && mesh.GetNumberOfLiveFaces() > 40; ++attempt)
    {
      const int32_t v0 = pick(rng);
      if (!mesh.IsCollapsible(v0))
      {
        continue;
      }
      std::vector<int32_t> ring;
      mesh.ForEachNeighbor(v0, [&](int32_t u) { ring.push_back(u); });
      const int32_t v1 = ring[rng() % ring.size()];
      if (!rules.IsLegal(mesh, m.Positions.data(), v0, v1))
      {
        ++refused;
        continue;
      }
      const bool interiorEdge = mesh.FindHalfEdge(v0, v1) >= 0 && mesh.FindHalfEdge(v1, v0) >= 0;
      const int64_t before = mesh.GetNumberOfLiveFaces();
      const int removed = mesh.Collapse(v0, v1);
      CD_CHECK(removed == (interiorEdge ? 2 : 1));
      CD_CHECK(mesh.GetNumberOfLiveFaces() == before - removed);
      CD_CHECK(mesh.IsRemoved(v0) && !mesh.IsCollapsible(v0));
      boundaryCollapses += interiorEdge ? 0 : 1;
      ++collapses;
      if (CheckMeshConsistency(mesh, c.Closed) != 0)
      {
        ReportFailure(__FILE__, __LINE__, "consistent after collapse",
                      "after collapse " + std::to_string(collapses) + ": " + std::to_string(v0) +
                        " -> " + std::to_string(v1));
        return;
      }
      CD_CHECK(AnalyseTopology(LiveTriangles(mesh)).Euler() == euler);
    }
    std::cout << "  " << m.NumberOfTriangles() << " -> " << mesh.GetNumberOfLiveFaces()
              << " triangles in " << collapses << " collapses (" << boundaryCollapses
              << " on the boundary), " << refused << " refused" << std::endl;
    CD_CHECK(collapses > m.NumberOfTriangles() / 4);
    CD_CHECK(refused > 0);
    CD_CHECK(c.Closed || boundaryCollapses > 0);
  }
}

//------------------------------------------------------------------------------
/// Morton codes by hand: x, y and z take bits 0, 1 and 2 of each group of three.
void CheckMortonCodes()
{
  const double lo[3] = { 0, 0, 0 };
  const double cell = 1.0 / 1024; // box [0,1]^3
  auto code = [&](double x, double y, double z)
  {
    const double p[3] = { (x + 0.5) * cell, (y + 0.5) * cell, (z + 0.5) * cell };
    return MortonCode(p, lo, 1.0);
  };
  CD_CHECK(code(0, 0, 0) == 0u);
  CD_CHECK(code(1, 0, 0) == 1u);
  CD_CHECK(code(0, 1, 0) == 2u);
  CD_CHECK(code(0, 0, 1) == 4u);
  CD_CHECK(code(2, 0, 0) == 8u);
  // x = 3 (bits 0, 1), y = 5 (bits 0, 2), z = 6 (bits 1, 2): bits 0, 3; 1, 7; 5, 8.
  CD_CHECK(code(3, 5, 6) == 1u + 8u + 2u + 128u + 32u + 256u);
  CD_CHECK(code(1023, 1023, 1023) == (1u << 30) - 1);
  const double outside[3] = { -5, 2, std::nan("") };
  CD_CHECK(MortonCode(outside, lo, 1.0) == code(0, 1023, 0)); // clamped; NaN goes to 0
}

/// Permute: block i goes to block to[i], cycles of every length included.
void CheckPermute()
{
  const int32_t to[7] = { 3, 0, 1, 2, 4, 6, 5 }; // a 4-cycle, a fixed point, a swap
  std::vector<int> values;
  for (int i = 0; i < 7; ++i)
  {
    values.insert(values.end(), { 10 * i, 10 * i + 1 });
  }
  Permute(values, 7, to, 2);
  for (int i = 0; i < 7; ++i)
  {
    CD_CHECK(values[2 * to[i]] == 10 * i && values[2 * to[i] + 1] == 10 * i + 1);
  }
}

/// The vertex order is a permutation that follows the Morton codes, equal codes in input order.
void CheckSpatialVertexOrder(const PlainMesh& m, const SpatialOrder& order)
{
  const int32_t n = m.NumberOfPoints();
  CD_CHECK(static_cast<int32_t>(order.OldVertex.size()) == n);
  CD_CHECK(static_cast<int32_t>(order.NewVertex.size()) == n);
  std::vector<char> seen(n, 0);
  for (int32_t v = 0; v < n; ++v)
  {
    const int32_t old = order.OldVertex[v];
    CD_CHECK(old >= 0 && old < n && !seen[old]);
    seen[old] = 1;
    CD_CHECK(order.NewVertex[old] == v);
  }
  double boxLo[3] = { 1e300, 1e300, 1e300 }, boxHi[3] = { -1e300, -1e300, -1e300 };
  for (int32_t v = 1; v < n; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      boxLo[k] = std::min(boxLo[k], m.Points[3 * v + k]);
      boxHi[k] = std::max(boxHi[k], m.Points[3 * v + k]);
    }
  }
  const double extent = std::max({ boxHi[0] - boxLo[0], boxHi[1] - boxLo[1], boxHi[2] - boxLo[2] });
  for (int32_t v = 1; v < n; ++v)
  {
    const int32_t a = order.OldVertex[v - 1], b = order.OldVertex[v];
    const uint32_t ca = MortonCode(&m.Points[3 * a], boxLo, extent);
    const uint32_t cb = MortonCode(&m.Points[3 * b], boxLo, extent);
    CD_CHECK(ca < cb || (ca == cb && a < b));
  }
}

/// The face order is a permutation by smallest renumbered vertex, equal keys in input order.
void CheckSpatialFaceOrder(const PlainMesh& m, const SpatialOrder& order)
{
  const int32_t nt = m.NumberOfTriangles();
  CD_CHECK(static_cast<int32_t>(order.OldFace.size()) == nt);
  std::vector<char> seenFace(nt, 0);
  int32_t previousKey = -1, previousFace = -1;
  for (int32_t f = 0; f < nt; ++f)
  {
    const int32_t old = order.OldFace[f];
    CD_CHECK(old >= 0 && old < nt && !seenFace[old]);
    seenFace[old] = 1;
    const int32_t* t = &m.Triangles[3 * old];
    const int32_t key =
      std::min({ order.NewVertex[t[0]], order.NewVertex[t[1]], order.NewVertex[t[2]] });
    CD_CHECK(key > previousKey || (key == previousKey && old > previousFace));
    previousKey = key;
    previousFace = old;
  }
}

CD_TEST_CASE(SpatialOrder)
{
  CheckMortonCodes();
  CheckPermute();

  // A whole mesh: both orders are permutations, vertices follow their codes, triangles their
  // smallest renumbered vertex, and equal keys keep the input order.
  PlainMesh m = ToPlain(meshes::Torus(40, 16, meshes::Pattern::Constant));
  m.Points[0] = std::nan(""); // a non-finite point must not break the order
  SpatialOrder order;
  ComputeSpatialOrder(m.NumberOfPoints(), m.Points.data(), m.NumberOfTriangles(),
                      m.Triangles.data(), order);
  CheckSpatialVertexOrder(m, order);
  CheckSpatialFaceOrder(m, order);
}

/// Decimate a little (random legal collapses), so that dead faces and removed vertices exist.
void DecimateALittle(HalfEdgeMesh& mesh, const PlainMesh& m, std::mt19937& rng)
{
  CollapseRuleOptions options;
  options.MinimumNormalCosine = -1.0;
  CollapseRules rules(options);
  for (int attempt = 0; attempt < 400; ++attempt)
  {
    const int32_t v0 = static_cast<int32_t>(rng() % m.NumberOfPoints());
    if (!mesh.IsCollapsible(v0))
    {
      continue;
    }
    std::vector<int32_t> ring;
    mesh.ForEachNeighbor(v0, [&](int32_t u) { ring.push_back(u); });
    const int32_t v1 = ring[rng() % ring.size()];
    if (rules.IsLegal(mesh, m.Positions.data(), v0, v1))
    {
      mesh.Collapse(v0, v1);
    }
  }
}

/// The identity permutation of `count` ids, shuffled.
std::vector<int32_t> ShuffledIds(int32_t count, std::mt19937& rng)
{
  std::vector<int32_t> to(count);
  for (int32_t i = 0; i < count; ++i)
  {
    to[i] = i;
  }
  std::shuffle(to.begin(), to.end(), rng);
  return to;
}

/// The inverse of a permutation.
std::vector<int32_t> InversePermutation(const std::vector<int32_t>& to)
{
  std::vector<int32_t> back(to.size());
  for (int32_t i = 0; i < static_cast<int32_t>(to.size()); ++i)
  {
    back[to[i]] = i;
  }
  return back;
}

/// The renumbered faces are the old ones under the new names, twins included.
void CheckRenumberedFaces(const HalfEdgeMesh& before, const HalfEdgeMesh& mesh,
                          const std::vector<int32_t>& vertexTo, const std::vector<int32_t>& faceTo)
{
  const int32_t nf = before.GetNumberOfFaceSlots();
  for (int32_t f = 0; f < nf; ++f)
  {
    CD_CHECK(mesh.IsFaceAlive(faceTo[f]) == before.IsFaceAlive(f));
    if (!before.IsFaceAlive(f))
    {
      continue;
    }
    int32_t a[3], b[3];
    before.GetFace(f, a);
    mesh.GetFace(faceTo[f], b);
    for (int k = 0; k < 3; ++k)
    {
      CD_CHECK(b[k] == vertexTo[a[k]]);
      const int32_t twin = before.Twin(3 * f + k);
      CD_CHECK(mesh.Twin(3 * faceTo[f] + k) == (twin < 0 ? -1 : 3 * faceTo[twin / 3] + twin % 3));
    }
  }
}

/// The renumbered vertices keep their flags and their fans (from the same half-edge).
void CheckRenumberedVertices(const HalfEdgeMesh& before, const HalfEdgeMesh& mesh,
                             const std::vector<int32_t>& vertexTo)
{
  const int32_t n = before.GetNumberOfVertices();
  for (int32_t v = 0; v < n; ++v)
  {
    const int32_t w = vertexTo[v];
    CD_CHECK(mesh.IsLocked(w) == before.IsLocked(v));
    CD_CHECK(mesh.IsRemoved(w) == before.IsRemoved(v));
    CD_CHECK(mesh.IsCollapsible(w) == before.IsCollapsible(v));
    if (before.IsCollapsible(v))
    {
      CD_CHECK(mesh.IsBoundaryVertex(w) == before.IsBoundaryVertex(v));
      std::vector<int32_t> expected, got;
      before.ForEachNeighbor(v, [&](int32_t u) { expected.push_back(vertexTo[u]); });
      mesh.ForEachNeighbor(w, [&](int32_t u) { got.push_back(u); });
      CD_CHECK(got == expected); // the same fan, from the same starting half-edge
    }
  }
}

/// Renumbering back with the inverse permutations gives the very same arrays.
void CheckRenumberedBack(const HalfEdgeMesh& before, HalfEdgeMesh& mesh,
                         const std::vector<int32_t>& vertexTo, const std::vector<int32_t>& faceTo)
{
  const int32_t n = before.GetNumberOfVertices();
  const int32_t nf = before.GetNumberOfFaceSlots();
  const std::vector<int32_t> vertexBack = InversePermutation(vertexTo);
  const std::vector<int32_t> faceBack = InversePermutation(faceTo);
  mesh.Renumber(vertexBack.data(), faceBack.data());
  for (int32_t h = 0; h < 3 * nf; ++h)
  {
    CD_CHECK(mesh.Origin(h) == before.Origin(h) && mesh.Twin(h) == before.Twin(h));
  }
  for (int32_t v = 0; v < n; ++v)
  {
    CD_CHECK(mesh.Outgoing(v) == before.Outgoing(v));
    CD_CHECK(mesh.IsLocked(v) == before.IsLocked(v) && mesh.IsRemoved(v) == before.IsRemoved(v));
  }
}

/// HalfEdgeMesh::Renumber: a renumbered mesh is the same mesh under new names, and renumbering
/// it back restores every array, mid-decimation included.
CD_TEST_CASE(HalfEdgeRenumber)
{
  for (bool closed : { true, false })
  {
    const PlainMesh m = ToPlain(closed ? meshes::Torus(30, 12, meshes::Pattern::Constant)
                                       : meshes::Grid(20, 14, meshes::Pattern::Constant));
    HalfEdgeMesh mesh;
    mesh.Build(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
    mesh.Lock(7);
    // Decimate a little first, so that dead faces and removed vertices are renumbered too.
    std::mt19937 rng(5);
    DecimateALittle(mesh, m, rng);
    const HalfEdgeMesh before = mesh;
    const std::vector<int32_t> vertexTo = ShuffledIds(mesh.GetNumberOfVertices(), rng);
    const std::vector<int32_t> faceTo = ShuffledIds(mesh.GetNumberOfFaceSlots(), rng);
    mesh.Renumber(vertexTo.data(), faceTo.data());
    CheckMeshConsistency(mesh, closed);
    CD_CHECK(mesh.GetNumberOfLiveFaces() == before.GetNumberOfLiveFaces());
    CheckRenumberedFaces(before, mesh, vertexTo, faceTo);
    CheckRenumberedVertices(before, mesh, vertexTo);
    CheckRenumberedBack(before, mesh, vertexTo, faceTo);
  }
}

/// The arrays of an input renumbered by hand (RenumberByHand).
struct RenumberedArrays
{
  std::vector<double> Points;
  std::vector<float> Colors;
  std::vector<uint8_t> Fixed;
  std::vector<int32_t> Triangles;
};

/// The same input (with colours and fixed points) renumbered by hand in `order`.
DecimatorInput RenumberByHand(const DecimatorInput& input, const SpatialOrder& order,
                              RenumberedArrays& arrays)
{
  const int32_t n = input.NumberOfPoints;
  const int32_t nt = input.NumberOfTriangles;
  std::vector<double>& points = arrays.Points;
  std::vector<float>& colors2 = arrays.Colors;
  std::vector<uint8_t>& fixed2 = arrays.Fixed;
  std::vector<int32_t>& triangles = arrays.Triangles;
  points.assign(3 * static_cast<size_t>(n), 0.0);
  colors2.assign(3 * static_cast<size_t>(n), 0.0f);
  fixed2.assign(n, 0);
  triangles.assign(3 * static_cast<size_t>(nt), 0);
  for (int32_t v = 0; v < n; ++v)
  {
    const int32_t old = order.OldVertex[v];
    for (int k = 0; k < 3; ++k)
    {
      points[3 * v + k] = input.Points[3 * old + k];
      colors2[3 * v + k] = input.Colors[3 * old + k];
    }
    fixed2[v] = input.Fixed[old];
  }
  for (int32_t f = 0; f < nt; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      triangles[3 * f + k] = order.NewVertex[input.Triangles[3 * order.OldFace[f] + k]];
    }
  }
  DecimatorInput renumbered = input;
  renumbered.Points = points.data();
  renumbered.Colors = colors2.data();
  renumbered.Fixed = fixed2.data();
  renumbered.Triangles = triangles.data();
  return renumbered;
}

/// The faces of the run in order (input ids) that differ from the run on the renumbered input.
long long CountRenumberedFaceMismatches(const HalfEdgeMesh& ma, const HalfEdgeMesh& mb,
                                        const SpatialOrder& order, int32_t nt)
{
  long long mismatches = 0;
  for (int32_t f = 0; f < nt; ++f)
  {
    const int32_t slot = order.OldFace[f]; // b's face f is the input's face `slot`
    if (ma.IsFaceAlive(slot) != mb.IsFaceAlive(f))
    {
      ++mismatches;
      continue;
    }
    if (!mb.IsFaceAlive(f))
    {
      continue;
    }
    int32_t ta[3], tb[3];
    ma.GetFace(slot, ta);
    mb.GetFace(f, tb);
    for (int k = 0; k < 3; ++k)
    {
      mismatches += ta[k] != order.OldVertex[tb[k]] ? 1 : 0;
    }
  }
  return mismatches;
}

/// The vertex states (removal, position, metric) of the two runs that differ.
long long CountRenumberedVertexMismatches(const Decimator& inOrder, const Decimator& byHand,
                                          const SpatialOrder& order, int32_t n, ErrorMetric metric)
{
  const HalfEdgeMesh& ma = inOrder.GetMesh();
  const HalfEdgeMesh& mb = byHand.GetMesh();
  long long mismatches = 0;
  for (int32_t v = 0; v < n; ++v)
  {
    const int32_t old = order.OldVertex[v];
    mismatches += ma.IsRemoved(old) != mb.IsRemoved(v) ? 1 : 0;
    mismatches += inOrder.IsMoved(old) != byHand.IsMoved(v) ? 1 : 0;
    const float* pa = inOrder.GetNormalizedPosition(old);
    const float* pb = byHand.GetNormalizedPosition(v);
    mismatches += std::equal(pa, pa + 3, pb) ? 0 : 1;
    if (metric == ErrorMetric::HalfEdgeColor)
    {
      mismatches += inOrder.GetMetrics()[old].Importance != byHand.GetMetrics()[v].Importance;
      mismatches += inOrder.GetMetrics()[old].Q.C != byHand.GetMetrics()[v].Q.C;
    }
    else
    {
      mismatches += inOrder.GetColorQuadrics()[old].C != byHand.GetColorQuadrics()[v].C;
    }
  }
  return mismatches;
}

/// With `metric`: the run in spatial order against the plain run on the renumbered input.
void CheckRenumberedRun(ErrorMetric metric, const DecimatorInput& input,
                        const DecimatorInput& renumbered, const SpatialOrder& order)
{
  const int32_t n = input.NumberOfPoints;
  const int32_t nt = input.NumberOfTriangles;
  DecimatorOptions options;
  options.Metric = metric;
  options.OptimalPlacement = metric == ErrorMetric::ColorQuadric;
  Decimator inOrder(options);
  const DecimatorStatistics a = inOrder.Run(input, nt / 10);
  options.Renumber = false;
  Decimator byHand(options);
  const DecimatorStatistics b = byHand.Run(renumbered, nt / 10);
  CD_CHECK(a.OutputTriangles <= nt / 10);
  CD_CHECK(a.Collapses == b.Collapses && a.OutputTriangles == b.OutputTriangles);

  const HalfEdgeMesh& ma = inOrder.GetMesh();
  const HalfEdgeMesh& mb = byHand.GetMesh();
  CD_CHECK(ma.GetNumberOfFaceSlots() == nt && mb.GetNumberOfFaceSlots() == nt);
  long long mismatches = CountRenumberedFaceMismatches(ma, mb, order, nt);
  CD_CHECK_MSG(mismatches == 0, mismatches << " faces differ from the run on the renumbered input");
  mismatches = CountRenumberedVertexMismatches(inOrder, byHand, order, n, metric);
  CD_CHECK_MSG(mismatches == 0, mismatches << " vertex states differ");
  for (int32_t i = 0; i < n; i += 97)
  {
    CD_CHECK(!ma.IsRemoved(i)); // the fixed points followed their vertices
  }
  CD_CHECK(b.Collapses > nt / 3); // a real decimation, not an empty comparison
}

/**
 * Decimating in the spatial order (DecimatorOptions::Renumber) is decimating the renumbered
 * mesh and mapping the result back: it must give exactly what a plain run on the renumbered
 * input gives, in the input's ids (faces, vertices, positions and metric state).
 */
CD_TEST_CASE(RenumberSameResult)
{
  auto poly = meshes::UVSphere(260, meshes::Pattern::FineDetail);
  const PlainMesh m = ToPlain(poly);
  const int32_t n = m.NumberOfPoints();
  const int32_t nt = m.NumberOfTriangles();
  CD_CHECK(n >= 65536); // above Decimator::LargeMeshVertices
  const std::vector<float> colors = UnitColors(poly);
  std::vector<uint8_t> fixed(n, 0);
  for (int32_t i = 0; i < n; i += 97)
  {
    fixed[i] = 1;
  }
  DecimatorInput input;
  input.NumberOfPoints = n;
  input.Points = m.Points.data();
  input.Colors = colors.data();
  input.NumberOfTriangles = nt;
  input.Triangles = m.Triangles.data();
  input.Fixed = fixed.data();

  // The same input, renumbered by hand.
  SpatialOrder order;
  ComputeSpatialOrder(n, m.Points.data(), nt, m.Triangles.data(), order);
  RenumberedArrays arrays;
  const DecimatorInput renumbered = RenumberByHand(input, order, arrays);

  for (ErrorMetric metric : { ErrorMetric::HalfEdgeColor, ErrorMetric::ColorQuadric })
  {
    CheckRenumberedRun(metric, input, renumbered, order);
  }
}

//------------------------------------------------------------------------------
/// The core's input on a plain mesh's points and triangles, with `colors` (3 a point).
DecimatorInput InputOf(const PlainMesh& m, const float* colors)
{
  DecimatorInput input;
  input.NumberOfPoints = m.NumberOfPoints();
  input.Points = m.Points.data();
  input.Colors = colors;
  input.NumberOfTriangles = m.NumberOfTriangles();
  input.Triangles = m.Triangles.data();
  return input;
}

/// A jittered sphere with random colours: no two collapses cost exactly the same.
DecimatorInput JitteredSphere(int resolution, std::vector<double>& points,
                              std::vector<float>& colors, std::vector<int32_t>& triangles)
{
  const PlainMesh m = ToPlain(meshes::UVSphere(resolution, meshes::Pattern::SmoothGradient));
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  points = m.Points;
  for (double& x : points)
  {
    x += jitter(rng);
  }
  colors.resize(points.size());
  for (float& c : colors)
  {
    c = unit(rng);
  }
  triangles = m.Triangles;
  DecimatorInput input;
  input.NumberOfPoints = m.NumberOfPoints();
  input.Points = points.data();
  input.Colors = colors.data();
  input.NumberOfTriangles = m.NumberOfTriangles();
  input.Triangles = triangles.data();
  return input;
}

/// Face slots and removed vertices that differ between two runs (any metric).
long long CountMeshDifferences(const Decimator& a, const Decimator& b)
{
  const HalfEdgeMesh& ma = a.GetMesh();
  const HalfEdgeMesh& mb = b.GetMesh();
  if (ma.GetNumberOfFaceSlots() != mb.GetNumberOfFaceSlots() ||
      ma.GetNumberOfVertices() != mb.GetNumberOfVertices())
  {
    return -1;
  }
  long long differences = 0;
  for (int32_t f = 0; f < ma.GetNumberOfFaceSlots(); ++f)
  {
    int32_t ta[3], tb[3];
    ma.GetFace(f, ta);
    mb.GetFace(f, tb);
    differences += std::equal(ta, ta + 3, tb) ? 0 : 1;
  }
  for (int32_t v = 0; v < ma.GetNumberOfVertices(); ++v)
  {
    differences += ma.IsRemoved(v) != mb.IsRemoved(v) ? 1 : 0;
  }
  return differences;
}

/// Faces, removed vertices, positions and metric state that differ between two runs.
long long CountDifferences(const Decimator& a, const Decimator& b, ErrorMetric metric)
{
  const HalfEdgeMesh& ma = a.GetMesh();
  const HalfEdgeMesh& mb = b.GetMesh();
  if (ma.GetNumberOfFaceSlots() != mb.GetNumberOfFaceSlots() ||
      ma.GetNumberOfVertices() != mb.GetNumberOfVertices())
  {
    return -1;
  }
  long long differences = CountMeshDifferences(a, b);
  for (int32_t v = 0; v < ma.GetNumberOfVertices(); ++v)
  {
    const float* pa = a.GetNormalizedPosition(v);
    const float* pb = b.GetNormalizedPosition(v);
    differences += std::equal(pa, pa + 3, pb) ? 0 : 1;
    if (metric == ErrorMetric::ColorQuadric)
    {
      differences += a.GetColorQuadrics()[v].C != b.GetColorQuadrics()[v].C ? 1 : 0;
    }
    else
    {
      differences += a.GetMetrics()[v].Importance != b.GetMetrics()[v].Importance ? 1 : 0;
      differences += a.GetMetrics()[v].Q.C != b.GetMetrics()[v].Q.C ? 1 : 0;
    }
  }
  return differences;
}

/// The same run on 1 and on 3 threads.
struct OneAndThree
{
  std::unique_ptr<Decimator> One, Three;
  DecimatorStatistics A, B;
  OneAndThree(DecimatorOptions options, const DecimatorInput& input, int64_t target)
  {
    options.NumberOfThreads = 1;
    this->One.reset(new Decimator(options));
    this->A = this->One->Run(input, target);
    options.NumberOfThreads = 3;
    this->Three.reset(new Decimator(options));
    this->B = this->Three->Run(input, target);
  }
};

/**
 * Costing on several threads gives the same decimation as on one, for both schedules and
 * the metrics with and without placement (each evaluation writes its own vertex only).
 */
CD_TEST_CASE(ThreadsSameResult)
{
  std::vector<double> points;
  std::vector<float> colors;
  std::vector<int32_t> triangles;
  // Large enough for the blocks of a pass to be collapsed on several threads; blocks of 256
  // ids so that the wide blocks (2048) are many too.
  const DecimatorInput input = JitteredSphere(260, points, colors, triangles);
  const int64_t target = input.NumberOfTriangles / 10;
  for (CollapseSchedule schedule : { CollapseSchedule::Greedy, CollapseSchedule::Batched })
  {
    for (ErrorMetric metric : { ErrorMetric::HalfEdgeColor, ErrorMetric::ColorQuadric })
    {
      DecimatorOptions options;
      options.BlockShift = 8;
      options.VerifyBlockFlags = true;
      options.Metric = metric;
      options.OptimalPlacement = metric == ErrorMetric::ColorQuadric;
      options.Schedule = schedule;
      const OneAndThree runs(options, input, target);
      const Decimator &one = *runs.One, &three = *runs.Three;
      const DecimatorStatistics &a = runs.A, &b = runs.B;
      std::cout << "  schedule " << static_cast<int>(schedule) << ", metric "
                << static_cast<int>(metric) << ": " << a.Collapses << " collapses, " << b.Passes
                << " passes, " << b.Threads << " threads costing, " << b.CollapseThreads << " ("
                << b.WideCollapseThreads << " in wide blocks) collapsing" << std::endl;
      CD_CHECK(a.Threads == 1 && b.Threads == 3); // the threads did start
      CD_CHECK(a.CollapseThreads == 1 && a.WideCollapseThreads == 1);
      CD_CHECK(schedule == CollapseSchedule::Batched
                 ? b.CollapseThreads >= 2 && b.WideCollapseThreads >= 2
                 : b.CollapseThreads == 1 && b.WideCollapseThreads == 1);
      CD_CHECK(a.OutputTriangles <= target && a.Collapses > input.NumberOfPoints / 3);
      CD_CHECK(a.Collapses == b.Collapses && a.OutputTriangles == b.OutputTriangles);
      CD_CHECK_MSG(a.StaleBlockFlags == 0 && b.StaleBlockFlags == 0,
                   a.StaleBlockFlags << " and " << b.StaleBlockFlags << " stale block flags");
      CD_CHECK(a.RejectedPops == b.RejectedPops && a.Passes == b.Passes);
      const long long differences = CountDifferences(one, three, metric);
      CD_CHECK_MSG(differences == 0, differences << " differences between 1 and 3 threads");
      CD_CHECK((schedule == CollapseSchedule::Batched) == (a.Passes > 0));
    }
  }
}

/// 401 triangle strips, one of 600 triangles and the others of 1 to 40, their vertex ids and
/// faces shuffled (so that the threads' ranges of faces unite the same sets at once).
struct ShuffledStrips
{
  static constexpr int Count = 401;
  std::vector<int32_t> First; ///< strip s: vertices First[s] .. First[s + 1] before the shuffle
  std::vector<int> Length;    ///< triangles of each strip
  std::vector<int32_t> Id;    ///< shuffled id of each vertex
  std::vector<int> StripOf;   ///< strip of each face, in the shuffled face order
  std::vector<int32_t> Triangles;

  explicit ShuffledStrips(std::mt19937& random)
    : First(Count + 1, 0)
    , Length(Count)
  {
    for (int s = 0; s < Count; ++s)
    {
      this->Length[s] = s == 0 ? 600 : 1 + static_cast<int>(random() % 40);
      this->First[s + 1] = this->First[s] + this->Length[s] + 2;
    }
    this->Id.resize(static_cast<size_t>(this->First[Count]));
    std::iota(this->Id.begin(), this->Id.end(), 0);
    std::shuffle(this->Id.begin(), this->Id.end(), random);
    // Triangle i of a strip: (i, i + 1, i + 2), every other one turned (consistent orientation).
    std::vector<std::pair<std::array<int32_t, 3>, int>> faces;
    for (int s = 0; s < Count; ++s)
    {
      for (int32_t i = 0; i < this->Length[s]; ++i)
      {
        const int32_t a = this->Id[this->First[s] + i], b = this->Id[this->First[s] + i + 1],
                      c = this->Id[this->First[s] + i + 2];
        faces.push_back(
          { i % 2 == 0 ? std::array<int32_t, 3>{ a, b, c } : std::array<int32_t, 3>{ b, a, c },
            s });
      }
    }
    std::shuffle(faces.begin(), faces.end(), random);
    for (const auto& face : faces)
    {
      this->Triangles.insert(this->Triangles.end(), face.first.begin(), face.first.end());
      this->StripOf.push_back(face.second);
    }
  }
  /// Its lowest vertex id.
  int32_t Lowest(int s) const
  {
    return *std::min_element(this->Id.begin() + this->First[s],
                             this->Id.begin() + this->First[s + 1]);
  }
};

/// FindSmallPieces on the strips, a vertex of strips 5 and 9 kept, against the strips by hand:
/// every strip but the largest and those two, by lowest vertex id, faces in face order.
Pieces CheckStripPieces(const ShuffledStrips& strips, const HalfEdgeMesh& mesh, int threads)
{
  const std::set<int32_t> kept = { strips.Id[strips.First[5]], strips.Id[strips.First[9] + 2] };
  std::vector<std::pair<int32_t, int>> expected; // (lowest id, strip)
  for (int s = 1; s < ShuffledStrips::Count; ++s)
  {
    if (s != 5 && s != 9)
    {
      expected.emplace_back(strips.Lowest(s), s);
    }
  }
  std::sort(expected.begin(), expected.end());
  const Pieces pieces = FindSmallPieces(
    mesh, [&kept](int32_t v) { return kept.count(v) > 0; }, threads);
  CD_CHECK_MSG(pieces.Size() == expected.size(), pieces.Size() << " pieces");
  int wrong = 0;
  for (size_t k = 0; k < std::min(pieces.Size(), expected.size()); ++k)
  {
    const int strip = expected[k].second;
    wrong += pieces.Start[k + 1] - pieces.Start[k] != strips.Length[strip] ? 1 : 0;
    for (int32_t i = pieces.Start[k]; i < pieces.Start[k + 1]; ++i)
    {
      wrong += strips.StripOf[size_t(pieces.Faces[i])] != strip ? 1 : 0;
      wrong += i > pieces.Start[k] && pieces.Faces[i] <= pieces.Faces[i - 1] ? 1 : 0;
    }
  }
  CD_CHECK_MSG(wrong == 0, wrong << " wrong faces or counts on " << threads << " threads");
  return pieces;
}

/// 2,500 grey tetrahedra (closed: only removed whole) of edges 0.001-0.01 beside a crumpled
/// 30 x 30 grid in random colours, so that they are cheaper to remove than its collapses.
struct TetrahedraBesideGrid
{
  std::vector<double> Points;
  std::vector<float> Colors;
  std::vector<int32_t> Cells;

  explicit TetrahedraBesideGrid(std::mt19937& random)
  {
    const PlainMesh grid = ToPlain(meshes::FlatGrid(30, 30, meshes::Pattern::Constant));
    this->Points = grid.Points;
    this->Cells = grid.Triangles;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (size_t v = 0; v < this->Points.size() / 3; ++v)
    {
      this->Points[3 * v + 2] = 0.05 * unit(random);
    }
    for (int t = 0; t < 2500; ++t)
    {
      const auto base = static_cast<int32_t>(this->Points.size() / 3);
      const double size = 0.1 + 0.9 * unit(random), at[3] = { 3.0 + t % 50, 3.0 + t / 50, 1.0 };
      const double corner[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
      for (const auto& c : corner)
      {
        for (int k = 0; k < 3; ++k)
        {
          this->Points.push_back(at[k] + 0.01 * size * c[k]);
        }
      }
      const int32_t tetrahedron[12] = { 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2 };
      for (const int32_t corner : tetrahedron)
      {
        this->Cells.push_back(base + corner);
      }
    }
    this->Colors.assign(this->Points.size(), 0.5f);
    for (size_t i = 0; i < grid.Points.size(); ++i)
    {
      this->Colors[i] = static_cast<float>(unit(random));
    }
  }
  DecimatorInput Input() const
  {
    DecimatorInput input;
    input.NumberOfPoints = static_cast<int32_t>(this->Points.size() / 3);
    input.Points = this->Points.data();
    input.Colors = this->Colors.data();
    input.NumberOfTriangles = static_cast<int32_t>(this->Cells.size() / 3);
    input.Triangles = this->Cells.data();
    return input;
  }
};

/**
 * The pieces a run may remove (FindSmallPieces), on the shuffled strips: as found by hand, and
 * the same on 1 and 3 threads. And a run whose pieces are costed on several threads (some
 * 10,000 faces in small pieces: two threads) removes the same pieces, and leaves the same
 * mesh, on 1 and 3.
 */
CD_TEST_CASE(SmallPiecesOnThreads)
{
  std::mt19937 random(7);
  const ShuffledStrips strips(random);
  HalfEdgeMesh mesh;
  mesh.Build(strips.First[ShuffledStrips::Count], strips.Triangles.data(),
             static_cast<int32_t>(strips.StripOf.size()));
  const Pieces one = CheckStripPieces(strips, mesh, 1);
  const Pieces three = CheckStripPieces(strips, mesh, 3);
  CD_CHECK(one.Start == three.Start && one.Faces == three.Faces);

  const TetrahedraBesideGrid scene(random);
  const DecimatorInput input = scene.Input();
  DecimatorOptions options;
  options.Metric = ErrorMetric::AttributeQuadric;
  options.Schedule = CollapseSchedule::Batched;
  options.PieceWeight = 10; // the filter's default
  const OneAndThree runs(options, input, input.NumberOfTriangles / 10);
  std::cout << "  " << runs.A.PrunedComponents << " pieces removed, " << runs.A.OutputTriangles
            << " triangles left\n";
  CD_CHECK(runs.A.PrunedComponents > 1000 && runs.A.PrunedComponents == runs.B.PrunedComponents);
  CD_CHECK(runs.A.OutputTriangles == runs.B.OutputTriangles);
  CD_CHECK(CountMeshDifferences(*runs.One, *runs.Three) == 0);
}

/**
 * The Batched schedule's re-costing by one new neighbour's cost (ChooseNewNeighbor) chooses
 * what a full evaluation chooses, on 1 and 3 threads alike: on a jittered sphere with random
 * colours (no two costs equal), on a flat grid of one colour, where most costs tie (equal
 * costs go to the lowest id, wherever the walk around the vertex starts), the same tilted, and
 * a flat grid whose colour is linear in the position (every cost 0 in exact arithmetic: what
 * rounding leaves of them must not fall when a vertex's quadric grows), at the defaults'
 * weights (KeptVertexErrorWeight 0 among them) and with none (no edge length nor boundary term
 * to outweigh the rounding; KeptVertexErrorWeight 1, where the kept vertex's error counts).
 */
CD_TEST_CASE(NewNeighborChoices)
{
  std::vector<double> points;
  std::vector<float> colors;
  std::vector<int32_t> triangles;
  const DecimatorInput sphere = JitteredSphere(260, points, colors, triangles);
  // Flat grids: of one colour (costs tie), tilted (the same, rounded differently), and with a
  // linear colour ramp (every cost 0 in exact arithmetic).
  const PlainMesh grid = ToPlain(meshes::FlatGrid(150, 150, meshes::Pattern::Constant));
  const std::vector<float> grey(grid.Points.size(), 0.5f);
  PlainMesh tilted = grid;
  std::vector<float> ramp(grid.Points.size());
  for (int32_t v = 0; v < grid.NumberOfPoints(); ++v)
  {
    const double x = grid.Points[3 * v], y = grid.Points[3 * v + 1];
    tilted.Points[3 * v + 2] = 0.3 * x - 0.7 * y;
    tilted.Positions[3 * v + 2] = static_cast<float>(tilted.Points[3 * v + 2]);
    const float rgb[3] = { float(0.5 + 0.2 * x), float(0.5 - 0.3 * y), float(0.4 + 0.1 * x) };
    std::copy(rgb, rgb + 3, ramp.begin() + 3 * v);
  }
  std::vector<DecimatorInput> inputs(4, sphere);
  for (const int i : { 1, 2, 3 })
  {
    inputs[i] = InputOf(i == 2 ? tilted : grid, i == 3 ? ramp.data() : grey.data());
  }
  for (const DecimatorInput& input : inputs)
  {
    for (const bool weighted : { true, false })
    {
      DecimatorOptions options;
      options.Metric = ErrorMetric::AttributeQuadric;
      options.Schedule = CollapseSchedule::Batched;
      options.BoundaryWeight = weighted ? 16 : 0;
      options.SceneRelativeWeights = weighted; // these meshes are below 270 mean edge lengths
      options.EdgeLengthWeight = weighted ? 1e-4 : 0;
      options.KeptVertexErrorWeight = weighted ? 0 : 1; // the filter's default, the total error
      options.BlockShift = 8; // blocks of 256 vertices: several threads even on the grids
      options.VerifyNewNeighbors = true;
      const int64_t target = input.NumberOfTriangles / 10;
      const OneAndThree runs(options, input, target);
      const Decimator &one = *runs.One, &three = *runs.Three;
      const DecimatorStatistics &a = runs.A, &b = runs.B;
      std::cout << "  " << input.NumberOfTriangles << " triangles, weights "
                << (weighted ? "on" : "off") << ": " << a.Collapses << " collapses, "
                << a.NewNeighborChoices << " choices by a new neighbour\n";
      CD_CHECK(a.OutputTriangles <= target && a.NewNeighborChoices > a.Collapses / 4);
      CD_CHECK_MSG(b.Threads > 1 && b.CollapseThreads > 1,
                   b.Threads << " threads costing, " << b.CollapseThreads << " collapsing");
      CD_CHECK_MSG(a.NewNeighborMismatches == 0 && b.NewNeighborMismatches == 0,
                   a.NewNeighborMismatches << " and " << b.NewNeighborMismatches << " mismatches");
      CD_CHECK(a.NewNeighborChoices == b.NewNeighborChoices && a.Collapses == b.Collapses);
      CD_CHECK(CountMeshDifferences(one, three) == 0);
    }
  }
}

/**
 * Equal costs go to the lowest vertex id, also in the choice over the legal collapses alone
 * (the re-costing of a refused vertex): on a flat grid without colour, where every collapse of
 * an interior vertex costs the same (1 + Q with Q = 0, the paper's metric by geometry alone),
 * each interior vertex's legal choice is its legal neighbour of lowest id, not the first legal
 * one its walk meets (which depends on where the walk starts).
 */
CD_TEST_CASE(LegalChoiceTies)
{
  PlainMesh grid = ToPlain(meshes::FlatGrid(14, 14, meshes::Pattern::Constant));
  // Triangles in a shuffled order, so that the walks start at various places.
  std::vector<std::array<int32_t, 3>> triangles(size_t(grid.NumberOfTriangles()));
  std::memcpy(triangles.data(), grid.Triangles.data(), grid.Triangles.size() * sizeof(int32_t));
  std::shuffle(triangles.begin(), triangles.end(), std::mt19937(3));
  std::memcpy(grid.Triangles.data(), triangles.data(), grid.Triangles.size() * sizeof(int32_t));
  Engine<HalfEdgeColorMetric> engine{ DecimatorOptions() };
  DecimatorStatistics stats;
  engine.Start(InputOf(grid, nullptr), stats);
  Engine<HalfEdgeColorMetric>::Workspace& ws = engine.GetWorkspace(0);
  const HalfEdgeMesh& mesh = engine.GetMesh();
  const float* positions = engine.GetHot()[0].P;
  int checked = 0, walkOrderDiffers = 0;
  for (int32_t v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (!mesh.IsCollapsible(v) || mesh.IsBoundaryVertex(v))
    {
      continue;
    }
    int32_t lowest = -1, firstInWalk = -1;
    mesh.ForEachNeighbor(v,
                         [&](int32_t u)
                         {
                           CD_CHECK(engine.CollapseCost(v, u) == 1.0);
                           if (ws.Rules.IsLegal(mesh, positions, v, u, HotStride))
                           {
                             firstInWalk = firstInWalk < 0 ? u : firstInWalk;
                             lowest = lowest < 0 ? u : std::min(lowest, u);
                           }
                         });
    const Choice legal = engine.Evaluate(v, true, false, ws);
    CD_CHECK_MSG(legal.Target == lowest,
                 "vertex " << v << ": legal choice " << legal.Target << ", not " << lowest);
    checked += lowest >= 0;
    walkOrderDiffers += lowest >= 0 && firstInWalk != lowest;
  }
  std::cout << "  " << checked << " interior vertices with a legal collapse, " << walkOrderDiffers
            << " whose walk meets another legal neighbour first" << std::endl;
  CD_CHECK(checked > 100 && walkOrderDiffers > 0);
}

/**
 * After every pass of the Batched schedule, each live vertex keyed by its cheapest collapse has
 * the choice and the key a full evaluation gives (VerifyKeys): those the pass re-costed, those
 * ChooseNewNeighbor updated, and those it left alone because no cost their key holds changed.
 * For the three metrics, the attribute quadric with and without the kept vertex's error, on a
 * jittered sphere with random colours and on a seam sphere, whose seam vertices collapse in
 * pairs and whose keys hold their mirror's cost too: a neighbour of v1 whose twin's choice
 * mirrors v1 is affected by the collapse into v1 even where its own choice is another vertex
 * (twins' choices differ once a refused pair has re-costed one of them over its legal pairs).
 */
CD_TEST_CASE(KeysExactAfterEachPass)
{
  std::vector<double> points;
  std::vector<float> colors;
  std::vector<int32_t> triangles;
  const DecimatorInput sphere = JitteredSphere(120, points, colors, triangles);
  const PlainMesh seamed = ToPlain(meshes::SeamSphere(100));
  std::vector<float> seamColors(seamed.Points.size());
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (float& c : seamColors)
  {
    c = unit(rng);
  }
  const DecimatorInput seamSphere = InputOf(seamed, seamColors.data());
  for (const DecimatorInput* input : { &sphere, &seamSphere })
  {
    for (const ErrorMetric metric :
         { ErrorMetric::AttributeQuadric, ErrorMetric::HalfEdgeColor, ErrorMetric::ColorQuadric })
    {
      for (const double kept : { 0.0, 1.0 })
      {
        if (kept > 0 && metric != ErrorMetric::AttributeQuadric)
        {
          continue; // the weight is the attribute quadric's
        }
        DecimatorOptions options;
        options.Metric = metric;
        options.Schedule = CollapseSchedule::Batched;
        options.KeptVertexErrorWeight = kept;
        options.BlockShift = 8;
        options.VerifyKeys = true;
        options.VerifyBlockFlags = true; // also kept up to date by the seam pairs' collapses
        Decimator decimator(options);
        const DecimatorStatistics stats = decimator.Run(*input, input->NumberOfTriangles / 8);
        const char* name = metric == ErrorMetric::AttributeQuadric ? "attribute quadric"
          : metric == ErrorMetric::HalfEdgeColor                   ? "half-edge colour"
                                                                   : "colour quadric";
        std::cout << "  " << input->NumberOfTriangles << " triangles, " << name
                  << ", kept vertex error " << kept << ": " << stats.Collapses << " collapses in "
                  << stats.Passes << " passes, " << stats.StaleKeys << " stale keys, "
                  << stats.StaleBlockFlags << " stale block flags\n";
        CD_CHECK(stats.Passes > 5 && stats.OutputTriangles <= input->NumberOfTriangles / 8);
        CD_CHECK(stats.StaleKeys == 0 && stats.StaleBlockFlags == 0);
      }
    }
  }
}

/**
 * With a batch of one collapse per pass, the Batched schedule is the Greedy one: the
 * cheapest valid collapse of the whole mesh each time, the same rejections and re-costs
 * (costs are distinct on this mesh, so that ties cannot be broken differently).
 */
CD_TEST_CASE(BatchedOneAtATimeIsGreedy)
{
  std::vector<double> points;
  std::vector<float> colors;
  std::vector<int32_t> triangles;
  const DecimatorInput input = JitteredSphere(30, points, colors, triangles);
  const int64_t target = input.NumberOfTriangles / 8;
  for (ErrorMetric metric :
       { ErrorMetric::HalfEdgeColor, ErrorMetric::Geometry, ErrorMetric::ColorQuadric })
  {
    // (Half-edge collapses only: a full collapse of v0 and v1 costs the same from either
    // side, a tie that the two schedules may break differently.)
    DecimatorOptions options;
    options.Metric = metric;
    options.BoundHighValence = false; // exact keys, as the Batched schedule uses
    Decimator greedy(options);
    const DecimatorStatistics a = greedy.Run(input, target);
    options.Schedule = CollapseSchedule::Batched;
    options.BatchFraction = 1e-12; // one candidate per pass
    Decimator batched(options);
    const DecimatorStatistics b = batched.Run(input, target);
    std::cout << "  metric " << static_cast<int>(metric) << ": " << a.Collapses << " collapses, "
              << a.RejectedPops << " rejected; batched " << b.Collapses << ", " << b.RejectedPops
              << ", " << b.Passes << " passes" << std::endl;
    CD_CHECK(a.Collapses > input.NumberOfPoints / 2);
    CD_CHECK(a.RejectedPops > 0 || metric == ErrorMetric::Geometry); // rejections are covered
    CD_CHECK(b.Collapses == a.Collapses && b.RejectedPops == a.RejectedPops);
    CD_CHECK(b.Passes == b.Collapses + b.RejectedPops);
    const long long differences = CountDifferences(greedy, batched, metric);
    CD_CHECK_MSG(differences == 0, differences << " differences from the greedy run");

    // Larger batches change the order, not the guarantees: the target is met.
    options.BatchFraction = 0.25;
    Decimator quarter(options);
    const DecimatorStatistics c = quarter.Run(input, target);
    CD_CHECK(c.OutputTriangles <= target && c.OutputTriangles >= target - 2);
    CD_CHECK(c.Passes > 1 && c.Passes < c.Collapses / 4);
  }
}

/**
 * ReleaseInput is called once, after the set-up: a caller that then spoils its points,
 * colours and triangles (as one that frees them would) gets the same decimation. Not called
 * with PruneComponents, which reads the points at the end. The mesh is large enough to be
 * decimated in a spatial order (the input read through the maps).
 */
CD_TEST_CASE(ReleaseInput)
{
  std::vector<double> points;
  std::vector<float> colors;
  std::vector<int32_t> triangles;
  const DecimatorInput input = JitteredSphere(260, points, colors, triangles);
  CD_CHECK(input.NumberOfPoints >= 65536);
  const int64_t target = input.NumberOfTriangles / 10;
  for (CollapseSchedule schedule : { CollapseSchedule::Greedy, CollapseSchedule::Batched })
  {
    for (ErrorMetric metric : { ErrorMetric::AttributeQuadric, ErrorMetric::HalfEdgeColor })
    {
      DecimatorOptions options;
      options.Metric = metric;
      options.Schedule = schedule;
      Decimator kept(options);
      const DecimatorStatistics a = kept.Run(input, target);
      std::vector<double> p = points;
      std::vector<float> c = colors;
      std::vector<int32_t> t = triangles;
      DecimatorInput spoiled = input;
      spoiled.Points = p.data();
      spoiled.Colors = c.data();
      spoiled.Triangles = t.data();
      int calls = 0;
      spoiled.ReleaseInput = [&]()
      {
        ++calls;
        std::fill(p.begin(), p.end(), std::numeric_limits<double>::quiet_NaN());
        std::fill(c.begin(), c.end(), -1.0f);
        std::fill(t.begin(), t.end(), -1);
      };
      Decimator released(options);
      const DecimatorStatistics b = released.Run(spoiled, target);
      CD_CHECK(calls == 1);
      CD_CHECK(a.Collapses > input.NumberOfPoints / 3 && a.Collapses == b.Collapses);
      const long long differences = CountMeshDifferences(kept, released);
      CD_CHECK_MSG(differences == 0, differences << " differences after the release");

      options.PruneComponents = true;
      p = points;
      c = colors;
      t = triangles;
      calls = 0;
      Decimator pruned(options);
      pruned.Run(spoiled, target);
      CD_CHECK(calls == 0);
    }
  }
}

//------------------------------------------------------------------------------
/// A tetrahedron: every collapse would make two triangles share all three vertices.
void CheckLinkTetrahedron(CollapseRules& rules, HalfEdgeMesh& mesh)
{
  const int32_t tetra[12] = { 0, 2, 1, 0, 3, 2, 0, 1, 3, 1, 2, 3 };
  const float tetraPositions[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  mesh.Build(4, tetra, 4);
  for (int32_t a = 0; a < 4; ++a)
  {
    for (int32_t b = 0; b < 4; ++b)
    {
      if (a != b)
      {
        CD_CHECK(rules.Check(mesh, tetraPositions, a, b) == CollapseVerdict::LinkCondition);
      }
    }
  }
}

/**
 * An open annulus with k vertices on each boundary loop, radii 1 and 2 in the z = 0 plane:
 * a_i = i, b_i = k + i; triangles (a_i, b_i, b_i+1), (a_i, b_i+1, a_i+1).
 */
void Annulus(int k, std::vector<int32_t>& tris, std::vector<float>& pos)
{
  tris.clear();
  pos.clear();
  for (int i = 0; i < k; ++i)
  {
    const int32_t a = i, a1 = (i + 1) % k, b = k + i, b1 = k + (i + 1) % k;
    const int32_t t[6] = { a, b, b1, a, b1, a1 };
    tris.insert(tris.end(), t, t + 6);
  }
  for (int ring = 0; ring < 2; ++ring)
  {
    for (int i = 0; i < k; ++i)
    {
      const double angle = 2.0 * 3.14159265358979 * i / k;
      const double r = ring == 0 ? 1.0 : 2.0;
      pos.push_back(static_cast<float>(r * std::cos(angle)));
      pos.push_back(static_cast<float>(r * std::sin(angle)));
      pos.push_back(0.0f);
    }
  }
}

/// Annuli: with 3 vertices per loop a collapse along the inner loop pinches it, with 4 not.
void CheckLinkAnnulus(CollapseRules& rules, HalfEdgeMesh& mesh)
{
  // An open annulus with 3 vertices on each boundary loop: collapsing along the inner loop
  // would pinch it (a0 and a1 share a2 besides the opposite vertex b1).
  std::vector<int32_t> tris;
  std::vector<float> pos;
  Annulus(3, tris, pos);
  MeshBuildReport report = mesh.Build(6, tris.data(), 6);
  CD_CHECK(report.LockedVertices == 0 && report.BoundaryEdges == 6);
  CD_CHECK(mesh.IsBoundaryVertex(0) && mesh.IsBoundaryVertex(1));
  CD_CHECK(rules.Check(mesh, pos.data(), 0, 1) == CollapseVerdict::LinkCondition);
  CD_CHECK(rules.Check(mesh, pos.data(), 1, 0) == CollapseVerdict::LinkCondition);
  // With 4 vertices per loop the same collapse is fine.
  Annulus(4, tris, pos);
  mesh.Build(8, tris.data(), 8);
  CD_CHECK(rules.Check(mesh, pos.data(), 0, 1) == CollapseVerdict::Legal);
}

/// An octahedron collapsed down to a tetrahedron: which collapses the link condition refuses.
void CheckLinkOctahedron(CollapseRules& rules, HalfEdgeMesh& mesh)
{
  // An octahedron: collapsing +x onto +y is fine and gives a triangular bipyramid whose
  // apexes (+z, -z) have valence 3. There an equator edge is refused (its opposite vertices
  // have valence 3), an apex -> equator collapse is fine (a tetrahedron results), and then
  // nothing collapses any more.
  const int32_t octa[24] = {
    0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5
  };
  mesh.Build(6, octa, 8);
  CD_CHECK(CheckMeshConsistency(mesh, true) == 0);
  CD_CHECK(rules.CheckTopology(mesh, 0, 2) == CollapseVerdict::Legal);
  CD_CHECK(mesh.Collapse(0, 2) == 2);
  CD_CHECK(CheckMeshConsistency(mesh, true) == 0);
  CD_CHECK(AnalyseTopology(LiveTriangles(mesh)).Euler() == 2);
  CD_CHECK(mesh.Valence(4) == 3 && mesh.Valence(5) == 3 && mesh.Valence(1) == 4);
  CD_CHECK(rules.CheckTopology(mesh, 1, 2) == CollapseVerdict::LinkCondition);
  CD_CHECK(rules.CheckTopology(mesh, 2, 3) == CollapseVerdict::LinkCondition);
  CD_CHECK(rules.CheckTopology(mesh, 3, 1) == CollapseVerdict::LinkCondition);
  CD_CHECK(rules.CheckTopology(mesh, 4, 1) == CollapseVerdict::Legal);
  CD_CHECK(mesh.Collapse(4, 1) == 2);
  CD_CHECK(CheckMeshConsistency(mesh, true) == 0);
  CD_CHECK(mesh.GetNumberOfLiveFaces() == 4 && AnalyseTopology(LiveTriangles(mesh)).Euler() == 2);
  for (int32_t a : { 1, 2, 3, 5 })
  {
    mesh.ForEachNeighbor(
      a, [&](int32_t b) { CD_CHECK(rules.CheckTopology(mesh, a, b) != CollapseVerdict::Legal); });
  }
}

/// Locked and removed vertices, and non-neighbours, are not collapsible.
void CheckNotCollapsible(CollapseRules& rules, HalfEdgeMesh& mesh)
{
  const int32_t fin[9] = { 0, 1, 2, 1, 0, 3, 0, 1, 4 };
  const float finPositions[15] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1 };
  mesh.Build(5, fin, 3);
  CD_CHECK(rules.Check(mesh, finPositions, 2, 0) == CollapseVerdict::NotCollapsible);
  CD_CHECK(rules.Check(mesh, finPositions, 0, 2) == CollapseVerdict::NotCollapsible);
  CD_CHECK(rules.Check(mesh, finPositions, 2, 3) == CollapseVerdict::NotCollapsible);
}

CD_TEST_CASE(RulesLinkCondition)
{
  // The phases share the rules and rebuild the one mesh, in this order.
  CollapseRules rules{ CollapseRuleOptions() };
  HalfEdgeMesh mesh;
  CheckLinkTetrahedron(rules, mesh);
  CheckLinkAnnulus(rules, mesh);

  // A single triangle: collapsing an edge would leave it hanging by a vertex.
  const int32_t one[3] = { 0, 1, 2 };
  const float onePositions[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  mesh.Build(3, one, 1);
  CD_CHECK(rules.Check(mesh, onePositions, 0, 1) == CollapseVerdict::LinkCondition);

  CheckLinkOctahedron(rules, mesh);
  CheckNotCollapsible(rules, mesh);
}

/**
 * The topological rules as docs/ALGORITHM.md section 5 lists them, each on its own and over
 * the same mesh queries, the valence of vl and vr counted in full whatever the rest says: what
 * CheckTopology must agree with. `valenceRule` false leaves that rule out (to count where it
 * alone decides).
 */
CollapseVerdict TopologyByDefinition(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1,
                                     bool preserveBoundary, bool valenceRule)
{
  if (v0 == v1 || !mesh.IsCollapsible(v0) || !mesh.IsCollapsible(v1))
  {
    return CollapseVerdict::NotCollapsible;
  }
  const int32_t sides[2] = { mesh.FindHalfEdge(v0, v1), mesh.FindHalfEdge(v1, v0) };
  if (sides[0] < 0 && sides[1] < 0)
  {
    return CollapseVerdict::NotCollapsible;
  }
  if (mesh.IsBoundaryVertex(v0) && (preserveBoundary || (sides[0] >= 0 && sides[1] >= 0)))
  {
    return CollapseVerdict::Boundary; // kept, or an interior edge of a boundary vertex
  }
  std::set<int32_t> opposite;
  bool link = false;
  for (const int32_t h : sides)
  {
    if (h >= 0)
    {
      const int32_t x = mesh.Origin(HalfEdgeMesh::Prev(h));
      link = link || (mesh.Twin(HalfEdgeMesh::Next(h)) < 0 && mesh.Twin(HalfEdgeMesh::Prev(h)) < 0);
      link = link || mesh.IsLocked(x) || opposite.count(x) != 0;
      link = link || (valenceRule && !mesh.IsBoundaryVertex(x) && mesh.Valence(x) <= 3);
      opposite.insert(x);
    }
  }
  std::set<int32_t> ring0, ring1;
  mesh.ForEachNeighbor(v0, [&](int32_t u) { ring0.insert(u); });
  mesh.ForEachNeighbor(v1, [&](int32_t u) { ring1.insert(u); });
  for (const int32_t u : ring0)
  {
    link = link || (u != v1 && ring1.count(u) != 0 && opposite.count(u) == 0);
  }
  return link ? CollapseVerdict::LinkCondition : CollapseVerdict::Legal;
}

/// Closed and open meshes, some with faces deleted at random (holes; what the build cannot
/// represent as a manifold fan is locked).
std::vector<PlainMesh> TopologyCases(std::mt19937& rng)
{
  std::vector<PlainMesh> cases;
  for (auto poly : { meshes::Icosphere(1, meshes::Pattern::Constant),
                     meshes::Icosphere(2, meshes::Pattern::Constant),
                     meshes::Torus(9, 5, meshes::Pattern::Constant),
                     meshes::Grid(6, 5, meshes::Pattern::Constant) })
  {
    cases.push_back(ToPlain(poly));
  }
  for (int k : { 3, 4, 6 })
  {
    PlainMesh annulus;
    Annulus(k, annulus.Triangles, annulus.Positions);
    annulus.Points.assign(annulus.Positions.begin(), annulus.Positions.end());
    cases.push_back(annulus);
  }
  for (int i = 0; i < 3; ++i)
  {
    PlainMesh holed = cases[size_t(i)];
    for (int hole = 0; hole < 2 + 3 * i; ++hole)
    {
      const size_t f = rng() % size_t(holed.NumberOfTriangles());
      holed.Triangles.erase(holed.Triangles.begin() + 3 * f, holed.Triangles.begin() + 3 * f + 3);
    }
    cases.push_back(holed);
  }
  return cases;
}

/// What RulesTopologyByDefinition counted.
struct TopologyCounts
{
  int64_t Checked = 0, ByValenceAlone = 0, Disagreements = 0;
};

/// CheckTopology against TopologyByDefinition on both directions of every edge of `mesh`; the
/// legal collapses.
std::vector<std::pair<int32_t, int32_t>> CompareEveryEdge(CollapseRules& rules,
                                                          const HalfEdgeMesh& mesh,
                                                          TopologyCounts& counts)
{
  const bool preserve = rules.GetOptions().PreserveBoundary;
  std::vector<std::pair<int32_t, int32_t>> legal;
  for (int32_t v0 = 0; v0 < mesh.GetNumberOfVertices(); ++v0)
  {
    mesh.ForEachNeighbor(v0,
                         [&](int32_t v1)
                         {
                           const CollapseVerdict expected =
                             TopologyByDefinition(mesh, v0, v1, preserve, true);
                           counts.Disagreements += rules.CheckTopology(mesh, v0, v1) != expected;
                           counts.ByValenceAlone +=
                             expected != TopologyByDefinition(mesh, v0, v1, preserve, false);
                           ++counts.Checked;
                           if (expected == CollapseVerdict::Legal)
                           {
                             legal.emplace_back(v0, v1);
                           }
                         });
  }
  return legal;
}

/// Random collapses until none is legal (a closed sphere down to a tetrahedron), with and
/// without PreserveBoundary: after each collapse CheckTopology gives the verdicts of
/// TopologyByDefinition on both directions of every edge, also where the valence of vl or vr
/// alone refuses a collapse.
CD_TEST_CASE(RulesTopologyByDefinition)
{
  std::mt19937 rng(5);
  TopologyCounts counts;
  for (const PlainMesh& m : TopologyCases(rng))
  {
    for (int run = 0; run < 6; ++run)
    {
      CollapseRuleOptions options;
      options.PreserveBoundary = run % 2 == 1;
      CollapseRules rules(options);
      HalfEdgeMesh mesh;
      mesh.Build(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
      for (auto legal = CompareEveryEdge(rules, mesh, counts); !legal.empty();
           legal = CompareEveryEdge(rules, mesh, counts))
      {
        const auto& pick = legal[rng() % legal.size()];
        mesh.Collapse(pick.first, pick.second);
      }
    }
  }
  std::cout << "  " << counts.Checked << " verdicts, " << counts.ByValenceAlone
            << " refused by the valence of vl or vr alone, " << counts.Disagreements
            << " disagreements" << std::endl;
  CD_CHECK(counts.Disagreements == 0);
  CD_CHECK(counts.ByValenceAlone > 0);
}

/// FanHalfEdge(v, k) on every vertex of `mesh`: the k-th half-edge ForEachOutgoing lists (one
/// per face of the fan), from v to the k-th neighbour ForEachNeighbor lists; past the last, -1
/// where the fan is open (its last face has no twin before it) and the first again where it
/// closes; -1 for a vertex without faces. Returns the number of faces walked.
int64_t CheckFanWalk(const HalfEdgeMesh& mesh)
{
  int64_t walked = 0;
  for (int32_t v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    std::vector<int32_t> outgoing, ring;
    mesh.ForEachOutgoing(v, [&](int32_t h) { outgoing.push_back(h); });
    mesh.ForEachNeighbor(v, [&](int32_t u) { ring.push_back(u); });
    const int faces = static_cast<int>(outgoing.size());
    for (int k = 0; k < faces; ++k)
    {
      const int32_t h = mesh.FanHalfEdge(v, k);
      CD_CHECK(h == outgoing[size_t(k)] && mesh.Origin(h) == v &&
               mesh.Target(h) == ring[size_t(k)]);
    }
    const bool open = faces == 0 || mesh.Twin(HalfEdgeMesh::Prev(outgoing[size_t(faces - 1)])) < 0;
    CD_CHECK(mesh.FanHalfEdge(v, faces) == (open ? -1 : outgoing[0]));
    walked += faces;
  }
  return walked;
}

/// FanHalfEdge against ForEachNeighbor on closed, open and holed meshes (locked vertices among
/// them), after each of random legal collapses until none is legal (removed vertices among
/// them); on the meshes as built, the faces walked are three per triangle when none is locked.
CD_TEST_CASE(HalfEdgeFanWalk)
{
  std::mt19937 rng(11);
  TopologyCounts counts;
  CollapseRules rules{ CollapseRuleOptions() };
  int64_t meshes = 0;
  for (const PlainMesh& m : TopologyCases(rng))
  {
    HalfEdgeMesh mesh;
    const MeshBuildReport report =
      mesh.Build(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
    const int64_t walked = CheckFanWalk(mesh);
    CD_CHECK(report.LockedVertices > 0 || walked == 3 * int64_t(m.NumberOfTriangles()));
    for (auto legal = CompareEveryEdge(rules, mesh, counts); !legal.empty();
         legal = CompareEveryEdge(rules, mesh, counts))
    {
      const auto& pick = legal[rng() % legal.size()];
      mesh.Collapse(pick.first, pick.second);
      CheckFanWalk(mesh);
      ++meshes;
    }
  }
  CD_CHECK(meshes > 100);
}

/// The pyramid with the apex at height h, as float positions.
std::vector<float> PyramidPositions(double h)
{
  std::vector<float> p(PyramidPoints, PyramidPoints + 15);
  p[2] = static_cast<float>(h);
  return p;
}

CD_TEST_CASE(RulesFlip)
{
  // Collapsing the pyramid's apex onto ring vertex 1 lays faces (0,2,3) and (0,3,4) flat:
  // their normals (-1,1,1)/sqrt3 and (-1,-1,1)/sqrt3 turn to (0,0,1), by acos(1/sqrt3) =
  // 54.7356 degrees.
  HalfEdgeMesh mesh;
  mesh.Build(5, PyramidTriangles, 4);
  const std::vector<float> p = PyramidPositions(1.0);
  const double turn = std::acos(1.0 / Sqrt3) * 180.0 / 3.14159265358979323846;
  CD_CHECK_NEAR(turn, 54.7356, 1e-4);
  auto options = [](double degrees)
  {
    CollapseRuleOptions o;
    o.MinimumNormalCosine = std::cos(degrees * 3.14159265358979323846 / 180.0);
    return o;
  };
  CollapseRules strict(options(54.0)), loose(options(55.5));
  CD_CHECK(strict.Check(mesh, p.data(), 0, 1) == CollapseVerdict::Flip);
  CD_CHECK(loose.Check(mesh, p.data(), 0, 1) == CollapseVerdict::Legal);
  CD_CHECK(strict.CheckTopology(mesh, 0, 1) == CollapseVerdict::Legal);

  // A planar fan that is not star-shaped from ring vertex A: collapsing the centre onto A
  // turns triangle (c,B,C) upside down (180 degrees). Refused at 90 degrees and even at
  // 179; allowed only when the guard is off (180).
  // c = 0 at the origin; ring A(1,0) B(0.2,0.2) C(-1,1) D(-1,-1) E(0.2,-0.2).
  const int32_t fan[15] = { 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1 };
  const float fanPositions[18] = { 0,  0, 0, 1,  0,  0, 0.2f, 0.2f,  0,
                                   -1, 1, 0, -1, -1, 0, 0.2f, -0.2f, 0 };
  mesh.Build(6, fan, 5);
  CD_CHECK(CollapseRules(options(90)).Check(mesh, fanPositions, 0, 1) == CollapseVerdict::Flip);
  CD_CHECK(CollapseRules(options(179)).Check(mesh, fanPositions, 0, 1) == CollapseVerdict::Flip);
  CD_CHECK(CollapseRules(options(180)).Check(mesh, fanPositions, 0, 1) == CollapseVerdict::Legal);
  // The same centre collapses onto B without any flip: B sees every edge of the ring
  // (triangles (B,C,D), (B,D,E), (B,E,A) stay counter-clockwise), but not onto C, which
  // would turn (A,B) around.
  CD_CHECK(CollapseRules(options(90)).CheckGeometry(mesh, fanPositions, 0, 2) ==
           CollapseVerdict::Legal);
  CD_CHECK(CollapseRules(options(90)).CheckGeometry(mesh, fanPositions, 0, 3) ==
           CollapseVerdict::Flip);
}

/// The drift guard reads the packed reference normals: a flat fan whose reference normals lean
/// by 74.9 degrees may collapse, by 75.1 degrees it may not (the guard's bound is 75).
CD_TEST_CASE(RulesDrift)
{
  const double pi = 3.14159265358979323846;
  const int32_t fan[15] = { 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1 };
  const float flat[18] = { 0, 0, 0, 1, 0, 0, 0.2f, 0.2f, 0, -1, 1, 0, -1, -1, 0, 0.2f, -0.2f, 0 };
  HalfEdgeMesh mesh;
  mesh.Build(6, fan, 5);
  CollapseRuleOptions options;
  options.MinimumNormalCosine = 0.0;
  options.MinimumDriftCosine = std::cos(75.0 * pi / 180.0);
  for (const double degrees : { 74.9, 75.1 })
  {
    // The reference: the same fan turned about the x axis, normals (0, -sin, cos).
    const double a = degrees * pi / 180.0;
    std::vector<float> turned(flat, flat + 18);
    for (int v = 0; v < 6; ++v)
    {
      turned[3 * v + 1] = static_cast<float>(flat[3 * v + 1] * std::cos(a));
      turned[3 * v + 2] = static_cast<float>(flat[3 * v + 1] * std::sin(a));
    }
    Buffer<PackedNormal> normals;
    CollapseRules::ComputeReferenceNormals(mesh, turned.data(), 3, normals);
    CollapseRules rules(options);
    rules.SetReferenceNormals(normals.data());
    const CollapseVerdict verdict = rules.Check(mesh, flat, 0, 2);
    CD_CHECK(verdict == (degrees < 75 ? CollapseVerdict::Legal : CollapseVerdict::Flip));
    rules.SetReferenceNormals(nullptr); // no reference, no drift guard
    CD_CHECK(rules.Check(mesh, flat, 0, 2) == CollapseVerdict::Legal);
  }
}

CD_TEST_CASE(RulesDegenerate)
{
  // Centre at the origin, ring A(1,0) B(0,1) C(-1,2) D(-1,-1) E(0.5,-1): A, B and C are
  // collinear, so collapsing the centre onto A gives triangle (A,B,C) no area.
  const int32_t fan[15] = { 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1 };
  const float positions[18] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 2, 0, -1, -1, 0, 0.5f, -1, 0 };
  HalfEdgeMesh mesh;
  mesh.Build(6, fan, 5);
  for (double degrees : { 90.0, 180.0 })
  {
    CollapseRuleOptions o;
    o.MinimumNormalCosine = std::cos(degrees * 3.14159265358979323846 / 180.0);
    CollapseRules rules(o);
    CD_CHECK(rules.Check(mesh, positions, 0, 1) == CollapseVerdict::Degenerate);
    CD_CHECK(rules.CheckTopology(mesh, 0, 1) == CollapseVerdict::Legal);
    // Onto D nothing degenerates or flips.
    CD_CHECK(rules.Check(mesh, positions, 0, 4) == CollapseVerdict::Legal);
  }
  // Two ring vertices at the same place: collapsing the centre onto one of them would
  // leave a triangle with a zero-length edge.
  std::vector<float> coincident(positions, positions + 18);
  coincident[6] = 1; // B moves onto A
  coincident[7] = 0;
  CollapseRules rules{ CollapseRuleOptions() };
  CD_CHECK(rules.Check(mesh, coincident.data(), 0, 1) == CollapseVerdict::Degenerate);
}

CD_TEST_CASE(RulesRounding)
{
  // The fan of RulesDegenerate at z = 1000, where a float coordinate is rounded by up to
  // 3e-5 (x and y, below 2, by up to 6e-8).
  const int32_t fan[15] = { 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1 };
  const float z = 1000;
  // A, B and C on the line A + t (-1, 1, 1/3): the floats of z + 1/3 and z + 2/3 leave
  // (A,B,C) a sine of 2e-5 (above 1e-6), but an area that the rounding of z accounts for.
  const float rounded[18] = { 0,  0,  z, 1,    0,  z, 0, 1, z + 1.0f / 3, -1, 2, z + 2.0f / 3,
                              -1, -1, z, 0.5f, -1, z };
  // C at (-1, 1.999): (A,B,C) is a sliver of twice-area 1e-3 in the plane z = 1000, far
  // above what rounding x and y could do; rounding z tilts it but cannot flatten it.
  const float sliver[18] = { 0, 0, z, 1, 0, z, 0, 1, z, -1, 1.999f, z, -1, -1, z, 0.5f, -1, z };
  HalfEdgeMesh mesh;
  mesh.Build(6, fan, 5);
  CollapseRules rules{ CollapseRuleOptions() };
  CD_CHECK(rules.Check(mesh, rounded, 0, 1) == CollapseVerdict::Degenerate);
  CD_CHECK(rules.Check(mesh, sliver, 0, 1) == CollapseVerdict::Legal);
  // The same with x and z swapped: no axis is favoured.
  float across[18];
  for (int i = 0; i < 6; ++i)
  {
    across[3 * i] = sliver[3 * i + 2];
    across[3 * i + 1] = sliver[3 * i + 1];
    across[3 * i + 2] = sliver[3 * i];
  }
  CD_CHECK(rules.Check(mesh, across, 0, 1) == CollapseVerdict::Legal);
}

/// The drift guard's reference normals in 4 bytes: axes exact, any direction within 1e-4
/// radians, the length ignored, no direction for degenerate input.
CD_TEST_CASE(PackedNormals)
{
  const double axes[6][3] = { { 1, 0, 0 },  { -1, 0, 0 }, { 0, 1, 0 },
                              { 0, -1, 0 }, { 0, 0, 1 },  { 0, 0, -1 } };
  for (const auto& axis : axes)
  {
    double n[3];
    UnpackNormal(PackNormal(axis), n);
    CD_CHECK(n[0] == axis[0] && n[1] == axis[1] && n[2] == axis[2]);
  }
  // On the folds (z < 0 with x or y zero, a signed zero, z just below 0).
  const double folds[6][3] = { { 0, 1, -1 },  { 0, -1, -1 },   { 1, 0, -1 },
                               { -1, 0, -1 }, { -0.0, 1, -1 }, { 0, 1, -1e-9 } };
  for (const auto& f : folds)
  {
    double n[3];
    UnpackNormal(PackNormal(f), n);
    const double l1 = std::abs(f[0]) + std::abs(f[1]) + std::abs(f[2]);
    for (int k = 0; k < 3; ++k)
    {
      CD_CHECK_NEAR(n[k], f[k] / l1, 1e-4);
    }
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double bad[3][3] = { { 0, 0, 0 },
                             { std::numeric_limits<double>::quiet_NaN(), 0, 1 },
                             { inf, 0, 0 } };
  for (const auto& b : bad)
  {
    double n[3] = { 1, 1, 1 };
    UnpackNormal(PackNormal(b), n);
    CD_CHECK(n[0] == 0 && n[1] == 0 && n[2] == 0);
  }
  std::mt19937 rng(5);
  std::normal_distribution<double> gauss;
  double worst = 0;
  int differentByLength = 0;
  for (int i = 0; i < 100000; ++i)
  {
    const double d[3] = { gauss(rng), gauss(rng), gauss(rng) };
    const double scaled[3] = { 1e-6 * d[0], 1e-6 * d[1], 1e-6 * d[2] };
    const PackedNormal p = PackNormal(d);
    const PackedNormal q = PackNormal(scaled);
    differentByLength += (p.U != q.U || p.V != q.V) ? 1 : 0;
    double n[3];
    UnpackNormal(p, n);
    const double cross[3] = { d[1] * n[2] - d[2] * n[1], d[2] * n[0] - d[0] * n[2],
                              d[0] * n[1] - d[1] * n[0] };
    const double angle =
      std::atan2(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]),
                 d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
    worst = std::max(worst, angle);
  }
  std::cout << "  largest angle after packing: " << worst << " rad" << std::endl;
  CD_CHECK(worst < 1e-4);
  CD_CHECK(differentByLength == 0);
}

CD_TEST_CASE(RulesBoundary)
{
  const int nx = 6, ny = 4;
  const PlainMesh m = ToPlain(meshes::Grid(nx, ny, meshes::Pattern::Constant));
  HalfEdgeMesh mesh;
  mesh.Build(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
  auto id = [](int i, int j) { return j * (nx + 1) + i; };
  CollapseRules free{ CollapseRuleOptions() };
  CollapseRuleOptions keep;
  keep.PreserveBoundary = true;
  CollapseRules preserve(keep);
  // A boundary vertex of the bottom side along the side: allowed, unless preserved.
  CD_CHECK(free.Check(mesh, m.Positions.data(), id(2, 0), id(3, 0)) == CollapseVerdict::Legal);
  CD_CHECK(preserve.Check(mesh, m.Positions.data(), id(2, 0), id(3, 0)) ==
           CollapseVerdict::Boundary);
  // A boundary vertex into the interior: never.
  CD_CHECK(free.Check(mesh, m.Positions.data(), id(2, 0), id(2, 1)) == CollapseVerdict::Boundary);
  // An interior vertex onto the boundary: allowed both ways of the option.
  CD_CHECK(free.Check(mesh, m.Positions.data(), id(2, 1), id(2, 0)) == CollapseVerdict::Legal);
  CD_CHECK(preserve.Check(mesh, m.Positions.data(), id(2, 1), id(2, 0)) == CollapseVerdict::Legal);
  // Interior into interior.
  CD_CHECK(free.Check(mesh, m.Positions.data(), id(2, 2), id(3, 2)) == CollapseVerdict::Legal);
  // An interior vertex onto a corner along a diagonal: the opposite vertices are on the
  // boundary, so the valence rule does not apply.
  CD_CHECK(free.CheckTopology(mesh, id(1, 1), id(0, 0)) == CollapseVerdict::Legal);
}

} // namespace

// The record by hand: a mesh of 8 points and 10 triangles; collapses 0 -> 1 (2 triangles), a
// seam pair 2 -> 3 and 4 -> 5 (2 each, made together), 1 -> 7 (2). Append gives the pair the
// count after both and the larger error; a level never ends inside the pair; the survivors
// follow chains of parents; a bad record is found out.
CD_TEST_CASE(CollapseRecordByHand)
{
  CollapseRecord record;
  record.InputPoints = 8;
  record.InputTriangles = 10;
  const double scale = 2.0; // frame units per input unit
  std::vector<RecordedCollapse> made = { { 0, 1, 2, 0, 0, 0.5, 4.0 },
                                         { 2, 3, 2, 0, 0, 0.7, 36.0 },
                                         { 4, 5, 2, 1, 0, 0.7, 16.0 },
                                         { 1, 7, 2, 0, 0, 0.9, 64.0 } };
  const int32_t toInput[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  record.Append(made.data(), made.size(), toInput, scale);
  CD_CHECK((record.Triangles == Buffer<int64_t>{ 8, 4, 4, 2 }));
  CD_CHECK((record.Error == Buffer<double>{ 1.0, 3.0, 3.0, 4.0 }));
  std::string why;
  CD_CHECK_MSG(IsConsistent(record, why), why);
  // Target 6: the first collapse leaves 8 > 6, the pair 4: both go in, then stop.
  CD_CHECK(LevelLength(record, 6, 0.0) == 3);
  CD_CHECK(LevelLength(record, 8, 0.0) == 1);
  CD_CHECK(LevelLength(record, 10, 0.0) == 0);
  CD_CHECK(LevelLength(record, 0, 0.0) == 4);
  // MaximumError 2: the pair's error is 3, so the level stops before it; 3.5: after it.
  CD_CHECK(LevelLength(record, 0, 2.0) == 1);
  CD_CHECK(LevelLength(record, 0, 3.5) == 3);
  std::vector<int32_t> where;
  ResolveSurvivors(record, 4, where);
  CD_CHECK((where == std::vector<int32_t>{ 7, 7, 3, 3, 5, 5, 6, 7 }));
  ResolveSurvivors(record, 1, where);
  CD_CHECK((where == std::vector<int32_t>{ 1, 1, 2, 3, 4, 5, 6, 7 }));
  // Bad records: a point removed twice, a collapse into a removed point, three equal counts.
  CollapseRecord bad = record;
  bad.Removed[3] = 0;
  CD_CHECK(!IsConsistent(bad, why) && why.find("earlier") != std::string::npos);
  bad = record;
  bad.Survivor[3] = 2;
  CD_CHECK(!IsConsistent(bad, why) && why.find("earlier") != std::string::npos);
  bad = record;
  bad.Triangles[3] = 4;
  CD_CHECK(!IsConsistent(bad, why) && why.find("decrease") != std::string::npos);
  bad = record;
  bad.Survivor[0] = 8;
  CD_CHECK(!IsConsistent(bad, why) && why.find("out of range") != std::string::npos);
}

// A piece removed whole in the record, by hand: 9 points, 12 triangles; 0 -> 1 (2 triangles),
// then the piece of points 5, 6, 7, 8 (4 triangles, a tetrahedron) removed, one entry a point
// into -1, as one step with its largest error; then 1 -> 2. The piece's points resolve to -1,
// a level never ends inside the step, and a level under a bound below the piece's error skips
// the piece and goes on.
CD_TEST_CASE(CollapseRecordPiece)
{
  CollapseRecord record;
  record.InputPoints = 9;
  record.InputTriangles = 12;
  std::vector<RecordedCollapse> made = {
    { 0, 1, 2, 0, 0, 0.5, 1.0 },   { 5, -1, 4, 0, -1, 0.6, 4.0 }, { 6, -1, 0, 1, -1, 0.6, 9.0 },
    { 7, -1, 0, 1, -1, 0.6, 1.0 }, { 8, -1, 0, 1, -1, 0.6, 0.0 }, { 1, 2, 2, 0, 0, 0.8, 1.0 }
  };
  record.Append(made.data(), made.size(), nullptr, 1.0);
  CD_CHECK((record.Triangles == Buffer<int64_t>{ 10, 6, 6, 6, 6, 4 }));
  CD_CHECK((record.Error == Buffer<double>{ 1.0, 3.0, 3.0, 3.0, 3.0, 1.0 }));
  CD_CHECK((record.Survivor == Buffer<int32_t>{ 1, -1, -1, -1, -1, 2 }));
  std::string why;
  CD_CHECK_MSG(IsConsistent(record, why), why);
  CD_CHECK(LevelLength(record, 9, 0.0) == 5); // 10 > 9: the whole step goes in
  CD_CHECK(LevelLength(record, 6, 0.0) == 5);
  CD_CHECK(LevelLength(record, 0, 4.0) == 6);
  std::vector<int32_t> where;
  ResolveSurvivors(record, 6, where);
  CD_CHECK((where == std::vector<int32_t>{ 2, 2, 2, 3, 4, -1, -1, -1, -1 }));
  // MaximumError 2: the piece (error 3) is skipped, not a stop; its 4 faces count as left, so
  // a target of 8 still takes the last collapse (10 left before it), and its points stay.
  CD_CHECK(LevelLength(record, 0, 2.0) == 6);
  CD_CHECK(LevelLength(record, 8, 2.0) == 6);
  CD_CHECK(LevelLength(record, 10, 2.0) == 1);
  CD_CHECK(IsSkippedPiece(record, 2, 2.0) && !IsSkippedPiece(record, 2, 4.0) &&
           !IsSkippedPiece(record, 5, 0.5) && !IsSkippedPiece(record, 2, 0.0));
  ResolveSurvivors(record, 6, where, 2.0);
  CD_CHECK((where == std::vector<int32_t>{ 2, 2, 2, 3, 4, 5, 6, 7, 8 }));
  // Bad: a piece's first entry that removes nothing; a collapse after the piece that removes
  // nothing (not the second of a pair); a collapse into a removed piece's point; an id below
  // -1.
  CollapseRecord bad = record;
  bad.Triangles[1] = 10;
  CD_CHECK(!IsConsistent(bad, why) && why.find("decrease") != std::string::npos);
  bad = record;
  bad.Triangles[5] = 6;
  CD_CHECK(!IsConsistent(bad, why) && why.find("decrease") != std::string::npos);
  bad = record;
  bad.Survivor[5] = 6;
  CD_CHECK(!IsConsistent(bad, why) && why.find("earlier") != std::string::npos);
  bad = record;
  bad.Survivor[2] = -2;
  CD_CHECK(!IsConsistent(bad, why) && why.find("out of range") != std::string::npos);
}

CD_TEST_CASE(SeamDetection)
{
  // The roles by hand (mesh/Seams.h): a seam sphere of resolution r has r - 1 twinned pairs on
  // its meridian and two shared poles; a cube of n x n quads a face has 12 (n - 1) pairs and 8
  // corners of three faces (24 locked points); a sphere without duplicates has none.
  SeamMap seams;
  const auto detect = [&seams](vtkPolyData* polydata, bool lockAll, HalfEdgeMesh& mesh)
  {
    const PlainMesh m = ToPlain(polydata);
    mesh.Build(m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles());
    return seams.Detect(mesh, m.Points.data(), nullptr, lockAll, 2);
  };
  HalfEdgeMesh mesh;
  SeamReport found = detect(meshes::SeamSphere(8), false, mesh);
  CD_CHECK(found.TwinnedVertices == 14 && found.SharedVertices == 2 && found.LockedVertices == 0);
  // Point 1 is the first column of the first row, point 9 the last (its twin); 0 the pole.
  CD_CHECK(seams.GetTwin(1) == 9 && seams.GetTwin(9) == 1 && seams.GetTwin(2) == -1);
  CD_CHECK(seams.GetRole(0) == SeamMap::Shared && seams.MirrorTarget(0) == 0);
  CD_CHECK(seams.MirrorTarget(1) == 9 && seams.MirrorTarget(2) == -1);
  // The pole may not collapse along the seam; point 1 only along it (mirror edge 9-0 or 9-18).
  CD_CHECK(!seams.Admits(mesh, 0, 1) && seams.Admits(mesh, 1, 0) && seams.Admits(mesh, 1, 10));
  CD_CHECK(!seams.Admits(mesh, 1, 2));
  found = detect(meshes::SeamSphere(8), true, mesh); // lockAll: every seam point locked
  CD_CHECK(seams.Empty() && found.LockedVertices == 16 && mesh.IsLocked(0) && mesh.IsLocked(9));
  found = detect(meshes::ColorCube(3), false, mesh);
  CD_CHECK(found.TwinnedVertices == 48 && found.SharedVertices == 0 && found.LockedVertices == 24);
  found = detect(meshes::UVSphere(8, meshes::Pattern::Constant), false, mesh);
  CD_CHECK(seams.Empty() &&
           found.TwinnedVertices + found.SharedVertices + found.LockedVertices == 0);

  // Two pyramids on one square (the octahedron cut along its equator): 1-4 and 6-9 are pairs.
  // The pair 1 -> 2, 6 -> 7 is apart (the closed rings {1, 0, 2, 4} and {6, 5, 7, 9}); 1 -> 2
  // and 3 -> 4 are not (3 is a neighbour of 2 and 4, which are 1's).
  const std::vector<double> points = { 0, 0, 1,  1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0,
                                       0, 0, -1, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0 };
  const int32_t triangles[] = { 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1,
                                5, 7, 6, 5, 8, 7, 5, 9, 8, 5, 6, 9 };
  mesh.Build(10, triangles, 8);
  found = seams.Detect(mesh, points.data(), nullptr, false, 1);
  CD_CHECK(found.TwinnedVertices == 8 && found.SharedVertices == 0);
  CD_CHECK(seams.GetTwin(1) == 6 && seams.MirrorTarget(2) == 7 && seams.Admits(mesh, 1, 2));
  std::vector<int32_t> scratch;
  CD_CHECK(SeamMap::AreApart(mesh, 1, 2, 6, 7, scratch));
  CD_CHECK(!SeamMap::AreApart(mesh, 1, 2, 3, 4, scratch));
}

int main(int argc, char* argv[])
{
  return RunTestCases(argc, argv);
}
