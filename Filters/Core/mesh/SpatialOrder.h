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
 * lines. The Decimator builds its mesh and state under the new ids (reading the input through
 * the map) and maps the result back, so that callers only ever see their own ids.
 *
 * Both orders are stable (equal codes keep their input order) and cost O(n): a three-pass
 * radix sort of 30-bit codes (10 bits per axis) and a counting sort of the triangles.
 */
#ifndef colordecimation_SpatialOrder_h
#define colordecimation_SpatialOrder_h

#include "util/Buffer.h"
#include "util/Parallel.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <algorithm>
#include <cstdint>

namespace colordecimation
{

struct SpatialOrder
{
  // Written in parallel, each slot once (a Buffer is not zeroed first).
  Buffer<int32_t> NewVertex; ///< input vertex -> renumbered vertex
  Buffer<int32_t> OldVertex; ///< renumbered vertex -> input vertex
  Buffer<int32_t> OldFace;   ///< renumbered triangle -> input triangle

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
 * vertex ids each, in [0, numVertices)), partly on `threads` threads (the same for any
 * number).
 */
VTKCOLORDECIMATION_EXPORT void ComputeSpatialOrder(int32_t numVertices, const double* points,
                                                   int32_t numTriangles, const int32_t* triangles,
                                                   SpatialOrder& order, int threads = 1);

/**
 * Move block i of `block` consecutive values to block to[i], for i in [0, count) (`to` is a
 * permutation of [0, count)), through a second array: independent moves, so the cache misses
 * of the scattered writes overlap (following the permutation's cycles in place would make
 * each miss wait for the one before), shared among `threads` threads. The caller frees what it can
 * before, so that the copy fits in what it freed.
 */
template <typename Vector>
void Permute(Vector& values, int64_t count, const int32_t* to, int block = 1, int threads = 1)
{
  using T = typename Vector::value_type;
  Vector moved(values.size()); // a Buffer's is left unwritten: every slot is filled below
  const T* from = values.data();
  T* into = moved.data();
  ParallelFor(static_cast<size_t>(std::max<int64_t>(count, 0)), threads,
              [from, into, to, block](size_t begin, size_t end, int)
              {
                for (size_t i = begin; i < end; ++i)
                {
                  std::copy_n(from + block * i, block, into + block * size_t(to[i]));
                }
              });
  values.swap(moved);
}

} // namespace colordecimation

#endif
