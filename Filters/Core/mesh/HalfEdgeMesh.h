/**
 * @file HalfEdgeMesh.h
 * @brief Compact triangle connectivity (a corner table) that supports half-edge collapses.
 *
 * Half-edge `h` lives in face `h / 3` and runs from its corner's vertex `Corners[h].Vertex`
 * to that of `Next(h)`. `Corners[h].Twin` is its twin (the same edge in the neighbouring face,
 * running the other way) or -1 on a boundary. Each vertex keeps one outgoing half-edge in
 * `Out`; for a boundary vertex it is the one whose twin is -1, so that circulating forward
 * from it visits the whole fan.
 *
 * Everything is stored in flat arrays (no per-vertex allocation): 24 bytes per triangle and
 * 5 bytes per vertex.
 *
 * Edges used by more than two triangles, edges whose triangles disagree on orientation, and
 * vertices whose triangles form more than one fan (bow-ties) cannot be represented by twins.
 * Their vertices are *locked*: they keep all their triangles and never take part in a
 * collapse, so non-manifold input is carried through unchanged around those places.
 *
 * A collapse v0 -> v1 (see CollapseRules.h for when it is allowed) deletes the one or two
 * triangles on the edge, stitches their outer edges together and moves v0's other corners to
 * v1:
 *
 * @verbatim
 *          vl                        vl
 *         /  \                      /  \
 *        /    \                    /    \
 *      v0 ---- v1       ==>      ...--- v1
 *        \    /                    \    /
 *         \  /                      \  /
 *          vr                        vr
 * @endverbatim
 */
#ifndef colordecimation_HalfEdgeMesh_h
#define colordecimation_HalfEdgeMesh_h

#include "util/Buffer.h"
#include "util/Prefetch.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>

namespace colordecimation
{

/// Counts of what the connectivity build found in the input.
struct MeshBuildReport
{
  int64_t BoundaryEdges = 0;
  int64_t NonManifoldEdges = 0;    ///< edges with 3+ triangles or inconsistent orientation
  int64_t MisorientedEdges = 0;    ///< of those, edges of two triangles that run them one way
  int64_t NonManifoldVertices = 0; ///< vertices with more than one fan (bow-ties)
  int64_t LockedVertices = 0;
  int64_t IsolatedVertices = 0;
};

class VTKCOLORDECIMATION_EXPORT HalfEdgeMesh
{
public:
  enum VertexFlag : uint8_t
  {
    Locked = 1,  ///< non-manifold neighbourhood: never collapsed
    Removed = 2, ///< collapsed away
    Fixed = 4,   ///< locked for more than its neighbourhood (lock array, ghost, seam corner)
  };

  /// Build from `numTriangles` triangles given as 3 vertex ids each. Triangles must not
  /// repeat a vertex (the caller drops those). The twins are paired on `threads` threads
  /// (the result is the same for any number). Renumbered: face f is the given triangle
  /// faceOrder[f], on the vertices newVertex[id] (both non-null, or both null).
  MeshBuildReport Build(int32_t numVertices, const int32_t* triangles, int32_t numTriangles,
                        int threads = 1, const int32_t* faceOrder = nullptr,
                        const int32_t* newVertex = nullptr);

  static int32_t Next(int32_t h) { return (h % 3 == 2) ? h - 2 : h + 1; }
  static int32_t Prev(int32_t h) { return (h % 3 == 0) ? h + 2 : h - 1; }

  int32_t Origin(int32_t h) const { return this->Corners[h].Vertex; }
  int32_t Target(int32_t h) const { return this->Corners[Next(h)].Vertex; }
  int32_t Twin(int32_t h) const { return this->Corners[h].Twin; }
  int32_t Outgoing(int32_t v) const { return this->Out[v]; }

  /// Hint that v's record is about to be read (the first stage of a prefetch pipeline).
  void PrefetchVertex(int32_t v) const
  {
    COLORDECIMATION_PREFETCH(this->Out.data() + v);
    COLORDECIMATION_PREFETCH(this->Flags.data() + v);
  }
  /// Hint that the faces [firstFace, lastFace) are about to be read.
  void PrefetchFaces(int32_t firstFace, int32_t lastFace) const
  {
    PrefetchRange(this->Corners.data() + 3 * size_t(firstFace),
                  this->Corners.data() + 3 * size_t(lastFace));
  }
  /// Hint that the face of v's outgoing half-edge is about to be read (reads Out[v]).
  void PrefetchFirstFace(int32_t v) const
  {
    const int32_t h = this->Out[v];
    if (h >= 0)
    {
      COLORDECIMATION_PREFETCH(this->Corners.data() + (h - h % 3));
    }
  }

