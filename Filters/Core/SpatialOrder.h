/**
 * @file SpatialOrder.h
 * @brief A renumbering of vertices and triangles that puts neighbours near each other in
 * memory: vertices along a Morton (Z-order) curve through their bounding box, triangles by
 * their smallest renumbered vertex.
 *
 * The decimation collapses edges in cost order, which jumps about the surface; each collapse
 * then reads and re-costs the two-ring around it. When that neighbourhood is scattered over
 * the arrays, as in a scan written slice by slice or a subdivided mesh, nearly every vertex
 * and triangle it touches is a cache miss. Renumbered, a neighbourhood sits in a few cache
 * lines. The Decimator works on the renumbered copy and maps the result back, so that
 * callers only ever see their own ids.
 *
 * Both orders are stable (equal codes keep their input order) and cost O(n): a three-pass
 * radix sort of 30-bit codes (10 bits per axis) and a counting sort of the triangles.
 */
#ifndef colordecimation_SpatialOrder_h
#define colordecimation_SpatialOrder_h

#include "vtkColorDecimationModule.h" // for export macro

#include <algorithm>
#include <cstdint>
#include <vector>

namespace colordecimation
{

struct SpatialOrder
{
  std::vector<int32_t> NewVertex; ///< input vertex -> renumbered vertex
  std::vector<int32_t> OldVertex; ///< renumbered vertex -> input vertex
  std::vector<int32_t> OldFace;   ///< renumbered triangle -> input triangle

  bool Empty() const { return this->OldVertex.empty(); }
};

/**
 * 30-bit Morton code of a point quantised to a 1024^3 grid over the box [lo, lo + extent]
 * (the same extent on every axis). Coordinates outside the box or not finite go to its
 * nearest face.
 */
VTKCOLORDECIMATION_EXPORT uint32_t MortonCode(const double p[3], const double lo[3], double extent);

/**
 * The renumbering of `numVertices` points (3 doubles each) and `numTriangles` triangles (3
 * vertex ids each, in [0, numVertices)).
 */
VTKCOLORDECIMATION_EXPORT void ComputeSpatialOrder(int32_t numVertices, const double* points,
                                                   int32_t numTriangles, const int32_t* triangles,
                                                   SpatialOrder& order);

/**
 * Move block i of `block` consecutive values to block to[i], for i in [0, count), in place
 * (`to` is a permutation of [0, count)): one pass along the permutation's cycles, with one
 * bit of scratch per block instead of a second copy of the array.
 */
template <typename T>
void PermuteInPlace(T* values, int64_t count, const int32_t* to, int block = 1)
{
  std::vector<bool> done(static_cast<size_t>(count), false);
  std::vector<T> carried(block), displaced(block);
  for (int64_t start = 0; start < count; ++start)
  {
    if (done[start])
    {
      continue;
    }
    std::copy(values + block * start, values + block * (start + 1), carried.begin());
    int64_t i = start;
    do
    {
      const int64_t j = to[i];
      std::copy(values + block * j, values + block * (j + 1), displaced.begin());
      std::copy(carried.begin(), carried.end(), values + block * j);
      carried.swap(displaced);
      done[j] = true;
      i = j;
    } while (i != start);
  }
}

} // namespace colordecimation

#endif
