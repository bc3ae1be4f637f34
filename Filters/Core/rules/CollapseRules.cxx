#include "rules/CollapseRules.h"

#include "mesh/HalfEdgeMesh.h"
#include "util/Parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colordecimation
{
namespace
{
/// (b - a) x (c - a), in double.
template <typename T>
void TriangleNormal(const T* a, const float* b, const float* c, double n[3])
{
  const double e1[3] = { double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2] };
  const double e2[3] = { double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2] };
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/// Whether `to` (squared length toLength2 > 0) is more than acos(minCos) away from `from`;
/// a degenerate `from` has no direction to keep.
bool TurnsTooFar(const double from[3], const double to[3], double toLength2, double minCos)
{
  const double fromLength2 = from[0] * from[0] + from[1] * from[1] + from[2] * from[2];
  if (!(fromLength2 > 0))
  {
    return false;
  }
  const double dot = from[0] * to[0] + from[1] * to[1] + from[2] * to[2];
  return dot < minCos * std::sqrt(fromLength2 * toLength2);
}
} // namespace

namespace
{
constexpr double PackScale = 32767.0;
constexpr int16_t NoDirection = std::numeric_limits<int16_t>::min(); // never a packed value

double SignOf(double x)
{
  return x >= 0 ? 1.0 : -1.0;
}

/// The octahedron's lower half onto the corners of its upper square, and back.
void Fold(double& u, double& v)
{
  const double fu = (1.0 - std::abs(v)) * SignOf(u);
  const double fv = (1.0 - std::abs(u)) * SignOf(v);
  u = fu;
  v = fv;
}
} // namespace

PackedNormal PackNormal(const double n[3])
{
  const double l1 = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
  if (!(l1 > 0) || !std::isfinite(l1))
  {
    return { NoDirection, NoDirection };
  }
  double u = n[0] / l1, v = n[1] / l1;
  if (n[2] < 0)
  {
    Fold(u, v);
  }
  return { static_cast<int16_t>(std::lround(u * PackScale)),
           static_cast<int16_t>(std::lround(v * PackScale)) };
}

void UnpackNormal(PackedNormal packed, double n[3])
{
  if (packed.U == NoDirection)
  {
    n[0] = n[1] = n[2] = 0.0;
    return;
  }
  double u = packed.U / PackScale, v = packed.V / PackScale;
  const double z = 1.0 - std::abs(u) - std::abs(v);
  if (z < 0)
  {
    Fold(u, v);
  }
  n[0] = u;
  n[1] = v;
  n[2] = z;
}

CollapseVerdict CollapseRules::Check(const HalfEdgeMesh& mesh, const float* positions, int32_t v0,
                                     int32_t v1, int stride)
{
  const CollapseVerdict topology = this->CheckTopology(mesh, v0, v1);
  if (topology != CollapseVerdict::Legal)
  {
    return topology;
  }
  return this->CheckGeometry(mesh, positions, v0, v1, stride);
}

CollapseVerdict CollapseRules::Check(const HalfEdgeMesh& mesh, const float* positions, int32_t v0,
                                     int32_t v1, int stride, const double newPosition[3])
{
  const CollapseVerdict topology = this->CheckTopology(mesh, v0, v1);
  if (topology != CollapseVerdict::Legal)
  {
    return topology;
  }
  return this->CheckGeometry(mesh, positions, v0, v1, stride, newPosition);
}

namespace
{
/// vl and vr, the vertices opposite the edge in the triangles of its half-edges `sides` (-1
/// where a side has none); false if such a triangle would hang by a vertex, vl or vr is locked,
/// or they are the same vertex (rules 3 and 4).
bool FindOpposite(const HalfEdgeMesh& mesh, const int32_t sides[2], int32_t opposite[2])
{
  for (int s = 0; s < 2; ++s)
  {
    const int32_t h = sides[s];
    opposite[s] = -1;
    if (h < 0)
    {
      continue;
    }
    if (mesh.Twin(HalfEdgeMesh::Next(h)) < 0 && mesh.Twin(HalfEdgeMesh::Prev(h)) < 0)
    {
      return false; // the triangle would hang by a vertex
    }
    opposite[s] = mesh.Origin(HalfEdgeMesh::Prev(h));
    if (mesh.IsLocked(opposite[s]))
    {
      return false;
    }
  }
  return opposite[0] < 0 || opposite[0] != opposite[1];
}

/// Whether the 1-rings of v0 and v1 share a vertex other than vl and vr (rule 5); v0's valence
/// into `valence`. `neighbors`: scratch.
bool RingsShare(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1, const int32_t opposite[2],
                std::vector<int32_t>& neighbors, int& valence)
{
  neighbors.clear();
  valence = 0;
  mesh.ForEachNeighbor(v0,
                       [&](int32_t u)
                       {
                         ++valence;
                         if (u != v1 && u != opposite[0] && u != opposite[1])
                         {
                           neighbors.push_back(u);
                         }
                       });
  bool shared = false;
  mesh.ForEachNeighbor(v1,
                       [&](int32_t u)
                       {
                         if (!shared && u != v0 && u != opposite[0] && u != opposite[1])
                         {
                           shared =
                             std::find(neighbors.begin(), neighbors.end(), u) != neighbors.end();
                         }
                       });
  return shared;
}

/// Whether an interior vl or vr has valence 3 or less (rule 4's valence), for a collapse whose
/// rings share nothing else: its third neighbour can then only be the other opposite vertex, and
/// v0's fan is closed by three triangles (docs/ALGORITHM.md, section 5), so only then are their
/// fans walked.
bool OppositeValenceTooLow(const HalfEdgeMesh& mesh, const int32_t opposite[2], int valence0)
{
  if (valence0 != 3 || opposite[0] < 0 || opposite[1] < 0)
  {
    return false;
  }
  for (int s = 0; s < 2; ++s)
  {
    if (!mesh.IsBoundaryVertex(opposite[s]) && mesh.IsValenceAtMost(opposite[s], 3))
    {
      return true;
    }
  }
  return false;
}
} // namespace