  /// The half-edge leaving v in the k-th face of its fan, in the order of ForEachNeighbor
  /// (reads the k faces before it): -1 past the end of an open fan (or for a vertex without
  /// one); a closed fan goes round again. For a locked vertex, the part ForEachNeighbor walks.
  int32_t FanHalfEdge(int32_t v, int k) const
  {
    int32_t h = this->Out[v];
    for (; k > 0 && h >= 0; --k)
    {
      h = this->Corners[Prev(h)].Twin;
    }
    return h;
  }

  int32_t GetNumberOfVertices() const { return static_cast<int32_t>(this->Out.size()); }
  int32_t GetNumberOfFaceSlots() const { return static_cast<int32_t>(this->Corners.size() / 3); }
  int64_t GetNumberOfLiveFaces() const { return this->LiveFaces; }
  bool IsFaceAlive(int32_t f) const { return this->Corners[3 * f].Vertex >= 0; }
  void GetFace(int32_t f, int32_t ids[3]) const
  {
    ids[0] = this->Corners[3 * f].Vertex;
    ids[1] = this->Corners[3 * f + 1].Vertex;
    ids[2] = this->Corners[3 * f + 2].Vertex;
  }

  bool IsLocked(int32_t v) const { return (this->Flags[v] & Locked) != 0; }
  bool IsRemoved(int32_t v) const { return (this->Flags[v] & Removed) != 0; }
  bool IsFixed(int32_t v) const { return (this->Flags[v] & Fixed) != 0; }
  /// A vertex that still has triangles, is manifold and may take part in collapses.
  bool IsCollapsible(int32_t v) const { return this->Flags[v] == 0 && this->Out[v] >= 0; }
  /// Only meaningful for unlocked vertices.
  bool IsBoundaryVertex(int32_t v) const
  {
    return this->Out[v] >= 0 && this->Corners[this->Out[v]].Twin < 0;
  }

  /**
   * Call `f(h)` for every outgoing half-edge of an unlocked vertex, in fan order (for a
   * boundary vertex starting at its boundary half-edge).
   */
  template <typename F>
  void ForEachOutgoing(int32_t v, F&& f) const
  {
    const int32_t start = this->Out[v];
    if (start < 0)
    {
      return;
    }
    int32_t h = start;
    do
    {
      f(h);
      h = this->Corners[Prev(h)].Twin;
    } while (h >= 0 && h != start);
  }

  /**
   * Call `f(u)` for every neighbour of an unlocked vertex, in fan order. A boundary vertex
   * has one neighbour more than it has outgoing half-edges: the last one is reached through
   * the incoming boundary half-edge.
   */
  template <typename F>
  void ForEachNeighbor(int32_t v, F&& f) const
  {
    const int32_t start = this->Out[v];
    if (start < 0)
    {
      return;
    }
    int32_t h = start;
    do
    {
      f(this->Target(h));
      const int32_t p = Prev(h);
      h = this->Corners[p].Twin;
      if (h < 0)
      {
        f(this->Corners[p].Vertex);
      }
    } while (h >= 0 && h != start);
  }

  /// Exclude v from every collapse (it and all its triangles' corners stay as they are).
  void Lock(int32_t v) { this->Flags[v] |= Locked; }
  /// Lock v for more than its neighbourhood: the input fixes it (lock array, ghost point) or it
  /// holds a seam together; its piece is never removed whole.
  void Fix(int32_t v) { this->Flags[v] |= Locked | Fixed; }

  /// Number of neighbours of an unlocked vertex.
  int Valence(int32_t v) const;
  /// Valence(v) <= most, walking no further than needed.
  bool IsValenceAtMost(int32_t v, int most) const;

