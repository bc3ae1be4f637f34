#include "CollapseRules.h"

#include "HalfEdgeMesh.h"

#include <algorithm>
#include <cmath>

namespace colordecimation
{

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

CollapseVerdict CollapseRules::CheckTopology(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1)
{
  if (v0 == v1 || !mesh.IsCollapsible(v0) || !mesh.IsCollapsible(v1))
  {
    return CollapseVerdict::NotCollapsible;
  }
  const int32_t h01 = mesh.FindHalfEdge(v0, v1);
  const int32_t h10 = mesh.FindHalfEdge(v1, v0);
  if (h01 < 0 && h10 < 0)
  {
    return CollapseVerdict::NotCollapsible;
  }
  const bool edgeOnBoundary = h01 < 0 || h10 < 0;
  if (mesh.IsBoundaryVertex(v0) && (this->Options.PreserveBoundary || !edgeOnBoundary))
  {
    return CollapseVerdict::Boundary;
  }

  int32_t opposite[2] = { -1, -1 };
  const int32_t sides[2] = { h01, h10 };
  for (int s = 0; s < 2; ++s)
  {
    const int32_t h = sides[s];
    if (h < 0)
    {
      continue;
    }
    if (mesh.Twin(HalfEdgeMesh::Next(h)) < 0 && mesh.Twin(HalfEdgeMesh::Prev(h)) < 0)
    {
      return CollapseVerdict::LinkCondition; // the triangle would hang by a vertex
    }
    const int32_t x = mesh.Origin(HalfEdgeMesh::Prev(h));
    if (mesh.IsLocked(x))
    {
      return CollapseVerdict::LinkCondition;
    }
    if (!mesh.IsBoundaryVertex(x) && mesh.Valence(x) <= 3)
    {
      return CollapseVerdict::LinkCondition;
    }
    opposite[s] = x;
  }
  if (opposite[0] >= 0 && opposite[0] == opposite[1])
  {
    return CollapseVerdict::LinkCondition;
  }

  // The 1-rings of v0 and v1 may only share vl and vr.
  this->Neighbors.clear();
  mesh.ForEachNeighbor(v0,
                       [&](int32_t u)
                       {
                         if (u != v1 && u != opposite[0] && u != opposite[1])
                         {
                           this->Neighbors.push_back(u);
                         }
                       });
  bool shared = false;
  mesh.ForEachNeighbor(v1,
                       [&](int32_t u)
                       {
                         if (!shared && u != v0 && u != opposite[0] && u != opposite[1])
                         {
                           shared = std::find(this->Neighbors.begin(), this->Neighbors.end(), u) !=
                             this->Neighbors.end();
                         }
                       });
  return shared ? CollapseVerdict::LinkCondition : CollapseVerdict::Legal;
}

CollapseVerdict CollapseRules::CheckGeometry(const HalfEdgeMesh& mesh, const float* positions,
                                             int32_t v0, int32_t v1, int stride) const
{
  const float* p0 = positions + stride * v0;
  const float* p1 = positions + stride * v1;
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
      double oldN[3], newN[3], ea[3], eb[3], fa[3], fb[3];
      for (int k = 0; k < 3; ++k)
      {
        ea[k] = double(pa[k]) - p0[k];
        eb[k] = double(pb[k]) - p0[k];
        fa[k] = double(pa[k]) - p1[k];
        fb[k] = double(pb[k]) - p1[k];
      }
      oldN[0] = ea[1] * eb[2] - ea[2] * eb[1];
      oldN[1] = ea[2] * eb[0] - ea[0] * eb[2];
      oldN[2] = ea[0] * eb[1] - ea[1] * eb[0];
      newN[0] = fa[1] * fb[2] - fa[2] * fb[1];
      newN[1] = fa[2] * fb[0] - fa[0] * fb[2];
      newN[2] = fa[0] * fb[1] - fa[1] * fb[0];
      const double newLength2 = newN[0] * newN[0] + newN[1] * newN[1] + newN[2] * newN[2];
      const double fa2 = fa[0] * fa[0] + fa[1] * fa[1] + fa[2] * fa[2];
      const double fb2 = fb[0] * fb[0] + fb[1] * fb[1] + fb[2] * fb[2];
      // Degenerate: the sine of the angle at p1 below 1e-6 (or a zero-length edge).
      if (!(newLength2 > 1e-12 * fa2 * fb2) || !(fa2 > 0) || !(fb2 > 0))
      {
        verdict = CollapseVerdict::Degenerate;
        return;
      }
      const double oldLength2 = oldN[0] * oldN[0] + oldN[1] * oldN[1] + oldN[2] * oldN[2];
      if (oldLength2 > 0)
      {
        const double dot = oldN[0] * newN[0] + oldN[1] * newN[1] + oldN[2] * newN[2];
        if (dot < minCos * std::sqrt(oldLength2 * newLength2))
        {
          verdict = CollapseVerdict::Flip;
        }
      }
    });
  return verdict;
}

} // namespace colordecimation
