#include "mesh/FaceWalk.h"

#include <algorithm>
#include <limits>

namespace colordecimation
{

int32_t FaceWalk::From(int32_t f) const
{
  if ((f & ((int32_t(1) << ChunkShift) - 1)) != 0)
  {
    return f;
  }
  for (auto c = static_cast<size_t>(f) >> ChunkShift; c < this->NumChunks; ++c)
  {
    if (this->Ranges[2 * c + 1] >= this->First && this->Ranges[2 * c] < this->Last)
    {
      return std::min(this->NumFaces, static_cast<int32_t>(c << ChunkShift));
    }
  }
  return this->NumChunks > 0 ? this->NumFaces : f;
}

std::vector<int32_t> ChunkVertexRanges(const HalfEdgeMesh& mesh, int threads)
{
  constexpr int shift = FaceWalk::ChunkShift;
  const int32_t numFaces = mesh.GetNumberOfFaceSlots();
  const size_t numChunks = threads > 1 ? (static_cast<size_t>(numFaces) >> shift) + 1 : 0;
  std::vector<int32_t> chunkRange(2 * numChunks);
  int32_t* ranges = chunkRange.data();
  const HalfEdgeMesh* faces = &mesh;
  ParallelFor(numChunks, threads,
              [faces, ranges, numFaces](size_t begin, size_t end, int)
              {
                for (size_t c = begin; c < end; ++c)
                {
                  int32_t lo = std::numeric_limits<int32_t>::max(), hi = -1;
                  const auto f0 = static_cast<int32_t>(c << shift);
                  const int32_t f1 = std::min(numFaces, f0 + (int32_t(1) << shift));
                  for (int32_t h = 3 * f0; h < 3 * f1; ++h)
                  {
                    const int32_t v = faces->Origin(h);
                    if (v >= 0)
                    {
                      lo = std::min(lo, v);
                      hi = std::max(hi, v);
                    }
                  }
                  ranges[2 * c] = lo;
                  ranges[2 * c + 1] = hi;
                }
              });
  return chunkRange;
}

} // namespace colordecimation
