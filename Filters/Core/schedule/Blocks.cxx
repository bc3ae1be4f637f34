#include "schedule/Blocks.h"

#include "mesh/HalfEdgeMesh.h"
#include "util/Parallel.h"

#include <algorithm>
#include <utility>

namespace colordecimation
{

BlockPartition::BlockPartition(int shift)
{
  shift = std::min(std::max(shift, 4), 24);
  this->Levels[0] = { shift, 0, 1, 0 };
  this->Levels[1] = { shift + 3, 0, 2, 1 | 4 };
  this->Levels[2] = { shift + 3, int32_t(1) << (shift + 2), 4, 1 | 2 };
}

void BlockPartition::FlagFan(const HalfEdgeMesh& mesh, int32_t v, uint8_t flags)
{
  uint8_t outside = 0; // the flags of the levels where v has a neighbour in another block
  mesh.ForEachNeighbor(v, [this, &outside, v](int32_t u) { outside |= this->Crossings(u, v); });
  this->Interior[v] = static_cast<uint8_t>((this->Interior[v] & ~flags) | (flags & ~outside));
}

void BlockPartition::FlagAfterCollapse(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1,
                                       const int32_t* formerNeighbors, size_t count, uint8_t flags)
{
  for (size_t i = 0; i < count; ++i)
  {
    const int32_t u = formerNeighbors[i];
    const uint8_t interior = this->Interior[u];
    // A level where u had a neighbour across, and v0 was one: v0 may have been the only one.
    if (u == v1 || (this->Crossings(u, v0) & flags & ~interior) != 0)
    {
      this->FlagFan(mesh, u, flags);
      continue;
    }
    // Elsewhere what u had stands, less the levels where v1 lies across.
    this->Interior[u] = static_cast<uint8_t>(interior & ~(this->Crossings(u, v1) & flags));
  }
}

void BlockPartition::FlagEveryInterior(const HalfEdgeMesh& mesh, int threads)
{
  // Each edge is a side of at least one live face: both of its ends learn of a neighbour in
  // another block. Few edges cross blocks: the threads list those ends, each for its own range
  // of faces, and this thread clears their flags. (For a locked vertex this may be stricter
  // than its fan; its flag is never read.)
  const int32_t numFaces = mesh.GetNumberOfFaceSlots();
  std::vector<std::vector<std::pair<int32_t, uint8_t>>> crossed(static_cast<size_t>(threads));
  ParallelFor(static_cast<size_t>(numFaces), threads,
              [this, &mesh, &crossed](size_t begin, size_t end, int t)
              {
                std::vector<std::pair<int32_t, uint8_t>>& list = crossed[t];
                for (auto f = static_cast<int32_t>(begin); f < static_cast<int32_t>(end); ++f)
                {
                  if (!mesh.IsFaceAlive(f))
                  {
                    continue;
                  }
                  int32_t ids[3];
                  mesh.GetFace(f, ids);
                  for (int k = 0; k < 3; ++k)
                  {
                    const int32_t a = ids[k], b = ids[k == 2 ? 0 : k + 1];
                    const uint8_t crossings = this->Crossings(a, b);
                    if (crossings != 0)
                    {
                      list.emplace_back(a, crossings);
                      list.emplace_back(b, crossings);
                    }
                  }
                }
              });
  this->Interior.assign(mesh.GetNumberOfVertices(), this->AllFlags());
  for (const auto& list : crossed)
  {
    for (const auto& crossing : list)
    {
      this->Interior[crossing.first] &= static_cast<uint8_t>(~crossing.second);
    }
  }
}

int64_t BlockPartition::CountStaleFlags(const HalfEdgeMesh& mesh, int threads)
{
  LargeVector<uint8_t> kept;
  kept.swap(this->Interior);
  this->FlagEveryInterior(mesh, threads);
  int64_t stale = 0;
  for (int32_t v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    stale += mesh.IsCollapsible(v) && kept[v] != this->Interior[v] ? 1 : 0;
  }
  this->Interior.swap(kept);
  return stale;
}

bool BlockPartition::IsInsideBlock(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1, int32_t block,
                                   const BlockLevel& level) const
{
  // The collapse reads and writes the faces around v0, v1 and their common neighbours (vl
  // and vr), and the records of their vertices: all of them must be in the block, i.e. these
  // four vertices must be interior to it. A locked vl or vr fails the rules without its fan
  // being read.
  const uint8_t* interior = this->Interior.data();
  if (!(interior[v0] & level.Flag) || level.BlockOf(v1) != block || !(interior[v1] & level.Flag))
  {
    return false;
  }
  const int32_t h01 = mesh.FindHalfEdge(v0, v1);
  const int32_t h10 = mesh.FindReverseHalfEdge(v0, v1, h01);
  for (const int32_t h : { h01, h10 })
  {
    if (h < 0)
    {
      continue;
    }
    const int32_t x = mesh.Origin(HalfEdgeMesh::Prev(h)); // vl or vr
    if (!mesh.IsLocked(x) && !(interior[x] & level.Flag))
    {
      return false;
    }
  }
  return true;
}

void BlockPartition::FindBlockFaces(const HalfEdgeMesh& mesh)
{
  // None is collapsed yet: a binary search for each block, from the previous block's answer on.
  const int32_t n = mesh.GetNumberOfVertices();
  const int32_t faces = mesh.GetNumberOfFaceSlots();
  const int shift = this->Small().Shift;
  auto smallest = [&mesh](int32_t f)
  {
    int32_t ids[3];
    mesh.GetFace(f, ids);
    return std::min(ids[0], std::min(ids[1], ids[2]));
  };
  const int32_t blocks = (n >> shift) + 1;
  this->BlockFaces.resize(size_t(blocks) + 1);
  int32_t first = 0;
  for (int32_t b = 0; b <= blocks; ++b)
  {
    const int64_t v = std::min<int64_t>(int64_t(b) << shift, n);
    int32_t lo = first, hi = faces;
    while (lo < hi)
    {
      const int32_t mid = lo + (hi - lo) / 2;
      if (smallest(mid) < v)
      {
        lo = mid + 1;
      }
      else
      {
        hi = mid;
      }
    }
    this->BlockFaces[b] = first = lo;
  }
}

bool BlockPartition::WarmRange(int32_t block, const BlockLevel& level, size_t numVertices,
                               BlockRange& range) const
{
  if (this->BlockFaces.empty())
  {
    return false;
  }
  const size_t size = size_t(1) << level.Shift;
  const size_t n = numVertices;
  const size_t start = std::max(size_t(block) * size, size_t(level.Offset)) - size_t(level.Offset);
  range.FirstVertex = std::min(start, n);
  range.EndVertex = std::min(size_t(block + 1) * size - level.Offset, n);
  // The faces from the first small block's to the one after the last (the small blocks lie
  // inside the block).
  const int smallShift = this->Small().Shift;
  const size_t last = this->BlockFaces.size() - 1;
  range.FirstFace = this->BlockFaces[std::min(range.FirstVertex >> smallShift, last)];
  range.EndFace =
    this
      ->BlockFaces[std::min((range.EndVertex + (size_t(1) << smallShift) - 1) >> smallShift, last)];
  return true;
}

} // namespace colordecimation
