/**
 * @file VertexHeap.h
 * @brief An indexed binary min-heap of vertices keyed by their collapse cost, with
 * decrease-key, increase-key and removal in O(log n).
 *
 * Flat arrays only: the heap of vertex ids, and per vertex its key and its slot in the heap
 * (-1 when absent). 16 bytes per vertex.
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
    this->Key.assign(numVertices, 0.0);
  }

  bool Empty() const { return this->Heap.empty(); }
  size_t Size() const { return this->Heap.size(); }
  bool Contains(int32_t v) const { return this->Slot[v] >= 0; }
  double GetKey(int32_t v) const { return this->Key[v]; }
  int32_t Top() const { return this->Heap.front(); }

  /// Insert v, or move it to its new key if it is already in.
  void Set(int32_t v, double key)
  {
    if (this->Slot[v] < 0)
    {
      this->Key[v] = key;
      this->Slot[v] = static_cast<int32_t>(this->Heap.size());
      this->Heap.push_back(v);
      this->Up(this->Slot[v]);
      return;
    }
    const double old = this->Key[v];
    this->Key[v] = key;
    if (key < old)
    {
      this->Up(this->Slot[v]);
    }
    else
    {
      this->Down(this->Slot[v]);
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
    const int32_t last = this->Heap.back();
    this->Heap.pop_back();
    this->Slot[v] = -1;
    if (last != v)
    {
      this->Heap[slot] = last;
      this->Slot[last] = slot;
      this->Up(slot);
      this->Down(this->Slot[last]);
    }
  }

  /// Remove and return the vertex with the smallest key.
  int32_t Pop()
  {
    const int32_t v = this->Heap.front();
    this->Remove(v);
    return v;
  }

private:
  void Up(int32_t slot)
  {
    const int32_t v = this->Heap[slot];
    const double key = this->Key[v];
    while (slot > 0)
    {
      const int32_t parent = (slot - 1) / 2;
      const int32_t p = this->Heap[parent];
      if (!(key < this->Key[p]))
      {
        break;
      }
      this->Heap[slot] = p;
      this->Slot[p] = slot;
      slot = parent;
    }
    this->Heap[slot] = v;
    this->Slot[v] = slot;
  }

  void Down(int32_t slot)
  {
    const int32_t n = static_cast<int32_t>(this->Heap.size());
    const int32_t v = this->Heap[slot];
    const double key = this->Key[v];
    for (;;)
    {
      int32_t child = 2 * slot + 1;
      if (child >= n)
      {
        break;
      }
      if (child + 1 < n && this->Key[this->Heap[child + 1]] < this->Key[this->Heap[child]])
      {
        ++child;
      }
      const int32_t c = this->Heap[child];
      if (!(this->Key[c] < key))
      {
        break;
      }
      this->Heap[slot] = c;
      this->Slot[c] = slot;
      slot = child;
    }
    this->Heap[slot] = v;
    this->Slot[v] = slot;
  }

  std::vector<int32_t> Heap;
  std::vector<int32_t> Slot;
  std::vector<double> Key;
};

} // namespace colordecimation

#endif
