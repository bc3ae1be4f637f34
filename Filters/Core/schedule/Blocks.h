/**
 * @file Blocks.h
 * @brief The blocks of the Batched schedule (docs/ALGORITHM.md, section 7): fixed partitions
 * of the vertex ids, and for each vertex whether all its neighbours lie in its block.
 *
 * A collapse whose whole neighbourhood lies inside one block touches nothing another block's
 * collapses touch, so the blocks of a level run on several threads. Three levels: small blocks
 * of 2^Shift ids, wide blocks of eight small ones, and wide blocks shifted by half their size
 * (so that the wide blocks' borders lie inside them). The partitions are fixed, so the result
 * depends on them, never on the number of threads.
 */
#ifndef colordecimation_Blocks_h
#define colordecimation_Blocks_h

#include "util/Buffer.h"

#include <cstddef>
#include <cstdint>

namespace colordecimation
{
class HalfEdgeMesh;

/// A partition of the vertex ids into blocks of 2^Shift ids, the first Offset ids short
/// (block b: from b 2^Shift - Offset on), and its bit in the interior flags.
struct BlockLevel
{
  int Shift;
  int32_t Offset;
  uint8_t Flag;
  /// The flags of the other partitions whose blocks a block of this one does not lie inside:
  /// the flags a collapse inside it may change.
  uint8_t OtherFlags;
  int32_t BlockOf(int32_t v) const
  {
    return static_cast<int32_t>((static_cast<uint32_t>(v) + uint32_t(this->Offset)) >> this->Shift);
  }
};

/// The vertex ids and face slots a sweep of one block reads (WarmRange).
struct BlockRange
{
  size_t FirstVertex, EndVertex;
  int32_t FirstFace, EndFace;
};

class BlockPartition
{
public:
  /// Blocks of 2^shift ids (shift clamped to [4, 24]), wide ones of eight of them, and wide
  /// ones shifted by half their size.
  explicit BlockPartition(int shift);

  const BlockLevel& Small() const { return this->Levels[0]; }
  const BlockLevel* begin() const { return this->Levels; }
  const BlockLevel* end() const { return this->Levels + 3; }
  uint8_t AllFlags() const { return 1 | 2 | 4; }

  /// Interior flags for every vertex, on `threads` threads.
  void FlagEveryInterior(const HalfEdgeMesh& mesh, int threads);
  /**
   * The given flags anew after the collapse v0 -> v1, for v0's former neighbours (v1 among
   * them): they may now have a neighbour in another block of those levels, or no longer have
   * one. v1's fan is walked; another former neighbour u lost v0 and gained v1, so its fan is
   * walked only where v0 may have been its one neighbour across a block's border.
   */
  void FlagAfterCollapse(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1,
                         const int32_t* formerNeighbors, size_t count, uint8_t flags);
  /// How many live, unlocked vertices' flags differ from those FlagEveryInterior would compute
  /// now (for tests: should be 0).
  int64_t CountStaleFlags(const HalfEdgeMesh& mesh, int threads);
  /// Whether every vertex of every face the collapse v0 -> v1 reads or writes is in `block`.
  bool IsInsideBlock(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1, int32_t block,
                     const BlockLevel& level) const;

  /**
   * Where each small block's faces start, for the sweeps of WarmRange: on a renumbered mesh
   * before any collapse, the faces come in order of their smallest vertex.
   */
  void FindBlockFaces(const HalfEdgeMesh& mesh);
  /// The records of `block` to sweep into the cache: its vertices, and the faces from its first
  /// small block's to the one after its last. False when FindBlockFaces was not called.
  bool WarmRange(int32_t block, const BlockLevel& level, size_t numVertices,
                 BlockRange& range) const;

private:
  /// The flags of the partitions where u and v lie in different blocks.
  uint8_t Crossings(int32_t u, int32_t v) const
  {
    uint8_t crossings = 0;
    for (const BlockLevel& level : this->Levels)
    {
      crossings |= level.BlockOf(u) != level.BlockOf(v) ? level.Flag : 0;
    }
    return crossings;
  }

  /// The given flags of v anew from its fan.
  void FlagFan(const HalfEdgeMesh& mesh, int32_t v, uint8_t flags);

  BlockLevel Levels[3];
  /// Vertex -> for each level (its Flag), all its neighbours are in its block. A collapse
  /// inside a block never changes that level's flag; one across blocks may, either way, for
  /// v0's former neighbours (FlagAfterCollapse).
  LargeVector<uint8_t> Interior;
  /// BlockFaces[b]: the first face of small block b, i.e. the first whose smallest vertex is in
  /// it or after it; one entry per block and one more. Empty: no block is swept.
  LargeVector<int32_t> BlockFaces;
};

} // namespace colordecimation

#endif
