#include "metric/ColorQuadricMetric.h"

#include "mesh/HalfEdgeMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colordecimation
{

ColorQuadricMetric::ColorQuadricMetric(const DecimatorOptions& options)
  : ColorWeight(std::max(options.ColorWeight, 0.0))
  , BoundaryWeight(std::max(options.BoundaryWeight, 0.0))
  , Placing(options.OptimalPlacement)
  , PreserveBoundary(options.PreserveBoundary)
  , Space(options.Space)
{
}

void ColorQuadricMetric::Initialize(const HalfEdgeMesh& mesh, const Frame& frame,
                                    Buffer<HotVertex>& hot, bool useColor, int)
{
  this->Mesh = &mesh;
  this->Hot = &hot;
  this->UseColor = useColor;
  // GH98's frame: the bounding box scaled uniformly into the unit cube.
  const double extent =
    std::max({ frame.Hi[0] - frame.Lo[0], frame.Hi[1] - frame.Lo[1], frame.Hi[2] - frame.Lo[2] });
  this->CubeScale = extent > 0 && std::isfinite(extent) ? 1.0 / (frame.Scale * extent) : 1.0;
  InitializeColorQuadrics(mesh, hot.empty() ? nullptr : hot[0].P, HotStride, this->CubeScale,
                          useColor && !hot.empty() ? hot[0].C : nullptr, HotStride,
                          this->ColorWeight, this->BoundaryWeight, this->States);
  if (this->Placing)
  {
    this->Moved.assign(hot.size(), 0);
  }
}

void ColorQuadricMetric::Offset6(int32_t v0, int32_t v1, double d[6]) const
{
  const HotVertex& a = (*this->Hot)[v0];
  const HotVertex& b = (*this->Hot)[v1];
  for (int k = 0; k < 3; ++k)
  {
    d[k] = this->CubeScale * (double(b.P[k]) - a.P[k]);
    d[3 + k] = this->ColorWeight * (double(b.C[k]) - a.C[k]);
  }
}

void ColorQuadricMetric::PlacementPosition(int32_t v0, const double y[6], double p[3]) const
{
  const HotVertex& a = (*this->Hot)[v0];
  for (int k = 0; k < 3; ++k)
  {
    p[k] = static_cast<float>(a.P[k] + y[k] / this->CubeScale);
  }
}

void ColorQuadricMetric::CostRing(int32_t v0, bool, Ring& ring, double* costs,
                                  Scratch& scratch) const
{
  const int n = ring.PaddedSize();
  if (this->Placing && scratch.Placements.size() < 6 * static_cast<size_t>(n))
  {
    scratch.Placements.resize(12 * n);
  }
  const HotVertex& hot0 = (*this->Hot)[v0];
  const double g = this->CubeScale;
  const double w = this->ColorWeight;
  const ColorQuadric& q0 = this->States[v0];
  for (int j = 0; j < ring.Size; ++j)
  {
    const double d[6] = { g * (ring.X[j] - hot0.P[0]), g * (ring.Y[j] - hot0.P[1]),
                          g * (ring.Z[j] - hot0.P[2]), w * (ring.R[j] - hot0.C[0]),
                          w * (ring.G[j] - hot0.C[1]), w * (ring.B[j] - hot0.C[2]) };
    if (this->Placing)
    {
      costs[j] = ring.IsCandidate[j]
        ? this->PlaceCollapse(v0, ring.Vertex[j], d, &scratch.Placements[6 * j])
        : std::numeric_limits<double>::infinity();
    }
    else
    {
      // (Q(v0) + Q(j))(xj): Q(v0) is centred at x0, Q(j) at xj (it contributes its constant).
      costs[j] = std::max(0.0, q0.Evaluate(d) + ring.QC[j]);
    }
  }
  for (int j = ring.Size; j < n; ++j)
  {
    costs[j] = std::numeric_limits<double>::infinity();
  }
}

bool ColorQuadricMetric::Place(int32_t v0, int32_t v1, Placement& place,
                               double newPosition[3]) const
{
  if (!this->Placing)
  {
    return false;
  }
  double d01[6];
  this->Offset6(v0, v1, d01);
  this->PlaceCollapse(v0, v1, d01, place.Y);
  const bool moves = !std::equal(place.Y, place.Y + 6, d01);
  if (moves)
  {
    this->PlacementPosition(v0, place.Y, newPosition);
  }
  return moves;
}

bool ColorQuadricMetric::RingPlacement(int32_t v0, int j, const Scratch& scratch, double p[3]) const
{
  if (!this->Placing)
  {
    return false;
  }
  this->PlacementPosition(v0, &scratch.Placements[6 * j], p);
  return true;
}

double ColorQuadricMetric::PlaceCollapse(int32_t v0, int32_t v1, const double d01[6],
                                         double y[6]) const
{
  // Q = Q(v0) + Q(v1), centred at x0 (Q(v1) is centred at x1 = x0 + d01).
  ColorQuadricD q;
  q.Assign(this->States[v0]);
  const double d10[6] = { -d01[0], -d01[1], -d01[2], -d01[3], -d01[4], -d01[5] };
  q.AddShifted(this->States[v1], d10);

  // Where boundaries are preserved, a boundary v1 stays where it is (a half-edge collapse).
  bool placed =
    !(this->PreserveBoundary && this->Mesh->IsBoundaryVertex(v1)) && MinimizeColorQuadric(q, y);
  if (placed)
  {
    // Guard against nearly singular systems: the minimiser stays near the edge.
    double far = 0.0, length2 = 0.0;
    for (int k = 0; k < 6; ++k)
    {
      const double m = y[k] - 0.5 * d01[k];
      far += m * m;
      length2 += d01[k] * d01[k];
    }
    placed = far <= 4.0 * length2;
  }
  return placed ? this->SnapPlacement(v0, q, d01, y) : this->BetterEndpoint(v1, q, d01, y);
}

double ColorQuadricMetric::SnapPlacement(int32_t v0, const ColorQuadricD& q, const double d01[6],
                                         double y[6]) const
{
  const double w = this->ColorWeight;
  const HotVertex& a = (*this->Hot)[v0];
  if (w > 0 && this->UseColor)
  {
    // The colour within the displayable range (in the metric's colour space).
    double c[3] = { a.C[0] + y[3] / w, a.C[1] + y[4] / w, a.C[2] + y[5] / w };
    if (ClampMetricColor(this->Space, c))
    {
      for (int k = 0; k < 3; ++k)
      {
        y[3 + k] = w * (c[k] - a.C[k]);
      }
    }
  }
  else
  {
    // No colour to place: v1 keeps its own.
    std::copy(d01 + 3, d01 + 6, y + 3);
  }
  // As the point will be stored (float), so that the cost is the one of that point.
  double p[3];
  this->PlacementPosition(v0, y, p);
  for (int k = 0; k < 3; ++k)
  {
    y[k] = this->CubeScale * (p[k] - a.P[k]);
  }
  if (w > 0 && this->UseColor)
  {
    for (int k = 0; k < 3; ++k)
    {
      const float c = static_cast<float>(a.C[k] + y[3 + k] / w);
      y[3 + k] = w * (double(c) - a.C[k]);
    }
  }
  return std::max(0.0, q.Evaluate(y));
}

double ColorQuadricMetric::BetterEndpoint(int32_t v1, const ColorQuadricD& q, const double d01[6],
                                          double y[6]) const
{
  // v1's point (a half-edge collapse) unless v0's is better by more than the rounding of the
  // evaluation (so that ties, as on flat uniform patches, do not move vertices for nothing).
  const double at1 = q.Evaluate(d01);
  const double at0 = q.C;
  double trace = 0.0, length2 = 0.0;
  for (int k = 0; k < 6; ++k)
  {
    trace += std::abs(q.GetA(k, k));
    length2 += d01[k] * d01[k];
  }
  if (at0 < at1 - 1e-6 * trace * length2 &&
      !(this->PreserveBoundary && this->Mesh->IsBoundaryVertex(v1)))
  {
    std::fill(y, y + 6, 0.0);
    return std::max(0.0, at0);
  }
  std::copy(d01, d01 + 6, y);
  return std::max(0.0, at1);
}

void ColorQuadricMetric::Merge(int32_t v0, int32_t v1, bool moves, const Placement& place)
{
  ColorQuadric& q1 = this->States[v1];
  const ColorQuadric& q0 = this->States[v0];
  HotVertex& a = (*this->Hot)[v0];
  HotVertex& b = (*this->Hot)[v1];
  if (!moves)
  {
    double d01[6];
    this->Offset6(v0, v1, d01);
    q1.AddShifted(q0, d01);
    b.QC = q1.C;
    return;
  }
  // The new point, stored, then both quadrics re-centred there.
  const double w = this->ColorWeight;
  HotVertex placed = b;
  double p[3];
  this->PlacementPosition(v0, place.Y, p);
  for (int k = 0; k < 3; ++k)
  {
    placed.P[k] = static_cast<float>(p[k]);
    if (w > 0 && this->UseColor)
    {
      placed.C[k] = static_cast<float>(a.C[k] + place.Y[3 + k] / w);
    }
  }
  double dn0[6], dn1[6];
  for (int k = 0; k < 3; ++k)
  {
    dn0[k] = this->CubeScale * (double(placed.P[k]) - a.P[k]);
    dn1[k] = this->CubeScale * (double(placed.P[k]) - b.P[k]);
    dn0[3 + k] = w * (double(placed.C[k]) - a.C[k]);
    dn1[3 + k] = w * (double(placed.C[k]) - b.C[k]);
  }
  ColorQuadricD sum;
  sum.AddShifted(q0, dn0);
  sum.AddShifted(q1, dn1);
  q1.Assign(sum);
  std::copy(placed.P, placed.P + 3, b.P);
  std::copy(placed.C, placed.C + 3, b.C);
  b.QC = q1.C;
  this->Moved[v1] = 1;
}

bool ColorQuadricMetric::AnyMoved() const
{
  return std::find(this->Moved.begin(), this->Moved.end(), 1) != this->Moved.end();
}

} // namespace colordecimation