CollapseVerdict CollapseRules::CheckTopology(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1)
{
  if (v0 == v1 || !mesh.IsCollapsible(v0) || !mesh.IsCollapsible(v1))
  {
    return CollapseVerdict::NotCollapsible;
  }
  const int32_t h01 = mesh.FindHalfEdge(v0, v1);
  const int32_t sides[2] = { h01, mesh.FindReverseHalfEdge(v0, v1, h01) };
  if (sides[0] < 0 && sides[1] < 0)
  {
    return CollapseVerdict::NotCollapsible;
  }
  const bool edgeOnBoundary = sides[0] < 0 || sides[1] < 0;
  if (mesh.IsBoundaryVertex(v0) && (this->Options.PreserveBoundary || !edgeOnBoundary))
  {
    return CollapseVerdict::Boundary;
  }
  int32_t opposite[2];
  int valence = 0;
  if (!FindOpposite(mesh, sides, opposite) ||
      RingsShare(mesh, v0, v1, opposite, this->Neighbors, valence) ||
      OppositeValenceTooLow(mesh, opposite, valence))
  {
    return CollapseVerdict::LinkCondition;
  }
  return CollapseVerdict::Legal;
}

CollapseVerdict CollapseRules::CheckGeometry(const HalfEdgeMesh& mesh, const float* positions,
                                             int32_t v0, int32_t v1, int stride) const
{
  const float* p1 = positions + stride * v1;
  const double p[3] = { p1[0], p1[1], p1[2] };
  return this->CheckFan(mesh, positions, stride, v0, v1, p);
}

CollapseVerdict CollapseRules::CheckGeometry(const HalfEdgeMesh& mesh, const float* positions,
                                             int32_t v0, int32_t v1, int stride,
                                             const double newPosition[3]) const
{
  const CollapseVerdict verdict = this->CheckFan(mesh, positions, stride, v0, v1, newPosition);
  const float* p1 = positions + stride * v1;
  if (verdict != CollapseVerdict::Legal ||
      (newPosition[0] == p1[0] && newPosition[1] == p1[1] && newPosition[2] == p1[2]))
  {
    return verdict;
  }
  return this->CheckFan(mesh, positions, stride, v1, v0, newPosition);
}

namespace
{
/// |(e x n)_0| eta_0 + |(e x n)_1| eta_1 + |(e x n)_2| eta_2.
inline double RoundingLever(const double e[3], const double n[3], const double eta[3])
{
  return eta[0] * std::abs(e[1] * n[2] - e[2] * n[1]) +
    eta[1] * std::abs(e[2] * n[0] - e[0] * n[2]) + eta[2] * std::abs(e[0] * n[1] - e[1] * n[0]);
}

/// Whether the triangle (p1, pa, pb), of normal n (twice its area, squared length
/// newLength2) and edges fa = pa - p1, fb = pb - p1, has an area that the float rounding of
/// its corners could account for. Coordinate k of a corner is rounded by up to
/// eta_k = 8 eps max|x_k|; moving corner c by d changes the area along n by
/// d . (e_c x n) / |n|, e_c the edge opposite c, so the area can reach zero only if
/// |n|^2 <= sum_c sum_k eta_k |(e_c x n)_k|. Per axis, because a triangle far from the origin
/// along one axis is rounded coarsely along that axis only, which moves its area only if its
/// plane is not across that axis. Refused only when the bound over all axes at once
/// (|n|^2 <= 2 noise^2 (fa2 + fb2), noise the largest eta_k) says so too; it is tested first,
/// as it rules out most triangles cheaply.
inline bool WithinRounding(const double p1[3], const float* pa, const float* pb, const double n[3],
                           double newLength2, const double fa[3], const double fb[3], double fa2,
                           double fb2)
{
  double eta[3];
  for (int k = 0; k < 3; ++k)
  {
    eta[k] = 8.0 * std::numeric_limits<float>::epsilon() *
      std::max(std::abs(p1[k]), std::max(std::abs(double(pa[k])), std::abs(double(pb[k]))));
  }
  const double noise = std::max(eta[0], std::max(eta[1], eta[2]));
  if (newLength2 > 2.0 * noise * noise * (fa2 + fb2))
  {
    return false;
  }
  const double opposite[3] = { fb[0] - fa[0], fb[1] - fa[1], fb[2] - fa[2] };
  return !(newLength2 >
           RoundingLever(opposite, n, eta) + RoundingLever(fa, n, eta) + RoundingLever(fb, n, eta));
}
} // namespace

