#include "mesh/SpatialOrder.h"

#include "util/Buffer.h"
#include "util/Parallel.h"

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

namespace
{
/// The bounding box of the finite points, as a cube: its low corner and its side.
double FiniteBox(const double* points, size_t n, double lo[3])
{
  double hi[3] = { 0, 0, 0 };
  lo[0] = lo[1] = lo[2] = 0;
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
  return std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
}

/// Vertices: LSD radix sort of (code, vertex) pairs, 10 bits of the code per pass (stable:
/// equal codes keep the vertices' order).
void OrderVertices(const double* points, size_t n, int threads, SpatialOrder& order)
{
  double lo[3];
  const double extent = FiniteBox(points, n, lo);
  Buffer<uint64_t> current(n), next(n); // every slot written by each pass
  uint64_t* pairs = current.data();
  const double box[3] = { lo[0], lo[1], lo[2] };
  ParallelFor(n, threads,
              [pairs, points, box, extent](size_t begin, size_t end, int)
              {
                for (size_t v = begin; v < end; ++v)
                {
                  pairs[v] = (uint64_t(MortonCode(points + 3 * v, box, extent)) << 32) | v;
                }
              });
  std::vector<size_t> digitStart;
  for (int shift = 32; shift < 62; shift += 10)
  {
    const uint64_t* from = current.data();
    uint64_t* into = next.data();
    CountingSort(
      n, 1024, threads, [from, shift](size_t i) { return (from[i] >> shift) & 0x3ff; },
      [from, into](size_t i, size_t slot) { into[slot] = from[i]; }, digitStart);
    current.swap(next);
  }
  order.OldVertex.resize(n);
  order.NewVertex.resize(n);
  int32_t* oldVertex = order.OldVertex.data();
  int32_t* newVertex = order.NewVertex.data();
  const uint64_t* sorted = current.data();
  ParallelFor(n, threads,
              [oldVertex, newVertex, sorted](size_t begin, size_t end, int)
              {
                for (size_t i = begin; i < end; ++i)
                {
                  oldVertex[i] = static_cast<int32_t>(sorted[i] & 0xffffffffu);
                  newVertex[oldVertex[i]] = static_cast<int32_t>(i);
                }
              });
}

/// Triangles: counting sort on their smallest renumbered vertex.
void OrderFaces(const int32_t* triangles, size_t nt, int threads, SpatialOrder& order)
{
  const size_t n = order.NewVertex.size();
  const int32_t* newVertex = order.NewVertex.data();
  Buffer<int32_t> key(nt); // every slot written below
  int32_t* keys = key.data();
  ParallelFor(nt, threads,
              [keys, triangles, newVertex](size_t begin, size_t end, int)
              {
                for (size_t f = begin; f < end; ++f)
                {
                  const int32_t* t = triangles + 3 * f;
                  keys[f] = std::min({ newVertex[t[0]], newVertex[t[1]], newVertex[t[2]] });
                }
              });
  order.OldFace.resize(nt);
  int32_t* oldFace = order.OldFace.data();
  Buffer<int32_t> faceStart;
  CountingSort(
    nt, n, threads, [keys](size_t f) { return keys[f]; },
    [oldFace](size_t f, int32_t slot) { oldFace[slot] = static_cast<int32_t>(f); }, faceStart);
}
} // namespace

void ComputeSpatialOrder(int32_t numVertices, const double* points, int32_t numTriangles,
                         const int32_t* triangles, SpatialOrder& order, int threads)
{
  OrderVertices(points, static_cast<size_t>(std::max(numVertices, 0)), threads, order);
  OrderFaces(triangles, static_cast<size_t>(std::max(numTriangles, 0)), threads, order);
}

} // namespace colordecimation