  /// The half-edge a -> b of an unlocked vertex a, or -1.
  int32_t FindHalfEdge(int32_t a, int32_t b) const;
  /**
   * The half-edge b -> a of an unlocked vertex b, given hab = FindHalfEdge(a, b): hab's twin
   * when it has one (b has one half-edge to a at most), otherwise searched.
   */
  int32_t FindReverseHalfEdge(int32_t a, int32_t b, int32_t hab) const
  {
    const int32_t twin = hab >= 0 ? this->Corners[hab].Twin : -1;
    return twin >= 0 ? twin : this->FindHalfEdge(b, a);
  }

  /**
   * Collapse v0 into v1 (both unlocked, adjacent; legality is the caller's business, see
   * CollapseRules). Returns the number of triangles removed (1 or 2).
   */
  int Collapse(int32_t v0, int32_t v1);

  /**
   * Collapse without counting: the live-face count is left to the caller (RemoveLiveFaces).
   * Collapses on different threads are safe when every vertex of every face around v0, v1
   * and their common neighbours (the faces it reads and writes) is touched by one thread
   * only; the count is the one thing they would otherwise share.
   */
  int CollapseUncounted(int32_t v0, int32_t v1);
  /**
   * Remove the `count` faces `faces` and their vertices: a whole connected piece (every face of
   * each of their vertices is among them, so no half-edge outside refers to them).
   */
  void RemoveComponent(const int32_t* faces, int32_t count);

  /// Account for `count` faces removed by CollapseUncounted.
  void RemoveLiveFaces(int64_t count) { this->LiveFaces -= count; }

  /**
   * Renumber: vertex v becomes vertexTo[v] and face slot f becomes faceTo[f] (both
   * permutations), with every half-edge, twin and outgoing half-edge following. Used to map a
   * mesh decimated in a spatial order (SpatialOrder.h) back to its input's ids.
   */
  void Renumber(const int32_t* vertexTo, const int32_t* faceTo, int threads = 1);

private:
  struct Corner;
  struct OutgoingRows;
  // The phases of Build.
  void CopyCorners(const int32_t* triangles, int32_t numTriangles, const int32_t* faceOrder,
                   const int32_t* newVertex, int threads);
  void SortOutgoing(int32_t numVertices, int threads, OutgoingRows& rows) const;
  /// Twins of the manifold edges; the ends of the others locked.
  void PairTwins(int32_t numVertices, int threads, const OutgoingRows& rows,
                 MeshBuildReport& report);
  /// The unpaired half-edges a -> b with a >= b, looked at by `pair` (PairTwins).
  template <typename Pair, typename Result>
  void ReportUnpaired(int32_t numHalfEdges, int threads, const Pair& pair, Result* results) const;
  /// One thread's pairing result: its counts added, its vertices locked.
  template <typename Result>
  void Gather(const Result& result, MeshBuildReport& report);
  /// Each vertex's outgoing half-edge; bow-ties (more than one fan) locked.
  void FindFans(int32_t numVertices, int threads, const OutgoingRows& rows,
                MeshBuildReport& report);
  static void FindFan(const Corner* corners, const int32_t* rows, const int32_t* rowHalfEdges,
                      int32_t v, int32_t* out, uint8_t* flags, MeshBuildReport& found);

  void RemoveFace(int32_t h);
  /// Out[v] anew from a live outgoing half-edge; `closed`: v's fan is known to have no
  /// boundary (then any outgoing half-edge will do, without circulating).
  void RepairOutgoing(int32_t v, int32_t candidate, bool closed);
  /// Whether v's fan has no boundary (Out points to the boundary half-edge if there is one).
  bool HasClosedFan(int32_t v) const
  {
    return this->Out[v] >= 0 && this->Corners[this->Out[v]].Twin >= 0;
  }

  /// A corner of a face, which is also the half-edge leaving it. Vertex and twin sit side by
  /// side so that circulating a vertex touches one cache line per face.
  struct Corner
  {
    int32_t Vertex; ///< -1 for deleted faces
    int32_t Twin;   ///< twin half-edge, -1 on boundaries
  };
  Buffer<Corner> Corners;
  LargeVector<int32_t> Out;   ///< vertex -> one outgoing half-edge, -1 if it has none
  LargeVector<uint8_t> Flags; ///< VertexFlag bits
  int64_t LiveFaces = 0;
};

} // namespace colordecimation

#endif
