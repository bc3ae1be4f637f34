/**
 * @file VertexHeap.h
 * @brief An indexed 4-ary min-heap of vertices keyed by their collapse cost, with
 * decrease-key and removal in O(log n) and lazy increase-key in O(1).
 *
 * Flat arrays only: the heap entries (key and vertex side by side, so that comparing the
 * four children of a node reads one or two cache lines) and, per vertex, its slot in the
 * heap (-1 when absent), its key and the key it is placed under. A 4-ary heap is half as
 * deep as a binary one, which matters because the decimation touches the heap at random
 * places.
 *
 * Increases are lazy. Most re-costings after a collapse raise a vertex's cost, and a vertex
 * is re-costed several times before it is collapsed; moving it down the heap each time costs
 * a cache miss per level. Instead, a raised vertex only records its new key and stays where
 * it is, placed under its old, lower key. The heap order holds for the placed keys, and
 * every placed key is at most its vertex's key; so when the top's placed key is its key, no
 * other vertex has a smaller one. Top() restores that: a top placed too low is moved down
 * under its key (once, however often it was raised) until the top is placed at its key.
 * Pop order is therefore that of an eagerly updated heap (up to the order of equal keys).
 *
 * Memory: 16 bytes per heap entry + 20 per vertex. The per-vertex keys are indexed by vertex,
 * so re-costing a neighbourhood touches memory near the one it already reads.
 */
#ifndef colordecimation_VertexHeap_h
#define colordecimation_VertexHeap_h

#include "util/Buffer.h"
#include "util/Prefetch.h"

#include <algorithm>
#include <cstdint>

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
    this->Key.assign(numVertices, 0.0);
    this->Placed.assign(numVertices, 0.0);
  }

  /// Empty the heap and give its memory back.
  void Release()
  {
    this->Heap = Entries();
    this->Slot = LargeVector<int32_t>();
    this->Key = LargeVector<double>();
    this->Placed = LargeVector<double>();
  }

  bool Empty() const { return this->Heap.empty(); }
  size_t Size() const { return this->Heap.size(); }
  bool Contains(int32_t v) const { return this->Slot[v] >= 0; }
  /// The key of a vertex in the heap.
  double GetKey(int32_t v) const { return this->Key[v]; }
  /// The vertex with the smallest key (the heap must not be empty).
  int32_t Top()
  {
    this->Settle();
    return this->Heap.front().Vertex;
  }
  double TopKey()
  {
    this->Settle();
    return this->Heap.front().Key;
  }

  /// Hint that v's key is about to be set.
  void Prefetch(int32_t v) const
  {
    COLORDECIMATION_PREFETCH(this->Slot.data() + v);
    COLORDECIMATION_PREFETCH(this->Key.data() + v);
    COLORDECIMATION_PREFETCH(this->Placed.data() + v);
  }

  /// Insert v, or give it a new key if it is already in.
  void Set(int32_t v, double key)
  {
    int32_t slot = this->Slot[v];
    this->Key[v] = key;
    if (slot < 0)
    {
      slot = static_cast<int32_t>(this->Heap.size());
      this->Heap.push_back(Entry{ key, v });
      this->Placed[v] = key;
      this->Up(slot, Entry{ key, v });
      return;
    }
    if (key < this->Placed[v])
    {
      this->Placed[v] = key;
      this->Up(slot, Entry{ key, v });
    }
    // else raised: v stays placed under its old key until it reaches the top (Settle).
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
    const int32_t v = this->Top();
    this->Remove(v);
    return v;
  }

private:
  struct Entry
  {
    double Key;
    int32_t Vertex;
  };

  /**
   * The heap's array, laid out so that the four children of a node (slots 4s+1 to 4s+4, 64
   * bytes) share one cache line: slot 0 sits 48 bytes past a 64-byte boundary. Down then
   * reads one line per level instead of two.
   */
  class Entries
  {
  public:
    void clear() { this->Count = 0; }
    void reserve(size_t n)
    {
      if (n + 3 <= this->Storage.size() - this->Offset && !this->Storage.empty())
      {
        return;
      }
      LargeVector<Entry> storage(n + 3);
      const auto address = reinterpret_cast<uintptr_t>(storage.data());
      const size_t offset = ((112 - address % 64) % 64) / sizeof(Entry); // 0 to 3
      std::copy(this->Storage.begin() + this->Offset,
                this->Storage.begin() + this->Offset + this->Count, storage.begin() + offset);
      this->Storage.swap(storage);
      this->Offset = offset;
    }
    bool empty() const { return this->Count == 0; }
    size_t size() const { return this->Count; }
    Entry& operator[](size_t i) { return this->Storage[this->Offset + i]; }
    const Entry& operator[](size_t i) const { return this->Storage[this->Offset + i]; }
    const Entry& front() const { return (*this)[0]; }
    const Entry& back() const { return (*this)[this->Count - 1]; }
    void push_back(const Entry& e)
    {
      if (this->Offset + this->Count >= this->Storage.size())
      {
        this->reserve(2 * this->Count + 4);
      }
      (*this)[this->Count++] = e;
    }
    void pop_back() { --this->Count; }

  private:
    LargeVector<Entry> Storage;
    size_t Offset = 0;
    size_t Count = 0;
  };

  void Place(int32_t slot, const Entry& e)
  {
    this->Heap[slot] = e;
    this->Slot[e.Vertex] = slot;
  }

  /// Move raised vertices off the top until the top is placed under its own key.
  void Settle()
  {
    for (;;)
    {
      const Entry top = this->Heap.front();
      const double key = this->Key[top.Vertex];
      if (!(key > top.Key))
      {
        return;
      }
      this->Placed[top.Vertex] = key;
      this->Down(0, Entry{ key, top.Vertex });
    }
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
      int32_t best = first;
      if (first + 4 <= n)
      {
        // All four children: a tournament the compiler turns into conditional moves (which
        // child wins is unpredictable, and a mispredicted branch costs as much as a miss).
        const double k0 = this->Heap[first].Key, k1 = this->Heap[first + 1].Key;
        const double k2 = this->Heap[first + 2].Key, k3 = this->Heap[first + 3].Key;
        const int32_t a = k1 < k0 ? first + 1 : first;
        const double ka = k1 < k0 ? k1 : k0;
        const int32_t b = k3 < k2 ? first + 3 : first + 2;
        const double kb = k3 < k2 ? k3 : k2;
        best = kb < ka ? b : a;
      }
      else
      {
        for (int32_t c = first + 1; c < n; ++c)
        {
          best = this->Heap[c].Key < this->Heap[best].Key ? c : best;
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

  Entries Heap;
  LargeVector<int32_t> Slot;  ///< vertex -> its heap slot, -1 when absent
  LargeVector<double> Key;    ///< vertex -> its key
  LargeVector<double> Placed; ///< vertex -> the key its heap entry holds (<= Key)
};

} // namespace colordecimation

#endif