CollapseVerdict CollapseRules::CheckFan(const HalfEdgeMesh& mesh, const float* positions,
                                        int stride, int32_t v0, int32_t v1,
                                        const double p1[3]) const
{
  const float* p0 = positions + stride * v0;
  const double minCos = this->Options.MinimumNormalCosine;
  CollapseVerdict verdict = CollapseVerdict::Legal;
  mesh.ForEachOutgoing(
    v0,
    [&](int32_t h)
    {
      if (verdict != CollapseVerdict::Legal)
      {
        return;
      }
      const int32_t a = mesh.Target(h);
      const int32_t b = mesh.Origin(HalfEdgeMesh::Prev(h));
      if (a == v1 || b == v1)
      {
        return; // this triangle disappears
      }
      const float* pa = positions + stride * a;
      const float* pb = positions + stride * b;
      double oldN[3], newN[3];
      TriangleNormal(p0, pa, pb, oldN);
      TriangleNormal(p1, pa, pb, newN);
      const double fa[3] = { double(pa[0]) - p1[0], double(pa[1]) - p1[1], double(pa[2]) - p1[2] };
      const double fb[3] = { double(pb[0]) - p1[0], double(pb[1]) - p1[1], double(pb[2]) - p1[2] };
      const double newLength2 = newN[0] * newN[0] + newN[1] * newN[1] + newN[2] * newN[2];
      const double fa2 = fa[0] * fa[0] + fa[1] * fa[1] + fa[2] * fa[2];
      const double fb2 = fb[0] * fb[0] + fb[1] * fb[1] + fb[2] * fb[2];
      // Degenerate: the sine of the angle at p1 below 1e-6, a zero-length edge, or an area
      // within the rounding of the stored (float) positions, where exactly collinear input
      // points can come out with a sine above 1e-6.
      if (!(newLength2 > 1e-12 * fa2 * fb2) || !(fa2 > 0) || !(fb2 > 0) ||
          WithinRounding(p1, pa, pb, newN, newLength2, fa, fb, fa2, fb2))
      {
        verdict = CollapseVerdict::Degenerate;
        return;
      }
      if (TurnsTooFar(oldN, newN, newLength2, minCos))
      {
        verdict = CollapseVerdict::Flip;
        return;
      }
      if (this->ReferenceNormals)
      {
        double refN[3];
        UnpackNormal(this->ReferenceNormals[h / 3], refN);
        if (TurnsTooFar(refN, newN, newLength2, this->Options.MinimumDriftCosine))
        {
          verdict = CollapseVerdict::Flip;
        }
      }
    });
  return verdict;
}

void CollapseRules::ComputeReferenceNormals(const HalfEdgeMesh& mesh, const float* positions,
                                            int stride, Buffer<PackedNormal>& normals, int threads)
{
  const int32_t numFaces = mesh.GetNumberOfFaceSlots();
  normals.resize(static_cast<size_t>(numFaces)); // every slot written below
  PackedNormal* out = normals.data();
  ParallelFor(static_cast<size_t>(numFaces), threads,
              [&mesh, positions, stride, out](size_t begin, size_t end, int)
              {
                for (auto f = static_cast<int32_t>(begin); f < static_cast<int32_t>(end); ++f)
                {
                  double n[3] = { 0, 0, 0 };
                  if (mesh.IsFaceAlive(f))
                  {
                    int32_t ids[3];
                    mesh.GetFace(f, ids);
                    TriangleNormal(positions + stride * ids[0], positions + stride * ids[1],
                                   positions + stride * ids[2], n);
                  }
                  out[f] = PackNormal(n);
                }
              });
}

} // namespace colordecimation
