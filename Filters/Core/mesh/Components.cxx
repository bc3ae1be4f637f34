#include "mesh/Components.h"

#include "mesh/HalfEdgeMesh.h"
#include "util/Parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <vector>

namespace colordecimation
{
namespace
{
/// The root of v's set: parents only ever move to lower ids in the same set, so a parent read
/// while other threads unite still leads to a root. Halves the path on the way (v is no root,
/// so no link writes its parent meanwhile).
int32_t FindRoot(std::atomic<int32_t>* parent, int32_t v)
{
  for (;;)
  {
    const int32_t p = parent[v].load(std::memory_order_relaxed);
    if (p == v)
    {
      return v;
    }
    const int32_t grandparent = parent[p].load(std::memory_order_relaxed);
    if (grandparent != p)
    {
      parent[v].store(grandparent, std::memory_order_relaxed);
    }
    v = grandparent;
  }
}

/// Unite the sets of a and b: the higher root goes under the lower one, if it is still a root
/// (another thread may have linked it first: then again from the new roots).
void Unite(std::atomic<int32_t>* parent, int32_t a, int32_t b)
{
  for (;;)
  {
    a = FindRoot(parent, a);
    b = FindRoot(parent, b);
    if (a == b)
    {
      return;
    }
    int32_t high = std::max(a, b);
    if (parent[high].compare_exchange_strong(high, std::min(a, b), std::memory_order_relaxed))
    {
      return;
    }
  }
}

/**
 * Each vertex's root in the union of the live faces' vertices: the lowest id of its piece, on
 * `threads` threads (each uniting a range of faces; the lowest id is the root whatever the
 * order of the unions).
 */
std::vector<int32_t> UnionOfFaces(const HalfEdgeMesh& mesh, int threads)
{
  const auto n = static_cast<size_t>(mesh.GetNumberOfVertices());
  std::vector<std::atomic<int32_t>> parents(n);
  std::atomic<int32_t>* parent = parents.data();
  ParallelFor(n, threads,
              [parent](size_t begin, size_t end, int)
              {
                for (size_t v = begin; v < end; ++v)
                {
                  parent[v].store(static_cast<int32_t>(v), std::memory_order_relaxed);
                }
              });
  const HalfEdgeMesh* faces = &mesh;
  ParallelFor(size_t(mesh.GetNumberOfFaceSlots()), threads,
              [faces, parent](size_t begin, size_t end, int)
              {
                for (auto f = static_cast<int32_t>(begin); f < static_cast<int32_t>(end); ++f)
                {
                  if (faces->IsFaceAlive(f))
                  {
                    int32_t ids[3];
                    faces->GetFace(f, ids);
                    Unite(parent, ids[0], ids[1]);
                    Unite(parent, ids[0], ids[2]);
                  }
                }
              });
  // A parent is never above its child: in increasing order each parent's root is known.
  std::vector<int32_t> root(n);
  for (size_t v = 0; v < n; ++v)
  {
    const int32_t p = parent[v].load(std::memory_order_relaxed);
    root[v] = p == static_cast<int32_t>(v) ? p : root[size_t(p)];
  }
  return root;
}

/// The live faces whose root has a piece number (numberOf[root] >= 0), listed by piece.
Pieces ListPieces(const HalfEdgeMesh& mesh, const std::vector<int32_t>& root,
                  const std::vector<int32_t>& numberOf, int32_t count)
{
  std::vector<int32_t> faceOf, faces;
  const int32_t slots = mesh.GetNumberOfFaceSlots();
  for (int32_t f = 0; f < slots; ++f)
  {
    if (mesh.IsFaceAlive(f))
    {
      int32_t ids[3];
      mesh.GetFace(f, ids);
      const int32_t p = numberOf[root[ids[0]]];
      if (p >= 0)
      {
        faceOf.push_back(p);
        faces.push_back(f);
      }
    }
  }
  Pieces pieces;
  pieces.Faces.resize(faces.size());
  CountingSort(
    faces.size(), static_cast<size_t>(count), 1, [&faceOf](size_t i) { return faceOf[i]; },
    [&faces, &pieces](size_t i, int32_t slot) { pieces.Faces[slot] = faces[i]; }, pieces.Start);
  return pieces;
}

/// Every piece of the live faces, numbered by its first face.
Pieces FindPieces(const HalfEdgeMesh& mesh)
{
  const std::vector<int32_t> root = UnionOfFaces(mesh, 1);
  std::vector<int32_t> numberOf(root.size(), -1);
  int32_t count = 0;
  const int32_t slots = mesh.GetNumberOfFaceSlots();
  for (int32_t f = 0; f < slots; ++f)
  {
    if (mesh.IsFaceAlive(f))
    {
      int32_t ids[3];
      mesh.GetFace(f, ids);
      int32_t& p = numberOf[root[ids[0]]];
      p = p >= 0 ? p : count++;
    }
  }
  return ListPieces(mesh, root, numberOf, count);
}

double TriangleArea(const double* points, const int32_t ids[3])
{
  const double* a = points + 3 * size_t(ids[0]);
  const double* b = points + 3 * size_t(ids[1]);
  const double* c = points + 3 * size_t(ids[2]);
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                        u[0] * v[1] - u[1] * v[0] };
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}
} // namespace

