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
/// The pieces of the live faces: each face's piece, and each piece's faces in face order.
struct Pieces
{
  std::vector<int32_t> Start; ///< piece p has faces Faces[Start[p] .. Start[p + 1])
  std::vector<int32_t> Faces;
};

int32_t Root(std::vector<int32_t>& parent, int32_t v)
{
  while (parent[v] != v)
  {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

Pieces FindPieces(const HalfEdgeMesh& mesh)
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
  // Number the pieces by their first face, then list each one's faces (in face order).
  std::vector<int32_t> piece(parent.size(), -1), faceOf, faces;
  int32_t count = 0;
  for (int32_t f = 0; f < slots; ++f)
  {
    if (mesh.IsFaceAlive(f))
    {
      int32_t ids[3];
      mesh.GetFace(f, ids);
      int32_t& p = piece[Root(parent, ids[0])];
      p = p >= 0 ? p : count++;
      faceOf.push_back(p);
      faces.push_back(f);
    }
  }
  Pieces pieces;
  pieces.Faces.resize(faces.size());
  CountingSort(
    faces.size(), static_cast<size_t>(count), 1, [&faceOf](size_t i) { return faceOf[i]; },
    [&faces, &pieces](size_t i, int32_t slot) { pieces.Faces[slot] = faces[i]; }, pieces.Start);
  return pieces;
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
