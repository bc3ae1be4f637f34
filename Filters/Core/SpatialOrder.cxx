#include "SpatialOrder.h"

#include <algorithm>
#include <cmath>

namespace colordecimation
{
namespace
{
/// The 10 bits of x spread to every third bit.
uint32_t Spread10(uint32_t x)
{
  x &= 0x3ff;
  x = (x | (x << 16)) & 0x030000ff;
  x = (x | (x << 8)) & 0x0300f00f;
  x = (x | (x << 4)) & 0x030c30c3;
  x = (x | (x << 2)) & 0x09249249;
  return x;
}
} // namespace

uint32_t MortonCode(const double p[3], const double lo[3], double extent)
{
  const double scale = extent > 0 && std::isfinite(extent) ? 1024.0 / extent : 0.0;
  uint32_t code = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double q = (p[k] - lo[k]) * scale;
    // NaN and values below the box go to 0, values above to 1023.
    const uint32_t cell = q >= 0 ? static_cast<uint32_t>(std::min(q, 1023.0)) : 0u;
    code |= Spread10(cell) << k;
  }
  return code;
}

void ComputeSpatialOrder(int32_t numVertices, const double* points, int32_t numTriangles,
                         const int32_t* triangles, SpatialOrder& order)
{
  const auto n = static_cast<size_t>(std::max(numVertices, 0));
  const auto nt = static_cast<size_t>(std::max(numTriangles, 0));

  // The bounding box (finite coordinates only), as a cube.
  double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
  bool any = false;
  for (size_t v = 0; v < n; ++v)
  {
    const double* p = points + 3 * v;
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = any ? std::min(lo[k], p[k]) : p[k];
      hi[k] = any ? std::max(hi[k], p[k]) : p[k];
    }
    any = true;
  }
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });

  // Vertices: LSD radix sort of the codes, 10 bits per pass.
  std::vector<uint32_t> codes(n);
  for (size_t v = 0; v < n; ++v)
  {
    codes[v] = MortonCode(points + 3 * v, lo, extent);
  }
  std::vector<int32_t> current(n), next(n);
  for (size_t v = 0; v < n; ++v)
  {
    current[v] = static_cast<int32_t>(v);
  }
  for (int shift = 0; shift < 30; shift += 10)
  {
    size_t count[1025] = {};
    for (size_t i = 0; i < n; ++i)
    {
      ++count[((codes[current[i]] >> shift) & 0x3ff) + 1];
    }
    for (int b = 0; b < 1024; ++b)
    {
      count[b + 1] += count[b];
    }
    for (size_t i = 0; i < n; ++i)
    {
      next[count[(codes[current[i]] >> shift) & 0x3ff]++] = current[i];
    }
    current.swap(next);
  }
  order.OldVertex.swap(current);
  order.NewVertex.assign(n, -1);
  for (size_t i = 0; i < n; ++i)
  {
    order.NewVertex[order.OldVertex[i]] = static_cast<int32_t>(i);
  }

  // Triangles: counting sort on their smallest renumbered vertex.
  std::vector<int32_t> key(nt);
  std::vector<size_t> start(n + 1, 0);
  for (size_t f = 0; f < nt; ++f)
  {
    const int32_t* t = triangles + 3 * f;
    key[f] = std::min({ order.NewVertex[t[0]], order.NewVertex[t[1]], order.NewVertex[t[2]] });
    ++start[key[f] + 1];
  }
  for (size_t v = 0; v < n; ++v)
  {
    start[v + 1] += start[v];
  }
  order.OldFace.assign(nt, -1);
  for (size_t f = 0; f < nt; ++f)
  {
    order.OldFace[start[key[f]]++] = static_cast<int32_t>(f);
  }
}

} // namespace colordecimation
