/**
 * @file VertexHeap.h
 * @brief An indexed 4-ary min-heap of vertices keyed by their collapse cost, with
 * decrease-key, increase-key and removal in O(log n).
 *
 * Flat arrays only: the heap entries (key and vertex side by side, so that comparing the
 * four children of a node reads one or two cache lines) and, per vertex, its slot in the
 * heap (-1 when absent). A 4-ary heap is half as deep as a binary one, which matters because
 * the decimation touches the heap at random places: 16 bytes per heap entry + 4 per vertex.
 */
#ifndef colordecimation_VertexHeap_h
#define colordecimation_VertexHeap_h

#include <cstdint>
#include <vector>

namespace colordecimation
{

class VertexHeap
{
public:
  explicit VertexHeap(int32_t numVertices = 0) { this->Reset(numVertices); }

  void Reset(int32_t numVertices)
  {
    this->Heap.clear();
    this->Heap.reserve(numVertices);
    this->Slot.assign(numVertices, -1);
  }

  bool Empty() const { return this->Heap.empty(); }
  size_t Size() const { return this->Heap.size(); }
  bool Contains(int32_t v) const { return this->Slot[v] >= 0; }
  /// The key of a vertex in the heap.
  double GetKey(int32_t v) const { return this->Heap[this->Slot[v]].Key; }
  int32_t Top() const { return this->Heap.front().Vertex; }
  double TopKey() const { return this->Heap.front().Key; }

  /// Insert v, or move it to its new key if it is already in.
  void Set(int32_t v, double key)
  {
    int32_t slot = this->Slot[v];
    if (slot < 0)
    {
      slot = static_cast<int32_t>(this->Heap.size());
      this->Heap.push_back(Entry{ key, v });
      this->Up(slot, Entry{ key, v });
      return;
    }
    const double old = this->Heap[slot].Key;
    if (key < old)
    {
      this->Up(slot, Entry{ key, v });
    }
    else
    {
      this->Down(slot, Entry{ key, v });
    }
  }

  /// Remove v if it is in.
  void Remove(int32_t v)
  {
    const int32_t slot = this->Slot[v];
    if (slot < 0)
    {
      return;
    }
    const Entry last = this->Heap.back();
    this->Heap.pop_back();
    this->Slot[v] = -1;
    if (last.Vertex != v)
    {
      if (slot > 0 && last.Key < this->Heap[(slot - 1) / 4].Key)
      {
        this->Up(slot, last);
      }
      else
      {
        this->Down(slot, last);
      }
    }
  }

  /// Remove and return the vertex with the smallest key.
  int32_t Pop()
  {
    const int32_t v = this->Heap.front().Vertex;
    this->Remove(v);
    return v;
  }

private:
  struct Entry
  {
    double Key;
    int32_t Vertex;
  };

  void Place(int32_t slot, const Entry& e)
  {
    this->Heap[slot] = e;
    this->Slot[e.Vertex] = slot;
  }

  /// Move `e`, destined for `slot`, up to its place.
  void Up(int32_t slot, Entry e)
  {
    while (slot > 0)
    {
      const int32_t parent = (slot - 1) / 4;
      if (!(e.Key < this->Heap[parent].Key))
      {
        break;
      }
      this->Place(slot, this->Heap[parent]);
      slot = parent;
    }
    this->Place(slot, e);
  }

  /// Move `e`, destined for `slot`, down to its place.
  void Down(int32_t slot, Entry e)
  {
    const int32_t n = static_cast<int32_t>(this->Heap.size());
    for (;;)
    {
      const int32_t first = 4 * slot + 1;
      if (first >= n)
      {
        break;
      }
      const int32_t last = first + 4 < n ? first + 4 : n;
      int32_t best = first;
      for (int32_t c = first + 1; c < last; ++c)
      {
        if (this->Heap[c].Key < this->Heap[best].Key)
        {
          best = c;
        }
      }
      if (!(this->Heap[best].Key < e.Key))
      {
        break;
      }
      this->Place(slot, this->Heap[best]);
      slot = best;
    }
    this->Place(slot, e);
  }

  std::vector<Entry> Heap;
  std::vector<int32_t> Slot;
};

} // namespace colordecimation

#endif
