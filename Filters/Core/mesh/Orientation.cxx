#include "mesh/Orientation.h"

#include <algorithm>

namespace colordecimation
{
namespace
{
/// One triangle's side of an edge: the edge (smaller id high), the triangle, which corner.
struct Side
{
  uint64_t Edge;
  int32_t Triangle;
  int8_t Corner;
  bool Ascending; ///< the triangle runs the edge from its smaller id to its larger
  bool operator<(const Side& o) const
  {
    return this->Edge != o.Edge ? this->Edge < o.Edge : this->Triangle < o.Triangle;
  }
};

/// Each triangle's neighbour across each corner's edge (-1: none), and whether the two run
/// the edge the same way (then one of them must be reversed).
struct Adjacency
{
  std::vector<int32_t> Neighbor;
  std::vector<uint8_t> SameWay;
};

Adjacency FindNeighbors(const int32_t* triangles, int32_t numTriangles)
{
  std::vector<Side> sides(3 * size_t(numTriangles));
  for (int32_t t = 0; t < numTriangles; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const auto a = static_cast<uint32_t>(triangles[3 * t + k]);
      const auto b = static_cast<uint32_t>(triangles[3 * t + (k + 1) % 3]);
      sides[3 * size_t(t) + k] = { (uint64_t(std::min(a, b)) << 32) | std::max(a, b), t,
                                   static_cast<int8_t>(k), a < b };
    }
  }
  std::sort(sides.begin(), sides.end());
  Adjacency adjacency;
  adjacency.Neighbor.assign(sides.size(), -1);
  adjacency.SameWay.assign(sides.size(), 0);
  for (size_t i = 0; i < sides.size();)
  {
    size_t j = i + 1;
    while (j < sides.size() && sides[j].Edge == sides[i].Edge)
    {
      ++j;
    }
    if (j - i == 2)
    {
      const Side& p = sides[i];
      const Side& q = sides[i + 1];
      const uint8_t same = p.Ascending == q.Ascending ? 1 : 0;
      adjacency.Neighbor[3 * size_t(p.Triangle) + p.Corner] = q.Triangle;
      adjacency.Neighbor[3 * size_t(q.Triangle) + q.Corner] = p.Triangle;
      adjacency.SameWay[3 * size_t(p.Triangle) + p.Corner] = same;
      adjacency.SameWay[3 * size_t(q.Triangle) + q.Corner] = same;
    }
    i = j;
  }
  return adjacency;
}
} // namespace

std::vector<uint8_t> OrientTriangles(const int32_t* triangles, int32_t numTriangles,
                                     std::vector<int32_t>& oriented)
{
  const Adjacency adjacency = FindNeighbors(triangles, numTriangles);
  std::vector<uint8_t> flip(size_t(numTriangles), 0), seen(size_t(numTriangles), 0);
  std::vector<int32_t> piece;
  for (int32_t start = 0; start < numTriangles; ++start)
  {
    if (seen[start])
    {
      continue;
    }
    // Breadth first over the piece: a neighbour that runs the shared edge the same way gets
    // the other flip. A neighbour already seen with the wrong flip is a non-orientable place,
    // left as it is (the mesh build locks it).
    piece.assign(1, start);
    seen[start] = 1;
    size_t flipped = 0;
    for (size_t i = 0; i < piece.size(); ++i)
    {
      const int32_t t = piece[i];
      flipped += flip[t];
      for (int k = 0; k < 3; ++k)
      {
        const int32_t u = adjacency.Neighbor[3 * size_t(t) + k];
        if (u >= 0 && !seen[u])
        {
          seen[u] = 1;
          flip[u] = flip[t] ^ adjacency.SameWay[3 * size_t(t) + k];
          piece.push_back(u);
        }
      }
    }
    if (2 * flipped > piece.size()) // keep the majority's winding
    {
      for (const int32_t t : piece)
      {
        flip[t] ^= 1;
      }
    }
  }
  oriented.assign(triangles, triangles + 3 * size_t(numTriangles));
  for (int32_t t = 0; t < numTriangles; ++t)
  {
    if (flip[t])
    {
      std::swap(oriented[3 * size_t(t) + 1], oriented[3 * size_t(t) + 2]);
    }
  }
  return flip;
}

} // namespace colordecimation
