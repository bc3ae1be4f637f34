#include "mesh/Seams.h"

#include "mesh/HalfEdgeMesh.h"
#include "util/Parallel.h"

#include <algorithm>
#include <cstring>

namespace colordecimation
{
namespace
{
/// A boundary vertex keyed by the bits of its position (bit-exact, NaN and -0 included).
struct Keyed
{
  uint64_t Key[3];
  int32_t Vertex;
  bool SamePlace(const Keyed& o) const
  {
    return this->Key[0] == o.Key[0] && this->Key[1] == o.Key[1] && this->Key[2] == o.Key[2];
  }
  bool operator<(const Keyed& o) const
  {
    for (int k = 0; k < 3; ++k)
    {
      if (this->Key[k] != o.Key[k])
      {
        return this->Key[k] < o.Key[k];
      }
    }
    return this->Vertex < o.Vertex;
  }
};

/// A vertex of a group of boundary vertices at one position, with its two boundary neighbours.
struct Member
{
  int32_t Vertex, Out, In;
};

/// The unlocked boundary vertices, sorted by position.
std::vector<Keyed> SortBoundary(const HalfEdgeMesh& mesh, const double* points,
                                const int32_t* source, int threads)
{
  std::vector<Keyed> keyed;
  const int32_t n = mesh.GetNumberOfVertices();
  CollectInOrder(
    size_t(n), threads,
    [&mesh, points, source](size_t i, Keyed& item)
    {
      const auto v = static_cast<int32_t>(i);
      if (mesh.IsLocked(v) || mesh.Outgoing(v) < 0 || !mesh.IsBoundaryVertex(v))
      {
        return false;
      }
      std::memcpy(item.Key, points + 3 * size_t(source ? source[v] : v), sizeof(item.Key));
      item.Vertex = v;
      return true;
    },
    keyed);
  std::sort(keyed.begin(), keyed.end());
  return keyed;
}

/**
 * The roles of one group of boundary vertices at one position: a member on a seam edge (another
 * member has a boundary edge to the position of the edge's other end) is twinned when the group
 * is a pair, locked otherwise; the other end of a seam edge that is alone at its position is
 * shared by both sides.
 */
void ClassifyGroup(HalfEdgeMesh& mesh, const std::vector<Member>& members,
                   const std::vector<int32_t>& group, bool lockAll, std::vector<uint8_t>& roles,
                   std::vector<int32_t>& twins, SeamReport& report)
{
  // A vertex alone at its position is its own group (~v, negative).
  const auto key = [&group](int32_t u) { return group[u] >= 0 ? group[u] : ~u; };
  for (const Member& m : members)
  {
    bool seam = false;
    for (const int32_t b : { m.Out, m.In })
    {
      for (const Member& o : members)
      {
        if (o.Vertex != m.Vertex && (key(o.Out) == key(b) || key(o.In) == key(b)))
        {
          seam = true;
          if (group[b] < 0 && !mesh.IsLocked(b))
          {
            roles[b] = SeamMap::Shared; // both sides use b
          }
        }
      }
    }
    if (!seam)
    {
      continue;
    }
    if (members.size() == 2 && !lockAll)
    {
      roles[m.Vertex] = SeamMap::Twinned;
      twins[m.Vertex] = members[0].Vertex == m.Vertex ? members[1].Vertex : members[0].Vertex;
      ++report.TwinnedVertices;
    }
    else
    {
      mesh.Fix(m.Vertex); // locked, and its piece is never removed whole
      ++report.LockedVertices;
    }
  }
}
} // namespace

SeamReport SeamMap::Detect(HalfEdgeMesh& mesh, const double* points, const int32_t* source,
                           bool lockAll, int threads)
{
  this->Release();
  SeamReport report;
  const std::vector<Keyed> keyed = SortBoundary(mesh, points, source, threads);
  // Groups: runs of two or more boundary vertices at one position (none: no seam, the usual
  // case, left here).
  std::vector<size_t> runs;
  for (size_t i = 0; i + 1 < keyed.size(); ++i)
  {
    if (keyed[i].SamePlace(keyed[i + 1]) && (i == 0 || !keyed[i - 1].SamePlace(keyed[i])))
    {
      runs.push_back(i);
    }
  }
  if (runs.empty())
  {
    return report;
  }
  const int32_t n = mesh.GetNumberOfVertices();
  std::vector<int32_t> group(size_t(n), -1);
  for (size_t r = 0; r < runs.size(); ++r)
  {
    for (size_t i = runs[r]; i < keyed.size() && keyed[i].SamePlace(keyed[runs[r]]); ++i)
    {
      group[keyed[i].Vertex] = static_cast<int32_t>(r);
    }
  }
  std::vector<uint8_t> roles(size_t(n), None);
  std::vector<int32_t> twins(size_t(n), -1);
  std::vector<Member> members;
  for (size_t r = 0; r < runs.size(); ++r)
  {
    members.clear();
    for (size_t i = runs[r]; i < keyed.size() && keyed[i].SamePlace(keyed[runs[r]]); ++i)
    {
      Member m{ keyed[i].Vertex, mesh.Target(mesh.Outgoing(keyed[i].Vertex)), -1 };
      mesh.ForEachNeighbor(m.Vertex, [&m](int32_t u) { m.In = u; }); // the last: along the boundary
      members.push_back(m);
    }
    ClassifyGroup(mesh, members, group, lockAll, roles, twins, report);
  }
  const bool any = report.TwinnedVertices + report.LockedVertices > 0;
  for (int32_t v = 0; any && v < n; ++v)
  {
    if (roles[v] == Shared && !lockAll)
    {
      ++report.SharedVertices;
    }
    else if (roles[v] == Shared)
    {
      mesh.Fix(v);
      ++report.LockedVertices;
    }
  }
  if (report.TwinnedVertices + report.SharedVertices > 0)
  {
    this->Roles.swap(roles);
    this->Twins.swap(twins);
  }
  return report;
}

bool SeamMap::Admits(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1) const
{
  const Role role = this->GetRole(v0);
  if (role == Shared)
  {
    return this->GetRole(v1) == None; // a seam edge: it would leave the other side behind
  }
  if (role != Twinned)
  {
    return true;
  }
  const int32_t t0 = this->Twins[v0], m1 = this->MirrorTarget(v1);
  if (m1 < 0 || m1 == v0 || !mesh.IsCollapsible(t0) || !mesh.IsCollapsible(m1))
  {
    return false;
  }
  // The mirror edge t0-m1 must be a boundary edge, whichever way it runs.
  const int32_t h = mesh.FindHalfEdge(t0, m1);
  if (h >= 0)
  {
    return mesh.Twin(h) < 0;
  }
  const int32_t back = mesh.FindHalfEdge(m1, t0);
  return back >= 0 && mesh.Twin(back) < 0;
}

bool SeamMap::AreApart(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1, int32_t t0, int32_t m1,
                       std::vector<int32_t>& scratch)
{
  scratch.clear();
  scratch.push_back(v0);
  mesh.ForEachNeighbor(v0, [&scratch](int32_t u) { scratch.push_back(u); });
  bool apart = true;
  const auto visit = [&](int32_t u)
  {
    if (apart && (u != v1 || m1 != v1) &&
        std::find(scratch.begin(), scratch.end(), u) != scratch.end())
    {
      apart = false;
    }
  };
  visit(t0);
  mesh.ForEachNeighbor(t0, visit);
  return apart;
}

void SeamMap::Release()
{
  this->Roles = std::vector<uint8_t>();
  this->Twins = std::vector<int32_t>();
}

} // namespace colordecimation