Pieces FindSmallPieces(const HalfEdgeMesh& mesh, const std::function<bool(int32_t)>& keep,
                       int threads)
{
  const std::vector<int32_t> root = UnionOfFaces(mesh, threads);
  const auto n = static_cast<int32_t>(root.size());
  // Faces per root, the root of the largest piece, the roots of pieces with a kept vertex.
  std::vector<int32_t> numberOf(root.size(), 0);
  std::vector<uint8_t> kept(root.size(), 0);
  const int32_t slots = mesh.GetNumberOfFaceSlots();
  for (int32_t f = 0; f < slots; ++f)
  {
    if (mesh.IsFaceAlive(f))
    {
      int32_t ids[3];
      mesh.GetFace(f, ids);
      ++numberOf[root[ids[0]]];
    }
  }
  int32_t largest = 0, roots = 0;
  for (int32_t v = 0; v < n; ++v)
  {
    roots += numberOf[v] > 0 ? 1 : 0;
    largest = numberOf[v] > numberOf[largest] ? v : largest;
    kept[root[v]] |= keep(v) ? 1 : 0;
  }
  if (roots <= 1)
  {
    return Pieces();
  }
  int32_t count = 0;
  for (int32_t v = 0; v < n; ++v)
  {
    numberOf[v] = numberOf[v] > 0 && v != largest && !kept[v] ? count++ : -1;
  }
  return ListPieces(mesh, root, numberOf, count);
}

void PieceVertices(const HalfEdgeMesh& mesh, const int32_t* faces, size_t count,
                   std::vector<int32_t>& vertices)
{
  vertices.clear();
  for (size_t i = 0; i < count; ++i)
  {
    if (mesh.IsFaceAlive(faces[i]))
    {
      int32_t ids[3];
      mesh.GetFace(faces[i], ids);
      vertices.insert(vertices.end(), ids, ids + 3);
    }
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
}

PruneReport PruneComponents(HalfEdgeMesh& mesh, const double* points, const uint8_t* fixed,
                            int64_t target)
{
  PruneReport report;
  if (mesh.GetNumberOfLiveFaces() <= target)
  {
    return report;
  }
  const Pieces pieces = FindPieces(mesh);
  const size_t count = pieces.Start.size() - 1;
  std::vector<double> area(count, 0.0);
  std::vector<char> kept(count, 0);
  for (size_t p = 0; p < count; ++p)
  {
    for (int32_t i = pieces.Start[p]; i < pieces.Start[p + 1]; ++i)
    {
      int32_t ids[3];
      mesh.GetFace(pieces.Faces[i], ids);
      area[p] += TriangleArea(points, ids);
      kept[p] |= fixed && (fixed[ids[0]] || fixed[ids[1]] || fixed[ids[2]]) ? 1 : 0;
    }
  }
  std::vector<size_t> order(count);
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b)
            {
              const int32_t fa = pieces.Start[a + 1] - pieces.Start[a];
              const int32_t fb = pieces.Start[b + 1] - pieces.Start[b];
              return area[a] != area[b] ? area[a] < area[b] : fa != fb ? fa < fb : a < b;
            });
  size_t left = count;
  for (size_t k = 0; k < count && mesh.GetNumberOfLiveFaces() > target && left > 1; ++k)
  {
    const size_t p = order[k];
    if (kept[p])
    {
      continue;
    }
    const int32_t n = pieces.Start[p + 1] - pieces.Start[p];
    mesh.RemoveComponent(pieces.Faces.data() + pieces.Start[p], n);
    ++report.Components;
    report.Triangles += n;
    --left;
  }
  return report;
}

} // namespace colordecimation
