#include "mesh/HalfEdgeMesh.h"

#include "mesh/SpatialOrder.h"
#include "util/Parallel.h"

#include <algorithm>

namespace colordecimation
{

/// Outgoing half-edges of each vertex, in compressed rows (counting sort on the origin), with
/// their targets alongside, so that pairing scans two short contiguous rows.
struct HalfEdgeMesh::OutgoingRows
{
  Buffer<int32_t> Offsets;            ///< row of vertex v: [Offsets[v], Offsets[v + 1])
  Buffer<int32_t> HalfEdges, Targets; ///< each slot filled once
};

namespace
{
/// What pairing found on one thread: edges to count, vertices to lock.
struct PairingResult
{
  int64_t BoundaryEdges = 0, NonManifoldEdges = 0, MisorientedEdges = 0;
  std::vector<int32_t> ToLock;
};
} // namespace

MeshBuildReport HalfEdgeMesh::Build(int32_t numVertices, const int32_t* triangles,
                                    int32_t numTriangles, int threads, const int32_t* faceOrder,
                                    const int32_t* newVertex)
{
  MeshBuildReport report;
  this->CopyCorners(triangles, numTriangles, faceOrder, newVertex, threads);
  this->Out.assign(numVertices, -1);
  this->Flags.assign(numVertices, 0);
  this->LiveFaces = numTriangles;
  OutgoingRows rows;
  this->SortOutgoing(numVertices, threads, rows);
  this->PairTwins(numVertices, threads, rows, report);
  this->FindFans(numVertices, threads, rows, report);
  return report;
}

void HalfEdgeMesh::CopyCorners(const int32_t* triangles, int32_t numTriangles,
                               const int32_t* faceOrder, const int32_t* newVertex, int threads)
{
  const int32_t numHalfEdges = 3 * numTriangles;
  this->Corners.resize(numHalfEdges);
  Corner* corners = this->Corners.data();
  ParallelFor(static_cast<size_t>(numHalfEdges), threads,
              [corners, triangles, faceOrder, newVertex](size_t begin, size_t end, int)
              {
                if (faceOrder && newVertex)
                {
                  for (size_t h = begin; h < end; ++h)
                  {
                    const size_t corner = 3 * size_t(faceOrder[h / 3]) + h % 3;
                    corners[h] = { newVertex[triangles[corner]], -1 };
                  }
                  return;
                }
                for (size_t h = begin; h < end; ++h)
                {
                  corners[h] = { triangles[h], -1 };
                }
              });
}

void HalfEdgeMesh::SortOutgoing(int32_t numVertices, int threads, OutgoingRows& rows) const
{
  const auto numHalfEdges = static_cast<size_t>(this->Corners.size());
  rows.HalfEdges.resize(numHalfEdges);
  rows.Targets.resize(numHalfEdges);
  const Corner* corners = this->Corners.data();
  int32_t* rowOutgoing = rows.HalfEdges.data();
  int32_t* rowTarget = rows.Targets.data();
  CountingSort(
    numHalfEdges, static_cast<size_t>(numVertices), threads,
    [corners](size_t h) { return corners[h].Vertex; },
    [this, rowOutgoing, rowTarget](size_t h, int32_t k)
    {
      rowOutgoing[k] = static_cast<int32_t>(h);
      rowTarget[k] = this->Target(static_cast<int32_t>(h));
    },
    rows.Offsets);
}

void HalfEdgeMesh::PairTwins(int32_t numVertices, int threads, const OutgoingRows& outgoing,
                             MeshBuildReport& report)
{
  // An edge is manifold when it has exactly one half-edge each way. Each thread takes a range
  // of vertices a and, for their half-edges a -> b with a < b, counts those of the edge each
  // way; when there is one each way it pairs them (writing both twins: no other half-edge pairs
  // these). Then each takes a range of half-edges and, for those a -> b with a >= b left
  // unpaired, counts them too (a boundary or non-manifold edge). A non-manifold edge is counted
  // by its smallest half-edge. What the threads find is gathered afterwards.
  Corner* corners = this->Corners.data();
  const int32_t numHalfEdges = static_cast<int32_t>(this->Corners.size());
  std::vector<PairingResult> found(static_cast<size_t>(std::max(threads, 1)));
  const int32_t* rows = outgoing.Offsets.data();
  const int32_t* rowHalfEdges = outgoing.HalfEdges.data();
  const int32_t* rowTargets = outgoing.Targets.data();
  PairingResult* results = found.data();
  // Looks at h = a -> b: pairs it with its twin, or reports it.
  const auto pair = [corners, rows, rowHalfEdges, rowTargets](int32_t h, int32_t a, int32_t b,
                                                              PairingResult& result)
  {
    int32_t forward = 0, backward = 0, twin = -1, smallest = h;
    for (int32_t k = rows[a]; k < rows[a + 1]; ++k)
    {
      if (rowTargets[k] == b)
      {
        ++forward;
        smallest = std::min(smallest, rowHalfEdges[k]);
      }
    }
    for (int32_t k = rows[b]; k < rows[b + 1]; ++k)
    {
      if (rowTargets[k] == a)
      {
        ++backward;
        twin = rowHalfEdges[k];
        smallest = std::min(smallest, rowHalfEdges[k]);
      }
    }
    if (forward == 1 && backward == 1)
    {
      corners[h].Twin = twin;
      corners[twin].Twin = h;
    }
    else if (forward == 1 && backward == 0)
    {
      ++result.BoundaryEdges;
    }
    else
    {
      result.ToLock.push_back(a);
      result.ToLock.push_back(b);
      if (smallest == h)
      {
        ++result.NonManifoldEdges;
        result.MisorientedEdges += forward + backward == 2 ? 1 : 0; // two triangles, one way
      }
    }
  };
  ParallelFor(static_cast<size_t>(numVertices), threads,
              [rows, rowHalfEdges, rowTargets, results, pair](size_t begin, size_t end, int t)
              {
                PairingResult result; // on this thread's stack, copied out at the end
                for (auto a = static_cast<int32_t>(begin); a < static_cast<int32_t>(end); ++a)
                {
                  for (int32_t i = rows[a]; i < rows[a + 1]; ++i)
                  {
                    if (a < rowTargets[i])
                    {
                      pair(rowHalfEdges[i], a, rowTargets[i], result);
                    }
                  }
                }
                results[t] = std::move(result);
              });
  this->ReportUnpaired(numHalfEdges, threads, pair, results);
  for (const PairingResult& result : found)
  {
    this->Gather(result, report);
  }
}

template <typename Result>
void HalfEdgeMesh::Gather(const Result& result, MeshBuildReport& report)
{
  report.BoundaryEdges += result.BoundaryEdges;
  report.NonManifoldEdges += result.NonManifoldEdges;
  report.MisorientedEdges += result.MisorientedEdges;
  for (const int32_t v : result.ToLock)
  {
    this->Flags[v] |= Locked;
  }
}

template <typename Pair, typename Result>
void HalfEdgeMesh::ReportUnpaired(int32_t numHalfEdges, int threads, const Pair& pair,
                                  Result* results) const
{
  const Corner* corners = this->Corners.data();
  ParallelFor(static_cast<size_t>(numHalfEdges), threads,
              [this, corners, results, pair](size_t begin, size_t end, int t)
              {
                auto result = std::move(results[t]); // as above
                for (int32_t h = static_cast<int32_t>(begin); h < static_cast<int32_t>(end); ++h)
                {
                  if (corners[h].Twin >= 0)
                  {
                    continue;
                  }
                  const int32_t a = corners[h].Vertex;
                  const int32_t b = this->Target(h);
                  if (a >= b)
                  {
                    pair(h, a, b, result); // pairs nothing (a repeated id aside): b -> a would have
                  }
                }
                results[t] = std::move(result);
              });
}

void HalfEdgeMesh::FindFans(int32_t numVertices, int threads, const OutgoingRows& outgoing,
                            MeshBuildReport& report)
{
  // One outgoing half-edge per vertex; bow-ties detected by circulating. Each vertex writes its
  // own records only; the counts are summed afterwards.
  std::vector<MeshBuildReport> counted(static_cast<size_t>(std::max(threads, 1)));
  MeshBuildReport* counts = counted.data();
  const Corner* corners = this->Corners.data();
  const int32_t* rows = outgoing.Offsets.data();
  const int32_t* rowHalfEdges = outgoing.HalfEdges.data();
  int32_t* out = this->Out.data();
  uint8_t* flags = this->Flags.data();
  ParallelFor(static_cast<size_t>(numVertices), threads,
              [corners, rows, rowHalfEdges, out, flags, counts](size_t begin, size_t end, int t)
              {
                MeshBuildReport found;
                for (auto v = static_cast<int32_t>(begin); v < static_cast<int32_t>(end); ++v)
                {
                  FindFan(corners, rows, rowHalfEdges, v, out, flags, found);
                }
                counts[t] = found;
              });
  for (const MeshBuildReport& found : counted)
  {
    report.IsolatedVertices += found.IsolatedVertices;
    report.NonManifoldVertices += found.NonManifoldVertices;
    report.LockedVertices += found.LockedVertices;
  }
}

void HalfEdgeMesh::FindFan(const Corner* corners, const int32_t* rows, const int32_t* rowHalfEdges,
                           int32_t v, int32_t* out, uint8_t* flags, MeshBuildReport& found)
{
  const int32_t count = rows[v + 1] - rows[v];
  if (count == 0)
  {
    ++found.IsolatedVertices;
    return;
  }
  int32_t boundaryOut = -1, boundaryCount = 0;
  for (int32_t k = rows[v]; k < rows[v + 1]; ++k)
  {
    if (corners[rowHalfEdges[k]].Twin < 0)
    {
      boundaryOut = rowHalfEdges[k];
      ++boundaryCount;
    }
  }
  out[v] = boundaryCount == 1 ? boundaryOut : rowHalfEdges[rows[v]];
  if ((flags[v] & Locked) == 0)
  {
    int32_t visited = 0;
    if (boundaryCount <= 1)
    {
      int32_t h = out[v];
      do
      {
        ++visited;
        h = corners[Prev(h)].Twin;
      } while (h >= 0 && h != out[v] && visited <= count);
    }
    if (visited != count)
    {
      flags[v] |= Locked;
      ++found.NonManifoldVertices;
    }
  }
  found.LockedVertices += (flags[v] & Locked) ? 1 : 0;
}

int HalfEdgeMesh::Valence(int32_t v) const
{
  int valence = 0;
  this->ForEachNeighbor(v, [&](int32_t) { ++valence; });
  return valence;
}

bool HalfEdgeMesh::IsValenceAtMost(int32_t v, int most) const
{
  // Counts as ForEachNeighbor visits, but stops as soon as the answer is known.
  const int32_t start = this->Out[v];
  if (start < 0)
  {
    return true;
  }
  int valence = 0;
  int32_t h = start;
  do
  {
    if (++valence > most)
    {
      return false;
    }
    const int32_t p = Prev(h);
    h = this->Corners[p].Twin;
    if (h < 0)
    {
      ++valence; // a boundary fan's last neighbour
      break;
    }
  } while (h != start);
  return valence <= most;
}

int32_t HalfEdgeMesh::FindHalfEdge(int32_t a, int32_t b) const
{
  // The fan of an unlocked vertex reaches each neighbour once: the first match is the one.
  const int32_t start = this->Out[a];
  if (start < 0)
  {
    return -1;
  }
  int32_t h = start;
  do
  {
    if (this->Target(h) == b)
    {
      return h;
    }
    h = this->Corners[Prev(h)].Twin;
  } while (h >= 0 && h != start);
  return -1;
}

void HalfEdgeMesh::RemoveFace(int32_t h)
{
  const int32_t ta = this->Corners[Next(h)].Twin;
  const int32_t tb = this->Corners[Prev(h)].Twin;
  if (ta >= 0)
  {
    this->Corners[ta].Twin = tb;
  }
  if (tb >= 0)
  {
    this->Corners[tb].Twin = ta;
  }
  const int32_t first = h - h % 3;
  for (int32_t k = first; k < first + 3; ++k)
  {
    this->Corners[k].Vertex = -1;
    this->Corners[k].Twin = -1;
  }
}

void HalfEdgeMesh::RepairOutgoing(int32_t v, int32_t candidate, bool closed)
{
  if (this->Flags[v] & Locked)
  {
    // Locked vertices are never circulated; any live outgoing half-edge will do.
    const int32_t current = this->Out[v];
    if (current < 0 || this->Corners[current].Vertex != v)
    {
      this->Out[v] = candidate;
    }
    return;
  }
  if (closed)
  {
    this->Out[v] = candidate;
    return;
  }
  // Turn backwards until the boundary (or all the way round).
  int32_t h = candidate;
  do
  {
    if (this->Corners[h].Twin < 0)
    {
      break;
    }
    h = Next(this->Corners[h].Twin);
  } while (h != candidate);
  this->Out[v] = h;
}

int HalfEdgeMesh::Collapse(int32_t v0, int32_t v1)
{
  const int removed = this->CollapseUncounted(v0, v1);
  this->LiveFaces -= removed;
  return removed;
}

int HalfEdgeMesh::CollapseUncounted(int32_t v0, int32_t v1)
{
  const int32_t h01 = this->FindHalfEdge(v0, v1);
  const int32_t h10 = this->FindReverseHalfEdge(v0, v1, h01);
  // When the four outer edges of the two faces that go all have twins, stitching them creates
  // no boundary: a vertex whose fan was closed keeps it closed, and needs no circulating to
  // find its new outgoing half-edge.
  bool stitched = true;
  const auto closedBefore = [this](int32_t v) { return v >= 0 && this->HasClosedFan(v); };
  const bool closed1 = closedBefore(v1);
  const bool closedL = h01 >= 0 && closedBefore(this->Corners[Prev(h01)].Vertex);
  const bool closedR = h10 >= 0 && closedBefore(this->Corners[Prev(h10)].Vertex);

  // v0's corners become v1's first (the fan is walked before anything else changes; the
  // corners of the two faces that go are cleared below anyway).
  this->ForEachOutgoing(v0, [this, v1](int32_t h) { this->Corners[h].Vertex = v1; });

  int32_t vl = -1, vr = -1, leftCandidate = -1, rightCandidate = -1, keepCandidate = -1;
  int removed = 0;
  if (h01 >= 0)
  {
    // Face (v0, v1, vl): ta runs vl -> v1, tb runs v0 -> vl (v1 -> vl after relabelling).
    const int32_t ta = this->Corners[Next(h01)].Twin;
    const int32_t tb = this->Corners[Prev(h01)].Twin;
    vl = this->Corners[Prev(h01)].Vertex;
    stitched = stitched && ta >= 0 && tb >= 0;
    leftCandidate = ta >= 0 ? ta : Next(tb);
    keepCandidate = tb >= 0 ? tb : Next(ta);
    this->RemoveFace(h01);
    ++removed;
  }
  if (h10 >= 0)
  {
    // Face (v1, v0, vr): ta runs vr -> v0 (vr -> v1 after relabelling), tb runs v1 -> vr.
    const int32_t ta = this->Corners[Next(h10)].Twin;
    const int32_t tb = this->Corners[Prev(h10)].Twin;
    vr = this->Corners[Prev(h10)].Vertex;
    stitched = stitched && ta >= 0 && tb >= 0;
    rightCandidate = ta >= 0 ? ta : Next(tb);
    keepCandidate = tb >= 0 ? tb : Next(ta);
    this->RemoveFace(h10);
    ++removed;
  }
  this->Out[v0] = -1;
  this->Flags[v0] |= Removed;

  this->RepairOutgoing(v1, keepCandidate, stitched && closed1);
  if (vl >= 0)
  {
    this->RepairOutgoing(vl, leftCandidate, stitched && closedL);
  }
  if (vr >= 0)
  {
    this->RepairOutgoing(vr, rightCandidate, stitched && closedR);
  }
  return removed;
}

void HalfEdgeMesh::Renumber(const int32_t* vertexTo, const int32_t* faceTo, int threads)
{
  // New names first, then every face and vertex record moved to its new slot.
  Corner* corners = this->Corners.data();
  ParallelFor(this->Corners.size(), threads,
              [corners, vertexTo, faceTo](size_t begin, size_t end, int)
              {
                for (size_t h = begin; h < end; ++h)
                {
                  Corner& corner = corners[h];
                  corner.Vertex = corner.Vertex < 0 ? -1 : vertexTo[corner.Vertex];
                  corner.Twin =
                    corner.Twin < 0 ? -1 : 3 * faceTo[corner.Twin / 3] + corner.Twin % 3;
                }
              });
  int32_t* out = this->Out.data();
  ParallelFor(this->Out.size(), threads,
              [out, faceTo](size_t begin, size_t end, int)
              {
                for (size_t v = begin; v < end; ++v)
                {
                  out[v] = out[v] < 0 ? -1 : 3 * faceTo[out[v] / 3] + out[v] % 3;
                }
              });
  Permute(this->Corners, this->GetNumberOfFaceSlots(), faceTo, 3, threads);
  Permute(this->Out, this->GetNumberOfVertices(), vertexTo, 1, threads);
  Permute(this->Flags, this->GetNumberOfVertices(), vertexTo, 1, threads);
}

void HalfEdgeMesh::RemoveComponent(const int32_t* faces, int32_t count)
{
  for (int32_t i = 0; i < count; ++i)
  {
    for (int32_t h = 3 * faces[i]; h < 3 * faces[i] + 3; ++h)
    {
      const int32_t v = this->Corners[h].Vertex;
      this->Out[v] = -1;
      this->Flags[v] |= Removed;
      this->Corners[h] = Corner{ -1, -1 };
    }
  }
  this->LiveFaces -= count;
}

} // namespace colordecimation
