#include "mesh/Components.h"

#include "mesh/HalfEdgeMesh.h"
#include "util/Parallel.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace colordecimation
{
namespace
{
int32_t Root(std::vector<int32_t>& parent, int32_t v)
{
  while (parent[v] != v)
  {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

/// Each vertex's root in the union of the live faces' vertices: the lowest id of its piece.
std::vector<int32_t> UnionOfFaces(const HalfEdgeMesh& mesh)
{
  std::vector<int32_t> parent(static_cast<size_t>(mesh.GetNumberOfVertices()));
  std::iota(parent.begin(), parent.end(), 0);
  const int32_t slots = mesh.GetNumberOfFaceSlots();
  for (int32_t f = 0; f < slots; ++f)
  {
    if (mesh.IsFaceAlive(f))
    {
      int32_t ids[3];
      mesh.GetFace(f, ids);
      for (int k = 1; k < 3; ++k)
      {
        const int32_t a = Root(parent, ids[0]), b = Root(parent, ids[k]);
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  // A parent is never above its child: in increasing order each parent is a root already.
  for (int32_t& p : parent)
  {
    p = parent[p];
  }
  return parent;
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
  const std::vector<int32_t> root = UnionOfFaces(mesh);
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

Pieces FindSmallPieces(const HalfEdgeMesh& mesh, const std::function<bool(int32_t)>& keep)
{
  const std::vector<int32_t> root = UnionOfFaces(mesh);
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
