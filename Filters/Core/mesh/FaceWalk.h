/**
 * @file FaceWalk.h
 * @brief Per-vertex sums over the faces on several threads, the same bit for bit as on one.
 *
 * Each thread owns a range of vertices and walks the faces in index order, adding to its own
 * vertices only, so every vertex sees the same terms in the same order whatever the number of
 * threads. With several threads the faces are taken in chunks with the range of vertex ids each
 * chunk uses, and a thread skips the chunks that use none of its vertices (in the spatial
 * order, most of the other threads' faces). Used by the set-up of the metrics' quadrics and of
 * the error bound's plane sums.
 */
#ifndef colordecimation_FaceWalk_h
#define colordecimation_FaceWalk_h

#include "mesh/HalfEdgeMesh.h"
#include "util/Parallel.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstddef>
#include <cstdint>
#include <vector>

namespace colordecimation
{

/**
 * The faces a thread owning the vertices [First, Last) walks: face f, or, if f starts a chunk,
 * the first face from there on whose chunk uses a vertex of [First, Last) (NumFaces if none
 * does). Without chunks (one thread) every face.
 */
struct FaceWalk
{
  static constexpr int ChunkShift = 10; // faces per chunk: 1024

  const int32_t* Ranges;
  size_t NumChunks;
  int32_t First, Last, NumFaces;

  bool Owns(int32_t v) const { return v >= this->First && v < this->Last; }
  int32_t From(int32_t f) const;
};

/// For each chunk of faces, the lowest and highest vertex id its faces use (2 per chunk); none
/// with one thread.
VTKCOLORDECIMATION_EXPORT std::vector<int32_t> ChunkVertexRanges(const HalfEdgeMesh& mesh,
                                                                 int threads);

/// Calls body(walk) for each of `threads` ranges of the mesh's vertices, on its own thread.
template <typename Body>
void ForEachVertexRange(const HalfEdgeMesh& mesh, int threads, const Body& body)
{
  const std::vector<int32_t> chunkRange = ChunkVertexRanges(mesh, threads);
  const int32_t* ranges = chunkRange.data();
  const size_t numChunks = chunkRange.size() / 2;
  const int32_t numFaces = mesh.GetNumberOfFaceSlots();
  ParallelFor(static_cast<size_t>(mesh.GetNumberOfVertices()), threads,
              [body, ranges, numChunks, numFaces](size_t begin, size_t end, int)
              {
                body(FaceWalk{ ranges, numChunks, static_cast<int32_t>(begin),
                               static_cast<int32_t>(end), numFaces });
              });
}

/// Calls face(f) for each live face of the walk, in index order.
template <typename Face>
void ForEachLiveFace(const HalfEdgeMesh& mesh, const FaceWalk& walk, const Face& face)
{
  for (int32_t f = walk.From(0); f < walk.NumFaces; f = walk.From(f + 1))
  {
    if (mesh.IsFaceAlive(f))
    {
      face(f);
    }
  }
}

} // namespace colordecimation

#endif
